//! `riverworld bench --only backends`: view-dependent adaption (paper §5) on the CPU backend
//! and on the wgpu compute backend over the same views, in one run, with the device's stage
//! times (state update, split-list compaction, splits) where the adapter has timestamp queries.

use super::adapt::Scene;
use riverworld::adapt::cpu::state;
use riverworld::adapt::gpu::{self, Backend, DeviceTimes, GpuAdaption};
use riverworld::adapt::{AdaptStats, Adapter, Camera, View};
use riverworld::mesh::Mesh;
use riverworld::params::Params;
use riverworld::planet::PlanetSpec;
use std::sync::Arc;
use std::time::Instant;

/// One backend's adaption of a camera sequence from the base mesh.
struct Run {
    mesh: Mesh,
    adapt_ms: f64,
    device: DeviceTimes,
}

fn adapt_all(
    base: &Mesh,
    params: &Params,
    cams: &[Camera],
    max_faces: Option<usize>,
    gpu: Option<&Arc<GpuAdaption>>,
) -> Run {
    let mut a = Adapter::new(base.clone(), params.clone()).with_gpu(gpu.cloned());
    if let Some(g) = gpu {
        g.take_times();
    }
    let mut total = AdaptStats::default();
    for cam in cams {
        let s = a.adapt(cam, max_faces);
        total.adapt_ms += s.adapt_ms;
    }
    let device = gpu.map(|g| g.take_times()).unwrap_or_default();
    Run { mesh: a.into_mesh(), adapt_ms: total.adapt_ms, device }
}

/// Median of `reps` timings of `f`, milliseconds.
fn median_ms(reps: usize, mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..reps)
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64() * 1000.0
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

fn kernel(d: &DeviceTimes) -> String {
    if d.timed {
        format!("{:.2}", d.kernel_ms)
    } else {
        "n/a".into()
    }
}

/// Device time per stage, `state / select / split / collapse / compact` milliseconds.
fn stages(d: &DeviceTimes) -> String {
    if d.timed {
        let [a, b, c, e, f] = d.stage_ms;
        format!("{a:.1} / {b:.1} / {c:.1} / {e:.1} / {f:.1}")
    } else {
        "n/a".into()
    }
}

/// Prints the two-backend table for `spec`'s planet, or says why the GPU backend is missing.
pub fn run(spec: &PlanetSpec) {
    let g = match gpu::select(Backend::Gpu) {
        Ok((Some(g), line)) => {
            println!("{line}; CPU backend: rayon on {} threads.\n", rayon::current_num_threads());
            g
        }
        Ok((None, _)) => return,
        Err(e) => return println!("GPU backend unavailable ({e}); no backend comparison.\n"),
    };
    let Scene { planet, views, path } = Scene::new(spec);
    let p = &spec.params;
    // Compile the pipeline and size the buffers outside the timings.
    let _ = gpu::edge_wants(
        &g,
        &planet.mesh,
        &View::new(&views[0].1, p.radius_m, p.min_edge_length_m, riverworld::adapt::terrain_top(p, &planet.mesh)),
    );
    println!(
        "Adaption from the base mesh ({} faces). Every stage on the device: state update, split-list \
         compaction, splits, collapses and compaction (the spatial order between cameras is computed \
         on the host's copy and followed on the device).\n",
        planet.stats.faces
    );
    println!("| view | faces | same mesh | CPU adapt (ms) | GPU adapt (ms) | GPU device (ms) | device state / select / split / collapse / compact (ms) | submissions | uploaded (MB) | read back (MB) |");
    println!("|---|---:|:---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut cases: Vec<(String, Vec<Camera>, Option<usize>)> =
        views.iter().map(|(n, c)| (n.to_string(), vec![c.clone()], None)).collect();
    let budget = riverworld::adapt::flight::FLY_THROUGH_FACES;
    cases.push((format!("fly-through, {} frames, at most {budget} faces (sum)", path.len()), path, Some(budget)));
    let mut finals = Vec::new();
    for (name, cams, max_faces) in &cases {
        let cpu = adapt_all(&planet.mesh, p, cams, *max_faces, None);
        let dev = adapt_all(&planet.mesh, p, cams, *max_faces, Some(&g));
        let mb = |b: u64| b as f64 / (1024.0 * 1024.0);
        println!(
            "| {name} | {} | {} | {:.0} | {:.0} | {} | {} | {} | {:.0} | {:.0} |",
            cpu.mesh.faces.len(),
            if cpu.mesh == dev.mesh { "yes" } else { "NO" },
            cpu.adapt_ms,
            dev.adapt_ms,
            kernel(&dev.device),
            stages(&dev.device),
            dev.device.dispatches,
            mb(dev.device.upload_bytes),
            mb(dev.device.download_bytes),
        );
        finals.push((name.clone(), cams.last().cloned(), cpu.mesh));
    }
    println!("\nStatic state pass over the adapted mesh (median of 5):\n");
    println!("| view | edges | CPU (ms) | CPU M edges/s | GPU wall (ms) | GPU device (ms) | GPU device M edges/s |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for (name, cam, mesh) in finals {
        let Some(cam) = cam else { continue };
        let view = View::new(&cam, p.radius_m, p.min_edge_length_m, riverworld::adapt::terrain_top(p, &planet.mesh));
        let cpu_ms = median_ms(5, || {
            std::hint::black_box(state::edge_wants(&mesh, &view));
        });
        g.take_times();
        let mut device_ms = Vec::new();
        let wall_ms = median_ms(5, || {
            let _ = std::hint::black_box(gpu::edge_wants(&g, &mesh, &view));
            device_ms.push(g.take_times());
        });
        let timed = device_ms.first().copied().unwrap_or_default();
        let mut dms: Vec<f64> = device_ms.iter().map(|d| d.kernel_ms).collect();
        dms.sort_by(f64::total_cmp);
        let dmed = DeviceTimes { kernel_ms: dms[dms.len() / 2], ..timed };
        let e = mesh.edges.len() as f64;
        let rate = if timed.timed { format!("{:.0}", e / dmed.kernel_ms / 1000.0) } else { "n/a".into() };
        println!(
            "| {name} | {} | {cpu_ms:.1} | {:.0} | {wall_ms:.1} | {} | {rate} |",
            mesh.edges.len(),
            e / cpu_ms / 1000.0,
            kernel(&dmed),
        );
    }
}
