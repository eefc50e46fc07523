//! `riverworld bench` adaption table (paper §6, Table 4): an orbit view, two ground views and a
//! recorded fly-through over the Earth planet, with the paper's columns — faces, memory, adapt
//! time, triangles per second — plus the static-view state pass rate.

use glam::DVec3;
use riverworld::adapt::cpu::state;
use riverworld::adapt::flight::{fly_through, ground_camera, local_top, FLY_THROUGH_FACES};
use riverworld::adapt::{Adapter, Camera, View};
use riverworld::geo::direction;
use riverworld::mesh::VertexFlags;
use riverworld::planet::{build_planet, Planet, PlanetSpec};
use std::time::Instant;

fn mb(bytes: f64) -> f64 {
    bytes / (1024.0 * 1024.0)
}

/// The benchmark's cameras over one planet: an orbit view, two ground views near its largest
/// river, and a 30-frame fly-through from orbit down to that river.
pub struct Scene {
    pub planet: Planet,
    pub views: Vec<(&'static str, Camera)>,
    pub path: Vec<Camera>,
}

impl Scene {
    pub fn new(spec: &PlanetSpec) -> Scene {
        let planet = build_planet(spec, &mut |_, _| {}).expect("benchmark planet builds");
        let r = spec.params.radius_m;
        // A river vertex far from the coast for the ground views.
        let graph = &planet.rivers;
        let river = graph
            .order
            .iter()
            .copied()
            .filter(|&v| !planet.mesh.vertices[v as usize].flags.contains(VertexFlags::MOUTH))
            .max_by(|&a, &b| graph.tributaries(a).cmp(&graph.tributaries(b)).then(b.cmp(&a)))
            .unwrap_or(0);
        let (rlat, rlon) = riverworld::geo::lat_lon(planet.mesh.pos(river));
        let orbit = Camera::new(direction(10.0, 20.0) * 3.0 * r, DVec3::ZERO, None, 40.0, 1920, 1080, 2.0, 10.0, r)
            .expect("orbit camera");
        let top1 = local_top(&planet.mesh, rlat, rlon, 150_000.0);
        let top2 = local_top(&planet.mesh, rlat + 0.3, rlon + 0.3, 150_000.0);
        let views = vec![
            ("orbit view", orbit),
            ("ground view 1 (2 km above the local peaks)", ground_camera(r, top1, rlat, rlon, 2000.0, 20_000.0, 0.0)),
            (
                "ground view 2 (300 m above the local peaks)",
                ground_camera(r, top2, rlat + 0.3, rlon + 0.3, 300.0, 3000.0, 135.0),
            ),
        ];
        let path = fly_through(r, top1, rlat, rlon, 30);
        Scene { planet, views, path }
    }
}

/// Prints the adaption table for `spec`'s planet.
pub fn run(spec: &PlanetSpec) {
    let Scene { planet, views, path } = Scene::new(spec);
    let p = &spec.params;
    let r = p.radius_m;
    println!("Base mesh: {} faces, {} vertices.\n", planet.stats.faces, planet.stats.vertices);
    println!(
        "| view | faces | memory (MB) | bytes/vertex | adapt from base (ms) | state / select / split (ms) | new M tris/s | spatial order (ms) | static pass (ms) | static M tris/s |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (name, cam) in &views {
        let mut a = Adapter::new(planet.mesh.clone(), p.clone());
        let s = a.adapt(cam, None);
        let made = s.faces.saturating_sub(planet.stats.faces);
        // The same camera again, as frame-to-frame adaption sees a static view: the adapter
        // puts the mesh it keeps in spatial order first (see adapt/cpu/compact.rs).
        let again = a.adapt(cam, None);
        let view = View::new(cam, r, p.min_edge_length_m, riverworld::adapt::terrain_top(p, &planet.mesh));
        let t = Instant::now();
        let reps = 5;
        for _ in 0..reps {
            std::hint::black_box(state::edge_wants(a.mesh(), &view));
        }
        let pass_ms = t.elapsed().as_secs_f64() * 1000.0 / reps as f64;
        let bytes = s.bytes_per_vertex * s.vertices as f64;
        println!(
            "| {name} | {} | {:.1} | {:.0} | {:.0} | {:.0} / {:.0} / {:.0} | {:.2} | {:.0} | {:.1} | {:.0} |",
            s.faces,
            mb(bytes),
            s.bytes_per_vertex,
            s.adapt_ms,
            s.stage_ms.state,
            s.stage_ms.select,
            s.stage_ms.split,
            made as f64 / s.adapt_ms / 1000.0,
            again.stage_ms.compact,
            pass_ms,
            s.faces as f64 / pass_ms / 1000.0
        );
    }
    let mut a = Adapter::new(planet.mesh.clone(), p.clone());
    let (mut max_faces, mut max_ms, mut total_ms, mut max_bytes, mut new_tris) = (0usize, 0.0f64, 0.0, 0.0f64, 0usize);
    for cam in &path {
        let s = a.adapt(cam, Some(FLY_THROUGH_FACES));
        max_faces = max_faces.max(s.faces);
        max_ms = max_ms.max(s.adapt_ms);
        total_ms += s.adapt_ms;
        max_bytes = max_bytes.max(s.bytes_per_vertex * s.vertices as f64);
        new_tris += 2 * s.splits;
    }
    println!(
        "| fly-through, {} frames of at most {FLY_THROUGH_FACES} faces (max / mean per frame) | {max_faces} | {:.1} | | {max_ms:.0} / {:.0} | | {:.2} | | | |",
        path.len(),
        mb(max_bytes),
        total_ms / path.len() as f64,
        new_tris as f64 / total_ms / 1000.0
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use riverworld::maps::{Map, MapKind, MapLimits};
    use riverworld::params::Params;

    /// The benchmark's views of the Earth planet converge: a split that never shortens its edge
    /// (a wall whose new vertex copies one end's altitude) showed up here as 400 passes of ever
    /// finer splits instead of a finished mesh.
    #[test]
    fn the_benchmark_views_converge() {
        let bytes =
            std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/maps/earth_landmask_ne10m_1024x512.png")).unwrap();
        let map = Map::decode(&bytes, MapKind::Continents, None, None, &MapLimits::default()).unwrap();
        let spec = PlanetSpec { seed: 42, params: Params::default(), map: Some(map.into()), precipitation: None };
        let scene = Scene::new(&spec);
        for (name, cam) in &scene.views {
            let s = Adapter::new(scene.planet.mesh.clone(), spec.params.clone()).adapt(cam, None);
            assert!(s.converged, "{name}: {s:?}");
        }
        let mut a = Adapter::new(scene.planet.mesh.clone(), spec.params.clone());
        for (i, cam) in scene.path.iter().enumerate() {
            let s = a.adapt(cam, Some(FLY_THROUGH_FACES));
            assert!(s.converged && s.faces <= FLY_THROUGH_FACES, "frame {i}: {s:?}");
        }
    }
}
