//! A planet's tileset on disk (`riverworld tiles`): `tileset.json`, and under `tiles/` every
//! tile's `.glb` and every external tileset down to a last level — the same names and bytes as
//! the server's `tileset.json` and `tiles/` routes, except that the deepest level written has no
//! children.

use super::{is_subtree_root, PlanetTiles, TileFile, TileKey};
use crate::export::glb::Compression;
use rayon::prelude::*;
use serde::Serialize;
use std::path::Path;
use std::time::Instant;

/// What [`PlanetTiles::write_files`] wrote.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct WriteStats {
    pub levels: u8,
    pub tiles: usize,
    pub tileset_files: usize,
    pub tile_bytes: u64,
    pub ms: f64,
}

impl PlanetTiles {
    /// Writes levels `0..levels` (at most the planet's deepest) to `dir`, level by level (a
    /// tile's placement needs its parent's), contents made in parallel and stored as
    /// `compression` says.
    pub fn write_files(&self, dir: &Path, levels: u8, compression: Compression) -> std::io::Result<WriteStats> {
        let start = Instant::now();
        let last = levels.clamp(1, self.max_level() + 1) - 1;
        let tiles_dir = dir.join("tiles");
        std::fs::create_dir_all(&tiles_dir)?;
        let mut stats = WriteStats { levels: last + 1, ..WriteStats::default() };
        let mut level: Vec<TileKey> = (0..8).map(TileKey::root).collect();
        loop {
            for chunk in level.chunks(64) {
                let made: Vec<(TileKey, Vec<u8>)> =
                    chunk.par_iter().map(|&k| (k, self.placed_content(k, compression).glb)).collect();
                for (key, glb) in made {
                    stats.tiles += 1;
                    stats.tile_bytes += glb.len() as u64;
                    std::fs::write(tiles_dir.join(TileFile::Content(key).name()), glb)?;
                }
            }
            if level[0].level == last {
                break;
            }
            level = level.iter().flat_map(|k| k.children()).collect();
        }
        std::fs::write(dir.join("tileset.json"), self.tileset_json(last, compression).json)?;
        stats.tileset_files = 1;
        let mut key_level: Vec<TileKey> = (0..8).map(TileKey::root).collect();
        while key_level[0].level < last {
            key_level = key_level.iter().flat_map(|k| k.children()).collect();
            if is_subtree_root(key_level[0].level) {
                for &key in &key_level {
                    let file = self.subtree_json(key, last, compression).expect("a subtree root");
                    std::fs::write(tiles_dir.join(TileFile::Subtree(key).name()), file.json)?;
                    stats.tileset_files += 1;
                }
            }
        }
        stats.ms = start.elapsed().as_secs_f64() * 1000.0;
        Ok(stats)
    }
}
