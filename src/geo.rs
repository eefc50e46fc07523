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

/// Items at points of the sphere, bucketed on a latitude/longitude grid of square cells (rows
/// from 90°S, columns from 180°W); only cells that hold items are stored (sorted by cell
/// number), so a fine grid over a small region costs the region's items, not the globe's.
/// Within a cell, items keep the order they were given in.
#[derive(Clone, Debug, PartialEq)]
pub struct Buckets<T> {
    cell_deg: f64,
    rows: usize,
    cols: usize,
    /// Numbers (`row * cols + col`) of the cells that hold items, ascending.
    cells: Vec<u64>,
    /// Items of `cells[i]` are `items[start[i]..start[i + 1]]`.
    start: Vec<u32>,
    items: Vec<T>,
}

impl<T> Buckets<T> {
    /// Buckets `items` at their unit directions on cells of `cell_deg` degrees (0.0001-30: 11 m
    /// to 3,300 km).
    pub fn new(cell_deg: f64, items: Vec<(DVec3, T)>) -> Buckets<T> {
        let cell_deg = cell_deg.clamp(1e-4, 30.0);
        let (rows, cols) = ((180.0 / cell_deg).ceil() as usize, (360.0 / cell_deg).ceil() as usize);
        let mut grid = Buckets { cell_deg, rows, cols, cells: Vec::new(), start: vec![0], items: Vec::new() };
        let mut keyed: Vec<(u64, usize, T)> =
            items.into_iter().enumerate().map(|(i, (d, t))| (grid.cell_of(d), i, t)).collect();
        keyed.sort_unstable_by_key(|k| (k.0, k.1));
        grid.items.reserve_exact(keyed.len());
        for (n, (cell, _, t)) in keyed.into_iter().enumerate() {
            if grid.cells.last() != Some(&cell) {
                if n > 0 {
                    grid.start.push(n as u32);
                }
                grid.cells.push(cell);
            }
            grid.items.push(t);
        }
        grid.start.push(grid.items.len() as u32);
        grid
    }

    pub fn cell_deg(&self) -> f64 {
        self.cell_deg
    }

    pub fn rows(&self) -> usize {
        self.rows
    }

    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Row of a latitude (degrees), clamped to the grid.
    pub fn row_of(&self, lat_deg: f64) -> usize {
        ((lat_deg + 90.0) / self.cell_deg).floor().clamp(0.0, (self.rows - 1) as f64) as usize
    }

    /// Row and column of the cell holding unit direction `dir`.
    pub fn row_col(&self, dir: DVec3) -> (usize, usize) {
        let (lat, lon) = lat_lon(dir);
        let col = ((lon + 180.0) / self.cell_deg).floor().rem_euclid(self.cols as f64) as usize;
        (self.row_of(lat), col)
    }

    fn cell_of(&self, dir: DVec3) -> u64 {
        let (r, c) = self.row_col(dir);
        (r * self.cols + c) as u64
    }

    /// The items of row `r`'s cells in columns `c0..=c1`.
    pub fn row_items(&self, r: usize, c0: usize, c1: usize) -> &[T] {
        let base = (r * self.cols) as u64;
        let lo = self.cells.partition_point(|&c| c < base + c0 as u64);
        let hi = self.cells.partition_point(|&c| c <= base + c1 as u64);
        &self.items[self.start[lo] as usize..self.start[hi] as usize]
    }

    /// The columns within `span` of column `col`, as at most two ranges `(c0, c1)` without
    /// wrapping (all columns, one range, or two across the antimeridian; an unused one is
    /// `(1, 0)`, empty).
    pub fn column_ranges(&self, col: usize, span: usize) -> [(usize, usize); 2] {
        let cols = self.cols;
        let first = (col + cols - span % cols) % cols;
        if 2 * span + 1 >= cols {
            [(0, cols - 1), (1, 0)]
        } else if first + 2 * span < cols {
            [(first, first + 2 * span), (1, 0)]
        } else {
            [(first, cols - 1), (0, first + 2 * span - cols)]
        }
    }

    /// Every item, cell by cell.
    pub fn items(&self) -> &[T] {
        &self.items
    }

    /// Bytes held.
    pub fn bytes(&self) -> usize {
        self.cells.len() * 8 + self.start.len() * 4 + self.items.len() * std::mem::size_of::<T>()
    }
}
