//! The face budget's search (`max_faces`): the smallest power of 1.25 by which the target pixel
//! sizes must be scaled for the converged mesh to fit, found with trial adaptions of the one
//! adaption loop (`run.rs`) on whichever backend the adapter has.

use super::cpu::state;
#[cfg(feature = "gpu")]
use super::gpu;
use super::{wishes_exceed, AdaptStats, Adapter, Camera, Fitted, BUDGET_STEP, MAX_STEP, PROBE_STEPS};

/// Default face budget of `riverworld view` (~1.5 GB of mesh: a guard against a camera that
/// would fill the memory).
pub const VIEW_FACES: usize = 20_000_000;
/// Default face budget of `riverworld render`.
pub const RENDER_FACES: usize = 1_000_000;
/// Default face budget of the HTTP views and renders (`max_faces` not given), within the
/// server's `--max-faces-cap`.
pub const HTTP_VIEW_FACES: usize = 500_000;

impl Adapter {
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
    pub(super) fn fit_budget(&mut self, cam: &Camera, max: usize, stats: &mut AdaptStats) -> i32 {
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
                Some(f) if !self.on_gpu() => Some(state::edge_wants(&f.mesh, &view)),
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
        let device = self.device.as_mut().map(gpu::Device::take_copy).unwrap_or_default();
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
        if let Some(device) = &mut self.device {
            device.resume(&fitted.device);
        }
    }

    /// Goes back to the fitted mesh, its device copy included.
    fn restore(&mut self, fitted: Fitted) {
        self.set_mesh(fitted.mesh, fitted.ordered_faces);
        #[cfg(feature = "gpu")]
        if let Some(device) = &mut self.device {
            // (After a fall back to the CPU the kept device copy is dropped instead.)
            device.restore(fitted.device);
        }
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
}
