//! `GET /v1/planets/{id}/dem.tif?bbox=W,S,E,N&width=W[&height=H]`: a DEM of any region
//! (`export::dem`), and the elevation tiles of MapLibre's `raster-dem` sources
//! (`export::terrain_rgb`): `dem/tilejson.json` and `dem/{z}/{x}/{y}.png`. All are sampled from
//! the planet's tiling (the bisection tree behind its mesh, cached beside the planet by
//! `tiles.rs`), cached and immutable like the other derived files.
//!
//! The query is checked before anything else: every key once (a second one answers 422 naming
//! it), values percent-decoded, no other keys; `bbox` inside -180..180 / -90..90 and not empty,
//! `width` and `height` in 1..=8192 and at most `--max-dem-pixels` cells, or 422 naming the field.

use super::error::ApiError;
use super::resources::{cached, cost, set_once, unknown_key, whole_number_in, Derived, BYTES_PER_PIXEL};
use super::state::AppState;
use super::tiles::{planet_entry, tiling};
use crate::export::dem::{dem_tiff, DemRequest, MAX_DEM_SIDE};
use crate::export::terrain_rgb::{self, Encoding, TileError, MAX_ZOOM};
use crate::query::{pairs, percent_decode};
use axum::extract::{Path, RawQuery, State};
use axum::http::HeaderMap;
use axum::response::Response;
use std::sync::Arc;

/// Parses and checks a `dem.tif` query.
pub fn parse_query(query: &str, max_pixels: u64) -> Result<DemRequest, ApiError> {
    let (mut bbox, mut width, mut height) = (None, None, None);
    for (k, v) in pairs(query) {
        let v = percent_decode(v);
        let slot = match k {
            "bbox" => &mut bbox,
            "width" => &mut width,
            "height" => &mut height,
            _ => return Err(unknown_key(k, "bbox, width, height")),
        };
        set_once(slot, k, v)?;
    }
    let missing = |k: &str| ApiError::unprocessable("missing_parameter", k, format!("{k} is required"));
    let bbox = bbox.ok_or_else(|| missing("bbox"))?;
    let width = whole_number_in("width", &width.ok_or_else(|| missing("width"))?, 1, MAX_DEM_SIDE)?;
    let height = height.map(|h| whole_number_in("height", &h, 1, MAX_DEM_SIDE)).transpose()?;
    DemRequest::new(&bbox, width, height, max_pixels).map_err(|e| {
        let code = if e.field == "bbox" { "invalid_bbox" } else { "invalid_parameter" };
        ApiError::unprocessable(code, e.field, e.message)
    })
}

/// `GET /v1/planets/{id}/dem.tif`.
pub async fn dem(
    State(state): State<Arc<AppState>>,
    Path(id): Path<String>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, ApiError> {
    let entry = planet_entry(&state, &id).await?;
    let req = parse_query(query.as_deref().unwrap_or(""), state.config.max_dem_pixels)?;
    let cells = u64::from(req.width) * u64::from(req.height);
    let cost = cost(cells * BYTES_PER_PIXEL, None, true);
    let derived = Derived { route: "dem.tif".into(), norm: req.to_query(), content_type: "image/tiff", cost };
    let (shared, owner) = (Arc::clone(&state), Arc::clone(&entry));
    cached(state, entry, derived, headers, move |planet| {
        let tiling = tiling(&shared, &owner, planet);
        Ok(dem_tiff(&crate::export::dem::sample_dem(&tiling, &req)))
    })
    .await
}

/// The `encoding` of an elevation tile's query: each key once, no other keys.
fn parse_encoding(query: &str) -> Result<Encoding, ApiError> {
    let mut encoding = None;
    for (k, v) in pairs(query) {
        if k != "encoding" {
            return Err(unknown_key(k, "encoding"));
        }
        let v = percent_decode(v);
        let e = Encoding::parse(&v).ok_or_else(|| {
            ApiError::unprocessable("invalid_parameter", "encoding", format!("{v:?}: expected terrarium or mapbox"))
        })?;
        set_once(&mut encoding, k, e)?;
    }
    Ok(encoding.unwrap_or(Encoding::Terrarium))
}

/// Where the tiles are, as the client reached this server: `{scheme}://{host}` from the `Host`
/// (and `X-Forwarded-Proto`) headers when they are plain, else an absolute path.
pub(super) fn origin(headers: &HeaderMap) -> String {
    let plain = |s: &str, extra: &str| {
        !s.is_empty() && s.len() <= 255 && s.chars().all(|c| c.is_ascii_alphanumeric() || extra.contains(c))
    };
    let host = headers.get(axum::http::header::HOST).and_then(|h| h.to_str().ok()).filter(|h| plain(h, ".-:[]"));
    let scheme = headers
        .get("x-forwarded-proto")
        .and_then(|h| h.to_str().ok())
        .filter(|s| *s == "https" || *s == "http")
        .unwrap_or("http");
    host.map(|h| format!("{scheme}://{h}")).unwrap_or_default()
}

/// `GET /v1/planets/{id}/dem/tilejson.json[?encoding=mapbox]`.
pub async fn tilejson(
    State(state): State<Arc<AppState>>,
    Path(id): Path<String>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, ApiError> {
    let entry = planet_entry(&state, &id).await?;
    let encoding = parse_encoding(query.as_deref().unwrap_or(""))?;
    let base = format!("{}/v1/planets/{id}/dem", origin(&headers));
    let norm = format!("encoding={}&base={base}", encoding.name());
    let derived = Derived {
        route: "dem/tilejson.json".into(),
        norm,
        content_type: "application/json",
        cost: cost(1 << 20, None, false),
    };
    cached(state, entry, derived, headers, move |_| {
        Ok(terrain_rgb::tilejson(&id, &terrain_rgb::tile_template(&base, encoding), encoding, MAX_ZOOM).into_bytes())
    })
    .await
}

/// `GET /v1/planets/{id}/dem/{z}/{x}/{y}.png[?encoding=mapbox]`.
pub async fn tile(
    State(state): State<Arc<AppState>>,
    Path((id, z, x, file)): Path<(String, String, String, String)>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, ApiError> {
    let entry = planet_entry(&state, &id).await?;
    let (zoom, x, y) = tile_address(&z, &x, &file, "png")?;
    let encoding = parse_encoding(query.as_deref().unwrap_or(""))?;
    terrain_rgb::tile_bounds(zoom, x, y).map_err(|e| tile_missing(e, zoom, x, y, MAX_ZOOM))?;
    let derived = Derived {
        route: format!("dem/{zoom}/{x}/{y}.png"),
        norm: format!("encoding={}", encoding.name()),
        content_type: "image/png",
        cost: cost(512 * 512 * BYTES_PER_PIXEL, None, true),
    };
    let (shared, owner) = (Arc::clone(&state), Arc::clone(&entry));
    cached(state, entry, derived, headers, move |planet| {
        let tiling = tiling(&shared, &owner, planet);
        terrain_rgb::dem_tile_png(&tiling, zoom, x, y, encoding).map_err(|_| ApiError::internal("tile checked"))
    })
    .await
}

/// The zoom, `x` and `y` of a tile route's `{z}/{x}/{y}.{suffix}`: whole numbers, or 422
/// `invalid_tile`; numbers too large for any zoom's grid are 404.
pub(super) fn tile_address(z: &str, x: &str, file: &str, suffix: &str) -> Result<(u8, u32, u32), ApiError> {
    let malformed = || {
        ApiError::unprocessable(
            "invalid_tile",
            "tile",
            format!("{z}/{x}/{file:?} is no tile: expected whole numbers z/x/y and .{suffix}"),
        )
    };
    let number = |s: &str| {
        if s.len() <= 10 && !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()) {
            s.parse::<u64>().ok()
        } else {
            None
        }
    };
    let y = file.strip_suffix(suffix).and_then(|f| f.strip_suffix('.')).and_then(number).ok_or_else(malformed)?;
    let (z, x) = (number(z).ok_or_else(malformed)?, number(x).ok_or_else(malformed)?);
    // Ten digits may pass 2^32: such a tile lies outside every zoom's grid.
    let outside = || ApiError::not_found(&format!("tile {z}/{x}/{y} (x and y are below the zoom's grid size)"));
    let (x, y) = (u32::try_from(x).map_err(|_| outside())?, u32::try_from(y).map_err(|_| outside())?);
    let z = u8::try_from(z).map_err(|_| ApiError::not_found(&format!("tile {z}/{x}/{y} (no zoom is that deep)")))?;
    Ok((z, x, y))
}

/// The 404 of a tile address outside a scheme whose deepest zoom is `max_zoom`.
pub(super) fn tile_missing(e: TileError, z: u8, x: u32, y: u32, max_zoom: u8) -> ApiError {
    match e {
        TileError::TooDeep => ApiError::not_found(&format!("tile {z}/{x}/{y} (the deepest zoom is {max_zoom})")),
        TileError::Outside => ApiError::not_found(&format!("tile {z}/{x}/{y} (x and y are outside the zoom's grid)")),
    }
}

#[cfg(test)]
mod tests {
    use super::parse_query;

    #[test]
    fn queries_are_checked_by_field() {
        let r = parse_query("bbox=10%2C40%2C12%2C41&width=200", 1 << 24).unwrap();
        assert_eq!((r.width, r.height), (200, 100));
        for (q, field) in [
            ("width=10", "bbox"),
            ("bbox=10,40,12,41", "width"),
            ("bbox=10,40,12,41&width=10&width=20", "width"),
            ("bbox=10,40,12,41&width=10&size=3", "size"),
            ("bbox=10,40,12,41&width=0", "width"),
            ("bbox=10,40,12,41&width=9000", "width"),
            ("bbox=10,40,12,41&width=10&height=x", "height"),
            ("bbox=10,40,190,41&width=10", "bbox"),
            ("bbox=10,41,12,40&width=10", "bbox"),
            ("bbox=10,40,12,41&width=8192&height=8192", "width"),
        ] {
            let e = parse_query(q, 1 << 24).unwrap_err();
            assert_eq!(e.field.as_deref(), Some(field), "{q}");
        }
    }
}
