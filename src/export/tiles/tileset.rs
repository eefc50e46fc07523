//! Tileset JSON files (3D Tiles 1.1): `tileset.json` — an empty root around the planet, the
//! eight level-0 tiles, and references to the external tilesets that start at level 1 — and
//! the external tilesets `{key}.json` of the tiles at levels 1, 3, 5, ..., each listing its
//! root and one more level, then referencing the external tilesets two levels down.
//!
//! Every tile carries its `transform` (the translation from its parent's origin to its own),
//! its box relative to its origin, `geometricError` and its content. The root of an external
//! tileset has no transform: the referencing tile's applies to it.

use super::{PlanetTiles, TileKey};
use crate::export::glb::Compression;
use serde_json::{json, Value};

/// Levels each external tileset lists (its root's and the next).
pub const LEVELS_PER_FILE: u8 = 2;

/// Whether tiles of `level` start external tilesets (levels 1, 3, 5, ...).
pub fn is_subtree_root(level: u8) -> bool {
    level >= 1 && (level - 1).is_multiple_of(LEVELS_PER_FILE)
}

/// The query a tileset file's content URIs carry: none for the default (meshopt), else
/// `?compression=none`, so that a client that asked for plain contents keeps getting them down
/// the tree (a static copy's server ignores it).
pub fn content_query(compression: Compression) -> String {
    if compression == Compression::default() {
        String::new()
    } else {
        format!("?compression={}", compression.as_str())
    }
}

/// A tileset file: its JSON and the tile contents made to place its tiles, as `(key, glb)`.
pub struct TilesetFile {
    pub json: Vec<u8>,
    pub contents: Vec<(TileKey, Vec<u8>)>,
}

/// 4x4 column-major translation by `d`.
fn translation(d: glam::DVec3) -> [f64; 16] {
    [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, d.x, d.y, d.z, 1.0]
}

impl PlanetTiles {
    /// `tileset.json`, listing levels up to `last_level` (at most the planet's deepest), its
    /// URIs relative to it: `tiles/{key}.glb` and `tiles/{key}.json`, with
    /// `?compression=none` when the contents are plain ([`content_query`]).
    pub fn tileset_json(&self, last_level: u8, compression: Compression) -> TilesetFile {
        let last = last_level.min(self.max_level());
        let roots: Vec<TileKey> = (0..8).map(TileKey::root).collect();
        let contents = self.place_all(&file_keys(&roots, last), compression);
        let planet = self.planet_bounds();
        let children: Vec<Value> =
            roots.iter().map(|&k| self.tile_value(k, Some(glam::DVec3::ZERO), "tiles/", last, compression)).collect();
        let geometric_error = self.params().radius_m;
        let sea = self.params().radius_m + self.params().sea_level_m;
        let doc = json!({
            "asset": { "version": "1.1", "generator": "riverworld" },
            "extensionsUsed": ["3DTILES_ellipsoid"],
            "extensions": { "3DTILES_ellipsoid": { "body": "none", "radii": [sea, sea, sea] } },
            "geometricError": geometric_error,
            "root": {
                "boundingVolume": { "box": planet.to_tiles_box(glam::DVec3::ZERO) },
                "geometricError": geometric_error,
                "refine": "REPLACE",
                "children": children,
            },
        });
        TilesetFile { json: serde_json::to_vec(&doc).expect("JSON serialises"), contents }
    }

    /// The external tileset below `key`, or `None` when tiles of its level start none or it is
    /// deeper than `last_level`. URIs are relative to it (its siblings in `tiles/`).
    pub fn subtree_json(&self, key: TileKey, last_level: u8, compression: Compression) -> Option<TilesetFile> {
        let last = last_level.min(self.max_level());
        if !is_subtree_root(key.level) || key.level > last {
            return None;
        }
        let contents = self.place_all(&file_keys(&[key], last), compression);
        let mut root = self.tile_value(key, None, "", last, compression);
        root["refine"] = json!("REPLACE");
        let doc = json!({
            "asset": { "version": "1.1", "generator": "riverworld" },
            "geometricError": self.geometric_error(key.level),
            "root": root,
        });
        Some(TilesetFile { json: serde_json::to_vec(&doc).expect("JSON serialises"), contents })
    }

    /// One tile and what it lists below it. `parent_origin` is `None` for the root of an
    /// external tileset (no transform); a tile starting an external tileset of its own is
    /// written as a reference to it.
    fn tile_value(
        &self,
        key: TileKey,
        parent_origin: Option<glam::DVec3>,
        prefix: &str,
        last: u8,
        compression: Compression,
    ) -> Value {
        let query = content_query(compression);
        let place = self.placement(key);
        let mut tile = json!({
            "boundingVolume": { "box": place.bounds.to_tiles_box(place.origin) },
            "geometricError": self.geometric_error(key.level),
        });
        if let Some(parent) = parent_origin {
            tile["transform"] = json!(translation(place.origin - parent));
            if is_subtree_root(key.level) {
                tile["content"] = json!({ "uri": format!("{prefix}{key}.json{query}") });
                return tile;
            }
        }
        tile["content"] = json!({ "uri": format!("{prefix}{key}.glb{query}") });
        if key.level < last {
            let children: Vec<Value> = key
                .children()
                .iter()
                .map(|&c| self.tile_value(c, Some(place.origin), prefix, last, compression))
                .collect();
            tile["children"] = json!(children);
        }
        tile
    }
}

/// The tiles a file lists from `tops` down: each tile, and below it its children until the
/// children start external tilesets (included, as references) or `last` is reached.
fn file_keys(tops: &[TileKey], last: u8) -> Vec<TileKey> {
    let mut out = Vec::new();
    let mut stack: Vec<TileKey> = tops.iter().rev().copied().collect();
    while let Some(k) = stack.pop() {
        out.push(k);
        let is_reference = is_subtree_root(k.level) && !tops.contains(&k);
        if !is_reference && k.level < last {
            stack.extend(k.children().iter().rev());
        }
    }
    out
}
