//! The adaption loop (paper §5, Figure 4): passes of state update, split-list compaction,
//! splits, collapses and compaction until the mesh no longer changes, written once over a
//! [`Passes`] backend that works a whole pass at a time — the CPU reference (`cpu/mod.rs`) or
//! the wgpu device (`gpu/run.rs`, which records a pass as one submission). Both backends
//! therefore make the same splits and collapses in the same passes.
//!
//! With the camera fixed, an edge's answer never changes, so the split wishes are decided once
//! and then only for edges the splits or collapses touched; collapses are looked for in the first
//! pass, after a pass that collapsed something (coarsening unwinds level by level), and before
//! convergence is declared — except with `refine_only`, for a mesh that is a sub-refinement of
//! the target's (the base mesh, or one converged for a coarser target): every vertex it has or
//! gains is wanted or needed by a wanted split, so no collapse can be due.
//!
//! Collapses only mark what they remove, so the wishes stay indexed by slot and need answers
//! only for the edges the collapses restored; the face cap counts live faces. The holes are
//! compacted once at the end, or early when they outgrow both a quarter of the face slots and
//! the slack `N_ALLOC` (and then every edge is decided again).

use super::camera::View;
use super::cpu::compact::N_ALLOC;
use super::{AdaptStats, StageTimes, MAX_PASSES};

/// Where the collapse candidates of a pass are looked for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Look {
    /// Only among the newest vertices of the faces the last collapses restored (elsewhere
    /// neither a vertex's faces nor the demanded edges changed since the last look).
    pub among_apexes: bool,
    /// Look at every vertex when none of those is a candidate (convergence is only declared
    /// after a look at every vertex).
    pub everywhere_if_none: bool,
}

/// A backend of the adaption loop: the mesh it adapts, and the stages of a pass over it. Each
/// method adds the time it took to its stages in `times`.
pub(crate) trait Passes {
    type Error;

    /// Face slots of the mesh, dead ones of collapses included.
    fn faces(&self) -> usize;

    /// The state update of every edge: how many want a split.
    fn decide(&mut self, view: &View, times: &mut StageTimes) -> Result<usize, Self::Error>;

    /// How many edges the next pass splits (the split-list compaction of the wishes as they
    /// are now).
    fn ready(&mut self, times: &mut StageTimes) -> Result<usize, Self::Error>;

    /// One pass: the ready edges split when `split` (with the state update of the edges the
    /// splits make or change), then, with `look`, collapse candidates looked for there and
    /// collapsed (with the state update of the edges they restore). Returns the collapses.
    fn pass(
        &mut self,
        view: &View,
        split: bool,
        look: Option<Look>,
        times: &mut StageTimes,
    ) -> Result<usize, Self::Error>;

    /// Squeezes out the entities of `dead_faces / 2` collapses, keeping the order of the rest.
    fn compact(&mut self, dead_faces: usize, times: &mut StageTimes) -> Result<(), Self::Error>;
}

/// What one run adapts to: the view, the face cap (live faces), and whether the mesh is a
/// sub-refinement of the target's, so that it only needs refining.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Target<'a> {
    pub view: &'a View,
    pub cap: Option<usize>,
    pub refine_only: bool,
}

/// What [`adapt`] did besides its statistics.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Outcome {
    /// Nothing more to split or collapse, within the face cap.
    pub converged: bool,
    /// Whether any split or collapse was made.
    pub changed: bool,
    /// Faces left by the smallest compaction (to know how much of the mesh is still in the
    /// spatial order it had); `None` without compaction.
    pub compacted_to: Option<usize>,
}

impl Outcome {
    fn compacted(&mut self, faces: usize) {
        self.compacted_to = Some(self.compacted_to.map_or(faces, |c| c.min(faces)));
    }
}

/// Passes until nothing changes (`converged`), the face cap is exceeded or [`MAX_PASSES`] is
/// hit. See the module doc for the policy.
pub(crate) fn adapt<P: Passes>(mesh: &mut P, target: Target, stats: &mut AdaptStats) -> Result<Outcome, P::Error> {
    let Target { view, cap, refine_only } = target;
    let over = |faces: usize| cap.is_some_and(|c| faces > c);
    let mut outcome = Outcome { converged: false, changed: false, compacted_to: None };
    let wanted = mesh.decide(view, &mut stats.stage_ms)?;
    // From a sub-refinement every wanted split is in the target's mesh, and each adds two faces.
    if refine_only && over(mesh.faces() + 2 * wanted) {
        return Ok(outcome);
    }
    let mut dead_faces = 0;
    let mut look_for_collapses = true;
    let mut among_apexes = false;
    for _ in 0..MAX_PASSES {
        stats.passes += 1;
        // Over the face cap: only coarsen; if nothing can be, a coarser target is needed.
        let over_cap = over(mesh.faces() - dead_faces);
        if refine_only && over_cap {
            break;
        }
        let splits = if over_cap { 0 } else { mesh.ready(&mut stats.stage_ms)? };
        // From a sub-refinement every ready split is in the target's mesh: if they would take it
        // over the cap, that already proves it (and memory stays within the cap).
        if refine_only && over(mesh.faces() - dead_faces + 2 * splits) {
            break;
        }
        let collapse_step = !refine_only && (look_for_collapses || splits == 0);
        let look = collapse_step.then_some(Look { among_apexes, everywhere_if_none: splits == 0 && among_apexes });
        if splits == 0 && look.is_none() {
            // Refining only, and nothing left to split.
            outcome.converged = true;
            break;
        }
        let collapses = mesh.pass(view, splits > 0, look, &mut stats.stage_ms)?;
        among_apexes |= collapse_step;
        if collapses > 0 {
            dead_faces += 2 * collapses;
            if dead_faces > N_ALLOC.max(mesh.faces() / 4) {
                // Many holes: squeeze them out now (and decide every edge again) so that
                // memory stays within the slack policy.
                mesh.compact(dead_faces, &mut stats.stage_ms)?;
                dead_faces = 0;
                among_apexes = false;
                outcome.compacted(mesh.faces());
                mesh.decide(view, &mut stats.stage_ms)?;
            }
        }
        look_for_collapses = collapses > 0;
        stats.splits += splits;
        stats.collapses += collapses;
        outcome.changed |= splits + collapses > 0;
        if splits == 0 && collapses == 0 {
            outcome.converged = !over_cap;
            break;
        }
        if !over_cap && over(mesh.faces() - dead_faces) {
            look_for_collapses = true;
            among_apexes = false;
        }
    }
    if dead_faces > 0 {
        mesh.compact(dead_faces, &mut stats.stage_ms)?;
        outcome.compacted(mesh.faces());
    }
    Ok(outcome)
}
