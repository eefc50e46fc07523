//! `riverworld bench` snapshot table: end-to-end `render.png` (adaption from the base mesh,
//! vertex preparation, wgpu drawing with read-back, PNG encoding) for orbit and ground views at
//! 1024x768 and 1920x1080, on whatever adapter wgpu finds.

use glam::DVec3;
use riverworld::adapt::flight::{ground_camera, local_top};
use riverworld::adapt::{Adapter, Camera};
use riverworld::geo::direction;
use riverworld::planet::{build_planet, PlanetSpec};
use riverworld::render::{self, scene, ImageFormat, Shot};
use std::time::Instant;

/// Face budget of a snapshot, as `render.png` uses without `max_faces`.
const FACES: usize = riverworld::adapt::HTTP_VIEW_FACES;

fn resized(cam: &Camera, width: u32, height: u32) -> Camera {
    Camera { width, height, ..cam.clone() }
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1000.0
}

/// Prints the snapshot table for `spec`'s planet, median of `runs` per row.
pub fn run(spec: &PlanetSpec, runs: usize) {
    let renderer = match render::shared() {
        Ok(r) => r,
        Err(e) => {
            println!("Skipped: {e}");
            return;
        }
    };
    let planet = build_planet(spec, &mut |_, _| {}).expect("benchmark planet builds");
    let (gpu, choice) =
        riverworld::adapt::gpu::select(riverworld::adapt::gpu::Backend::Auto).unwrap_or((None, String::new()));
    let p = &spec.params;
    let r = p.radius_m;
    let orbit = Camera::new(direction(10.0, 20.0) * 3.0 * r, DVec3::ZERO, None, 40.0, 1920, 1080, 8.0, 40.0, r)
        .expect("orbit camera");
    let (lat, lon) = (29.5, 107.6);
    let ground = ground_camera(r, local_top(&planet.mesh, lat, lon, 100_000.0), lat, lon, 2000.0, 20_000.0, 30.0);
    let t = Instant::now();
    let first = Shot { camera: resized(&orbit, 64, 48), sun: None };
    render::snapshot(renderer, &planet.mesh, p, &first, 10_000, gpu.clone()).expect("warm-up render");
    println!("Adapter: {}; {choice}. First render (pipelines, 64x48): {:.0} ms.\n", renderer.describe(), ms(t));
    println!("| view | size | faces | adapt (ms) | prepare (ms) | draw + read back (ms) | PNG (ms) | total (ms) |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|");
    for (name, cam) in [("orbit", &orbit), ("ground, 2 km up", &ground)] {
        for (w, h) in [(1024, 768), (1920, 1080)] {
            let shot = Shot { camera: resized(cam, w, h), sun: None };
            let mut rows = Vec::new();
            let mut faces = 0;
            for _ in 0..runs.max(1) {
                let t0 = Instant::now();
                let mut a = Adapter::new(planet.mesh.clone(), p.clone()).with_gpu(gpu.clone());
                faces = a.adapt(&shot.camera, Some(FACES)).faces;
                let adapt = ms(t0);
                let t1 = Instant::now();
                let s = scene::prepare(a.mesh(), p, &shot.camera, scene::default_sun(&shot.camera));
                let prepare = ms(t1);
                let t2 = Instant::now();
                let px =
                    renderer.draw(&s, riverworld::export::climate::Palette::of(p), w, h).expect("benchmark render");
                let draw = ms(t2);
                let t3 = Instant::now();
                std::hint::black_box(render::encode(&px, w, h, ImageFormat::Png));
                let png = ms(t3);
                rows.push([adapt, prepare, draw, png, ms(t0)]);
            }
            rows.sort_by(|a, b| a[4].total_cmp(&b[4]));
            let m = rows[rows.len() / 2];
            println!(
                "| {name} | {w}x{h} | {faces} | {:.0} | {:.0} | {:.0} | {:.0} | {:.0} |",
                m[0], m[1], m[2], m[3], m[4]
            );
        }
    }
}
