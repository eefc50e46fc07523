//! Sphere geometry shared by every layer: latitude and longitude of planet-centred points
//! (+Z north, longitude 0 on +X).

use glam::DVec3;

/// Latitude and longitude in degrees of a planet-centred point.
pub fn lat_lon(p: DVec3) -> (f64, f64) {
    let n = p.normalize();
    (n.z.clamp(-1.0, 1.0).asin().to_degrees(), n.y.atan2(n.x).to_degrees())
}

/// Unit direction of a latitude/longitude in degrees.
pub fn direction(lat_deg: f64, lon_deg: f64) -> DVec3 {
    let (lat, lon) = (lat_deg.to_radians(), lon_deg.to_radians());
    DVec3::new(lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin())
}
