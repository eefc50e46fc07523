//! Buffer compaction on the device (paper §5.5): `shaders/adapt/compact.wgsl`, the twin of
//! [`crate::mesh::Mesh::compact`] (the live entities keep their order). The spatial order, a
//! sort, is computed on the host, which holds the mesh between cameras; the device copy
//! follows its new ids with the same moves (see `adapt/cpu/compact.rs`).

use super::buffers::DeviceMesh;
use super::layout::ScanGrid;
use super::{GpuAdaption, GpuError, Stage, Submission};
use crate::mesh::Renumbering;
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
        let module = super::shader(device, Stage::Compact)?;
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
        let maps = [nv, ne, nf].map(|n| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("compaction map"),
                size: (4 * n as u64).next_multiple_of(256).max(256),
                usage: wgpu::BufferUsages::STORAGE,
                mapped_at_creation: false,
            })
        });
        let (shapes, grids) = grids(device, dm.lens);
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
        self.encode_moves(gpu, &mut pass, dm, &out, [&maps[0], &maps[1], &maps[2]], &shapes, &grids);
        drop(pass);
        Ok(out)
    }

    /// Records the renumbering of `dm` by `order`, which the host computed on its copy of the
    /// same mesh (the spatial order between cameras), into fresh buffers and returns them:
    /// the three maps are uploaded (4 bytes an entity), the mesh is not.
    pub(super) fn encode_renumbering(
        &self,
        gpu: &GpuAdaption,
        sub: &mut Submission,
        dm: &DeviceMesh,
        order: &Renumbering,
    ) -> Result<DeviceMesh, GpuError> {
        let device = &gpu.device;
        let (nv, ne, nf) = order.sizes;
        let mut out = DeviceMesh::with_capacity(gpu, nv, ne, nf)?;
        out.lens = order.sizes;
        let maps = [&order.vertices, &order.edges, &order.faces].map(|map| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("renumbering map"),
                contents: bytemuck::cast_slice(map),
                usage: wgpu::BufferUsages::STORAGE,
            })
        });
        let (shapes, grids) = grids(device, dm.lens);
        let mut pass = sub.pass(gpu, Stage::Compact);
        self.encode_moves(gpu, &mut pass, dm, &out, [&maps[0], &maps[1], &maps[2]], &shapes, &grids);
        drop(pass);
        Ok(out)
    }

    /// Records the moves of every kept entity of `dm` to its new id in `out`, with its
    /// references renumbered, by the maps `[vertices, edges, faces]`.
    #[allow(clippy::too_many_arguments)]
    fn encode_moves(
        &self,
        gpu: &GpuAdaption,
        pass: &mut wgpu::ComputePass,
        dm: &DeviceMesh,
        out: &DeviceMesh,
        [vmap, emap, fmap]: [&wgpu::Buffer; 3],
        shapes: &[Shape; 3],
        grids: &[wgpu::Buffer; 3],
    ) {
        let bind = |p: &wgpu::ComputePipeline, entries: &[(u32, &wgpu::Buffer)]| super::bind(&gpu.device, p, entries);
        let moves = [
            bind(&self.moves[0], &[(0, &dm.vertices), (3, &out.vertices), (6, vmap), (7, emap), (11, &grids[0])]),
            bind(&self.moves[1], &[(1, &dm.edges), (4, &out.edges), (6, vmap), (7, emap), (8, fmap), (11, &grids[1])]),
            bind(&self.moves[2], &[(2, &dm.faces), (5, &out.faces), (7, emap), (8, fmap), (11, &grids[2])]),
        ];
        for (k, group) in moves.iter().enumerate() {
            let (_, (gx, gy), _) = shapes[k];
            pass.set_pipeline(&self.moves[k]);
            pass.set_bind_group(0, group, &[]);
            pass.dispatch_workgroups(gx, gy, 1);
        }
    }
}

/// A scan grid's uniform, its item dispatch and its block dispatch (see [`ScanGrid::new`]).
type Shape = (ScanGrid, (u32, u32), (u32, u32));

/// The dispatch shapes and grid uniforms of the vertex, edge and face buffers of lengths `lens`.
fn grids(device: &wgpu::Device, (nv, ne, nf): (usize, usize, usize)) -> ([Shape; 3], [wgpu::Buffer; 3]) {
    let shapes = [nv, ne, nf].map(|n| ScanGrid::new(device, n as u32));
    let grids = shapes.map(|(grid, _, _)| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("compaction grid"),
            contents: bytemuck::bytes_of(&grid),
            usage: wgpu::BufferUsages::UNIFORM,
        })
    });
    (shapes, grids)
}
