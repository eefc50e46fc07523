use super::*;
use crate::export::test_planet;

/// A feature as the spec describes it, read by this decoder alone (not the encoder's crate).
#[derive(Debug)]
struct Feat {
    id: u64,
    kind: u64,
    tags: Vec<(String, String)>,
    /// Pieces (lines) or rings (polygons), in tile units.
    paths: Vec<Vec<[i64; 2]>>,
}

fn varint(b: &[u8], at: &mut usize) -> u64 {
    let mut v = 0u64;
    let mut shift = 0;
    loop {
        let byte = b[*at];
        *at += 1;
        v |= u64::from(byte & 0x7f) << shift;
        if byte < 0x80 {
            return v;
        }
        shift += 7;
    }
}

/// Fields of one protobuf message: (number, varint or bytes).
fn fields(b: &[u8]) -> Vec<(u64, Result<u64, Vec<u8>>)> {
    let mut at = 0;
    let mut out = Vec::new();
    while at < b.len() {
        let key = varint(b, &mut at);
        let v = match key & 7 {
            0 => Ok(varint(b, &mut at)),
            1 => {
                at += 8;
                Err(b[at - 8..at].to_vec())
            }
            2 => {
                let n = varint(b, &mut at) as usize;
                at += n;
                Err(b[at - n..at].to_vec())
            }
            5 => {
                at += 4;
                Err(b[at - 4..at].to_vec())
            }
            w => panic!("wire type {w}"),
        };
        out.push((key >> 3, v));
    }
    out
}

fn packed(b: &[u8]) -> Vec<u64> {
    let mut at = 0;
    let mut out = Vec::new();
    while at < b.len() {
        out.push(varint(b, &mut at));
    }
    out
}

/// Layers by name: extent and features.
fn read(tile: &[u8]) -> Vec<(String, u64, Vec<Feat>)> {
    fields(tile)
        .into_iter()
        .filter(|f| f.0 == 3)
        .map(|(_, l)| {
            let l = l.unwrap_err();
            let (mut name, mut extent, mut keys, mut values, mut raw) = (String::new(), 0, vec![], vec![], vec![]);
            for (n, v) in fields(&l) {
                match (n, v) {
                    (1, Err(s)) => name = String::from_utf8(s).unwrap(),
                    (2, Err(f)) => raw.push(f),
                    (3, Err(k)) => keys.push(String::from_utf8(k).unwrap()),
                    (4, Err(v)) => {
                        let (n, v) = fields(&v).remove(0);
                        values.push(match (n, v) {
                            (1, Err(s)) => String::from_utf8(s).unwrap(),
                            (3, Err(d)) => f64::from_le_bytes(d.try_into().unwrap()).to_string(),
                            (5, Ok(u)) => u.to_string(),
                            (7, Ok(b)) => (b != 0).to_string(),
                            other => panic!("value {other:?}"),
                        });
                    }
                    (5, Ok(e)) => extent = e,
                    _ => {}
                }
            }
            let feats = raw
                .iter()
                .map(|f| {
                    let (mut id, mut kind, mut tags, mut geom) = (0, 0, vec![], vec![]);
                    for (n, v) in fields(f) {
                        match (n, v) {
                            (1, Ok(i)) => id = i,
                            (2, Err(t)) => tags = packed(&t),
                            (3, Ok(k)) => kind = k,
                            (4, Err(g)) => geom = packed(&g),
                            _ => {}
                        }
                    }
                    let tags =
                        tags.chunks(2).map(|t| (keys[t[0] as usize].clone(), values[t[1] as usize].clone())).collect();
                    let (mut paths, mut cur, mut at, mut pos) = (vec![], vec![], 0, [0i64, 0]);
                    while at < geom.len() {
                        let (cmd, count) = (geom[at] & 7, geom[at] >> 3);
                        at += 1;
                        if cmd == 7 {
                            continue;
                        }
                        if cmd == 1 && !cur.is_empty() {
                            paths.push(std::mem::take(&mut cur));
                        }
                        for _ in 0..count {
                            let z = |v: u64| ((v >> 1) as i64) ^ -((v & 1) as i64);
                            pos = [pos[0] + z(geom[at]), pos[1] + z(geom[at + 1])];
                            at += 2;
                            cur.push(pos);
                        }
                    }
                    if !cur.is_empty() {
                        paths.push(cur);
                    }
                    Feat { id, kind, tags, paths }
                })
                .collect();
            (name, extent, feats)
        })
        .collect()
}

fn lines() -> &'static RiverLines {
    static L: std::sync::OnceLock<RiverLines> = std::sync::OnceLock::new();
    L.get_or_init(|| RiverLines::new(test_planet()))
}

/// A river feature's kind, fields and positions.
fn check_feature(f: &Feat, z: u8) {
    assert_eq!(f.kind, 2, "a LineString");
    let tag = |k: &str| f.tags.iter().find(|t| t.0 == k).map(|t| t.1.clone());
    assert_eq!(tag("id").unwrap(), f.id.to_string());
    let order: u32 = tag("strahler").unwrap().parse().unwrap();
    assert!(order >= min_strahler(z));
    for k in ["upstream_area_km2", "discharge_m3s", "width_m", "depth_m", "slope", "perennial", "length_km"] {
        assert!(tag(k).is_some(), "{k}");
    }
    for p in f.paths.iter().flatten() {
        assert!((-64..=4160).contains(&p[0]) && (-64..=4160).contains(&p[1]), "{p:?}");
    }
    assert!(f.paths.iter().all(|p| p.len() >= 2));
}

#[test]
fn tiles_hold_the_reaches_that_matter_at_their_zoom() {
    let planet = test_planet();
    let reaches = planet.rivers.reaches(&planet.mesh, &planet.water);
    // The zoom where the largest order starts: its reaches, and no other, in the tiles; none
    // a zoom above.
    let top = reaches.iter().map(|r| r.strahler).max().unwrap();
    let z0 = (9 - top.min(8)) as u8;
    let mut seen = std::collections::BTreeSet::new();
    for tx in 0..1u32 << z0 {
        for ty in 0..1u32 << z0 {
            let layers = read(&river_tile(lines(), z0, tx, ty).unwrap());
            let names: Vec<&str> = layers.iter().map(|l| l.0.as_str()).collect();
            assert_eq!(names, ["rivers", "lakes"]);
            assert_eq!(layers[0].1, 4096);
            for f in &layers[0].2 {
                check_feature(f, z0);
                seen.insert(f.id);
            }
        }
    }
    let want: std::collections::BTreeSet<u64> =
        reaches.iter().filter(|r| r.strahler >= min_strahler(z0)).map(|r| r.id as u64).collect();
    assert!(!want.is_empty());
    assert_eq!(seen, want);
    if z0 > 0 {
        let layers = read(&river_tile(lines(), z0 - 1, 0, 0).unwrap());
        assert!(layers[0].2.is_empty());
    }
    // Deeper: every order, and a reach's position where the projection puts it.
    let r = reaches.iter().find(|r| r.strahler == 1 && r.vertices.len() >= 2).unwrap();
    let (lat, lon) = lat_lon(planet.mesh.pos(r.vertices[0]));
    let z = 9u8;
    let n = f64::from(1u32 << z);
    let tx = ((lon + 180.0) / 360.0 * n).floor() as u32;
    let ty = ((1.0 - lat.to_radians().tan().asinh() / std::f64::consts::PI) / 2.0 * n).floor() as u32;
    let layers = read(&river_tile(lines(), z, tx, ty).unwrap());
    let f = layers[0].2.iter().find(|f| f.id == r.id as u64).expect("the reach in its tile");
    let want = project([lon, lat], z, tx, ty, 0.0);
    let first = f.paths[0][0];
    assert!((first[0] as f64 - want[0]).abs() <= 1.0 && (first[1] as f64 - want[1]).abs() <= 1.0, "{first:?} {want:?}");
}

#[test]
fn lines_and_rings_are_clipped_to_the_buffered_tile() {
    let pieces = clip_line(&[[-100.0, 10.0], [50.0, 10.0], [50.0, 5000.0], [60.0, 4000.0], [60.0, 3000.0]], 0.0, 100.0);
    assert_eq!(pieces, vec![vec![[0.0, 10.0], [50.0, 10.0], [50.0, 100.0]]]);
    let pieces = clip_line(&[[10.0, 10.0], [10.0, 200.0], [20.0, 200.0], [20.0, 10.0]], 0.0, 100.0);
    assert_eq!(pieces.len(), 2);
    let ring = clip_ring(&[[-10.0, -10.0], [50.0, -10.0], [50.0, 50.0], [-10.0, 50.0]], 0.0, 100.0);
    assert!((area(&ring).abs() - 2500.0).abs() < 1e-9, "{ring:?}");
    assert!(clip_ring(&[[200.0, 200.0], [300.0, 200.0], [300.0, 300.0]], 0.0, 100.0).is_empty());
    // Clockwise on screen (y down) is positive: the spec's exterior.
    assert!(area(&[[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]) > 0.0);
}

#[test]
fn tilejson_names_both_layers() {
    let doc: serde_json::Value =
        serde_json::from_str(&tilejson("earth", "http://h/v1/planets/earth/rivers", MAX_ZOOM)).unwrap();
    assert_eq!(doc["tiles"][0], "http://h/v1/planets/earth/rivers/{z}/{x}/{y}.mvt");
    let ids: Vec<&str> = doc["vector_layers"].as_array().unwrap().iter().map(|l| l["id"].as_str().unwrap()).collect();
    assert_eq!(ids, ["rivers", "lakes"]);
    assert!(doc["vector_layers"][0]["fields"]["discharge_m3s"].is_string());
}
