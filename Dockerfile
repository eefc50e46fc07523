# Build stage: compile the release binary.
FROM rust:1-bookworm AS build
WORKDIR /src
COPY Cargo.toml Cargo.lock ./
COPY src ./src
COPY maps ./maps
RUN cargo build --release --locked

# Runtime: Debian with Mesa's Vulkan drivers so wgpu finds an adapter (lavapipe without a GPU).
FROM debian:bookworm-slim
RUN apt-get update \
 && apt-get install -y --no-install-recommends mesa-vulkan-drivers libvulkan1 ca-certificates \
 && rm -rf /var/lib/apt/lists/*
COPY --from=build /src/target/release/riverworld /usr/local/bin/riverworld
COPY --from=build /src/maps /usr/share/riverworld/maps
WORKDIR /data
ENTRYPOINT ["riverworld"]
CMD ["--help"]
