//! Vertex collapses on the device (paper §5.4, Algorithm 3): `shaders/adapt/collapse.wgsl`, the
//! twin of [`crate::mesh::Mesh::collapse_vertices`], on the candidates the state update marked
//! (`state.rs`, `collapse_candidates` in `shaders/adapt/state.wgsl`).

use super::buffers::DeviceMesh;
use super::layout::Sweep;
use super::{dispatch_grid, GpuAdaption, Stage, Submission, WORKGROUP};
use crate::adapt::View;

impl Sweep {
    pub(super) fn new(device: &wgpu::Device, vertices: usize, among: bool) -> Sweep {
        let (_, _, row) = dispatch_grid(device, (vertices as u32).max(1), WORKGROUP);
        Sweep { vertices: vertices as u32, row, among: among as u32, _pad: 0 }
    }

    /// Workgroups `(x, y)` of the dispatch.
    pub(super) fn workgroups(&self, device: &wgpu::Device) -> (u32, u32) {
        let (gx, gy, _) = dispatch_grid(device, self.vertices.max(1), WORKGROUP);
        (gx, gy)
    }
}

pub(super) struct CollapsePipeline {
    pipeline: wgpu::ComputePipeline,
}

impl CollapsePipeline {
    pub(super) fn new(device: &wgpu::Device) -> Result<CollapsePipeline, super::GpuError> {
        let module = super::shader(device, Stage::Collapse)?;
        Ok(CollapsePipeline { pipeline: super::pipeline(device, &module, "collapse_vertices") })
    }

    /// Records a collapse step: the candidates of `dm` for `view` (among the vertices the last
    /// step marked, with `among`; with `full_look`, every vertex when those give none), then
    /// their collapses, which leave the removed entities marked dead, decide the restored edges'
    /// split wishes and mark the restored faces' apexes for the next step. The split list is
    /// stale afterwards (the caller records the split-list compaction again).
    pub(super) fn encode(
        &self,
        gpu: &GpuAdaption,
        sub: &mut Submission,
        dm: &DeviceMesh,
        view: &View,
        among: bool,
        full_look: bool,
    ) {
        let sweep = Sweep::new(&gpu.device, dm.lens.0, among);
        gpu.queue.write_buffer(&dm.sweep, 0, bytemuck::bytes_of(&sweep));
        gpu.state.encode_candidates(gpu, sub, dm, view, &sweep, full_look);
        let bind = super::bind(
            &gpu.device,
            &self.pipeline,
            &[
                (0, &dm.vertices),
                (1, &dm.edges),
                (2, &dm.faces),
                (3, &dm.marks),
                (4, &dm.sweep),
                (5, &dm.view),
                (6, &dm.wants),
            ],
        );
        let (gx, gy) = sweep.workgroups(&gpu.device);
        let mut pass = sub.pass(gpu, Stage::Collapse);
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
    }
}
