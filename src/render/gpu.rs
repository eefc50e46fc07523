//! The wgpu device and pipelines of snapshot rendering: created once, shared by every render,
//! one frame at a time (a mutex queues concurrent callers). Draws `shaders/render.wgsl` into an
//! offscreen sRGB target with a reversed-Z 32-bit float depth buffer and reads the pixels back.

use super::scene::{FrameUniforms, LineVertex, RenderVertex, Scene};
use super::RenderError;
use crate::export::climate::{climate_texture, water_colour, Palette};
use std::sync::Mutex;
use wgpu::util::DeviceExt;

/// The shader of every pass.
pub const SHADER: &str = include_str!("../../shaders/render.wgsl");
/// Size of the climate lookup texture (altitude x latitude).
const CLIMATE_SIZE: (u32, u32, u32) = (256, 64, 32);
/// Texels of the water colour ramp (square root of depth / darkest depth).
const RAMP_SIZE: u32 = 256;
const COLOUR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// A device with the snapshot pipelines.
pub struct Renderer {
    device: wgpu::Device,
    queue: wgpu::Queue,
    info: wgpu::AdapterInfo,
    layout: wgpu::BindGroupLayout,
    sky: wgpu::RenderPipeline,
    terrain: wgpu::RenderPipeline,
    water: wgpu::RenderPipeline,
    rivers: wgpu::RenderPipeline,
    sampler: wgpu::Sampler,
    ramp: wgpu::TextureView,
    climates: Vec<(Palette, wgpu::TextureView)>,
    frame_lock: Mutex<()>,
}

impl Renderer {
    /// Opens the first adapter wgpu finds (`WGPU_BACKEND` and friends narrow the choice).
    pub fn new() -> Result<Renderer, RenderError> {
        let adapter = crate::adapt::gpu::open_adapter(wgpu::Backends::PRIMARY | wgpu::Backends::GL)
            .map_err(RenderError::NoAdapter)?;
        let info = adapter.get_info();
        let limits = adapter.limits();
        let (device, queue) = futures::executor::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("riverworld render"),
            required_limits: wgpu::Limits {
                max_buffer_size: limits.max_buffer_size,
                max_texture_dimension_2d: limits.max_texture_dimension_2d,
                ..wgpu::Limits::downlevel_defaults()
            },
            ..Default::default()
        }))
        .map_err(|e| RenderError::NoAdapter(format!("{} ({:?}): {e}", info.name, info.backend)))?;
        Ok(Renderer::with_device(device, queue, info))
    }

    fn with_device(device: wgpu::Device, queue: wgpu::Queue, info: wgpu::AdapterInfo) -> Renderer {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("render.wgsl"),
            source: wgpu::ShaderSource::Wgsl(SHADER.into()),
        });
        let texture_entry = |binding, view_dimension| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: true },
                view_dimension,
                multisampled: false,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("frame"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                texture_entry(1, wgpu::TextureViewDimension::D3),
                texture_entry(2, wgpu::TextureViewDimension::D2),
                wgpu::BindGroupLayoutEntry {
                    binding: 3,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("frame"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let vertex_layout = wgpu::VertexBufferLayout {
            array_stride: std::mem::size_of::<RenderVertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &wgpu::vertex_attr_array![
                0 => Float32x3, 1 => Float32, 2 => Float32x3, 3 => Float32, 4 => Float32x3, 5 => Float32,
                6 => Float32
            ],
        };
        let pipeline = |label: &str, vs: &str, fs: &str, blend: Option<wgpu::BlendState>, depth: bool| {
            let buffers = [Some(vertex_layout.clone())];
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(&pipeline_layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some(vs),
                    compilation_options: Default::default(),
                    buffers: if depth { &buffers } else { &[] },
                },
                primitive: wgpu::PrimitiveState {
                    // The mesh winds counter-clockwise seen from outside; from inside the planet
                    // nothing is drawn, so back faces are culled.
                    cull_mode: depth.then_some(wgpu::Face::Back),
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(depth),
                    depth_compare: Some(if depth {
                        wgpu::CompareFunction::Greater
                    } else {
                        wgpu::CompareFunction::Always
                    }),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(fs),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: COLOUR_FORMAT,
                        blend,
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let rivers = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("rivers"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("river_vertex"),
                compilation_options: Default::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: std::mem::size_of::<LineVertex>() as u64,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32, 2 => Float32x3, 3 => Float32],
                })],
            },
            primitive: wgpu::PrimitiveState { topology: wgpu::PrimitiveTopology::LineList, ..Default::default() },
            // On the water surface, which lies on or above the ground along a river edge: drawn
            // where nothing nearer is, without hiding what comes after.
            depth_stencil: Some(wgpu::DepthStencilState {
                format: DEPTH_FORMAT,
                depth_write_enabled: Some(false),
                depth_compare: Some(wgpu::CompareFunction::GreaterEqual),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("river_fragment"),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format: COLOUR_FORMAT,
                    blend: Some(wgpu::BlendState::ALPHA_BLENDING),
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });
        let sky = pipeline("sky", "sky_vertex", "sky_fragment", None, false);
        let terrain = pipeline("terrain", "terrain_vertex", "terrain_fragment", None, true);
        let water = pipeline("water", "water_vertex", "water_fragment", Some(wgpu::BlendState::ALPHA_BLENDING), true);
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("lookup"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let ramp: Vec<u8> = (0..RAMP_SIZE)
            .flat_map(|i| {
                // Texel i holds depth = darkest * (i / (n - 1))^2, matching the shader's sqrt.
                let t = i as f64 / (RAMP_SIZE - 1) as f64;
                let [r, g, b] = water_colour(t * t * crate::export::climate::DEEPEST_M);
                [r, g, b, 255]
            })
            .collect();
        let ramp = upload(&device, &queue, "water ramp", (RAMP_SIZE, 1, 1), &ramp);
        let climates = Palette::ALL
            .into_iter()
            .map(|c| {
                let (w, h, d) = CLIMATE_SIZE;
                (c, upload(&device, &queue, "climate", CLIMATE_SIZE, &climate_texture(c, w, h, d)))
            })
            .collect();
        Renderer {
            device,
            queue,
            info,
            layout,
            sky,
            terrain,
            water,
            rivers,
            sampler,
            ramp,
            climates,
            frame_lock: Mutex::new(()),
        }
    }

    /// The adapter's name, backend and kind, for logs and errors.
    pub fn describe(&self) -> String {
        format!("{} ({:?}, {:?})", self.info.name, self.info.backend, self.info.device_type)
    }

    /// Whether the adapter is a CPU (software rasteriser such as lavapipe or llvmpipe).
    pub fn is_cpu(&self) -> bool {
        self.info.device_type == wgpu::DeviceType::Cpu
    }

    /// Draws `scene` at `width` x `height` and returns tightly packed sRGB RGBA8 rows, top first.
    pub fn draw(&self, scene: &Scene, palette: Palette, width: u32, height: u32) -> Result<Vec<u8>, RenderError> {
        let limits = self.device.limits();
        let vertex_bytes = (scene.vertices.len() * std::mem::size_of::<RenderVertex>()) as u64;
        if vertex_bytes > limits.max_buffer_size || (scene.terrain.len() * 4) as u64 > limits.max_buffer_size {
            return Err(RenderError::TooLarge(format!(
                "{} vertices exceed the device's largest buffer ({} bytes)",
                scene.vertices.len(),
                limits.max_buffer_size
            )));
        }
        if width > limits.max_texture_dimension_2d || height > limits.max_texture_dimension_2d {
            return Err(RenderError::TooLarge(format!(
                "{width}x{height} exceeds the device's largest texture ({})",
                limits.max_texture_dimension_2d
            )));
        }
        let _frame = self.frame_lock.lock().unwrap_or_else(|e| e.into_inner());
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let validation = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let pixels = self.encode_and_read(scene, palette, width, height);
        let invalid = futures::executor::block_on(validation.pop());
        let oom = futures::executor::block_on(scope.pop());
        if let Some(e) = oom {
            return Err(RenderError::Device(format!("out of memory on {}: {e}", self.describe())));
        }
        if let Some(e) = invalid {
            return Err(RenderError::Device(format!("{}: {e}", self.describe())));
        }
        pixels
    }

    fn encode_and_read(
        &self,
        scene: &Scene,
        palette: Palette,
        width: u32,
        height: u32,
    ) -> Result<Vec<u8>, RenderError> {
        let device = &self.device;
        let size = wgpu::Extent3d { width, height, depth_or_array_layers: 1 };
        let target = |label, format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let colour_tex =
            target("colour", COLOUR_FORMAT, wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC);
        let colour = colour_tex.create_view(&Default::default());
        let depth =
            target("depth", DEPTH_FORMAT, wgpu::TextureUsages::RENDER_ATTACHMENT).create_view(&Default::default());
        let buffer = |label, contents: &[u8], usage| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage })
        };
        let uniforms = buffer("frame", bytemuck::bytes_of(&scene.frame), wgpu::BufferUsages::UNIFORM);
        let vertices = buffer("vertices", bytemuck::cast_slice(&scene.vertices), wgpu::BufferUsages::VERTEX);
        let terrain = buffer("terrain", bytemuck::cast_slice(&scene.terrain), wgpu::BufferUsages::INDEX);
        let water = buffer("water", bytemuck::cast_slice(&scene.water), wgpu::BufferUsages::INDEX);
        let rivers = buffer("rivers", bytemuck::cast_slice(&scene.rivers), wgpu::BufferUsages::VERTEX);
        let climate_view = &self.climates.iter().find(|(c, _)| *c == palette).expect("every palette uploaded").1;
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("frame"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniforms.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(climate_view) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&self.ramp) },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::Sampler(&self.sampler) },
            ],
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("snapshot"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &colour,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth,
                    depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(0.0), store: wgpu::StoreOp::Discard }),
                    stencil_ops: None,
                }),
                ..Default::default()
            });
            pass.set_bind_group(0, &bind, &[]);
            pass.set_pipeline(&self.sky);
            pass.draw(0..3, 0..1);
            pass.set_vertex_buffer(0, vertices.slice(..));
            pass.set_pipeline(&self.terrain);
            pass.set_index_buffer(terrain.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..scene.terrain.len() as u32, 0, 0..1);
            if !scene.water.is_empty() {
                pass.set_pipeline(&self.water);
                pass.set_index_buffer(water.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..scene.water.len() as u32, 0, 0..1);
            }
            if !scene.rivers.is_empty() {
                pass.set_pipeline(&self.rivers);
                pass.set_vertex_buffer(0, rivers.slice(..));
                pass.draw(0..scene.rivers.len() as u32, 0..1);
            }
        }
        let row = width * 4;
        let padded = row.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let readback = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: padded as u64 * height as u64,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        encoder.copy_texture_to_buffer(
            colour_tex.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &readback,
                layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(padded), rows_per_image: None },
            },
            size,
        );
        self.queue.submit([encoder.finish()]);
        let slice = readback.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| RenderError::Device(format!("waiting for {}: {e}", self.describe())))?;
        rx.recv()
            .map_err(|_| RenderError::Device("the readback was dropped".into()))?
            .map_err(|e| RenderError::Device(format!("reading pixels back: {e}")))?;
        let mapped = slice.get_mapped_range().map_err(|e| RenderError::Device(format!("reading pixels back: {e}")))?;
        let mut pixels = Vec::with_capacity((row * height) as usize);
        for y in 0..height as usize {
            let start = y * padded as usize;
            pixels.extend_from_slice(&mapped[start..start + row as usize]);
        }
        drop(mapped);
        readback.unmap();
        Ok(pixels)
    }
}

/// An sRGB RGBA8 lookup texture of `(width, height, depth)` texels: 2D where the depth is 1.
fn upload(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    label: &str,
    size: (u32, u32, u32),
    rgba: &[u8],
) -> wgpu::TextureView {
    let (w, h, d) = size;
    device
        .create_texture_with_data(
            queue,
            &wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: d },
                mip_level_count: 1,
                sample_count: 1,
                dimension: if d > 1 { wgpu::TextureDimension::D3 } else { wgpu::TextureDimension::D2 },
                format: wgpu::TextureFormat::Rgba8UnormSrgb,
                usage: wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            },
            wgpu::util::TextureDataOrder::LayerMajor,
            rgba,
        )
        .create_view(&Default::default())
}

// Uniform buffers are read in 16-byte rows.
const _: () = assert!(std::mem::size_of::<FrameUniforms>().is_multiple_of(16));
