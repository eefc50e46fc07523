use super::*;
use crate::export::test_planet;
use serde_json::Value;
use std::collections::{HashMap, HashSet};
use std::sync::OnceLock;

/// The shared test planet, tiled once.
fn tiles() -> &'static PlanetTiles {
    static TILES: OnceLock<PlanetTiles> = OnceLock::new();
    TILES.get_or_init(|| {
        let params = Params { base_faces: 2000, ..Params::default() };
        PlanetTiles::new(Arc::new(test_planet().clone()), params).expect("the base mesh is a bisection refinement")
    })
}

/// `(JSON chunk, BIN chunk)` of a `.glb`.
fn glb_chunks(glb: &[u8]) -> (Value, &[u8]) {
    let u32_at = |at: usize| u32::from_le_bytes(glb[at..at + 4].try_into().unwrap()) as usize;
    let json_len = u32_at(12);
    let json = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    (json, &glb[20 + json_len + 8..])
}

/// Positions of the first mesh of a `.glb` (glTF axes).
fn glb_positions(glb: &[u8]) -> Vec<DVec3> {
    let (json, bin) = glb_chunks(glb);
    let acc =
        &json["accessors"][json["meshes"][0]["primitives"][0]["attributes"]["POSITION"].as_u64().unwrap() as usize];
    let view = &json["bufferViews"][acc["bufferView"].as_u64().unwrap() as usize];
    let start = view["byteOffset"].as_u64().unwrap_or(0) as usize;
    let floats: Vec<f64> = bin[start..start + 12 * acc["count"].as_u64().unwrap() as usize]
        .chunks(4)
        .map(|c| f32::from_le_bytes(c.try_into().unwrap()) as f64)
        .collect();
    floats.chunks(3).map(|c| DVec3::new(c[0], c[1], c[2])).collect()
}

/// 3D Tiles turns glTF's Y-up content Z-up: `(x, y, z) -> (x, -z, y)`.
fn y_up_to_z_up(p: DVec3) -> DVec3 {
    DVec3::new(p.x, -p.z, p.y)
}

fn translation_of(tile: &Value) -> DVec3 {
    tile.get("transform").map_or(DVec3::ZERO, |t| {
        let m: Vec<f64> = t.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        assert_eq!(m.len(), 16);
        let identity = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0];
        assert_eq!(&m[..12], &identity, "transforms are translations");
        assert_eq!(m[15], 1.0);
        DVec3::new(m[12], m[13], m[14])
    })
}

fn box_of(tile: &Value, origin: DVec3) -> OrientedBox {
    let b: Vec<f64> = tile["boundingVolume"]["box"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    OrientedBox::from_tiles_box(&b.try_into().unwrap(), origin)
}

#[test]
fn the_base_tree_holds_every_base_split() {
    let t = tiles();
    let mesh = &test_planet().mesh;
    assert_eq!(t.tree.splits(), mesh.vertices.len() - 6);
    // Walking the tree above the base mesh's leaves makes no vertex.
    let mut r = Refiner::new(mesh, &t.tree, &t.params);
    let mut out = Vec::new();
    r.descendants(tree::ROOTS[0], 4, &mut out);
    assert_eq!((out.len(), r.splits()), (16, 0));
}

#[test]
fn level_zero_closes_the_sphere_without_cracks() {
    // Every border edge of every level-0 tile is the reverse of another tile's border edge,
    // with bit-identical end points: the eight tiles close the sphere.
    let t = tiles();
    let mut edges: Vec<([u64; 3], [u64; 3])> = Vec::new();
    for root in 0..8 {
        let c = t.content(TileKey::root(root), Compression::None);
        assert_eq!(c.surface.faces.len(), 1 << CONTENT_DEPTH);
        let bits = |v: u32| c.surface.vertices[v as usize].pos.map(f64::to_bits);
        edges.extend(content::border_edges(&c.surface.triangles()).iter().map(|&(a, b)| (bits(a), bits(b))));
    }
    let set: HashSet<_> = edges.iter().copied().collect();
    assert!(edges.len() > 8 * 64);
    for (a, b) in &edges {
        assert!(set.contains(&(*b, *a)), "a border edge without its neighbour");
    }
}

#[test]
fn neighbouring_tiles_share_their_border_vertices() {
    // Level 2 inside root 0: the quadrant tiles that touch share every border vertex they
    // have in common, bit for bit, and the border edges between them match.
    let t = tiles();
    let keys: Vec<TileKey> = TileKey::root(0).children().iter().flat_map(|k| k.children()).collect();
    let mut all: Vec<([u64; 3], [u64; 3])> = Vec::new();
    for &k in &keys {
        let c = t.content(k, Compression::None);
        assert!(c.splits > 0, "level 2 is finer than the test planet's base mesh");
        let bits = |v: u32| c.surface.vertices[v as usize].pos.map(f64::to_bits);
        all.extend(content::border_edges(&c.surface.triangles()).iter().map(|&(a, b)| (bits(a), bits(b))));
    }
    let set: HashSet<_> = all.iter().copied().collect();
    let shared = all.iter().filter(|(a, b)| set.contains(&(*b, *a))).count();
    // The 16 tiles tile root 0: all edges but those on root 0's own border are shared.
    let outer = content::border_edges(&t.content(TileKey::root(0), Compression::None).surface.triangles()).len() * 4;
    assert_eq!(shared + outer, all.len(), "outer border edges: {outer}");
}

/// Checks that `contents` light every vertex they share alike, bit for bit, and every vertex
/// whose ring closes in their union as the area-weighted normal over that ring. Returns how many
/// vertices were shared and how many had whole rings.
fn normals_are_seamless(contents: &[TileContent]) -> (usize, usize) {
    type Key = [u64; 3];
    let mut ring: HashMap<Key, Vec<[Key; 3]>> = HashMap::new();
    let mut area: HashMap<[Key; 3], DVec3> = HashMap::new();
    let mut given: HashMap<Key, DVec3> = HashMap::new();
    let mut shared = 0;
    for c in contents {
        let bits = |v: u32| c.surface.vertices[v as usize].pos.map(f64::to_bits);
        for f in c.surface.triangles() {
            let [a, b, d] = f.map(|v| c.surface.vertices[v as usize].p());
            let tri = f.map(bits);
            area.insert(tri, (b - a).cross(d - a) * 0.5);
            for k in tri {
                ring.entry(k).or_default().push(tri);
            }
        }
        for (v, &n) in c.normals.iter().enumerate() {
            if let Some(old) = given.insert(bits(v as u32), n) {
                assert_eq!(old.to_array().map(f64::to_bits), n.to_array().map(f64::to_bits), "a seam at {v}");
                shared += 1;
            }
        }
    }
    let mut whole = 0;
    for (key, n) in &given {
        let faces = &ring[key];
        let mut balance: HashMap<Key, i32> = HashMap::new();
        for t in faces {
            let i = t.iter().position(|k| k == key).unwrap();
            *balance.entry(t[(i + 1) % 3]).or_default() += 1;
            *balance.entry(t[(i + 2) % 3]).or_default() -= 1;
        }
        if balance.values().all(|&b| b == 0) {
            whole += 1;
            let want = faces.iter().fold(DVec3::ZERO, |acc, t| acc + area[t]).normalize();
            assert!(n.distance(want) < 1e-12, "normal {n} but its ring gives {want}");
        }
    }
    (shared, whole)
}

#[test]
fn neighbouring_tiles_light_their_common_border_alike() {
    // Level 0 covers the sphere: every vertex's ring is in the union, across the roots' borders.
    let t = tiles();
    let level0: Vec<TileContent> = (0..8).map(|r| t.content(TileKey::root(r), Compression::None)).collect();
    let (shared, whole) = normals_are_seamless(&level0);
    let vertices: usize = level0.iter().map(|c| c.surface.vertices.len()).sum::<usize>() - shared;
    assert!(shared > 8 * 30 && whole == vertices, "{shared} shared, {whole} of {vertices} whole rings");
    // Level 2 inside root 0 (shared vertices alike; whole rings everywhere but on root 0's border).
    let keys: Vec<TileKey> = TileKey::root(0).children().iter().flat_map(|k| k.children()).collect();
    let level2: Vec<TileContent> = keys.iter().map(|&k| t.content(k, Compression::None)).collect();
    let (shared, whole) = normals_are_seamless(&level2);
    assert!(shared > 16 * 20 && whole > 16 * 450, "{shared} shared, {whole} whole rings");
}

#[test]
fn glb_positions_plus_transforms_give_the_mesh_positions() {
    let t = tiles();
    let file = t.tileset_json(1, Compression::None);
    let doc: Value = serde_json::from_slice(&file.json).unwrap();
    let level0 = &doc["root"]["children"][3];
    let key = TileKey::root(3);
    assert_eq!(level0["content"]["uri"], "tiles/3.glb?compression=none");
    let packed: Value = serde_json::from_slice(&t.tileset_json(1, Compression::Meshopt).json).unwrap();
    assert_eq!(packed["root"]["children"][3]["content"]["uri"], "tiles/3.glb");
    assert_eq!(packed["root"]["children"][3]["children"][1]["content"]["uri"], "tiles/31.json");
    let origin = translation_of(&doc["root"]) + translation_of(level0);
    let content = t.content(key, Compression::None);
    let positions = glb_positions(&content.glb);
    assert!(positions.len() > content.surface.vertices.len(), "skirts add vertices");
    for (v, q) in content.surface.vertices.iter().zip(&positions) {
        let world = origin + y_up_to_z_up(*q);
        // f32 offsets within a 90-degree cell: well under a metre.
        assert!(world.distance(v.p()) < 1.0, "{world} vs {:?}", v.pos);
    }
    // The same through a subtree file and a level-1 tile.
    let sub = t.subtree_json(key.child(2), 2, Compression::None).unwrap();
    let sub_doc: Value = serde_json::from_slice(&sub.json).unwrap();
    let reference = &level0["children"][2];
    assert_eq!(reference["content"]["uri"], "tiles/32.json?compression=none");
    assert!(reference.get("children").is_none());
    assert_eq!(reference["boundingVolume"], sub_doc["root"]["boundingVolume"]);
    let origin1 = origin + translation_of(reference) + translation_of(&sub_doc["root"]);
    let child = t.content(key.child(2), Compression::None);
    for (v, q) in child.surface.vertices.iter().zip(glb_positions(&child.glb)) {
        assert!((origin1 + y_up_to_z_up(q)).distance(v.p()) < 0.5);
    }
}

/// Walks a tileset file: checks each tile's fields, geometric errors falling with depth,
/// children's boxes inside their parent's, each content inside its box, and returns the URIs.
fn check_tiles(
    t: &PlanetTiles,
    tile: &Value,
    origin: DVec3,
    parent: Option<(&OrientedBox, f64)>,
    uris: &mut Vec<String>,
) {
    let origin = origin + translation_of(tile);
    let b = box_of(tile, origin);
    let ge = tile["geometricError"].as_f64().unwrap();
    if let Some((pb, pge)) = parent {
        assert!(ge < pge, "geometric error {ge} not below the parent's {pge}");
        assert!(pb.contains_box(&b, 1e-3), "a child's box sticks out of its parent's");
    }
    if let Some(uri) = tile["content"]["uri"].as_str() {
        uris.push(uri.to_string());
        if let Some(name) = uri.strip_suffix(".glb") {
            let key = TileKey::parse(name.trim_start_matches("tiles/"), t.max_level()).unwrap();
            let c = t.content(key, Compression::None);
            for v in &c.surface.vertices {
                assert!(b.contains(v.p(), 1e-3), "tile {key}: a vertex outside its box");
                if let Some((pb, _)) = parent {
                    assert!(pb.contains(v.p(), 1e-3), "tile {key}: a vertex outside its parent's box");
                }
            }
        }
    }
    for child in tile["children"].as_array().into_iter().flatten() {
        check_tiles(t, child, origin, Some((&b, ge)), uris);
    }
}

#[test]
fn tileset_files_are_well_formed_and_nested() {
    let t = tiles();
    let top: Value = serde_json::from_slice(&t.tileset_json(t.max_level(), Compression::Meshopt).json).unwrap();
    assert_eq!(top["asset"]["version"], "1.1");
    assert_eq!(top["extensionsUsed"][0], "3DTILES_ellipsoid");
    let r = top["extensions"]["3DTILES_ellipsoid"]["radii"][0].as_f64().unwrap();
    assert_eq!(r, t.params.radius_m + t.params.sea_level_m);
    assert_eq!(top["root"]["refine"], "REPLACE");
    assert!(top["geometricError"].as_f64().unwrap() >= top["root"]["geometricError"].as_f64().unwrap());
    let mut uris = Vec::new();
    check_tiles(t, &top["root"], DVec3::ZERO, None, &mut uris);
    assert_eq!(uris.len(), 8 + 32);
    // Every URI names a file the tiles serve, and one subtree file is checked the same way.
    for uri in &uris {
        let file = TileFile::parse(uri.strip_prefix("tiles/").unwrap(), t.max_level()).unwrap();
        if let TileFile::Subtree(k) = file {
            assert!(is_subtree_root(k.level));
        }
    }
    let key = TileKey::root(5).child(1);
    let reference = &top["root"]["children"][5]["children"][1];
    let origin = translation_of(&top["root"]["children"][5]) + translation_of(reference);
    let sub: Value =
        serde_json::from_slice(&t.subtree_json(key, t.max_level(), Compression::Meshopt).unwrap().json).unwrap();
    assert_eq!(sub["root"]["refine"], "REPLACE");
    assert_eq!(sub["geometricError"], reference["geometricError"]);
    let mut sub_uris = Vec::new();
    let parent_box = box_of(&top["root"]["children"][5], translation_of(&top["root"]["children"][5]));
    let parent_ge = top["root"]["children"][5]["geometricError"].as_f64().unwrap();
    check_tiles(t, &sub["root"], origin, Some((&parent_box, parent_ge)), &mut sub_uris);
    assert_eq!(sub_uris.len(), 1 + 4 + 16);
    assert_eq!(sub_uris[0], "51.glb");
    assert!(sub_uris.iter().all(|u| u.starts_with("51") && TileFile::parse(u, t.max_level()).is_ok()));
    assert!(
        t.subtree_json(TileKey::root(5).child(1).child(0), 20, Compression::Meshopt).is_none(),
        "level 2 starts no file"
    );
}

#[test]
fn contents_and_files_are_deterministic() {
    let a = tiles();
    let b = PlanetTiles::new(Arc::new(test_planet().clone()), a.params.clone()).unwrap();
    let key = TileKey::root(6).child(3).child(1);
    assert_eq!(a.content(key, Compression::None).glb, b.content(key, Compression::None).glb);
    // Files do not depend on what was made before.
    let sub = TileKey::root(6).child(3);
    assert_eq!(
        a.subtree_json(sub, 4, Compression::None).unwrap().json,
        b.subtree_json(sub, 4, Compression::None).unwrap().json
    );
}

#[test]
fn tile_vertices_are_the_vertices_of_a_view() {
    use crate::adapt::{Adapter, Camera};
    let t = tiles();
    let key = TileKey::root(0).child(1).child(2).child(0).child(3);
    let c = t.content(key, Compression::None);
    let r = t.params.radius_m;
    let top = c.surface.vertices.iter().map(|v| v.p().length()).fold(r, f64::max);
    let eye = c.bounds.centre.normalize() * (top + 30_000.0);
    let cam = Camera::new(eye, c.bounds.centre, None, 60.0, 640, 360, 4.0, 20.0, r).unwrap();
    let mut adapter = Adapter::new(test_planet().mesh.clone(), t.params.clone());
    adapter.adapt(&cam, Some(400_000));
    let view: HashSet<[u64; 3]> = adapter.mesh().vertices.iter().map(|v| v.pos.map(f64::to_bits)).collect();
    // Below the eye the view is much finer than the tile: every tile vertex there is a view
    // vertex, bit for bit.
    let near: Vec<_> =
        c.surface.vertices.iter().filter(|v| v.p().normalize().distance(eye.normalize()) * r < 60_000.0).collect();
    let found = near.iter().filter(|v| view.contains(&v.pos.map(f64::to_bits))).count();
    assert!(near.len() > 10, "{}", near.len());
    assert_eq!(found, near.len());
}

#[test]
fn skirts_hang_below_the_border() {
    let t = tiles();
    let key = TileKey::root(2).child(0);
    let c = t.content(key, Compression::None);
    let border = content::border_edges(&c.surface.triangles());
    let positions = glb_positions(&c.glb);
    let n = c.surface.vertices.len();
    let feet = positions.len() - n;
    let border_vertices: HashSet<u32> = border.iter().map(|e| e.0).collect();
    assert_eq!(feet, border_vertices.len());
    let origin = c.origin();
    let skirt = t.geometric_error(key.level);
    for foot in &positions[n..] {
        let p = origin + y_up_to_z_up(*foot);
        let top =
            c.surface.vertices.iter().map(|v| v.p()).min_by(|a, b| a.distance(p).total_cmp(&b.distance(p))).unwrap();
        assert!((top.length() - p.length() - skirt).abs() < 1.0, "a skirt foot not {skirt} m below its vertex");
    }
}

#[test]
fn deep_tiles_stay_small_and_precise() {
    let t = tiles();
    let mut key = TileKey::root(4);
    for q in [1, 3, 0, 2, 2, 1, 3, 0, 1, 1, 2, 0] {
        key = key.child(q);
    }
    let c = t.content(key, Compression::None);
    assert_eq!(c.surface.faces.len(), 1 << CONTENT_DEPTH);
    let e = t.edge_length(key.level);
    let max_half = c.bounds.half.iter().copied().fold(0.0, f64::max);
    assert!(max_half < 200.0 * e, "box half-size {max_half} for edges of {e}");
    // Sub-millimetre f32 offsets.
    for (v, q) in c.surface.vertices.iter().zip(glb_positions(&c.glb)) {
        assert!((c.origin() + y_up_to_z_up(q)).distance(v.p()) < 1e-3);
    }
}

#[test]
fn boxes_nest_without_falling_back_to_their_parents_axes() {
    // The pads leave room for the tilt between parent and child: every box down to level 3
    // of one root cell keeps its own axes and its own fit.
    let t = tiles();
    let mut level = vec![TileKey::root(1)];
    for _ in 0..4 {
        for &k in &level {
            let own = t.content(k, Compression::None).bounds;
            assert_eq!(t.placement(k).bounds, own, "tile {k} fell back to its parent's axes");
        }
        level = level.iter().flat_map(|k| k.children()).collect();
    }
}

/// Colours (linear RGBA8) of the first mesh of an uncompressed `.glb`.
fn glb_colours(glb: &[u8]) -> Vec<[u8; 4]> {
    let (json, bin) = glb_chunks(glb);
    let acc =
        &json["accessors"][json["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"].as_u64().unwrap() as usize];
    assert_eq!(acc["componentType"], 5121);
    let view = &json["bufferViews"][acc["bufferView"].as_u64().unwrap() as usize];
    let start = view["byteOffset"].as_u64().unwrap_or(0) as usize + acc["byteOffset"].as_u64().unwrap_or(0) as usize;
    let stride = view["byteStride"].as_u64().unwrap_or(4) as usize;
    (0..acc["count"].as_u64().unwrap() as usize).map(|i| bin[start + i * stride..][..4].try_into().unwrap()).collect()
}

/// The area-weighted mean colour (linear, 0-1) over a tile's terrain surface, and its area.
fn mean_colour(content: &TileContent) -> ([f64; 3], f64) {
    let colours = glb_colours(&content.glb);
    let s = &content.surface;
    let (mut sum, mut area) = ([0.0f64; 3], 0.0);
    for t in s.triangles() {
        let [a, b, c] = t.map(|v| s.pos(v));
        let w = (b - a).cross(c - a).length() * 0.5;
        area += w;
        for i in 0..3 {
            sum[i] += w * t.iter().map(|&v| f64::from(colours[v as usize][i]) / 255.0).sum::<f64>() / 3.0;
        }
    }
    (sum.map(|x| x / area), area)
}

/// sRGB 0-255 of a linear 0-1 component.
fn srgb(l: f64) -> f64 {
    255.0 * if l <= 0.0031308 { 12.92 * l } else { 1.055 * l.powf(1.0 / 2.4) - 0.055 }
}

/// A coarse tile shows what its descendants four levels down show, averaged: its mean colour
/// against theirs, on the Earth DEM planet (a mipmap's first requirement), for Asia's root tile
/// and a level-1 tile in it. With point colours each coarse vertex shows its own point's
/// colour (a summit's snow, a lake bed) and the base mesh's smoothed heights.
#[test]
fn coarse_levels_show_the_mean_colour_of_the_fine_ones() {
    let Some(planet) = crate::planet::tests_relief::earth() else { return };
    let tiles = PlanetTiles::new(Arc::new(planet.clone()), Params::default()).unwrap();
    let colours = crate::export::colour_mip::ColourMip::new(&planet.mesh, tiles.params());
    let content = |key: TileKey, mip: bool| {
        let mut refiner = tiles.refiner();
        let spec = tiles.spec(key.level);
        let c =
            content::tile_content(&mut refiner, key, &spec, tiles.params(), mip.then_some(&colours), Compression::None);
        tiles.recycle(refiner);
        c
    };
    let mut report = Vec::new();
    // Asia's root (tile 2: 0-90°E, north) and a level-1 tile inside it.
    for key in [TileKey::root(2), TileKey::root(2).child(1)] {
        let mut fine = vec![key];
        for _ in 0..4 {
            fine = fine.iter().flat_map(|k| k.children()).collect();
        }
        let (mut sum, mut area) = ([0.0f64; 3], 0.0);
        for &k in &fine {
            let (m, a) = mean_colour(&content(k, true));
            area += a;
            for i in 0..3 {
                sum[i] += a * m[i];
            }
        }
        let truth = sum.map(|x| srgb(x / area));
        let worst = |m: [f64; 3]| (0..3).map(|i| (srgb(m[i]) - truth[i]).abs()).fold(0.0, f64::max);
        let (with, without) = (worst(mean_colour(&content(key, true)).0), worst(mean_colour(&content(key, false)).0));
        report.push((key.level, with, without));
        // Measured 0.4 and 1.9 (point colours: 5.6 and 13.6; base-mesh means alone, without the
        // map's cells: 3.9 and 11.5).
        assert!(
            with <= 3.0,
            "level {}: mean colour off by {with:.1} (point colours: {without:.1}); {report:?}",
            key.level
        );
    }
    println!("largest channel difference (sRGB 0-255), level / means / points: {report:?}");
}

/// Tiles carry the perennial rivers as lines laid on their own surface: the Earth DEM's level-0
/// tile over South America holds the great rivers (channels over ~800 m at its ~80 km pixel,
/// drawn at 10-20 % opacity, as a render from that far draws them), and every line end lies
/// above the tile's terrain by at most a fiftieth of an edge (on it, not under it).
#[test]
fn tiles_carry_their_rivers_as_lines_on_their_surface() {
    let Some(planet) = crate::planet::tests_relief::earth() else { return };
    let tiles = PlanetTiles::new(Arc::new(planet.clone()), Params::default()).unwrap();
    // The root cell holding the Amazon's mouth (0°, 50°W).
    let amazon = crate::geo::direction(-2.0, -55.0);
    let root = (0..8u8)
        .find(|&r| {
            let mut refiner = tiles.refiner();
            let (cell, _) = content::cell_frame(&mut refiner, TileKey::root(r));
            tree::holds(cell.map(|v| refiner.mesh().pos(v).normalize()), amazon)
        })
        .unwrap();
    let content = tiles.content(TileKey::root(root), Compression::None);
    let (json, bin) = glb_chunks(&content.glb);
    let meshes = json["meshes"].as_array().unwrap();
    let lines = meshes.iter().position(|m| m["primitives"][0]["mode"] == 1).expect("a LINES primitive");
    let prim = &json["meshes"][lines]["primitives"][0];
    let acc = |i: &Value| &json["accessors"][i.as_u64().unwrap() as usize];
    let colours = acc(&prim["attributes"]["COLOR_0"]);
    let view = &json["bufferViews"][colours["bufferView"].as_u64().unwrap() as usize];
    let start = view["byteOffset"].as_u64().unwrap_or(0) as usize;
    let alphas: Vec<u8> = (0..colours["count"].as_u64().unwrap() as usize).map(|i| bin[start + 4 * i + 3]).collect();
    // At least a tenth opaque (a channel over a hundredth of the pixel) at one end at least.
    let seen = alphas.iter().filter(|&&a| a >= 25).count();
    assert!(alphas.len() > 20 && seen * 3 >= alphas.len(), "{} line ends: {alphas:?}", alphas.len());
    // Line ends against the terrain below them: the tile's surface, the same leaf search.
    let positions = {
        let a = acc(&prim["attributes"]["POSITION"]);
        let v = &json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
        let s = v["byteOffset"].as_u64().unwrap_or(0) as usize;
        (0..a["count"].as_u64().unwrap() as usize)
            .map(|i| {
                let f =
                    |k: usize| f32::from_le_bytes(bin[s + 12 * i + 4 * k..s + 12 * i + 4 * k + 4].try_into().unwrap());
                y_up_to_z_up(DVec3::new(f(0).into(), f(1).into(), f(2).into())) + content.origin()
            })
            .collect::<Vec<_>>()
    };
    let edge = tiles.edge_length(0);
    let surface = &content.surface;
    for p in positions.iter().step_by(17) {
        let d = p.normalize();
        // The terrain's height below the line end: the surface triangle the direction meets.
        let below = surface.triangles().into_iter().find_map(|t| {
            let [a, b, c] = t.map(|v| surface.pos(v));
            let n = (b - a).cross(c - a);
            let inside = [(a, b), (b, c), (c, a)].iter().all(|(x, y)| x.cross(*y).dot(d) >= 0.0);
            inside.then(|| d * (a.dot(n) / d.dot(n)))
        });
        let Some(below) = below else { continue };
        let above = p.length() - below.length();
        assert!(above > -1.0 && above < 0.02 * edge, "a line end {above:.0} m above the terrain");
    }
}

/// A refiner gives back its buffers as a copy of the base mesh again, so the next refiner
/// (which refines them without copying the base) starts from the base: after tile contents,
/// DEM tiles and terrain tiles, every spare equals the base mesh, and a content made on
/// recycled buffers is the one made on a fresh copy.
#[test]
fn recycled_buffers_are_the_base_mesh_again() {
    let params = Params { base_faces: 2000, ..Params::default() };
    let t = PlanetTiles::new(Arc::new(test_planet().clone()), params).unwrap();
    let base = &test_planet().mesh;
    let check = |what: &str| {
        let spares = t.spares.lock().unwrap();
        assert!(!spares.is_empty(), "{what}: buffers kept");
        for m in spares.iter() {
            assert!(m.vertices == base.vertices && m.edges == base.edges && m.faces == base.faces, "{what}");
        }
    };
    let key = TileKey::root(3).children()[1].children()[2];
    let first = t.content(key, Compression::None).glb;
    check("a tile content");
    for (z, x, y) in [(5, 9, 11), (7, 40, 50), (2, 1, 1)] {
        crate::export::terrain_rgb::dem_tile_png(&t, z, x, y, crate::export::terrain_rgb::Encoding::Terrarium).unwrap();
        check("an elevation tile");
        let ext = crate::export::quantized_mesh::Extensions::ALL;
        crate::export::quantized_mesh::terrain_tile(&t, (z, x, y), ext, 14).unwrap();
        check("a terrain tile");
    }
    assert_eq!(t.content(key, Compression::None).glb, first, "a content on recycled buffers");
}

/// The tile of `level` whose cell's centre is nearest `dir` at every level down to it.
fn tile_at(t: &PlanetTiles, dir: DVec3, level: u8) -> TileKey {
    let mut refiner = t.refiner();
    let mut near = |k: TileKey| {
        let (cell, _) = content::cell_frame(&mut refiner, k);
        let m = refiner.mesh();
        let centre = cell.iter().map(|&v| m.pos(v).normalize()).sum::<DVec3>().normalize();
        centre.distance(dir).to_bits()
    };
    let mut key = (0..8).map(TileKey::root).min_by_key(|&k| near(k)).expect("eight roots");
    while key.level < level {
        key = key.children().into_iter().min_by_key(|&k| near(k)).expect("four children");
    }
    key
}

#[test]
fn tiles_carve_wide_rivers_alike_across_their_borders() {
    use crate::export::water::channel_width;
    use crate::mesh::VertexFlags;
    let t = tiles();
    let base = &t.planet.mesh;
    // The test planet's widest river, and the first level whose edges are under a sixth of it.
    let (dir, width) = base
        .vertices
        .iter()
        .filter_map(|v| Some((v.p().normalize(), channel_width(base, v)?)))
        .fold((DVec3::ZERO, 0.0), |a, b| if b.1 > a.1 { b } else { a });
    let level = (1..=t.max_level()).find(|&l| t.edge_length(l) < width / 6.0).expect("a level finer than it");
    let edge = t.edge_length(level);
    // The four tiles of that level around it.
    let parent = tile_at(t, dir, level - 1);
    let contents: Vec<TileContent> = parent.children().iter().map(|&k| t.content(k, Compression::None)).collect();
    // Leaf edges against the level's nominal edge, as the carving's margin assumes, here and at
    // levels 0 and 1 (0.18-4.2 measured).
    let shares = |c: &TileContent, edge: f64| {
        let vs = &c.surface.vertices;
        let lengths = c.surface.triangles().into_iter().flat_map(|t| {
            [0, 1, 2].map(|k| vs[t[k] as usize].p().normalize().distance(vs[t[(k + 1) % 3] as usize].p().normalize()))
        });
        lengths.fold((f64::MAX, 0.0f64), |(lo, hi), l| {
            (lo.min(l * t.params.radius_m / edge), hi.max(l * t.params.radius_m / edge))
        })
    };
    let coarse: Vec<(TileContent, u8)> = (0..8)
        .map(TileKey::root)
        .flat_map(|k| std::iter::once(k).chain(k.children()))
        .map(|k| (t.content(k, Compression::None), k.level))
        .collect();
    for (c, l) in contents.iter().map(|c| (c, level)).chain(coarse.iter().map(|(c, l)| (c, *l))) {
        let (lo, hi) = shares(c, t.edge_length(l));
        assert!(lo > 0.1 && hi < 0.75 * carve::LONGEST_EDGE_SHARE, "level {l}: {lo}-{hi}");
    }
    let not_carved = VertexFlags::SEA | VertexFlags::COAST | VertexFlags::RIVER | VertexFlags::LAKE;
    let carved = |v: &crate::mesh::Vertex| v.submerged() && v.flags.0 & not_carved.0 == 0;
    // Every vertex two tiles share is the same, carved or not, and lit alike.
    let mut all: Vec<([u64; 3], [u64; 3])> = Vec::new();
    let mut seen: HashMap<[u64; 3], usize> = HashMap::new();
    for c in &contents {
        let bits = |v: u32| c.surface.vertices[v as usize].pos.map(f64::to_bits);
        all.extend(content::border_edges(&c.surface.triangles()).iter().map(|&(a, b)| (bits(a), bits(b))));
        for v in &c.surface.vertices {
            *seen.entry(v.pos.map(f64::to_bits)).or_default() += usize::from(carved(v));
        }
    }
    let set: HashSet<_> = all.iter().copied().collect();
    let shared = all.iter().filter(|(a, b)| set.contains(&(*b, *a))).count();
    let outer = content::border_edges(&t.content(parent, Compression::None).surface.triangles()).len() * 2;
    assert_eq!(shared + outer, all.len(), "outer border edges: {outer}");
    let carved_shared = seen.values().filter(|&&n| n > 1).count();
    assert!(carved_shared > 2, "{carved_shared} carved vertices on shared borders");
    normals_are_seamless(&contents);
    // The tiles' water surface covers every carved vertex.
    for c in &contents {
        let levels = crate::export::water::water_levels(&c.surface, &c.surface.triangles());
        for (v, level) in c.surface.vertices.iter().zip(levels) {
            assert!(!carved(v) || level > v.ground, "a carved vertex under no water");
        }
    }
    // The carved bed lies within the channel's half width of the river, and reaches most of it.
    let rivers: Vec<(DVec3, f64)> = contents
        .iter()
        .flat_map(|c| c.surface.vertices.iter().filter_map(|v| Some((v.p().normalize(), channel_width(base, v)?))))
        .collect();
    let r = t.params.radius_m;
    let (mut farthest, mut beside, mut count) = (0.0f64, 0, 0);
    for c in &contents {
        for v in c.surface.vertices.iter().filter(|v| carved(v)) {
            let d = v.p().normalize();
            let (gap, w) = rivers.iter().map(|&(p, w)| (p.distance(d) * r, w)).fold((f64::MAX, 0.0), |a, b| {
                if b.0 < a.0 {
                    b
                } else {
                    a
                }
            });
            // (Rivers just outside the four tiles carve some too.)
            count += 1;
            if gap < w / 2.0 + edge {
                beside += 1;
                farthest = farthest.max(gap / (w / 2.0));
            }
        }
    }
    assert!(beside * 10 >= count * 9, "{beside} of {count} carved vertices beside a river in the tiles");
    assert!(farthest > 0.6, "the bed reaches {farthest} of the half width ({width} m river, {edge} m edges)");
}

#[test]
fn tiles_far_finer_than_a_wide_river_carve_it_by_its_course() {
    use crate::export::water::{channel_width, water_levels};
    let t = tiles();
    let base = &t.planet.mesh;
    let sea = t.params.sea_level_m;
    // The test planet's widest river away from the sea; the first level whose edges its half
    // width spans more than MAX_CARVE_EDGES of, and the first where it spans more than 32.
    let (dir, width) = base
        .vertices
        .iter()
        .filter(|v| v.ground > sea + 20.0)
        .filter_map(|v| Some((v.p().normalize(), channel_width(base, v)?)))
        .fold((DVec3::ZERO, 0.0), |a, b| if b.1 > a.1 { b } else { a });
    let first = |edges: f64| (1..=t.max_level()).find(|&l| t.edge_length(l) * 2.0 * edges < width).expect("a level");
    for (level, least) in [(first(crate::export::carve::MAX_CARVE_EDGES), 40), (first(32.0), 300)] {
        // The four tiles of that level around the river vertex: a few edges' worth of the channel.
        let parent = tile_at(t, dir, level - 1);
        let contents: Vec<TileContent> = parent.children().iter().map(|&k| t.content(k, Compression::None)).collect();
        // Neighbours share their border vertices bit for bit and are lit alike.
        let mut all: Vec<([u64; 3], [u64; 3])> = Vec::new();
        for c in &contents {
            let bits = |v: u32| c.surface.vertices[v as usize].pos.map(f64::to_bits);
            all.extend(content::border_edges(&c.surface.triangles()).iter().map(|&(a, b)| (bits(a), bits(b))));
        }
        let set: HashSet<_> = all.iter().copied().collect();
        let shared = all.iter().filter(|(a, b)| set.contains(&(*b, *a))).count();
        let outer = content::border_edges(&t.content(parent, Compression::None).surface.triangles()).len() * 2;
        assert_eq!(shared + outer, all.len(), "level {level}: outer border edges: {outer}");
        normals_are_seamless(&contents);
        // Every vertex within half the half width of the river vertex lies under water (the
        // course passes through it); without the course only those beside the tiles' own river
        // vertices would (measured at levels 13 and 15: 50 of 50 and 773 of 773; 9 and 73
        // without).
        let r = t.params.radius_m;
        let (mut near, mut wet) = (0, 0);
        for c in &contents {
            let levels = water_levels(&c.surface, &c.surface.triangles());
            for (v, level) in c.surface.vertices.iter().zip(levels) {
                if v.p().normalize().distance(dir) * r < width / 4.0 {
                    near += 1;
                    wet += usize::from(level > v.ground);
                }
            }
        }
        assert!(near > least && wet == near, "{wet} of {near} vertices near the river under water (level {level})");
    }
}
