//! Split-list compaction on the device (paper §5.3, Algorithm 2 steps 1–2):
//! `shaders/adapt/select.wgsl`, the twin of [`crate::adapt::cpu::split::Selection::select`]. Chains of
//! blocking edges are walked with an atomic flag per edge; the ready edges are compacted into
//! a list in edge order by a prefix sum over blocks (`shaders/adapt/scan.wgsl`), so the list
//! is the CPU's. The chain flags left in `seen` are the demanded edges of
//! [`crate::adapt::cpu::state::demanded`], which the collapse candidates read.

use super::buffers::DeviceMesh;
use super::layout::ScanGrid;
use super::{GpuAdaption, Stage, Submission};

pub(super) struct SelectPipeline {
    walk: wgpu::ComputePipeline,
    block_sums: wgpu::ComputePipeline,
    scan_sums: wgpu::ComputePipeline,
    scatter: wgpu::ComputePipeline,
}

impl SelectPipeline {
    pub(super) fn new(device: &wgpu::Device) -> Result<SelectPipeline, super::GpuError> {
        let module = super::shader(device, Stage::Select)?;
        Ok(SelectPipeline {
            walk: super::pipeline(device, &module, "walk_chains"),
            block_sums: super::pipeline(device, &module, "block_sums"),
            scan_sums: super::pipeline(device, &module, "scan_sums"),
            scatter: super::pipeline(device, &module, "scatter"),
        })
    }

    /// Records the compaction of the ready edges of the wanted chains into `dm.list`, their
    /// number into `dm.counts[0]` and the number of wanted edges into `dm.counts[1]`.
    pub(super) fn encode(&self, gpu: &GpuAdaption, sub: &mut Submission, dm: &DeviceMesh) {
        let n = dm.lens.1 as u32;
        let device = &gpu.device;
        let (grid, (gx, gy), (bx, by)) = ScanGrid::new(device, n);
        gpu.queue.write_buffer(&dm.grid, 0, bytemuck::bytes_of(&grid));
        let flags = 4 * n.max(1) as u64;
        sub.encoder.clear_buffer(&dm.seen, 0, Some(flags.next_multiple_of(4)));
        sub.encoder.clear_buffer(&dm.ready, 0, Some(flags.next_multiple_of(4)));
        sub.encoder.clear_buffer(&dm.counts, 0, Some(8));
        let walk = super::bind(
            device,
            &self.walk,
            &[
                (0, &dm.edges),
                (1, &dm.faces),
                (2, &dm.wants),
                (3, &dm.seen),
                (4, &dm.ready),
                (7, &dm.counts),
                (8, &dm.grid),
            ],
        );
        let sums = super::bind(device, &self.block_sums, &[(4, &dm.ready), (5, &dm.sums), (8, &dm.grid)]);
        let scan = super::bind(device, &self.scan_sums, &[(5, &dm.sums), (7, &dm.counts), (8, &dm.grid)]);
        let scatter =
            super::bind(device, &self.scatter, &[(4, &dm.ready), (5, &dm.sums), (6, &dm.list), (8, &dm.grid)]);
        let mut pass = sub.pass(gpu, Stage::Select);
        pass.set_pipeline(&self.walk);
        pass.set_bind_group(0, &walk, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
        pass.set_pipeline(&self.block_sums);
        pass.set_bind_group(0, &sums, &[]);
        pass.dispatch_workgroups(bx, by, 1);
        pass.set_pipeline(&self.scan_sums);
        pass.set_bind_group(0, &scan, &[]);
        pass.dispatch_workgroups(1, 1, 1);
        pass.set_pipeline(&self.scatter);
        pass.set_bind_group(0, &scatter, &[]);
        pass.dispatch_workgroups(bx, by, 1);
    }
}
