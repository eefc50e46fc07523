//! The mesh resident on the device (paper §5.2): the vertex, edge and face buffers in the
//! `#[repr(C)]` layouts of `crate::mesh`, the per-edge scratch of the state update and the
//! split list, and a small readback of counts and timestamps. Capacities grow with slack like
//! the host buffers (`compact::N_ALLOC`), copying what the device holds, so passes and cameras
//! reuse the same buffers and only counts cross the bus until the mesh is read back.

use super::{GpuAdaption, GpuError};
use crate::adapt::cpu::compact::SLACK;
use crate::mesh::{Edge, Face, Mesh, Vertex, EDGE_BYTES, FACE_BYTES, VERTEX_BYTES};
use wgpu::BufferUsages as U;

/// Byte offset of the resolved timestamps in the readback buffer (after the four counts).
pub(super) const STAMPS_AT: u64 = 16;

/// The device copy of one adapter's mesh.
pub struct DeviceMesh {
    pub(super) vertices: wgpu::Buffer,
    pub(super) edges: wgpu::Buffer,
    pub(super) faces: wgpu::Buffer,
    /// One `u32` per edge slot each: split wishes, chain flags (the demanded edges of the
    /// collapse candidates), ready flags, the split list.
    pub(super) wants: wgpu::Buffer,
    pub(super) seen: wgpu::Buffer,
    pub(super) ready: wgpu::Buffer,
    pub(super) list: wgpu::Buffer,
    /// Ready edges per block of the split-list compaction, then the blocks' offsets.
    pub(super) sums: wgpu::Buffer,
    /// One `u32` per vertex slot: collapse marks (`MARK_LOOK`, `MARK_COLLAPSE`). Slots past the
    /// live vertices are zero: the buffer is fresh whenever the vertex count shrinks.
    pub(super) marks: wgpu::Buffer,
    /// `[ready edges, wanted edges]` of the last split-list compaction, then the collapse
    /// candidates and those of a full look.
    pub(super) counts: wgpu::Buffer,
    /// Stage parameters (`GpuView`, `ScanGrid`, `SplitParams`, `Sweep`).
    pub(super) view: wgpu::Buffer,
    pub(super) grid: wgpu::Buffer,
    pub(super) split: wgpu::Buffer,
    pub(super) sweep: wgpu::Buffer,
    /// Resolved timestamps, and the counts and timestamps mapped for reading.
    pub(super) stamps: wgpu::Buffer,
    pub(super) readback: wgpu::Buffer,
    /// Live lengths of the vertex, edge and face buffers.
    pub lens: (usize, usize, usize),
}

impl std::fmt::Debug for DeviceMesh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "DeviceMesh({:?})", self.lens)
    }
}

/// Bytes [`buffer`] allocates for `size`.
fn padded(size: u64) -> u64 {
    size.next_multiple_of(256).max(256)
}

fn buffer(device: &wgpu::Device, label: &str, size: u64, usage: U) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: padded(size),
        usage,
        mapped_at_creation: false,
    })
}

/// Runs `work` (buffer creation, copies) with the device's out-of-memory and validation errors
/// caught: an error is returned instead of reaching the device's handler, which panics, so
/// that the adapter can go on on the CPU. Whatever `work` made is dropped on an error.
fn scoped<T>(gpu: &GpuAdaption, work: impl FnOnce() -> T) -> Result<T, GpuError> {
    let oom = gpu.device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
    let validation = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
    let out = work();
    let invalid = futures::executor::block_on(validation.pop());
    match futures::executor::block_on(oom.pop()).or(invalid) {
        Some(e) => Err(GpuError::Device(e.to_string())),
        None => Ok(out),
    }
}

const STORE: U = U::STORAGE.union(U::COPY_SRC).union(U::COPY_DST);

/// Capacity for `n` entities: `n` plus the slack, scaled like the host buffers'.
fn with_slack(n: usize, slack: usize) -> u64 {
    (n + n / 4 + slack) as u64
}

impl DeviceMesh {
    /// Device buffers holding `mesh`.
    pub(super) fn upload(gpu: &GpuAdaption, mesh: &Mesh) -> Result<DeviceMesh, GpuError> {
        let (nv, ne, nf) = (mesh.vertices.len(), mesh.edges.len(), mesh.faces.len());
        let mut dm = DeviceMesh::with_capacity(gpu, nv, ne, nf)?;
        scoped(gpu, || {
            gpu.queue.write_buffer(&dm.vertices, 0, bytemuck::cast_slice(&mesh.vertices));
            gpu.queue.write_buffer(&dm.edges, 0, bytemuck::cast_slice(&mesh.edges));
            gpu.queue.write_buffer(&dm.faces, 0, bytemuck::cast_slice(&mesh.faces));
        })?;
        dm.lens = (nv, ne, nf);
        Ok(dm)
    }

    /// Buffers with room for `nv` vertices, `ne` edges and `nf` faces plus slack; empty. A
    /// mesh over the device's limits, or its memory, is an error.
    pub(super) fn with_capacity(gpu: &GpuAdaption, nv: usize, ne: usize, nf: usize) -> Result<DeviceMesh, GpuError> {
        let device = &gpu.device;
        let (cv, ce, cf) = (with_slack(nv, SLACK.0), with_slack(ne, SLACK.1), with_slack(nf, SLACK.2));
        let limits = device.limits();
        let limit = limits.max_storage_buffer_binding_size.min(limits.max_buffer_size);
        for needed in [cv * VERTEX_BYTES as u64, ce * EDGE_BYTES as u64, cf * FACE_BYTES as u64].map(padded) {
            if needed > limit {
                return Err(GpuError::TooLarge { needed, limit });
            }
        }
        scoped(gpu, || DeviceMesh::create(device, (cv, ce, cf), (nv, ne, nf)))
    }

    /// The buffers of [`DeviceMesh::with_capacity`], capacities `(cv, ce, cf)`, lengths `lens`.
    fn create(device: &wgpu::Device, (cv, ce, cf): (u64, u64, u64), lens: (usize, usize, usize)) -> DeviceMesh {
        let flags = |label| buffer(device, label, 4 * ce, STORE);
        DeviceMesh {
            vertices: buffer(device, "vertices", cv * VERTEX_BYTES as u64, STORE),
            edges: buffer(device, "edges", ce * EDGE_BYTES as u64, STORE),
            faces: buffer(device, "faces", cf * FACE_BYTES as u64, STORE),
            wants: flags("wants"),
            seen: flags("chain flags"),
            ready: flags("ready flags"),
            list: flags("split list"),
            sums: buffer(device, "block sums", 4 * ce.div_ceil(super::BLOCK as u64), STORE),
            marks: buffer(device, "collapse marks", 4 * cv, STORE),
            counts: buffer(device, "counts", STAMPS_AT, STORE),
            view: buffer(device, "view", std::mem::size_of::<super::layout::GpuView>() as u64, STORE),
            grid: buffer(device, "grid", 16, U::UNIFORM | U::COPY_DST),
            split: buffer(
                device,
                "split params",
                std::mem::size_of::<super::layout::SplitParams>() as u64,
                U::UNIFORM | U::COPY_DST,
            ),
            sweep: buffer(device, "sweep", 16, U::UNIFORM | U::COPY_DST),
            stamps: buffer(device, "timestamps", 16 * super::TIMED_PASSES as u64, U::QUERY_RESOLVE | U::COPY_SRC),
            readback: buffer(
                device,
                "readback",
                STAMPS_AT + 16 * super::TIMED_PASSES as u64,
                U::MAP_READ | U::COPY_DST,
            ),
            lens,
        }
    }

    /// A copy of the mesh in new buffers, made on the device: the same as uploading the mesh
    /// again (fresh scratch and collapse marks), without crossing the bus.
    pub(super) fn duplicate(&self, gpu: &GpuAdaption) -> Result<DeviceMesh, GpuError> {
        let (nv, ne, nf) = self.lens;
        let copy = DeviceMesh::with_capacity(gpu, nv, ne, nf)?;
        scoped(gpu, || {
            let mut encoder = gpu.device.create_command_encoder(&Default::default());
            encoder.copy_buffer_to_buffer(&self.vertices, 0, &copy.vertices, 0, (nv * VERTEX_BYTES) as u64);
            encoder.copy_buffer_to_buffer(&self.edges, 0, &copy.edges, 0, (ne * EDGE_BYTES) as u64);
            encoder.copy_buffer_to_buffer(&self.faces, 0, &copy.faces, 0, (nf * FACE_BYTES) as u64);
            gpu.queue.submit([encoder.finish()]);
        })?;
        Ok(copy)
    }

    /// Capacity in vertices, edges and faces.
    pub(super) fn capacity(&self) -> (usize, usize, usize) {
        (
            self.vertices.size() as usize / VERTEX_BYTES,
            self.edges.size() as usize / EDGE_BYTES,
            self.faces.size() as usize / FACE_BYTES,
        )
    }

    /// Makes room for `n` more splits (a vertex, three edges and two faces each), moving the
    /// mesh, the split list and the collapse marks into larger buffers on the device when it is
    /// short (split wishes and chain flags are decided again after the splits).
    pub(super) fn reserve_splits(&mut self, gpu: &GpuAdaption, n: usize) -> Result<(), GpuError> {
        let (nv, ne, nf) = self.lens;
        let (cv, ce, cf) = self.capacity();
        if nv + n <= cv && ne + 3 * n <= ce && nf + 2 * n <= cf {
            return Ok(());
        }
        let bigger = DeviceMesh::with_capacity(gpu, nv + n, ne + 3 * n, nf + 2 * n)?;
        scoped(gpu, || {
            let mut encoder = gpu.device.create_command_encoder(&Default::default());
            encoder.copy_buffer_to_buffer(&self.vertices, 0, &bigger.vertices, 0, (nv * VERTEX_BYTES) as u64);
            encoder.copy_buffer_to_buffer(&self.edges, 0, &bigger.edges, 0, (ne * EDGE_BYTES) as u64);
            encoder.copy_buffer_to_buffer(&self.faces, 0, &bigger.faces, 0, (nf * FACE_BYTES) as u64);
            encoder.copy_buffer_to_buffer(&self.list, 0, &bigger.list, 0, 4 * ne as u64);
            encoder.copy_buffer_to_buffer(&self.marks, 0, &bigger.marks, 0, 4 * nv as u64);
            gpu.queue.submit([encoder.finish()]);
        })?;
        *self = DeviceMesh { lens: self.lens, ..bigger };
        Ok(())
    }

    /// Reads the mesh back: the three buffers copied into one staging buffer, one wait, and
    /// each mapped range turned into its typed vector with a single copy. A mesh larger than
    /// the device's largest buffer is read buffer by buffer instead.
    pub(super) fn download(&self, gpu: &GpuAdaption, radius: f64) -> Result<Mesh, GpuError> {
        self.download_staged(gpu, radius, gpu.device.limits().max_buffer_size)
    }

    /// [`DeviceMesh::download`] with staging buffers of at most `largest` bytes (but one per
    /// mesh buffer).
    pub(super) fn download_staged(&self, gpu: &GpuAdaption, radius: f64, largest: u64) -> Result<Mesh, GpuError> {
        let (nv, ne, nf) = self.lens;
        let sizes = [nv * VERTEX_BYTES, ne * EDGE_BYTES, nf * FACE_BYTES].map(|n| n as u64);
        let total: u64 = sizes.iter().sum();
        if total == 0 {
            return Ok(Mesh { radius, ..Mesh::default() });
        }
        let buffers = [&self.vertices, &self.edges, &self.faces];
        if total > largest {
            let [v, e, f] = [0, 1, 2].map(|i| read_bytes(gpu, buffers[i], sizes[i]));
            return Ok(Mesh {
                radius,
                vertices: bytemuck::pod_collect_to_vec::<u8, Vertex>(&v?),
                edges: checked_vec::<Edge>(&e?, "edge")?,
                faces: checked_vec::<Face>(&f?, "face")?,
                guide: None,
                channels: None,
                precipitation: None,
            });
        }
        let staging = scoped(gpu, || {
            let staging = buffer_exact(&gpu.device, "staging", total, U::MAP_READ | U::COPY_DST);
            let mut encoder = gpu.device.create_command_encoder(&Default::default());
            let mut at = 0;
            for (buffer, size) in buffers.into_iter().zip(sizes) {
                encoder.copy_buffer_to_buffer(buffer, 0, &staging, at, size);
                at += size;
            }
            gpu.queue.submit([encoder.finish()]);
            staging
        })?;
        map_with(gpu, &staging, total, |data| {
            let (vertex_bytes, rest) = data.split_at(sizes[0] as usize);
            let (edge_bytes, face_bytes) = rest.split_at(sizes[1] as usize);
            Ok(Mesh {
                radius,
                vertices: bytemuck::pod_collect_to_vec::<u8, Vertex>(vertex_bytes),
                edges: checked_vec::<Edge>(edge_bytes, "edge")?,
                faces: checked_vec::<Face>(face_bytes, "face")?,
                guide: None,
                channels: None,
                precipitation: None,
            })
        })?
    }

    /// Reads the split wishes of the live edges back.
    pub(super) fn download_wants(&self, gpu: &GpuAdaption) -> Result<Vec<bool>, GpuError> {
        let words = read(gpu, &self.wants, 4 * self.lens.1 as u64)?;
        Ok(words.iter().map(|&w| w != 0).collect())
    }
}

/// The first `size` bytes of `buffer` (a multiple of four), as words, through a staging buffer.
pub(super) fn read(gpu: &GpuAdaption, buffer: &wgpu::Buffer, size: u64) -> Result<Vec<u32>, GpuError> {
    Ok(bytemuck::pod_collect_to_vec::<u8, u32>(&read_bytes(gpu, buffer, size)?))
}

/// The first `size` bytes of a device buffer.
fn read_bytes(gpu: &GpuAdaption, buffer: &wgpu::Buffer, size: u64) -> Result<Vec<u8>, GpuError> {
    if size == 0 {
        return Ok(Vec::new());
    }
    let staging = scoped(gpu, || {
        let staging = buffer_exact(&gpu.device, "staging", size, U::MAP_READ | U::COPY_DST);
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, size);
        gpu.queue.submit([encoder.finish()]);
        staging
    })?;
    map_with(gpu, &staging, size, |data| data.to_vec())
}

fn buffer_exact(device: &wgpu::Device, label: &str, size: u64, usage: U) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: size.next_multiple_of(wgpu::COPY_BUFFER_ALIGNMENT),
        usage,
        mapped_at_creation: false,
    })
}

/// Maps the first `size` bytes of a `MAP_READ` buffer (after the submitted work) as words.
pub(super) fn map_words(gpu: &GpuAdaption, buffer: &wgpu::Buffer, size: u64) -> Result<Vec<u32>, GpuError> {
    map_with(gpu, buffer, size, bytemuck::pod_collect_to_vec::<u8, u32>)
}

/// Maps the first `size` bytes of a `MAP_READ` buffer (after the submitted work) and hands them
/// to `f`.
fn map_with<R>(gpu: &GpuAdaption, buffer: &wgpu::Buffer, size: u64, f: impl FnOnce(&[u8]) -> R) -> Result<R, GpuError> {
    let device_error = |e: &dyn std::fmt::Display| GpuError::Device(e.to_string());
    let slice = buffer.slice(..size);
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |r| {
        let _ = tx.send(r);
    });
    gpu.device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| device_error(&e))?;
    rx.recv().map_err(|e| device_error(&e))?.map_err(|e| device_error(&e))?;
    let out = {
        let data = slice.get_mapped_range().map_err(|e| device_error(&e))?;
        f(&data)
    };
    buffer.unmap();
    Ok(out)
}

/// `bytes` as entities of a type with invalid bit patterns (an enum field), each checked: cast
/// in place where the mapping is aligned for `T`, else through an aligned copy.
fn checked_vec<T: bytemuck::CheckedBitPattern + Copy>(bytes: &[u8], what: &str) -> Result<Vec<T>, GpuError> {
    use bytemuck::checked::{try_cast_slice, CheckedCastError};
    use bytemuck::PodCastError;
    let bad = || GpuError::Device(format!("the device returned an invalid {what}"));
    match try_cast_slice::<u8, T>(bytes) {
        Ok(items) => Ok(items.to_vec()),
        Err(CheckedCastError::PodCastError(PodCastError::TargetAlignmentGreaterAndInputNotAligned)) => {
            let words = bytemuck::pod_collect_to_vec::<u8, u32>(bytes);
            Ok(try_cast_slice::<u32, T>(&words).map_err(|_| bad())?.to_vec())
        }
        Err(_) => Err(bad()),
    }
}
