//! View-dependent adaption (paper §5): refine and coarsen the planet for a camera. [`Adapter`]
//! keeps a mesh between cameras; the adaption loop (`run.rs`) and the face budget's search
//! (`budget.rs`) are written once over two backends, the CPU reference (`cpu/`) and the wgpu
//! device (`gpu/`), whose stages carry the same names: state update (`state`), split-list
//! compaction (`select`), edge splits (`split`), vertex collapses (`collapse`), memory
//! management and compaction (`compact`), each with its shader `shaders/adapt/<stage>.wgsl`.
//!
//! Positions stay `f64` metres in the planet-centred frame throughout, so the 1 cm minimum edge
//! length is far above rounding at Earth radius (an `f64` there resolves ~1 nm). Exports move the
//! mesh to a local origin before converting to `f32`.
//!
//! Reproducibility (§3.1): each split sees the same four vertices (newest-vertex bisection) and
//! draws its random numbers from its vertex's seed, and the refinement criterion is hereditary
//! (see `camera.rs`), so adaption run to convergence gives the same mesh for a camera whatever
//! was adapted before.

mod budget;
pub use budget::{HTTP_VIEW_FACES, RENDER_FACES, VIEW_FACES};
pub mod camera;
pub mod cpu;
pub mod flight;
#[cfg(feature = "gpu")]
pub mod gpu;
mod run;

pub use camera::{Camera, CameraError, View};

use crate::mesh::Mesh;
use crate::params::Params;
use serde::Serialize;
use std::time::Instant;

/// Most passes one adaption runs before it reports that it did not converge.
pub const MAX_PASSES: usize = 400;
/// Each step of the face budget's search scales the criterion's `c` by this.
const BUDGET_STEP: f64 = 1.25;
/// Coarsest step of the face budget's search (`1.25^130` is about 4e12).
const MAX_STEP: i32 = 130;
/// How much coarser than the plain target the first budget search probes (faces added to the
/// base mesh shrink about `1.25^2`-fold per step: six steps are ~15 times fewer).
const PROBE_STEPS: i32 = 6;

/// How far above the highest terrain that the parameters and the base mesh allow horizon
/// culling still looks: splits may lift a vertex somewhat above those bounds (a riverbank
/// rising from a spring at the highest altitude allowed).
pub const HORIZON_MARGIN: f64 = 7_000.0;

/// The highest altitude above the base sphere, metres, that terrain or water adapted from
/// `base` with `params` may reach, margin included: the highest mountain, spring or sea level
/// the parameters allow, or the highest vertex of the base mesh where a map put one above them.
pub fn terrain_top(params: &Params, base: &Mesh) -> f64 {
    let highest = base.vertices.iter().map(|v| v.ground.max(v.water)).fold(f64::MIN, f64::max);
    let allowed = params.max_mountain_altitude_m.max(params.max_river_altitude_m).max(params.sea_level_m);
    allowed.max(highest) + HORIZON_MARGIN
}

/// Most faces an adapted mesh may have before adaption stops refining, whatever the budget
/// (`converged: false`). The cap is checked before each pass, whose slots hold at most a third
/// more dead ones of collapses (a quarter of all slots), and one pass at most doubles the live
/// faces: under `7/3` of the cap in all, so the edges (1.5 per face) stay within the `u32`
/// index range, whose top values mark absent and removed entities.
pub const MAX_MESH_FACES: usize = 1 << 30;

/// The face cap of a run: its budget, never above [`MAX_MESH_FACES`].
fn face_cap(budget: Option<usize>) -> usize {
    budget.unwrap_or(MAX_MESH_FACES).min(MAX_MESH_FACES)
}

/// A face budget smaller than the base mesh, the coarsest mesh adaption can give (collapses
/// never remove a base vertex).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BudgetBelowBase {
    pub max_faces: usize,
    pub base_faces: usize,
}

impl std::fmt::Display for BudgetBelowBase {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} faces is below the {} faces of this planet's base mesh, its coarsest view",
            self.max_faces, self.base_faces
        )
    }
}

impl std::error::Error for BudgetBelowBase {}

/// Refuses a face budget that no adaption of `base` can respect.
pub fn check_budget(base: &Mesh, max_faces: usize) -> Result<(), BudgetBelowBase> {
    match base.faces.len() {
        n if max_faces < n => Err(BudgetBelowBase { max_faces, base_faces: n }),
        _ => Ok(()),
    }
}

/// The face budget for views of `base`: the one `asked` for, refused below the base mesh (no
/// view can be coarser), else `default` raised to the base mesh where that is larger (the view
/// is then the base mesh).
pub fn face_budget(base: &Mesh, asked: Option<usize>, default: usize) -> Result<usize, BudgetBelowBase> {
    match asked {
        Some(n) => check_budget(base, n).map(|()| n),
        None => Ok(default.max(base.faces.len())),
    }
}

/// What one adaption did (`riverworld view --stats`). Splits, collapses and passes count all
/// the work done: with a face budget, that includes the trials of the search for the scale
/// that fits (see [`Adapter::fit_budget`]), whose meshes are thrown away.
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
    /// Targets the face budget's search tried (0 without a budget).
    pub trials: usize,
    /// Wall time per stage, milliseconds.
    pub stage_ms: StageTimes,
}

/// Wall time of each adaption stage (`AdaptStats::stage_ms`), milliseconds.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct StageTimes {
    /// State update: split wishes of every edge (and again after a compaction, or of the
    /// edges collapses restored).
    pub state: f64,
    /// Split-list compaction: blocker chains to the ready edges.
    pub select: f64,
    /// Edge splits (new vertices, then topology), with the split wishes of the edges each
    /// split makes or changes (the state update of the refining passes).
    pub split: f64,
    /// Collapse marks (demanded edges, candidates) and vertex collapses.
    pub collapse: f64,
    /// Buffer compaction after collapses.
    pub compact: f64,
}

/// Whether refining a mesh of `faces` faces with split wishes `wants`, a sub-refinement of the
/// target's converged mesh, must exceed `max` faces: each edge that wants a split is split in
/// the converged mesh (a wish depends on the edge alone), and each split adds two faces.
fn wishes_exceed(faces: usize, wants: &[bool], max: usize) -> bool {
    faces + 2 * wants.iter().filter(|&&w| w).count() > max
}

/// The mesh of the finest budget-search trial that fitted so far, and its step.
struct Fitted {
    step: i32,
    mesh: Mesh,
    /// [`Adapter::ordered_faces`] of that mesh.
    ordered_faces: usize,
    /// Its device copy on the GPU backend, so that finer trials start from a copy made on the
    /// device instead of an upload.
    #[cfg(feature = "gpu")]
    device: gpu::Resident,
}

/// Adds the time since `t` to `slot` and restarts `t`.
fn lap(t: &mut Instant, slot: &mut f64) {
    *slot += t.elapsed().as_secs_f64() * 1000.0;
    *t = Instant::now();
}

/// Keeps a mesh between cameras (the paper's frame-to-frame mode).
#[derive(Clone, Debug)]
pub struct Adapter {
    mesh: Mesh,
    params: Params,
    /// The mesh adaption started from; budget searches restart from it instead of coarsening.
    base: Mesh,
    /// Whether the mesh is still the base mesh (nothing adapted yet).
    fresh: bool,
    /// [`terrain_top`] of the base mesh.
    top: f64,
    /// Step of the last budget search (see [`Adapter::fit_budget`]); `None` before the first.
    last_step: Option<i32>,
    /// Faces of the mesh when its buffers were last put in spatial order (see `compact.rs`).
    ordered_faces: usize,
    /// The GPU backend and the device copy of the mesh; `None` on the CPU backend (or after
    /// a device failure fell back to it).
    #[cfg(feature = "gpu")]
    device: Option<gpu::Device>,
}

impl Adapter {
    /// Starts from a base mesh.
    pub fn new(base: Mesh, params: Params) -> Adapter {
        Adapter {
            mesh: base.clone(),
            top: terrain_top(&params, &base),
            params,
            ordered_faces: base.faces.len(),
            base,
            fresh: true,
            last_step: None,
            #[cfg(feature = "gpu")]
            device: None,
        }
    }

    /// Runs the stages the GPU backend has on `gpu` (`None`: everything on the CPU).
    #[cfg(feature = "gpu")]
    pub fn with_gpu(mut self, gpu: Option<std::sync::Arc<gpu::GpuAdaption>>) -> Adapter {
        self.device = gpu.map(gpu::Device::new);
        self
    }

    /// Replaces the mesh, dropping the old one (and its device copy, unread); `ordered_faces`
    /// is the new mesh's (see [`Adapter::ordered_faces`]).
    fn set_mesh(&mut self, mesh: Mesh, ordered_faces: usize) {
        self.forget_device_mesh();
        self.mesh = mesh;
        self.ordered_faces = ordered_faces;
    }

    /// Goes back to the base mesh.
    fn reset_to_base(&mut self) {
        self.set_mesh(self.base.clone(), self.base.faces.len());
    }

    /// Faces of the current mesh (slots, dead ones included), wherever it is.
    fn face_count(&self) -> usize {
        #[cfg(feature = "gpu")]
        if let Some(n) = self.device.as_ref().and_then(gpu::Device::faces_ahead) {
            return n;
        }
        self.mesh.faces.len()
    }

    /// Brings the host mesh up to date where a run on the device left it behind (the GPU
    /// backend reads a mesh back only when it is going to be used). A device failure here
    /// leaves the older host mesh and the CPU backend, and says so.
    fn sync_host(&mut self) {
        #[cfg(feature = "gpu")]
        if let Some(device) = &mut self.device {
            if let Err(e) = device.read_back(&mut self.mesh, &self.base) {
                tracing::warn!("reading the adapted mesh back failed ({e}); continuing on the CPU");
                self.device = None;
            }
        }
    }

    /// Drops the device copy of the mesh, after the host copy changed.
    fn forget_device_mesh(&mut self) {
        #[cfg(feature = "gpu")]
        if let Some(device) = &mut self.device {
            device.forget();
        }
    }

    /// Whether stages run on the GPU (false after a device failure fell back to the CPU).
    pub fn on_gpu(&self) -> bool {
        #[cfg(feature = "gpu")]
        return self.device.is_some();
        #[cfg(not(feature = "gpu"))]
        false
    }

    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    pub fn into_mesh(self) -> Mesh {
        self.mesh
    }

    /// Adapts to `cam` until the mesh stops changing. With `max_faces`, the target pixel sizes
    /// are scaled by the smallest power of 1.25 whose converged mesh fits (the most important
    /// splits, the largest projected edges, are the ones kept), so the result still depends only
    /// on the camera and the budget. See [`Adapter::fit_budget`] for how that power is found.
    /// A budget below the base mesh (see [`check_budget`]) leaves the base mesh and reports
    /// `converged: false`.
    pub fn adapt(&mut self, cam: &Camera, max_faces: Option<usize>) -> AdaptStats {
        let start = Instant::now();
        let mut stats = AdaptStats { lod_scale: 1.0, ..AdaptStats::default() };
        if cpu::compact::scattered(self.mesh.faces.len(), self.ordered_faces) {
            // Kept between cameras, the mesh is worth ordering once most of it was appended.
            let mut t = Instant::now();
            self.order();
            lap(&mut t, &mut stats.stage_ms.compact);
        }
        let step = match max_faces {
            None => {
                stats.converged = self.run(&self.view(cam, 0), None, self.fresh, None, &mut stats);
                0
            }
            Some(max) => self.fit_budget(cam, max, &mut stats),
        };
        self.sync_host();
        self.fresh = false;
        stats.lod_scale = BUDGET_STEP.powi(step);
        stats.faces = self.mesh.faces.len();
        stats.vertices = self.mesh.vertices.len();
        stats.bytes_per_vertex = self.mesh.bytes_per_vertex();
        stats.adapt_ms = start.elapsed().as_secs_f64() * 1000.0;
        stats
    }

    /// The view of `cam` with its pixel targets scaled by `1.25^step`.
    fn view(&self, cam: &Camera, step: i32) -> View {
        let mut view = View::new(cam, self.params.radius_m, self.params.min_edge_length_m, self.top);
        let scale = BUDGET_STEP.powi(step);
        view.c_land *= scale;
        view.c_water *= scale;
        view
    }

    /// Puts the mesh kept between cameras in spatial order; its device copy (equal to it between
    /// cameras) follows on the device.
    fn order(&mut self) {
        let order = cpu::compact::order(&mut self.mesh);
        self.ordered_faces = self.mesh.faces.len();
        #[cfg(feature = "gpu")]
        if let Some(device) = &mut self.device {
            device.renumber(&order);
        }
        #[cfg(not(feature = "gpu"))]
        drop(order);
    }

    /// Passes until nothing changes (true), the face cap is exceeded or the pass limit is hit
    /// (`run.rs`), on the device when the adapter has one. `wishes`, when given, are the state
    /// update's answers for the mesh as it is.
    fn run(
        &mut self,
        view: &View,
        cap: Option<usize>,
        refine_only: bool,
        wishes: Option<Vec<bool>>,
        stats: &mut AdaptStats,
    ) -> bool {
        self.sync_host();
        let target = run::Target { view, cap: Some(face_cap(cap)), refine_only };
        #[cfg(feature = "gpu")]
        if let Some(device) = &mut self.device {
            let before = stats.clone();
            match device.run(&mut self.mesh, &self.base, &self.params, target, stats) {
                Ok(outcome) => return self.ran(outcome),
                Err(e) => {
                    // The host mesh is still the one the run started from: run it again here.
                    tracing::warn!("GPU adaption failed ({e}); continuing on the CPU");
                    self.device = None;
                    *stats = before;
                }
            }
        }
        let mut passes = cpu::CpuPasses::new(&mut self.mesh, &self.params, wishes);
        let Ok(outcome) = run::adapt(&mut passes, target, stats);
        self.ran(outcome)
    }

    /// Takes note of a run's compactions (the mesh's ordered part shrinks with them) and
    /// returns whether it converged.
    fn ran(&mut self, outcome: run::Outcome) -> bool {
        if let Some(faces) = outcome.compacted_to {
            self.ordered_faces = self.ordered_faces.min(faces);
        }
        outcome.converged
    }
}

#[cfg(test)]
mod tests;
