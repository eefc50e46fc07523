//! View-dependent adaption (paper §5): refine and coarsen the planet for a camera, one
//! data-parallel stage per file — state update (`state`), edge splits (`split`), vertex
//! collapses (`collapse`), memory management and compaction (`compact`) — repeated until the
//! mesh no longer changes.
//!
//! Positions stay `f64` metres in the planet-centred frame throughout, so the 1 cm minimum edge
//! length is far above rounding at Earth radius (an `f64` there resolves ~1 nm). Exports move the
//! mesh to a local origin before converting to `f32`.
//!
//! Reproducibility (§3.1): each split sees the same four vertices (newest-vertex bisection) and
//! draws its random numbers from its vertex's seed, and the refinement criterion is hereditary
//! (see `camera.rs`), so adaption run to convergence gives the same mesh for a camera whatever
//! was adapted before.

pub mod camera;
pub mod collapse;
pub mod compact;
pub mod split;
pub mod state;

pub use camera::{Camera, CameraError, View};

use crate::mesh::Mesh;
use crate::params::Params;
use serde::Serialize;
use std::time::Instant;

/// Most passes one adaption runs before it reports that it did not converge.
pub const MAX_PASSES: usize = 400;
/// Each step of the face budget's search scales the criterion's `c` by this.
const BUDGET_STEP: f64 = 1.25;

/// What one adaption did (`riverworld view --stats`).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct AdaptStats {
    pub faces: usize,
    pub vertices: usize,
    pub splits: usize,
    pub collapses: usize,
    pub passes: usize,
    pub adapt_ms: f64,
    pub bytes_per_vertex: f64,
    pub converged: bool,
    /// Factor applied to the target pixel sizes to respect `max_faces` (1 = not limited).
    pub lod_scale: f64,
}

/// Keeps a mesh between cameras (the paper's frame-to-frame mode).
#[derive(Clone, Debug)]
pub struct Adapter {
    mesh: Mesh,
    params: Params,
}

impl Adapter {
    /// Starts from a base mesh.
    pub fn new(base: Mesh, params: Params) -> Adapter {
        Adapter { mesh: base, params }
    }

    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    pub fn into_mesh(self) -> Mesh {
        self.mesh
    }

    /// Adapts to `cam` until the mesh stops changing. With `max_faces`, the target pixel sizes
    /// grow in steps of 1.25x until the converged mesh fits: the most important splits (largest
    /// projected edges) are the ones kept, and the result still depends only on the camera.
    pub fn adapt(&mut self, cam: &Camera, max_faces: Option<usize>) -> AdaptStats {
        let start = Instant::now();
        let mut stats = AdaptStats { lod_scale: 1.0, ..AdaptStats::default() };
        let mut scale = 1.0;
        loop {
            let mut view = View::new(cam, self.params.radius_m, self.params.min_edge_length_m);
            view.c_land *= scale;
            view.c_water *= scale;
            let cap = max_faces.map(|m| m.saturating_mul(4).max(64));
            let converged = self.run(&view, cap, &mut stats);
            let over = max_faces.is_some_and(|m| self.mesh.faces.len() > m);
            if !over {
                stats.converged = converged;
                break;
            }
            scale *= BUDGET_STEP;
            if scale > 1.0e12 {
                stats.converged = false;
                break;
            }
        }
        stats.lod_scale = scale;
        stats.faces = self.mesh.faces.len();
        stats.vertices = self.mesh.vertices.len();
        stats.bytes_per_vertex = self.mesh.bytes_per_vertex();
        stats.adapt_ms = start.elapsed().as_secs_f64() * 1000.0;
        stats
    }

    /// Passes until nothing changes (true), the face cap is exceeded or the pass limit is hit.
    ///
    /// With the camera fixed, an edge's answer never changes, so the flags are computed once
    /// and then only for edges the splits touched; collapses are looked for in the first pass,
    /// after a pass that collapsed something (coarsening unwinds level by level), and before
    /// convergence is declared.
    fn run(&mut self, view: &View, cap: Option<usize>, stats: &mut AdaptStats) -> bool {
        let mut wants = state::edge_wants(&self.mesh, view);
        let mut look_for_collapses = true;
        for _ in 0..MAX_PASSES {
            stats.passes += 1;
            // Over the face cap: only coarsen; if nothing can be, a coarser target is needed.
            let over_cap = cap.is_some_and(|c| self.mesh.faces.len() > c);
            let ready = if over_cap { Vec::new() } else { split::select_splits(&self.mesh, &wants) };
            let splits = split::apply_splits(&mut self.mesh, &ready, &self.params);
            if splits > 0 {
                state::update_wants(&self.mesh, view, &mut wants, &ready);
            }
            let mut collapses = 0;
            if look_for_collapses || splits == 0 {
                let demanded = state::demanded(&self.mesh, &wants);
                let sites = state::collapse_candidates(&self.mesh, view, &demanded);
                collapses = collapse::apply_collapses(&mut self.mesh, &sites);
                if collapses > 0 {
                    compact::compact(&mut self.mesh);
                    wants = state::edge_wants(&self.mesh, view);
                }
            }
            look_for_collapses = collapses > 0;
            stats.splits += splits;
            stats.collapses += collapses;
            if splits == 0 && collapses == 0 {
                return !over_cap;
            }
            if !over_cap && cap.is_some_and(|c| self.mesh.faces.len() > c) {
                look_for_collapses = true;
            }
        }
        false
    }
}

#[cfg(test)]
mod tests;
