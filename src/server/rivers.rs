//! Rivers and lakes as vector tiles (`export::vector_tiles`): `GET /v1/planets/{id}/rivers/
//! tilejson.json` and the Mapbox Vector Tiles it names, `rivers/{z}/{x}/{y}.mvt`, cached and
//! immutable like the other derived files, gzip-compressed on `Accept-Encoding`.

use super::dem::{origin, tile_address, tile_missing};
use super::error::ApiError;
use super::resources::{cached, cost, no_query, Derived};
use super::state::AppState;
use super::tiles::{planet_entry, tiling};
use crate::export::terrain_rgb::{self, MAX_ZOOM};
use crate::export::vector_tiles;
use axum::extract::{Path, RawQuery, State};
use axum::http::HeaderMap;
use axum::response::Response;
use std::sync::Arc;

/// The content type of vector tiles.
pub const CONTENT_TYPE: &str = "application/vnd.mapbox-vector-tile";

/// `GET /v1/planets/{id}/rivers/tilejson.json`.
pub async fn tilejson(
    State(state): State<Arc<AppState>>,
    Path(id): Path<String>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, ApiError> {
    let entry = planet_entry(&state, &id).await?;
    no_query(query.as_deref())?;
    let base = format!("{}/v1/planets/{id}/rivers", origin(&headers));
    let derived = Derived {
        route: "rivers/tilejson.json".into(),
        norm: format!("base={base}"),
        content_type: "application/json",
        cost: cost(1 << 20, None, false),
    };
    cached(state, entry, derived, headers, move |_| Ok(vector_tiles::tilejson(&id, &base, MAX_ZOOM).into_bytes())).await
}

/// `GET /v1/planets/{id}/rivers/{z}/{x}/{y}.mvt`.
pub async fn tile(
    State(state): State<Arc<AppState>>,
    Path((id, z, x, file)): Path<(String, String, String, String)>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, ApiError> {
    let entry = planet_entry(&state, &id).await?;
    let (z, x, y) = tile_address(&z, &x, &file, "mvt")?;
    no_query(query.as_deref())?;
    terrain_rgb::tile_bounds(z, x, y).map_err(|e| tile_missing(e, z, x, y, MAX_ZOOM))?;
    let derived = Derived {
        route: format!("rivers/{z}/{x}/{y}.mvt"),
        norm: String::new(),
        content_type: CONTENT_TYPE,
        cost: cost(8 << 20, None, true),
    };
    let (shared, owner) = (Arc::clone(&state), Arc::clone(&entry));
    cached(state, entry, derived, headers, move |planet| {
        let tiling = tiling(&shared, &owner, planet);
        vector_tiles::river_tile(tiling.rivers(), z, x, y).map_err(|_| ApiError::internal("tile checked"))
    })
    .await
}
