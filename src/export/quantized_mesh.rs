//! Cesium terrain: quantized-mesh-1.0 tiles and the `layer.json` that names them, for
//! `CesiumTerrainProvider` (spec: CesiumGS/quantized-mesh).
//!
//! **Scheme.** Geographic (EPSG:4326) TMS: level `z` has `2^(z+1) x 2^z` tiles of
//! `180 / 2^z` degrees, two at level 0, `x` from 180°W and `y` from the south.
//!
//! **Surface.** A tile is a regular grid of [`GRID`] x [`GRID`] cells whose vertices are sampled
//! from the planet refined to the cell size with the same reproducible split as views, tiles and
//! `dem.tif` (`dem.rs`): the visible surface, i.e. the water where water stands (sea, lakes,
//! rivers' channels at their width) and the ground elsewhere, in metres above sea level, which
//! Cesium puts on its ellipsoid. Where the sea is, the water mask says so and Cesium draws its
//! water there; the sea floor is in `dem.tif` and the elevation tiles.
//!
//! **Borders.** The surface is refined [`MARGIN`] cells past the tile on every side, so that
//! along a side both tiles that share it refine alike and give the same heights (up to each
//! tile's 16-bit height step). Measured on the Earth DEM on and beside the octahedron's edges
//! (the equator, the meridians 0°, 90°E, 180° and 90°W, the polar rows; zooms 2-7, the test
//! `earth_borders_on_octahedron_edges`): 528 of 528 shared sides match. (They did not, 22 of
//! them by 0.5-218 m, while the refinement passed over tree nodes lying just outside its
//! region: a node's descendants reach past it, and base faces inside the region were left
//! unsplit; `dem.rs` now descends every node whose descendants may reach the region. Since
//! then 40 tiles of zooms 2-12 are the same bytes with margins of 2 and 8 cells.)
//!
//! **Extensions**, written when the request's `Accept` asks for them (the static export writes
//! all three): `octvertexnormals` (normals from central differences of the grid and a ring of
//! samples around it, so they match across borders), `watermask` (256 x 256, north-west first,
//! or one byte when the tile is all land or all water), `metadata` (which descendants exist, the
//! next [`METADATA_LEVELS`] levels).
//!
//! The bytes are written by the `quantized-mesh` crate: zig-zag delta vertices, high-water-mark
//! indices (vertices numbered in order of first use), edge index lists for Cesium's skirts.

use super::dem::{Dem, DemRequest, Rows};
use super::terrain_rgb::TileError;
use super::tiles::PlanetTiles;
use crate::maps::GeoBounds;
use quantized_mesh::coords::geodetic_to_ecef;
use quantized_mesh::{
    EdgeIndices, EncodeOptions, QuantizedMeshEncoder, QuantizedMeshHeader, QuantizedVertices, TileBounds, TileMetadata,
    WaterMask,
};
use serde_json::json;

/// Cells along a tile's side (vertices: one more).
pub const GRID: u32 = 64;
/// Deepest level served: cells of ~19 m at the equator.
pub const MAX_ZOOM: u8 = 14;
/// Levels of descendants a tile's metadata lists.
pub const METADATA_LEVELS: u8 = 10;
/// Cells refined past a tile's sides.
pub const MARGIN: u32 = 2;
/// Side of the water mask.
const MASK: u32 = 256;
/// The largest quantized coordinate.
const Q: f64 = 32767.0;

/// The extensions a tile carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Extensions {
    pub normals: bool,
    pub water_mask: bool,
    pub metadata: bool,
}

impl Extensions {
    /// All three (the static export's tiles).
    pub const ALL: Extensions = Extensions { normals: true, water_mask: true, metadata: true };

    /// The extensions an `Accept` header asks for: the `extensions` parameter of its
    /// `application/vnd.quantized-mesh` entries, names joined by `-` (as CesiumJS sends them);
    /// unknown names are ignored.
    pub fn from_accept(accept: &str) -> Extensions {
        let mut e = Extensions::default();
        for entry in accept.split(',') {
            let mut parts = entry.split(';').map(str::trim);
            if !parts.next().is_some_and(|t| t.eq_ignore_ascii_case("application/vnd.quantized-mesh")) {
                continue;
            }
            for param in parts {
                let Some((k, v)) = param.split_once('=') else { continue };
                if !k.trim().eq_ignore_ascii_case("extensions") {
                    continue;
                }
                for name in v.trim().trim_matches('"').split('-') {
                    match name {
                        "octvertexnormals" | "vertexnormals" => e.normals = true,
                        "watermask" => e.water_mask = true,
                        "metadata" => e.metadata = true,
                        _ => {}
                    }
                }
            }
        }
        e
    }

    /// Normal form, for cache keys: the names joined by `-` (empty for none).
    pub fn key(self) -> String {
        let mut names = Vec::new();
        if self.normals {
            names.push("octvertexnormals");
        }
        if self.water_mask {
            names.push("watermask");
        }
        if self.metadata {
            names.push("metadata");
        }
        names.join("-")
    }
}

/// Longitude of the west side of column `x` at level `z` (degrees).
fn lon_at(z: u8, x: u32) -> f64 {
    f64::from(x) * 180.0 / f64::from(1u32 << z) - 180.0
}

/// Latitude of the south side of row `y` at level `z` (degrees).
fn lat_at(z: u8, y: u32) -> f64 {
    f64::from(y) * 180.0 / f64::from(1u32 << z) - 90.0
}

/// Bounds (degrees) of tile `z/x/y`.
pub fn tile_bounds(z: u8, x: u32, y: u32) -> Result<GeoBounds, TileError> {
    if z > MAX_ZOOM {
        return Err(TileError::TooDeep);
    }
    if x >= 2u32 << z || y >= 1u32 << z {
        return Err(TileError::Outside);
    }
    Ok(GeoBounds { west: lon_at(z, x), east: lon_at(z, x + 1), south: lat_at(z, y), north: lat_at(z, y + 1) })
}

/// A grid of `cols x rows` points spaced `step` degrees, the first at (`lon`, `lat`) (the
/// north-west one), as the cell centres of a DEM request.
fn points(lon: f64, lat: f64, cols: u32, rows: u32, step: f64) -> DemRequest {
    let h = step / 2.0;
    let bounds = GeoBounds {
        west: lon - h,
        east: lon - h + f64::from(cols) * step,
        north: lat + h,
        south: lat + h - f64::from(rows) * step,
    };
    DemRequest { bounds, width: cols, height: rows, rows: Rows::Degrees }
}

/// The visible surface of a sample: the water where it stands, else the ground.
fn top(dem: &Dem, i: usize) -> f64 {
    let (g, w) = (dem.ground[i], dem.water[i]);
    f64::from(if w.is_nan() { g } else { w.max(g) })
}

/// The `(GRID + 3)^2` grid of vertices around tile `z/x/y` (row-major from the north-west, one
/// ring outside the tile), and its water mask's grid when `mask` holds, sampled from one
/// surface refined for the vertex grid's cells.
fn sample(tiles: &PlanetTiles, b: &GeoBounds, mask: bool) -> (Vec<f64>, Option<WaterMask>) {
    let step = (b.east - b.west) / f64::from(GRID);
    let n = GRID + 3;
    let vertices = points(b.west - step, b.north + step, n, n, step);
    let mut grids = vec![vertices];
    if mask {
        grids.push(DemRequest { bounds: *b, width: MASK, height: MASK, rows: Rows::Degrees });
    }
    // Refined MARGIN cells past the tile on every side, so that the surface along a border
    // does not depend on which side's tile asks (see **Borders**).
    let m = MARGIN + 1;
    let detail =
        points(b.west - f64::from(m) * step, b.north + f64::from(m) * step, n + 2 * MARGIN, n + 2 * MARGIN, step);
    let dems = super::dem::sample_grids(tiles, &detail, &grids);
    let h = (0..(n * n) as usize).map(|i| top(&dems[0], i)).collect();
    let mask = dems.get(1).map(|dem| {
        let m: Vec<u8> = dem.water.iter().map(|w| if w.is_nan() { 0 } else { 255 }).collect();
        WaterMask::from_data(&m)
    });
    (h, mask)
}

/// The quantized-mesh tile `z/x/y` of the planet, uncompressed; its metadata lists descendants
/// down to `max_zoom` ([`MAX_ZOOM`] for the server, the last level written for a static export).
pub fn terrain_tile(
    tiles: &PlanetTiles,
    (z, x, y): (u8, u32, u32),
    ext: Extensions,
    max_zoom: u8,
) -> Result<Vec<u8>, TileError> {
    let b = tile_bounds(z, x, y)?;
    let (h, mask) = sample(tiles, &b, ext.water_mask);
    let n = GRID + 3;
    let step = (b.east - b.west) / f64::from(GRID);
    // Grid vertex (i, j): column i from the west, row j from the north, 0..=GRID.
    let height = |i: u32, j: u32| h[((j + 1) * n + i + 1) as usize];
    let lon = |i: i64| b.west + i as f64 * step;
    let lat = |j: i64| (b.north - j as f64 * step).clamp(-90.0, 90.0);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for j in 0..=GRID {
        for i in 0..=GRID {
            lo = lo.min(height(i, j));
            hi = hi.max(height(i, j));
        }
    }
    // Heights as the file stores them (f32 bounds), quantized against those.
    let (lo, hi) = (lo as f32, hi as f32);
    let range = f64::from(hi) - f64::from(lo);
    let qh = |v: f64| if range > 0.0 { ((v - f64::from(lo)) / range * Q).round().clamp(0.0, Q) as u16 } else { 0 };
    let qc = |k: u32| (f64::from(k) / f64::from(GRID) * Q).round() as u16;

    // Triangles, counter-clockwise seen from above (u east, v north), over grid ids j * 65 + i.
    let side = GRID + 1;
    let id = |i: u32, j: u32| j * side + i;
    let mut grid_tris = Vec::with_capacity((GRID * GRID * 6) as usize);
    for j in 0..GRID {
        for i in 0..GRID {
            // South-west, south-east, north-east, north-west corners (rows grow southwards).
            let (sw, se, ne, nw) = (id(i, j + 1), id(i + 1, j + 1), id(i + 1, j), id(i, j));
            // Alternate diagonals so no direction is favoured.
            if (i + j) % 2 == 0 {
                grid_tris.extend_from_slice(&[sw, se, ne, sw, ne, nw]);
            } else {
                grid_tris.extend_from_slice(&[sw, se, nw, se, ne, nw]);
            }
        }
    }
    // Vertices numbered in order of first use (what high-water-mark coding needs).
    let mut number = vec![u32::MAX; (side * side) as usize];
    let mut order = Vec::with_capacity(number.len());
    let indices: Vec<u32> = grid_tris
        .iter()
        .map(|&g| {
            if number[g as usize] == u32::MAX {
                number[g as usize] = order.len() as u32;
                order.push(g);
            }
            number[g as usize]
        })
        .collect();
    let mut vertices = QuantizedVertices::with_capacity(order.len());
    let mut geodetic = Vec::with_capacity(order.len());
    for &g in &order {
        let (i, j) = (g % side, g / side);
        vertices.push(qc(i), qc(GRID - j), qh(height(i, j)));
        geodetic.push([lon(i64::from(i)), lat(i64::from(j)), height(i, j)]);
    }
    // Border lists, sorted along their side (south to north, west to east).
    let list = |ids: Vec<u32>| ids.into_iter().map(|g| number[g as usize]).collect::<Vec<u32>>();
    let edges = EdgeIndices {
        west: list((0..=GRID).rev().map(|j| id(0, j)).collect()),
        south: list((0..=GRID).map(|i| id(i, GRID)).collect()),
        east: list((0..=GRID).rev().map(|j| id(GRID, j)).collect()),
        north: list((0..=GRID).map(|i| id(i, 0)).collect()),
    };
    let bounds = TileBounds::new(b.west, b.south, b.east, b.north);
    let header = QuantizedMeshHeader::from_bounds_with_vertices_iter(&bounds, lo, hi, geodetic);

    let mut options = EncodeOptions { compression_level: 0, ..Default::default() };
    if ext.normals {
        let p = |i: i64, j: i64| {
            let v = h[((j + 1) as u32 * n + (i + 1) as u32) as usize];
            glam::DVec3::from(geodetic_to_ecef(lon(i), lat(j), v))
        };
        let normals = order
            .iter()
            .map(|&g| {
                let (i, j) = (i64::from(g % side), i64::from(g / side));
                let east = p(i + 1, j) - p(i - 1, j);
                let north = p(i, j - 1) - p(i, j + 1);
                let up = glam::DVec3::from(geodetic_to_ecef(lon(i), lat(j), 0.0)).normalize();
                let mut nrm = east.cross(north).normalize_or_zero();
                if nrm == glam::DVec3::ZERO || !nrm.is_finite() {
                    nrm = up;
                } else if nrm.dot(up) < 0.0 {
                    nrm = -nrm;
                }
                nrm.as_vec3().to_array()
            })
            .collect();
        options.include_normals = true;
        options.normals = Some(normals);
    }
    if ext.water_mask {
        options.include_water_mask = true;
        options.water_mask = mask;
    }
    let max_zoom = max_zoom.min(MAX_ZOOM);
    if ext.metadata && z < max_zoom {
        options.include_metadata = true;
        options.metadata = Some(TileMetadata::for_tile(x, y, z, max_zoom.min(z + METADATA_LEVELS)));
    }
    Ok(QuantizedMeshEncoder::new(header, vertices, indices, edges).encode_with_options(&options))
}

/// `layer.json`: tiles at `{z}/{x}/{y}.terrain?v={version}` relative to it, every tile of the
/// scheme available down to `max_zoom` (at most [`MAX_ZOOM`]).
pub fn layer_json(name: &str, version: &str, max_zoom: u8) -> String {
    let max_zoom = max_zoom.min(MAX_ZOOM);
    let available: Vec<_> = (0..=max_zoom)
        .map(|z| json!([{ "startX": 0, "startY": 0, "endX": (2u32 << z) - 1, "endY": (1u32 << z) - 1 }]))
        .collect();
    let doc = json!({
        "tilejson": "2.1.0",
        "name": format!("{name} terrain"),
        "description": "The planet's visible surface (water where it stands, else the ground) in metres \
                        above sea level, refined to each tile's cell size",
        "version": version,
        "format": "quantized-mesh-1.0",
        "scheme": "tms",
        "projection": "EPSG:4326",
        "tiles": ["{z}/{x}/{y}.terrain?v={version}"],
        "bounds": [-180.0, -90.0, 180.0, 90.0],
        "minzoom": 0,
        "maxzoom": max_zoom,
        "available": available,
        "metadataAvailability": METADATA_LEVELS,
        "extensions": ["octvertexnormals", "watermask", "metadata"],
        "attribution": "",
    });
    serde_json::to_string_pretty(&doc).expect("JSON serialises")
}

#[cfg(test)]
#[path = "quantized_mesh_tests.rs"]
mod tests;
