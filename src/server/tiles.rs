//! 3D Tiles routes of a planet (`export::tiles`): `tileset.json`, the tiles' contents
//! `tiles/{key}.glb` and the external tilesets `tiles/{key}.json`, cached and immutable like the
//! other derived files (`resources.rs`). A planet's tiling — the bisection tree behind its mesh
//! and the tiles' placements — is cached beside the planet; the tile contents made to place the
//! tiles a tileset file lists are cached as the answers of their own routes.
//!
//! Tile names are checked before anything else: a name that is no key (`0`-`7`, then quadrant
//! digits `0`-`3`) with `.glb` or `.json` answers 422 `invalid_tile`; a key deeper than the
//! planet's deepest level, or `.json` for a tile that starts no external tileset, answers 404.

use super::error::ApiError;
use super::resources::{cache_key, cached, compression_value, cost, unknown_key, Derived};
use super::state::{AppState, Cached, Entry};
use crate::export::glb::Compression;
use crate::export::tiles::{self, is_subtree_root, KeyError, PlanetTiles, TileFile, TileKey};
use crate::planet::Planet;
use crate::query::{pairs, percent_decode};
use axum::body::Bytes;
use axum::extract::{Path, RawQuery, State};
use axum::http::HeaderMap;
use axum::response::Response;
use std::sync::Arc;

type Answer = Result<Response, ApiError>;

pub(super) async fn planet_entry(state: &AppState, id: &str) -> Result<Arc<Entry>, ApiError> {
    state.lookup(id).await?.ok_or_else(|| ApiError::not_found(&format!("planet {id:?}")))
}

/// The query of a tileset or tile route: `compression` (`meshopt`, the default, or `none`),
/// given at most once or repeated with one value (a client may carry a tileset's query to the
/// URIs it lists, which carry it already), and its normal form.
fn tile_query(query: Option<&str>) -> Result<(Compression, String), ApiError> {
    let mut compression = None;
    for (k, v) in pairs(query.unwrap_or("")) {
        if k != "compression" {
            return Err(unknown_key(k, "compression"));
        }
        let c = compression_value(&percent_decode(v))?;
        if compression.is_some_and(|was| was != c) {
            return Err(ApiError::unprocessable(
                "duplicate_parameter",
                "compression",
                "query parameter \"compression\" is given twice with different values".to_string(),
            ));
        }
        compression = Some(c);
    }
    let c = compression.unwrap_or_default();
    let norm = if c == Compression::default() { String::new() } else { format!("compression={}", c.as_str()) };
    Ok((c, norm))
}

/// `GET /v1/planets/{id}/tileset.json`.
pub async fn tileset(
    State(state): State<Arc<AppState>>,
    Path(id): Path<String>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Answer {
    let entry = planet_entry(&state, &id).await?;
    let (compression, norm) = tile_query(query.as_deref())?;
    let derived = Derived {
        route: "tileset.json".into(),
        norm: norm.clone(),
        content_type: "application/json",
        cost: cost(16 << 20, None, true),
    };
    let (shared, owner) = (Arc::clone(&state), Arc::clone(&entry));
    cached(state, entry, derived, headers, move |planet| {
        let tiling = tiling(&shared, &owner, planet);
        let file = tiling.tileset_json(tiling.max_level(), compression);
        keep_contents(&shared, &id, &norm, file.contents);
        Ok(file.json)
    })
    .await
}

/// `GET /v1/planets/{id}/tiles/{name}`: `{key}.glb` or `{key}.json`.
pub async fn tile(
    State(state): State<Arc<AppState>>,
    Path((id, name)): Path<(String, String)>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Answer {
    let entry = planet_entry(&state, &id).await?;
    let (compression, norm) = tile_query(query.as_deref())?;
    let max_level = tiles::max_level(&entry.input.params);
    let file = TileFile::parse(&name, max_level).map_err(|e| match e {
        KeyError::Malformed => ApiError::unprocessable(
            "invalid_tile",
            "tile",
            format!("{name:?} is no tile: expected a root digit 0-7, quadrant digits 0-3, then .glb or .json"),
        ),
        KeyError::TooDeep => ApiError::not_found(&format!("tile {name:?} (the deepest level is {max_level})")),
    })?;
    let content_type = match file {
        TileFile::Content(_) => "model/gltf-binary",
        TileFile::Subtree(k) if is_subtree_root(k.level) => "application/json",
        TileFile::Subtree(_) => {
            return Err(ApiError::not_found(&format!("tileset {name:?} (only levels 1, 3, 5, ... start one)")))
        }
    };
    let derived = Derived {
        route: format!("tiles/{}", file.name()),
        norm: norm.clone(),
        content_type,
        cost: cost(16 << 20, None, true),
    };
    let (shared, owner) = (Arc::clone(&state), Arc::clone(&entry));
    cached(state, entry, derived, headers, move |planet| {
        let tiling = tiling(&shared, &owner, planet);
        Ok(match file {
            TileFile::Content(key) => tiling.content(key, compression).glb,
            TileFile::Subtree(key) => {
                let file = tiling.subtree_json(key, max_level, compression).expect("checked to start a tileset");
                keep_contents(&shared, &id, &norm, file.contents);
                file.json
            }
        })
    })
    .await
}

/// The planet's tiling, from the cache or made now (blocking).
pub(super) fn tiling(state: &AppState, entry: &Entry, planet: Arc<Planet>) -> Arc<PlanetTiles> {
    let key = format!("{}/tiling", entry.id);
    if let Some(Cached::Tiles(t)) = state.cache.get(&key) {
        return t;
    }
    let made = Arc::new(
        PlanetTiles::new(planet, entry.input.params.clone())
            .expect("a planet's mesh is a bisection refinement of the octahedron"),
    );
    if state.entry(&entry.id).is_some() {
        state.cache.insert(key, Cached::Tiles(Arc::clone(&made)), made.bytes());
    }
    made
}

/// Caches tile contents made on the way as the answers of their routes (with the query whose
/// normal form is `norm`).
fn keep_contents(state: &AppState, id: &str, norm: &str, contents: Vec<(TileKey, Vec<u8>)>) {
    if state.entry(id).is_none() {
        return;
    }
    for (key, glb) in contents {
        let cache_key = cache_key(id, &format!("tiles/{}", TileFile::Content(key).name()), norm);
        let bytes = Bytes::from(glb);
        let weight = bytes.len() + cache_key.len();
        state.cache.insert(cache_key, Cached::Response(bytes), weight);
    }
}
