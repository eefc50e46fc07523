//! Rivers and lakes as GeoJSON (RFC 7946): one Feature per reach of the river network,
//! coordinates `[lon, lat, water_altitude_m]` ordered downstream, altitude relative to sea
//! level; and one per lake.
//!
//! Positions are rounded to 1e-6° (about 0.1 m) and altitudes to 0.01 m. Each reach carries
//! `kind: "river"`, `id` (also as the Feature's `id`), `downstream_id` (the reach it flows into,
//! `null` at a mouth, a closed basin's pit or where the network ends), `strahler`,
//! `upstream_area_km2`, `length_km`, its hydraulics where it ends (`discharge_m3s`, the mean
//! discharge from the planet's climate; `width_m` and `depth_m` of its channel by
//! [`Reach::width_m`]; `perennial`, false for a wadi), `slope` (the water's fall over its length)
//! and `lake_id` (the first lake it flows into or through, else `null`).
//!
//! A lake is a Polygon (a MultiPolygon if its water stands in several pieces) with
//! `kind: "lake"`, `lake_id`, `water_altitude_m`, `area_km2` and `endorheic` (no outlet to the
//! sea); its Feature `id` is `"lake-<lake_id>"`. Its shore is [`crate::planet::lakes::outlines`]:
//! exterior rings counter-clockwise, islands clockwise, every position at the lake's level. A
//! lake's rings are unwrapped across the antimeridian (longitudes may pass ±180° there) rather
//! than cut.
//!
//! **Antimeridian.** Following RFC 7946 §3.1.9, a reach that crosses ±180° is cut there into a
//! MultiLineString: the part before the crossing ends on 180° (or -180°) and the next part starts
//! on the opposite meridian at the same latitude and altitude, both interpolated linearly along
//! the segment. Longitudes therefore always lie in [-180, 180]. Reaches that do not cross stay
//! LineStrings. A reach of a single vertex (a broken network end) is written with its point
//! repeated, so every LineString has two positions and every `downstream_id` still resolves.

use crate::geo::lat_lon;
use crate::mesh::{Mesh, NONE};
use crate::params::Params;
use crate::planet::lakes::{outlines, Lake};
use crate::planet::network::Reach;
use crate::planet::Planet;
use serde_json::{json, Value};

/// Rounds to `decimals` decimal places (dividing by the power of ten prints cleanly).
fn round_to(x: f64, decimals: i32) -> f64 {
    let f = 10f64.powi(decimals);
    let r = (x * f).round() / f;
    // Avoid "-0.0" in the output.
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

/// Cuts a `[lon, lat, alt]` polyline where consecutive longitudes jump by more than 180°.
pub fn split_antimeridian(points: &[[f64; 3]]) -> Vec<Vec<[f64; 3]>> {
    let mut parts = Vec::new();
    let mut current: Vec<[f64; 3]> = Vec::new();
    for &p in points {
        if let Some(&q) = current.last() {
            let d = p[0] - q[0];
            if d.abs() > 180.0 {
                // Eastward across +180 when the jump is negative, westward when positive.
                let edge = if d < 0.0 { 180.0 } else { -180.0 };
                let unwrapped = p[0] + 2.0 * edge;
                let t = if unwrapped != q[0] { ((edge - q[0]) / (unwrapped - q[0])).clamp(0.0, 1.0) } else { 0.0 };
                let lat = q[1] + t * (p[1] - q[1]);
                let alt = q[2] + t * (p[2] - q[2]);
                current.push([edge, lat, alt]);
                parts.push(std::mem::take(&mut current));
                current.push([-edge, lat, alt]);
            }
        }
        current.push(p);
    }
    if !current.is_empty() {
        parts.push(current);
    }
    parts
}

fn coordinates(part: &[[f64; 3]]) -> Value {
    let mut coords: Vec<Value> =
        part.iter().map(|p| json!([round_to(p[0], 6), round_to(p[1], 6), round_to(p[2], 2)])).collect();
    if coords.len() == 1 {
        coords.push(coords[0].clone());
    }
    Value::Array(coords)
}

/// The water's fall over a reach's length.
pub(crate) fn reach_slope(mesh: &Mesh, reach: &Reach) -> f64 {
    let (first, last) = (reach.vertices[0], *reach.vertices.last().unwrap_or(&reach.vertices[0]));
    let fall = mesh.vertices[first as usize].water - mesh.vertices[last as usize].water;
    if reach.length_m > 0.0 {
        fall / reach.length_m
    } else {
        0.0
    }
}

/// The first lake a reach flows into or through.
pub(crate) fn reach_lake(reach: &Reach, lake_of: &[u32]) -> Option<u32> {
    reach.vertices.iter().map(|&v| lake_of.get(v as usize).copied().unwrap_or(NONE)).find(|&l| l != NONE)
}

/// A lake's shore rings as `[lon, lat]`, longitudes unwrapped along each ring (so a ring that
/// crosses ±180° stays one ring, past ±180°).
pub(crate) fn unwrapped_rings(rings: &[Vec<glam::DVec3>]) -> Vec<Vec<[f64; 2]>> {
    rings
        .iter()
        .map(|ring| {
            let mut prev: Option<f64> = None;
            ring.iter()
                .map(|&p| {
                    let (lat, mut lon) = lat_lon(p);
                    if let Some(q) = prev {
                        lon = q + crate::mesh::raster::wrap180(lon - q);
                    }
                    prev = Some(lon);
                    [lon, lat]
                })
                .collect()
        })
        .collect()
}

fn feature(mesh: &Mesh, reach: &Reach, sea_level: f64, lake_of: &[u32]) -> Value {
    let slope = reach_slope(mesh, reach);
    let lake_id = reach_lake(reach, lake_of);
    let points: Vec<[f64; 3]> = reach
        .vertices
        .iter()
        .map(|&v| {
            let (lat, lon) = lat_lon(mesh.pos(v));
            [lon, lat, mesh.vertices[v as usize].water - sea_level]
        })
        .collect();
    let parts = split_antimeridian(&points);
    let geometry = if parts.len() == 1 {
        json!({"type": "LineString", "coordinates": coordinates(&parts[0])})
    } else {
        let lines: Vec<Value> = parts.iter().map(|p| coordinates(p)).collect();
        json!({"type": "MultiLineString", "coordinates": lines})
    };
    json!({
        "type": "Feature",
        "id": reach.id,
        "geometry": geometry,
        "properties": {
            "kind": "river",
            "id": reach.id,
            "downstream_id": reach.downstream_id,
            "strahler": reach.strahler,
            "upstream_area_km2": round_to(reach.upstream_area_m2 / 1e6, 3),
            "length_km": round_to(reach.length_m / 1e3, 3),
            "discharge_m3s": round_to(reach.discharge_m3s, 3),
            "width_m": round_to(reach.width_m(), 2),
            "depth_m": round_to(reach.depth_m(), 2),
            "slope": round_to(slope, 8),
            "perennial": reach.perennial(),
            "lake_id": lake_id,
        },
    })
}

/// Twice the signed area of a `[lon, lat]` ring (positive counter-clockwise).
fn signed_area(ring: &[[f64; 2]]) -> f64 {
    ring.windows(2).map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1]).sum()
}

/// Whether `p` lies inside `ring` (even-odd rule).
fn contains(ring: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut inside = false;
    for w in ring.windows(2) {
        let (a, b) = (w[0], w[1]);
        if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
            inside = !inside;
        }
    }
    inside
}

fn lake_feature(lake: &Lake, rings: &[Vec<glam::DVec3>]) -> Option<Value> {
    let flat = unwrapped_rings(rings);
    let outer: Vec<&Vec<[f64; 2]>> = flat.iter().filter(|r| signed_area(r) > 0.0).collect();
    let holes: Vec<&Vec<[f64; 2]>> = flat.iter().filter(|r| signed_area(r) <= 0.0).collect();
    let level = round_to(lake.water_altitude_m, 2);
    let ring_json =
        |r: &[[f64; 2]]| Value::Array(r.iter().map(|p| json!([round_to(p[0], 6), round_to(p[1], 6), level])).collect());
    let polygons: Vec<Value> = outer
        .iter()
        .map(|o| {
            let mut rings = vec![ring_json(o)];
            rings.extend(holes.iter().filter(|h| contains(o, h[0])).map(|h| ring_json(h)));
            Value::Array(rings)
        })
        .collect();
    let geometry = match polygons.len() {
        0 => return None,
        1 => json!({"type": "Polygon", "coordinates": polygons[0]}),
        _ => json!({"type": "MultiPolygon", "coordinates": polygons}),
    };
    Some(json!({
        "type": "Feature",
        "id": format!("lake-{}", lake.id),
        "geometry": geometry,
        "properties": {
            "kind": "lake",
            "lake_id": lake.id,
            "water_altitude_m": level,
            "area_km2": round_to(lake.area_m2 / 1e6, 3),
            "endorheic": lake.endorheic,
        },
    }))
}

/// The river network and the lakes as a GeoJSON FeatureCollection: one feature per reach,
/// then one per lake.
pub fn rivers_geojson(planet: &Planet, params: &Params) -> String {
    let mesh = &planet.mesh;
    let mut features: Vec<Value> = planet
        .rivers
        .reaches(mesh, &planet.water)
        .iter()
        .map(|r| feature(mesh, r, params.sea_level_m, &planet.lake_of))
        .collect();
    let shores = outlines(mesh, &planet.lake_of, planet.lakes.len());
    features.extend(planet.lakes.iter().filter_map(|l| lake_feature(l, &shores[l.id as usize])));
    json!({"type": "FeatureCollection", "features": features}).to_string()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::test_planet;
    use std::collections::BTreeSet;

    fn lines(geometry: &Value) -> Vec<Vec<[f64; 3]>> {
        let to_pt = |p: &Value| {
            let a = p.as_array().unwrap();
            assert_eq!(a.len(), 3);
            [0, 1, 2].map(|k| a[k].as_f64().unwrap())
        };
        let to_line = |l: &Value| l.as_array().unwrap().iter().map(to_pt).collect::<Vec<_>>();
        match geometry["type"].as_str().unwrap() {
            "LineString" => vec![to_line(&geometry["coordinates"])],
            "MultiLineString" => geometry["coordinates"].as_array().unwrap().iter().map(to_line).collect(),
            t => panic!("unexpected geometry {t}"),
        }
    }

    #[test]
    fn rivers_geojson_is_a_valid_downstream_network() {
        let planet = test_planet();
        let params = Params::default();
        let text = rivers_geojson(planet, &params);
        let doc: Value = serde_json::from_str(&text).expect("valid JSON");
        assert_eq!(doc["type"], "FeatureCollection");
        let features = doc["features"].as_array().unwrap();
        let reaches = planet.rivers.reaches(&planet.mesh, &planet.water);
        assert_eq!(features.len(), reaches.len());
        assert!(!features.is_empty(), "the test planet has rivers");
        let ids: BTreeSet<u64> = features.iter().map(|f| f["properties"]["id"].as_u64().unwrap()).collect();
        assert_eq!(ids.len(), features.len(), "ids are unique");
        let mut linked = 0;
        for (f, r) in features.iter().zip(&reaches) {
            assert_eq!(f["type"], "Feature");
            let props = &f["properties"];
            assert_eq!(f["id"], props["id"]);
            assert_eq!((&props["kind"], &props["lake_id"]), (&json!("river"), &Value::Null));
            match &props["downstream_id"] {
                Value::Null => {}
                d => {
                    assert!(ids.contains(&d.as_u64().unwrap()), "dangling downstream_id {d}");
                    linked += 1;
                }
            }
            assert!(props["strahler"].as_u64().unwrap() >= 1);
            assert!(props["length_km"].as_f64().unwrap() >= 0.0);
            assert!(props["upstream_area_km2"].as_f64().unwrap() >= 0.0);
            let q = props["discharge_m3s"].as_f64().unwrap();
            assert!(q >= 0.0 && props["slope"].as_f64().unwrap() >= 0.0 && props["perennial"].is_boolean());
            assert_eq!(props["width_m"].as_f64().unwrap() > 0.0, q > 0.0, "{props}");
            assert!(props["depth_m"].as_f64().unwrap() < props["width_m"].as_f64().unwrap().max(0.01));
            let parts = lines(&f["geometry"]);
            let flat: Vec<[f64; 3]> = parts.iter().flatten().copied().collect();
            for p in &parts {
                assert!(p.len() >= 2);
            }
            for p in &flat {
                assert!((-180.0..=180.0).contains(&p[0]) && (-90.0..=90.0).contains(&p[1]), "{p:?}");
            }
            for w in flat.windows(2) {
                assert!(w[1][2] <= w[0][2], "reach {} flows uphill: {w:?}", r.id);
            }
            // Starts at the reach's first vertex, in sea-level altitude.
            let v0 = &planet.mesh.vertices[r.vertices[0] as usize];
            assert!((flat[0][2] - (v0.water - params.sea_level_m)).abs() <= 0.006);
            let (lat, lon) = lat_lon(v0.p());
            assert!((flat[0][1] - lat).abs() < 1e-6 && (flat[0][0] - lon).abs() < 1e-6);
        }
        assert!(linked > 0, "some reaches flow into others");
    }

    #[test]
    fn rivers_geojson_is_deterministic() {
        let planet = test_planet();
        let params = Params::default();
        let a = rivers_geojson(planet, &params);
        let mut again = planet.clone();
        again.rivers = crate::planet::RiverGraph::from_mesh(&planet.mesh);
        assert_eq!(a, rivers_geojson(&again, &params));
    }

    #[test]
    fn antimeridian_crossings_split_into_parts() {
        let pts = [[178.0, 0.0, 30.0], [-178.0, 4.0, 10.0], [-176.0, 5.0, 5.0]];
        let parts = split_antimeridian(&pts);
        assert_eq!(parts.len(), 2);
        assert_eq!(parts[0], vec![[178.0, 0.0, 30.0], [180.0, 2.0, 20.0]]);
        assert_eq!(parts[1], vec![[-180.0, 2.0, 20.0], [-178.0, 4.0, 10.0], [-176.0, 5.0, 5.0]]);
        // Westward.
        let parts = split_antimeridian(&[[-179.0, 0.0, 2.0], [179.0, 0.0, 0.0]]);
        assert_eq!(
            parts,
            vec![vec![[-179.0, 0.0, 2.0], [-180.0, 0.0, 1.0]], vec![[180.0, 0.0, 1.0], [179.0, 0.0, 0.0]]]
        );
        // No crossing: one part, untouched.
        let pts = [[10.0, 1.0, 3.0], [12.0, 1.0, 2.0]];
        assert_eq!(split_antimeridian(&pts), vec![pts.to_vec()]);
        let json = coordinates(&[[1.0, 2.0, -0.001]]);
        assert_eq!(json.to_string(), "[[1.0,2.0,0.0],[1.0,2.0,0.0]]");
    }
}
