//! Equirectangular rasters of the mesh: land mask PNG, elevation GeoTIFF and (in `preview`) a
//! colour preview, all sampled through one [`SphereRaster`].
//!
//! **Grid.** `width x height` pixels cover the whole sphere: row 0 touches 90°N, column 0 touches
//! 180°W, and pixel `(col, row)` is sampled at its centre, longitude `-180 + (col + 0.5) * 360 /
//! width` and latitude `90 - (row + 0.5) * 180 / height`.
//!
//! **Face search.** Every face is visited once (in parallel). Its latitude range comes from its
//! corners and the poleward bulge of its great-circle edges; its longitude range is the smallest
//! interval holding its corners, or all longitudes when it contains or nears a pole (so faces
//! across the antimeridian are handled by unwrapping). Each candidate pixel direction `d` is then
//! tested exactly against the three planes through the planet centre and each edge: `d` lies in
//! face `(A, B, C)` when `d·(B×C)`, `d·(C×A)` and `d·(A×B)` are all `>= 0`. A shared edge's plane
//! normal is computed from the same two vertices with opposite signs, which floating point keeps
//! exactly antisymmetric, so a pixel on an edge is claimed by at least one of its two faces; ties
//! go to the smallest face id. The three products, normalised, are also the barycentric weights
//! of the point where the ray along `d` meets the (planar) face, so values interpolate linearly
//! on the mesh's triangles. A pixel no face claims (only possible through rounding at a vertex,
//! or on an invalid mesh) takes the face it lies least outside of, found by a full scan.

use crate::mesh::{FaceKind, Mesh};
use crate::params::Params;

pub use crate::mesh::raster::SphereRaster;

/// 8-bit grayscale PNG of the land mask: 255 where the pixel's face is land, 0 where it is sea.
pub fn landmask_png(mesh: &Mesh, width: u32, height: u32) -> Vec<u8> {
    let raster = SphereRaster::new(mesh, width, height);
    let buf: Vec<u8> =
        raster.faces.iter().map(|&f| if mesh.face_kind(f) == FaceKind::Land { 255 } else { 0 }).collect();
    encode_png(&buf, width, height, image::ExtendedColorType::L8)
}

/// Single-band float32 Cloud-Optimized GeoTIFF ([`super::cog`]) of the ground altitude in
/// metres relative to sea level, interpolated on the mesh, georeferenced as EPSG:4326 covering
/// -180..180, -90..90. The sea gets its floor's (negative) altitude: no pixel is without data.
pub fn elevation_tiff(mesh: &Mesh, params: &Params, width: u32, height: u32) -> Vec<u8> {
    let raster = SphereRaster::new(mesh, width, height);
    let sea = params.sea_level_m;
    let data = raster.interpolate(mesh, |v| mesh.vertices[v].ground - sea);
    super::cog::write_cog(&super::cog::CogRaster {
        width: width as usize,
        height: height as usize,
        bands: vec![&data],
        names: vec!["ground_m"],
        west: -180.0,
        north: 90.0,
        pixel: [360.0 / width as f64, 180.0 / height as f64],
        nodata_nan: false,
    })
}

/// Encodes a raw buffer as PNG (deterministic: no time or text chunks).
pub(crate) fn encode_png(buf: &[u8], width: u32, height: u32, colour: image::ExtendedColorType) -> Vec<u8> {
    use image::ImageEncoder;
    let mut out = Vec::new();
    image::codecs::png::PngEncoder::new(&mut out)
        .write_image(buf, width, height, colour)
        .expect("PNG encodes into memory");
    out
}

#[cfg(test)]
#[path = "raster_tests.rs"]
mod tests;
