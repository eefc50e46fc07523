//! Rivers and lakes as Mapbox Vector Tiles 2.1 (Web Mercator XYZ, extent 4096) and the
//! TileJSON 3.0.0 that describes them, for MapLibre GL JS and other vector-tile clients.
//!
//! **Layers.** `rivers`: one LineString feature per reach (ordered downstream) with the fields
//! of `rivers.geojson` (`geojson.rs`): `id`, `downstream_id` (absent at a mouth), `strahler`,
//! `upstream_area_km2`, `length_km`, `discharge_m3s`, `width_m`, `depth_m`, `slope`,
//! `perennial`, `lake_id` (absent when none). `lakes`: one Polygon per lake with `lake_id`,
//! `water_altitude_m`, `area_km2`, `endorheic`.
//!
//! **Zoom.** A reach is in the tiles from zoom `max(0, 9 - strahler)` (order 8 and above from
//! zoom 1, brooks of order 1 from zoom 8), so coarse tiles stay small; lakes are in every zoom.
//!
//! **Geometry.** Positions are projected to the tile's 4096 x 4096 grid and clipped to it
//! grown by [`BUFFER`] units on each side (lines by Liang-Barsky into pieces, lake rings by
//! Sutherland-Hodgman); exterior rings are clockwise in tile coordinates, holes
//! counter-clockwise, as the spec asks. Reaches crossing ±180° are cut there as in GeoJSON.
//! The encoder is the `mvt` crate.

use super::geojson::{reach_lake, reach_slope, split_antimeridian, unwrapped_rings};
use super::terrain_rgb::{tile_bounds, TileError, MAX_LAT, MAX_ZOOM};
use crate::geo::lat_lon;
use crate::planet::lakes::outlines;
use crate::planet::Planet;
use mvt::{GeomEncoder, GeomType, Tile};
use pointy::BBox;
use serde_json::json;

/// Tile grid units along a side.
pub const EXTENT: u32 = 4096;
/// Units drawn past each side, so that lines and shores join across tiles.
pub const BUFFER: f64 = 64.0;

/// A reach's polyline (`[lon, lat]` pieces, cut at ±180°) and fields.
struct Line {
    parts: Vec<Vec<[f64; 2]>>,
    /// Longitude and latitude bounds, for skipping tiles.
    bounds: [f64; 4],
    id: u64,
    downstream_id: Option<u64>,
    strahler: u32,
    upstream_area_km2: f64,
    length_km: f64,
    discharge_m3s: f64,
    width_m: f64,
    depth_m: f64,
    slope: f64,
    perennial: bool,
    lake_id: Option<u32>,
}

/// A lake's rings (`[lon, lat]`, longitudes unwrapped along each ring) and fields.
struct LakeShape {
    rings: Vec<Vec<[f64; 2]>>,
    bounds: [f64; 4],
    lake_id: u32,
    water_altitude_m: f64,
    area_km2: f64,
    endorheic: bool,
}

/// A planet's rivers and lakes, ready to cut into tiles.
pub struct RiverLines {
    lines: Vec<Line>,
    lakes: Vec<LakeShape>,
}

fn bounds_of<'a>(points: impl Iterator<Item = &'a [f64; 2]>) -> [f64; 4] {
    points.fold([f64::MAX, f64::MAX, f64::MIN, f64::MIN], |b, p| {
        [b[0].min(p[0]), b[1].min(p[1]), b[2].max(p[0]), b[3].max(p[1])]
    })
}

impl RiverLines {
    pub fn new(planet: &Planet) -> RiverLines {
        let mesh = &planet.mesh;
        let lines = planet
            .rivers
            .reaches(mesh, &planet.water)
            .iter()
            .map(|r| {
                let pts: Vec<[f64; 3]> = r
                    .vertices
                    .iter()
                    .map(|&v| {
                        let (lat, lon) = lat_lon(mesh.pos(v));
                        [lon, lat, 0.0]
                    })
                    .collect();
                let parts: Vec<Vec<[f64; 2]>> =
                    split_antimeridian(&pts).into_iter().map(|p| p.iter().map(|q| [q[0], q[1]]).collect()).collect();
                Line {
                    bounds: bounds_of(parts.iter().flatten()),
                    parts,
                    id: r.id as u64,
                    downstream_id: r.downstream_id.map(|d| d as u64),
                    strahler: r.strahler,
                    upstream_area_km2: r.upstream_area_m2 / 1e6,
                    length_km: r.length_m / 1e3,
                    discharge_m3s: r.discharge_m3s,
                    width_m: r.width_m(),
                    depth_m: r.depth_m(),
                    slope: reach_slope(mesh, r),
                    perennial: r.perennial(),
                    lake_id: reach_lake(r, &planet.lake_of),
                }
            })
            .collect();
        let shores = outlines(mesh, &planet.lake_of, planet.lakes.len());
        let lakes = planet
            .lakes
            .iter()
            .map(|l| {
                let rings = unwrapped_rings(&shores[l.id as usize]);
                LakeShape {
                    bounds: bounds_of(rings.iter().flatten()),
                    rings,
                    lake_id: l.id,
                    water_altitude_m: l.water_altitude_m,
                    area_km2: l.area_m2 / 1e6,
                    endorheic: l.endorheic,
                }
            })
            .collect();
        RiverLines { lines, lakes }
    }

    /// Bytes held (estimate).
    pub fn bytes(&self) -> usize {
        let points: usize = self.lines.iter().flat_map(|l| &l.parts).map(Vec::len).sum::<usize>()
            + self.lakes.iter().flat_map(|l| &l.rings).map(Vec::len).sum::<usize>();
        16 * points + 160 * (self.lines.len() + self.lakes.len())
    }
}

/// The least Strahler order drawn at zoom `z`.
pub fn min_strahler(z: u8) -> u32 {
    9u32.saturating_sub(u32::from(z)).max(1)
}

/// Projects `[lon, lat]` to tile `z/x/y`'s units (y down), shifted by `turn` degrees.
fn project(p: [f64; 2], z: u8, x: u32, y: u32, turn: f64) -> [f64; 2] {
    let world = f64::from(EXTENT) * f64::from(1u32 << z);
    let lat = p[1].clamp(-MAX_LAT, MAX_LAT).to_radians();
    let wx = (p[0] + turn + 180.0) / 360.0 * world;
    let wy = (1.0 - lat.tan().asinh() / std::f64::consts::PI) / 2.0 * world;
    [wx - f64::from(x) * f64::from(EXTENT), wy - f64::from(y) * f64::from(EXTENT)]
}

/// The pieces of a polyline inside the box `[lo, hi]^2` (Liang-Barsky per segment).
fn clip_line(points: &[[f64; 2]], lo: f64, hi: f64) -> Vec<Vec<[f64; 2]>> {
    let mut pieces: Vec<Vec<[f64; 2]>> = Vec::new();
    let mut current: Vec<[f64; 2]> = Vec::new();
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let mut inside = true;
        for (p, q) in [(-d[0], a[0] - lo), (d[0], hi - a[0]), (-d[1], a[1] - lo), (d[1], hi - a[1])] {
            if p == 0.0 {
                if q < 0.0 {
                    inside = false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
        if !inside || t0 > t1 {
            if current.len() > 1 {
                pieces.push(std::mem::take(&mut current));
            }
            current.clear();
            continue;
        }
        let at = |t: f64| [a[0] + t * d[0], a[1] + t * d[1]];
        if current.is_empty() {
            current.push(at(t0));
        } else if t0 > 0.0 {
            if current.len() > 1 {
                pieces.push(std::mem::take(&mut current));
            }
            current = vec![at(t0)];
        }
        current.push(at(t1));
        if t1 < 1.0 {
            pieces.push(std::mem::take(&mut current));
        }
    }
    if current.len() > 1 {
        pieces.push(current);
    }
    pieces
}

/// A ring clipped to the box `[lo, hi]^2` (Sutherland-Hodgman).
fn clip_ring(ring: &[[f64; 2]], lo: f64, hi: f64) -> Vec<[f64; 2]> {
    let mut out = ring.to_vec();
    for (axis, bound, keep_above) in [(0, lo, true), (0, hi, false), (1, lo, true), (1, hi, false)] {
        let input = std::mem::take(&mut out);
        let inside = |p: &[f64; 2]| if keep_above { p[axis] >= bound } else { p[axis] <= bound };
        for (i, p) in input.iter().enumerate() {
            let q = input[(i + 1) % input.len()];
            let cross = |a: &[f64; 2], b: &[f64; 2]| {
                let t = (bound - a[axis]) / (b[axis] - a[axis]);
                [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
            };
            match (inside(p), inside(&q)) {
                (true, true) => out.push(q),
                (true, false) => out.push(cross(p, &q)),
                (false, true) => {
                    out.push(cross(p, &q));
                    out.push(q);
                }
                (false, false) => {}
            }
        }
        if out.is_empty() {
            break;
        }
    }
    out
}

/// Surveyor's area in tile units (positive: clockwise on screen, an exterior ring).
fn area(ring: &[[f64; 2]]) -> f64 {
    (0..ring.len())
        .map(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
        / 2.0
}

/// The vector tile `z/x/y` of the planet's rivers and lakes (uncompressed protobuf).
pub fn river_tile(lines: &RiverLines, z: u8, x: u32, y: u32) -> Result<Vec<u8>, TileError> {
    let b = tile_bounds(z, x, y)?;
    // Degrees of the buffer at this zoom, to skip shapes far away cheaply.
    let pad = BUFFER / f64::from(EXTENT) * (b.east - b.west);
    let (lo, hi) = (-BUFFER, f64::from(EXTENT) + BUFFER);
    let bbox: BBox<f64> = BBox::new([(lo, lo), (hi, hi)]);
    let meets = |bn: &[f64; 4], turn: f64| {
        bn[0] + turn <= b.east + pad && bn[2] + turn >= b.west - pad && bn[1] <= b.north + pad && bn[3] >= b.south - pad
    };
    let turns = |bn: &[f64; 4]| -> Vec<f64> { [0.0, -360.0, 360.0].into_iter().filter(|&t| meets(bn, t)).collect() };
    let mut tile = Tile::new(EXTENT);

    let mut layer = tile.create_layer("rivers");
    for line in lines.lines.iter().filter(|l| l.strahler >= min_strahler(z)) {
        for turn in turns(&line.bounds) {
            let mut enc = GeomEncoder::new(GeomType::Linestring).bbox(bbox);
            let mut any = false;
            for part in &line.parts {
                let projected: Vec<[f64; 2]> = part.iter().map(|&p| project(p, z, x, y, turn)).collect();
                for piece in clip_line(&projected, lo, hi) {
                    for p in piece {
                        enc.add_point(p[0], p[1]).expect("finite tile units");
                    }
                    enc.complete_geom().expect("a line");
                    any = true;
                }
            }
            if !any {
                continue;
            }
            let geom = enc.encode().expect("a line");
            if geom.is_empty() {
                continue;
            }
            let mut f = layer.into_feature(geom);
            f.set_id(line.id);
            f.add_tag_uint("id", line.id);
            if let Some(d) = line.downstream_id {
                f.add_tag_uint("downstream_id", d);
            }
            f.add_tag_uint("strahler", u64::from(line.strahler));
            f.add_tag_double("upstream_area_km2", round3(line.upstream_area_km2));
            f.add_tag_double("length_km", round3(line.length_km));
            f.add_tag_double("discharge_m3s", round3(line.discharge_m3s));
            f.add_tag_double("width_m", round3(line.width_m));
            f.add_tag_double("depth_m", round3(line.depth_m));
            f.add_tag_double("slope", (line.slope * 1e8).round() / 1e8);
            f.add_tag_bool("perennial", line.perennial);
            if let Some(l) = line.lake_id {
                f.add_tag_uint("lake_id", u64::from(l));
            }
            layer = f.into_layer();
        }
    }
    tile.add_layer(layer).expect("a layer of this tile");

    let mut layer = tile.create_layer("lakes");
    for lake in &lines.lakes {
        for turn in turns(&lake.bounds) {
            let mut enc = GeomEncoder::new(GeomType::Polygon).bbox(bbox);
            // Exteriors first, each followed by the holes inside it (as GeoJSON orders them).
            let mut rings: Vec<Vec<[f64; 2]>> = lake
                .rings
                .iter()
                .map(|r| clip_ring(&r.iter().map(|&p| project(p, z, x, y, turn)).collect::<Vec<_>>(), lo, hi))
                .filter(|r| r.len() >= 3 && area(r).abs() >= 0.5)
                .collect();
            if rings.is_empty() {
                continue;
            }
            // Geographic exteriors are counter-clockwise with y up, so clockwise (negative
            // surveyor's area) with y down: flip every ring to the spec's sense.
            for r in &mut rings {
                r.reverse();
            }
            rings.sort_by(|a, b| area(b).total_cmp(&area(a)));
            let (outer, holes): (Vec<_>, Vec<_>) = rings.into_iter().partition(|r| area(r) > 0.0);
            for o in &outer {
                for ring in std::iter::once(o).chain(holes.iter().filter(|h| inside(o, h[0]))) {
                    for p in ring {
                        enc.add_point(p[0], p[1]).expect("finite tile units");
                    }
                    enc.complete_geom().expect("a ring");
                }
            }
            let geom = enc.encode().expect("a polygon");
            if geom.is_empty() {
                continue;
            }
            let mut f = layer.into_feature(geom);
            f.set_id(u64::from(lake.lake_id));
            f.add_tag_uint("lake_id", u64::from(lake.lake_id));
            f.add_tag_double("water_altitude_m", (lake.water_altitude_m * 100.0).round() / 100.0);
            f.add_tag_double("area_km2", round3(lake.area_km2));
            f.add_tag_bool("endorheic", lake.endorheic);
            layer = f.into_layer();
        }
    }
    tile.add_layer(layer).expect("a layer of this tile");
    Ok(tile.to_bytes().expect("a tile encodes"))
}

fn round3(v: f64) -> f64 {
    (v * 1e3).round() / 1e3
}

/// Whether `p` lies inside `ring` (even-odd).
fn inside(ring: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut c = false;
    for i in 0..ring.len() {
        let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
        if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
            c = !c;
        }
    }
    c
}

/// TileJSON 3.0.0 of the river tiles, whose URLs start with `base` (ending before `/{z}`),
/// zooms 0 to `max_zoom`.
pub fn tilejson(name: &str, base: &str, max_zoom: u8) -> String {
    let max_zoom = max_zoom.min(MAX_ZOOM);
    let doc = json!({
        "tilejson": "3.0.0",
        "name": format!("{name} rivers"),
        "description": "Rivers (one line per reach, small ones from the zoom where they matter) and lakes",
        "tiles": [format!("{base}/{{z}}/{{x}}/{{y}}.mvt")],
        "scheme": "xyz",
        "minzoom": 0,
        "maxzoom": max_zoom,
        "bounds": [-180.0, -MAX_LAT, 180.0, MAX_LAT],
        "center": [0.0, 0.0, 2],
        "vector_layers": [
            {
                "id": "rivers",
                "description": "One LineString per reach, ordered downstream; order s from zoom 9 - s",
                "minzoom": 0,
                "maxzoom": max_zoom,
                "fields": {
                    "id": "Number", "downstream_id": "Number (absent at a mouth)", "strahler": "Number",
                    "upstream_area_km2": "Number", "length_km": "Number", "discharge_m3s": "Number",
                    "width_m": "Number", "depth_m": "Number", "slope": "Number", "perennial": "Boolean",
                    "lake_id": "Number (absent when none)",
                },
            },
            {
                "id": "lakes",
                "description": "One Polygon per lake",
                "minzoom": 0,
                "maxzoom": max_zoom,
                "fields": {
                    "lake_id": "Number", "water_altitude_m": "Number", "area_km2": "Number", "endorheic": "Boolean",
                },
            },
        ],
    });
    serde_json::to_string_pretty(&doc).expect("JSON serialises")
}

#[cfg(test)]
#[path = "vector_tiles_tests.rs"]
mod tests;
