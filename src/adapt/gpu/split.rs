//! Edge splits on the device (paper §5.3, Algorithm 2 steps 3–6): `shaders/adapt_split.wgsl`,
//! the twin of [`crate::adapt::split::apply_splits`] — new vertices by
//! [`crate::mesh::altitude::split_vertex`] and the topology of `Mesh::split_edges`, one
//! invocation per entry of the split list, writing the slots the CPU would.

use super::buffers::DeviceMesh;
use super::{dispatch_grid, GpuAdaption, Stage, Submission};
use crate::mesh::altitude::{LAND_ROUGHNESS, LAND_ROUGHNESS_LENGTH, SEA_ROUGHNESS};
use crate::mesh::terrain::MIN_SPLIT_QUALITY;
use crate::mesh::Tangent;
use crate::params::Params;
use bytemuck::{Pod, Zeroable};

pub(super) const WORKGROUP: u32 = 64;

/// The terrain parameters and batch shape as `adapt_split.wgsl` reads them (`SplitParams`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(super) struct SplitParams {
    radius: f64,
    sea_level: f64,
    riverbed_edge_height: f64,
    max_river_depth: f64,
    min_river_length: f64,
    max_river_altitude: f64,
    max_mountain_altitude: f64,
    riverbed_slope: f64,
    near_river_slope: f64,
    ground_slope: f64,
    river_slope: f64,
    quality_scale: f64,
    min_quality: f64,
    one: f64,
    half: f64,
    quarter: f64,
    three_quarters: f64,
    sea_roughness: f64,
    roughness: f64,
    roughness_length: f64,
    tangent_scale: f64,
    tangent_offset: f64,
    vertices: u32,
    edges: u32,
    faces: u32,
    count: u32,
    row: u32,
    _pad: u32,
}

impl SplitParams {
    fn new(p: &Params, radius: f64, lens: (usize, usize, usize), count: u32, row: u32) -> SplitParams {
        SplitParams {
            radius,
            sea_level: p.sea_level_m,
            riverbed_edge_height: p.riverbed_edge_height_m,
            max_river_depth: p.max_river_depth_m,
            min_river_length: p.min_river_length_m,
            max_river_altitude: p.max_river_altitude_m,
            max_mountain_altitude: p.max_mountain_altitude_m,
            riverbed_slope: p.riverbed_slope(),
            near_river_slope: p.near_river_slope(),
            ground_slope: p.ground_slope(),
            river_slope: p.river_slope(),
            quality_scale: 2.0 * 3f64.sqrt(),
            min_quality: MIN_SPLIT_QUALITY,
            one: 1.0,
            half: 0.5,
            quarter: 0.25,
            three_quarters: 0.75,
            sea_roughness: SEA_ROUGHNESS,
            roughness: LAND_ROUGHNESS,
            roughness_length: LAND_ROUGHNESS_LENGTH,
            tangent_scale: Tangent::SCALE,
            tangent_offset: Tangent::OFFSET,
            vertices: lens.0 as u32,
            edges: lens.1 as u32,
            faces: lens.2 as u32,
            count,
            row,
            _pad: 0,
        }
    }
}

pub(super) struct SplitPipeline {
    pipeline: wgpu::ComputePipeline,
}

impl SplitPipeline {
    pub(super) fn new(device: &wgpu::Device) -> Result<SplitPipeline, super::GpuError> {
        let module = super::shader(
            device,
            "adapt_split.wgsl",
            &[include_str!("../../../shaders/adapt_split.wgsl"), super::EDGE_HELPERS],
        )?;
        Ok(SplitPipeline { pipeline: super::pipeline(device, &module, "split_edges") })
    }

    /// Records the splits of the first `count` edges of `dm.list` (room reserved) and counts
    /// the new entities into `dm.lens`.
    pub(super) fn encode(
        &self,
        gpu: &GpuAdaption,
        sub: &mut Submission,
        dm: &mut DeviceMesh,
        params: &Params,
        radius: f64,
        count: usize,
    ) {
        if count == 0 {
            return;
        }
        let (gx, gy, row) = dispatch_grid(&gpu.device, count as u32, WORKGROUP);
        let sp = SplitParams::new(params, radius, dm.lens, count as u32, row);
        gpu.queue.write_buffer(&dm.split, 0, bytemuck::bytes_of(&sp));
        let bind = super::bind(
            &gpu.device,
            &self.pipeline,
            &[(0, &dm.vertices), (1, &dm.edges), (2, &dm.faces), (3, &dm.list), (4, &dm.split)],
        );
        {
            let mut pass = sub.pass(gpu, Stage::Split);
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &bind, &[]);
            pass.dispatch_workgroups(gx, gy, 1);
        }
        let (nv, ne, nf) = dm.lens;
        dm.lens = (nv + count, ne + 3 * count, nf + 2 * count);
    }
}
