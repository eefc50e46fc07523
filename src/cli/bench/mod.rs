//! `riverworld bench`: times base-mesh construction (paper §4, Table 4's "creating the base
//! mesh") for random planets and Earth maps, then view-dependent adaption on the Earth planet
//! (`bench_adapt`), and prints Markdown tables.

use riverworld::input::{load_map, MapSource};
use riverworld::maps::MapLimits;
use riverworld::params::Params;
use riverworld::planet::{build_planet, PlanetSpec};
use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

/// One benchmark case.
struct Case {
    name: String,
    spec: PlanetSpec,
}

fn cases(maps: &Path, quick: bool) -> Vec<Case> {
    let random = |faces: u32| Case {
        name: format!("random, {faces} base faces"),
        spec: PlanetSpec {
            seed: 42,
            params: Params { base_faces: faces, ..Params::default() },
            map: None,
            precipitation: None,
        },
    };
    let mut out = vec![random(5_000), random(100_000)];
    if !quick {
        out.push(random(1_000_000));
    }
    let mut maps_list = vec!["earth_landmask_ne10m_1024x512.png"];
    if !quick {
        maps_list.push("earth_landmask_ne10m_4096x2048.png");
    }
    for file in maps_list {
        let src = MapSource { path: maps.join(file), ..MapSource::default() };
        match load_map(&src, &MapLimits::default()) {
            Ok(map) => out.push(Case {
                name: format!("Earth bitmap {file}"),
                spec: PlanetSpec { seed: 42, params: Params::default(), map: Some(Arc::new(map)), precipitation: None },
            }),
            Err(e) => eprintln!("skipping {file}: {e}"),
        }
    }
    out
}

/// The tables `riverworld bench` can print.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Table {
    /// Planet builds.
    Build,
    /// View-dependent adaption.
    Adapt,
    /// End-to-end snapshots.
    Render,
    /// Adaption on the CPU and the wgpu compute backend, side by side.
    Backends,
}

/// Prints the chosen tables (all when `only` is empty); builds run every case `runs` times and
/// report the median.
mod adapt;
mod backends;
mod render;

pub fn run(maps: &Path, runs: usize, quick: bool, only: &[Table]) {
    let wants = |t: Table| only.is_empty() || only.contains(&t);
    if wants(Table::Build) {
        build_table(maps, runs, quick);
    }
    if !wants(Table::Adapt) && !wants(Table::Render) && !wants(Table::Backends) {
        return;
    }
    let src = MapSource { path: maps.join("earth_landmask_ne10m_1024x512.png"), ..MapSource::default() };
    let spec = match load_map(&src, &MapLimits::default()) {
        Ok(map) => PlanetSpec { seed: 42, params: Params::default(), map: Some(Arc::new(map)), precipitation: None },
        Err(e) => return eprintln!("skipping the adaption and snapshot tables: {e}"),
    };
    if wants(Table::Adapt) {
        println!("\n### Adaption, Earth bitmap 1024x512, 1920x1080, default land/water pixel targets\n");
        adapt::run(&spec);
    }
    if wants(Table::Backends) {
        println!("\n### Adaption backends, Earth bitmap 1024x512, 1920x1080, default land/water pixel targets\n");
        backends::run(&spec);
    }
    if wants(Table::Render) {
        println!("\n### Snapshots (render.png), Earth bitmap 1024x512, default targets, median of {runs}\n");
        render::run(&spec, runs);
    }
}

fn build_table(maps: &Path, runs: usize, quick: bool) {
    println!("| case | faces | vertices | bytes/vertex | build ms (median of {runs}) | Mfaces/s |");
    println!("|---|---:|---:|---:|---:|---:|");
    for case in cases(maps, quick) {
        let mut times = Vec::new();
        let mut last = None;
        for _ in 0..runs {
            let t = Instant::now();
            let planet = build_planet(&case.spec, &mut |_, _| {}).expect("benchmark planet builds");
            times.push(t.elapsed().as_secs_f64() * 1000.0);
            last = Some(planet.stats);
        }
        times.sort_by(f64::total_cmp);
        let ms = times[times.len() / 2];
        let s = last.expect("at least one run");
        println!(
            "| {} | {} | {} | {:.1} | {:.1} | {:.2} |",
            case.name,
            s.faces,
            s.vertices,
            s.bytes_per_vertex,
            ms,
            s.faces as f64 / ms / 1000.0
        );
    }
}
