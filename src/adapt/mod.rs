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
#[cfg(feature = "gpu")]
pub mod gpu;
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
    /// The device for the stages that run on the GPU backend; `None` on the CPU backend.
    #[cfg(feature = "gpu")]
    gpu: Option<std::sync::Arc<gpu::GpuAdaption>>,
    /// The mesh on that device, while it equals `mesh`.
    #[cfg(feature = "gpu")]
    resident: gpu::Resident,
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
            gpu: None,
            #[cfg(feature = "gpu")]
            resident: Default::default(),
        }
    }

    /// Runs the stages the GPU backend has on `gpu` (`None`: everything on the CPU).
    #[cfg(feature = "gpu")]
    pub fn with_gpu(mut self, gpu: Option<std::sync::Arc<gpu::GpuAdaption>>) -> Adapter {
        self.gpu = gpu;
        self.resident = Default::default();
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
        if let Some(n) = self.device_faces() {
            return n;
        }
        self.mesh.faces.len()
    }

    /// Brings the host mesh up to date where a run on the device left it behind (the GPU
    /// backend reads a mesh back only when it is going to be used).
    fn sync_host(&mut self) {
        #[cfg(feature = "gpu")]
        self.read_back_mesh();
    }

    /// Drops the device copy of the mesh, after the host copy changed.
    fn forget_device_mesh(&mut self) {
        #[cfg(feature = "gpu")]
        {
            self.resident = Default::default();
        }
    }

    /// Whether stages run on the GPU (false after a device failure fell back to the CPU).
    pub fn on_gpu(&self) -> bool {
        #[cfg(feature = "gpu")]
        return self.gpu.is_some();
        #[cfg(not(feature = "gpu"))]
        false
    }

    /// The state update's split wishes of every edge, on the GPU backend when there is one. A
    /// device failure (lost, out of memory, a mesh beyond its buffer limits) falls back to the
    /// CPU for the rest of this adapter's life and says so in the log.
    fn edge_wants(&mut self, view: &View) -> Vec<bool> {
        #[cfg(feature = "gpu")]
        if let Some(g) = &self.gpu {
            match gpu::edge_wants(g, &self.mesh, view) {
                Ok(w) => return w,
                Err(e) => {
                    tracing::warn!("GPU adaption failed ({e}); continuing on the CPU");
                    self.gpu = None;
                }
            }
        }
        state::edge_wants(&self.mesh, view)
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
        if compact::scattered(self.mesh.faces.len(), self.ordered_faces) {
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

    /// Finds the smallest step `k` whose converged face count `F(k)` is at most `max` and
    /// leaves that mesh; returns `k`.
    ///
    /// `F` falls as `k` grows (a coarser target wants a subset of the splits, and the
    /// converged mesh is the least conforming refinement holding them), so this is a search
    /// over a monotone function. Trials run with the budget as a face cap: refining stops as
    /// soon as the mesh exceeds it, which proves `F(k) > max`. Coarsening (collapses) is the
    /// slow direction, so trials start from the coarsest mesh at hand: the last mesh that
    /// fitted (a sub-refinement of every finer target) or the base mesh.
    ///
    /// The search starts at the previous call's step (frame-to-frame coherence) or, on the
    /// first call, [`PROBE_STEPS`] coarser than the plain target: a cheap first fit that finer
    /// trials refine instead of starting over. From a fitting trial the next step comes from
    /// the faces added to the base mesh growing with the square of the inverse target size
    /// ([`Adapter::steps_to_fill`]), so one overshoot usually ends the search.
    ///
    /// Where an estimate is refuted, steps grow twofold from one trial to the next (finer from
    /// a fitted mesh, coarser before any fits), so that even a camera whose targets fit only
    /// ~130 steps coarser costs a dozen trials rather than a hundred. Between a step over the
    /// budget and a fitted one, a trial that did not halve the range of steps left is followed
    /// by a bisection, so a search where the estimate misleads (a budget the base mesh nearly
    /// fills, where finer targets add a few faces each) still ends in a few dozen trials at most.
    fn fit_budget(&mut self, cam: &Camera, max: usize, stats: &mut AdaptStats) -> i32 {
        if max < self.base.faces.len() {
            // No target fits; the base mesh is the coarsest there is.
            self.reset_to_base();
            stats.converged = false;
            return MAX_STEP;
        }
        let steps_for = |ratio: f64| (ratio.max(1.0).sqrt().ln() / BUDGET_STEP.ln()).ceil() as i32;
        let mut k = self.last_step.unwrap_or(PROBE_STEPS).clamp(0, MAX_STEP);
        let mut over: i32 = -1;
        let mut fits: Option<Fitted> = None;
        let mut first = true;
        // The stride of the next refuted estimate: doubled by each.
        let mut stride = 1;
        // The width of the range of steps left before the last trial, once there is a range.
        let mut last_width: Option<i32> = None;
        loop {
            stats.trials += 1;
            let view = self.view(cam, k);
            // A finer trial from the fitted mesh is over the budget before it starts if the
            // fitted mesh's wanted splits alone would exceed it (no copy needed to know);
            // otherwise the trial starts from a copy with those wishes. (On the GPU backend the
            // run itself checks that first, on a copy made on the device.)
            let wishes = match fits.as_mut() {
                Some(f) if !self.on_gpu() => Some(self.wishes_of(&mut f.mesh, &view)),
                _ => None,
            };
            let hopeless = match (&fits, &wishes) {
                (Some(f), Some(w)) => wishes_exceed(f.mesh.faces.len(), w, max),
                _ => false,
            };
            let (converged, faces) = if hopeless {
                (false, max + 1)
            } else {
                if !first {
                    match &fits {
                        Some(f) => self.resume_from(f),
                        None => self.reset_to_base(),
                    }
                }
                // Later trials start from the base mesh or one that fitted a coarser target:
                // both are sub-refinements of this target's mesh, so they only refine.
                let refine_only = !first || self.fresh;
                let converged = self.run(&view, Some(max), refine_only, wishes, stats);
                (converged, self.face_count())
            };
            first = false;
            if converged && faces <= max {
                stats.converged = true;
                if k == 0 || k == over + 1 {
                    break;
                }
                fits = Some(self.keep_fitted(k));
            } else {
                over = k;
                if k >= MAX_STEP {
                    // Not even the coarsest target fits: a camera so close to the ground that
                    // even 1.25^130 coarser targets want splits there. The base mesh is the
                    // coarsest mesh there is, and no step to start the next search from.
                    stats.converged = false;
                    self.reset_to_base();
                    self.last_step = None;
                    return MAX_STEP;
                }
                if fits.as_ref().is_some_and(|f| f.step == over + 1) {
                    self.restore(fits.take().expect("a fitting mesh"));
                    k = over + 1;
                    break;
                }
            }
            k = match &fits {
                Some(f) => {
                    // The answer is in `over + 1 ..= f.step`: at least two steps here.
                    let width = f.step - over;
                    let guess = f.step - self.steps_to_fill(f.mesh.faces.len(), max);
                    let next = if last_width.is_some_and(|w| 2 * width > w) {
                        // The last trial did not halve the range (the estimate is off, as
                        // where finer targets add almost nothing): bisect.
                        over + width / 2
                    } else if guess > over {
                        stride = 1;
                        guess.min(f.step - 1)
                    } else {
                        // The estimate is refuted (or says nothing, from the base mesh): steps
                        // grow from the last step over the budget, up to the middle.
                        let next = (over + stride).min(over + width / 2);
                        stride = stride.saturating_mul(2);
                        next
                    };
                    last_width = Some(width);
                    next
                }
                None => {
                    let next = k.saturating_add(steps_for(faces as f64 / max as f64).max(stride));
                    stride = stride.saturating_mul(2);
                    next.min(MAX_STEP)
                }
            };
        }
        self.last_step = Some(k);
        k
    }

    /// Takes the mesh (and its device copy) as the budget search's fitted mesh of `step`.
    fn keep_fitted(&mut self, step: i32) -> Fitted {
        self.sync_host();
        #[cfg(feature = "gpu")]
        let device = self.take_device_mesh();
        self.forget_device_mesh();
        Fitted {
            step,
            mesh: std::mem::take(&mut self.mesh),
            ordered_faces: self.ordered_faces,
            #[cfg(feature = "gpu")]
            device,
        }
    }

    /// Starts a trial from a copy of the fitted mesh (and of its device copy).
    fn resume_from(&mut self, fitted: &Fitted) {
        self.set_mesh(fitted.mesh.clone(), fitted.ordered_faces);
        #[cfg(feature = "gpu")]
        self.resume_device_mesh(&fitted.device);
    }

    /// Goes back to the fitted mesh, its device copy included.
    fn restore(&mut self, fitted: Fitted) {
        self.set_mesh(fitted.mesh, fitted.ordered_faces);
        #[cfg(feature = "gpu")]
        if self.gpu.is_some() {
            // (After a fall back to the CPU the kept device copy is dropped instead.)
            self.resident = fitted.device;
        }
    }

    /// Compacts the mesh during a run, keeping the order of what stays.
    fn compact(&mut self) {
        self.forget_device_mesh();
        compact::compact(&mut self.mesh);
        self.ordered_faces = self.ordered_faces.min(self.mesh.faces.len());
    }

    /// Puts the mesh kept between cameras in spatial order; its device copy (equal to it between
    /// cameras) follows on the device.
    fn order(&mut self) {
        let order = compact::order(&mut self.mesh);
        self.ordered_faces = self.mesh.faces.len();
        #[cfg(feature = "gpu")]
        self.renumber_device_mesh(&order);
        #[cfg(not(feature = "gpu"))]
        drop(order);
    }

    /// The state update's split wishes of the edges of `mesh` (lent to the adapter for it).
    fn wishes_of(&mut self, mesh: &mut Mesh, view: &View) -> Vec<bool> {
        std::mem::swap(&mut self.mesh, mesh);
        let wishes = self.edge_wants(view);
        std::mem::swap(&mut self.mesh, mesh);
        wishes
    }

    /// How many steps finer than a fitting mesh of `faces` faces the budget `max` allows, by
    /// the faces added to the base mesh growing `1.25^2`-fold per step (where the view stays at
    /// the base mesh's resolution nothing grows). Large when the mesh is the base mesh itself.
    fn steps_to_fill(&self, faces: usize, max: usize) -> i32 {
        let base = self.base.faces.len() as f64;
        let (added, room) = (faces as f64 - base, max as f64 - base);
        if added < 1.0 {
            return MAX_STEP;
        }
        ((room / added).max(1.0).ln() / (2.0 * BUDGET_STEP.ln())).floor() as i32
    }

    /// Passes until nothing changes (true), the face cap is exceeded or the pass limit is hit;
    /// on the device when the adapter has one (`gpu/adapt.rs`, the same passes).
    ///
    /// With the camera fixed, an edge's answer never changes, so the flags are computed once
    /// and then only for edges the splits touched; collapses are looked for in the first pass,
    /// after a pass that collapsed something (coarsening unwinds level by level), and before
    /// convergence is declared — except with `refine_only`, for a mesh that is a sub-refinement
    /// of the target's (the base mesh, or one converged for a coarser target): every vertex it
    /// has or gains is wanted or needed by a wanted split, so no collapse can be due.
    /// `wishes`, when given, are the state update's answers for the mesh as it is.
    ///
    /// Collapses only mark what they remove, so the flags stay indexed by slot and need answers
    /// only for the edges the collapses restored; the face cap counts live faces. The holes are
    /// compacted once at the end, or early when they outgrow both a quarter of the face slots and
    /// the slack `N_ALLOC`.
    fn run(
        &mut self,
        view: &View,
        cap: Option<usize>,
        refine_only: bool,
        wishes: Option<Vec<bool>>,
        stats: &mut AdaptStats,
    ) -> bool {
        self.sync_host();
        #[cfg(feature = "gpu")]
        if let Some(g) = self.gpu.clone() {
            let before = (stats.clone(), self.ordered_faces);
            match self.run_on_device(&g, view, Some(face_cap(cap)), refine_only, stats) {
                Ok(converged) => return converged,
                Err(e) => {
                    // The host mesh is still the one the run started from: run it again here.
                    tracing::warn!("GPU adaption failed ({e}); continuing on the CPU");
                    self.gpu = None;
                    (*stats, self.ordered_faces) = before;
                }
            }
        }
        self.forget_device_mesh();
        self.run_on_cpu(view, Some(face_cap(cap)), refine_only, wishes, stats)
    }

    /// [`Adapter::run`] on the CPU.
    fn run_on_cpu(
        &mut self,
        view: &View,
        cap: Option<usize>,
        refine_only: bool,
        wishes: Option<Vec<bool>>,
        stats: &mut AdaptStats,
    ) -> bool {
        let mut t = Instant::now();
        let mut wants = match wishes {
            Some(w) => w,
            None => self.edge_wants(view),
        };
        lap(&mut t, &mut stats.stage_ms.state);
        if refine_only && cap.is_some_and(|c| wishes_exceed(self.mesh.faces.len(), &wants, c)) {
            return false;
        }
        let mut converged = false;
        let mut dead_faces = 0;
        let mut look_for_collapses = true;
        // Where the last collapses may have made more collapsible (None: look everywhere). Only
        // the newest vertices of the faces a collapse restores can have become collapsible;
        // elsewhere neither a vertex's faces nor the demanded edges changed.
        let mut apexes: Option<Vec<u32>> = None;
        let mut selection = split::Selection::default();
        for _ in 0..MAX_PASSES {
            stats.passes += 1;
            // Over the face cap: only coarsen; if nothing can be, a coarser target is needed.
            let over_cap = cap.is_some_and(|c| self.mesh.faces.len() - dead_faces > c);
            if refine_only && over_cap {
                break;
            }
            let ready = if over_cap { Vec::new() } else { selection.select(&self.mesh, &wants) };
            lap(&mut t, &mut stats.stage_ms.select);
            // From a sub-refinement every ready split is in the target's mesh: if they would
            // take it over the cap, that already proves it (and memory stays within the cap).
            if refine_only && cap.is_some_and(|c| self.mesh.faces.len() - dead_faces + 2 * ready.len() > c) {
                break;
            }
            let answers = split::apply_splits(&mut self.mesh, &ready, &self.params, view);
            let splits = ready.len();
            state::record_splits(&mut wants, &ready, &answers);
            lap(&mut t, &mut stats.stage_ms.split);
            let mut collapses = 0;
            if !refine_only && (look_for_collapses || splits == 0) {
                let demanded = split::demanded(&self.mesh, &wants);
                let mut sites = state::collapse_candidates(&self.mesh, view, &demanded, apexes.as_deref());
                if sites.is_empty() && splits == 0 && apexes.is_some() {
                    // Convergence is only declared after a look at every vertex.
                    sites = state::collapse_candidates(&self.mesh, view, &demanded, None);
                }
                collapses = collapse::apply_collapses(&mut self.mesh, &sites);
                lap(&mut t, &mut stats.stage_ms.collapse);
                apexes = Some(state::restored_apexes(&sites));
                if collapses > 0 {
                    dead_faces += 2 * collapses;
                    if dead_faces > compact::N_ALLOC.max(self.mesh.faces.len() / 4) {
                        // Many holes: squeeze them out now (and decide every edge again) so
                        // that memory stays within the slack policy.
                        self.compact();
                        dead_faces = 0;
                        apexes = None;
                        lap(&mut t, &mut stats.stage_ms.compact);
                        wants = self.edge_wants(view);
                    } else {
                        state::update_after_collapses(&self.mesh, view, &mut wants, &sites);
                    }
                    lap(&mut t, &mut stats.stage_ms.state);
                }
            }
            look_for_collapses = collapses > 0;
            stats.splits += splits;
            stats.collapses += collapses;
            if splits == 0 && collapses == 0 {
                converged = !over_cap;
                break;
            }
            if !over_cap && cap.is_some_and(|c| self.mesh.faces.len() - dead_faces > c) {
                look_for_collapses = true;
                apexes = None;
            }
        }
        if dead_faces > 0 {
            self.compact();
            lap(&mut t, &mut stats.stage_ms.compact);
        }
        converged
    }
}

#[cfg(test)]
mod tests;
