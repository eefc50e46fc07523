//! Snapshot rendering (paper §3.3) with wgpu: the planet adapted to a camera (§5), drawn
//! offscreen with a 3D climate lookup texture (altitude x latitude x the climate's
//! precipitation, see [`crate::export::climate`]), a water surface coloured by depth with a specular sun, diffuse sun
//! light, atmospheric haze and a sky or star background, then encoded as PNG or JPEG.
//!
//! One [`Renderer`] (device, pipelines, lookup textures) serves the whole process; see
//! [`shared`]. Where no adapter exists, rendering answers [`RenderError::NoAdapter`] and the rest
//! of the program carries on.

pub mod gpu;
pub mod scene;

use crate::adapt::{Adapter, Camera, CameraError};
use crate::mesh::Mesh;
use crate::params::Params;
use glam::DVec3;
pub use gpu::Renderer;
use std::sync::OnceLock;

/// Why a snapshot could not be made.
#[derive(Clone, Debug, thiserror::Error)]
pub enum RenderError {
    /// No usable graphics adapter (the service still runs; renders answer 503).
    #[error("no graphics adapter for rendering: {0}")]
    NoAdapter(String),
    /// The request exceeds what the device can hold.
    #[error("too large for the graphics device: {0}")]
    TooLarge(String),
    /// The device failed mid-frame (lost, out of memory, invalid use).
    #[error("the graphics device failed: {0}")]
    Device(String),
}

/// Image encodings of a snapshot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageFormat {
    Png,
    Jpeg,
}

impl ImageFormat {
    pub fn content_type(self) -> &'static str {
        match self {
            ImageFormat::Png => "image/png",
            ImageFormat::Jpeg => "image/jpeg",
        }
    }
}

impl std::str::FromStr for ImageFormat {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.to_ascii_lowercase().as_str() {
            "png" => Ok(ImageFormat::Png),
            "jpeg" | "jpg" => Ok(ImageFormat::Jpeg),
            _ => Err(format!("unknown image format {s:?} (png or jpeg)")),
        }
    }
}

/// JPEG quality of snapshots.
pub const JPEG_QUALITY: u8 = 90;

/// What to draw besides the camera.
#[derive(Clone, Debug, PartialEq)]
pub struct Shot {
    pub camera: Camera,
    /// Direction towards the sun (planet frame); None = over the viewer's shoulder.
    pub sun: Option<DVec3>,
}

impl Shot {
    /// Parses a camera query plus `sun=X,Y,Z`; other keys are returned for the caller.
    pub fn parse_query(query: &str, radius: f64) -> Result<(Shot, Vec<(String, String)>), CameraError> {
        let (camera, rest) = Camera::parse_query(query, radius)?;
        let mut sun = None;
        let mut others = Vec::new();
        for (k, v) in rest {
            if k == "sun" {
                sun = Some(parse_sun(&v)?);
            } else {
                others.push((k, v));
            }
        }
        Ok((Shot { camera, sun }, others))
    }

    /// The query that parses back to this shot (cache keys).
    pub fn to_query(&self) -> String {
        match self.sun {
            Some(s) => format!("{}&sun={},{},{}", self.camera.to_query(), s.x, s.y, s.z),
            None => self.camera.to_query(),
        }
    }

    fn sun_direction(&self) -> DVec3 {
        self.sun.unwrap_or_else(|| scene::default_sun(&self.camera))
    }
}

fn parse_sun(s: &str) -> Result<DVec3, CameraError> {
    let bad = |m: String| CameraError { field: "sun", message: m };
    let parts: Vec<f64> = s
        .split(',')
        .map(|p| p.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| bad(format!("expected X,Y,Z numbers, got {s:?}")))?;
    match parts[..] {
        [x, y, z] if [x, y, z].iter().all(|c| c.is_finite()) => {
            let d = DVec3::new(x, y, z);
            if d.length() > 0.0 {
                Ok(d.normalize())
            } else {
                Err(bad("must not be zero".into()))
            }
        }
        _ => Err(bad(format!("expected three finite numbers X,Y,Z, got {s:?}"))),
    }
}

/// The process-wide renderer, created on first use; the error is remembered.
pub fn shared() -> Result<&'static Renderer, RenderError> {
    static RENDERER: OnceLock<Result<Renderer, RenderError>> = OnceLock::new();
    RENDERER.get_or_init(Renderer::new).as_ref().map_err(Clone::clone)
}

/// Draws an already adapted `mesh` for `shot`; tightly packed sRGB RGBA8 rows.
pub fn draw(renderer: &Renderer, mesh: &Mesh, params: &Params, shot: &Shot) -> Result<Vec<u8>, RenderError> {
    let cam = &shot.camera;
    let scene = scene::prepare(mesh, params, cam, shot.sun_direction());
    renderer.draw(&scene, crate::export::climate::Palette::of(params), cam.width, cam.height)
}

/// Adapts `base` to the shot's camera (at most `max_faces`; on `gpu`'s device where given) and
/// draws it.
pub fn snapshot(
    renderer: &Renderer,
    base: &Mesh,
    params: &Params,
    shot: &Shot,
    max_faces: usize,
    gpu: Option<std::sync::Arc<crate::adapt::gpu::GpuAdaption>>,
) -> Result<Vec<u8>, RenderError> {
    let mut adapter = Adapter::new(base.clone(), params.clone()).with_gpu(gpu);
    adapter.adapt(&shot.camera, Some(max_faces));
    draw(renderer, adapter.mesh(), params, shot)
}

/// Encodes RGBA8 pixels; JPEG drops the alpha.
pub fn encode(rgba: &[u8], width: u32, height: u32, format: ImageFormat) -> Vec<u8> {
    let mut out = Vec::new();
    let cursor = &mut std::io::Cursor::new(&mut out);
    match format {
        ImageFormat::Png => image::codecs::png::PngEncoder::new(cursor)
            .write_image(rgba, width, height, image::ExtendedColorType::Rgba8)
            .expect("PNG encoding to memory"),
        ImageFormat::Jpeg => {
            let rgb: Vec<u8> = rgba.chunks_exact(4).flat_map(|p| [p[0], p[1], p[2]]).collect();
            image::codecs::jpeg::JpegEncoder::new_with_quality(cursor, JPEG_QUALITY)
                .write_image(&rgb, width, height, image::ExtendedColorType::Rgb8)
                .expect("JPEG encoding to memory")
        }
    }
    out
}

use image::ImageEncoder;

#[cfg(test)]
mod tests;
