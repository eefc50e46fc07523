//! Buffer compaction on the device (paper §5.5): `shaders/adapt_compact.wgsl`, the twin of
//! [`crate::mesh::Mesh::compact`] (the live entities keep their order). Compaction in spatial
//! order, a sort, stays on the host (see `adapt.rs`).

use super::buffers::DeviceMesh;
use super::{GpuAdaption, GpuError, ScanGrid, Stage, Submission};
use wgpu::util::DeviceExt;

pub(super) struct CompactPipeline {
    live: [wgpu::ComputePipeline; 3],
    block_sums: wgpu::ComputePipeline,
    scan_sums: wgpu::ComputePipeline,
    number: wgpu::ComputePipeline,
    moves: [wgpu::ComputePipeline; 3],
}

impl CompactPipeline {
    pub(super) fn new(device: &wgpu::Device) -> Result<CompactPipeline, super::GpuError> {
        let module = super::shader(
            device,
            "adapt_compact.wgsl",
            &[include_str!("../../../shaders/adapt_compact.wgsl"), include_str!("../../../shaders/adapt_scan.wgsl")],
        )?;
        let p = |entry| super::pipeline(device, &module, entry);
        Ok(CompactPipeline {
            live: [p("live_vertices"), p("live_edges"), p("live_faces")],
            block_sums: p("block_sums"),
            scan_sums: p("scan_sums"),
            number: p("number"),
            moves: [p("move_vertices"), p("move_edges"), p("move_faces")],
        })
    }

    /// Records the compaction of `dm` into fresh buffers holding `live` vertices, edges and
    /// faces (the counts the collapses left), and returns them; `dm` must outlive the
    /// submission's recording only (wgpu keeps its buffers until the work is done).
    pub(super) fn encode(
        &self,
        gpu: &GpuAdaption,
        sub: &mut Submission,
        dm: &DeviceMesh,
        live: (usize, usize, usize),
    ) -> Result<DeviceMesh, GpuError> {
        let device = &gpu.device;
        let mut out = DeviceMesh::with_capacity(gpu, live.0, live.1, live.2)?;
        out.lens = live;
        let (nv, ne, nf) = dm.lens;
        let olds = [&dm.vertices, &dm.edges, &dm.faces];
        let news = [&out.vertices, &out.edges, &out.faces];
        let maps = [nv, ne, nf].map(|n| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("compaction map"),
                size: (4 * n as u64).next_multiple_of(256).max(256),
                usage: wgpu::BufferUsages::STORAGE,
                mapped_at_creation: false,
            })
        });
        let shapes = [nv, ne, nf].map(|n| ScanGrid::new(device, n as u32));
        let grids = shapes.map(|(grid, _, _)| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("compaction grid"),
                contents: bytemuck::bytes_of(&grid),
                usage: wgpu::BufferUsages::UNIFORM,
            })
        });
        let bind = |p: &wgpu::ComputePipeline, entries: &[(u32, &wgpu::Buffer)]| super::bind(device, p, entries);
        let mut groups = Vec::new();
        for k in 0..3 {
            let (map, grid) = (&maps[k], &grids[k]);
            groups.push([
                bind(&self.live[k], &[(k as u32, olds[k]), (9, map), (11, grid)]),
                bind(&self.block_sums, &[(9, map), (10, &dm.sums), (11, grid)]),
                bind(&self.scan_sums, &[(10, &dm.sums), (11, grid)]),
                bind(&self.number, &[(9, map), (10, &dm.sums), (11, grid)]),
            ]);
        }
        let [vmap, emap, fmap] = &maps;
        let moves = [
            bind(&self.moves[0], &[(0, olds[0]), (3, news[0]), (6, vmap), (7, emap), (11, &grids[0])]),
            bind(&self.moves[1], &[(1, olds[1]), (4, news[1]), (6, vmap), (7, emap), (8, fmap), (11, &grids[1])]),
            bind(&self.moves[2], &[(2, olds[2]), (5, news[2]), (7, emap), (8, fmap), (11, &grids[2])]),
        ];
        let mut pass = sub.pass(gpu, Stage::Compact);
        for (k, [live, sums, scan, number]) in groups.iter().enumerate() {
            let (_, (gx, gy), (bx, by)) = shapes[k];
            for (pipeline, group, (x, y)) in [
                (&self.live[k], live, (gx, gy)),
                (&self.block_sums, sums, (bx, by)),
                (&self.scan_sums, scan, (1, 1)),
                (&self.number, number, (bx, by)),
            ] {
                pass.set_pipeline(pipeline);
                pass.set_bind_group(0, group, &[]);
                pass.dispatch_workgroups(x, y, 1);
            }
        }
        for (k, group) in moves.iter().enumerate() {
            let (_, (gx, gy), _) = shapes[k];
            pass.set_pipeline(&self.moves[k]);
            pass.set_bind_group(0, group, &[]);
            pass.dispatch_workgroups(gx, gy, 1);
        }
        drop(pass);
        Ok(out)
    }
}
