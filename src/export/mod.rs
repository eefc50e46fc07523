//! Exports (paper §3.3 colours): glTF binary, GeoJSON rivers, equirectangular rasters.
//!
//! Every export is deterministic: the same mesh and parameters give byte-identical output (no
//! timestamps, no hash-map iteration order, parallel work written to fixed slots).
//!
//! Altitudes in every export are metres relative to sea level (`ground - params.sea_level_m`),
//! not to the base sphere the mesh stores them against.

pub mod carve;
pub mod climate;
pub mod cog;
pub mod colour_mip;
pub mod dem;
pub mod face_index;
pub mod geojson;
pub mod glb;
pub mod glb_pack;
pub mod preview;
pub mod quantized_mesh;
pub mod raster;
pub mod terrain_rgb;
pub mod tile_sets;
pub mod tiles;
pub mod vector_tiles;
pub mod view;
pub mod water;

pub use climate::{climate_colour, climate_texture, water_colour};
pub use geojson::rivers_geojson;
pub use glb::{encode_glb, planet_glb, to_gltf_axes, GlbMesh};
pub use preview::preview_png;
pub use raster::{elevation_tiff, landmask_png, SphereRaster};

use crate::mesh::Mesh;
use glam::DVec3;

/// Unit surface normal of every vertex: the area-weighted sum of its faces' normals, given the
/// mesh's triangles ([`Mesh::triangles`], derived once by each export and shared).
///
/// The mesh stores no normals (river vertices keep only their downstream tangent), so exports
/// compute them from the faces.
pub fn surface_normals(mesh: &Mesh, triangles: &[[u32; 3]]) -> Vec<DVec3> {
    use rayon::prelude::*;
    // Face vectors in parallel, then summed per vertex in face order (the same bits as a serial
    // pass), then normalised in parallel.
    let areas: Vec<DVec3> = triangles.par_iter().map(|&t| mesh.triangle_area_vector(t)).collect();
    let mut acc = vec![DVec3::ZERO; mesh.vertices.len()];
    for (corners, &n) in triangles.iter().zip(&areas) {
        for &v in corners {
            acc[v as usize] += n;
        }
    }
    acc.par_iter()
        .zip(mesh.vertices.par_iter())
        .map(|(n, v)| {
            let n = n.normalize_or_zero();
            if n == DVec3::ZERO {
                v.p().normalize_or_zero()
            } else {
                n
            }
        })
        .collect()
}

/// A small planet shared by the export tests (built once).
#[cfg(test)]
pub(crate) fn test_planet() -> &'static crate::planet::Planet {
    use std::sync::OnceLock;
    static PLANET: OnceLock<crate::planet::Planet> = OnceLock::new();
    PLANET.get_or_init(|| {
        let spec = crate::planet::PlanetSpec {
            seed: 1,
            params: crate::params::Params { base_faces: 2000, ..Default::default() },
            map: None,
            precipitation: None,
        };
        crate::planet::build_planet(&spec, &mut |_, _| {}).expect("test planet builds")
    })
}
