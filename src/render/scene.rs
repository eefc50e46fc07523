//! What a snapshot draws, prepared on the CPU: eye-relative vertices, the water triangles and
//! the frame uniforms (paper §3.3 shading inputs), in the `#[repr(C)]` layouts of
//! `shaders/render.wgsl`.
//!
//! Precision: vertex positions are `f64` in the mesh; here they become `f32` offsets from the
//! eye, computed in `f64`, so the error is relative to the distance from the camera (about 0.1 mm
//! at 1 km, 1 m at 10,000 km). Depth is reversed-Z (near plane maps to 1, infinity to 0) with an
//! infinite far plane and a 32-bit float buffer: the float's exponent follows `near / distance`,
//! so depth resolution stays relative (about 1e-7 of the distance) from 10 cm to orbit, with no
//! far-plane clipping and no z-fighting between the ground and the water above it.

use crate::adapt::Camera;
use crate::geo::lat_lon;
use crate::mesh::Mesh;
use crate::params::Params;
use bytemuck::{Pod, Zeroable};
use glam::{DMat4, DVec3};
use rayon::prelude::*;

/// Near plane, metres: closer than any sensible eye-to-ground distance.
pub const NEAR_M: f64 = 0.05;
/// Height of the top of the atmosphere above the sea surface, metres.
pub const ATMOSPHERE_M: f64 = 60_000.0;
/// Distance through air over which haze on the ground reaches `1 - 1/e`, metres.
pub const HAZE_M: f64 = 700_000.0;
/// The same for the sky (thicker: it looks through the whole air column).
pub const SKY_M: f64 = 40_000.0;

/// One vertex: eye-relative ground position, altitudes relative to sea level, the area-weighted
/// surface normal, the local up (the water surface's normal), the latitude and the climate's
/// precipitation (mm/yr, [`crate::export::climate::precipitation_mm`]): the climate lookup's
/// coordinates with the altitude.
///
/// `water_m` is the level of the water body the vertex borders: its own water altitude where it
/// is submerged, else the highest water altitude of the submerged vertices it shares a face
/// with. A river bank thus carries the river's level, below its ground, and the water surface
/// (flat at that level) meets the linearly interpolated ground inside the face: faces with wet
/// and dry corners are partially flooded (paper §3.3) instead of drowned up to the dry corner.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct RenderVertex {
    pub position: [f32; 3],
    pub ground_m: f32,
    pub normal: [f32; 3],
    pub water_m: f32,
    pub up: [f32; 3],
    pub latitude_deg: f32,
    pub precip_mm: f32,
}

/// One end of a river line (`LineIn` in the shader): the water surface's eye-relative position,
/// the line's opacity there (from the share of a pixel the channel covers), the local up, and
/// the channel's depth.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct LineVertex {
    pub position: [f32; 3],
    pub coverage: f32,
    pub up: [f32; 3],
    pub depth_m: f32,
}

/// Uniforms of one frame (`Frame` in the shader).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct FrameUniforms {
    pub view_proj: [[f32; 4]; 4],
    pub forward: [f32; 4],
    pub right: [f32; 4],
    pub up: [f32; 4],
    pub centre: [f32; 4],
    pub sun: [f32; 4],
    pub lookup: [f32; 4],
    pub sky: [f32; 4],
    /// Bare rock on steep land: its colour in linear light (xyz).
    pub rock: [f32; 4],
}

/// Vertex and index data of a mesh for one camera.
pub struct Scene {
    pub vertices: Vec<RenderVertex>,
    /// All faces.
    pub terrain: Vec<u32>,
    /// Faces with at least one corner under water (the water surface).
    pub water: Vec<u32>,
    /// River edges narrower than a pixel, as line pairs (see [`river_lines`]).
    pub rivers: Vec<LineVertex>,
    pub frame: FrameUniforms,
}

/// Rivers narrower than a pixel as lines ([`crate::export::water::river_lines`]), one pixel
/// wide, as opaque as the square root of the share of the pixel the channel covers (so that the
/// eye sees a river covering a tenth of its pixels at a third, as a map draws it). A river whose
/// channel spans a pixel or more is drawn by its water surface too, where the mesh resolves it,
/// and by an opaque line where not.
pub fn river_lines(mesh: &Mesh, cam: &Camera) -> Vec<LineVertex> {
    let eye = cam.eye;
    crate::export::water::river_lines(mesh, cam)
        .into_iter()
        .flatten()
        .map(|end| LineVertex {
            position: (end.position - eye).as_vec3().to_array(),
            coverage: end.coverage.sqrt() as f32,
            up: end.up.as_vec3().to_array(),
            depth_m: end.depth_m as f32,
        })
        .collect()
}

/// The default sun: over the viewer's right shoulder, high above the view's centre.
pub fn default_sun(cam: &Camera) -> DVec3 {
    let (fwd, right, up) = cam.basis();
    let local_up = cam.eye.normalize();
    (local_up * 1.2 + right * 0.5 + up * 0.4 - fwd * 0.3).normalize()
}

/// Reversed-Z, infinite-far perspective times a rotation-only view (the eye is the origin).
pub fn view_projection(cam: &Camera) -> DMat4 {
    let (fwd, _, up) = cam.basis();
    let aspect = cam.width as f64 / cam.height as f64;
    let proj = DMat4::perspective_infinite_reverse_rh(cam.fov_deg.to_radians(), aspect, NEAR_M);
    proj * DMat4::look_to_rh(DVec3::ZERO, fwd, up)
}

/// Prepares `mesh` (ground altitudes above the base sphere) for drawing from `cam`.
pub fn prepare(mesh: &Mesh, params: &Params, cam: &Camera, sun: DVec3) -> Scene {
    let triangles = mesh.triangles();
    // Wide rivers' channels carved where the view is finer than them (`export/carve.rs`).
    let mesh = &*crate::export::carve::carved(mesh, &triangles);
    let normals = crate::export::surface_normals(mesh, &triangles);
    let levels = crate::export::water::water_levels(mesh, &triangles);
    let sea = params.sea_level_m;
    let eye = cam.eye;
    let vertices: Vec<RenderVertex> = mesh
        .vertices
        .par_iter()
        .zip(normals.par_iter())
        .zip(levels.par_iter())
        .map(|((v, n), level)| {
            let p = v.p();
            let up = p.normalize_or(DVec3::Z);
            let (lat, lon) = lat_lon(p);
            RenderVertex {
                position: (p - eye).as_vec3().to_array(),
                ground_m: (v.ground - sea) as f32,
                normal: n.as_vec3().to_array(),
                water_m: (level - sea) as f32,
                up: up.as_vec3().to_array(),
                latitude_deg: lat as f32,
                precip_mm: crate::export::climate::precipitation_mm(mesh, lat, lon) as f32,
            }
        })
        .collect();
    let water: Vec<u32> = triangles
        .par_iter()
        .filter(|t| crate::export::water::shows_water(mesh, &levels, t))
        .flat_map_iter(|&t| t)
        .collect();
    let terrain: Vec<u32> = triangles.into_iter().flatten().collect();
    let (fwd, right, up) = cam.basis();
    let tan_y = (cam.fov_deg.to_radians() * 0.5).tan();
    let tan_x = tan_y * cam.width as f64 / cam.height as f64;
    let v4 = |d: DVec3, w: f64| [d.x as f32, d.y as f32, d.z as f32, w as f32];
    let sea_radius = params.radius_m + sea;
    let frame = FrameUniforms {
        view_proj: view_projection(cam).as_mat4().to_cols_array_2d(),
        forward: v4(fwd, 0.0),
        right: v4(right * tan_x, 0.0),
        up: v4(up * tan_y, 0.0),
        centre: v4(-eye, sea_radius),
        sun: v4(sun.normalize_or(DVec3::Z), sea_radius + ATMOSPHERE_M),
        lookup: [
            crate::export::climate::TEXTURE_MIN_ALTITUDE_M as f32,
            (crate::export::climate::TEXTURE_MAX_ALTITUDE_M - crate::export::climate::TEXTURE_MIN_ALTITUDE_M) as f32,
            HAZE_M as f32,
            // The depth at which the water ramp texture (built from `water_colour`) ends.
            crate::export::climate::DEEPEST_M as f32,
        ],
        sky: {
            // The cosines of the slopes between which land turns to bare rock.
            let [gentle, steep] = crate::export::climate::BARE_ROCK_SLOPE_DEG.map(|d| d.to_radians().cos() as f32);
            [SKY_M as f32, crate::export::climate::TEXTURE_MAX_PRECIP_MM as f32, steep, gentle]
        },
        rock: {
            let [r, g, b] = crate::export::climate::rock_linear().map(|c| c as f32);
            [r, g, b, 0.0]
        },
    };
    Scene { vertices, terrain, water, rivers: river_lines(mesh, cam), frame }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec4;

    fn camera(eye: DVec3, target: DVec3) -> Camera {
        Camera::new(eye, target, None, 60.0, 640, 480, 8.0, 40.0, 6_371_000.0).unwrap()
    }

    #[test]
    fn reversed_depth_keeps_resolution_from_centimetres_to_orbit() {
        let r = 6_371_000.0;
        let eye = DVec3::new(r + 2.0, 0.0, 0.0);
        let cam = camera(eye, DVec3::new(r, 1000.0, 0.0));
        let vp = view_projection(&cam);
        let (fwd, _, _) = cam.basis();
        let depth = |d: f64| {
            let c = vp * (fwd * d).extend(1.0);
            c.z / c.w
        };
        // Nearer is larger; the far plane is at infinity.
        assert!((depth(NEAR_M) - 1.0).abs() < 1e-9);
        assert!(depth(1e9) > 0.0 && depth(1e9) < depth(1e7));
        // Two surfaces 0.1% of their distance apart get distinct f32 depths at every scale.
        for d in [0.2, 3.0, 100.0, 10_000.0, 1e6, 2e7] {
            let (a, b) = (depth(d) as f32, depth(d * 1.001) as f32);
            assert!(a > b, "{d}: {a} {b}");
        }
        // Points on the view axis land in the screen centre.
        let c: DVec4 = vp * (fwd * 500.0).extend(1.0);
        assert!((c.x / c.w).abs() < 1e-9 && (c.y / c.w).abs() < 1e-9);
    }

    #[test]
    fn vertices_are_eye_relative_and_water_covers_submerged_faces() {
        let planet = crate::export::test_planet();
        let p = Params { base_faces: 2000, ..Params::default() };
        let eye = DVec3::new(p.radius_m * 3.0, 0.0, 0.0);
        let cam = camera(eye, DVec3::ZERO);
        let s = prepare(&planet.mesh, &p, &cam, default_sun(&cam));
        assert_eq!(s.vertices.len(), planet.mesh.vertices.len());
        assert_eq!(s.terrain.len(), planet.mesh.faces.len() * 3);
        assert!(!s.water.is_empty() && s.water.len() < s.terrain.len());
        for (rv, v) in s.vertices.iter().zip(&planet.mesh.vertices) {
            let back = DVec3::from_array(rv.position.map(|x| x as f64)) + eye;
            assert!(back.distance(v.p()) < 4.0, "f32 offset error at 3 radii stays metres");
            assert!((rv.ground_m as f64 - (v.ground - p.sea_level_m)).abs() < 1e-3);
            let (lat, lon) = lat_lon(v.p());
            assert_eq!(rv.precip_mm, crate::export::climate::precipitation_mm(&planet.mesh, lat, lon) as f32);
        }
        assert!(planet.mesh.precipitation.is_some(), "a built planet carries its climate");
        assert_eq!(std::mem::size_of::<RenderVertex>(), 52);
        assert_eq!(std::mem::size_of::<FrameUniforms>(), 192);
    }
}
