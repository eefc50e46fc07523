//! Elevation tiles for MapLibre GL JS (and Mapbox GL, Tangram, deck.gl): Web Mercator XYZ tiles
//! of 512x512 pixels whose colours encode the ground's height, for a `raster-dem` source (3D
//! terrain and hillshade), and the TileJSON 3.0.0 that describes them.
//!
//! **Tiles.** Tile `z/x/y` covers the Web Mercator square `x..x+1`, `y..y+1` of `2^z` across,
//! `y` from the north (the XYZ scheme), between ±85.0511°. Its pixels are the cells of a
//! [`DemRequest`] with Mercator rows over the tile's bounds, sampled from the planet refined to
//! the pixel size as for `dem.tif` (`dem.rs`): the ground relative to sea level, the sea floor
//! under the sea.
//!
//! **Encodings.** Terrarium (the default): `height = (R * 256 + G + B / 256) - 32768`, steps of
//! 1/256 m. Mapbox Terrain-RGB: `height = -10000 + (R * 65536 + G * 256 + B) * 0.1`, steps of
//! 0.1 m. Heights are rounded to the nearest step (not truncated) and clamped to what the
//! encoding can hold.

use super::dem::{DemRequest, Rows};
use super::tiles::PlanetTiles;
use crate::maps::GeoBounds;
use serde_json::json;

/// Pixels along a tile's side.
pub const TILE_SIZE: u32 = 512;
/// Deepest zoom served: pixels of ~4.8 m at the equator.
pub const MAX_ZOOM: u8 = 14;
/// Web Mercator's latitude limit (degrees).
pub const MAX_LAT: f64 = 85.051_128_779_806_59;

/// How heights become colours.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    Terrarium,
    Mapbox,
}

impl Encoding {
    pub fn parse(s: &str) -> Option<Encoding> {
        match s {
            "terrarium" => Some(Encoding::Terrarium),
            "mapbox" => Some(Encoding::Mapbox),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Encoding::Terrarium => "terrarium",
            Encoding::Mapbox => "mapbox",
        }
    }

    /// The colour of a height in metres, rounded to the encoding's step.
    pub fn encode(self, h: f64) -> [u8; 3] {
        let n = match self {
            Encoding::Terrarium => ((h + 32768.0) * 256.0).round(),
            Encoding::Mapbox => ((h + 10000.0) * 10.0).round(),
        };
        let n = if n.is_nan() { 0 } else { n.clamp(0.0, f64::from((1u32 << 24) - 1)) as u32 };
        [(n >> 16) as u8, (n >> 8) as u8, n as u8]
    }

    /// The height a colour stands for, as clients decode it.
    pub fn decode(self, [r, g, b]: [u8; 3]) -> f64 {
        let (r, g, b) = (f64::from(r), f64::from(g), f64::from(b));
        match self {
            Encoding::Terrarium => r * 256.0 + g + b / 256.0 - 32768.0,
            Encoding::Mapbox => -10000.0 + (r * 65536.0 + g * 256.0 + b) * 0.1,
        }
    }
}

/// Why a tile address is refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TileError {
    /// Deeper than [`MAX_ZOOM`].
    TooDeep,
    /// `x` or `y` outside `0..2^z`.
    Outside,
}

/// Bounds (degrees) of tile `z/x/y`.
pub fn tile_bounds(z: u8, x: u32, y: u32) -> Result<GeoBounds, TileError> {
    if z > MAX_ZOOM {
        return Err(TileError::TooDeep);
    }
    let n = 1u32 << z;
    if x >= n || y >= n {
        return Err(TileError::Outside);
    }
    let lon = |x: u32| f64::from(x) / f64::from(n) * 360.0 - 180.0;
    let lat = |y: u32| super::dem::mercator_lat(std::f64::consts::PI * (1.0 - 2.0 * f64::from(y) / f64::from(n)));
    Ok(GeoBounds { west: lon(x), east: lon(x + 1), north: lat(y), south: lat(y + 1) })
}

/// The PNG of tile `z/x/y` of the planet.
pub fn dem_tile_png(tiles: &PlanetTiles, z: u8, x: u32, y: u32, encoding: Encoding) -> Result<Vec<u8>, TileError> {
    let bounds = tile_bounds(z, x, y)?;
    let req = DemRequest { bounds, width: TILE_SIZE, height: TILE_SIZE, rows: Rows::Mercator };
    let dem = super::dem::sample_dem(tiles, &req);
    let rgb: Vec<u8> = dem.ground.iter().flat_map(|&h| encoding.encode(f64::from(h))).collect();
    Ok(super::raster::encode_png(&rgb, TILE_SIZE, TILE_SIZE, image::ExtendedColorType::Rgb8))
}

/// The tile URL template of the server's elevation tiles under `base` (ending before `/{z}`).
pub fn tile_template(base: &str, encoding: Encoding) -> String {
    let query = match encoding {
        Encoding::Terrarium => "",
        Encoding::Mapbox => "?encoding=mapbox",
    };
    format!("{base}/{{z}}/{{x}}/{{y}}.png{query}")
}

/// TileJSON 3.0.0 of elevation tiles at `tiles` (a URL template), zooms 0 to `max_zoom`.
pub fn tilejson(name: &str, tiles: &str, encoding: Encoding, max_zoom: u8) -> String {
    let doc = json!({
        "tilejson": "3.0.0",
        "name": format!("{name} elevation"),
        "description": "Ground altitude relative to sea level (the sea floor under the sea), \
                        from the planet refined to each tile's pixel size",
        "tiles": [tiles],
        "scheme": "xyz",
        "minzoom": 0,
        "maxzoom": max_zoom.min(MAX_ZOOM),
        "bounds": [-180.0, -MAX_LAT, 180.0, MAX_LAT],
        "center": [0.0, 0.0, 2],
        "tileSize": TILE_SIZE,
        "encoding": encoding.name(),
    });
    serde_json::to_string_pretty(&doc).expect("JSON serialises")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn heights_round_to_the_encodings_step_and_decode() {
        for enc in [Encoding::Terrarium, Encoding::Mapbox] {
            let step = if enc == Encoding::Terrarium { 1.0 / 256.0 } else { 0.1 };
            for h in [-10_000.0, -4321.987, -0.04, 0.0, 0.06, 1.0, 1234.5678, 8848.86] {
                let back = enc.decode(enc.encode(h));
                assert!((back - h).abs() <= step / 2.0 + 1e-9, "{enc:?} {h} -> {back}");
            }
        }
        // Rounding, not truncation: 0.07 m is 0.1 m in Mapbox's steps, -0.07 m is -0.1 m.
        assert!((Encoding::Mapbox.decode(Encoding::Mapbox.encode(0.07)) - 0.1).abs() < 1e-9);
        assert!((Encoding::Mapbox.decode(Encoding::Mapbox.encode(-0.07)) + 0.1).abs() < 1e-9);
        // Terrarium's zero: R=128, G=0, B=0.
        assert_eq!(Encoding::Terrarium.encode(0.0), [128, 0, 0]);
        // Out of range: clamped.
        assert_eq!(Encoding::Mapbox.encode(-20_000.0), [0, 0, 0]);
    }

    #[test]
    fn tiles_cover_web_mercator() {
        let b = tile_bounds(0, 0, 0).unwrap();
        assert_eq!((b.west, b.east), (-180.0, 180.0));
        assert!((b.north - MAX_LAT).abs() < 1e-9 && (b.south + MAX_LAT).abs() < 1e-9);
        let b = tile_bounds(1, 1, 0).unwrap();
        assert_eq!((b.west, b.east), (0.0, 180.0));
        assert!(b.south.abs() < 1e-12);
        assert_eq!(tile_bounds(2, 4, 0), Err(TileError::Outside));
        assert_eq!(tile_bounds(MAX_ZOOM + 1, 0, 0), Err(TileError::TooDeep));
    }
}
