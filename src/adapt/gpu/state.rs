//! State update on the device (paper §5.1, Algorithm 1): `shaders/adapt/state.wgsl`, the twin
//! of [`crate::adapt::cpu::state::edge_wants`] and [`crate::adapt::cpu::state::collapse_candidates`].

use super::buffers::DeviceMesh;
use super::layout::{GpuView, Sweep};
use super::{dispatch_grid, GpuAdaption, Stage, Submission};
use crate::adapt::camera::{View, C_LOD};

pub(super) const WORKGROUP: u32 = 256;

impl GpuView {
    pub fn new(view: &View, edges: u32, row: u32) -> GpuView {
        GpuView {
            eye: view.eye.to_array(),
            planes: view.planes.map(|p| p.to_array()),
            per_unit: view.per_unit,
            eye_dir: view.eye_dir.to_array(),
            horizon: view.horizon,
            c_land: view.c_land,
            c_water: view.c_water,
            min_len: view.min_len,
            c_lod: C_LOD,
            edges,
            row,
        }
    }
}

/// The stage's pipelines: split wishes, collapse candidates, and candidates of a full look.
pub(super) struct StatePipeline {
    pipeline: wgpu::ComputePipeline,
    candidates: wgpu::ComputePipeline,
    if_none: wgpu::ComputePipeline,
}

impl StatePipeline {
    pub(super) fn new(device: &wgpu::Device) -> Result<StatePipeline, super::GpuError> {
        let module = super::shader(device, Stage::State)?;
        Ok(StatePipeline {
            pipeline: super::pipeline(device, &module, "edge_wants"),
            candidates: super::pipeline(device, &module, "collapse_candidates"),
            if_none: super::pipeline(device, &module, "candidates_if_none"),
        })
    }

    /// Writes `view` for `dm`'s edges (the same bytes for every stage of a submission, since
    /// queue writes land before it runs) and returns the edge-wise workgroups.
    pub(super) fn write_view(gpu: &GpuAdaption, dm: &DeviceMesh, view: &View) -> (u32, u32) {
        let n = dm.lens.1 as u32;
        let (gx, gy, row) = dispatch_grid(&gpu.device, n.max(1), WORKGROUP);
        gpu.queue.write_buffer(&dm.view, 0, bytemuck::bytes_of(&GpuView::new(view, n, row)));
        (gx, gy)
    }

    /// Records the split wish of every live edge of `dm` for `view` into its `wants` buffer.
    pub(super) fn encode(&self, gpu: &GpuAdaption, sub: &mut Submission, dm: &DeviceMesh, view: &View) {
        if dm.lens.1 == 0 {
            return;
        }
        let (gx, gy) = StatePipeline::write_view(gpu, dm, view);
        let bind = super::bind(
            &gpu.device,
            &self.pipeline,
            &[(0, &dm.vertices), (1, &dm.edges), (2, &dm.view), (3, &dm.wants)],
        );
        let mut pass = sub.pass(gpu, Stage::State);
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
    }
}

impl StatePipeline {
    /// Records the collapse candidates of `dm`'s vertices for `view` into `dm.marks` and their
    /// number into `dm.counts[2]` (`sweep.among`: only where the last collapses left a look
    /// mark), then with `full_look`, when none was found, those of every vertex into
    /// `dm.counts[3]`. The demanded edges are the chain flags of the split-list compaction last
    /// recorded, which must follow the last change of the mesh.
    pub(super) fn encode_candidates(
        &self,
        gpu: &GpuAdaption,
        sub: &mut Submission,
        dm: &DeviceMesh,
        view: &View,
        sweep: &Sweep,
        full_look: bool,
    ) {
        StatePipeline::write_view(gpu, dm, view);
        sub.encoder.clear_buffer(&dm.counts, 8, Some(8));
        let (gx, gy) = sweep.workgroups(&gpu.device);
        let entries = [
            (0, &dm.vertices),
            (1, &dm.edges),
            (2, &dm.view),
            (4, &dm.faces),
            (5, &dm.seen),
            (6, &dm.marks),
            (7, &dm.counts),
            (8, &dm.sweep),
        ];
        let candidates = super::bind(&gpu.device, &self.candidates, &entries);
        let if_none = full_look.then(|| super::bind(&gpu.device, &self.if_none, &entries));
        let mut pass = sub.pass(gpu, Stage::Collapse);
        pass.set_pipeline(&self.candidates);
        pass.set_bind_group(0, &candidates, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
        if let Some(bind) = &if_none {
            pass.set_pipeline(&self.if_none);
            pass.set_bind_group(0, bind, &[]);
            pass.dispatch_workgroups(gx, gy, 1);
        }
    }
}
