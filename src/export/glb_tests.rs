use super::*;
use crate::export::test_planet;
use gltf_json::validation::Validate;

pub(crate) struct Parsed {
    pub root: json::Root,
    pub value: serde_json::Value,
    pub bin: Vec<u8>,
}

fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes(b[at..at + 4].try_into().unwrap())
}

/// Checks the container (header, chunk types, lengths, alignment) and parses the JSON chunk.
pub(crate) fn parse(glb: &[u8]) -> Parsed {
    assert_eq!(&glb[0..4], b"glTF");
    assert_eq!(u32_at(glb, 4), 2);
    assert_eq!(u32_at(glb, 8) as usize, glb.len());
    let json_len = u32_at(glb, 12) as usize;
    assert_eq!(&glb[16..20], b"JSON");
    assert_eq!(json_len % 4, 0, "JSON chunk is 4-byte aligned");
    let json_bytes = &glb[20..20 + json_len];
    assert!(json_bytes.ends_with(b"}") || json_bytes.ends_with(b" "));
    let mut bin = Vec::new();
    let rest = 20 + json_len;
    if rest < glb.len() {
        assert_eq!(rest % 4, 0);
        let bin_len = u32_at(glb, rest) as usize;
        assert_eq!(&glb[rest + 4..rest + 8], b"BIN\0");
        assert_eq!(bin_len % 4, 0, "BIN chunk is 4-byte aligned");
        assert_eq!(rest + 8 + bin_len, glb.len());
        bin = glb[rest + 8..].to_vec();
    }
    let root = json::Root::from_slice(json_bytes).expect("JSON chunk parses as glTF");
    let mut errors = Vec::new();
    root.validate(&root, json::Path::new, &mut |path, err| errors.push(format!("{}: {err:?}", path())));
    // gltf-json knows neither extension of compressed files (the Khronos validator checks them
    // in CI).
    errors.retain(|e| !["EXT_meshopt_compression", "KHR_mesh_quantization"].iter().any(|x| e.contains(x)));
    assert!(errors.is_empty(), "{errors:?}");
    let value = serde_json::from_slice(json_bytes).unwrap();
    Parsed { root, value, bin }
}

/// Bytes an accessor covers.
fn accessor_bytes<'a>(p: &'a Parsed, acc: &json::Accessor, elem: usize) -> &'a [u8] {
    let view = &p.root.buffer_views[acc.buffer_view.unwrap().value()];
    let start = view.byte_offset.map_or(0, |o| o.0 as usize) + acc.byte_offset.map_or(0, |o| o.0 as usize);
    let len = acc.count.0 as usize * elem;
    assert!(start + len <= (view.byte_offset.map_or(0, |o| o.0) + view.byte_length.0) as usize);
    &p.bin[start..start + len]
}

fn f32s(b: &[u8]) -> Vec<f32> {
    b.chunks(4).map(|c| f32::from_le_bytes(c.try_into().unwrap())).collect()
}

fn attribute(p: &Parsed, prim: &json::mesh::Primitive, s: json::mesh::Semantic) -> json::Accessor {
    let i = prim.attributes[&Valid(s)];
    p.root.accessors[i.value()].clone()
}

#[test]
fn planet_glb_is_valid_and_matches_the_mesh() {
    let planet = test_planet();
    let (mesh, params) = (&planet.mesh, &Params::default());
    let glb = planet_glb(mesh, params).unwrap();
    let p = parse(&glb);
    assert_eq!(p.root.asset.generator.as_deref(), Some("riverworld"));
    assert_eq!(p.root.asset.version, "2.0");
    assert_eq!(p.root.meshes.len(), 1);
    assert_eq!(p.root.buffers[0].byte_length.0 as usize, p.bin.len());
    // Materials carry only what differs from glTF's defaults, which readers fill back in.
    let material = &p.value["materials"][0];
    for key in ["emissiveFactor", "doubleSided", "alphaMode"] {
        assert!(material.get(key).is_none(), "{key} is a default: {material}");
    }
    assert!(material["pbrMetallicRoughness"].get("baseColorFactor").is_none());
    assert_eq!(material["pbrMetallicRoughness"]["roughnessFactor"], 0.9);
    let m = &p.root.materials[0];
    assert_eq!((m.alpha_mode, m.double_sided), (Valid(json::material::AlphaMode::Opaque), false));
    assert_eq!(m.pbr_metallic_roughness.base_color_factor.0, [1.0; 4]);
    let prim = &p.root.meshes[0].primitives[0];
    assert_eq!(prim.mode, Valid(json::mesh::Mode::Triangles));
    let n = mesh.vertices.len();

    let pos_acc = attribute(&p, prim, json::mesh::Semantic::Positions);
    assert_eq!(pos_acc.count.0 as usize, n);
    let pos = f32s(accessor_bytes(&p, &pos_acc, 12));
    let (min, max) = (pos_acc.min.clone().unwrap(), pos_acc.max.clone().unwrap());
    for k in 0..3 {
        let vals = pos.iter().skip(k).step_by(3);
        let lo = vals.clone().fold(f32::INFINITY, |a, &b| a.min(b));
        let hi = vals.fold(f32::NEG_INFINITY, |a, &b| a.max(b));
        assert_eq!(min[k].as_f64().unwrap(), lo as f64, "min is exact");
        assert_eq!(max[k].as_f64().unwrap(), hi as f64, "max is exact");
    }

    let nrm_acc = attribute(&p, prim, json::mesh::Semantic::Normals);
    assert_eq!(nrm_acc.count.0 as usize, n);
    for c in f32s(accessor_bytes(&p, &nrm_acc, 12)).chunks(3) {
        let len = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
        assert!((len - 1.0).abs() < 1e-5, "normal length {len}");
    }
    let col_acc = attribute(&p, prim, json::mesh::Semantic::Colors(0));
    assert_eq!(col_acc.count.0 as usize, n);
    assert!(col_acc.normalized);
    assert!(matches!(col_acc.component_type, Valid(GenericComponentType(ComponentType::U8))));

    let idx_acc = &p.root.accessors[prim.indices.unwrap().value()];
    assert_eq!(idx_acc.count.0 as usize, mesh.faces.len() * 3);
    let idx: Vec<u32> = match idx_acc.component_type {
        Valid(GenericComponentType(ComponentType::U16)) => {
            accessor_bytes(&p, idx_acc, 2).chunks(2).map(|c| u16::from_le_bytes(c.try_into().unwrap()) as u32).collect()
        }
        _ => accessor_bytes(&p, idx_acc, 4).chunks(4).map(|c| u32::from_le_bytes(c.try_into().unwrap())).collect(),
    };
    assert!(idx.iter().all(|&i| (i as usize) < n));

    // Winding: every triangle's normal points away from the planet centre in glTF axes too.
    let at = |i: u32| glam::Vec3::from_slice(&pos[i as usize * 3..i as usize * 3 + 3]).as_dvec3();
    for t in idx.chunks(3) {
        let (a, b, c) = (at(t[0]), at(t[1]), at(t[2]));
        assert!((b - a).cross(c - a).dot(a + b + c) > 0.0, "face {t:?} winds inwards");
    }
}

#[test]
fn axes_put_the_north_pole_on_plus_y() {
    let planet = test_planet();
    let mesh = &planet.mesh;
    let glb = planet_glb(mesh, &Params::default()).unwrap();
    let p = parse(&glb);
    let prim = &p.root.meshes[0].primitives[0];
    let pos = f32s(accessor_bytes(&p, &attribute(&p, prim, json::mesh::Semantic::Positions), 12));
    let find = |dir: glam::DVec3| {
        (0..mesh.vertices.len())
            .max_by(|&a, &b| {
                mesh.pos(a as u32).normalize().dot(dir).total_cmp(&mesh.pos(b as u32).normalize().dot(dir))
            })
            .unwrap()
    };
    let north = find(glam::DVec3::Z);
    assert!(mesh.pos(north as u32).normalize().z > 0.999_999);
    let g = &pos[north * 3..north * 3 + 3];
    let r = mesh.pos(north as u32).length() as f32;
    assert!((g[1] - r).abs() < 1.0 && g[0].abs() < 1.0 && g[2].abs() < 1.0, "{g:?}");
    // 90°E (+Y in the planet frame) goes to glTF -Z.
    let east = find(glam::DVec3::Y);
    let g = &pos[east * 3..east * 3 + 3];
    assert!(g[2] < -0.999 * mesh.pos(east as u32).length() as f32, "{g:?}");
    assert_eq!(to_gltf_axes([1.0, 2.0, 3.0]), [1.0, 3.0, -2.0]);
}

#[test]
fn planet_glb_is_deterministic() {
    let planet = test_planet();
    let params = Params::default();
    let a = planet_glb(&planet.mesh, &params).unwrap();
    assert_eq!(a, planet_glb(&planet.mesh, &params).unwrap());
    assert_eq!(a, planet_glb(&planet.mesh.clone(), &params.clone()).unwrap());
}

#[test]
fn encode_glb_writes_several_nodes_with_precise_translations() {
    let tri = GlbMesh {
        positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        normals: vec![[0.0, 0.0, 1.0]; 3],
        colors: vec![[10, 20, 30, 255]; 3],
        indices: vec![0, 1, 2],
        lines: false,
        translation: Some([6_371_000.125, -12.5, 3.25]),
    };
    let water = GlbMesh { colors: vec![[0, 0, 255, 128]; 3], normals: Vec::new(), translation: None, ..tri.clone() };
    let glb = encode_glb(&[tri.clone(), GlbMesh::default(), water], Compression::None).unwrap();
    let p = parse(&glb);
    assert_eq!(p.root.nodes.len(), 2, "the empty mesh is left out");
    assert_eq!(p.root.meshes.len(), 2);
    assert_eq!(p.root.scenes[0].nodes.len(), 2);
    assert_eq!(p.root.scene.map(|s| s.value()), Some(0));
    let t = &p.value["nodes"][0]["translation"];
    assert_eq!(t[0].as_f64(), Some(6_371_000.125), "f64 precision kept: {t}");
    assert!(p.value["nodes"][1].get("translation").is_none());
    let m0 = &p.root.materials[p.root.meshes[0].primitives[0].material.unwrap().value()];
    let m1 = &p.root.materials[p.root.meshes[1].primitives[0].material.unwrap().value()];
    assert_eq!(m0.alpha_mode, Valid(json::material::AlphaMode::Opaque));
    assert_eq!(m1.alpha_mode, Valid(json::material::AlphaMode::Blend));
    // The ground is seen from above only; the water also from below (an eye under the sea).
    assert!(!m0.double_sided && m1.double_sided);
    assert!(!p.root.meshes[1].primitives[0].attributes.contains_key(&Valid(json::mesh::Semantic::Normals)));
    assert_eq!(
        glb,
        encode_glb(
            &[
                tri,
                GlbMesh::default(),
                GlbMesh {
                    colors: vec![[0, 0, 255, 128]; 3],
                    normals: Vec::new(),
                    translation: None,
                    ..encode_sample()
                }
            ],
            Compression::None
        )
        .unwrap()
    );

    let empty = parse(&encode_glb(&[], Compression::None).unwrap());
    assert!(empty.bin.is_empty() && empty.root.buffers.is_empty() && empty.root.scenes.is_empty());
}

fn encode_sample() -> GlbMesh {
    GlbMesh {
        positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        indices: vec![0, 1, 2],
        ..Default::default()
    }
}

#[test]
#[should_panic(expected = "index out of range")]
fn encode_glb_rejects_bad_indices() {
    let _ = encode_glb(&[GlbMesh { indices: vec![0, 1, 3], ..encode_sample() }], Compression::None);
}

/// The container's lengths are `u32`: a `.glb` one byte over 4 GiB is refused, naming its size,
/// instead of being written with a wrapped length.
#[test]
fn glb_lengths_stop_at_the_containers_limit() {
    let sample = encode_glb(&[encode_sample()], Compression::None).unwrap();
    let json_len = u32::from_le_bytes(sample[12..16].try_into().unwrap()) as usize;
    let bin_len = u32::from_le_bytes(sample[20 + json_len..24 + json_len].try_into().unwrap()) as usize;
    assert_eq!(glb_len(json_len, bin_len), Ok(sample.len() as u32));
    assert_eq!(glb_len(json_len, 0), Ok(20 + json_len as u32));
    let max = u32::MAX as usize;
    assert_eq!(glb_len(1000, max - 1028), Ok(u32::MAX));
    let e = glb_len(1000, max - 1027).unwrap_err();
    assert_eq!(e, GlbTooLarge { bytes: u32::MAX as u64 + 1 });
    assert!(e.to_string().contains("4294967296 bytes, over the 4 GiB"), "{e}");
    assert!(glb_len(usize::MAX / 2, usize::MAX / 2).is_err());
}

/// COLOR_0 is linear: sRGB bytes are converted (black and white stay, mid grey darkens to
/// 0.216, a colour keeps its hue), and the base mesh's colours are its climate colours so.
#[test]
fn vertex_colours_are_linear() {
    assert_eq!(linear_rgba([0, 128, 255], 7), [0, 55, 255, 7]);
    let [r, g, b, _] = linear_rgba([200, 150, 100], 255);
    assert!(r > g && g > b && b < 40, "{r} {g} {b}");
    let planet = test_planet();
    let params = Params::default();
    let mesh = planet_mesh(&planet.mesh, &params);
    let land = planet
        .mesh
        .vertices
        .iter()
        .position(|v| v.flags.contains(VertexFlags::CONTINENT) && !v.flags.contains(VertexFlags::RIVER))
        .unwrap();
    let v = &planet.mesh.vertices[land];
    let srgb = crate::export::climate::ground_colour(
        &planet.mesh,
        crate::export::climate::Palette::of(&params),
        v.p(),
        v.ground - params.sea_level_m,
    );
    assert_eq!(mesh.colors[land], linear_rgba(srgb, 255));
    // River vertices: blue in the planet model, their land's colour in a view or tile (their
    // water is the water surface's).
    let river = planet.mesh.vertices.iter().position(|v| v.flags.contains(VertexFlags::RIVER)).unwrap();
    let v = &planet.mesh.vertices[river];
    assert_eq!(mesh.colors[river], linear_rgba(RIVER_RGB, 255));
    let srgb = crate::export::climate::ground_colour(
        &planet.mesh,
        crate::export::climate::Palette::of(&params),
        v.p(),
        v.ground - params.sea_level_m,
    );
    assert_eq!(terrain_mesh(&planet.mesh, &params, None).colors[river], linear_rgba(srgb, 255));
    // A view or tile colours steep land as bare rock (`climate::on_slope`), from its normals.
    let triangles = planet.mesh.triangles();
    let mut normals: Vec<glam::DVec3> = planet.mesh.vertices.iter().map(|v| v.p().normalize()).collect();
    let flat = terrain_mesh_with_normals(&planet.mesh, &params, None, &triangles, &normals).colors[land];
    let up = normals[land];
    normals[land] = (up + 2.0 * up.any_orthonormal_vector()).normalize();
    let steep = terrain_mesh_with_normals(&planet.mesh, &params, None, &triangles, &normals).colors[land];
    let rock = crate::export::climate::on_slope(srgb, 0.0);
    assert_eq!(steep, linear_rgba(rock, 255));
    assert_ne!(flat, steep);
}
