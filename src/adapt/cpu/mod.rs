//! The CPU backend of view-dependent adaption (paper §5), the reference the device stages of
//! `adapt/gpu/` are checked against: one data-parallel stage per file, named as its device twin
//! (`adapt/gpu/<stage>.rs`, `shaders/adapt/<stage>.wgsl`) — state update (`state`), split-list
//! compaction (`select`), edge splits (`split`), vertex collapses (`collapse`), memory management
//! and compaction (`compact`) — and [`CpuPasses`], which works a whole pass of them for the one
//! adaption loop (`adapt/run.rs`).

pub mod collapse;
pub mod compact;
pub mod select;
pub mod split;
pub mod state;

use super::camera::View;
use super::run::{Look, Passes};
use super::{lap, StageTimes};
use crate::mesh::Mesh;
use crate::params::Params;
use std::convert::Infallible;
use std::time::Instant;

/// A mesh being adapted on the CPU, with what its passes keep between them: the split wishes of
/// every edge slot, the chains' flags of the split-list compaction, the ready list of the next
/// pass once known, and the vertices the last collapses made worth another look.
pub(crate) struct CpuPasses<'a> {
    mesh: &'a mut Mesh,
    params: &'a Params,
    wants: Vec<bool>,
    /// Wishes for the mesh as it is, given by the caller, taken by the first [`Passes::decide`].
    given: Option<Vec<bool>>,
    selection: select::Selection,
    ready: Option<Vec<u32>>,
    apexes: Vec<u32>,
}

impl<'a> CpuPasses<'a> {
    /// Adapts `mesh`; `wishes`, when given, are the state update's answers for it as it is.
    pub(crate) fn new(mesh: &'a mut Mesh, params: &'a Params, wishes: Option<Vec<bool>>) -> CpuPasses<'a> {
        CpuPasses {
            mesh,
            params,
            wants: Vec::new(),
            given: wishes,
            selection: Default::default(),
            ready: None,
            apexes: Vec::new(),
        }
    }
}

impl Passes for CpuPasses<'_> {
    type Error = Infallible;

    fn faces(&self) -> usize {
        self.mesh.faces.len()
    }

    fn decide(&mut self, view: &View, times: &mut StageTimes) -> Result<usize, Infallible> {
        let mut t = Instant::now();
        self.wants = match self.given.take() {
            Some(w) => w,
            None => state::edge_wants(self.mesh, view),
        };
        self.ready = None;
        lap(&mut t, &mut times.state);
        Ok(self.wants.iter().filter(|&&w| w).count())
    }

    fn ready(&mut self, times: &mut StageTimes) -> Result<usize, Infallible> {
        if self.ready.is_none() {
            let mut t = Instant::now();
            self.ready = Some(self.selection.select(self.mesh, &self.wants));
            lap(&mut t, &mut times.select);
        }
        Ok(self.ready.as_ref().map_or(0, Vec::len))
    }

    fn pass(
        &mut self,
        view: &View,
        split: bool,
        look: Option<Look>,
        times: &mut StageTimes,
    ) -> Result<usize, Infallible> {
        let mut t = Instant::now();
        let ready = self.ready.take().filter(|_| split).unwrap_or_default();
        if !ready.is_empty() {
            let answers = split::apply_splits(self.mesh, &ready, self.params, view);
            state::record_splits(&mut self.wants, &ready, &answers);
            lap(&mut t, &mut times.split);
        }
        let Some(look) = look else {
            return Ok(0);
        };
        let demanded = select::demanded(self.mesh, &self.wants);
        let among = look.among_apexes.then_some(self.apexes.as_slice());
        let mut sites = state::collapse_candidates(self.mesh, view, &demanded, among);
        if sites.is_empty() && look.everywhere_if_none {
            sites = state::collapse_candidates(self.mesh, view, &demanded, None);
        }
        let collapses = collapse::apply_collapses(self.mesh, &sites);
        lap(&mut t, &mut times.collapse);
        self.apexes = state::restored_apexes(&sites);
        if collapses > 0 {
            state::update_after_collapses(self.mesh, view, &mut self.wants, &sites);
            lap(&mut t, &mut times.state);
        }
        Ok(collapses)
    }

    fn compact(&mut self, _dead_faces: usize, times: &mut StageTimes) -> Result<(), Infallible> {
        let mut t = Instant::now();
        compact::compact(self.mesh);
        self.ready = None;
        lap(&mut t, &mut times.compact);
        Ok(())
    }
}
