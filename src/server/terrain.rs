//! Cesium terrain (`export::quantized_mesh`): `GET /v1/planets/{id}/terrain/layer.json` and the
//! quantized-mesh tiles it names, `terrain/{z}/{x}/{y}.terrain[?v=...]`.
//!
//! A tile carries the extensions its request's `Accept` asks for
//! (`application/vnd.quantized-mesh;extensions=octvertexnormals-watermask-metadata`, as CesiumJS
//! sends it), so answers vary by `Accept`; they are cached and immutable per extension set like
//! the other derived files, and gzip-compressed on `Accept-Encoding`.

use super::dem::{tile_address, tile_missing};
use super::error::ApiError;
use super::resources::{cached, cost, set_once, unknown_key, Derived, ANSWERS_REVISION, BYTES_PER_PIXEL};
use super::state::AppState;
use super::tiles::{planet_entry, tiling};
use crate::export::quantized_mesh::{self, Extensions, GRID, MAX_ZOOM};
use crate::query::{pairs, percent_decode};
use axum::extract::{Path, RawQuery, State};
use axum::http::{header, HeaderMap, HeaderValue};
use axum::response::Response;
use std::sync::Arc;

/// The content type of quantized-mesh tiles.
pub const CONTENT_TYPE: &str = "application/vnd.quantized-mesh";

/// The `version` layer.json gives, substituted into the tiles' `?v=`.
pub fn version() -> String {
    format!("1.0.{ANSWERS_REVISION}")
}

/// `GET /v1/planets/{id}/terrain/layer.json`.
pub async fn layer(
    State(state): State<Arc<AppState>>,
    Path(id): Path<String>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, ApiError> {
    let entry = planet_entry(&state, &id).await?;
    super::resources::no_query(query.as_deref())?;
    let derived = Derived {
        route: "terrain/layer.json".into(),
        norm: String::new(),
        content_type: "application/json",
        cost: cost(1 << 20, None, false),
    };
    cached(state, entry, derived, headers, move |_| {
        Ok(quantized_mesh::layer_json(&id, &version(), MAX_ZOOM).into_bytes())
    })
    .await
}

/// `GET /v1/planets/{id}/terrain/{z}/{x}/{y}.terrain`.
pub async fn tile(
    State(state): State<Arc<AppState>>,
    Path((id, z, x, file)): Path<(String, String, String, String)>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, ApiError> {
    let entry = planet_entry(&state, &id).await?;
    let (z, x, y) = tile_address(&z, &x, &file, "terrain")?;
    // `v`, the layer's version, busts caches; any value is accepted.
    let mut v = None;
    for (k, value) in pairs(query.as_deref().unwrap_or("")) {
        if k != "v" {
            return Err(unknown_key(k, "v"));
        }
        set_once(&mut v, k, percent_decode(value))?;
    }
    quantized_mesh::tile_bounds(z, x, y).map_err(|e| tile_missing(e, z, x, y, MAX_ZOOM))?;
    let accept = headers.get(header::ACCEPT).and_then(|h| h.to_str().ok()).unwrap_or("");
    let ext = Extensions::from_accept(accept);
    let samples = u64::from((GRID + 3) * (GRID + 3)) + if ext.water_mask { 256 * 256 } else { 0 };
    let derived = Derived {
        route: format!("terrain/{z}/{x}/{y}.terrain"),
        norm: format!("extensions={}", ext.key()),
        content_type: CONTENT_TYPE,
        cost: cost(samples * BYTES_PER_PIXEL, None, true),
    };
    let (shared, owner) = (Arc::clone(&state), Arc::clone(&entry));
    let mut answer = cached(state, entry, derived, headers, move |planet| {
        let tiling = tiling(&shared, &owner, planet);
        quantized_mesh::terrain_tile(&tiling, (z, x, y), ext, MAX_ZOOM).map_err(|_| ApiError::internal("tile checked"))
    })
    .await?;
    answer.headers_mut().append(header::VARY, HeaderValue::from_static("accept"));
    Ok(answer)
}
