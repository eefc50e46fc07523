//! Camera paths over a planet for benchmarks and tests (`riverworld bench`, the backends'
//! comparisons): a camera at a height above the ground looking along it, and a flight from orbit
//! down to a river valley.

use super::camera::Camera;
use crate::geo::direction;
use glam::DVec3;

/// Highest ground or water altitude (above the base sphere) among the base-mesh vertices within
/// `reach` metres of (lat, lon): a safe floor for a camera there.
pub fn local_top(mesh: &crate::mesh::Mesh, lat: f64, lon: f64, reach: f64) -> f64 {
    let p = direction(lat, lon) * mesh.radius;
    let near = mesh.vertices.iter().filter(|v| v.p().normalize().distance(p.normalize()) * mesh.radius < reach);
    let top = near.map(|v| v.ground.max(v.water)).fold(f64::MIN, f64::max);
    if top == f64::MIN {
        mesh.vertices.iter().map(|v| v.ground.max(v.water)).fold(0.0, f64::max)
    } else {
        top
    }
}

/// A camera `height` m above the altitude `sea` (above the base sphere) at (lat, lon), looking
/// `ahead` m along the ground toward the heading `bearing_deg` (0 = north), at 1920x1080.
pub fn ground_camera(radius: f64, sea: f64, lat: f64, lon: f64, height: f64, ahead: f64, bearing_deg: f64) -> Camera {
    let up = direction(lat, lon);
    let north = (DVec3::Z - up * up.z).normalize_or(DVec3::X);
    let east = north.cross(up);
    let b = bearing_deg.to_radians();
    let heading = north * b.cos() + east * b.sin();
    let eye = up * (radius + sea + height);
    let target = (up + heading * (ahead / radius)).normalize() * (radius + sea);
    Camera::new(
        eye,
        target,
        None,
        60.0,
        1920,
        1080,
        super::camera::DEFAULT_LAND_PX,
        super::camera::DEFAULT_WATER_PX,
        radius,
    )
    .expect("benchmark camera is valid")
}

/// Face budget of each fly-through frame: its lowest frames would need tens of GB unbounded.
pub const FLY_THROUGH_FACES: usize = 2_000_000;

/// The fly-through: from orbit down to a river valley in `frames` steps.
pub fn fly_through(radius: f64, sea: f64, lat: f64, lon: f64, frames: usize) -> Vec<Camera> {
    (0..frames)
        .map(|i| {
            let t = i as f64 / (frames - 1).max(1) as f64;
            let height = 2.0e7 * (1.0 - t) + 1500.0 * t;
            let height = height.min(2.0e7 * (0.05f64).powf(t * 4.0)).max(1500.0);
            ground_camera(radius, sea, lat - 2.0 * (1.0 - t), lon, height, height * 2.0 + 5000.0, 10.0 * t)
        })
        .collect()
}
