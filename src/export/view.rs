//! A view-dependent mesh (paper §5) as glTF: the adapted terrain relative to a local origin, a
//! translucent water surface wherever water stands above the ground (sea and rivers, §3.3), and
//! rivers narrower than a pixel as lines (as renders draw them).

use super::climate::water_colour;
use super::glb::{encode_glb, linear_rgba, terrain_mesh_with_normals, to_gltf_axes, Compression, GlbMesh, GlbTooLarge};
use super::surface_normals;
use super::water::{river_lines, shows_water, water_levels};
use crate::adapt::Camera;
use crate::mesh::split::position::lift;
use crate::mesh::Mesh;
use crate::params::Params;
use glam::DVec3;

/// Alpha of the water surface.
const WATER_ALPHA: u8 = 200;

/// The local origin for a camera: the point of the base sphere below the eye, so positions near
/// the viewer are small `f32` offsets (within 1 mm up to 16 km away, 1 cm up to 130 km).
pub fn local_origin(eye: DVec3, radius: f64) -> DVec3 {
    eye.normalize_or(DVec3::X) * radius
}

/// Terrain, water surface and river lines (for `cam`) as one `.glb`, positions relative to
/// `origin`, stored as `compression` says; refused when it would be over the container's 4 GiB
/// (about 80 million faces of a view mostly under water).
pub fn view_glb(
    mesh: &Mesh,
    params: &Params,
    cam: &Camera,
    origin: DVec3,
    compression: Compression,
) -> Result<Vec<u8>, GlbTooLarge> {
    let triangles = mesh.triangles();
    // Wide rivers' channels carved where the view is finer than them (`export/carve.rs`).
    let mesh = &*super::carve::carved(mesh, &triangles);
    let normals = surface_normals(mesh, &triangles);
    let levels = water_levels(mesh, &triangles);
    encode_glb(
        &[
            terrain_mesh_with_normals(mesh, params, Some(origin), &triangles, &normals),
            water_mesh(mesh, origin, &triangles, &levels),
            river_lines_mesh(mesh, cam, origin),
        ],
        compression,
    )
}

/// The rivers narrower than a pixel of `cam` ([`river_lines`]) as line segments along their
/// water surface, coloured as water of the channel's depth, as opaque as the square root of
/// the share of a pixel the channel covers (as renders draw them); positions relative to
/// `origin`, each river vertex once. Segments whose channel covers under [`MIN_LINE_COVERAGE`]
/// of a pixel at both ends (drawn below 1/30 opacity: streams metres wide seen from hundreds
/// of kilometres) are left out, for smaller files. glTF lines are one pixel wide in the
/// clients that draw them.
pub fn river_lines_mesh(mesh: &Mesh, cam: &Camera, origin: DVec3) -> GlbMesh {
    let mut slot = std::collections::HashMap::new();
    let mut ends = Vec::new();
    let mut indices = Vec::new();
    for segment in river_lines(mesh, cam) {
        if segment.iter().all(|e| e.coverage < MIN_LINE_COVERAGE) {
            continue;
        }
        for e in segment {
            let i = *slot.entry(e.vertex).or_insert_with(|| {
                ends.push(e);
                ends.len() as u32 - 1
            });
            indices.push(i);
        }
    }
    GlbMesh {
        positions: ends.iter().map(|e| to_gltf_axes((e.position - origin).to_array()).map(|x| x as f32)).collect(),
        normals: Vec::new(),
        colors: ends.iter().map(|e| line_colour(e.coverage, e.depth_m)).collect(),
        indices,
        lines: true,
        translation: Some(to_gltf_axes(origin.to_array())),
    }
}

/// The colour of a river line's end (linear RGBA): water of the channel's depth, as opaque as
/// the square root of the share of a pixel the channel covers, at least 1/255.
pub fn line_colour(coverage: f64, depth_m: f64) -> [u8; 4] {
    linear_rgba(water_colour(depth_m), (coverage.sqrt() * 255.0).round().clamp(1.0, 255.0) as u8)
}

/// Least share of a pixel a river's channel covers for [`river_lines_mesh`] to draw it.
pub const MIN_LINE_COVERAGE: f64 = 1e-3;

/// Of the mesh's `triangles` ([`Mesh::triangles`]), those that show water at the water
/// `levels` ([`water_levels`]: a corner's level above its ground; dry corners below their
/// ground, so the surface meets the shore inside the face); colour by depth.
/// Vertices are numbered in order of first use.
pub fn water_mesh(mesh: &Mesh, origin: DVec3, triangles: &[[u32; 3]], levels: &[f64]) -> GlbMesh {
    use rayon::prelude::*;
    let vertices = &mesh.vertices;
    let wet: Vec<[u32; 3]> = triangles.par_iter().copied().filter(|t| shows_water(mesh, levels, t)).collect();
    // Numbering in order of first use is sequential; the attributes are computed in parallel.
    let mut slot = vec![u32::MAX; vertices.len()];
    let mut used = Vec::new();
    let mut indices = Vec::with_capacity(wet.len() * 3);
    for &v in wet.iter().flatten() {
        if slot[v as usize] == u32::MAX {
            slot[v as usize] = used.len() as u32;
            used.push(v);
        }
        indices.push(slot[v as usize]);
    }
    let up = to_gltf_axes(origin.normalize_or(DVec3::X).to_array()).map(|x| x as f32);
    let at = |v: &u32| &vertices[*v as usize];
    GlbMesh {
        positions: used
            .par_iter()
            .map(|&v| {
                let p = lift(vertices[v as usize].p(), mesh.radius, levels[v as usize]) - origin;
                to_gltf_axes(p.to_array()).map(|x| x as f32)
            })
            .collect(),
        normals: used
            .par_iter()
            .map(at)
            .map(|vert| {
                let n = to_gltf_axes(vert.p().normalize().to_array()).map(|x| x as f32);
                if n.iter().all(|x| x.is_finite()) {
                    n
                } else {
                    up
                }
            })
            .collect(),
        colors: used
            .par_iter()
            .map(|&v| {
                let [r, g, b] = water_colour((levels[v as usize] - vertices[v as usize].ground).max(0.0));
                linear_rgba([r, g, b], WATER_ALPHA)
            })
            .collect(),
        indices,
        lines: false,
        translation: Some(to_gltf_axes(origin.to_array())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapt::{Adapter, Camera};

    /// From orbit the test planet's perennial rivers, far narrower than a pixel, are lines:
    /// as opaque as the square root of the share of the pixel they cover, water-coloured, at the
    /// water surface of their river edges; the `.glb` holds them as a LINES primitive.
    #[test]
    fn a_view_from_orbit_draws_its_rivers_as_lines() {
        let planet = crate::export::test_planet();
        let p = Params { base_faces: 2000, ..Params::default() };
        let r = p.radius_m;
        let eye = crate::geo::direction(10.0, 20.0) * r * 3.0;
        let cam = Camera::new(eye, DVec3::ZERO, None, 40.0, 640, 480, 8.0, 40.0, r).unwrap();
        let mut a = Adapter::new(planet.mesh.clone(), p.clone());
        a.adapt(&cam, Some(100_000));
        let origin = local_origin(eye, r);
        let lines = river_lines_mesh(a.mesh(), &cam, origin);
        let segments = lines.indices.len() / 2;
        assert!(lines.lines && segments > 50, "{segments} river segments");
        let rivers = a.mesh().edges.iter().filter(|e| e.kind == crate::mesh::EdgeKind::River).count();
        assert!(segments <= rivers);
        assert!(lines.colors.iter().all(|c| c[3] >= 1 && c[2] > c[0]), "translucent water blue");
        assert!(lines.colors.iter().any(|c| c[3] < 255), "sub-pixel rivers are translucent");
        let glb = view_glb(a.mesh(), &p, &cam, origin, Compression::None).unwrap();
        let json = crate::export::glb::tests::parse(&glb).value;
        let modes: Vec<u64> = json["meshes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|m| m["primitives"][0]["mode"].as_u64().unwrap_or(4))
            .collect();
        assert_eq!(modes, vec![4, 4, 1], "terrain, water, river lines");
    }

    #[test]
    fn view_glb_keeps_centimetres_near_the_origin() {
        let planet = crate::export::test_planet();
        let p = Params { base_faces: 2000, ..Params::default() };
        let r = p.radius_m;
        let dir = crate::geo::direction(5.0, 10.0);
        let eye = dir * (r + 3000.0 + 2000.0);
        let cam = Camera::new(eye, dir * (r + 3000.0) + DVec3::Z * 5000.0, None, 60.0, 320, 180, 4.0, 20.0, r).unwrap();
        let mut a = Adapter::new(planet.mesh.clone(), p.clone());
        a.adapt(&cam, Some(200_000));
        let origin = local_origin(eye, r);
        let terrain = crate::export::glb::terrain_mesh(a.mesh(), &p, Some(origin));
        // Every vertex near the origin is reproduced to 1 cm from its f32 offset + f64 origin.
        let o = to_gltf_axes(origin.to_array());
        let mut near = 0;
        for (v, q) in a.mesh().vertices.iter().zip(&terrain.positions) {
            let true_pos = to_gltf_axes(v.pos);
            if v.p().distance(origin) < 50_000.0 {
                near += 1;
                for k in 0..3 {
                    assert!((o[k] + q[k] as f64 - true_pos[k]).abs() < 0.01);
                }
            }
        }
        assert!(near > 100, "{near}");
        let glb = view_glb(a.mesh(), &p, &cam, origin, Compression::None).unwrap();
        assert_eq!(view_glb(a.mesh(), &p, &cam, origin, Compression::None).unwrap(), glb);
        // A valid glTF: the terrain with normals, the water surface and the river lines (a
        // river crosses this view), all at the origin.
        let parsed = crate::export::glb::tests::parse(&glb);
        assert_eq!(parsed.root.nodes.len(), 3);
        for node in &parsed.value["nodes"].as_array().unwrap()[..] {
            let t = node["translation"].as_array().unwrap();
            // (serde_json reads the last digit of an f64 approximately.)
            assert!((0..3).all(|k| (t[k].as_f64().unwrap() - o[k]).abs() < 1e-6), "{t:?} vs {o:?}");
        }
        let normals = gltf_json::validation::Checked::Valid(gltf_json::mesh::Semantic::Normals);
        assert!(parsed.root.meshes[0].primitives[0].attributes.contains_key(&normals));
        let triangles = a.mesh().triangles();
        let water = water_mesh(a.mesh(), origin, &triangles, &water_levels(a.mesh(), &triangles));
        assert!(!water.indices.is_empty());
        assert!(water.indices.iter().all(|&i| (i as usize) < water.positions.len()));
    }
}
