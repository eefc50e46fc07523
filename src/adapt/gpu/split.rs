//! Edge splits on the device (paper §5.3, Algorithm 2 steps 3–6): `shaders/adapt/split.wgsl`,
//! the twin of [`crate::adapt::cpu::split::apply_splits`] — new vertices by
//! [`crate::mesh::split::altitude::split_vertex`] and the topology of `Mesh::split_edges`, one
//! invocation per entry of the split list, writing the slots the CPU would.

use super::buffers::DeviceMesh;
use super::layout::SplitParams;
use super::{dispatch_grid, GpuAdaption, Stage, Submission};
use crate::mesh::guide::{Guide, GuideFace};
use crate::mesh::split::altitude::{LAND_ROUGHNESS, LAND_ROUGHNESS_LENGTH, SEA_ROUGHNESS, SEA_ROUGHNESS_LENGTH};
use crate::mesh::split::landform;
use crate::mesh::split::position::MIN_SPLIT_QUALITY;
use crate::mesh::Tangent;
use crate::params::Params;

use std::sync::{Arc, Mutex};

pub(super) const WORKGROUP: u32 = 64;

impl SplitParams {
    fn new(
        p: &Params,
        radius: f64,
        lens: (usize, usize, usize),
        count: u32,
        row: u32,
        guide: Option<&Guide>,
    ) -> SplitParams {
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
            sea_roughness_length: SEA_ROUGHNESS_LENGTH,
            tangent_scale: Tangent::SCALE,
            tangent_offset: Tangent::OFFSET,
            guide_min_edge: guide.map_or(0.0, |g| g.min_edge_m),
            floor_slope: landform::FLOOR_SLOPE,
            floor_length: landform::FLOOR_LENGTH,
            relief: landform::RELIEF,
            altitude_gain: landform::ALTITUDE,
            hybrid: landform::HYBRID,
            relief_length: landform::RELIEF_LENGTH,
            smooth_length: landform::SMOOTH_LENGTH,
            threshold: landform::THRESHOLD,
            map_relief: landform::MAP_RELIEF,
            ridge: landform::RIDGE,
            floor_fade: landform::FLOOR_FADE,
            altitude_length: landform::ALTITUDE_LENGTH,
            sea_detail: landform::SEA_DETAIL,
            vertices: lens.0 as u32,
            edges: lens.1 as u32,
            faces: lens.2 as u32,
            count,
            row,
            guide_faces: guide.map_or(0, |g| g.faces.len() as u32),
            guide_side: guide.map_or(0, |g| g.side),
            _pad: 0,
        }
    }
}

/// What a split's terrain depends on besides its diamond: the parameters, the base sphere's
/// radius and the planet's elevation map.
#[derive(Clone, Copy)]
pub(super) struct Terrain<'a> {
    pub params: &'a Params,
    pub radius: f64,
    pub guide: Option<&'a Arc<Guide>>,
}

pub(super) struct SplitPipeline {
    pipeline: wgpu::ComputePipeline,
    /// The device copy of the last guide used (by its address, kept alive by the `Arc`), or of
    /// none: one small placeholder pair.
    guide: Mutex<Option<(Arc<Guide>, Arc<GuideBuffers>)>>,
    no_guide: GuideBuffers,
}

/// A guide's faces and values on the device.
struct GuideBuffers {
    faces: wgpu::Buffer,
    values: wgpu::Buffer,
}

impl GuideBuffers {
    fn new(device: &wgpu::Device, faces: &[u8], values: &[u8]) -> GuideBuffers {
        use wgpu::util::DeviceExt;
        let make = |label, contents: &[u8]| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents,
                usage: wgpu::BufferUsages::STORAGE,
            })
        };
        GuideBuffers { faces: make("guide faces", faces), values: make("guide values", values) }
    }
}

impl SplitPipeline {
    pub(super) fn new(device: &wgpu::Device) -> Result<SplitPipeline, super::GpuError> {
        let module = super::shader(device, Stage::Split)?;
        let no_guide = GuideBuffers::new(device, &[0; std::mem::size_of::<GuideFace>()], &[0; 4]);
        Ok(SplitPipeline {
            pipeline: super::pipeline(device, &module, "split_edges"),
            guide: Mutex::new(None),
            no_guide,
        })
    }

    /// The device copy of `guide`, made on first use.
    fn guide_buffers(&self, device: &wgpu::Device, guide: &Arc<Guide>) -> Arc<GuideBuffers> {
        let mut cached = self.guide.lock().unwrap_or_else(|e| e.into_inner());
        if let Some((g, b)) = cached.as_ref() {
            if Arc::ptr_eq(g, guide) {
                return Arc::clone(b);
            }
        }
        let made = Arc::new(GuideBuffers::new(
            device,
            bytemuck::cast_slice(&guide.faces),
            bytemuck::cast_slice(&guide.values),
        ));
        *cached = Some((Arc::clone(guide), Arc::clone(&made)));
        made
    }

    /// Records the splits of the first `count` edges of `dm.list` (room reserved) and counts
    /// the new entities into `dm.lens`.
    pub(super) fn encode(
        &self,
        gpu: &GpuAdaption,
        sub: &mut Submission,
        dm: &mut DeviceMesh,
        terrain: Terrain,
        count: usize,
    ) {
        if count == 0 {
            return;
        }
        let Terrain { params, radius, guide } = terrain;
        let held = guide.map(|g| self.guide_buffers(&gpu.device, g));
        let buffers = held.as_deref().unwrap_or(&self.no_guide);
        let (gx, gy, row) = dispatch_grid(&gpu.device, count as u32, WORKGROUP);
        let sp = SplitParams::new(params, radius, dm.lens, count as u32, row, guide.map(|g| &**g));
        gpu.queue.write_buffer(&dm.split, 0, bytemuck::bytes_of(&sp));
        let bind = super::bind(
            &gpu.device,
            &self.pipeline,
            &[
                (0, &dm.vertices),
                (1, &dm.edges),
                (2, &dm.faces),
                (3, &dm.list),
                (4, &dm.split),
                (5, &buffers.faces),
                (6, &buffers.values),
            ],
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
