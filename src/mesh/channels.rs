//! River channels at their true width: the channel width (m) of the base mesh's rivers, looked
//! up by position for any river vertex of any mesh refined from it (the width of the nearest
//! base-mesh river vertex), so that the water surface of views, tiles and renders covers a
//! river's channel rather than every face beside it (`export/water.rs`).
//!
//! Widths come from the discharge of the planet's climate by hydraulic geometry
//! (`planet/network.rs`: Leopold & Maddock, `w = 3.5 Q^0.51`); a river that does not flow all
//! year (a wadi) has width 0, a dry bed.

use glam::DVec3;

/// Widths of the base mesh's river vertices, bucketed on a latitude/longitude grid whose cells
/// are about as wide as a typical base-mesh river edge; a lookup searches outwards from its
/// cell until no unsearched cell can hold a nearer point, up to the longest river edge. Only
/// cells that hold points are stored (sorted by cell number), so a regional planet's fine grid
/// costs its rivers' size, not the globe's.
#[derive(Clone, Debug, PartialEq)]
pub struct Channels {
    /// Grid cell size in degrees, rows (from 90°S) and columns (from 180°W).
    cell_deg: f64,
    rows: usize,
    cols: usize,
    /// Farthest a point still gives its width, in degrees of arc.
    reach_deg: f64,
    /// Numbers (`row * cols + col`) of the cells that hold points, ascending.
    cells: Vec<u64>,
    /// Points of `cells[i]` are `points[start[i]..start[i + 1]]`.
    start: Vec<u32>,
    points: Vec<([f64; 3], f32)>,
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
        let cell_deg = (cell_m / radius).to_degrees().clamp(0.01, 30.0);
        let rows = (180.0 / cell_deg).ceil() as usize;
        let cols = (360.0 / cell_deg).ceil() as usize;
        let reach_deg = (reach_m / radius).to_degrees().max(cell_deg);
        let mut grid =
            Channels { cell_deg, rows, cols, reach_deg, cells: Vec::new(), start: vec![0], points: Vec::new() };
        let mut sorted: Vec<(u64, usize)> =
            points.iter().enumerate().map(|(i, (d, _))| (grid.cell_of(*d), i)).collect();
        sorted.sort_unstable();
        grid.points.reserve_exact(points.len());
        for (n, &(cell, i)) in sorted.iter().enumerate() {
            if grid.cells.last() != Some(&cell) {
                if n > 0 {
                    grid.start.push(n as u32);
                }
                grid.cells.push(cell);
            }
            let (d, w) = points[i];
            grid.points.push((d.normalize().to_array(), w));
        }
        grid.start.push(points.len() as u32);
        Some(grid)
    }

    fn row_col(&self, dir: DVec3) -> (usize, usize) {
        let (lat, lon) = crate::geo::lat_lon(dir);
        let row = ((lat + 90.0) / self.cell_deg).floor().clamp(0.0, (self.rows - 1) as f64) as usize;
        let col = ((lon + 180.0) / self.cell_deg).floor().rem_euclid(self.cols as f64) as usize;
        (row, col)
    }

    fn cell_of(&self, dir: DVec3) -> u64 {
        let (r, c) = self.row_col(dir);
        (r * self.cols + c) as u64
    }

    /// The points of row `r`'s cells in columns `c0..=c1`.
    fn row_points(&self, r: usize, c0: usize, c1: usize) -> &[([f64; 3], f32)] {
        let base = (r * self.cols) as u64;
        let lo = self.cells.partition_point(|&c| c < base + c0 as u64);
        let hi = self.cells.partition_point(|&c| c <= base + c1 as u64);
        &self.points[self.start[lo] as usize..self.start[hi] as usize]
    }

    /// Width (m) of the base-mesh river vertex nearest to `dir` (a unit direction), if one lies
    /// within the reach given to [`Channels::new`]; ties go to the first stored.
    pub fn width_at(&self, dir: DVec3) -> Option<f32> {
        let (row, col) = self.row_col(dir);
        let lat = (row as f64 + 0.5) * self.cell_deg - 90.0;
        let chord = |deg: f64| (deg.to_radians() * 0.5).sin() * 2.0;
        let max_chord = chord(self.reach_deg);
        let mut best: Option<(f64, f32)> = None;
        let rings = (self.reach_deg / self.cell_deg).ceil() as usize + 1;
        for k in 1..=rings {
            // Rows within k cells; columns spanning k cells' width at the widest latitude.
            let edge_lat = lat.abs() + (k as f64 + 0.5) * self.cell_deg;
            let span = if edge_lat >= 89.0 {
                self.cols
            } else {
                ((k as f64 / edge_lat.to_radians().cos()).ceil() as usize).min(self.cols)
            };
            // Column ranges without wrapping: all, one, or two across the antimeridian.
            let first = (col + self.cols - span % self.cols) % self.cols;
            let ranges = if 2 * span + 1 >= self.cols {
                [(0, self.cols - 1), (1, 0)]
            } else if first + 2 * span < self.cols {
                [(first, first + 2 * span), (1, 0)]
            } else {
                [(first, self.cols - 1), (0, first + 2 * span - self.cols)]
            };
            for r in row.saturating_sub(k)..=(row + k).min(self.rows - 1) {
                for &(c0, c1) in ranges.iter().filter(|(c0, c1)| c0 <= c1) {
                    for &(p, w) in self.row_points(r, c0, c1) {
                        let d = DVec3::from_array(p).distance(dir);
                        if d <= max_chord && best.is_none_or(|(bd, _)| d < bd) {
                            best = Some((d, w));
                        }
                    }
                }
            }
            // Any cell not yet searched lies at least k - 1 cells away.
            if best.is_some_and(|(d, _)| d <= chord((k - 1) as f64 * self.cell_deg)) {
                break;
            }
        }
        best.map(|(_, w)| w)
    }

    /// Bytes held.
    pub fn bytes(&self) -> usize {
        self.cells.len() * 8 + self.start.len() * 4 + self.points.len() * std::mem::size_of::<([f64; 3], f32)>()
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
