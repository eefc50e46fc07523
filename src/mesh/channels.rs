//! River channels at their true width: the channel width (m) of the base mesh's rivers, looked
//! up by position for any river vertex of any mesh refined from it (the width of the nearest
//! base-mesh river vertex), so that the water surface of views, tiles and renders covers a
//! river's channel rather than every face beside it (`export/water.rs`).
//!
//! Widths come from the discharge of the planet's climate by hydraulic geometry
//! (`planet/network.rs`: Leopold & Maddock, `w = 3.5 Q^0.51`); a river that does not flow all
//! year (a wadi) has width 0, a dry bed.

use crate::geo::Buckets;
use glam::DVec3;

/// Widths of the base mesh's river vertices, bucketed on a latitude/longitude grid whose cells
/// are about as wide as a typical base-mesh river edge ([`crate::geo::Buckets`]); a lookup
/// searches outwards from its cell until no unsearched cell can hold a nearer point, up to the
/// longest river edge.
#[derive(Clone, Debug, PartialEq)]
pub struct Channels {
    /// Farthest a point still gives its width, in degrees of arc.
    reach_deg: f64,
    /// The widest channel (m).
    widest: f32,
    points: Buckets<([f64; 3], f32)>,
}

impl Channels {
    /// Channels of river vertices at unit directions `points` with their widths (m); `cell_m`
    /// is the grid's cell size (a typical base-mesh river edge), `reach_m` the farthest a
    /// vertex still takes a point's width (the longest one), `radius` the planet's. `None`
    /// without points.
    pub fn new(points: &[(DVec3, f32)], cell_m: f64, reach_m: f64, radius: f64) -> Option<Channels> {
        if points.is_empty() {
            return None;
        }
        // Cells of at least 1/256 of the reach: a lookup searches at most ~257 rings of them.
        // (A 90 m regional map's rivers have 88 m median edges: its 200,000 points were
        // bucketed on 1.1 km cells, the grid's floor then, ~150 to a cell, and a lookup read
        // over a thousand.)
        let cell_deg = (cell_m.max(reach_m / 256.0) / radius).to_degrees();
        let items = points.iter().map(|&(d, w)| (d, (d.normalize().to_array(), w))).collect();
        let widest = points.iter().map(|&(_, w)| w).fold(0.0, f32::max);
        let points = Buckets::new(cell_deg, items);
        let reach_deg = (reach_m / radius).to_degrees().max(points.cell_deg());
        Some(Channels { reach_deg, widest, points })
    }

    /// Width (m) of the base-mesh river vertex nearest to `dir` (a unit direction), if one lies
    /// within the reach given to [`Channels::new`]; ties go to the first stored.
    pub fn width_at(&self, dir: DVec3) -> Option<f32> {
        let g = &self.points;
        let (cell_deg, rows, cols) = (g.cell_deg(), g.rows(), g.cols());
        let (row, col) = g.row_col(dir);
        let lat = (row as f64 + 0.5) * cell_deg - 90.0;
        let chord = |deg: f64| (deg.to_radians() * 0.5).sin() * 2.0;
        let max_chord = chord(self.reach_deg);
        let mut best: Option<(f64, f32)> = None;
        let rings = (self.reach_deg / cell_deg).ceil() as usize + 1;
        for k in 1..=rings {
            // Rows within k cells; columns spanning k cells' width at the widest latitude.
            let edge_lat = lat.abs() + (k as f64 + 0.5) * cell_deg;
            let span = if edge_lat >= 89.0 {
                cols
            } else {
                ((k as f64 / edge_lat.to_radians().cos()).ceil() as usize).min(cols)
            };
            let ranges = g.column_ranges(col, span);
            for r in row.saturating_sub(k)..=(row + k).min(rows - 1) {
                for &(c0, c1) in ranges.iter().filter(|(c0, c1)| c0 <= c1) {
                    for &(p, w) in g.row_items(r, c0, c1) {
                        let d = DVec3::from_array(p).distance(dir);
                        if d <= max_chord && best.is_none_or(|(bd, _)| d < bd) {
                            best = Some((d, w));
                        }
                    }
                }
            }
            // Any cell not yet searched lies at least k - 1 cells away.
            if best.is_some_and(|(d, _)| d <= chord((k - 1) as f64 * cell_deg)) {
                break;
            }
        }
        best.map(|(_, w)| w)
    }

    /// The widest channel (m).
    pub fn widest(&self) -> f32 {
        self.widest
    }

    /// The widest channel (m) a vertex within `angle` (radians) of unit direction `dir` can
    /// take by [`Channels::width_at`]: the widest point within that angle plus the reach; 0
    /// where none.
    pub fn widest_near(&self, dir: DVec3, angle: f64) -> f32 {
        self.widest_near_under(dir, angle, f32::INFINITY)
    }

    /// [`Channels::widest_near`] among the channels no wider than `cap` (m).
    pub fn widest_near_under(&self, dir: DVec3, angle: f64, cap: f32) -> f32 {
        self.widest_within(dir, angle.to_degrees() + self.reach_deg, cap)
    }

    /// The widest of the points (m) within `within_deg` degrees of arc of unit direction `dir`
    /// and no wider than `cap`, the reach not added; 0 where none.
    pub fn widest_within(&self, dir: DVec3, within_deg: f64, cap: f32) -> f32 {
        let g = &self.points;
        let (cell_deg, rows, cols) = (g.cell_deg(), g.rows(), g.cols());
        if within_deg >= 180.0 && self.widest <= cap {
            return self.widest;
        }
        let max_chord = if within_deg >= 180.0 { f64::INFINITY } else { (within_deg.to_radians() * 0.5).sin() * 2.0 };
        let (row, col) = g.row_col(dir);
        let k = (within_deg / cell_deg).ceil() as usize + 1;
        let edge_lat = crate::geo::lat_lon(dir).0.abs() + (k as f64 + 0.5) * cell_deg;
        let span =
            if edge_lat >= 89.0 { cols } else { ((k as f64 / edge_lat.to_radians().cos()).ceil() as usize).min(cols) };
        let ranges = g.column_ranges(col, span);
        let mut widest = 0.0f32;
        for r in row.saturating_sub(k)..=(row + k).min(rows - 1) {
            for &(c0, c1) in ranges.iter().filter(|(c0, c1)| c0 <= c1) {
                for &(p, w) in g.row_items(r, c0, c1) {
                    if w <= cap && DVec3::from_array(p).distance(dir) <= max_chord {
                        widest = widest.max(w);
                    }
                }
            }
        }
        widest
    }

    /// Bytes held.
    pub fn bytes(&self) -> usize {
        self.points.bytes()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geo::direction;

    #[test]
    fn the_nearest_river_vertex_gives_the_width() {
        let r = 6_371_000.0;
        let pts = [(direction(0.0, 0.0), 100.0), (direction(0.0, 1.0), 300.0), (direction(60.0, 179.9), 7.0)];
        let c = Channels::new(&pts, 50_000.0, 150_000.0, r).unwrap();
        assert_eq!(c.width_at(direction(0.0, 0.3)), Some(100.0));
        assert_eq!(c.width_at(direction(0.2, 0.7)), Some(300.0));
        // Across the antimeridian, and nothing where no river is near.
        assert_eq!(c.width_at(direction(60.1, -179.8)), Some(7.0));
        assert_eq!(c.width_at(direction(30.0, 30.0)), None);
        assert_eq!(c.width_at(direction(0.0, 3.0)), None);
        // Near a pole every column is searched.
        let polar = Channels::new(&[(direction(89.5, 10.0), 5.0)], 50_000.0, 150_000.0, r).unwrap();
        assert_eq!(polar.width_at(direction(89.5, -170.0)), Some(5.0));
        assert!(Channels::new(&[], 1.0, 1.0, r).is_none());
        // The widest any vertex near a point can take: the reach (150 km, 1.35°) added.
        let near = |lat: f64, lon: f64, deg: f64| c.widest_near(direction(lat, lon), f64::to_radians(deg));
        assert_eq!(near(0.0, 0.5, 0.1), 300.0);
        assert_eq!(near(0.0, -1.0, 0.1), 100.0);
        assert_eq!(near(0.0, -1.0, 0.7), 300.0);
        assert_eq!(near(0.0, -3.0, 0.1), 0.0);
        assert_eq!(near(60.0, -179.0, 0.1), 7.0);
        assert_eq!(near(-60.0, 0.0, 180.0), 300.0);
        // Among the channels no wider than a cap.
        let under = |lat: f64, lon: f64, deg: f64, cap: f32| {
            c.widest_near_under(direction(lat, lon), f64::to_radians(deg), cap)
        };
        assert_eq!(under(0.0, -1.0, 0.7, 299.0), 100.0);
        assert_eq!(under(0.0, -1.0, 0.7, 300.0), 300.0);
        assert_eq!(under(0.0, 0.5, 0.1, 50.0), 0.0);
        assert_eq!(under(-60.0, 0.0, 180.0, 200.0), 100.0);
        // Without the reach: only the points themselves within the angle.
        assert_eq!(c.widest_within(direction(0.0, 0.5), 0.6, f32::INFINITY), 300.0);
        assert_eq!(c.widest_within(direction(0.0, 0.5), 0.4, f32::INFINITY), 0.0);
        assert_eq!(c.widest_within(direction(0.0, -0.3), 0.4, f32::INFINITY), 100.0);
        for lon in [-0.3, 0.2, 0.9, 1.4] {
            let dir = direction(0.1, lon);
            assert!(c.width_at(dir).unwrap_or(0.0) <= c.widest_near(dir, 0.0));
        }
        // The nearest point wins even when a farther one lies in a nearer cell's search.
        let pair = [(direction(0.0, 0.0), 1.0), (direction(0.0, 0.9), 2.0)];
        let grid = Channels::new(&pair, 20_000.0, 150_000.0, r).unwrap();
        assert_eq!(grid.width_at(direction(0.0, 0.6)), Some(2.0));
        assert_eq!(grid.width_at(direction(0.0, 0.4)), Some(1.0));
        // A regional planet's fine grid (0.01° cells: 648 million) holds only its occupied cells.
        let fine: Vec<_> = (0..1000).map(|i| (direction(36.4, -84.2 + i as f64 * 1e-4), i as f32)).collect();
        let grid = Channels::new(&fine, 100.0, 2_000.0, r).unwrap();
        assert!(grid.bytes() < 100_000, "{} bytes", grid.bytes());
        assert_eq!(grid.width_at(direction(36.4001, -84.2 + 500.2e-4)), Some(500.0));
        assert_eq!(grid.width_at(direction(36.5, -84.2)), None);
    }
}
