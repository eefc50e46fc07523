//! The wgpu compute backend of view-dependent adaption (paper §5): each stage that runs on the
//! device has its WGSL twin in `shaders/adapt/<stage>.wgsl`, reading the mesh buffers in the
//! `#[repr(C)]` layouts of `crate::mesh` (`Vertex`, `Edge`, `Face`, spelt out once for the
//! shaders in `shaders/adapt/layout.wgsl`) through bytemuck.
//!
//! On the device: the state update with its collapse candidates (`state.rs`), split-list
//! compaction with its prefix sums (`select.rs`), the edge splits with their terrain
//! (`split.rs`), vertex collapses (`collapse.rs`) and buffer compaction (`compact.rs`), on a
//! mesh that stays resident between passes and runs (`buffers.rs`); a pass reads back four
//! counts, the mesh is read back once at the end of a run (`adapt.rs`). The one step left to the
//! host is the sort of the occasional spatial order between cameras: the host computes it on its
//! copy (the previous output) and uploads only the new ids, which the device copy follows.
//!
//! Precision: the shaders compute in `f64` (wgpu's `SHADER_F64`), on the mesh's own
//! planet-centred `f64` positions, with the operations of the CPU code in the same order, so a
//! decision is the CPU's: bit for bit where the device rounds `f64` arithmetic and `sqrt`
//! correctly (lavapipe, tested). Fused multiply-adds are forbidden on Vulkan, where the shaders
//! go to the driver as SPIR-V whose float operations are decorated `NoContraction`
//! (`spirv.rs`); on other backends a compiler may fuse, and a decision can then differ only for
//! an edge within about 1e-15 (relative) of its threshold. Adapters without `f64` (e.g. Metal)
//! are refused, and `auto` takes a GPU only when a small planet adapts there exactly as on the
//! CPU (`reproduce.rs`): it stays on the CPU otherwise.

mod buffers;
mod collapse;
mod compact;
mod layout;
mod reproduce;
mod run;
mod select;
mod shaders;
mod spirv;
mod split;
mod state;

pub use buffers::DeviceMesh;
pub use run::{Device, Resident};
use std::sync::Arc;
use std::time::Instant;

/// Where adaption runs (`--backend`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Backend {
    /// rayon on the CPU.
    Cpu,
    /// wgpu compute; fails if no suitable adapter exists.
    Gpu,
    /// The GPU backend when the adapter is a real GPU with `f64`, else the CPU backend.
    #[default]
    Auto,
}

impl std::str::FromStr for Backend {
    type Err = String;
    fn from_str(s: &str) -> Result<Backend, String> {
        match s {
            "cpu" => Ok(Backend::Cpu),
            "gpu" => Ok(Backend::Gpu),
            "auto" => Ok(Backend::Auto),
            _ => Err(format!("unknown backend {s:?}: use cpu, gpu or auto")),
        }
    }
}

/// Why the GPU backend cannot run.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    #[error("no graphics adapter: {0}")]
    NoAdapter(String),
    #[error("adapter {0} does not support f64 in shaders (SHADER_F64)")]
    NoF64(String),
    #[error("the mesh needs {needed} bytes in one storage binding; the device allows {limit}")]
    TooLarge { needed: u64, limit: u64 },
    #[error("device error: {0}")]
    Device(String),
}

/// The device, its queue and the adaption pipelines.
pub struct GpuAdaption {
    device: wgpu::Device,
    queue: wgpu::Queue,
    info: wgpu::AdapterInfo,
    state: state::StatePipeline,
    select: select::SelectPipeline,
    split: split::SplitPipeline,
    collapse: collapse::CollapsePipeline,
    compact: compact::CompactPipeline,
    /// A begin and an end timestamp for each of the first [`TIMED_PASSES`] compute passes of a
    /// submission, where the device has timestamp queries.
    stamps: Option<wgpu::QuerySet>,
    /// What the submissions since the last [`GpuAdaption::take_times`] cost.
    times: std::sync::Mutex<DeviceTimes>,
}

/// The stages that run on the device (`DeviceTimes::stage_ms` order).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Stage {
    State = 0,
    Select = 1,
    Split = 2,
    Collapse = 3,
    Compact = 4,
}

/// Compute passes of one submission that get timestamps (a pass records at most eight).
const TIMED_PASSES: usize = 16;

/// Items per block of the prefix sums (`BLOCK` in `scan.wgsl`).
pub(crate) const BLOCK: u32 = 1024;
/// Workgroup size of the item-wise stages.
pub(crate) const WORKGROUP: u32 = 256;

impl layout::ScanGrid {
    /// Item-wise and block-wise dispatch shapes for `items` items: the grid and the workgroups
    /// `(x, y)` of each.
    pub(crate) fn new(device: &wgpu::Device, items: u32) -> (layout::ScanGrid, (u32, u32), (u32, u32)) {
        let (gx, gy, row) = dispatch_grid(device, items.max(1), WORKGROUP);
        let blocks = items.div_ceil(BLOCK).max(1);
        let (bx, by, block_row) = dispatch_grid(device, blocks, 1);
        (layout::ScanGrid { items, row, blocks, block_row }, (gx, gy), (bx, by))
    }
}

/// What device work cost (`riverworld bench --only adapt`): summed over submissions.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DeviceTimes {
    /// Command submissions waited for (about one per pass).
    pub dispatches: u32,
    /// Host wall time of those submissions: encoding, waiting and reading back, milliseconds.
    pub wall_ms: f64,
    /// Device time of the compute passes from timestamp queries, milliseconds (0 if untimed).
    pub kernel_ms: f64,
    /// The same per stage: state update (with collapse candidates), split-list compaction,
    /// splits, collapses, buffer compaction.
    pub stage_ms: [f64; 5],
    /// Whether the adapter has timestamp queries (`kernel_ms` is measured).
    pub timed: bool,
    /// Bytes written to the device.
    pub upload_bytes: u64,
    /// Bytes of mesh and flags read back (counts and timestamps not included).
    pub download_bytes: u64,
}

impl DeviceTimes {
    fn add(&mut self, o: DeviceTimes) {
        self.dispatches += o.dispatches;
        self.wall_ms += o.wall_ms;
        self.kernel_ms += o.kernel_ms;
        for (a, b) in self.stage_ms.iter_mut().zip(o.stage_ms) {
            *a += b;
        }
        self.timed |= o.timed;
        self.upload_bytes += o.upload_bytes;
        self.download_bytes += o.download_bytes;
    }
}

impl std::fmt::Debug for GpuAdaption {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "GpuAdaption({} {:?})", self.info.name, self.info.backend)
    }
}

impl GpuAdaption {
    /// Opens the adapter wgpu prefers (`WGPU_BACKEND` and friends narrow the choice) with `f64`.
    pub fn new() -> Result<GpuAdaption, GpuError> {
        GpuAdaption::on(open_adapter(wgpu::Backends::PRIMARY).map_err(GpuError::NoAdapter)?)
    }

    /// Opens a device with `f64` on `adapter` and builds the pipelines.
    fn on(adapter: wgpu::Adapter) -> Result<GpuAdaption, GpuError> {
        let info = adapter.get_info();
        if !adapter.features().contains(wgpu::Features::SHADER_F64) {
            return Err(GpuError::NoF64(format!("{} ({:?})", info.name, info.backend)));
        }
        let limits = adapter.limits();
        // The collapse candidates bind seven storage buffers.
        if limits.max_storage_buffers_per_shader_stage < 7 {
            return Err(GpuError::Device(format!(
                "{} ({:?}) allows {} storage buffers per shader stage; adaption needs 7",
                info.name, info.backend, limits.max_storage_buffers_per_shader_stage
            )));
        }
        let timestamps = adapter.features().contains(wgpu::Features::TIMESTAMP_QUERY);
        let mut required_features = wgpu::Features::SHADER_F64;
        if timestamps {
            required_features |= wgpu::Features::TIMESTAMP_QUERY;
        }
        // SPIR-V without fused multiply-adds (`spirv.rs`), where the driver takes SPIR-V.
        if info.backend == wgpu::Backend::Vulkan && adapter.features().contains(wgpu::Features::PASSTHROUGH_SHADERS) {
            required_features |= wgpu::Features::PASSTHROUGH_SHADERS;
        }
        let (device, queue) = futures::executor::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("riverworld adaption"),
            required_features,
            required_limits: wgpu::Limits {
                max_buffer_size: limits.max_buffer_size,
                max_storage_buffer_binding_size: limits.max_storage_buffer_binding_size,
                max_compute_workgroups_per_dimension: limits.max_compute_workgroups_per_dimension,
                max_storage_buffers_per_shader_stage: limits.max_storage_buffers_per_shader_stage,
                ..wgpu::Limits::downlevel_defaults()
            },
            ..Default::default()
        }))
        .map_err(|e| GpuError::Device(format!("{} ({:?}): {e}", info.name, info.backend)))?;
        let stamps = timestamps.then(|| {
            device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("adaption stage timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: 2 * TIMED_PASSES as u32,
            })
        });
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let state = state::StatePipeline::new(&device)?;
        let select = select::SelectPipeline::new(&device)?;
        let split = split::SplitPipeline::new(&device)?;
        let collapse = collapse::CollapsePipeline::new(&device)?;
        let compact = compact::CompactPipeline::new(&device)?;
        if let Some(e) = futures::executor::block_on(scope.pop()) {
            return Err(GpuError::Device(format!("{} ({:?}): {e}", info.name, info.backend)));
        }
        Ok(GpuAdaption {
            device,
            queue,
            info,
            state,
            select,
            split,
            collapse,
            compact,
            stamps,
            times: Default::default(),
        })
    }

    /// The adapter, in words.
    pub fn describe(&self) -> String {
        let shaders = if self.exact_arithmetic() { "SPIR-V without contraction" } else { "WGSL" };
        format!("{} ({:?}, {:?}, {shaders})", self.info.name, self.info.backend, self.info.device_type)
    }

    /// Whether the shaders reach the driver with fused multiply-adds forbidden (`spirv.rs`).
    pub fn exact_arithmetic(&self) -> bool {
        takes_spirv(&self.device)
    }

    /// The device work since the last call, and starts counting again.
    pub fn take_times(&self) -> DeviceTimes {
        std::mem::take(&mut *self.times.lock().unwrap_or_else(|e| e.into_inner()))
    }

    fn record(&self, t: DeviceTimes) {
        self.times.lock().unwrap_or_else(|e| e.into_inner()).add(t);
    }

    /// Whether the adapter is a CPU (lavapipe, llvmpipe, WARP).
    pub fn is_cpu(&self) -> bool {
        self.info.device_type == wgpu::DeviceType::Cpu
    }
}

/// The adapter wgpu prefers among `backends` (high performance first); `WGPU_BACKEND` and
/// friends narrow the choice. Shared with the renderer.
pub fn open_adapter(backends: wgpu::Backends) -> Result<wgpu::Adapter, String> {
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = backends;
    let instance = wgpu::Instance::new(desc.with_env());
    futures::executor::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
        power_preference: wgpu::PowerPreference::HighPerformance,
        ..Default::default()
    }))
    .map_err(|e| e.to_string())
}

pub use reproduce::reproduces_cpu;

/// The GPU backend `backend` asks for (`None`: the CPU backend) and a line saying what was
/// chosen and why. `auto` takes the GPU only when the adapter is a real GPU with `f64` whose
/// meshes are the CPU's bit for bit ([`reproduces_cpu`]); `gpu` takes it anyway, saying so.
pub fn select(backend: Backend) -> Result<(Option<Arc<GpuAdaption>>, String), GpuError> {
    match backend {
        Backend::Cpu => Ok((None, "adaption on the CPU (--backend cpu)".into())),
        Backend::Gpu => {
            let gpu = Arc::new(GpuAdaption::new()?);
            let mut line = format!("adaption on the GPU: {}", gpu.describe());
            if !gpu.is_cpu() && !reproduces_cpu(&gpu)? {
                line += "; its meshes differ from the CPU's in the last bits";
            }
            Ok((Some(gpu), line))
        }
        Backend::Auto => {
            let adapter = match open_adapter(wgpu::Backends::PRIMARY) {
                Ok(a) => a,
                Err(e) => return Ok((None, format!("adaption on the CPU: {}", GpuError::NoAdapter(e)))),
            };
            let info = adapter.get_info();
            if info.device_type == wgpu::DeviceType::Cpu {
                let line =
                    format!("adaption on the CPU: the adapter {} ({:?}) is itself a CPU", info.name, info.backend);
                return Ok((None, line));
            }
            let gpu = match GpuAdaption::on(adapter) {
                Ok(gpu) => Arc::new(gpu),
                Err(e) => return Ok((None, format!("adaption on the CPU: {e}"))),
            };
            match reproduces_cpu(&gpu) {
                Ok(true) => Ok((Some(Arc::clone(&gpu)), format!("adaption on the GPU: {}", gpu.describe()))),
                Ok(false) => Ok((
                    None,
                    format!(
                        "adaption on the CPU: the GPU {} does not reproduce its meshes bit for bit",
                        gpu.describe()
                    ),
                )),
                Err(e) => Ok((None, format!("adaption on the CPU: the GPU {} failed ({e})", gpu.describe()))),
            }
        }
    }
}

/// Whether each edge of `mesh` wants to be split for `view`, decided on the device (the mesh is
/// uploaded for it; adaption itself keeps its mesh resident instead).
pub fn edge_wants(
    gpu: &GpuAdaption,
    mesh: &crate::mesh::Mesh,
    view: &crate::adapt::View,
) -> Result<Vec<bool>, GpuError> {
    if mesh.edges.is_empty() {
        return Ok(Vec::new());
    }
    let dm = DeviceMesh::upload(gpu, mesh)?;
    let mut sub = gpu.submission();
    gpu.state.encode(gpu, &mut sub, &dm, view);
    sub.finish(gpu, &dm)?;
    dm.download_wants(gpu)
}

/// Workgroups `(x, y)` covering `n` invocations of `size`, and invocations per row of the grid
/// (the index of an invocation is `x + y * row`).
pub(crate) fn dispatch_grid(device: &wgpu::Device, n: u32, size: u32) -> (u32, u32, u32) {
    let groups = n.div_ceil(size).max(1);
    let gx = groups.min(device.limits().max_compute_workgroups_per_dimension);
    (gx, groups.div_ceil(gx), gx * size)
}

/// Whether `device` was opened to take the shaders as SPIR-V (requested on Vulkan only).
fn takes_spirv(device: &wgpu::Device) -> bool {
    device.features().contains(wgpu::Features::PASSTHROUGH_SHADERS)
}

/// A stage's shader: a WGSL module, or SPIR-V passed through, one module per entry point with
/// the bind group layout wgpu cannot derive from it.
enum Shader {
    Wgsl(wgpu::ShaderModule),
    SpirV(Vec<(spirv::Entry, wgpu::ShaderModule)>),
}

/// A stage's shader: `shaders/adapt/layout.wgsl` followed by the stage's own sources; SPIR-V
/// without contraction where the device takes it (`spirv.rs`), else WGSL.
fn shader(device: &wgpu::Device, stage: Stage) -> Result<Shader, GpuError> {
    let (full, label) = (shaders::source(stage), shaders::file_name(stage));
    if takes_spirv(device) {
        let entries = spirv::compile(&full).map_err(|e| GpuError::Device(format!("{label}: {e}")))?;
        let modules = entries
            .into_iter()
            .map(|entry| {
                // SAFETY: the words are naga's own SPIR-V for a WGSL module naga validated, with
                // decorations added in the annotation section only
                // (`spirv::forbid_contraction`); the pipeline binds the layout derived from the
                // same module.
                let module = unsafe { device.create_shader_module_passthrough(entry.descriptor(label)) };
                (entry, module)
            })
            .collect();
        return Ok(Shader::SpirV(modules));
    }
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(full.into()),
    });
    Ok(Shader::Wgsl(module))
}

/// The compute pipeline of `entry` in `shader`, its bind group layout derived from the shader.
fn pipeline(device: &wgpu::Device, shader: &Shader, entry: &str) -> wgpu::ComputePipeline {
    let (module, layout) = match shader {
        Shader::Wgsl(module) => (module, None),
        Shader::SpirV(modules) => {
            let (compiled, module) = modules
                .iter()
                .find(|(e, _)| e.name == entry)
                .unwrap_or_else(|| panic!("no entry point {entry} in the stage's shader"));
            let group = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some(entry),
                entries: &compiled.bindings,
            });
            let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(entry),
                bind_group_layouts: &[Some(&group)],
                immediate_size: 0,
            });
            (module, Some(layout))
        }
    };
    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(entry),
        layout: layout.as_ref(),
        module,
        entry_point: Some(entry),
        compilation_options: Default::default(),
        cache: None,
    })
}

/// A bind group for `pipeline`'s group 0 with the whole buffers at the given bindings.
fn bind(device: &wgpu::Device, pipeline: &wgpu::ComputePipeline, entries: &[(u32, &wgpu::Buffer)]) -> wgpu::BindGroup {
    let entries: Vec<wgpu::BindGroupEntry> =
        entries.iter().map(|&(binding, b)| wgpu::BindGroupEntry { binding, resource: b.as_entire_binding() }).collect();
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &entries,
    })
}

/// Commands being recorded for one submission, with the error scopes that watch them.
pub(crate) struct Submission {
    pub encoder: wgpu::CommandEncoder,
    oom: wgpu::ErrorScopeGuard,
    validation: wgpu::ErrorScopeGuard,
    start: Instant,
    /// The stage of each compute pass recorded so far.
    stages: Vec<Stage>,
}

impl GpuAdaption {
    /// Starts recording a submission.
    pub(crate) fn submission(&self) -> Submission {
        let oom = self.device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let validation = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let encoder = self.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("adaption") });
        Submission { encoder, oom, validation, start: Instant::now(), stages: Vec::new() }
    }
}

impl Submission {
    /// A compute pass of `stage`, timed where the device has timestamp queries.
    fn pass<'e>(&'e mut self, gpu: &'e GpuAdaption, stage: Stage) -> wgpu::ComputePass<'e> {
        let n = self.stages.len() as u32;
        self.stages.push(stage);
        let timestamp_writes =
            gpu.stamps.as_ref().filter(|_| n < TIMED_PASSES as u32).map(|q| wgpu::ComputePassTimestampWrites {
                query_set: q,
                beginning_of_pass_write_index: Some(2 * n),
                end_of_pass_write_index: Some(2 * n + 1),
            });
        self.encoder
            .begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("adaption stage"), timestamp_writes })
    }

    /// Submits, waits, and returns `dm.counts` (`[ready edges, wanted edges]` of the last
    /// split-list compaction, collapse candidates and those of a full look); device errors
    /// raised by the recorded work are returned.
    pub(crate) fn finish(self, gpu: &GpuAdaption, dm: &DeviceMesh) -> Result<[usize; 4], GpuError> {
        let Submission { mut encoder, oom, validation, start, stages } = self;
        let timed = stages.len().min(TIMED_PASSES);
        encoder.copy_buffer_to_buffer(&dm.counts, 0, &dm.readback, 0, buffers::STAMPS_AT);
        if let (Some(q), true) = (&gpu.stamps, timed > 0) {
            encoder.resolve_query_set(q, 0..2 * timed as u32, &dm.stamps, 0);
            encoder.copy_buffer_to_buffer(&dm.stamps, 0, &dm.readback, buffers::STAMPS_AT, 16 * timed as u64);
        }
        gpu.queue.submit([encoder.finish()]);
        let invalid = futures::executor::block_on(validation.pop());
        if let Some(e) = futures::executor::block_on(oom.pop()).or(invalid) {
            return Err(GpuError::Device(e.to_string()));
        }
        let words = buffers::map_words(gpu, &dm.readback, buffers::STAMPS_AT + 16 * timed as u64)?;
        let mut t = DeviceTimes { dispatches: 1, timed: gpu.stamps.is_some(), ..Default::default() };
        if gpu.stamps.is_some() {
            let period = gpu.queue.get_timestamp_period() as f64;
            let at = buffers::STAMPS_AT as usize / 4;
            let tick = |i: usize| words[at + 2 * i] as u64 | (words[at + 2 * i + 1] as u64) << 32;
            for (n, stage) in stages.iter().take(timed).enumerate() {
                t.stage_ms[*stage as usize] += tick(2 * n + 1).saturating_sub(tick(2 * n)) as f64 * period / 1e6;
            }
            t.kernel_ms = t.stage_ms.iter().sum();
        }
        t.wall_ms = start.elapsed().as_secs_f64() * 1000.0;
        gpu.record(t);
        Ok([0, 1, 2, 3].map(|i| words[i] as usize))
    }
}

#[cfg(test)]
mod tests;
