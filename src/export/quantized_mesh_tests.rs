use super::*;
use crate::export::test_planet;
use crate::params::Params;
use std::sync::{Arc, OnceLock};

fn tiles() -> &'static PlanetTiles {
    static TILES: OnceLock<PlanetTiles> = OnceLock::new();
    TILES.get_or_init(|| {
        let params = Params { base_faces: 2000, ..Params::default() };
        PlanetTiles::new(Arc::new(test_planet().clone()), params).expect("a bisection refinement")
    })
}

/// A tile as the spec describes it, read by this decoder alone (not the encoder's crate).
#[derive(Debug)]
struct Read {
    min_h: f32,
    max_h: f32,
    u: Vec<u16>,
    v: Vec<u16>,
    h: Vec<u16>,
    triangles: Vec<[u32; 3]>,
    /// West, south, east, north.
    edges: [Vec<u32>; 4],
    /// Extension id and its bytes, in file order.
    extensions: Vec<(u8, Vec<u8>)>,
}

impl Read {
    fn height(&self, k: usize) -> f64 {
        f64::from(self.min_h) + f64::from(self.h[k]) / 32767.0 * (f64::from(self.max_h) - f64::from(self.min_h))
    }

    fn step(&self) -> f64 {
        (f64::from(self.max_h) - f64::from(self.min_h)) / 32767.0
    }
}

/// Reads quantized-mesh-1.0 bytes (little-endian; zig-zag deltas; high-water-mark indices;
/// 32-bit indices past 65,536 vertices, 4-byte aligned).
fn read(b: &[u8]) -> Read {
    struct Cursor<'a> {
        b: &'a [u8],
        at: usize,
    }
    impl<'a> Cursor<'a> {
        fn take(&mut self, n: usize) -> &'a [u8] {
            let s = &self.b[self.at..self.at + n];
            self.at += n;
            s
        }
        fn u32(&mut self) -> u32 {
            u32::from_le_bytes(self.take(4).try_into().unwrap())
        }
        fn f32(&mut self) -> f32 {
            f32::from_le_bytes(self.take(4).try_into().unwrap())
        }
        fn index(&mut self, wide: bool) -> u32 {
            if wide {
                self.u32()
            } else {
                u32::from(u16::from_le_bytes(self.take(2).try_into().unwrap()))
            }
        }
        /// `n` zig-zag coded deltas.
        fn stream(&mut self, n: usize) -> Vec<u16> {
            let raw = self.take(2 * n);
            let mut value = 0i32;
            (0..n)
                .map(|k| {
                    let z = i32::from(u16::from_le_bytes([raw[2 * k], raw[2 * k + 1]]));
                    value += (z >> 1) ^ -(z & 1);
                    value as u16
                })
                .collect()
        }
    }
    let mut c = Cursor { b, at: 0 };
    let _center = c.take(24);
    let min_h = c.f32();
    let max_h = c.f32();
    let _sphere = c.take(32);
    let _horizon = c.take(24);
    let n = c.u32() as usize;
    let u = c.stream(n);
    let v = c.stream(n);
    let h = c.stream(n);
    let wide = n > 65536;
    if wide && !c.at.is_multiple_of(4) {
        c.take(4 - c.at % 4);
    } else if !wide && !c.at.is_multiple_of(2) {
        c.take(1);
    }
    let count = c.u32() as usize;
    let mut highest = 0u32;
    let mut flat = Vec::with_capacity(count * 3);
    for _ in 0..count * 3 {
        let code = c.index(wide);
        flat.push(highest - code);
        if code == 0 {
            highest += 1;
        }
    }
    let triangles = flat.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
    let mut edges: [Vec<u32>; 4] = Default::default();
    for e in &mut edges {
        let k = c.u32() as usize;
        *e = (0..k).map(|_| c.index(wide)).collect();
    }
    let mut extensions = Vec::new();
    while c.at < b.len() {
        let id = c.take(1)[0];
        let len = c.u32() as usize;
        extensions.push((id, c.take(len).to_vec()));
    }
    Read { min_h, max_h, u, v, h, triangles, edges, extensions }
}

#[test]
fn tiles_follow_the_geographic_scheme() {
    let b = tile_bounds(0, 1, 0).unwrap();
    assert_eq!((b.west, b.south, b.east, b.north), (0.0, -90.0, 180.0, 90.0));
    let b = tile_bounds(3, 0, 7).unwrap();
    assert_eq!((b.west, b.south, b.east, b.north), (-180.0, 67.5, -157.5, 90.0));
    assert_eq!(tile_bounds(0, 2, 0), Err(TileError::Outside));
    assert_eq!(tile_bounds(2, 0, 4), Err(TileError::Outside));
    assert_eq!(tile_bounds(MAX_ZOOM + 1, 0, 0), Err(TileError::TooDeep));
}

#[test]
fn accept_headers_choose_the_extensions() {
    let cesium = "application/vnd.quantized-mesh;extensions=octvertexnormals-watermask-metadata,\
                  application/octet-stream;q=0.9,*/*;q=0.01";
    assert_eq!(Extensions::from_accept(cesium), Extensions::ALL);
    let e = Extensions::from_accept("application/vnd.quantized-mesh;extensions=watermask");
    assert_eq!(e, Extensions { water_mask: true, ..Default::default() });
    assert_eq!(e.key(), "watermask");
    assert_eq!(Extensions::from_accept("*/*"), Extensions::default());
    assert_eq!(Extensions::from_accept("application/json;extensions=watermask"), Extensions::default());
    assert_eq!(Extensions::ALL.key(), "octvertexnormals-watermask-metadata");
}

#[test]
fn a_tile_is_the_planets_surface_on_a_grid() {
    let (z, x, y) = (2, 5, 1);
    let bytes = terrain_tile(tiles(), (z, x, y), Extensions::default(), MAX_ZOOM).unwrap();
    let t = read(&bytes);
    let side = (GRID + 1) as usize;
    assert_eq!(t.u.len(), side * side);
    assert_eq!(t.triangles.len(), (GRID * GRID * 2) as usize);
    assert!(t.extensions.is_empty());
    // Every triangle counter-clockwise in (u, v) and of non-zero area.
    for tri in &t.triangles {
        let p = tri.map(|k| (f64::from(t.u[k as usize]), f64::from(t.v[k as usize])));
        let area = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
        assert!(area > 0.0, "{tri:?}");
    }
    // Edge lists hold exactly the border vertices, in order along their side.
    let [west, south, east, north] = &t.edges;
    for (list, fixed, want) in [(west, 'u', 0u16), (east, 'u', 32767), (south, 'v', 0), (north, 'v', 32767)] {
        assert_eq!(list.len(), side);
        for &k in list.iter() {
            let c = if fixed == 'u' { t.u[k as usize] } else { t.v[k as usize] };
            assert_eq!(c, want);
        }
    }
    assert!(west.windows(2).all(|w| t.v[w[0] as usize] < t.v[w[1] as usize]));
    assert!(south.windows(2).all(|w| t.u[w[0] as usize] < t.u[w[1] as usize]));
    // Heights: the planet's visible surface at each vertex, as `dem.tif` samples it.
    let b = tile_bounds(z, x, y).unwrap();
    let step = (b.east - b.west) / f64::from(GRID);
    let interior = points(b.west + step, b.north - step, GRID - 1, GRID - 1, step);
    let dem = crate::export::dem::sample_dem(tiles(), &interior);
    let mut checked = 0;
    for k in 0..t.u.len() {
        let (i, j) = (u32::from(t.u[k]) * GRID / 32767, GRID - u32::from(t.v[k]) * GRID / 32767);
        if i == 0 || j == 0 || i == GRID || j == GRID {
            continue;
        }
        let want = top(&dem, ((j - 1) * (GRID - 1) + i - 1) as usize);
        assert!((t.height(k) - want).abs() <= t.step(), "vertex {k}: {} against {want}", t.height(k));
        checked += 1;
    }
    assert_eq!(checked, ((GRID - 1) * (GRID - 1)) as usize);
    assert!(t.max_h > t.min_h + 100.0, "a tile of a quarter of the planet has relief");
}

/// Heights along tile `a`'s side `sa` and tile `b`'s side `sb` (each in its list's order).
fn side_heights(a: &Read, side: usize) -> Vec<f64> {
    a.edges[side].iter().map(|&k| a.height(k as usize)).collect()
}

#[test]
fn neighbours_share_their_borders() {
    let t = tiles();
    let get = |z, x, y| read(&terrain_tile(t, (z, x, y), Extensions::default(), MAX_ZOOM).unwrap());
    for (z, x, y) in [(3u8, 4u32, 2u32), (5, 40, 20), (1, 3, 0), (4, 0, 9)] {
        let here = get(z, x, y);
        // East neighbour (across the antimeridian for the last column), then north.
        let east = get(z, (x + 1) % (2 << z), y);
        let (a, b) = (side_heights(&here, 2), side_heights(&east, 0));
        let tol = here.step().max(east.step()) + 1e-3;
        for (p, q) in a.iter().zip(&b) {
            assert!((p - q).abs() <= tol, "{z}/{x}/{y} east side {p} against {q}");
        }
        if y + 1 < 1 << z {
            let north = get(z, x, y + 1);
            let (a, b) = (side_heights(&here, 3), side_heights(&north, 1));
            let tol = here.step().max(north.step()) + 1e-3;
            for (p, q) in a.iter().zip(&b) {
                assert!((p - q).abs() <= tol, "{z}/{x}/{y} north side {p} against {q}");
            }
        }
    }
}

#[test]
fn extensions_are_written_when_asked() {
    let t = tiles();
    // A tile with both land and sea: its mask is a grid.
    let mixed = (0..8u32)
        .flat_map(|x| (0..4u32).map(move |y| (x, y)))
        .map(|(x, y)| read(&terrain_tile(t, (2, x, y), Extensions::ALL, MAX_ZOOM).unwrap()))
        .find(|r| r.extensions.iter().any(|(id, b)| *id == 2 && b.len() == 65536))
        .expect("a level-2 tile with a coast");
    let ids: Vec<u8> = mixed.extensions.iter().map(|e| e.0).collect();
    assert_eq!(ids, vec![1, 2, 4]);
    let normals = &mixed.extensions[0].1;
    assert_eq!(normals.len(), 2 * mixed.u.len());
    let mask = &mixed.extensions[1].1;
    assert!(mask.iter().all(|&m| m == 0 || m == 255));
    let meta = &mixed.extensions[2].1;
    let len = u32::from_le_bytes(meta[..4].try_into().unwrap()) as usize;
    let json: serde_json::Value = serde_json::from_slice(&meta[4..4 + len]).unwrap();
    assert_eq!(json["available"].as_array().unwrap().len(), usize::from(METADATA_LEVELS));
    // Normals decode to unit vectors and vary with the relief.
    let decode = |b: &[u8]| {
        let f = |c: u8| (f32::from(c) / 255.0 * 2.0 - 1.0).clamp(-1.0, 1.0);
        let (mut x, mut y) = (f(b[0]), f(b[1]));
        let z = 1.0 - x.abs() - y.abs();
        if z < 0.0 {
            let ox = x;
            x = (1.0 - y.abs()) * ox.signum();
            y = (1.0 - ox.abs()) * y.signum();
        }
        glam::Vec3::new(x, y, z).normalize()
    };
    let distinct: std::collections::HashSet<[u8; 2]> = normals.chunks(2).map(|c| [c[0], c[1]]).collect();
    assert!(distinct.len() > 20);
    assert!(decode(&normals[..2]).is_finite());
    // Selected extensions only.
    let one = read(&terrain_tile(t, (2, 0, 0), Extensions { metadata: true, ..Default::default() }, MAX_ZOOM).unwrap());
    assert_eq!(one.extensions.iter().map(|e| e.0).collect::<Vec<_>>(), vec![4]);
    // The deepest level lists no descendants.
    let deepest = read(&terrain_tile(t, (MAX_ZOOM, 0, 0), Extensions::ALL, MAX_ZOOM).unwrap());
    assert_eq!(deepest.extensions.iter().map(|e| e.0).collect::<Vec<_>>(), vec![1, 2]);
}

#[test]
fn the_encoders_crate_reads_what_this_decoder_reads() {
    let bytes = terrain_tile(tiles(), (3, 9, 5), Extensions::ALL, MAX_ZOOM).unwrap();
    let ours = read(&bytes);
    let theirs = quantized_mesh::DecodedMesh::decode(&bytes).unwrap();
    assert_eq!(theirs.vertices.height, ours.h);
    assert_eq!(theirs.indices, ours.triangles.concat());
    assert_eq!(theirs.edge_indices.north, ours.edges[3]);
}

#[test]
fn layer_json_names_the_tiles() {
    let doc: serde_json::Value = serde_json::from_str(&layer_json("earth", "abc", MAX_ZOOM)).unwrap();
    assert_eq!(doc["format"], "quantized-mesh-1.0");
    assert_eq!(doc["tiles"][0], "{z}/{x}/{y}.terrain?v={version}");
    assert_eq!(doc["version"], "abc");
    let available = doc["available"].as_array().unwrap();
    assert_eq!(available.len(), usize::from(MAX_ZOOM) + 1);
    assert_eq!(available[0][0]["endX"], 1);
    assert_eq!(available[3][0]["endY"], 7);
}

/// Borders of the built-in Earth's tiles on and near the octahedron's edges (the equator and
/// the meridians 0°, 90°E, 180°, 90°W), where two tiles' refined regions may lie in different
/// root triangles.
#[test]
fn earth_borders_on_octahedron_edges() {
    let Some(planet) = crate::planet::tests_relief::earth() else { return };
    let t = PlanetTiles::new(Arc::new(planet.clone()), Params::default()).unwrap();
    let get = |z, x, y| read(&terrain_tile(&t, (z, x, y), Extensions::default(), MAX_ZOOM).unwrap());
    let (mut checked, mut bad) = (0, 0);
    for z in 2u8..=7 {
        let w = 2u32 << z;
        let h = 1u32 << z;
        let mut sides = Vec::new();
        // East sides on the meridians 0, 90E, 180, 90W and one column beside each.
        for col in [0, w / 4, w / 2, 3 * w / 4] {
            for dx in [0, 1] {
                let x = (col + w - 1 + dx) % w;
                for y in (0..h).step_by((h as usize / 8).max(1)) {
                    sides.push((x, y, true));
                }
            }
        }
        // North sides on the equator and one row beside it.
        for dy in [0, 1] {
            let y = (h / 2 + dy).saturating_sub(1);
            for x in (0..w).step_by((w as usize / 16).max(1)) {
                sides.push((x, y, false));
            }
        }
        for (x, y, east) in sides {
            if !east && y + 1 >= h {
                continue;
            }
            let here = get(z, x, y);
            let (other, sa, sb) = if east { (get(z, (x + 1) % w, y), 2, 0) } else { (get(z, x, y + 1), 3, 1) };
            let (a, b) = (side_heights(&here, sa), side_heights(&other, sb));
            let tol = here.step().max(other.step()) + 1e-3;
            let diffs: Vec<f64> = a.iter().zip(&b).map(|(p, q)| (p - q).abs()).collect();
            let worst = diffs.iter().copied().fold(0.0, f64::max);
            let at: Vec<usize> = (0..diffs.len()).filter(|&i| diffs[i] > tol).collect();
            checked += 1;
            if worst > tol {
                bad += 1;
                let b = tile_bounds(z, x, y).unwrap();
                println!(
                    "{z}/{x}/{y} {} side: worst {worst:.1} m at {at:?} of {} (bounds {:?})",
                    if east { "east" } else { "north" },
                    diffs.len(),
                    b
                );
            }
        }
    }
    println!("{bad} of {checked} sides differ");
    assert_eq!(bad, 0);
}
