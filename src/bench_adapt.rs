//! `riverworld bench` adaption table (paper §6, Table 4): an orbit view, two ground views and a
//! recorded fly-through over the Earth planet, with the paper's columns — faces, memory, adapt
//! time, triangles per second — plus the static-view state pass rate.

use crate::adapt::{state, Adapter, Camera, View};
use crate::build::continents::direction;
use crate::build::{build_planet, Planet, PlanetSpec};
use crate::mesh::VertexFlags;
use glam::DVec3;
use std::time::Instant;

/// Highest ground or water altitude (above the base sphere) among the base-mesh vertices within
/// `reach` metres of (lat, lon): a safe floor for a camera there.
pub fn local_top(mesh: &crate::mesh::Mesh, lat: f64, lon: f64, reach: f64) -> f64 {
    let p = direction(lat, lon) * mesh.radius;
    let near = mesh.vertices.iter().filter(|v| v.p().normalize().distance(p.normalize()) * mesh.radius < reach);
    let top = near.map(|v| v.ground.max(v.water)).fold(f64::MIN, f64::max);
    if top == f64::MIN {
        mesh.vertices.iter().map(|v| v.ground.max(v.water)).fold(0.0, f64::max)
    } else {
        top
    }
}

/// A camera `height` m above the altitude `sea` (above the base sphere) at (lat, lon), looking
/// `ahead` m along the ground toward the heading `bearing_deg` (0 = north), at 1920x1080.
pub fn ground_camera(radius: f64, sea: f64, lat: f64, lon: f64, height: f64, ahead: f64, bearing_deg: f64) -> Camera {
    let up = direction(lat, lon);
    let north = (DVec3::Z - up * up.z).normalize_or(DVec3::X);
    let east = north.cross(up);
    let b = bearing_deg.to_radians();
    let heading = north * b.cos() + east * b.sin();
    let eye = up * (radius + sea + height);
    let target = (up + heading * (ahead / radius)).normalize() * (radius + sea);
    Camera::new(
        eye,
        target,
        None,
        60.0,
        1920,
        1080,
        crate::adapt::camera::DEFAULT_LAND_PX,
        crate::adapt::camera::DEFAULT_WATER_PX,
        radius,
    )
    .expect("benchmark camera is valid")
}

/// Face budget of each fly-through frame: its lowest frames would need tens of GB unbounded.
pub const FLY_THROUGH_FACES: usize = 2_000_000;

/// The fly-through: from orbit down to a river valley in `frames` steps.
pub fn fly_through(radius: f64, sea: f64, lat: f64, lon: f64, frames: usize) -> Vec<Camera> {
    (0..frames)
        .map(|i| {
            let t = i as f64 / (frames - 1).max(1) as f64;
            let height = 2.0e7 * (1.0 - t) + 1500.0 * t;
            let height = height.min(2.0e7 * (0.05f64).powf(t * 4.0)).max(1500.0);
            ground_camera(radius, sea, lat - 2.0 * (1.0 - t), lon, height, height * 2.0 + 5000.0, 10.0 * t)
        })
        .collect()
}

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
        let (rlat, rlon) = crate::build::continents::lat_lon(planet.mesh.pos(river));
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
        // puts the mesh it keeps in spatial order first (see adapt/compact.rs).
        let again = a.adapt(cam, None);
        let view = View::new(cam, r, p.min_edge_length_m, crate::adapt::terrain_top(p, &planet.mesh));
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
    use crate::maps::{Map, MapKind, MapLimits};
    use crate::params::Params;

    /// The benchmark's views of the Earth planet converge: a split that never shortens its edge
    /// (a wall whose new vertex copies one end's altitude) showed up here as 400 passes of ever
    /// finer splits instead of a finished mesh.
    #[test]
    fn the_benchmark_views_converge() {
        let bytes =
            std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/maps/earth_landmask_ne10m_1024x512.png")).unwrap();
        let map = Map::decode(&bytes, MapKind::Continents, None, None, &MapLimits::default()).unwrap();
        let spec = PlanetSpec { seed: 42, params: Params::default(), map: Some(map.into()) };
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
