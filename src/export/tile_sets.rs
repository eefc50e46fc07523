//! Static tile sets on disk (`riverworld tiles --format ...`), for hosting on a CDN or an object
//! store: the same tile bytes as the server's routes, and the index file that names them
//! relative to itself.
//!
//! - `quantized-mesh`: `layer.json` and `{z}/{x}/{y}.terrain` with all three extensions (a static
//!   host cannot vary by `Accept`), as `terrain/{z}/{x}/{y}.terrain` answers a CesiumJS that asks
//!   for them; availability (in `layer.json` and each tile's metadata) stops at the last level
//!   written.
//! - `terrarium`: `tilejson.json` and `{z}/{x}/{y}.png`, as `dem/{z}/{x}/{y}.png`; the TileJSON's
//!   tile URL is relative (`./{z}/{x}/{y}.png`): put an absolute one there if a client needs it.
//!
//! - `mvt`: `tilejson.json` and `{z}/{x}/{y}.mvt` (uncompressed), as `rivers/{z}/{x}/{y}.mvt`.
//!
//! 3D Tiles are written by [`PlanetTiles::write_files`].

use super::quantized_mesh::{self, Extensions};
use super::terrain_rgb::{self, Encoding};
use super::tiles::{PlanetTiles, WriteStats};
use rayon::prelude::*;
use std::path::Path;
use std::time::Instant;

/// Writes `levels` zooms (0 to `levels - 1`) of tiles `z/x/y` from `grid(z)` = (columns, rows),
/// each made by `make` in parallel, to `dir/{z}/{x}/{y}.{ext}`.
fn write_levels(
    dir: &Path,
    levels: u8,
    ext: &str,
    grid: impl Fn(u8) -> (u32, u32),
    make: impl Fn(u8, u32, u32) -> Vec<u8> + Sync,
) -> std::io::Result<WriteStats> {
    let start = Instant::now();
    let mut stats = WriteStats { levels, ..WriteStats::default() };
    for z in 0..levels {
        let (cols, rows) = grid(z);
        for x in 0..cols {
            let column = dir.join(z.to_string()).join(x.to_string());
            std::fs::create_dir_all(&column)?;
            let made: Vec<Vec<u8>> = (0..rows).into_par_iter().map(|y| make(z, x, y)).collect();
            for (y, bytes) in made.into_iter().enumerate() {
                stats.tiles += 1;
                stats.tile_bytes += bytes.len() as u64;
                std::fs::write(column.join(format!("{y}.{ext}")), bytes)?;
            }
        }
    }
    stats.ms = start.elapsed().as_secs_f64() * 1000.0;
    Ok(stats)
}

/// Cesium terrain: `dir/layer.json` and its tiles, zooms `0..levels`.
pub fn write_quantized_mesh(tiles: &PlanetTiles, dir: &Path, levels: u8, name: &str) -> std::io::Result<WriteStats> {
    let levels = levels.clamp(1, quantized_mesh::MAX_ZOOM + 1);
    let last = levels - 1;
    let mut stats = write_levels(
        dir,
        levels,
        "terrain",
        |z| (2 << z, 1 << z),
        |z, x, y| quantized_mesh::terrain_tile(tiles, (z, x, y), Extensions::ALL, last).expect("inside the scheme"),
    )?;
    std::fs::write(dir.join("layer.json"), quantized_mesh::layer_json(name, env!("CARGO_PKG_VERSION"), last))?;
    stats.tileset_files = 1;
    Ok(stats)
}

/// Rivers and lakes as vector tiles: `dir/tilejson.json` and its tiles, zooms `0..levels`.
pub fn write_mvt(tiles: &PlanetTiles, dir: &Path, levels: u8, name: &str) -> std::io::Result<WriteStats> {
    let levels = levels.clamp(1, terrain_rgb::MAX_ZOOM + 1);
    let lines = tiles.rivers();
    let mut stats = write_levels(
        dir,
        levels,
        "mvt",
        |z| (1 << z, 1 << z),
        |z, x, y| super::vector_tiles::river_tile(lines, z, x, y).expect("inside the scheme"),
    )?;
    std::fs::write(dir.join("tilejson.json"), super::vector_tiles::tilejson(name, ".", levels - 1))?;
    stats.tileset_files = 1;
    Ok(stats)
}

/// MapLibre elevation tiles: `dir/tilejson.json` and its tiles, zooms `0..levels`.
pub fn write_terrarium(
    tiles: &PlanetTiles,
    dir: &Path,
    levels: u8,
    name: &str,
    encoding: Encoding,
) -> std::io::Result<WriteStats> {
    let levels = levels.clamp(1, terrain_rgb::MAX_ZOOM + 1);
    let mut stats = write_levels(
        dir,
        levels,
        "png",
        |z| (1 << z, 1 << z),
        |z, x, y| terrain_rgb::dem_tile_png(tiles, z, x, y, encoding).expect("inside the scheme"),
    )?;
    // A static host serves no query: the file names carry no encoding.
    let json = terrain_rgb::tilejson(name, "./{z}/{x}/{y}.png", encoding, levels - 1);
    std::fs::write(dir.join("tilejson.json"), json)?;
    stats.tileset_files = 1;
    Ok(stats)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::test_planet;
    use crate::params::Params;
    use std::sync::Arc;

    #[test]
    fn static_sets_hold_the_routes_tiles_and_their_index() {
        let params = Params { base_faces: 2000, ..Params::default() };
        let tiles = PlanetTiles::new(Arc::new(test_planet().clone()), params).unwrap();
        let dir = std::env::temp_dir().join(format!("riverworld-tile-sets-{}", std::process::id()));
        let stats = write_quantized_mesh(&tiles, &dir.join("qm"), 2, "test").unwrap();
        assert_eq!(stats.tiles, 2 + 8);
        let layer: serde_json::Value =
            serde_json::from_slice(&std::fs::read(dir.join("qm/layer.json")).unwrap()).unwrap();
        assert_eq!(layer["maxzoom"], 1);
        assert_eq!(layer["available"].as_array().unwrap().len(), 2);
        let file = std::fs::read(dir.join("qm/1/3/1.terrain")).unwrap();
        assert_eq!(file, quantized_mesh::terrain_tile(&tiles, (1, 3, 1), Extensions::ALL, 1).unwrap());
        // The deepest level lists no descendants: it is the route's tile at the deepest zoom
        // but for the metadata extension, which it lacks.
        let route = quantized_mesh::terrain_tile(&tiles, (1, 3, 1), Extensions::ALL, quantized_mesh::MAX_ZOOM).unwrap();
        assert!(route.starts_with(&file) && route.len() > file.len());

        let stats = write_terrarium(&tiles, &dir.join("dem"), 1, "test", Encoding::Mapbox).unwrap();
        assert_eq!(stats.tiles, 1);
        let png = std::fs::read(dir.join("dem/0/0/0.png")).unwrap();
        assert_eq!(png, terrain_rgb::dem_tile_png(&tiles, 0, 0, 0, Encoding::Mapbox).unwrap());
        let tj: serde_json::Value =
            serde_json::from_slice(&std::fs::read(dir.join("dem/tilejson.json")).unwrap()).unwrap();
        assert_eq!((tj["tiles"][0].as_str(), tj["encoding"].as_str()), (Some("./{z}/{x}/{y}.png"), Some("mapbox")));
        let stats = write_mvt(&tiles, &dir.join("mvt"), 2, "test").unwrap();
        assert_eq!(stats.tiles, 5);
        let mvt = std::fs::read(dir.join("mvt/1/1/0.mvt")).unwrap();
        assert_eq!(mvt, super::super::vector_tiles::river_tile(tiles.rivers(), 1, 1, 0).unwrap());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
