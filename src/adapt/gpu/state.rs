//! State update on the device (paper §5.1, Algorithm 1): `shaders/adapt_state.wgsl`, the twin
//! of [`crate::adapt::state::edge_wants`].

use super::buffers::DeviceMesh;
use super::{dispatch_grid, GpuAdaption, Stage, Submission};
use crate::adapt::camera::{View, C_LOD};
use bytemuck::{Pod, Zeroable};

const WORKGROUP: u32 = 256;

/// The view as `adapt_state.wgsl` reads it (`struct View`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct GpuView {
    pub eye: [f64; 3],
    pub planes: [[f64; 3]; 4],
    pub eye_dir: [f64; 3],
    pub horizon: f64,
    pub c_land: f64,
    pub c_water: f64,
    pub falloff: f64,
    pub min_len: f64,
    pub c_lod: f64,
    /// Edges to decide.
    pub edges: u32,
    /// Invocations per row of the dispatch grid (edge = x + y * row).
    pub row: u32,
}

impl GpuView {
    pub fn new(view: &View, edges: u32, row: u32) -> GpuView {
        GpuView {
            eye: view.eye.to_array(),
            planes: view.planes.map(|p| p.to_array()),
            eye_dir: view.eye_dir.to_array(),
            horizon: view.horizon,
            c_land: view.c_land,
            c_water: view.c_water,
            falloff: view.falloff,
            min_len: view.min_len,
            c_lod: C_LOD,
            edges,
            row,
        }
    }
}

/// The stage's pipeline.
pub(super) struct StatePipeline {
    pipeline: wgpu::ComputePipeline,
}

impl StatePipeline {
    pub(super) fn new(device: &wgpu::Device) -> StatePipeline {
        let module = super::shader(device, "adapt_state.wgsl", include_str!("../../../shaders/adapt_state.wgsl"));
        StatePipeline { pipeline: super::pipeline(device, &module, "edge_wants") }
    }

    /// Records the split wish of every live edge of `dm` for `view` into its `wants` buffer.
    pub(super) fn encode(&self, gpu: &GpuAdaption, sub: &mut Submission, dm: &DeviceMesh, view: &View) {
        let n = dm.lens.1 as u32;
        if n == 0 {
            return;
        }
        let (gx, gy, row) = dispatch_grid(&gpu.device, n, WORKGROUP);
        gpu.queue.write_buffer(&dm.view, 0, bytemuck::bytes_of(&GpuView::new(view, n, row)));
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
