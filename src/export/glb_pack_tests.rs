use super::*;
use crate::export::glb::tests::parse;
use crate::export::glb::{encode_glb, GlbMesh};
use crate::export::test_planet;
use crate::export::tiles::{PlanetTiles, TileKey};
use crate::params::Params;
use serde_json::Value;
use std::sync::{Arc, OnceLock};

fn tiles() -> &'static PlanetTiles {
    static TILES: OnceLock<PlanetTiles> = OnceLock::new();
    TILES.get_or_init(|| {
        let params = Params { base_faces: 2000, ..Params::default() };
        PlanetTiles::new(Arc::new(test_planet().clone()), params).unwrap()
    })
}

/// A `.glb` with its views in plain bytes: a compressed one's meshopt streams decoded (by the
/// meshoptimizer library's decoder) into the fallback buffer's layout.
fn unpack(glb: &[u8]) -> (Value, Vec<u8>) {
    let p = parse(glb);
    let Some(buffers) = p.value["buffers"].as_array() else { return (p.value, p.bin) };
    if buffers.len() < 2 {
        return (p.value, p.bin);
    }
    assert_eq!(buffers[1]["extensions"]["EXT_meshopt_compression"]["fallback"], true);
    assert!(buffers[1].get("uri").is_none(), "the fallback buffer holds no bytes");
    let mut plain = vec![0u8; buffers[1]["byteLength"].as_u64().unwrap() as usize];
    for view in p.value["bufferViews"].as_array().unwrap() {
        assert_eq!(view["buffer"], 1, "every view points into the fallback buffer");
        let ext = &view["extensions"]["EXT_meshopt_compression"];
        let at = |v: &Value, k: &str| v[k].as_u64().unwrap() as usize;
        let stream = &p.bin[at(ext, "byteOffset")..at(ext, "byteOffset") + at(ext, "byteLength")];
        let (count, stride) = (at(ext, "count"), at(ext, "byteStride"));
        let bytes: Vec<u8> = match ext["mode"].as_str().unwrap() {
            "ATTRIBUTES" => {
                assert_eq!(stream[0], 0xa0, "vertex codec version 0");
                let bytes = match stride {
                    4 => meshopt::decode_vertex_buffer::<[u8; 4]>(stream, count).unwrap().concat(),
                    8 => meshopt::decode_vertex_buffer::<[u8; 8]>(stream, count).unwrap().concat(),
                    12 => meshopt::decode_vertex_buffer::<[u8; 12]>(stream, count).unwrap().concat(),
                    s => panic!("stride {s}"),
                };
                unfilter(ext["filter"].as_str(), stride, bytes)
            }
            "TRIANGLES" => {
                assert_eq!(stream[0], 0xe1, "index codec version 1");
                let idx = meshopt::decode_index_buffer::<u32>(stream, count).unwrap();
                match stride {
                    2 => idx.iter().flat_map(|&i| (i as u16).to_le_bytes()).collect(),
                    _ => idx.iter().flat_map(|&i| i.to_le_bytes()).collect(),
                }
            }
            "INDICES" => {
                let idx = meshopt::decode_index_sequence::<u32>(stream, count).unwrap();
                match stride {
                    2 => idx.iter().flat_map(|&i| (i as u16).to_le_bytes()).collect(),
                    _ => idx.iter().flat_map(|&i| i.to_le_bytes()).collect(),
                }
            }
            m => panic!("mode {m}"),
        };
        assert_eq!(bytes.len(), at(view, "byteLength"));
        let start = at(view, "byteOffset");
        plain[start..start + bytes.len()].copy_from_slice(&bytes);
    }
    (p.value, plain)
}

/// A view's bytes as its filter gives them back (meshoptimizer's decoders).
fn unfilter(filter: Option<&str>, stride: usize, bytes: Vec<u8>) -> Vec<u8> {
    match (filter, stride) {
        (None, _) => bytes,
        (Some("OCTAHEDRAL"), 4) => {
            let mut v: Vec<[i8; 4]> = bytes.chunks_exact(4).map(|c| std::array::from_fn(|k| c[k] as i8)).collect();
            meshopt::decode_filter_oct(&mut v);
            v.iter().flatten().map(|&x| x as u8).collect()
        }
        (Some("EXPONENTIAL"), 12) => {
            let mut v: Vec<[u32; 3]> = bytes
                .chunks_exact(12)
                .map(|c| std::array::from_fn(|k| u32::from_le_bytes(c[4 * k..4 * k + 4].try_into().unwrap())))
                .collect();
            meshopt::decode_filter_exp(&mut v);
            v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect()
        }
        (f, s) => panic!("filter {f:?} on {s}-byte vertices"),
    }
}

/// The values of accessor `i` as numbers (normalized components scaled to -1..1 or 0..1).
fn values(json: &Value, bin: &[u8], i: usize) -> Vec<Vec<f64>> {
    let acc = &json["accessors"][i];
    let view = &json["bufferViews"][acc["bufferView"].as_u64().unwrap() as usize];
    let width = match acc["type"].as_str().unwrap() {
        "SCALAR" => 1,
        "VEC3" => 3,
        "VEC4" => 4,
        t => panic!("type {t}"),
    };
    let (size, normalized) = (
        match acc["componentType"].as_u64().unwrap() {
            5120 | 5121 => 1,
            5122 | 5123 => 2,
            _ => 4,
        },
        acc["normalized"].as_bool().unwrap_or(false),
    );
    let stride = view["byteStride"].as_u64().map_or(size * width, |s| s as usize);
    let start = view["byteOffset"].as_u64().unwrap_or(0) as usize;
    let component = |at: usize| -> f64 {
        let b = &bin[at..at + size];
        match acc["componentType"].as_u64().unwrap() {
            5120 => (b[0] as i8) as f64 / if normalized { 127.0 } else { 1.0 },
            5121 => b[0] as f64 / if normalized { 255.0 } else { 1.0 },
            5122 => i16::from_le_bytes([b[0], b[1]]) as f64,
            5123 => u16::from_le_bytes([b[0], b[1]]) as f64,
            5125 => u32::from_le_bytes(b.try_into().unwrap()) as f64,
            5126 => f32::from_le_bytes(b.try_into().unwrap()) as f64,
            c => panic!("component {c}"),
        }
    };
    (0..acc["count"].as_u64().unwrap() as usize)
        .map(|e| (0..width).map(|k| component(start + e * stride + k * size)).collect())
        .collect()
}

/// Per node: positions (translation + scale x position), normals, colours and indices.
type Decoded = Vec<(Vec<[f64; 3]>, Vec<Vec<f64>>, Vec<Vec<f64>>, Vec<f64>)>;

fn decode(glb: &[u8]) -> Decoded {
    let (json, bin) = unpack(glb);
    json["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|node| {
            let t: Vec<f64> = node
                .get("translation")
                .map_or(vec![0.0; 3], |t| t.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect());
            let s = node.get("scale").map_or(1.0, |s| s[0].as_f64().unwrap());
            let prim = &json["meshes"][node["mesh"].as_u64().unwrap() as usize]["primitives"][0];
            let get =
                |name: &str| prim["attributes"].get(name).map(|a| values(&json, &bin, a.as_u64().unwrap() as usize));
            let positions = get("POSITION").unwrap().iter().map(|p| std::array::from_fn(|k| t[k] + s * p[k])).collect();
            let indices = values(&json, &bin, prim["indices"].as_u64().unwrap() as usize).concat();
            (positions, get("NORMAL").unwrap_or_default(), get("COLOR_0").unwrap_or_default(), indices)
        })
        .collect()
}

/// Triangles, each rotated to start at its least index: the index codec keeps the order of
/// triangles and their winding, not which corner comes first.
fn rotated(indices: &[f64]) -> Vec<[u32; 3]> {
    indices
        .chunks_exact(3)
        .map(|t| {
            let t = [t[0] as u32, t[1] as u32, t[2] as u32];
            let first = (0..3).min_by_key(|&i| t[i]).unwrap();
            [t[first], t[(first + 1) % 3], t[(first + 2) % 3]]
        })
        .collect()
}

/// For each vertex of `packed`, the index of its twin in `plain`: the nearest, which must lie
/// within `tolerance` in each component, and no plain vertex twice.
fn twins(plain: &[[f64; 3]], packed: &[[f64; 3]], tolerance: f64) -> Vec<usize> {
    let cell = |p: &[f64; 3]| p.map(|x| (x / (4.0 * tolerance)).floor() as i64);
    let mut grid: std::collections::HashMap<[i64; 3], Vec<usize>> = Default::default();
    for (i, p) in plain.iter().enumerate() {
        grid.entry(cell(p)).or_default().push(i);
    }
    let mut used = vec![false; plain.len()];
    packed
        .iter()
        .map(|q| {
            let c = cell(q);
            let near = (0..27).flat_map(|d| grid.get(&[c[0] + d % 3 - 1, c[1] + d / 3 % 3 - 1, c[2] + d / 9 - 1]));
            let distance = |i: &usize| (0..3).map(|k| (plain[*i][k] - q[k]).abs()).fold(0.0, f64::max);
            let i = *near.flatten().min_by(|a, b| distance(a).total_cmp(&distance(b))).expect("a twin nearby");
            assert!(distance(&i) <= tolerance, "{q:?} is {} from {:?}", distance(&i), plain[i]);
            assert!(!std::mem::replace(&mut used[i], true), "{:?} twice", plain[i]);
            i
        })
        .collect()
}

/// The angle (degrees) between two directions.
fn degrees(a: &[f64], b: &[f64]) -> f64 {
    let dot: f64 = (0..3).map(|k| a[k] * b[k]).sum();
    let norm = |v: &[f64]| (0..3).map(|k| v[k] * v[k]).sum::<f64>().sqrt();
    (dot / norm(a) / norm(b)).clamp(-1.0, 1.0).acos().to_degrees()
}

/// Largest angle between a unit normal and its 8-bit octahedral encoding.
const OCTAHEDRAL_ERROR_DEG: f64 = 1.25;

/// A compressed tile decodes to the plain one: the same vertices (positions within half a
/// step, normals within [`OCTAHEDRAL_ERROR_DEG`], colours exactly) in another order, the same
/// triangles with the same winding; about half the bytes; quantized where fine enough.
#[test]
fn a_compressed_tile_decodes_to_the_plain_one() {
    let t = tiles();
    let deep = (0..t.max_level()).fold(TileKey::root(2), |k, i| k.child(i % 4));
    assert!(deep.level >= 8, "the test planet tiles down to level 8 at least");
    for key in [TileKey::root(0), TileKey::root(5).child(2), deep] {
        let plain = t.content(key, Compression::None).glb;
        let packed = t.content(key, Compression::Meshopt).glb;
        // Half the bytes or less (the river lines' few streams weigh most: their codecs' headers
        // on buffers of tens of vertices), and under half of the 45-49 KiB tiles had before
        // compression.
        assert!(
            packed.len() * 100 <= plain.len() * 48 && packed.len() <= 22 * 1024,
            "{key}: {} of {} bytes",
            packed.len(),
            plain.len()
        );
        let p = parse(&packed);
        assert!(p.root.extensions_required.iter().any(|e| e == "EXT_meshopt_compression"), "{key}");
        let terrain_quantized = p.value["nodes"][0].get("scale").is_some();
        assert_eq!(
            terrain_quantized,
            key == deep,
            "{key}: terrain quantized only in the deepest tile (steps <= 1 m from level 8)"
        );
        let (a, b) = (decode(&plain), decode(&packed));
        assert_eq!(a.len(), b.len());
        for (node, (a, b)) in a.iter().zip(&b).enumerate() {
            // Half an i16 step (the node's scale), or half the largest step of filtered f32
            // positions.
            let step = p.value["nodes"][node]["scale"][0].as_f64();
            let tolerance = step.unwrap_or(MAX_POSITION_STEP_M) / 2.0 + 1e-3;
            assert_eq!(b.0.len(), a.0.len(), "{key} node {node}: vertex count");
            let twin = twins(&a.0, &b.0, tolerance);
            for (j, &i) in twin.iter().enumerate() {
                if !a.1.is_empty() {
                    let angle = degrees(&a.1[i], &b.1[j]);
                    assert!(angle <= OCTAHEDRAL_ERROR_DEG, "{key} node {node}: normal {angle}° off");
                }
                assert_eq!(a.2[i], b.2[j], "{key} node {node}: colours");
            }
            let mut want = rotated(&a.3);
            let as_plain: Vec<f64> = b.3.iter().map(|&v| twin[v as usize] as f64).collect();
            let mut got = rotated(&as_plain);
            want.sort_unstable();
            got.sort_unstable();
            assert!(want == got, "{key} node {node}: triangles differ");
        }
    }
}

/// Quantization is refused where a step would not be small against the shortest edge: a
/// triangle a metre across beside a point 10 km away keeps `f32`, and the `.glb` says so.
#[test]
fn positions_stay_float_where_a_step_is_too_coarse() {
    let near = GlbMesh {
        positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [10_000.0, 0.0, 0.0]],
        indices: vec![0, 1, 2, 1, 3, 2],
        translation: Some([6_371_000.5, 0.25, -3.0]),
        ..Default::default()
    };
    let limit = |m: &GlbMesh| position_step_limit(shortest_edge(&m.positions, &m.indices, false));
    assert_eq!(limit(&near), 1.0 / POSITION_STEPS_PER_EDGE);
    assert!(quantize_positions(&near.positions, limit(&near)).is_none());
    let filtered = filter_positions(&near.positions, limit(&near)).unwrap();
    assert!(filtered.bits < 24, "{} bits", filtered.bits);
    let fine = [[0.0013, 0.0, 0.0], [10_000.0, 0.0, 0.0]];
    assert!(filter_positions(&fine, 1e-4).is_none(), "a step 1e-8 of the extent needs over 24 bits");
    let far = GlbMesh {
        positions: vec![[0.0, 0.0, 0.0], [500.0, 0.0, 0.0], [0.0, 500.0, 0.0]],
        indices: vec![0, 1, 2],
        ..near.clone()
    };
    assert_eq!(limit(&far), MAX_POSITION_STEP_M);
    let q = quantize_positions(&far.positions, limit(&far)).unwrap();
    assert!((q.step - 250.0 / 32767.0).abs() < 1e-12 && q.centre == [250.0, 250.0, 0.0], "{q:?}");

    let glb = encode_glb(&[near.clone(), far.clone()], Compression::Meshopt).unwrap();
    let p = parse(&glb);
    let component = |node: usize| {
        p.value["accessors"]
            [p.value["meshes"][node]["primitives"][0]["attributes"]["POSITION"].as_u64().unwrap() as usize]
            ["componentType"]
            .as_u64()
    };
    assert_eq!((component(0), component(1)), (Some(5126), Some(5122)), "f32, then i16");
    let filters: Vec<&str> = p.value["bufferViews"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|v| v["extensions"]["EXT_meshopt_compression"]["filter"].as_str())
        .collect();
    assert_eq!(filters, ["EXPONENTIAL"], "the f32 positions only (no normals here)");
    let decoded = decode(&glb);
    for (m, (positions, ..)) in [&near, &far].iter().zip(&decoded) {
        let t = m.translation.unwrap();
        for (p, q) in m.positions.iter().zip(positions) {
            assert!((0..3).all(|k| (t[k] + f64::from(p[k]) - q[k]).abs() < 0.01), "{p:?} vs {q:?}");
        }
    }
    assert_eq!(rotated(&decoded[0].3), vec![[0, 1, 2], [1, 3, 2]]);
}

/// Same meshes, same bytes; and `parse` names the query values.
#[test]
fn compression_is_deterministic_and_named() {
    let key = TileKey::root(7).child(0);
    assert_eq!(tiles().content(key, Compression::Meshopt).glb, tiles().content(key, Compression::Meshopt).glb);
    for c in [Compression::None, Compression::Meshopt] {
        assert_eq!(Compression::parse(c.as_str()), Some(c));
    }
    assert_eq!(Compression::parse("draco"), None);
    assert_eq!(Compression::default(), Compression::Meshopt);
}

/// Line segments (a view's rivers) compress as an index sequence and keep their order: the
/// compressed `.glb` decodes to the plain one's segments, vertices within half a step, colours
/// exactly.
#[test]
fn compressed_lines_decode_to_the_plain_ones() {
    let lines = GlbMesh {
        positions: (0..40).map(|i| [i as f32 * 37.5, (i % 7) as f32 * 11.0, -(i as f32) * 3.25]).collect(),
        colors: (0..40).map(|i| [10, 20, 200, 55 + 5 * i as u8]).collect(),
        indices: (0..40).collect(),
        lines: true,
        translation: Some([6_371_000.0, 5.0, -7.0]),
        ..Default::default()
    };
    let plain = encode_glb(std::slice::from_ref(&lines), Compression::None).unwrap();
    let packed = encode_glb(std::slice::from_ref(&lines), Compression::Meshopt).unwrap();
    let p = parse(&packed);
    assert_eq!(p.value["meshes"][0]["primitives"][0]["mode"], 1, "LINES");
    let views = p.value["bufferViews"].as_array().unwrap();
    assert!(views.iter().any(|v| v["extensions"]["EXT_meshopt_compression"]["mode"] == "INDICES"));
    let (a, b) = (decode(&plain), decode(&packed));
    let step = p.value["nodes"][0]["scale"][0].as_f64().unwrap_or(0.0);
    assert_eq!(a[0].3, b[0].3, "the same segments, in order");
    assert_eq!(a[0].2, b[0].2, "colours");
    for (x, y) in a[0].0.iter().zip(&b[0].0) {
        assert!((0..3).all(|k| (x[k] - y[k]).abs() <= step / 2.0 + x[k].abs() * 1e-7), "{x:?} vs {y:?}");
    }
}

/// Octahedral normals come back within [`OCTAHEDRAL_ERROR_DEG`] in every direction (a
/// Fibonacci sphere of 200,000 directions, decoded by meshoptimizer's decoder).
#[test]
fn octahedral_normals_keep_their_direction() {
    let n = 200_000;
    let normals: Vec<[f32; 3]> = (0..n)
        .map(|i| {
            let z = 1.0 - (2.0 * i as f64 + 1.0) / n as f64;
            let (r, a) = ((1.0 - z * z).sqrt(), i as f64 * std::f64::consts::PI * (3.0 - 5f64.sqrt()));
            [(r * a.cos()) as f32, (r * a.sin()) as f32, z as f32]
        })
        .collect();
    let mut decoded = octahedral_normals(&normals);
    meshopt::decode_filter_oct(&mut decoded);
    let worst = normals
        .iter()
        .zip(&decoded)
        .map(|(a, d)| degrees(&a.map(f64::from), &d.map(f64::from)[..3]))
        .fold(0.0, f64::max);
    assert!(worst <= OCTAHEDRAL_ERROR_DEG && worst > 0.5, "worst {worst}°");
    assert!(decoded.iter().all(|d| d[3] == 0), "the pad stays zero");
}
