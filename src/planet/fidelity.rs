//! How faithfully a planet built from an elevation map keeps the map's heights: the planet's
//! ground against the map box-averaged to a grid of about 1024 cells across (two map pixels or
//! more a cell), over the cells the map calls land.

use crate::maps::{GeoBounds, Map, MapKind};
use crate::mesh::raster::SphereRaster;
use crate::mesh::Mesh;
use serde::{Deserialize, Serialize};

/// `stats.json`'s `map_fidelity`: weighted by cell area on the sphere.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MapFidelity {
    /// Pearson correlation of planet and map altitudes.
    pub r: f64,
    /// Mean of planet minus map (m).
    pub bias_m: f64,
    /// Median of |planet - map| (m).
    pub median_abs_error_m: f64,
    /// The comparison grid (columns, rows) and its land cells.
    pub grid: [u32; 2],
    pub land_cells: usize,
}

/// Most cells across the comparison grid.
const GRID_CELLS: u32 = 1024;

/// The map fidelity of a planet's mesh (ground altitudes; sea level `sea` above the base
/// sphere), or `None` for a continent bitmap or a map without land.
pub fn map_fidelity(mesh: &Mesh, map: &Map, sea: f64) -> Option<MapFidelity> {
    if map.kind != MapKind::Elevation {
        return None;
    }
    let k = 2.max(map.width.div_ceil(GRID_CELLS));
    let (gw, gh) = ((map.width / k).max(1), (map.height / k).max(1));
    let (kx, ky) = (map.width / gw, map.height / gh);
    let (dx, dy) = map.pixel_size_deg();
    let b = map.bounds;
    let bounds = GeoBounds {
        west: b.west,
        north: b.north,
        east: b.west + f64::from(gw * kx) * dx,
        south: b.north - f64::from(gh * ky) * dy,
    };
    let raster = SphereRaster::new_in(mesh, bounds, gw, gh);
    let planet = raster.interpolate(mesh, |v| mesh.vertices[v].ground - sea);
    let mut cells = Vec::new(); // (planet, map, weight)
    for row in 0..gh {
        let weight = bounds.lat_of(row, gh).to_radians().cos();
        for col in 0..gw {
            if let Some(mean) = map.block_mean(col, row, kx, ky).filter(|&m| m >= 0.0) {
                cells.push((f64::from(planet[(row * gw + col) as usize]), mean, weight));
            }
        }
    }
    if cells.is_empty() {
        return None;
    }
    let total: f64 = cells.iter().map(|c| c.2).sum();
    let mean = |f: &dyn Fn(&(f64, f64, f64)) -> f64| cells.iter().map(|c| c.2 * f(c)).sum::<f64>() / total;
    let (mp, mm) = (mean(&|c| c.0), mean(&|c| c.1));
    let cov = mean(&|c| (c.0 - mp) * (c.1 - mm));
    let (vp, vm) = (mean(&|c| (c.0 - mp).powi(2)), mean(&|c| (c.1 - mm).powi(2)));
    let r = if vp > 0.0 && vm > 0.0 { cov / (vp * vm).sqrt() } else { 0.0 };
    let mut errors: Vec<(f64, f64)> = cells.iter().map(|c| ((c.0 - c.1).abs(), c.2)).collect();
    errors.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut acc = 0.0;
    let median = errors.iter().find(|e| {
        acc += e.1;
        acc >= total / 2.0
    });
    Some(MapFidelity {
        r,
        bias_m: mp - mm,
        median_abs_error_m: median.map_or(0.0, |e| e.0),
        grid: [gw, gh],
        land_cells: cells.len(),
    })
}
