//! A DEM of any region at any resolution, as a WCS `GetCoverage` would give it: `riverworld dem`
//! and `GET /v1/planets/{id}/dem.tif`.
//!
//! **Grid.** `width x height` cells over a bounding box `W,S,E,N` (degrees), sampled at cell
//! centres ([`DemRequest::lat_of`], [`GeoBounds::lon_of`]): rows evenly spaced in latitude
//! (EPSG:4326; `height` defaults to the value that keeps cells square in degrees) or in Web
//! Mercator `y` (the elevation tiles of `terrain_rgb.rs`).
//!
//! **Surface.** The planet is refined along its bisection tree (`tiles/tree.rs`) with the same
//! reproducible split as views and tiles, below every tree node that meets the bbox, down to the
//! base mesh's leaves at least and until the node's refinement edge is no longer than
//! [`LEAF_EDGE_CELLS`] cells (of its smaller side, at most four times finer than the larger near
//! the poles) or the planet's minimum edge length. So a DEM shows the
//! surface a view at that detail shows, and two DEMs agree wherever their detail does. The bbox
//! is cut into blocks of [`BLOCK`] x [`BLOCK`] cells refined in parallel, each by its own
//! refiner, which bounds memory; every cell takes the value linearly interpolated on the
//! triangle of the refined surface under its centre.
//!
//! **Bands** (float32, metres relative to sea level): 1 `ground_m`, the ground (the sea floor
//! under the sea: the raster has no hole there); 2 `water_m`, the water surface where water
//! stands, as views draw it (`water.rs`: the sea, lakes, and rivers' channels at their width,
//! none where a channel is narrower than an eighth of the edges at its vertex, nor on a dry
//! bed), and NaN, the file's no-data value, where the ground is dry. A vertex's level depends
//! on the faces around it, so the surface is refined and flooded past the rectangle by a ring
//! of leaves: blocks and neighbouring tiles agree.
//!
//! **Channels.** A channel whose half width spans one to [`MAX_CARVE_EDGES`] of the surface's
//! target edges at its latitude floods the surface as views' channels do (`carve.rs`). Where such a channel may
//! lie near the bbox, the surface is refined past it by twice that half width and a few leaves
//! and carved; cells sample the carved ground and water. The carving of a vertex depends on the
//! mesh within that margin only, so blocks and neighbouring tiles agree. A wider channel carves
//! the cells' surface by the distance to its course (`tiles/course.rs`), refined along the river
//! alone after the surface's faces are listed (they stay the surface's own).

use super::carve::{channel_beds, lay_bed, MAX_CARVE_EDGES};
use super::cog::{write_cog, CogRaster};
use super::tiles::{leaf_vertices_from, wide_course, PlanetTiles, Refiner, ROOTS};
use super::water::water_levels;
use crate::geo::lat_lon;
use crate::maps::GeoBounds;
use crate::mesh::raster::{inside, triangle_bounds, weights, wrap180};
use crate::mesh::split::position::DESCENDANT_REACH;
use glam::DVec3;
use rayon::prelude::*;
use rustc_hash::FxHashMap as HashMap;

/// Most cells along either side of a DEM.
pub const MAX_DEM_SIDE: u32 = 8192;
/// Default most cells (width x height) of one DEM.
pub const DEFAULT_MAX_DEM_PIXELS: u64 = 4096 * 4096;
/// Longest refinement edge of the surface a DEM samples, in cells: triangles whose legs are
/// about two cells: about one vertex per cell.
pub const LEAF_EDGE_CELLS: f64 = 2.0 * std::f64::consts::SQRT_2;
/// Side of the square blocks of cells refined and sampled together.
pub const BLOCK: u32 = 512;

/// A validated request: where and how many cells.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DemRequest {
    pub bounds: GeoBounds,
    pub width: u32,
    pub height: u32,
    /// How rows divide the bounds' latitudes.
    pub rows: Rows,
}

/// How a grid's rows divide its latitudes (columns always divide longitudes evenly).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rows {
    /// Equal steps of latitude (EPSG:4326).
    Degrees,
    /// Equal steps of Web Mercator `y` (EPSG:3857 tiles: square cells).
    Mercator,
}

/// Web Mercator `y` (radians of the projection) of a latitude in degrees.
pub fn mercator_y(lat_deg: f64) -> f64 {
    lat_deg.to_radians().tan().asinh()
}

/// Latitude in degrees of a Web Mercator `y`.
pub fn mercator_lat(y: f64) -> f64 {
    y.sinh().atan().to_degrees()
}

impl DemRequest {
    /// Latitude of the centres of row `row` (fractional rows allowed).
    pub fn lat_of(&self, row: f64) -> f64 {
        let b = &self.bounds;
        let t = (row + 0.5) / f64::from(self.height);
        match self.rows {
            Rows::Degrees => b.north - t * (b.north - b.south),
            Rows::Mercator => {
                let (n, s) = (mercator_y(b.north), mercator_y(b.south));
                mercator_lat(n - t * (n - s))
            }
        }
    }

    /// The fractional row whose centre lies at latitude `lat` (the inverse of [`Self::lat_of`]).
    pub fn row_of(&self, lat: f64) -> f64 {
        self.row_map().row(lat)
    }

    /// [`Self::row_of`] with the bounds' projection computed once, for many latitudes.
    fn row_map(&self) -> RowMap {
        let b = &self.bounds;
        let (n, s) = match self.rows {
            Rows::Degrees => (b.north, b.south),
            Rows::Mercator => (mercator_y(b.north), mercator_y(b.south)),
        };
        RowMap { rows: self.rows, n, per: f64::from(self.height) / (n - s) }
    }
}

/// Latitude to fractional row of one request: its top and rows per unit of its projection.
struct RowMap {
    rows: Rows,
    n: f64,
    per: f64,
}

impl RowMap {
    /// The fractional row of latitude `lat`.
    #[inline]
    fn row(&self, lat: f64) -> f64 {
        self.row_at(self.project(lat))
    }

    /// A latitude in the rows' coordinate: degrees, or Mercator `y`.
    #[inline]
    fn project(&self, lat: f64) -> f64 {
        match self.rows {
            Rows::Degrees => lat,
            Rows::Mercator => mercator_y(lat.clamp(-89.999_999, 89.999_999)),
        }
    }

    /// The fractional row of a projected latitude.
    #[inline]
    fn row_at(&self, y: f64) -> f64 {
        (self.n - y) * self.per - 0.5
    }
}

/// Why a request is refused: the field at fault and what is wrong.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{field}: {message}")]
pub struct DemError {
    pub field: &'static str,
    pub message: String,
}

fn refuse(field: &'static str, message: String) -> DemError {
    DemError { field, message }
}

impl DemRequest {
    /// Checks a request: `bbox` as `W,S,E,N` inside -180..180 / -90..90 and not empty, sides
    /// from 1 to [`MAX_DEM_SIDE`], at most `max_pixels` cells.
    pub fn new(bbox: &str, width: u32, height: Option<u32>, max_pixels: u64) -> Result<DemRequest, DemError> {
        let bounds = GeoBounds::parse(bbox).map_err(|e| refuse("bbox", e.to_string()))?;
        let side = |field: &'static str, v: u32| {
            if (1..=MAX_DEM_SIDE).contains(&v) {
                Ok(v)
            } else {
                Err(refuse(field, format!("{v} is outside 1..={MAX_DEM_SIDE}")))
            }
        };
        let width = side("width", width)?;
        let height = match height {
            Some(h) => side("height", h)?,
            None => {
                let h = (f64::from(width) * (bounds.north - bounds.south) / (bounds.east - bounds.west)).round();
                if h > f64::from(MAX_DEM_SIDE) {
                    return Err(refuse(
                        "height",
                        format!("square cells need {h} rows, over {MAX_DEM_SIDE}: give a smaller width or a height"),
                    ));
                }
                (h as u32).max(1)
            }
        };
        let pixels = u64::from(width) * u64::from(height);
        if pixels > max_pixels {
            let field = if height > width { "height" } else { "width" };
            return Err(refuse(field, format!("{width}x{height} is {pixels} cells; at most {max_pixels} are served")));
        }
        Ok(DemRequest { bounds, width, height, rows: Rows::Degrees })
    }

    /// Cell size in degrees (longitude, latitude).
    pub fn pixel(&self) -> [f64; 2] {
        let b = &self.bounds;
        [(b.east - b.west) / f64::from(self.width), (b.north - b.south) / f64::from(self.height)]
    }

    /// Normal form, for cache keys.
    pub fn to_query(&self) -> String {
        let b = &self.bounds;
        format!("bbox={},{},{},{}&width={}&height={}", b.west, b.south, b.east, b.north, self.width, self.height)
    }
}

/// The sampled DEM: both bands row-major from the north-west corner.
pub struct Dem {
    pub request: DemRequest,
    pub ground: Vec<f32>,
    pub water: Vec<f32>,
    /// Splits made below the base mesh (all blocks together).
    pub splits: usize,
}

/// Samples the DEM of `req` from the planet with base mesh `base` and its tree.
pub fn sample_dem(tiles: &PlanetTiles, req: &DemRequest) -> Dem {
    let (w, h) = (req.width, req.height);
    let blocks: Vec<(u32, u32)> =
        (0..h.div_ceil(BLOCK)).flat_map(|by| (0..w.div_ceil(BLOCK)).map(move |bx| (bx, by))).collect();
    let done: Vec<(Block, usize)> =
        blocks.par_iter().map(|&(bx, by)| sample_block(tiles, req, bx * BLOCK, by * BLOCK)).collect();
    let mut ground = vec![0f32; (w * h) as usize];
    let mut water = vec![0f32; (w * h) as usize];
    let mut splits = 0;
    for (b, s) in done {
        splits += s;
        for r in 0..b.rows {
            let at = ((b.row0 + r) * w + b.col0) as usize;
            let from = (r * b.cols) as usize;
            ground[at..at + b.cols as usize].copy_from_slice(&b.ground[from..from + b.cols as usize]);
            water[at..at + b.cols as usize].copy_from_slice(&b.water[from..from + b.cols as usize]);
        }
    }
    Dem { request: *req, ground, water, splits }
}

/// The DEM as a two-band Cloud-Optimized GeoTIFF.
pub fn dem_tiff(dem: &Dem) -> Vec<u8> {
    let r = &dem.request;
    write_cog(&CogRaster {
        width: r.width as usize,
        height: r.height as usize,
        bands: vec![&dem.ground, &dem.water],
        names: vec!["ground_m", "water_m"],
        west: r.bounds.west,
        north: r.bounds.north,
        pixel: r.pixel(),
        nodata_nan: true,
    })
}

/// One block's cells.
struct Block {
    col0: u32,
    row0: u32,
    cols: u32,
    rows: u32,
    ground: Vec<f32>,
    water: Vec<f32>,
}

/// Refines below the tree nodes that meet the block's cells and samples them.
fn sample_block(tiles: &PlanetTiles, req: &DemRequest, col0: u32, row0: u32) -> (Block, usize) {
    let (cols, rows) = (BLOCK.min(req.width - col0), BLOCK.min(req.height - row0));
    let window = Window { col0, row0, cols, rows };
    let surface = Surface::refine(tiles, window.rect(req), req.pixel(), req.rows);
    let (ground, water) = surface.sample(req, &window, tiles.params().sea_level_m);
    let splits = surface.splits();
    (Block { col0, row0, cols, rows, ground, water }, splits)
}

/// Samples small grids from one surface, refined over `detail`'s bounds for its cells: a
/// terrain tile's heights and water mask. Every grid must lie inside `detail`'s bounds.
pub fn sample_grids(tiles: &PlanetTiles, detail: &DemRequest, grids: &[DemRequest]) -> Vec<Dem> {
    sample_grids_in(tiles, detail.bounds, detail.pixel(), detail.rows, grids)
}

/// [`sample_grids`] from the surface refined over `rect` for cells of `cell` degrees
/// (longitude, latitude) whose rows divide latitudes as `rows` does.
pub fn sample_grids_in(
    tiles: &PlanetTiles,
    rect: GeoBounds,
    cell: [f64; 2],
    rows: Rows,
    grids: &[DemRequest],
) -> Vec<Dem> {
    let surface = Surface::refine(tiles, rect, cell, rows);
    grids
        .iter()
        .map(|req| {
            let window = Window { col0: 0, row0: 0, cols: req.width, rows: req.height };
            let (ground, water) = surface.sample(req, &window, tiles.params().sea_level_m);
            Dem { request: *req, ground, water, splits: surface.splits() }
        })
        .collect()
}

/// Cells `col0..col0 + cols` x `row0..row0 + rows` of a request.
struct Window {
    col0: u32,
    row0: u32,
    cols: u32,
    rows: u32,
}

impl Window {
    /// The rectangle the window's cells cover.
    fn rect(&self, req: &DemRequest) -> GeoBounds {
        let b = &req.bounds;
        let [dx, _] = req.pixel();
        GeoBounds {
            west: b.west + f64::from(self.col0) * dx,
            east: b.west + f64::from(self.col0 + self.cols) * dx,
            north: req.lat_of(f64::from(self.row0) - 0.5),
            south: req.lat_of(f64::from(self.row0 + self.rows) - 0.5),
        }
    }
}

/// The planet refined over a rectangle for cells of a given size, and its faces there.
struct Surface<'a> {
    tiles: &'a PlanetTiles,
    /// Always `Some` until dropped (then its buffers go back to `tiles`).
    refiner: Option<Refiner<'a>>,
    /// Faces of the refined (conforming) mesh that may meet the rectangle.
    leaves: Vec<[u32; 3]>,
    /// The same faces as corners in `heights`.
    local: Vec<[u32; 3]>,
    /// Ground (carved) and water level (`water::water_levels`), m above the base sphere, of
    /// the vertices of the faces listed past the rectangle.
    heights: Vec<[f64; 2]>,
}

impl<'a> Surface<'a> {
    /// Refines below the tree nodes that meet `rect` for cells of `cell` degrees (longitude,
    /// latitude) whose rows divide latitudes as `rows` does.
    fn refine(tiles: &'a PlanetTiles, rect: GeoBounds, cell: [f64; 2], rows: Rows) -> Surface<'a> {
        let [dx, dy] = cell;
        let params = tiles.params();
        let r = params.radius_m;
        // The surface is refined past the rectangle by a margin, and its channels carved and
        // water levels taken there, so that a block or a tile carves and floods its cells as a
        // larger request would (`export/carve.rs`, `export/water.rs`).
        let carve = carve_margin(tiles, rect, cell, rows);
        let carving = grown(rect, carve.margin / r);
        let region = Region::new(carving);
        let mut refiner = tiles.refiner();
        // About one split per cell at the finest, plus the border's.
        let span = |d: f64, c: f64| ((d / c).ceil().min(1e6) as usize) + 8;
        refiner.reserve((span(rect.east - rect.west, dx) * span(rect.north - rect.south, dy)).min(1 << 20));
        // Nodes with their corners' unit vectors (a child shares two corners with its parent)
        // and which of them lie in the region (bit `i` for corner `i`).
        let unit = |refiner: &Refiner, v: u32| refiner.mesh().pos(v).normalize();
        let mut stack: Vec<([u32; 3], [DVec3; 3], u8)> = ROOTS
            .iter()
            .map(|&node| {
                let u = node.map(|v| unit(&refiner, v));
                let held = (0..3).filter(|&i| region.holds(u[i])).fold(0, |m, i| m | 1 << i);
                (node, u, held)
            })
            .collect();
        while let Some((node, u, held)) = stack.pop() {
            // A node's descendants are not inside it (eq. 2): it is passed over only when
            // nothing within DESCENDANT_REACH of its longest edge meets the region (without
            // that, base faces 90 times the cells' size were left unsplit inside regions whose
            // ancestors lay outside; at a reach of 0.3, 4 of the 528 tested terrain-tile sides
            // differ again). A node with a corner in the region meets it.
            if held == 0 {
                let longest = u[0].distance(u[1]).max(u[1].distance(u[2])).max(u[2].distance(u[0]));
                if !region.may_meet_within(&u, DESCENDANT_REACH * longest) {
                    continue;
                }
            }
            // A leaf: at least the base mesh's detail, and edges no longer than a cell where the
            // node's cells are narrowest (a function of the node and the cell size alone, so
            // that overlapping requests on one grid refine alike, whatever their blocks).
            let polar = u.iter().map(|x| x.z.abs()).fold(0.0, f64::max).min(1.0);
            let ew = dx.to_radians() * r * (1.0 - polar * polar).sqrt();
            let ns = match rows {
                Rows::Degrees => dy.to_radians() * r,
                Rows::Mercator => ew, // square cells
            };
            let target = ew.min(ns).max(0.25 * ew.max(ns)).max(params.min_edge_length_m);
            if u[1].distance(u[2]) * r <= LEAF_EDGE_CELLS * target && !refiner.base_splits(node) {
                continue;
            }
            let [a, b] = refiner.children(node);
            let um = unit(&refiner, a[0]);
            let m = u8::from(region.holds(um));
            let bit = |i: usize| (held >> i) & 1;
            stack.extend([
                (a, [um, u[0], u[1]], m | bit(0) << 1 | bit(1) << 2),
                (b, [um, u[2], u[0]], m | bit(2) << 1 | bit(0) << 2),
            ]);
        }
        // The faces of the refined (conforming) mesh that may hold a cell: a split's vertex
        // leaves the split edge (eq. 2), so a node's children cover part of the neighbour across
        // its refinement edge and the tree's nodes alone do not tile the sphere; the mesh's
        // faces do. The index lists the base faces near the rectangle and every face a split
        // added.
        let mesh = refiner.mesh();
        // Each with whether it may meet the rectangle itself (the faces the cells are sampled
        // on; the others hold the margin's vertices), from one normalisation of its corners.
        let inside = Region::new(rect);
        let (leaves, inner): (Vec<[u32; 3]>, Vec<bool>) = tiles
            .faces()
            .candidates(&carving, mesh.faces.len())
            .into_iter()
            .filter_map(|f| {
                let c = mesh.corners(f);
                let u = c.map(|v| mesh.pos(v).normalize());
                region.may_meet(&u).then(|| (c, inside.may_meet(&u)))
            })
            .unzip();
        let (mut around, triangles, _) = leaf_vertices_from(mesh, &leaves, refiner.base_vertices());
        if let Carve { margin, floods: true, course } = carve {
            let target = |dir: DVec3| leaf_target(params, cell, rows, lat_lon(dir).0);
            // Channels too wide to flood the surface carve by their distance to their course,
            // refined along the rivers after the faces are listed (the faces stay the
            // surface's own; the listed faces' corners lie within the margin of the region).
            let course = course.map_or_else(Vec::new, |widest| {
                let meets = |u: &[DVec3; 3], reach: f64| region.may_meet_within(u, reach + margin / r);
                wide_course(&mut refiner, &meets, widest, &|dir| MAX_CARVE_EDGES * target(dir))
            });
            let limits = |dir: DVec3| {
                let t = target(dir);
                (t, MAX_CARVE_EDGES * t)
            };
            for (v, ground, water) in channel_beds(&around, &triangles, Some(&limits), &course) {
                lay_bed(&mut around.vertices[v as usize], r, ground, water);
            }
        }
        // The water surface as views draw it: the sea and lakes flat at their level, rivers'
        // channels at their width, none where a channel is too narrow for the faces at it or
        // dry part of the year. Each vertex's level depends on every face around it, listed
        // here: the margin holds a ring of leaves past the rectangle's. (Before, each face with a
        // submerged corner flooded to its level: 30 % of the Jacksboro DEM's land cells at 90 m
        // were water, beside streams a few metres wide.)
        let levels = water_levels(&around, &triangles);
        let heights = around.vertices.iter().zip(levels).map(|(v, level)| [v.ground, level]).collect();
        let (leaves, local) = leaves.into_iter().zip(triangles).zip(inner).filter(|x| x.1).map(|x| x.0).unzip();
        Surface { tiles, refiner: Some(refiner), leaves, local, heights }
    }

    fn refiner(&self) -> &Refiner<'a> {
        self.refiner.as_ref().expect("a surface's refiner until dropped")
    }

    /// Splits made below the base mesh.
    fn splits(&self) -> usize {
        self.refiner().splits()
    }

    /// Ground and water (metres relative to `sea`) of the window's cells of `req`, row-major.
    fn sample(&self, req: &DemRequest, window: &Window, sea: f64) -> (Vec<f32>, Vec<f32>) {
        let Window { col0, row0, cols, rows } = *window;
        let rect = window.rect(req);
        let [dx, _] = req.pixel();
        let b = &req.bounds;
        let mesh = self.refiner().mesh();
        let leaves = &self.leaves;
        let n = (cols * rows) as usize;
        let mut ground = vec![f32::NAN; n];
        let mut water = vec![f32::NAN; n];
        let mut owned = vec![false; n];
        // Cell directions from each row's and each column's sines and cosines, made per cell
        // (a table of every cell's direction, read in the leaves' order, missed the cache).
        let lats: Vec<(f64, f64)> = (0..rows).map(|i| req.lat_of(f64::from(row0 + i)).to_radians().sin_cos()).collect();
        let lons: Vec<(f64, f64)> = (0..cols).map(|i| b.lon_of(col0 + i, req.width).to_radians().sin_cos()).collect();
        let dir = |row: u32, col: u32| {
            let ((sa, ca), (so, co)) = (lats[row as usize], lons[col as usize]);
            DVec3::new(ca * co, ca * so, sa)
        };
        let row_map = req.row_map();
        // Ground and water of cell `i` on the triangle with corners `local` in `heights` and
        // edge planes `n`: water where the level, interpolated as the ground is, stands above it.
        let heights = &self.heights;
        let sample = |d: DVec3, local: &[u32; 3], n: &[DVec3; 3]| -> (f32, f32) {
            let wgt = weights(n, d);
            let [g, level] =
                [0, 1].map(|b| (0..3).map(|k| f64::from(wgt[k]) * heights[local[k] as usize][b]).sum::<f64>());
            let water = if level > g { (level - sea) as f32 } else { f32::NAN };
            ((g - sea) as f32, water)
        };
        // Latitude, longitude and projected latitude (the rows' coordinate) of each vertex,
        // computed once: the refiner's vertices in a table of their own (not one as long as
        // the base mesh's, filled on every call), the few base-mesh corners in a map.
        let first_new = self.refiner().base_vertices();
        let mut new_corners = vec![[f64::NAN; 3]; mesh.vertices.len().saturating_sub(first_new)];
        let mut base_corners: HashMap<u32, [f64; 3]> = HashMap::default();
        let mut corner = |v: u32| {
            let at = |v: u32| {
                let (lat, lon) = lat_lon(mesh.pos(v));
                [lat, lon, row_map.project(lat)]
            };
            match (v as usize).checked_sub(first_new) {
                Some(i) => {
                    let slot = &mut new_corners[i];
                    if slot[0].is_nan() {
                        *slot = at(v);
                    }
                    *slot
                }
                None => *base_corners.entry(v).or_insert_with(|| at(v)),
            }
        };
        const EPS: f64 = 1e-7;
        // The window's own rectangle: the surface may be refined over more (a margin).
        let region = Region::new(rect);
        for (leaf, local) in leaves.iter().zip(&self.local) {
            let p = leaf.map(|v| mesh.pos(v));
            let u = p.map(DVec3::normalize);
            if !region.may_meet(&u) {
                continue;
            }
            let n = [p[1].cross(p[2]), p[2].cross(p[0]), p[0].cross(p[1])];
            let size = u[0].distance(u[1]).max(u[1].distance(u[2])).max(u[2].distance(u[0]));
            let ll = leaf.map(&mut corner);
            let (r0, r1, lon) = if size < 0.01 && ll.iter().all(|x| x[0].abs() < 89.0) {
                // A small face away from the poles: its corners' ranges, widened by how far an
                // edge's great circle bulges poleward (under (L^2 / 8) tan(lat) for an arc of L
                // radians); in Mercator rows by the bulge times the secant poleward of it
                // (cos(lat + b) >= cos(lat) - b).
                let polar = u.iter().max_by(|a, b| a.z.abs().total_cmp(&b.z.abs())).expect("three corners");
                let cos = polar.x.hypot(polar.y);
                let bulge = size * size / 8.0 * (1.0 + polar.z.abs() / cos);
                let bulge = match req.rows {
                    Rows::Degrees => bulge.to_degrees(),
                    Rows::Mercator => bulge / (cos - bulge).max(1e-9),
                };
                let la = ll[0][1];
                let (lb, lc) = (la + wrap180(ll[1][1] - la), la + wrap180(ll[2][1] - la));
                let ys = ll.map(|x| x[2]);
                let (lo, hi) = (ys[0].min(ys[1]).min(ys[2]), ys[0].max(ys[1]).max(ys[2]));
                let rows = (row_map.row_at(hi + bulge + EPS), row_map.row_at(lo - bulge - EPS));
                (rows.0, rows.1, Some((la.min(lb).min(lc), la.max(lb).max(lc))))
            } else {
                let (lo, hi, lon) = triangle_bounds(u, &n);
                (row_map.row(hi + EPS), row_map.row(lo - EPS), lon)
            };
            let r0 = ((r0 - f64::from(row0)).ceil().max(0.0)) as u32;
            let r1 = (r1 - f64::from(row0)).floor();
            if r1 < f64::from(r0) {
                continue;
            }
            let r1 = (r1 as u32).min(rows - 1);
            let mut ranges = [None; 3];
            match lon {
                None => ranges[0] = Some((0, cols - 1)),
                Some((a, z)) => {
                    for (slot, turn) in ranges.iter_mut().zip([0.0, -360.0, 360.0]) {
                        let c0 = ((a + turn - EPS - rect.west) / dx - 0.5).ceil().max(0.0);
                        let c1 = ((z + turn + EPS - rect.west) / dx - 0.5).floor().min(f64::from(cols) - 1.0);
                        *slot = (c1 >= c0).then_some((c0 as u32, c1 as u32));
                    }
                }
            }
            let ranges = ranges.into_iter().flatten();
            for row in r0..=r1 {
                for (c0, c1) in ranges.clone() {
                    for col in c0..=c1 {
                        let i = (row * cols + col) as usize;
                        if !owned[i] {
                            let d = dir(row, col);
                            if inside(&n, d) {
                                (ground[i], water[i]) = sample(d, local, &n);
                                owned[i] = true;
                            }
                        }
                    }
                }
            }
        }
        // A cell no triangle claimed (rounding on an edge or corner): the leaf it lies least outside.
        for i in 0..n {
            if !owned[i] {
                let d = dir(i as u32 / cols, i as u32 % cols);
                let planes = |leaf: &[u32; 3]| {
                    let p = leaf.map(|v| mesh.pos(v));
                    [p[1].cross(p[2]), p[2].cross(p[0]), p[0].cross(p[1])]
                };
                let score = |leaf: &[u32; 3]| {
                    let n = planes(leaf);
                    n.iter().map(|m| d.dot(*m) / m.length().max(f64::MIN_POSITIVE)).fold(f64::INFINITY, f64::min)
                };
                let best = leaves.iter().zip(&self.local).max_by(|a, b| score(a.0).total_cmp(&score(b.0)));
                if let Some((leaf, local)) = best {
                    (ground[i], water[i]) = sample(d, local, &planes(leaf));
                }
            }
        }
        (ground, water)
    }
}

impl Drop for Surface<'_> {
    fn drop(&mut self) {
        if let Some(refiner) = self.refiner.take() {
            self.tiles.recycle(refiner);
        }
    }
}

/// Where and how a surface carves ([`carve_margin`]).
#[derive(Clone, Copy, Debug)]
struct Carve {
    /// How far (m) past the rectangle the surface is refined, carved and flooded.
    margin: f64,
    /// Whether a channel near it may flood it (`export/carve.rs`).
    floods: bool,
    /// The widest channel's half width (m) near it, where channels too wide to flood the
    /// surface may carve it by their course (`tiles/course.rs`).
    course: Option<f64>,
}

/// How far (m) past `rect` a surface refined for cells of `cell` degrees must be refined,
/// carved and flooded so that its cells do not depend on where the refinement stops: two of
/// the widest leaves (a vertex's water level depends on the faces around it and its
/// neighbours', `export/water.rs`), and twice the half width of the widest channel that may
/// flood it ([`crate::export::carve`]); whether one may (not where no channel near it has a
/// half width over the finest target edge), and whether wider channels may carve it by their
/// course.
fn carve_margin(tiles: &PlanetTiles, rect: GeoBounds, [dx, dy]: [f64; 2], rows: Rows) -> Carve {
    let params = tiles.params();
    let r = params.radius_m;
    // The leaves' targets (`Surface::refine`) at the rectangle's most polar and most
    // equatorial latitudes (a degree past each for the nodes and sources reaching past it).
    let (s, n) = (rect.south.clamp(-90.0, 90.0), rect.north.clamp(-90.0, 90.0));
    let polar = s.abs().max(n.abs());
    let equatorial = if s <= 0.0 && n >= 0.0 { 0.0 } else { s.abs().min(n.abs()) };
    let target = |lat: f64| leaf_target(params, [dx, dy], rows, lat);
    let (finest, coarsest) = (target(polar + 1.0), target((equatorial - 1.0).max(0.0)));
    // Two of the widest leaves: the faces around a leaf's corners, and around their
    // neighbours, decide the corners' water levels. A leaf's edges are up to about twice its
    // refinement edge, and no longer than the base mesh's longest.
    let ring = 2.0 * (2.0 * LEAF_EDGE_CELLS * coarsest).min(tiles.faces().longest_edge() * r);
    let dry = Carve { margin: ring, floods: false, course: None };
    let Some(channels) = tiles.planet().mesh.channels.as_deref() else { return dry };
    // A channel carves where its half width is between the target at its vertex's latitude
    // and MAX_CARVE_EDGES of it (`Surface::refine`).
    let centre = crate::geo::direction(0.5 * (s + n), 0.5 * (rect.west + rect.east));
    let angle = |d: DVec3| centre.cross(d).length().atan2(centre.dot(d));
    let spread = [s, 0.5 * (s + n), n]
        .iter()
        .flat_map(|&lat| [rect.west, 0.5 * (rect.west + rect.east), rect.east].map(|lon| (lat, lon)))
        .map(|(lat, lon)| angle(crate::geo::direction(lat, lon)))
        .fold(0.0, f64::max);
    let spread = if rect.east - rect.west >= 180.0 { std::f64::consts::PI } else { spread * 1.1 };
    let near = spread + (f64::from(channels.widest()) + 2.0 * LEAF_EDGE_CELLS * coarsest) / r;
    let small = crate::export::water::SMALL_STREAM_M;
    let half = 0.5 * f64::from(channels.widest_near(centre, near).max(small));
    if half <= finest {
        return dry;
    }
    // Channels that flood are no wider than MAX_CARVE_EDGES coarsest targets.
    let cap = (2.0 * MAX_CARVE_EDGES * coarsest) as f32 * (1.0 + 1e-6);
    let flood = 0.5 * f64::from(channels.widest_near_under(centre, near, cap).max(small));
    let spread = if flood > finest { 2.0 * flood } else { 0.0 };
    Carve { margin: spread + ring, floods: true, course: (half > MAX_CARVE_EDGES * finest).then_some(half) }
}

/// The edge (m) a surface refined for cells of `cell` degrees whose rows divide latitudes as
/// `rows` does aims at (`Surface::refine`) at latitude `lat`, and the least half width of a
/// channel that carves there.
fn leaf_target(params: &crate::params::Params, [dx, dy]: [f64; 2], rows: Rows, lat: f64) -> f64 {
    let r = params.radius_m;
    let ew = dx.to_radians() * r * lat.abs().min(90.0).to_radians().cos();
    let ns = match rows {
        Rows::Degrees => dy.to_radians() * r,
        Rows::Mercator => ew,
    };
    ew.min(ns).max(0.25 * ew.max(ns)).max(params.min_edge_length_m)
}

/// `rect` grown by `angle` radians on every side (to every longitude near a pole).
fn grown(rect: GeoBounds, angle: f64) -> GeoBounds {
    let d = angle.to_degrees();
    let (south, north) = ((rect.south - d).max(-90.0), (rect.north + d).min(90.0));
    let polar = south.abs().max(north.abs());
    if polar >= 89.0 || rect.east - rect.west + 2.0 * d / polar.to_radians().cos() >= 360.0 {
        return GeoBounds { west: -180.0, east: 180.0, south, north };
    }
    let dl = d / polar.to_radians().cos();
    GeoBounds { west: rect.west - dl, east: rect.east + dl, south, north }
}

/// A block's rectangle as half-spaces: the wedge between its west and east meridians (when
/// narrower than 180°) and the slab between its latitudes.
struct Region {
    /// Normals of the meridian planes, pointing into the wedge (none when 180° or wider).
    meridians: Option<[DVec3; 2]>,
    /// `sin` of the south and north latitudes.
    z: [f64; 2],
}

impl Region {
    fn new(rect: GeoBounds) -> Region {
        let (w, e) = (rect.west.to_radians(), rect.east.to_radians());
        let meridians = (rect.east - rect.west < 180.0)
            .then(|| [DVec3::new(-w.sin(), w.cos(), 0.0), DVec3::new(e.sin(), -e.cos(), 0.0)]);
        // A grid whose cells reach past a pole (the ring of a terrain tile) reaches the pole.
        let z = |lat: f64| lat.clamp(-90.0, 90.0).to_radians().sin();
        Region { meridians, z: [z(rect.south), z(rect.north)] }
    }

    /// Whether the unit direction `x` lies in the rectangle (then a triangle with that corner
    /// meets it: [`Region::may_meet_within`] is true for it).
    #[inline]
    fn holds(&self, x: DVec3) -> bool {
        self.meridians.is_none_or(|[nw, ne]| nw.dot(x) >= 0.0 && ne.dot(x) >= 0.0)
            && x.z >= self.z[0]
            && x.z <= self.z[1]
    }

    /// Whether the spherical triangle with unit corners `u` may meet the rectangle (never
    /// false when it does). The triangle is the cone of its corners, so a plane through the
    /// centre has some of it on its inner side exactly when a corner is; against a latitude,
    /// the edges' great circles may bulge poleward past the corners by up to `L^2 / 8` for an
    /// edge of chord `L`, allowed as a margin of `L^2 / 4`.
    #[inline]
    fn may_meet(&self, u: &[DVec3; 3]) -> bool {
        self.may_meet_within(u, 0.0)
    }

    /// Whether anything within `reach` (radians, small) of the triangle may meet the
    /// rectangle: a point that far from a plane through the centre lies at most `reach` past it
    /// (as a dot product with the unit normal), and that far from a latitude at most `reach`
    /// in `z`.
    #[inline]
    fn may_meet_within(&self, u: &[DVec3; 3], reach: f64) -> bool {
        if let Some([nw, ne]) = self.meridians {
            let out = -reach;
            if u.iter().all(|x| nw.dot(*x) < out) || u.iter().all(|x| ne.dot(*x) < out) {
                return false;
            }
        }
        let size = u[0].distance_squared(u[1]).max(u[1].distance_squared(u[2])).max(u[2].distance_squared(u[0]));
        let margin = size * 0.25 + 1e-12 + reach;
        let (lo, hi) = (u[0].z.min(u[1].z).min(u[2].z), u[0].z.max(u[1].z).max(u[2].z));
        lo <= self.z[1] + margin && hi >= self.z[0] - margin
    }
}

#[cfg(test)]
#[path = "dem_tests.rs"]
mod tests;
