//! State update on the device (paper §5.1, Algorithm 1): `shaders/adapt_state.wgsl`, the twin
//! of [`crate::adapt::state::edge_wants`].

use super::{DeviceTimes, GpuAdaption, GpuError};
use crate::adapt::camera::{View, C_LOD};
use crate::mesh::Mesh;
use bytemuck::{Pod, Zeroable};
use std::sync::Mutex;
use std::time::Instant;

const SHADER: &str = include_str!("../../../shaders/adapt_state.wgsl");
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

/// The stage's pipeline and the device buffers it reuses between calls (grown on demand).
pub(super) struct StagePipeline {
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::ComputePipeline,
    buffers: Mutex<Option<Buffers>>,
    /// Start and end of the dispatch, where the device has timestamp queries.
    stamps: Option<wgpu::QuerySet>,
}

struct Buffers {
    vertices: wgpu::Buffer,
    edges: wgpu::Buffer,
    view: wgpu::Buffer,
    wants: wgpu::Buffer,
    /// The two resolved timestamps (unused without timestamp queries).
    stamps: wgpu::Buffer,
    /// The flags, then (at `stamps_at`) the two timestamps.
    readback: wgpu::Buffer,
}

impl StagePipeline {
    pub(super) fn new(device: &wgpu::Device, timestamps: bool) -> StagePipeline {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("adapt_state.wgsl"),
            source: wgpu::ShaderSource::Wgsl(SHADER.into()),
        });
        let entry = |binding, read_only| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("adapt state"),
            entries: &[entry(0, true), entry(1, true), entry(2, true), entry(3, false)],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("adapt state"),
            bind_group_layouts: &[Some(&layout)],
            ..Default::default()
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("edge_wants"),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some("edge_wants"),
            compilation_options: Default::default(),
            cache: None,
        });
        let stamps = timestamps.then(|| {
            device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("edge_wants timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: 2,
            })
        });
        StagePipeline { layout, pipeline, buffers: Mutex::new(None), stamps }
    }
}

/// A buffer of at least `size` bytes: `old` if big enough, else a new one with room to grow.
fn ensure(
    device: &wgpu::Device,
    old: Option<wgpu::Buffer>,
    size: u64,
    usage: wgpu::BufferUsages,
    label: &str,
) -> wgpu::Buffer {
    match old {
        Some(b) if b.size() >= size => b,
        _ => device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: (size + size / 4).next_multiple_of(256).max(256),
            usage,
            mapped_at_creation: false,
        }),
    }
}

/// Whether each edge of `mesh` wants to be split for `view`, decided on the device.
pub fn edge_wants(gpu: &GpuAdaption, mesh: &Mesh, view: &View) -> Result<Vec<bool>, GpuError> {
    let n = mesh.edges.len();
    if n == 0 {
        return Ok(Vec::new());
    }
    let start = Instant::now();
    let device = &gpu.device;
    let limit = device.limits().max_storage_buffer_binding_size;
    let vertex_bytes: &[u8] = bytemuck::cast_slice(&mesh.vertices);
    let edge_bytes: &[u8] = bytemuck::cast_slice(&mesh.edges);
    for bytes in [vertex_bytes, edge_bytes] {
        if bytes.len() as u64 > limit {
            return Err(GpuError::TooLarge { needed: bytes.len() as u64, limit });
        }
    }
    let groups = (n as u32).div_ceil(WORKGROUP);
    let max_x = device.limits().max_compute_workgroups_per_dimension;
    let (gx, gy) = (groups.min(max_x), groups.div_ceil(groups.min(max_x)));
    let params = GpuView::new(view, n as u32, gx * WORKGROUP);

    let stage = &gpu.state;
    let mut slot = stage.buffers.lock().unwrap_or_else(|e| e.into_inner());
    let old = slot.take();
    let (ov, oe, ow, or, oview, ost) = match old {
        Some(b) => (Some(b.vertices), Some(b.edges), Some(b.wants), Some(b.readback), Some(b.view), Some(b.stamps)),
        None => (None, None, None, None, None, None),
    };
    use wgpu::BufferUsages as U;
    let wants_bytes = 4 * n as u64;
    let stamps_at = wants_bytes.next_multiple_of(8);
    let buffers = Buffers {
        vertices: ensure(device, ov, vertex_bytes.len() as u64, U::STORAGE | U::COPY_DST, "vertices"),
        edges: ensure(device, oe, edge_bytes.len() as u64, U::STORAGE | U::COPY_DST, "edges"),
        view: ensure(device, oview, std::mem::size_of::<GpuView>() as u64, U::STORAGE | U::COPY_DST, "view"),
        wants: ensure(device, ow, wants_bytes, U::STORAGE | U::COPY_SRC, "wants"),
        stamps: ensure(device, ost, 16, U::QUERY_RESOLVE | U::COPY_SRC, "timestamps"),
        readback: ensure(device, or, stamps_at + 16, U::MAP_READ | U::COPY_DST, "wants readback"),
    };
    gpu.queue.write_buffer(&buffers.vertices, 0, vertex_bytes);
    gpu.queue.write_buffer(&buffers.edges, 0, edge_bytes);
    gpu.queue.write_buffer(&buffers.view, 0, bytemuck::bytes_of(&params));

    fn binding(i: u32, b: &wgpu::Buffer, size: u64) -> wgpu::BindGroupEntry<'_> {
        wgpu::BindGroupEntry {
            binding: i,
            resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                buffer: b,
                offset: 0,
                size: wgpu::BufferSize::new(size),
            }),
        }
    }
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("adapt state"),
        layout: &stage.layout,
        entries: &[
            binding(0, &buffers.vertices, vertex_bytes.len() as u64),
            binding(1, &buffers.edges, edge_bytes.len() as u64),
            binding(2, &buffers.view, std::mem::size_of::<GpuView>() as u64),
            binding(3, &buffers.wants, wants_bytes),
        ],
    });
    let oom = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("adapt state") });
    {
        let timestamp_writes = stage.stamps.as_ref().map(|q| wgpu::ComputePassTimestampWrites {
            query_set: q,
            beginning_of_pass_write_index: Some(0),
            end_of_pass_write_index: Some(1),
        });
        let mut pass =
            encoder.begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("edge_wants"), timestamp_writes });
        pass.set_pipeline(&stage.pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
    }
    encoder.copy_buffer_to_buffer(&buffers.wants, 0, &buffers.readback, 0, wants_bytes);
    if let Some(q) = &stage.stamps {
        encoder.resolve_query_set(q, 0..2, &buffers.stamps, 0);
        encoder.copy_buffer_to_buffer(&buffers.stamps, 0, &buffers.readback, stamps_at, 16);
    }
    gpu.queue.submit([encoder.finish()]);
    let invalid = futures::executor::block_on(scope.pop());
    if let Some(e) = futures::executor::block_on(oom.pop()).or(invalid) {
        return Err(GpuError::Device(e.to_string()));
    }
    let (out, ticks) = read_flags(device, &buffers.readback, n, stamps_at)?;
    *slot = Some(buffers);
    let kernel_ms = stage.stamps.as_ref().map(|_| {
        let [begin, end] = ticks;
        end.saturating_sub(begin) as f64 * gpu.queue.get_timestamp_period() as f64 / 1e6
    });
    gpu.record(DeviceTimes {
        dispatches: 1,
        wall_ms: start.elapsed().as_secs_f64() * 1000.0,
        kernel_ms: kernel_ms.unwrap_or(0.0),
        timed: kernel_ms.is_some(),
        upload_bytes: (vertex_bytes.len() + edge_bytes.len()) as u64,
    });
    Ok(out)
}

/// Maps `buffer` and reads its first `n` u32 flags as booleans and the two u64 timestamps at
/// byte `stamps_at`.
fn read_flags(
    device: &wgpu::Device,
    buffer: &wgpu::Buffer,
    n: usize,
    stamps_at: u64,
) -> Result<(Vec<bool>, [u64; 2]), GpuError> {
    let slice = buffer.slice(..stamps_at + 16);
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |r| {
        let _ = tx.send(r);
    });
    device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| GpuError::Device(e.to_string()))?;
    rx.recv().map_err(|e| GpuError::Device(e.to_string()))?.map_err(|e| GpuError::Device(e.to_string()))?;
    let out = {
        let data = slice.get_mapped_range().map_err(|e| GpuError::Device(e.to_string()))?;
        let flags = bytemuck::cast_slice::<u8, u32>(&data[..4 * n]).iter().map(|&w| w != 0).collect();
        let at = stamps_at as usize;
        let tick = |i: usize| u64::from_le_bytes(data[at + 8 * i..at + 8 * i + 8].try_into().expect("8 bytes"));
        (flags, [tick(0), tick(1)])
    };
    buffer.unmap();
    Ok(out)
}
