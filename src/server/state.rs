//! The server's shared state: the known planets, their build state and records, and the build
//! jobs that turn stored inputs into meshes held in the byte-bounded cache.

use super::cache::ByteLru;
use super::error::ApiError;
use super::jobs::{ClientTicket, Pool};
use super::metrics::Metrics;
use super::store::{Store, StoredInput};
use super::Config;
use crate::maps::{Map, MapLimits};
use crate::planet::{build_planet, BuildError, Planet, PlanetSpec, Stats};
use axum::body::Bytes;
use axum::http::StatusCode;
use serde::Serialize;
use std::collections::{BTreeMap, HashMap};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, RwLock};
use tokio::sync::OnceCell;

/// Id of the built-in planet.
pub const EARTH_ID: &str = "earth";
/// The built-in planet's map, shipped in the binary.
pub const EARTH_MAP: &[u8] = include_bytes!("../../maps/earth_etopo5_1024x512.png");
/// The metres of the built-in map's 16-bit levels 0 and 65535 (maps/earth_etopo5_1024x512.json).
pub const EARTH_RANGE_M: (f64, f64) = (-9010.0, 6125.0);
/// The built-in planet's seed.
pub const EARTH_SEED: u64 = 42;

/// A cached value: a built planet, a rendered response body or a planet's tiling.
#[derive(Clone)]
pub enum Cached {
    Planet(Arc<Planet>),
    Response(Bytes),
    /// A planet prepared for 3D Tiles (`export::tiles`).
    Tiles(Arc<crate::export::tiles::PlanetTiles>),
}

/// Where a planet's build stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Job {
    Idle,
    Queued,
    Building,
}

struct EntryState {
    job: Job,
    progress: f32,
    stats: Option<Stats>,
    error: Option<ApiError>,
}

/// One known planet.
pub struct Entry {
    pub id: String,
    pub input: StoredInput,
    /// The built-in planet's map; stored planets read theirs from the store.
    embedded: Option<&'static [u8]>,
    state: Mutex<EntryState>,
    deleted: AtomicBool,
}

/// `GET /v1/planets/{id}`.
#[derive(Serialize)]
pub struct Record<'a> {
    pub id: &'a str,
    pub status: &'static str,
    pub progress: f32,
    pub seed: u64,
    pub params: &'a crate::params::Params,
    pub map: &'a Option<super::store::MapMeta>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub precipitation: &'a Option<super::store::PrecipitationMeta>,
    pub stats: Option<Stats>,
    pub error: Option<ApiError>,
}

/// What a planet's derived resources can use now.
pub enum Availability {
    Ready(Arc<Planet>),
    Pending,
    Failed(ApiError),
}

/// Everything the handlers share.
pub struct AppState {
    pub config: Config,
    pub store: Store,
    pub planets: RwLock<BTreeMap<String, Arc<Entry>>>,
    pub pool: Arc<Pool>,
    /// The built-in planet's own worker: its build never waits behind uploads.
    pub builtin_pool: Arc<Pool>,
    /// Each client's share of the build queue.
    pub clients: Arc<super::jobs::PerClient>,
    pub cache: ByteLru<Cached>,
    pub metrics: Metrics,
    /// Whether the built-in planet is built (or there is none).
    pub ready: AtomicBool,
    pub runtime: tokio::runtime::Handle,
    pub inflight: Mutex<HashMap<String, Arc<OnceCell<Bytes>>>>,
    /// Permits for heavy renders, with a bounded wait queue (429 `busy` beyond it).
    pub renders: super::limit::HeavyLimit,
    /// The device for adaption on the GPU backend; `None`: the CPU backend.
    pub adaption: Option<Arc<crate::adapt::gpu::GpuAdaption>>,
}

impl Entry {
    pub fn new(id: String, input: StoredInput, embedded: Option<&'static [u8]>) -> Entry {
        let state = EntryState { job: Job::Idle, progress: 0.0, stats: None, error: None };
        Entry { id, input, embedded, state: Mutex::new(state), deleted: AtomicBool::new(false) }
    }

    /// Marks the entry gone, so that a build still running does not cache its result.
    pub fn mark_deleted(&self) {
        self.deleted.store(true, Ordering::SeqCst);
    }
}

/// Cache key of a built planet; every key of a planet starts with `{id}/`.
pub fn planet_key(id: &str) -> String {
    format!("{id}/planet")
}

impl AppState {
    pub fn entry(&self, id: &str) -> Option<Arc<Entry>> {
        if !super::valid_id(id) {
            return None;
        }
        self.planets.read().expect("planets lock").get(id).cloned()
    }

    /// The planet `id` from memory or, when it is not known here, from the store: a planet
    /// created by another server sharing the store is found on its first request.
    pub async fn lookup(&self, id: &str) -> Result<Option<Arc<Entry>>, ApiError> {
        if let Some(entry) = self.entry(id) {
            return Ok(Some(entry));
        }
        if !super::valid_hex_id(id) {
            return Ok(None);
        }
        match self.store.input(id).await.map_err(storage_error)? {
            Some(input) => Ok(Some(self.adopt(id, input))),
            None => Ok(None),
        }
    }

    /// Like [`AppState::lookup`], but also confirms with the store that a planet known in memory
    /// still exists there (another server may have deleted it); forgets it if not.
    pub async fn lookup_confirmed(&self, id: &str) -> Result<Option<Arc<Entry>>, ApiError> {
        let Some(entry) = self.lookup(id).await? else { return Ok(None) };
        if entry.embedded.is_some() {
            return Ok(Some(entry));
        }
        match self.store.input(id).await.map_err(storage_error)? {
            Some(_) => Ok(Some(entry)),
            None => {
                self.forget(&entry);
                Ok(None)
            }
        }
    }

    /// Adds a stored planet to the known ones (or returns the entry already there).
    fn adopt(&self, id: &str, input: StoredInput) -> Arc<Entry> {
        let mut planets = self.planets.write().expect("planets lock");
        let entry = planets.entry(id.to_string()).or_insert_with(|| Arc::new(Entry::new(id.to_string(), input, None)));
        Arc::clone(entry)
    }

    /// Drops a planet from memory: its entry and every cached answer of it.
    pub fn forget(&self, entry: &Entry) {
        entry.mark_deleted();
        let mut planets = self.planets.write().expect("planets lock");
        if planets.get(&entry.id).is_some_and(|e| std::ptr::eq(Arc::as_ptr(e), entry)) {
            planets.remove(&entry.id);
        }
        drop(planets);
        self.cache.remove_prefix(&format!("{}/", entry.id));
    }

    /// Brings the known planets in line with the store: adopts planets stored by another server,
    /// forgets those deleted there.
    pub async fn sync_with_store(&self) -> Result<(), ApiError> {
        let ids = self.store.ids().await.map_err(|e| storage_error(e.to_string()))?;
        let known: Vec<Arc<Entry>> = self.planets.read().expect("planets lock").values().cloned().collect();
        for entry in known {
            if entry.embedded.is_none() && ids.binary_search(&entry.id).is_err() {
                self.forget(&entry);
            }
        }
        for id in ids {
            if self.entry(&id).is_none() {
                if let Some(input) = self.store.input(&id).await.map_err(storage_error)? {
                    self.adopt(&id, input);
                }
            }
        }
        Ok(())
    }

    /// The record of a planet as it stands now.
    pub fn record<'a>(&self, entry: &'a Entry) -> Record<'a> {
        let st = entry.state.lock().expect("entry lock");
        let built = self.cache.contains(&planet_key(&entry.id));
        let (status, progress) = match st.job {
            Job::Queued => ("queued", 0.0),
            Job::Building => ("building", st.progress.clamp(0.0, 0.99)),
            Job::Idle if st.error.is_some() => ("failed", 0.0),
            Job::Idle if built => ("ready", 1.0),
            Job::Idle => ("queued", 0.0),
        };
        Record {
            id: &entry.id,
            status,
            progress,
            seed: entry.input.seed,
            params: &entry.input.params,
            map: &entry.input.map,
            precipitation: &entry.input.precipitation,
            stats: st.stats.clone(),
            error: st.error.clone(),
        }
    }

    /// The built planet, or why there is none yet.
    pub fn availability(&self, entry: &Entry) -> Availability {
        if let Some(err) = entry.state.lock().expect("entry lock").error.clone() {
            return Availability::Failed(err);
        }
        match self.cache.get(&planet_key(&entry.id)) {
            Some(Cached::Planet(p)) => {
                self.metrics.cache_hit("planet");
                Availability::Ready(p)
            }
            _ => Availability::Pending,
        }
    }

    /// Starts a build unless the planet is built, building, queued or failed; 429 when the
    /// queue is full.
    pub fn ensure_build(self: &Arc<Self>, entry: &Arc<Entry>) -> Result<(), ApiError> {
        let mut st = entry.state.lock().expect("entry lock");
        if st.job != Job::Idle || st.error.is_some() || self.cache.contains(&planet_key(&entry.id)) {
            return Ok(());
        }
        let pool = if entry.embedded.is_some() { &self.builtin_pool } else { &self.pool };
        let slot = pool.reserve().ok_or_else(queue_full)?;
        self.metrics.cache_miss("planet");
        st.job = Job::Queued;
        st.progress = 0.0;
        drop(st);
        let (state, entry) = (Arc::clone(self), Arc::clone(entry));
        slot.submit(move || run_build(&state, &entry));
        Ok(())
    }

    /// Queues the build of a new planet into a reserved slot; the client's ticket is given
    /// back when the build has run.
    pub fn start_build(self: &Arc<Self>, entry: &Arc<Entry>, slot: super::jobs::Slot, ticket: ClientTicket) {
        entry.state.lock().expect("entry lock").job = Job::Queued;
        let (state, entry) = (Arc::clone(self), Arc::clone(entry));
        slot.submit(move || {
            run_build(&state, &entry);
            drop(ticket);
        });
    }

    /// Queues the build of the built-in planet whatever the queue holds.
    pub fn start_default_build(self: &Arc<Self>, entry: &Arc<Entry>) {
        entry.state.lock().expect("entry lock").job = Job::Queued;
        let (state, entry) = (Arc::clone(self), Arc::clone(entry));
        self.builtin_pool.submit_unbounded(move || {
            run_build(&state, &entry);
            if state.cache.contains(&planet_key(EARTH_ID)) {
                state.ready.store(true, Ordering::SeqCst);
                tracing::info!("built-in planet {EARTH_ID} is ready");
            }
        });
    }
}

/// 500 `storage_error`: the store could not be read.
pub fn storage_error(e: String) -> ApiError {
    ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, "storage_error", format!("cannot read the store: {e}"))
}

/// 429 with `Retry-After`.
pub fn queue_full() -> ApiError {
    ApiError::new(StatusCode::TOO_MANY_REQUESTS, "queue_full", "the build queue is full; retry later").retry_after(5)
}

/// 429 `client_queue_full`: this client has its share of the build queue.
pub fn client_queue_full(held: usize) -> ApiError {
    ApiError::new(
        StatusCode::TOO_MANY_REQUESTS,
        "client_queue_full",
        format!(
            "{held} planets of yours are queued or building, as many as one client may have; retry when they are built"
        ),
    )
    .retry_after(5)
}

/// Runs on a build worker: loads the inputs, builds, caches the planet or records the failure.
fn run_build(state: &Arc<AppState>, entry: &Arc<Entry>) {
    if !state.config.build_delay.is_zero() {
        std::thread::sleep(state.config.build_delay);
    }
    if entry.deleted.load(Ordering::SeqCst) {
        entry.state.lock().expect("entry lock").job = Job::Idle;
        return;
    }
    entry.state.lock().expect("entry lock").job = Job::Building;
    state.metrics.build_started();
    tracing::info!(id = %entry.id, "build started");
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| build_entry(state, entry)))
        .unwrap_or_else(|_| Err(ApiError::internal("the build panicked")));
    match outcome {
        Ok(planet) => {
            let planet = Arc::new(planet);
            let guide = planet.mesh.guide.as_ref().map_or(0, |g| 4 * g.values.len())
                + planet.mesh.channels.as_ref().map_or(0, |c| c.bytes())
                + planet.mesh.precipitation.as_ref().map_or(0, |p| p.bytes());
            let bytes = (planet.mesh.bytes_per_vertex() * planet.mesh.vertices.len() as f64) as usize + guide;
            tracing::info!(id = %entry.id, ms = planet.stats.build_ms, faces = planet.stats.faces, "build finished");
            let stats = Stats { build_ms: None, ..planet.stats.clone() };
            if !entry.deleted.load(Ordering::SeqCst) {
                state.cache.insert(planet_key(&entry.id), Cached::Planet(planet), bytes);
            }
            let mut st = entry.state.lock().expect("entry lock");
            st.stats = Some(stats);
            st.job = Job::Idle;
            state.metrics.build_finished();
        }
        Err(err) => {
            tracing::warn!(id = %entry.id, error = %err, "build failed");
            let mut st = entry.state.lock().expect("entry lock");
            st.error = Some(err);
            st.job = Job::Idle;
            state.metrics.build_failed();
        }
    }
}

/// Bytes a build takes per face of its base mesh (measured: a 840,000-face planet peaked at
/// 589 MB from the command line); it draws them, for its estimated faces, from the render
/// memory budget before it starts.
pub const BUILD_BYTES_PER_FACE: u64 = 700;

/// The answer to a stored input that cannot be read back.
fn storage_read(what: &'static str) -> impl Fn(object_store::Error) -> ApiError {
    move |e| ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, "storage_error", format!("reading {what}: {e}"))
}

/// Decodes a stored map of `size` pixels with `decode`, under limits that never lock out a map
/// accepted once, its decoding memory drawn from the budget renders share.
fn decode_stored(
    state: &AppState,
    bytes: &[u8],
    size: (u32, u32),
    decode: impl FnOnce(&MapLimits) -> Result<Map, ApiError>,
) -> Result<Arc<Map>, ApiError> {
    let pixels = u64::from(size.0) * u64::from(size.1);
    let limits = MapLimits {
        max_bytes: state.config.body_limit.max(bytes.len()),
        max_pixels: state.config.max_map_pixels.max(pixels),
    };
    let decoding = super::input::decode_cost(bytes, pixels);
    let _admitted = state.runtime.block_on(state.renders.admit_unqueued(decoding));
    decode(&limits).map(Arc::new)
}

fn build_entry(state: &AppState, entry: &Entry) -> Result<Planet, ApiError> {
    let input = &entry.input;
    let map = match &input.map {
        None => None,
        Some(meta) => {
            let bytes = match entry.embedded {
                Some(b) => Bytes::from_static(b),
                None => state.runtime.block_on(state.store.map(&entry.id)).map_err(storage_read("the map"))?,
            };
            Some(decode_stored(state, &bytes, (meta.width, meta.height), |limits| {
                Map::decode(&bytes, meta.kind, meta.range_m, meta.bounds, limits).map_err(|e| ApiError::from_map(&e))
            })?)
        }
    };
    let precipitation = match &input.precipitation {
        None => None,
        Some(meta) => {
            let bytes = state
                .runtime
                .block_on(state.store.precipitation(&entry.id))
                .map_err(storage_read("the precipitation map"))?;
            Some(decode_stored(state, &bytes, (meta.width, meta.height), |limits| {
                crate::maps::decode_precipitation(&bytes, meta.range_mm, meta.bounds, limits)
                    .map_err(|e| super::input::precipitation_error(&e))
            })?)
        }
    };
    let cost = crate::planet::estimated_faces(&input.params, map.as_deref()) as u64 * BUILD_BYTES_PER_FACE;
    let _admitted = state.runtime.block_on(state.renders.admit_unqueued(cost));
    let spec = PlanetSpec { seed: input.seed, params: input.params.clone(), map, precipitation };
    let mut progress = |_: &str, f: f32| {
        entry.state.lock().expect("entry lock").progress = f;
    };
    build_planet(&spec, &mut progress).map_err(|e| {
        let code = match e {
            BuildError::Params(_) => "invalid_params",
            BuildError::NoSea => "no_sea",
            BuildError::NoLand => "no_land",
        };
        ApiError::unprocessable(code, e.field(), e.to_string())
    })
}
