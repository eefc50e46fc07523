# riverworld in a container: `docker build -t riverworld .` then
# `docker run -p 8080:8080 -v riverworld-data:/data riverworld` serves the built-in planet.
#
# Build stage: the release binary. The crate compiles its shaders, the built-in Earth map,
# openapi.yaml and the web viewer into the binary, and Cargo.toml names the benches, so all of
# them are copied (CI lays out exactly these COPY lines and builds them: .ci/docker_context.py).
# `--build-arg FEATURES=s3` adds S3 storage (`serve --store s3://...`).
FROM rust:1-bookworm AS build
ARG FEATURES=""
WORKDIR /src
COPY Cargo.toml Cargo.lock ./
COPY src ./src
COPY benches ./benches
COPY shaders ./shaders
COPY maps ./maps
COPY openapi.yaml ./
COPY web/index.html ./web/
COPY web/dist ./web/dist
RUN cargo build --release --locked --bin riverworld --features "service ${FEATURES}"

# Runtime: Debian slim with Mesa's Vulkan drivers, so renders work without a GPU (lavapipe).
FROM debian:bookworm-slim
RUN apt-get update \
 && apt-get install -y --no-install-recommends mesa-vulkan-drivers libvulkan1 ca-certificates \
 && rm -rf /var/lib/apt/lists/* \
 && useradd --system --uid 10001 --home-dir /data --shell /usr/sbin/nologin riverworld \
 && mkdir -p /data /tmp/riverworld-runtime \
 && chown riverworld /data /tmp/riverworld-runtime
COPY --from=build /src/target/release/riverworld /usr/local/bin/riverworld
USER riverworld
WORKDIR /data
VOLUME ["/data"]
ENV XDG_RUNTIME_DIR=/tmp/riverworld-runtime RUST_LOG=info
EXPOSE 8080
# Liveness without curl in the image: an HTTP request over bash's /dev/tcp.
HEALTHCHECK --interval=30s --timeout=5s --start-period=120s --retries=3 \
  CMD ["bash", "-c", "exec 3<>/dev/tcp/127.0.0.1/8080 && printf 'GET /healthz HTTP/1.0\\r\\n\\r\\n' >&3 && head -n1 <&3 | grep -q ' 200 '"]
ENTRYPOINT ["riverworld"]
CMD ["serve", "--addr", "0.0.0.0:8080", "--data", "/data"]
