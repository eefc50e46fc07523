//! The shore around a regional elevation map: outside a regional map the planet is sea, and
//! without a margin its coast would run along the map's edges, dragging the ground inside the
//! bounds down to sea level within a base face or two of them and making every river leave
//! through a cliff at the edge. [`Map::with_shore`] widens the map by a margin whose ground
//! eases from the nearest edge pixel down to a shelf below sea level, so the coast lies outside
//! the user's bounds and the terrain inside them is the map's.

use super::{GeoBounds, Map, MapKind};

/// Ground at the outer rim of the margin (m): below sea level, so the rim is sea (the ocean of a
/// regional map touches its edges), about the depth of a continental shelf's edge.
pub const SHORE_RIM_M: f32 = -150.0;

impl Map {
    /// This elevation map widened by up to `pixels` pixels on each side (fewer where the globe's
    /// ±180°/±90° limits come first), with the added ground falling linearly from the nearest
    /// edge pixel to [`SHORE_RIM_M`] at the rim (sea and nodata edge pixels stay what they are:
    /// a sea pixel never rises). `None` for global maps and continent bitmaps, which keep
    /// their edges.
    pub fn with_shore(&self, pixels: u32) -> Option<Map> {
        if self.kind != MapKind::Elevation || self.bounds.is_global() || pixels == 0 {
            return None;
        }
        let (dlon, dlat) = self.pixel_size_deg();
        let b = self.bounds;
        // Whole pixels that fit between each edge and the globe's limits (a hair inside them).
        let fit = |room: f64, step: f64| ((room / step - 1e-9).floor().max(0.0) as u32).min(pixels);
        let (west, east) = (fit(b.west + 180.0, dlon), fit(180.0 - b.east, dlon));
        let (north, south) = (fit(90.0 - b.north, dlat), fit(b.south + 90.0, dlat));
        // The longitude span stays below a full turn, so the widened map is still regional.
        let room = ((360.0 - (b.east - b.west)) / dlon - 1.0).floor().max(0.0) as u32;
        let (west, east) =
            if west + east > room { (west.min(room / 2), east.min(room - room / 2)) } else { (west, east) };
        let (w, h) = (self.width + west + east, self.height + north + south);
        let bounds = GeoBounds {
            west: b.west - f64::from(west) * dlon,
            south: b.south - f64::from(south) * dlat,
            east: b.east + f64::from(east) * dlon,
            north: b.north + f64::from(north) * dlat,
        };
        let mut values = Vec::with_capacity(w as usize * h as usize);
        for row in 0..h {
            let r = i64::from(row) - i64::from(north);
            let rr = r.clamp(0, i64::from(self.height) - 1);
            for col in 0..w {
                let c = i64::from(col) - i64::from(west);
                let cc = c.clamp(0, i64::from(self.width) - 1);
                let edge = self.values[(rr * i64::from(self.width) + cc) as usize];
                // Pixels out from the map (Chebyshev), over the margin on that side.
                let out_r = (r - rr).unsigned_abs() as f32 / (if r < 0 { north } else { south }).max(1) as f32;
                let out_c = (c - cc).unsigned_abs() as f32 / (if c < 0 { west } else { east }).max(1) as f32;
                let t = out_r.max(out_c);
                let v = if t == 0.0 || !edge.is_finite() { edge } else { edge.min(edge + (SHORE_RIM_M - edge) * t) };
                values.push(v);
            }
        }
        Some(Map { kind: self.kind, width: w, height: h, bounds, values })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn regional(values: Vec<f32>, w: u32, h: u32, bounds: GeoBounds) -> Map {
        Map { kind: MapKind::Elevation, width: w, height: h, bounds, values }
    }

    #[test]
    fn the_shore_eases_from_the_edge_to_the_rim() {
        // 2x2 pixels of 1° at 10..12°E, 40..42°N; the east column is sea.
        let b = GeoBounds { west: 10.0, south: 40.0, east: 12.0, north: 42.0 };
        let m = regional(vec![1000.0, -20.0, 400.0, -20.0], 2, 2, b);
        let s = m.with_shore(4).unwrap();
        assert_eq!((s.width, s.height), (10, 10));
        assert_eq!(s.bounds, GeoBounds { west: 6.0, south: 36.0, east: 16.0, north: 46.0 });
        // The map itself is unchanged inside its bounds.
        assert_eq!(s.sample(41.5, 10.5), Some(1000.0));
        assert_eq!(s.sample(40.5, 11.5), Some(-20.0));
        // West of the 1000 m pixel, a quarter of the way down per pixel; the rim at the shelf.
        let row: Vec<f32> = (0..5).map(|c| s.values[4 * 10 + c]).collect();
        assert_eq!(row, vec![-150.0, 137.5, 425.0, 712.5, 1000.0]);
        // A sea pixel never rises; corners take the farther of the two ways out.
        assert!(s.values[4 * 10 + 9] <= -20.0);
        assert_eq!(s.values[0], -150.0);
        // The rim is below sea level all round.
        let rim = (0..10).flat_map(|i| [i, 90 + i, i * 10, i * 10 + 9]);
        assert!(rim.map(|i| s.values[i]).all(|v| v == -150.0));
    }

    #[test]
    fn the_globe_limits_the_margin() {
        // A map touching 180°E and 90°N widens only west and south.
        let b = GeoBounds { west: 170.0, south: 80.0, east: 180.0, north: 90.0 };
        let m = regional(vec![500.0; 4], 2, 2, b);
        let s = m.with_shore(3).unwrap();
        assert_eq!(s.bounds, GeoBounds { west: 155.0, south: 65.0, east: 180.0, north: 90.0 });
        s.bounds.validate().unwrap();
        // A map spanning nearly all longitudes keeps under a full turn.
        let b = GeoBounds { west: -179.0, south: 0.0, east: 179.0, north: 10.0 };
        let s = regional(vec![500.0; 2], 2, 1, b).with_shore(5).unwrap();
        assert!(s.bounds.east - s.bounds.west < 360.0 && !s.bounds.is_global(), "{:?}", s.bounds);
        // Global maps and continent bitmaps are left alone.
        let g = regional(vec![1.0; 2], 2, 1, GeoBounds::GLOBE);
        assert!(g.with_shore(4).is_none());
        let bitmap = Map { kind: MapKind::Continents, ..m };
        assert!(bitmap.with_shore(4).is_none());
    }
}
