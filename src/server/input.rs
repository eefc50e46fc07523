//! The body of `POST /v1/planets`: JSON `{"seed", "params"}` or `multipart/form-data` with a map,
//! checked completely (the map decoded) before anything is accepted, and the planet id that
//! names the inputs.

use super::error::ApiError;
use super::limit::HeavyLimit;
use super::store::{MapMeta, PrecipitationMeta, StoredInput};
use crate::maps::{GeoBounds, Map, MapError, MapKind, MapLimits};
use crate::params::PlanetRequest;
use axum::body::{Body, Bytes};
use axum::extract::{FromRequest, Multipart};
use axum::http::{header, Request, StatusCode};
use sha2::{Digest, Sha256};

/// Hex characters of an id.
pub const ID_HEX: usize = 16;

/// A validated planet request with its map bytes.
pub struct NewPlanet {
    pub input: StoredInput,
    pub map: Option<Bytes>,
    /// The precipitation map's bytes.
    pub precipitation: Option<Bytes>,
    /// Faces its base mesh will about have, at most ([`crate::planet::estimated_faces`]).
    pub estimated_faces: usize,
}

/// Id of a planet: the first 16 hex characters of SHA-256 over a canonical encoding of the
/// parameters, the seed and the maps with how they are read (a planet without a precipitation
/// map keeps the id it had before there were any).
pub fn planet_id(input: &StoredInput, map: Option<&[u8]>, precipitation: Option<&[u8]>) -> String {
    let mut h = Sha256::new();
    h.update(b"riverworld planet v1\0params\0");
    h.update(serde_json::to_vec(&input.params).expect("params serialise"));
    h.update(b"\0seed\0");
    h.update(input.seed.to_le_bytes());
    match (&input.map, map) {
        (Some(meta), Some(bytes)) => {
            h.update(b"\0map\0");
            h.update(meta.kind.as_str());
            hash_file(&mut h, &meta.range_m, &meta.bounds, bytes);
        }
        _ => h.update(b"\0no map"),
    }
    if let (Some(meta), Some(bytes)) = (&input.precipitation, precipitation) {
        h.update(b"\0precipitation");
        hash_file(&mut h, &meta.range_mm, &meta.bounds, bytes);
    }
    let digest = h.finalize();
    digest.iter().take(ID_HEX / 2).map(|b| format!("{b:02x}")).collect()
}

/// Feeds an uploaded file to the id's hash: how it is read, its length and its bytes.
fn hash_file(h: &mut Sha256, range: &Option<(f64, f64)>, bounds: &Option<GeoBounds>, bytes: &[u8]) {
    h.update(b"\0range\0");
    h.update(serde_json::to_vec(range).expect("range serialises"));
    h.update(b"\0bounds\0");
    h.update(serde_json::to_vec(bounds).expect("bounds serialise"));
    h.update(b"\0bytes\0");
    h.update((bytes.len() as u64).to_le_bytes());
    h.update(bytes);
}

/// Reads and validates a POST body of either content type; a map is decoded under `heavy`,
/// drawing its decoding memory ([`decode_cost`]) from the render memory budget.
pub async fn read(req: Request<Body>, limits: MapLimits, heavy: &HeavyLimit) -> Result<NewPlanet, ApiError> {
    let ctype = req.headers().get(header::CONTENT_TYPE).and_then(|v| v.to_str().ok()).unwrap_or("").to_string();
    let mime = ctype.split(';').next().unwrap_or("").trim().to_ascii_lowercase();
    match mime.as_str() {
        "application/json" => {
            let bytes = Bytes::from_request(req, &()).await.map_err(|r| body_error(r.status(), r.body_text()))?;
            let text = std::str::from_utf8(&bytes)
                .map_err(|_| ApiError::unprocessable("invalid_params", "body", "the body is not UTF-8"))?;
            let request = PlanetRequest::from_json(text).map_err(|e| ApiError::from_params(&e))?;
            let estimated_faces = crate::planet::estimated_faces(&request.params, None);
            let input = StoredInput { seed: request.seed, params: request.params, map: None, precipitation: None };
            Ok(NewPlanet { input, map: None, precipitation: None, estimated_faces })
        }
        "multipart/form-data" => {
            let mp = Multipart::from_request(req, &()).await.map_err(|r| body_error(r.status(), r.body_text()))?;
            read_multipart(mp, limits, heavy).await
        }
        "" => Err(unsupported("no Content-Type")),
        other => Err(unsupported(other)),
    }
}

fn unsupported(what: &str) -> ApiError {
    ApiError::new(
        StatusCode::UNSUPPORTED_MEDIA_TYPE,
        "unsupported_media_type",
        format!("{what}: send application/json or multipart/form-data"),
    )
}

/// An error while reading the body: over the limit (413) or unreadable (400).
fn body_error(status: StatusCode, text: String) -> ApiError {
    if status == StatusCode::PAYLOAD_TOO_LARGE {
        ApiError::new(status, "body_too_large", "the request body is over the size limit")
    } else {
        ApiError::new(StatusCode::BAD_REQUEST, "bad_request", text)
    }
}

fn text_part(name: &str, bytes: &[u8]) -> Result<String, ApiError> {
    String::from_utf8(bytes.to_vec())
        .map_err(|_| ApiError::unprocessable("invalid_field", name, format!("{name} is not UTF-8 text")))
}

/// The parts a multipart POST may have, each at most once.
const PARTS: [&str; 9] = [
    "map",
    "map_kind",
    "map_range",
    "map_bounds",
    "precipitation",
    "precipitation_range",
    "precipitation_bounds",
    "seed",
    "params",
];

async fn read_multipart(mut mp: Multipart, limits: MapLimits, heavy: &HeavyLimit) -> Result<NewPlanet, ApiError> {
    let (mut map, mut kind, mut range, mut bounds, mut seed, mut params) = (None, None, None, None, None, None);
    let (mut rain, mut rain_range, mut rain_bounds) = (None, None, None);
    let mut seen = std::collections::HashSet::new();
    loop {
        let field = match mp.next_field().await {
            Ok(Some(f)) => f,
            Ok(None) => break,
            Err(e) => return Err(body_error(e.status(), e.body_text())),
        };
        let name = field.name().unwrap_or("").to_string();
        if PARTS.contains(&name.as_str()) && !seen.insert(name.clone()) {
            return Err(ApiError::unprocessable(
                "duplicate_field",
                name.clone(),
                format!("the part {name:?} is given twice; give it once"),
            ));
        }
        let bytes = field.bytes().await.map_err(|e| body_error(e.status(), e.body_text()))?;
        match name.as_str() {
            "map" => map = Some(bytes),
            "map_kind" => {
                kind = Some(text_part(&name, &bytes)?.parse::<MapKind>().map_err(|e| ApiError::from_map(&e))?)
            }
            "map_range" => {
                let text = text_part(&name, &bytes)?;
                range = Some(crate::input::parse_range(&text).map_err(|e| ApiError::from_map(&e))?);
            }
            "map_bounds" => {
                let text = text_part(&name, &bytes)?;
                bounds = Some(GeoBounds::parse(&text).map_err(|e| ApiError::from_map(&e))?);
            }
            "precipitation" => rain = Some(bytes),
            "precipitation_range" => {
                let text = text_part(&name, &bytes)?;
                rain_range = Some(crate::input::parse_range(&text).map_err(|e| precipitation_error(&e))?);
            }
            "precipitation_bounds" => {
                let text = text_part(&name, &bytes)?;
                rain_bounds = Some(GeoBounds::parse(&text).map_err(|e| precipitation_error(&e))?);
            }
            "seed" => {
                let text = text_part(&name, &bytes)?;
                let s = text.trim().parse::<u64>().map_err(|_| {
                    ApiError::unprocessable("invalid_params", "seed", format!("{text:?} is not a whole number"))
                })?;
                seed = Some(s);
            }
            "params" => {
                let text = text_part(&name, &bytes)?;
                let value: serde_json::Value = serde_json::from_str(&text)
                    .map_err(|e| ApiError::unprocessable("invalid_params", "params", e.to_string()))?;
                params = Some(value);
            }
            _ => {
                return Err(ApiError::unprocessable(
                    "unknown_field",
                    name.clone(),
                    format!(
                        "unknown part {name:?}: expected map, map_kind, map_range, map_bounds, precipitation, \
                         precipitation_range, precipitation_bounds, seed or params"
                    ),
                ))
            }
        }
    }
    let map = map.ok_or_else(|| ApiError::unprocessable("missing_map", "map", "the map part is missing"))?;
    let body = serde_json::json!({ "seed": seed.unwrap_or(0), "params": params.unwrap_or(serde_json::json!({})) });
    let request = PlanetRequest::from_json(&body.to_string()).map_err(|e| ApiError::from_params(&e))?;
    let is_tiff = map.starts_with(b"II*\0") || map.starts_with(b"MM\0*");
    let kind = kind.unwrap_or(if is_tiff || range.is_some() { MapKind::Elevation } else { MapKind::Continents });
    let admitted = heavy.admit(decode_cost(&map, limits.max_pixels)).await?;
    let decoded = decode_map(map.clone(), kind, range, bounds, limits).await.map_err(|e| ApiError::from_map(&e))?;
    drop(admitted);
    check_land_and_sea(&decoded)?;
    let estimated_faces = crate::planet::estimated_faces(&request.params, Some(&decoded));
    let meta = MapMeta { kind, bytes: map.len(), width: decoded.width, height: decoded.height, range_m: range, bounds };
    let precipitation = match rain {
        Some(bytes) => {
            let admitted = heavy.admit(decode_cost(&bytes, limits.max_pixels)).await?;
            let decoded = decode_precipitation(bytes.clone(), rain_range, rain_bounds, limits)
                .await
                .map_err(|e| precipitation_error(&e))?;
            drop(admitted);
            let meta = PrecipitationMeta {
                bytes: bytes.len(),
                width: decoded.width,
                height: decoded.height,
                range_mm: rain_range,
                bounds: rain_bounds,
            };
            Some((meta, bytes))
        }
        None if rain_range.is_some() || rain_bounds.is_some() => {
            return Err(ApiError::unprocessable(
                "missing_precipitation",
                "precipitation",
                "precipitation_range or precipitation_bounds came without a precipitation part",
            ))
        }
        None => None,
    };
    let (rain_meta, rain_bytes) = precipitation.unzip();
    let input = StoredInput { seed: request.seed, params: request.params, map: Some(meta), precipitation: rain_meta };
    Ok(NewPlanet { input, map: Some(map), precipitation: rain_bytes, estimated_faces })
}

/// A precipitation map's problem, named by its own fields: `precipitation`,
/// `precipitation_range` or `precipitation_bounds`.
pub fn precipitation_error(e: &MapError) -> ApiError {
    let mut err = ApiError::from_map(e);
    err.field = Some(e.field().replacen("map", "precipitation", 1));
    err.message = format!("precipitation: {}", err.message);
    err
}

/// Refuses at upload a map that leaves the planet no land, or (covering the whole globe) no sea,
/// rather than storing a planet whose build must fail.
fn check_land_and_sea(map: &crate::maps::Map) -> Result<(), ApiError> {
    let land = map.land_fraction();
    let what = if map.kind == MapKind::Elevation { "ground above 0 m" } else { "white pixels" };
    if land <= 0.0 {
        return Err(ApiError::unprocessable("no_land", "map", format!("the map has no land ({what})")));
    }
    if land >= 1.0 && map.bounds.is_global() {
        return Err(ApiError::unprocessable(
            "no_sea",
            "map",
            format!("the map is land everywhere: a planet needs sea to drain to (a global map's sea is anything but {what})"),
        ));
    }
    Ok(())
}

/// Bytes a map's decoding may take: 12 per pixel (the decoded samples, the map's f32 values and
/// the land test's scratch), the pixels a PNG declares in its header, else the most a map may
/// have.
pub fn decode_cost(bytes: &[u8], max_pixels: u64) -> u64 {
    let declared = png_size(bytes).map(|(w, h)| u64::from(w) * u64::from(h));
    12 * declared.map_or(max_pixels, |p| p.min(max_pixels))
}

/// Width and height a PNG declares in its IHDR chunk; `None` for bytes that are no PNG.
pub fn png_size(bytes: &[u8]) -> Option<(u32, u32)> {
    if !bytes.starts_with(b"\x89PNG\r\n\x1a\n") || bytes.len() < 24 {
        return None;
    }
    let be = |i: usize| u32::from_be_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
    Some((be(16), be(20)))
}

/// Decodes a precipitation map off the async runtime.
pub async fn decode_precipitation(
    bytes: Bytes,
    range: Option<(f64, f64)>,
    bounds: Option<GeoBounds>,
    limits: MapLimits,
) -> Result<Map, MapError> {
    off_runtime(move || crate::maps::decode_precipitation(&bytes, range, bounds, &limits)).await
}

/// Decodes a map off the async runtime.
pub async fn decode_map(
    bytes: Bytes,
    kind: MapKind,
    range: Option<(f64, f64)>,
    bounds: Option<GeoBounds>,
    limits: MapLimits,
) -> Result<Map, MapError> {
    off_runtime(move || Map::decode(&bytes, kind, range, bounds, &limits)).await
}

/// Runs a decoder on the blocking pool; a decoder that died is a corrupt image.
async fn off_runtime(decode: impl FnOnce() -> Result<Map, MapError> + Send + 'static) -> Result<Map, MapError> {
    tokio::task::spawn_blocking(decode)
        .await
        .unwrap_or_else(|_| Err(MapError::Corrupt { format: "image", detail: "the decoder failed".into() }))
}

#[cfg(test)]
mod tests {
    use super::decode_cost;

    #[test]
    fn a_png_costs_the_pixels_its_header_declares() {
        let mut png = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR".to_vec();
        png.extend_from_slice(&8192u32.to_be_bytes());
        png.extend_from_slice(&4096u32.to_be_bytes());
        assert_eq!(decode_cost(&png, 64 << 20), 12 * 8192 * 4096);
        // Never more than the most pixels a map may have; other formats cost that.
        assert_eq!(decode_cost(&png, 1 << 20), 12 << 20);
        assert_eq!(decode_cost(b"II*\0", 1 << 20), 12 << 20);
    }
}
