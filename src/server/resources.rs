//! Files derived from a built planet: `view.glb` for a camera, `rivers.geojson`, `landmask.png`,
//! `preview.png` and `elevation.tif`.
//!
//! Each answer is a pure function of the planet id, the route and the normalised query, so it
//! carries a strong `ETag` over exactly those, is immutable for caches, and is kept in the
//! server's byte-bounded cache. Concurrent requests for the same answer share one rendering.
//! A planet that is not built yet answers 409 `not_ready` with `Retry-After: 1` (and its build
//! is started); one whose build failed answers 409 `build_failed`.

use super::error::ApiError;
use super::state::{AppState, Availability, Cached, Entry};
use super::Config;
use crate::adapt::gpu::GpuAdaption;
use crate::adapt::{Adapter, Camera};
use crate::export;
use crate::export::glb::Compression;
use crate::params::Params;
use crate::planet::Planet;
use crate::query::{pairs, percent_decode};
use axum::body::Bytes;
use axum::extract::{Path, RawQuery, State};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use sha2::{Digest, Sha256};
use std::sync::Arc;
use tokio::sync::OnceCell;

/// Default width of the rasters (height is half).
pub const DEFAULT_RASTER_WIDTH: u32 = 1024;
/// Widest raster by default (`Config::max_raster_width`).
pub const MAX_RASTER_WIDTH: u32 = 8192;

/// The derived resources.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Resource {
    View,
    Rivers,
    Landmask,
    Preview,
    Elevation,
}

impl Resource {
    fn name(self) -> &'static str {
        match self {
            Resource::View => "view.glb",
            Resource::Rivers => "rivers.geojson",
            Resource::Landmask => "landmask.png",
            Resource::Preview => "preview.png",
            Resource::Elevation => "elevation.tif",
        }
    }

    fn content_type(self) -> &'static str {
        match self {
            Resource::View => "model/gltf-binary",
            Resource::Rivers => "application/geo+json",
            Resource::Landmask | Resource::Preview => "image/png",
            Resource::Elevation => "image/tiff",
        }
    }
}

/// A parsed, validated query.
enum Job {
    /// `max_faces` as the query gave it (see [`view_budget`] for the default).
    View {
        cam: Camera,
        max_faces: Option<usize>,
        compression: Compression,
    },
    Rivers,
    Raster {
        width: u32,
    },
}

pub fn unknown_key(key: &str, allowed: &str) -> ApiError {
    let key = crate::query::cut(key);
    ApiError::unprocessable("unknown_parameter", &key, format!("unknown query parameter {key:?}; allowed: {allowed}"))
}

/// Refuses any query key, for routes that take none (422 `unknown_parameter` naming the first).
pub fn no_query(query: Option<&str>) -> Result<(), ApiError> {
    match pairs(query.unwrap_or("")).next() {
        Some((k, _)) => Err(unknown_key(k, "none")),
        None => Ok(()),
    }
}

/// The (decoded) value of a `compression` query parameter (`meshopt` or `none`), or a 422
/// naming it.
pub fn compression_value(v: &str) -> Result<Compression, ApiError> {
    Compression::parse(v).ok_or_else(|| {
        ApiError::unprocessable(
            "invalid_parameter",
            "compression",
            format!("compression {:?} is neither meshopt nor none", crate::query::cut(v)),
        )
    })
}

/// Fills a query key's slot, or a 422 naming the key when it is given twice.
pub fn set_once<T>(slot: &mut Option<T>, key: &str, value: T) -> Result<(), ApiError> {
    match slot.replace(value) {
        None => Ok(()),
        Some(_) => Err(ApiError::unprocessable(
            "duplicate_parameter",
            key,
            format!("query parameter {key:?} is given more than once"),
        )),
    }
}

/// Parses the query of `res` into the work to do and its normal form (the cache key).
fn prepare(res: Resource, query: &str, params: &Params, caps: &Config) -> Result<(Job, String), ApiError> {
    let max_faces_cap = caps.max_faces_cap;
    match res {
        Resource::View => {
            let (cam, rest) = Camera::parse_query(query, params.radius_m)
                .map_err(|e| ApiError::unprocessable("invalid_camera", e.field, e.message))?;
            let mut max_faces = None;
            let mut compression = None;
            for (k, v) in rest {
                match k.as_str() {
                    "max_faces" => max_faces = Some(whole_number_in("max_faces", &v, 1, max_faces_cap)?),
                    "compression" => set_once(&mut compression, &k, compression_value(&v)?)?,
                    _ => {
                        return Err(unknown_key(
                            &k,
                            "eye, target, up, fov, width, height, land_px, water_px, max_faces, compression",
                        ))
                    }
                }
            }
            let compression = compression.unwrap_or_default();
            let mut norm = budget_query(cam.to_query(), max_faces, max_faces_cap);
            if compression != Compression::default() {
                norm.push_str(&format!("&compression={}", compression.as_str()));
            }
            Ok((Job::View { cam, max_faces, compression }, norm))
        }
        Resource::Rivers => {
            no_query(Some(query))?;
            Ok((Job::Rivers, String::new()))
        }
        _ => {
            let mut asked = None;
            for (k, v) in pairs(query) {
                if k != "width" {
                    return Err(unknown_key(k, "width"));
                }
                let v = percent_decode(v);
                set_once(&mut asked, k, whole_number_in("width", &v, 2, caps.max_raster_width)?)?;
            }
            let width = asked.unwrap_or(DEFAULT_RASTER_WIDTH.min(caps.max_raster_width));
            Ok((Job::Raster { width }, format!("width={width}")))
        }
    }
}

/// The normal form of a view's query: the camera's, then `max_faces` as the query gave it or,
/// without one, the default within the server's `cap` (which [`view_budget`] may raise to the
/// base mesh: a function of the planet id, which the cache key holds too).
pub fn budget_query(camera: String, max_faces: Option<usize>, cap: usize) -> String {
    match max_faces {
        Some(n) => format!("{camera}&max_faces={n}"),
        None => format!("{camera}&max_faces=default:{}", crate::adapt::HTTP_VIEW_FACES.min(cap)),
    }
}

/// The face budget of a view of `planet` ([`crate::adapt::face_budget`]): the query's
/// `max_faces` (a 422 naming it below the base mesh), else [`crate::adapt::HTTP_VIEW_FACES`] within the
/// server's `cap`, raised to the base mesh where that is larger.
pub fn view_budget(planet: &Planet, asked: Option<usize>, cap: usize) -> Result<usize, ApiError> {
    // A planet stored before the server's cap was lowered may be above it: no view of it fits.
    if planet.mesh.faces.len() > cap {
        return Err(ApiError::unprocessable(
            "too_large",
            "max_faces",
            format!(
                "this planet's base mesh has {} faces, its coarsest view; this server gives views of at most {cap}",
                planet.mesh.faces.len()
            ),
        ));
    }
    crate::adapt::face_budget(&planet.mesh, asked, crate::adapt::HTTP_VIEW_FACES.min(cap))
        .map_err(|e| ApiError::unprocessable("invalid_parameter", "max_faces", e.to_string()))
}

/// Renders a resource from a built planet (blocking; runs off the async runtime).
fn render(
    res: Resource,
    job: &Job,
    planet: &Planet,
    params: &Params,
    gpu: Option<Arc<GpuAdaption>>,
    cap: usize,
) -> Result<Vec<u8>, ApiError> {
    let mesh = &planet.mesh;
    Ok(match (res, job) {
        (_, Job::View { cam, max_faces, compression }) => {
            let budget = view_budget(planet, *max_faces, cap)?;
            let mut adapter = Adapter::new(mesh.clone(), params.clone()).with_gpu(gpu);
            adapter.adapt(cam, Some(budget));
            let origin = export::view::local_origin(cam.eye, params.radius_m);
            export::view::view_glb(adapter.mesh(), params, cam, origin, *compression)
                .map_err(|e| ApiError::unprocessable("too_large", "max_faces", format!("{e}: ask for fewer faces")))?
        }
        (_, Job::Rivers) => export::rivers_geojson(planet, params).into_bytes(),
        (Resource::Landmask, Job::Raster { width }) => export::landmask_png(mesh, *width, (*width / 2).max(1)),
        (Resource::Preview, Job::Raster { width }) => {
            export::preview_png(mesh, &planet.rivers, params, *width, (*width / 2).max(1))
        }
        (_, Job::Raster { width }) => export::elevation_tiff(mesh, params, *width, (*width / 2).max(1)),
    })
}

/// Revision of what the derived answers hold, for the same id, route and query: raised whenever
/// a change to the software changes their bytes (revision 2: eq. 6 per side of the frustum, the
/// horizon's height, the sea never finer than the land; 3: the water surface meets the shore
/// inside partly wet faces, and is double-sided; 4: a refined river vertex's tangent lies in its
/// own tangent plane; 5: closed basins, lakes in `rivers.geojson`, lake beds under water; 6:
/// splits of an elevation map planet follow the map where it resolves them; 7: rivers' water
/// as wide as their channels, a regional elevation map's coast outside its bounds; 8: view.glb
/// and 3D Tiles contents quantized and meshopt-compressed by default, their vertex colours
/// linear as glTF defines them; 9-11: landform detail, the map's roughness, Earth's snow line;
/// 12: ground colours by the climate's moisture; 13: coarse 3D Tiles levels' colours are
/// means of the fine surface; 14: rivers as lines in view.glb; 15: and in 3D Tiles; 16:
/// elevation tiles resampled from samples every 4 pixels; 17: compressed glTF's `f32`
/// positions and normals through meshopt's filters, elevation tiles' PNG rows Paeth-filtered,
/// steep land bare rock; 18: elevation tiles from cells of 6 pixels; 19: the climate's monsoon
/// reach and wet land's gain; 20: wide rivers' channels carved into views; 21: and into 3D
/// Tiles and DEMs; 22: and into tiles and DEMs far finer than them, by their course, the
/// flooding bound 32 -> 8 edges; 23: elevation maps' base meshes at two map pixels per edge,
/// the map's roughness carried below its pixel at 3x, the guide's pixels read as means, flat
/// map pixels' floor; 24: under an elevation map, riverbanks give way where the map shows
/// lower ground; 25: an elevation map's base mesh at the map (rivers' water at it, mountain
/// vertices at its means, banks giving way), plateaus' roughness with the square of their
/// altitude, the floor fading beyond hillslopes; 26: DEMs' and elevation tiles' water at the
/// rivers' channel widths, as views draw it; 27: rivers on elevation maps no longer draining
/// uphill; 28: the sea floor's detail below an elevation map's pixel by its landform; 29: a
/// third tributary where every lower way out took two; 30: and a neighbour the flood reached
/// later; 31: splits below an elevation map's pixel bent by its bicubic surface; 32: coasts
/// that follow an elevation map's below the base mesh's coast edges), so that
/// caches holding the old bytes under a strong, immutable `ETag` see a new one.
pub const ANSWERS_REVISION: &str = "32";

/// Strong validator of one answer: the software version and answers' revision, id, route and
/// normalised query.
fn etag(id: &str, route: &str, norm: &str) -> String {
    let mut h = Sha256::new();
    for part in [env!("CARGO_PKG_VERSION"), ANSWERS_REVISION, id, route, norm] {
        h.update(part.as_bytes());
        h.update([0]);
    }
    let hex: String = h.finalize().iter().take(16).map(|b| format!("{b:02x}")).collect();
    format!("\"{hex}\"")
}

/// What `If-None-Match` asks of an answer tagged `tag`: whether it lists the tag (weak
/// comparison, as the header asks), and whether it lists `*` (any current representation).
fn if_none_match(headers: &HeaderMap, tag: &str) -> (bool, bool) {
    let mut answer = (false, false);
    for v in headers.get_all(header::IF_NONE_MATCH).iter().filter_map(|v| v.to_str().ok()) {
        for t in v.split(',').map(str::trim) {
            answer.0 |= t.trim_start_matches("W/") == tag;
            answer.1 |= t == "*";
        }
    }
    answer
}

fn immutable(res: Response, tag: &str) -> Response {
    let mut res = res;
    let h = res.headers_mut();
    h.insert(header::ETAG, HeaderValue::from_str(tag).expect("hex etag"));
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("public, max-age=31536000, immutable"));
    res
}

/// `GET /v1/planets/{id}/<resource>`.
pub async fn get(
    res: Resource,
    state: Arc<AppState>,
    id: String,
    query: Option<String>,
    headers: HeaderMap,
) -> Result<Response, ApiError> {
    let entry = state.lookup(&id).await?.ok_or_else(|| ApiError::not_found(&format!("planet {id:?}")))?;
    let params = entry.input.params.clone();
    let (job, norm) = prepare(res, query.as_deref().unwrap_or(""), &params, &state.config)?;
    let (gpu, cap) = (state.adaption.clone(), state.config.max_faces_cap);
    let cost = match &job {
        Job::View { max_faces, .. } => cost(0, Some((*max_faces, cap)), false),
        Job::Raster { width } => cost(u64::from(*width) * u64::from(*width / 2) * BYTES_PER_PIXEL, None, false),
        Job::Rivers => cost(16 << 20, None, false),
    };
    let derived = Derived { route: res.name().to_string(), norm, content_type: res.content_type(), cost };
    cached(state, entry, derived, headers, move |planet| render(res, &job, &planet, &params, gpu, cap)).await
}

/// One answer derived from a built planet: its route below the planet and normalised query
/// (what its `ETag` and cache key cover) and its content type.
pub struct Derived {
    pub route: String,
    pub norm: String,
    pub content_type: &'static str,
    /// Working memory its render may take, bytes, from the built planet: it is admitted
    /// against the server's memory budget for renders ([`super::limit::HeavyLimit`]).
    pub cost: Cost,
}

/// The working memory of a render, from the built planet (see [`cost`]).
pub type Cost = Box<dyn FnOnce(&Planet) -> u64 + Send>;

/// Bytes of working memory per face of an adapted mesh: the mesh being refined and the last one
/// that fitted the budget, then the glTF being written (a 1.36-million-face view measured
/// 594 MiB peak from the command line).
pub const VIEW_BYTES_PER_FACE: u64 = 450;
/// Bytes per pixel of a raster or image being drawn and encoded.
pub const BYTES_PER_PIXEL: u64 = 16;
/// Bytes per base-mesh face of the planet's tiling (the surface mesh the tiles and DEMs are cut
/// from), made once per planet and then cached.
pub const TILING_BYTES_PER_FACE: u64 = 200;

/// The cost of an answer: a fixed part plus the adapted mesh of a view with `view` = the face
/// budget asked for (`Some(asked)`), the tiling where `tiling` holds.
pub fn cost(fixed: u64, view: Option<(Option<usize>, usize)>, tiling: bool) -> Cost {
    Box::new(move |planet: &Planet| {
        let base = planet.mesh.faces.len() as u64;
        let faces = view.map_or(0, |(asked, cap)| view_budget(planet, asked, cap).map_or(base, |b| b as u64));
        fixed + faces * VIEW_BYTES_PER_FACE + if tiling { base * TILING_BYTES_PER_FACE } else { 0 }
    })
}

/// Cache key of a derived answer; every key of a planet starts with `{id}/`.
pub fn cache_key(id: &str, route: &str, norm: &str) -> String {
    format!("{id}/{route}?{norm}")
}

/// Answers a derived file: 304 when `If-None-Match` lists its tag (or `*` and the answer
/// exists: found in the cache or rendered without error), from the cache, or by
/// running `render` on the built planet (off the runtime, under a render permit, shared by
/// concurrent requests) and caching the bytes; 409 while the planet is not built. An error from
/// `render` is answered as it is and nothing is cached.
pub async fn cached<F>(
    state: Arc<AppState>,
    entry: Arc<Entry>,
    derived: Derived,
    headers: HeaderMap,
    render: F,
) -> Result<Response, ApiError>
where
    F: FnOnce(Arc<Planet>) -> Result<Vec<u8>, ApiError> + Send + 'static,
{
    let id = entry.id.clone();
    let Derived { route, norm, content_type, cost } = derived;
    let tag = etag(&id, &route, &norm);
    let key = cache_key(&id, &route, &norm);
    // A listed tag is the answer's (the tag is a function of what it is derived from), so it
    // stands even before the planet is built; `*` stands only once the answer exists.
    let (tagged, star) = if_none_match(&headers, &tag);
    let not_modified = || immutable(StatusCode::NOT_MODIFIED.into_response(), &tag);
    let ok = |bytes: Bytes| {
        if star {
            return not_modified();
        }
        let r = ([(header::CONTENT_TYPE, HeaderValue::from_static(content_type))], bytes).into_response();
        immutable(r, &tag)
    };
    let planet = match state.availability(&entry) {
        Availability::Failed(e) => {
            return Err(ApiError::new(StatusCode::CONFLICT, "build_failed", format!("the build failed: {}", e.message)))
        }
        _ if tagged => return Ok(not_modified()),
        Availability::Ready(p) => Some(p),
        Availability::Pending => None,
    };
    if let Some(Cached::Response(bytes)) = state.cache.get(&key) {
        state.metrics.cache_hit("response");
        return Ok(ok(bytes));
    }
    let Some(planet) = planet else {
        state.ensure_build(&entry)?;
        return Err(
            ApiError::new(StatusCode::CONFLICT, "not_ready", format!("planet {id} is not built yet")).retry_after(1)
        );
    };
    let cell = {
        let mut inflight = state.inflight.lock().expect("inflight lock");
        Arc::clone(inflight.entry(key.clone()).or_insert_with(|| Arc::new(OnceCell::new())))
    };
    let bytes = cell
        .get_or_try_init(|| async {
            state.metrics.cache_miss("response");
            let _permit = state.renders.admit(cost(&planet)).await?;
            if !state.config.render_delay.is_zero() {
                tokio::time::sleep(state.config.render_delay).await;
            }
            let out = tokio::task::spawn_blocking(move || render(planet).map(Bytes::from))
                .await
                .map_err(|_| ApiError::internal("rendering failed"))??;
            if !entry_gone(&state, &id) {
                state.cache.insert(key.clone(), Cached::Response(out.clone()), out.len() + key.len());
            }
            Ok::<Bytes, ApiError>(out)
        })
        .await
        .cloned();
    // Refused or failed renders leave no cell behind either.
    let mut inflight = state.inflight.lock().expect("inflight lock");
    if inflight.get(&key).is_some_and(|c| Arc::ptr_eq(c, &cell)) {
        inflight.remove(&key);
    }
    drop(inflight);
    Ok(ok(bytes?))
}

fn entry_gone(state: &AppState, id: &str) -> bool {
    state.entry(id).is_none()
}

type Answer = Result<Response, ApiError>;

pub async fn view(s: State<Arc<AppState>>, p: Path<String>, q: RawQuery, h: HeaderMap) -> Answer {
    get(Resource::View, s.0, p.0, q.0, h).await
}
pub async fn rivers(s: State<Arc<AppState>>, p: Path<String>, q: RawQuery, h: HeaderMap) -> Answer {
    get(Resource::Rivers, s.0, p.0, q.0, h).await
}
pub async fn landmask(s: State<Arc<AppState>>, p: Path<String>, q: RawQuery, h: HeaderMap) -> Answer {
    get(Resource::Landmask, s.0, p.0, q.0, h).await
}
pub async fn preview(s: State<Arc<AppState>>, p: Path<String>, q: RawQuery, h: HeaderMap) -> Answer {
    get(Resource::Preview, s.0, p.0, q.0, h).await
}
pub async fn elevation(s: State<Arc<AppState>>, p: Path<String>, q: RawQuery, h: HeaderMap) -> Answer {
    get(Resource::Elevation, s.0, p.0, q.0, h).await
}

/// Parses a query value as a whole number in `lo..=hi`, or a 422 naming the parameter.
pub fn whole_number_in<T>(name: &'static str, v: &str, lo: T, hi: T) -> Result<T, ApiError>
where
    T: std::str::FromStr + PartialOrd + std::fmt::Display,
{
    match v.trim().parse::<T>() {
        Ok(n) if n >= lo && n <= hi => Ok(n),
        _ => Err(ApiError::unprocessable(
            "invalid_parameter",
            name,
            format!("must be a whole number in {lo}..={hi}, got {v:?}"),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::budget_query;

    #[test]
    fn the_cache_key_holds_the_budget_the_answer_is_made_with() {
        assert_eq!(budget_query("eye=1,2,3".into(), Some(7), 100), "eye=1,2,3&max_faces=7");
        // Without max_faces the default depends on the server's cap: servers with other caps
        // make other answers, under other keys and ETags.
        assert_eq!(budget_query("eye=1,2,3".into(), None, 1000), "eye=1,2,3&max_faces=default:1000");
        assert_ne!(budget_query("q".into(), None, 1000), budget_query("q".into(), None, 2000));
        assert_eq!(budget_query("q".into(), None, 2_000_000), budget_query("q".into(), None, 600_000));
        assert_ne!(budget_query("q".into(), None, 1000), budget_query("q".into(), Some(1000), 1000));
    }
}
