//! `GET /v1/planets/{id}/dem.tif?bbox=W,S,E,N&width=W[&height=H]`: a DEM of any region
//! (`export::dem`), sampled from the planet's tiling (the bisection tree behind its mesh, cached
//! beside the planet by `tiles.rs`), cached and immutable like the other derived files.
//!
//! The query is checked before anything else: every key once (a second one answers 422 naming
//! it), values percent-decoded, no other keys; `bbox` inside -180..180 / -90..90 and not empty,
//! `width` and `height` in 1..=8192 and at most `--max-dem-pixels` cells, or 422 naming the field.

use super::error::ApiError;
use super::resources::{cached, unknown_key, whole_number_in, Derived};
use super::state::AppState;
use super::tiles::{planet_entry, tiling};
use crate::adapt::camera::percent_decode;
use crate::export::dem::{dem_tiff, DemRequest, MAX_DEM_SIDE};
use axum::extract::{Path, RawQuery, State};
use axum::http::HeaderMap;
use axum::response::Response;
use std::sync::Arc;

/// Parses and checks a `dem.tif` query.
pub fn parse_query(query: &str, max_pixels: u64) -> Result<DemRequest, ApiError> {
    let (mut bbox, mut width, mut height) = (None, None, None);
    for pair in query.split(['&', ';']).filter(|p| !p.is_empty()) {
        let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
        let v = percent_decode(v);
        let slot = match k {
            "bbox" => &mut bbox,
            "width" => &mut width,
            "height" => &mut height,
            _ => return Err(unknown_key(k, "bbox, width, height")),
        };
        if slot.replace(v).is_some() {
            return Err(ApiError::unprocessable(
                "duplicate_parameter",
                k,
                format!("query parameter {k:?} is given more than once"),
            ));
        }
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
    let derived = Derived { route: "dem.tif".into(), norm: req.to_query(), content_type: "image/tiff" };
    let (shared, owner) = (Arc::clone(&state), Arc::clone(&entry));
    cached(state, entry, derived, headers, move |planet| {
        let tiling = tiling(&shared, &owner, planet);
        Ok(dem_tiff(&tiling.dem(&req)))
    })
    .await
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
