//! The device backend of the adaption loop (paper §5): [`DevicePasses`] works the passes of
//! `adapt/run.rs` on the device, each recorded as one submission — its splits, the state update
//! of the changed mesh, the split-list compaction (whose chain flags are the demanded edges), the
//! collapse candidates and collapses (which decide the edges they restore), and the split list
//! of the coarsened mesh — that reads back four counts. Compaction runs on the device too. The
//! mesh is read back once, at the end, and stays on the device (`Resident`) for the next run
//! unless the host copy changes first; the spatial order between cameras (a sort, rare: once
//! the mesh appended more than it had ordered) is computed on the host copy, and the device copy
//! follows its new ids.

use super::buffers::DeviceMesh;
use super::{GpuAdaption, GpuError};
use crate::adapt::run::{self, Look, Passes};
use crate::adapt::{lap, AdaptStats, StageTimes, View};
use crate::mesh::{Mesh, Renumbering};
use crate::params::Params;
use std::sync::Arc;
use std::time::Instant;

/// The device copy of an adapter's mesh: equal to the host copy, or, with `ahead`, the newer
/// one (a run's result not read back yet). Between calls of `Adapter::adapt` it is never ahead,
/// so cloning an adapter, which does not share it (the clone uploads its own), loses nothing.
#[derive(Debug, Default)]
pub struct Resident {
    pub(crate) mesh: Option<DeviceMesh>,
    pub(crate) ahead: bool,
}

impl Clone for Resident {
    fn clone(&self) -> Resident {
        Resident::default()
    }
}

/// A mesh being adapted on the device, and the counts its last submission read back.
struct DevicePasses<'a> {
    gpu: &'a GpuAdaption,
    dm: DeviceMesh,
    terrain: super::split::Terrain<'a>,
    /// Edges the next pass splits.
    ready: usize,
}

impl Passes for DevicePasses<'_> {
    type Error = GpuError;

    fn faces(&self) -> usize {
        self.dm.lens.2
    }

    fn decide(&mut self, view: &View, times: &mut StageTimes) -> Result<usize, GpuError> {
        let mut t = Instant::now();
        let [ready, wanted, ..] = decide(self.gpu, &self.dm, view)?;
        self.ready = ready;
        lap(&mut t, &mut times.state);
        Ok(wanted)
    }

    fn ready(&mut self, _times: &mut StageTimes) -> Result<usize, GpuError> {
        Ok(self.ready)
    }

    fn pass(
        &mut self,
        view: &View,
        split: bool,
        look: Option<Look>,
        times: &mut StageTimes,
    ) -> Result<usize, GpuError> {
        let (gpu, mut t) = (self.gpu, Instant::now());
        let splits = if split { self.ready } else { 0 };
        if splits > 0 {
            self.dm.reserve_splits(gpu, splits)?;
        }
        let mut sub = gpu.submission();
        if splits > 0 {
            gpu.split.encode(gpu, &mut sub, &mut self.dm, self.terrain, splits);
            gpu.state.encode(gpu, &mut sub, &self.dm, view);
        }
        gpu.select.encode(gpu, &mut sub, &self.dm);
        if let Some(look) = look {
            gpu.collapse.encode(gpu, &mut sub, &self.dm, view, look.among_apexes, look.everywhere_if_none);
            gpu.select.encode(gpu, &mut sub, &self.dm);
        }
        let counts = sub.finish(gpu, &self.dm)?;
        self.ready = counts[0];
        lap(&mut t, if look.is_some() { &mut times.collapse } else { &mut times.split });
        Ok(if look.is_some() { counts[2] + counts[3] } else { 0 })
    }

    fn compact(&mut self, dead_faces: usize, times: &mut StageTimes) -> Result<(), GpuError> {
        let mut t = Instant::now();
        let (nv, ne, nf) = self.dm.lens;
        let n = dead_faces / 2;
        let live = (nv - n, ne - 3 * n, nf - 2 * n);
        let mut sub = self.gpu.submission();
        let out = self.gpu.compact.encode(self.gpu, &mut sub, &self.dm, live)?;
        sub.finish(self.gpu, &out)?;
        self.dm = out;
        lap(&mut t, &mut times.compact);
        Ok(())
    }
}

/// The device side of an adapter: the GPU it adapts on and the device copy of its mesh. The
/// adapter (`adapt/mod.rs`) holds one while the GPU backend is in use and drops it on a device
/// failure, continuing on the CPU.
#[derive(Clone)]
pub struct Device {
    gpu: Arc<GpuAdaption>,
    copy: Resident,
}

impl std::fmt::Debug for Device {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Device").field("adapter", &self.gpu.info.name).field("copy", &self.copy).finish()
    }
}

impl Device {
    pub fn new(gpu: Arc<GpuAdaption>) -> Device {
        Device { gpu, copy: Resident::default() }
    }

    /// The adaption loop on the device for `mesh` (adapted from `base`): the mesh is taken from
    /// the device copy, or uploaded. A result within the cap is read back into `mesh`; one over
    /// it (which the budget search usually throws away) stays on the device, ahead of `mesh`,
    /// until [`Device::read_back`]. Returns the outcome; on an error `mesh` is still the one the
    /// run started from.
    pub(crate) fn run(
        &mut self,
        mesh: &mut Mesh,
        base: &Mesh,
        params: &Params,
        target: run::Target,
        stats: &mut AdaptStats,
    ) -> Result<run::Outcome, GpuError> {
        let gpu = &*self.gpu;
        let dm = match self.copy.mesh.take() {
            Some(dm) => dm,
            None => upload(gpu, mesh)?,
        };
        let terrain = super::split::Terrain { params, radius: mesh.radius, guide: base.guide.as_ref() };
        let mut passes = DevicePasses { gpu, dm, terrain, ready: 0 };
        let outcome = run::adapt(&mut passes, target, stats)?;
        let dm = passes.dm;
        let wanted = target.cap.is_none_or(|c| outcome.converged && dm.lens.2 <= c);
        if outcome.changed && wanted {
            *mesh = download(gpu, &dm, base)?;
        }
        self.copy = Resident { mesh: Some(dm), ahead: outcome.changed && !wanted };
        Ok(outcome)
    }

    /// Drops the device copy, after the host copy changed.
    pub(crate) fn forget(&mut self) {
        self.copy = Resident::default();
    }

    /// Takes the device copy (equal to the host mesh: after [`Device::read_back`]), for a budget
    /// search to keep with the mesh it fitted.
    pub(crate) fn take_copy(&mut self) -> Resident {
        match self.copy.ahead {
            true => Resident::default(),
            false => std::mem::take(&mut self.copy),
        }
    }

    /// Makes `kept` the device copy again (its mesh was just made the host mesh again).
    pub(crate) fn restore(&mut self, kept: Resident) {
        self.copy = kept;
    }

    /// Makes a device-side duplicate of `kept` (the device copy of a mesh equal to the host mesh
    /// just set) the device copy, so the next run starts without an upload. When no duplicate
    /// can be made the run uploads the mesh as usual (a device failure during the copy shows in
    /// the run, which then falls back to the CPU).
    pub(crate) fn resume(&mut self, kept: &Resident) {
        let Some(dm) = &kept.mesh else {
            return;
        };
        match dm.duplicate(&self.gpu) {
            Ok(copy) => self.copy = Resident { mesh: Some(copy), ahead: false },
            Err(e) => tracing::debug!("copying the fitted mesh on the device failed ({e}); uploading it"),
        }
    }

    /// Faces of the device copy when it is ahead of the host mesh.
    pub(crate) fn faces_ahead(&self) -> Option<usize> {
        self.copy.mesh.as_ref().filter(|_| self.copy.ahead).map(|dm| dm.lens.2)
    }

    /// Reads the device copy into `mesh` (adapted from `base`) when it is ahead of it.
    pub(crate) fn read_back(&mut self, mesh: &mut Mesh, base: &Mesh) -> Result<(), GpuError> {
        let (Some(dm), true) = (&self.copy.mesh, self.copy.ahead) else {
            return Ok(());
        };
        *mesh = download(&self.gpu, dm, base)?;
        self.copy.ahead = false;
        Ok(())
    }

    /// Makes the device copy follow `order`, which the host copy (equal to it, between cameras)
    /// just went through; only the maps are uploaded. When that cannot be done the copy is
    /// dropped, and the next run uploads the mesh.
    pub(crate) fn renumber(&mut self, order: &Renumbering) {
        let (gpu, copy) = (&*self.gpu, std::mem::take(&mut self.copy));
        let (Some(dm), false) = (copy.mesh, copy.ahead) else {
            return;
        };
        let maps = (order.vertices.len(), order.edges.len(), order.faces.len());
        if maps != dm.lens {
            tracing::debug!("the device copy is not the host's ({:?} vs {maps:?}); uploading the mesh", dm.lens);
            return;
        }
        let mut sub = gpu.submission();
        let renumbered = gpu.compact.encode_renumbering(gpu, &mut sub, &dm, order).and_then(|out| {
            sub.finish(gpu, &out)?;
            Ok(out)
        });
        gpu.record(super::DeviceTimes { upload_bytes: 4 * (maps.0 + maps.1 + maps.2) as u64, ..Default::default() });
        match renumbered {
            Ok(out) => self.copy = Resident { mesh: Some(out), ahead: false },
            Err(e) => tracing::debug!("renumbering the device copy failed ({e}); uploading the mesh"),
        }
    }
}

/// The state update and split-list compaction of `dm`'s mesh: the counts of `dm.counts`
/// (`[ready edges, wanted edges, ..]`).
fn decide(gpu: &GpuAdaption, dm: &DeviceMesh, view: &View) -> Result<[usize; 4], GpuError> {
    let mut sub = gpu.submission();
    gpu.state.encode(gpu, &mut sub, dm, view);
    gpu.select.encode(gpu, &mut sub, dm);
    sub.finish(gpu, dm)
}

fn upload(gpu: &GpuAdaption, mesh: &crate::mesh::Mesh) -> Result<DeviceMesh, GpuError> {
    let dm = DeviceMesh::upload(gpu, mesh)?;
    gpu.record(super::DeviceTimes { upload_bytes: mesh_bytes(dm.lens), ..Default::default() });
    Ok(dm)
}

/// The device copy read back as a mesh adapted from `base` (whose map guide, channels and
/// precipitation it shares).
fn download(gpu: &GpuAdaption, dm: &DeviceMesh, base: &Mesh) -> Result<Mesh, GpuError> {
    let mesh = dm.download(gpu, base.radius)?;
    gpu.record(super::DeviceTimes { download_bytes: mesh_bytes(dm.lens), ..Default::default() });
    Ok(Mesh {
        guide: base.guide.clone(),
        channels: base.channels.clone(),
        precipitation: base.precipitation.clone(),
        ..mesh
    })
}

fn mesh_bytes((nv, ne, nf): (usize, usize, usize)) -> u64 {
    use crate::mesh::{EDGE_BYTES, FACE_BYTES, VERTEX_BYTES};
    (nv * VERTEX_BYTES + ne * EDGE_BYTES + nf * FACE_BYTES) as u64
}
