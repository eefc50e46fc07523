//! The HTTP service (`riverworld serve`): planets created from a seed or an uploaded map, built
//! in the background by a worker pool, and served as view-dependent glTF, GeoJSON rivers,
//! equirectangular rasters and 3D Tiles, with a web viewer at `/` ([`viewer`]). `openapi.yaml`
//! at the repository root describes every route.
//!
//! Only inputs are stored (see [`store`]); a planet's mesh and every file rendered from it are
//! caches, rebuilt on demand, because the same inputs always give the same bytes. The built-in
//! planet `earth` (the shipped Earth continent bitmap, seed 42, default parameters) is built at
//! start; `/readyz` answers 200 once it is.

pub mod auth;
pub mod cache;
pub mod dem;
pub mod error;
pub mod input;
pub mod jobs;
pub mod limit;
pub mod metrics;
pub mod planets;
pub mod resources;
pub mod rivers;
pub mod snapshot;
pub mod state;
pub mod store;
pub mod terrain;
pub mod tiles;
pub mod transport;
pub mod viewer;

use axum::extract::{DefaultBodyLimit, State};
use axum::http::{header, HeaderMap, HeaderValue, Method, StatusCode, Version};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::{middleware, Router};
use error::ApiError;
use state::{AppState, Entry, EARTH_ID, EARTH_MAP, EARTH_RANGE_M, EARTH_SEED};
use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, RwLock};
use std::time::Duration;
use store::{MapMeta, Store, StoredInput};
use tower_http::compression::predicate::{Predicate, SizeAbove};
use tower_http::compression::CompressionLayer;
use tower_http::cors::{AllowOrigin, CorsLayer};
use tower_http::limit::RequestBodyLimitLayer;
use tower_http::timeout::TimeoutLayer;
use tower_http::trace::{DefaultOnResponse, TraceLayer};

/// The API description served at `/openapi.yaml`.
pub const OPENAPI: &str = include_str!("../../openapi.yaml");

/// Default of [`Config::max_render_pixels`]: 4096 x 4096.
pub const DEFAULT_MAX_RENDER_PIXELS: u64 = 4096 * 4096;

/// Default of [`Config::render_memory_mib`]: a view at the default face cap (about 860 MiB)
/// runs, two do not run at once.
pub const DEFAULT_RENDER_MEMORY_MIB: u32 = 1024;

/// Default of [`Config::max_planet_faces`].
pub const DEFAULT_MAX_PLANET_FACES: usize = 1_000_000;

/// Defaults of [`Config`] and of `riverworld serve`'s flags: one home for both.
pub mod defaults {
    pub const ADDR: &str = "127.0.0.1:8080";
    pub const DATA_DIR: &str = "data";
    pub const MAX_QUEUE: usize = 8;
    pub const WORKERS: u32 = 1;
    pub const MAX_BUILDS_PER_CLIENT: usize = 2;
    pub const CACHE_MB: usize = 512;
    pub const BODY_LIMIT_MB: u32 = 64;
    pub const CORS_ORIGIN: &str = "*";
    pub const MAX_FACES_CAP: u64 = 2_000_000;
    pub const TIMEOUT_S: u64 = 120;
    pub const RENDER_QUEUE: usize = 16;
    /// Most pixels of an uploaded map, in units of 2^20.
    pub const MAX_MAP_MPIXELS: u64 = crate::maps::DEFAULT_MAX_MAP_PIXELS >> 20;
}

/// How the server runs; `Default` matches `riverworld serve` without options.
#[derive(Clone, Debug)]
pub struct Config {
    /// Directory of the default local store.
    pub data_dir: PathBuf,
    /// Store URL (`file:///dir`, a directory or `s3://bucket/prefix`); None = `data_dir`.
    pub store_url: Option<String>,
    /// Build jobs that may wait beyond the running ones; more answer 429.
    pub max_queue: usize,
    /// Build worker threads.
    pub workers: usize,
    /// Builds one client address may have queued or running; more answer 429 (0: no limit).
    pub max_builds_per_client: usize,
    /// Take the client's address from the last `X-Forwarded-For` entry (behind a proxy that
    /// sets it), not from the connection.
    pub trust_forwarded_for: bool,
    /// Budget of the in-memory cache of planets and rendered answers, bytes.
    pub cache_bytes: usize,
    /// Largest request body, bytes.
    pub body_limit: usize,
    /// Allowed CORS origins: `*` or a comma-separated list.
    pub cors_origin: String,
    /// Largest `max_faces` a view may ask for.
    pub max_faces_cap: usize,
    /// Most faces an uploaded planet's base mesh may have (estimated before it is accepted;
    /// also kept within `max_faces_cap`).
    pub max_planet_faces: usize,
    /// Longest a request may take before it is answered 503 `timeout`.
    pub request_timeout: Duration,
    /// Whether to serve (and build at start) the built-in planet `earth`.
    pub default_planet: bool,
    /// A pause before each build starts; zero in service, lets tests observe a full queue.
    pub build_delay: Duration,
    /// Token that `POST` and `DELETE` must present as `Authorization: Bearer`; None = open.
    pub api_token: Option<auth::ApiToken>,
    /// Heavy renders (answers that are not cached) running at once; 0 = one per CPU core, at
    /// least 2.
    pub render_permits: usize,
    /// Working memory (MiB) that the heavy work running at once (renders, map decodes, planet
    /// builds) may take together; each draws what its faces and pixels need before it starts.
    pub render_memory_mib: u32,
    /// Heavy renders that may wait for a permit; more answer 429 `busy`.
    pub render_queue: usize,
    /// Widest raster (`width` of landmask.png, preview.png, elevation.tif) a request may ask for.
    pub max_raster_width: u32,
    /// Most pixels (width x height, read from the header before decoding) an uploaded map may have.
    pub max_map_pixels: u64,
    /// Most pixels (width x height) a render.png or render.jpg may ask for.
    pub max_render_pixels: u64,
    /// Most cells (width x height) a dem.tif may ask for.
    pub max_dem_pixels: u64,
    /// A pause inside each heavy render while it holds its permit; zero in service, lets tests
    /// observe busy permits and request timeouts.
    pub render_delay: Duration,
    /// Where view-dependent adaption runs for views and snapshots (`--backend`).
    pub adapt_backend: crate::adapt::gpu::Backend,
}

impl Default for Config {
    fn default() -> Config {
        Config {
            data_dir: PathBuf::from(defaults::DATA_DIR),
            store_url: None,
            max_queue: defaults::MAX_QUEUE,
            workers: defaults::WORKERS as usize,
            max_builds_per_client: defaults::MAX_BUILDS_PER_CLIENT,
            trust_forwarded_for: false,
            cache_bytes: defaults::CACHE_MB << 20,
            body_limit: (defaults::BODY_LIMIT_MB as usize) << 20,
            cors_origin: defaults::CORS_ORIGIN.into(),
            max_faces_cap: defaults::MAX_FACES_CAP as usize,
            max_planet_faces: DEFAULT_MAX_PLANET_FACES,
            request_timeout: Duration::from_secs(defaults::TIMEOUT_S),
            default_planet: true,
            build_delay: Duration::ZERO,
            api_token: None,
            render_permits: 0,
            render_memory_mib: DEFAULT_RENDER_MEMORY_MIB,
            render_queue: defaults::RENDER_QUEUE,
            max_raster_width: resources::MAX_RASTER_WIDTH,
            max_map_pixels: defaults::MAX_MAP_MPIXELS << 20,
            max_render_pixels: DEFAULT_MAX_RENDER_PIXELS,
            max_dem_pixels: crate::export::dem::DEFAULT_MAX_DEM_PIXELS,
            render_delay: Duration::ZERO,
            adapt_backend: crate::adapt::gpu::Backend::Auto,
        }
    }
}

/// Whether `id` has the shape of a stored planet's id: 16 lowercase hex characters.
pub fn valid_hex_id(id: &str) -> bool {
    id.len() == input::ID_HEX && id.bytes().all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b))
}

/// Whether `id` can name a planet at all (checked before any lookup or storage access).
pub fn valid_id(id: &str) -> bool {
    id == EARTH_ID || valid_hex_id(id)
}

/// A running server.
pub struct Server {
    addr: SocketAddr,
    shutdown: Option<tokio::sync::oneshot::Sender<()>>,
    task: tokio::task::JoinHandle<std::io::Result<()>>,
}

impl Server {
    /// The address the server listens on.
    pub fn local_addr(&self) -> SocketAddr {
        self.addr
    }

    /// Stops accepting connections, lets open requests finish and waits for the server to end.
    pub async fn shutdown(mut self) -> std::io::Result<()> {
        if let Some(tx) = self.shutdown.take() {
            let _ = tx.send(());
        }
        self.task.await.unwrap_or_else(|e| Err(std::io::Error::other(e)))
    }
}

/// What to check when an S3 store cannot be listed at start, from the store's answer.
fn store_hint(place: &str, error: &str) -> &'static str {
    if !place.starts_with("s3://") {
        ""
    } else if error.contains("NoSuchBucket") {
        " (the bucket does not exist: create it, or correct the bucket in --store)"
    } else if ["SignatureDoesNotMatch", "InvalidAccessKeyId", "AccessDenied", "403 Forbidden"]
        .iter()
        .any(|code| error.contains(code))
    {
        " (the store refused the credentials: check AWS_ACCESS_KEY_ID and AWS_SECRET_ACCESS_KEY)"
    } else {
        " (check that the bucket exists and that AWS_ACCESS_KEY_ID, AWS_SECRET_ACCESS_KEY, AWS_REGION \
         and, for a store that is not AWS, AWS_ENDPOINT are right)"
    }
}

/// Opens the store, lists the stored planets (as `queued`: they are rebuilt on first access),
/// starts the built-in planet's build and serves on `listener` until [`Server::shutdown`].
pub async fn serve(config: Config, listener: tokio::net::TcpListener) -> Result<Server, String> {
    let store = Store::open(config.store_url.as_deref(), &config.data_dir)?;
    let mut planets = std::collections::BTreeMap::new();
    let listing = store.ids().await.map_err(|e| {
        let place = config.store_url.clone().unwrap_or_else(|| config.data_dir.display().to_string());
        format!("cannot list the stored planets in {place}{}: {e}", store_hint(&place, &e.to_string()))
    })?;
    for id in listing {
        match store.input(&id).await {
            Ok(Some(input)) => {
                planets.insert(id.clone(), Arc::new(Entry::new(id, input, None)));
            }
            Ok(None) => {}
            Err(e) => tracing::warn!(%id, error = %e, "skipping a stored planet that cannot be read"),
        }
    }
    tracing::info!(planets = planets.len(), "stored planets found");
    if config.api_token.is_none() {
        tracing::warn!(
            "no API token: anyone who can reach this server can create and delete planets; \
             set --api-token or RIVERWORLD_API_TOKEN to require Authorization: Bearer on POST and DELETE"
        );
    }
    let permits = match config.render_permits {
        0 => std::thread::available_parallelism().map_or(2, |n| n.get()).max(2),
        n => n,
    };
    let backend = config.adapt_backend;
    let (adaption, choice) = tokio::task::spawn_blocking(move || crate::adapt::gpu::select(backend))
        .await
        .map_err(|e| e.to_string())?
        .map_err(|e| format!("--backend gpu: {e}; --backend cpu (or auto) adapts on the CPU, the same bytes"))?;
    tracing::info!("{choice}");
    let state = Arc::new(AppState {
        adaption,
        pool: jobs::Pool::new(config.workers, config.max_queue),
        builtin_pool: jobs::Pool::new(1, 0),
        clients: jobs::PerClient::new(config.max_builds_per_client),
        cache: cache::ByteLru::new(config.cache_bytes),
        metrics: metrics::Metrics::default(),
        ready: AtomicBool::new(!config.default_planet),
        runtime: tokio::runtime::Handle::current(),
        inflight: Mutex::new(Default::default()),
        renders: limit::HeavyLimit::new(permits, config.render_memory_mib, config.render_queue),
        planets: RwLock::new(planets),
        store,
        config,
    });
    tokio::spawn(snapshot::announce());
    if state.config.default_planet {
        let earth = Arc::new(earth_entry());
        state.planets.write().expect("planets lock").insert(EARTH_ID.to_string(), Arc::clone(&earth));
        // Pinned: uploads can never evict the built-in planet and queue its rebuild.
        state.cache.pin(&state::planet_key(EARTH_ID));
        state.start_default_build(&earth);
    }
    let app = router(Arc::clone(&state))?;
    let addr = listener.local_addr().map_err(|e| e.to_string())?;
    let (tx, rx) = tokio::sync::oneshot::channel::<()>();
    let task = tokio::spawn(async move {
        let listener = transport::JsonErrorListener(listener);
        axum::serve(listener, app.into_make_service_with_connect_info::<transport::ClientAddr>())
            .with_graceful_shutdown(async move {
                let _ = rx.await;
            })
            .await
    });
    tracing::info!(%addr, "serving");
    Ok(Server { addr, shutdown: Some(tx), task })
}

/// The built-in planet: the shipped Earth DEM (ETOPO5 relief and bathymetry), seed 42, default
/// parameters.
fn earth_entry() -> Entry {
    let (width, height) = input::png_size(EARTH_MAP).expect("the built-in map is a PNG");
    let map = MapMeta {
        kind: crate::maps::MapKind::Elevation,
        bytes: EARTH_MAP.len(),
        width,
        height,
        range_m: Some(EARTH_RANGE_M),
        bounds: None,
    };
    let input =
        StoredInput { seed: EARTH_SEED, params: crate::params::Params::default(), map: Some(map), precipitation: None };
    Entry::new(EARTH_ID.to_string(), input, Some(EARTH_MAP))
}

/// Middleware that counts every request in the server's metrics ([`metrics::Metrics::track`]).
async fn track(State(state): State<Arc<AppState>>, req: axum::extract::Request, next: middleware::Next) -> Response {
    state.metrics.track(req, next).await
}

/// All routes with their layers (outermost first: trace, CORS, compression, JSON errors, the
/// request head's limits, metrics, timeout, access control, body limit).
fn router(state: Arc<AppState>) -> Result<Router, String> {
    let c = &state.config;
    let origin = if c.cors_origin.trim() == "*" {
        AllowOrigin::any()
    } else {
        let list = c
            .cors_origin
            .split(',')
            .map(|o| HeaderValue::from_str(o.trim()).map_err(|_| format!("invalid --cors-origin {o:?}")))
            .collect::<Result<Vec<_>, _>>()?;
        AllowOrigin::list(list)
    };
    let cors = CorsLayer::new()
        .allow_origin(origin)
        .allow_methods([Method::GET, Method::HEAD, Method::POST, Method::DELETE])
        .allow_headers([header::ACCEPT, header::CONTENT_TYPE, header::IF_NONE_MATCH, header::AUTHORIZATION])
        .expose_headers([header::ETAG, header::LOCATION, header::RETRY_AFTER, header::WWW_AUTHENTICATE])
        .max_age(Duration::from_secs(86_400));
    let textual = |_: StatusCode, _: Version, h: &HeaderMap, _: &axum::http::Extensions| {
        let ct = h.get(header::CONTENT_TYPE).and_then(|v| v.to_str().ok()).unwrap_or("");
        [
            "application/json",
            "application/geo+json",
            "application/yaml",
            "application/javascript",
            "text/",
            terrain::CONTENT_TYPE,
            rivers::CONTENT_TYPE,
        ]
        .iter()
        .any(|t| ct.starts_with(t))
    };
    let compression = CompressionLayer::new().compress_when(SizeAbove::new(256).and(textual));
    Ok(Router::new()
        .route("/", get(viewer::index))
        .route("/planets/{id}", get(viewer::planet))
        .route("/assets/viewer.js", get(viewer::script))
        .route("/healthz", get(healthz))
        .route("/readyz", get(readyz))
        .route("/metrics", get(metrics_text))
        .route("/openapi.yaml", get(openapi))
        .route("/v1/planets", get(planets::list).post(planets::create))
        .route("/v1/planets/{id}", get(planets::read).delete(planets::delete))
        .route("/v1/planets/{id}/view.glb", get(resources::view))
        .route("/v1/planets/{id}/rivers.geojson", get(resources::rivers))
        .route("/v1/planets/{id}/landmask.png", get(resources::landmask))
        .route("/v1/planets/{id}/preview.png", get(resources::preview))
        .route("/v1/planets/{id}/elevation.tif", get(resources::elevation))
        .route("/v1/planets/{id}/dem.tif", get(dem::dem))
        .route("/v1/planets/{id}/dem/tilejson.json", get(dem::tilejson))
        .route("/v1/planets/{id}/dem/{z}/{x}/{file}", get(dem::tile))
        .route("/v1/planets/{id}/rivers/tilejson.json", get(rivers::tilejson))
        .route("/v1/planets/{id}/rivers/{z}/{x}/{file}", get(rivers::tile))
        .route("/v1/planets/{id}/terrain/layer.json", get(terrain::layer))
        .route("/v1/planets/{id}/terrain/{z}/{x}/{file}", get(terrain::tile))
        .route("/v1/planets/{id}/render.png", get(snapshot::png))
        .route("/v1/planets/{id}/render.jpg", get(snapshot::jpeg))
        .route("/v1/planets/{id}/tileset.json", get(tiles::tileset))
        .route("/v1/planets/{id}/tiles/{name}", get(tiles::tile))
        .fallback(not_found)
        .layer(DefaultBodyLimit::max(c.body_limit))
        .layer(RequestBodyLimitLayer::new(c.body_limit))
        .layer(middleware::from_fn_with_state(Arc::clone(&state), auth::require_token))
        .layer(TimeoutLayer::with_status_code(StatusCode::SERVICE_UNAVAILABLE, c.request_timeout))
        .layer(middleware::from_fn_with_state(Arc::clone(&state), track))
        .layer(middleware::from_fn(error::head_limits))
        .layer(middleware::from_fn(error::json_errors))
        .layer(compression)
        .layer(cors)
        .layer(
            TraceLayer::new_for_http()
                .make_span_with(request_span)
                .on_request(())
                .on_response(DefaultOnResponse::new().level(tracing::Level::INFO)),
        )
        .with_state(state))
}

/// Longest request target written to the logs, in characters.
const LOGGED_URI_CHARS: usize = 200;

/// The span of one request's log line: its method label and target, cut to
/// [`LOGGED_URI_CHARS`] characters.
fn request_span(req: &axum::http::Request<axum::body::Body>) -> tracing::Span {
    let uri = req.uri().to_string();
    let uri = match uri.char_indices().nth(LOGGED_URI_CHARS) {
        Some((cut, _)) => format!("{}... ({} bytes)", &uri[..cut], uri.len()),
        None => uri,
    };
    tracing::info_span!("request", method = metrics::method_label(req.method()), uri = %uri)
}

async fn not_found() -> ApiError {
    ApiError::not_found("route")
}

fn plain(content_type: &'static str, body: impl Into<axum::body::Body>) -> Response {
    let mut res = Response::new(body.into());
    let h = res.headers_mut();
    h.insert(header::CONTENT_TYPE, HeaderValue::from_static(content_type));
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    res
}

async fn healthz() -> Response {
    plain("application/json", r#"{"status":"ok"}"#)
}

/// Ready once the built-in planet is built and held (it is pinned in the cache, so it stays);
/// without a built-in planet, once the server listens.
async fn readyz(State(state): State<Arc<AppState>>) -> Result<Response, ApiError> {
    let held = !state.config.default_planet || state.cache.contains(&state::planet_key(EARTH_ID));
    if state.ready.load(Ordering::SeqCst) && held {
        Ok(plain("application/json", r#"{"status":"ready"}"#))
    } else {
        Err(ApiError::new(StatusCode::SERVICE_UNAVAILABLE, "not_ready", "the built-in planet is still building")
            .retry_after(1))
    }
}

async fn metrics_text(State(state): State<Arc<AppState>>) -> Response {
    let planets = state.planets.read().expect("planets lock").len() as f64;
    let text = state.metrics.render(&[
        ("riverworld_build_jobs", "Build jobs running or waiting.", state.pool.load() as f64),
        ("riverworld_cache_bytes", "Bytes held by the in-memory cache.", state.cache.bytes() as f64),
        ("riverworld_planets", "Known planets.", planets),
        ("riverworld_renders_running", "Heavy renders holding a permit.", state.renders.running() as f64),
        ("riverworld_renders_waiting", "Heavy renders waiting for a permit.", state.renders.waiting() as f64),
    ]);
    plain("text/plain; version=0.0.4; charset=utf-8", text)
}

async fn openapi() -> impl IntoResponse {
    plain("application/yaml", OPENAPI)
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_store_that_cannot_be_listed_says_what_to_check() {
        let s3 = "s3://bucket/prefix";
        let refused = "Server returned non-2xx status code: 403 Forbidden: <Code>SignatureDoesNotMatch</Code>";
        assert!(super::store_hint(s3, refused).contains("refused the credentials"));
        assert!(super::store_hint(s3, "<Code>NoSuchBucket</Code>").contains("bucket does not exist"));
        assert!(super::store_hint(s3, "connection refused").contains("AWS_ENDPOINT"));
        assert_eq!(super::store_hint("/var/lib/riverworld", refused), "");
    }
}
