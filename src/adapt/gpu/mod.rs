//! The wgpu compute backend of view-dependent adaption (paper §5): each stage that runs on the
//! device has its WGSL twin in `shaders/adapt_*.wgsl`, reading the mesh buffers in the
//! `#[repr(C)]` layouts of `crate::mesh` (`Vertex`, `Edge`) through bytemuck.
//!
//! On the device so far: the state update's split wishes (`state.rs`, `adapt_state.wgsl`). The
//! other stages (split-list compaction, splits, collapses, compaction) run on the CPU between
//! dispatches, so the mesh is uploaded for each state update.
//!
//! Precision: the shaders compute in `f64` (wgpu's `SHADER_F64`), on the mesh's own
//! planet-centred `f64` positions, with the operations of the CPU code in the same order, so a
//! decision is the CPU's: bit for bit where the device rounds `f64` arithmetic and `sqrt`
//! correctly without fusing multiply-adds (lavapipe, tested); elsewhere a decision can differ
//! only for an edge within about 1e-15 (relative) of its threshold. Adapters without `f64`
//! (e.g. Metal) are refused: `auto` stays on the CPU there.

mod state;

use std::sync::Arc;

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
    state: state::StagePipeline,
    /// What the dispatches since the last [`GpuAdaption::take_times`] cost.
    times: std::sync::Mutex<DeviceTimes>,
}

/// What device work cost (`riverworld bench --only adapt`): summed over dispatches.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DeviceTimes {
    /// State updates run on the device.
    pub dispatches: u32,
    /// Host wall time of those calls: upload, dispatch, wait and readback, milliseconds.
    pub wall_ms: f64,
    /// Device time of the compute passes from timestamp queries, milliseconds (0 if untimed).
    pub kernel_ms: f64,
    /// Whether the adapter has timestamp queries (`kernel_ms` is measured).
    pub timed: bool,
    /// Bytes written to the device.
    pub upload_bytes: u64,
}

impl DeviceTimes {
    fn add(&mut self, o: DeviceTimes) {
        self.dispatches += o.dispatches;
        self.wall_ms += o.wall_ms;
        self.kernel_ms += o.kernel_ms;
        self.timed |= o.timed;
        self.upload_bytes += o.upload_bytes;
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
        let timestamps = adapter.features().contains(wgpu::Features::TIMESTAMP_QUERY);
        let mut required_features = wgpu::Features::SHADER_F64;
        if timestamps {
            required_features |= wgpu::Features::TIMESTAMP_QUERY;
        }
        let (device, queue) = futures::executor::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("riverworld adaption"),
            required_features,
            required_limits: wgpu::Limits {
                max_buffer_size: limits.max_buffer_size,
                max_storage_buffer_binding_size: limits.max_storage_buffer_binding_size,
                max_compute_workgroups_per_dimension: limits.max_compute_workgroups_per_dimension,
                ..wgpu::Limits::downlevel_defaults()
            },
            ..Default::default()
        }))
        .map_err(|e| GpuError::Device(format!("{} ({:?}): {e}", info.name, info.backend)))?;
        let state = state::StagePipeline::new(&device, timestamps);
        Ok(GpuAdaption { device, queue, info, state, times: Default::default() })
    }

    /// The adapter, in words.
    pub fn describe(&self) -> String {
        format!("{} ({:?}, {:?})", self.info.name, self.info.backend, self.info.device_type)
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

/// The GPU backend `backend` asks for (`None`: the CPU backend) and a line saying what was
/// chosen and why. `auto` takes the GPU only when the adapter is a real GPU with `f64`.
pub fn select(backend: Backend) -> Result<(Option<Arc<GpuAdaption>>, String), GpuError> {
    match backend {
        Backend::Cpu => Ok((None, "adaption on the CPU (--backend cpu)".into())),
        Backend::Gpu => {
            let gpu = GpuAdaption::new()?;
            let line = format!("adaption on the GPU: {}", gpu.describe());
            Ok((Some(Arc::new(gpu)), line))
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
            match GpuAdaption::on(adapter) {
                Ok(gpu) => {
                    let line = format!("adaption on the GPU: {}", gpu.describe());
                    Ok((Some(Arc::new(gpu)), line))
                }
                Err(e) => Ok((None, format!("adaption on the CPU: {e}"))),
            }
        }
    }
}

pub use state::edge_wants;

#[cfg(test)]
mod tests;
