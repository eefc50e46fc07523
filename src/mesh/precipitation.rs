//! The planet's mean annual precipitation, carried with its mesh so that the colours of any
//! mesh refined from it (views, tiles, renders, previews) follow the climate's moisture
//! (deserts where it is dry, forest where it is wet: `export/climate.rs`) rather than latitude
//! alone.
//!
//! The field is the climate model's global latitude/longitude grid (`planet/climate.rs`, cell
//! centres as [`crate::mesh::raster::SphereRaster`] places them, row 0 at the north pole),
//! looked up bilinearly between cell centres: longitudes wrap, latitudes beyond the first and
//! last rows' centres take those rows. The lookup is a pure function of the grid and the
//! position, so every path and backend gets the same colour for the same vertex.

/// Precipitation (mm/yr) on a global `width` x `height` grid, row-major from the north-west.
#[derive(Clone, Debug, PartialEq)]
pub struct Precipitation {
    width: usize,
    height: usize,
    mm: Vec<f32>,
}

impl Precipitation {
    /// `None` unless `mm` holds `width * height` finite values, both at least 1.
    pub fn new(width: usize, height: usize, mm: Vec<f32>) -> Option<Precipitation> {
        let ok = width > 0 && height > 0 && mm.len() == width * height && mm.iter().all(|x| x.is_finite());
        ok.then_some(Precipitation { width, height, mm })
    }

    /// Precipitation (mm/yr, at least 0) at a latitude and longitude in degrees.
    pub fn at(&self, lat_deg: f64, lon_deg: f64) -> f64 {
        let (w, h) = (self.width, self.height);
        // Continuous cell coordinates with cell centres on integers.
        let y = ((90.0 - lat_deg) / 180.0 * h as f64 - 0.5).clamp(0.0, (h - 1) as f64);
        let x = (lon_deg + 180.0) / 360.0 * w as f64 - 0.5;
        if !x.is_finite() || !y.is_finite() {
            return 0.0;
        }
        let (r0, fy) = (y.floor() as usize, y - y.floor());
        let r1 = (r0 + 1).min(h - 1);
        let (xf, fx) = (x.floor(), x - x.floor());
        let c0 = (xf as i64).rem_euclid(w as i64) as usize;
        let c1 = (c0 + 1) % w;
        let v = |r: usize, c: usize| f64::from(self.mm[r * w + c]);
        let top = v(r0, c0) + (v(r0, c1) - v(r0, c0)) * fx;
        let bottom = v(r1, c0) + (v(r1, c1) - v(r1, c0)) * fx;
        (top + (bottom - top) * fy).max(0.0)
    }

    /// Bytes held.
    pub fn bytes(&self) -> usize {
        self.mm.len() * 4
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lookup_is_bilinear_between_cell_centres_and_wraps() {
        // 4 x 2 grid: cells 90° wide, rows at 45°N and 45°S.
        let p = Precipitation::new(4, 2, vec![0.0, 100.0, 200.0, 300.0, 400.0, 500.0, 600.0, 700.0]).unwrap();
        // Cell centres.
        assert_eq!(p.at(45.0, -135.0), 0.0);
        assert_eq!(p.at(-45.0, 135.0), 700.0);
        // Halfway between two centres of a row, and between rows.
        assert!((p.at(45.0, -90.0) - 50.0).abs() < 1e-9);
        assert!((p.at(0.0, -135.0) - 200.0).abs() < 1e-9);
        // Across the antimeridian: halfway between the last and first columns.
        assert!((p.at(45.0, 180.0) - 150.0).abs() < 1e-9);
        assert!((p.at(45.0, -180.0) - 150.0).abs() < 1e-9);
        // Beyond the first row's centre: that row.
        assert_eq!(p.at(90.0, -135.0), 0.0);
        assert_eq!(p.at(f64::NAN, 0.0), 0.0);
    }

    #[test]
    fn bad_grids_are_refused() {
        assert!(Precipitation::new(2, 2, vec![0.0; 3]).is_none());
        assert!(Precipitation::new(0, 0, vec![]).is_none());
        assert!(Precipitation::new(1, 1, vec![f32::NAN]).is_none());
    }
}
