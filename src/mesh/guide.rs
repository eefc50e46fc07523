//! The elevation map's ground for vertices made below the base mesh's resolution.
//!
//! The base mesh of an elevation map keeps the map at its own resolution only (refinement edges
//! of a few map pixels, `build::map_edge_length`); a split of a continent edge longer than the
//! map's pixel takes its ground from the map instead of from its neighbours' mean plus noise
//! (`altitude.rs`), so views, tiles and DEMs show the map's valleys and ridges wherever it has
//! them, and add random detail only below its resolution.
//!
//! **Values.** The map's pixels are means over their areas; the guide takes the values whose
//! bilinear surface keeps those means (`Map::mean_preserving`), which recovers about half of
//! the relief a bilinear reading of the pixels flattens at two to four pixels.
//!
//! **Grid.** The map is resampled, once per planet, onto gnomonic grids: the six faces of a
//! cube for a global map, one tangent plane at the bounds' centre for a regional map. A
//! direction `d` is looked up on the face whose centre `c` it is nearest (largest `d·c`) at
//! `x = d·e / d·c`, `y = d·n / d·c` (the face's east and north axes), bilinearly between the
//! four cells around it. Every step is an addition, multiplication, division, comparison or
//! `floor`, so the WGSL twin in `split.wgsl` gets the same bits. Values are `f32` metres
//! relative to sea level; NaN where the map has no data or does not reach.

use crate::maps::{Map, MapKind};
use glam::DVec3;
use rayon::prelude::*;

/// Most cells along a face's side.
pub const MAX_SIDE: u32 = 1024;
/// How many times shorter than the map's pixel a split edge may be and still follow the
/// bend of the map's bicubic surface ([`Guide::bend`]): the bend at an edge `h` is the
/// surface's curvature times `h²`, so below a sixteenth of the pixel all the levels left add
/// about 1/256 of the bend at the pixel (under a metre where the pixel's own is 100 m), and
/// the splits that make up most of a fine DEM skip the 16 cells' lookup.
pub const BEND_REACH: f64 = 16.0;
/// A cell without data (stored instead of NaN, which shader compilers may assume away).
pub const NO_DATA: f32 = -1.0e30;

/// One gnomonic face: its centre and axes, and its grid's origin and cell size in tangent-plane
/// units. Laid out as the WGSL `GuideFace` reads it.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GuideFace {
    pub centre: [f64; 3],
    pub x0: f64,
    pub east: [f64; 3],
    pub y0: f64,
    pub north: [f64; 3],
    pub step: f64,
}

/// The map resampled for the splits.
#[derive(Clone, Debug)]
pub struct Guide {
    pub faces: Vec<GuideFace>,
    /// Cells along each side of every face.
    pub side: u32,
    /// `side * side` values per face, face after face, row-major from `(x0, y0)`.
    pub values: Vec<f32>,
    /// Splits of edges at least this long (m) follow the map: about the map's pixel.
    pub min_edge_m: f64,
}

impl PartialEq for Guide {
    fn eq(&self, other: &Guide) -> bool {
        self.faces == other.faces
            && self.side == other.side
            && self.min_edge_m.to_bits() == other.min_edge_m.to_bits()
            && self.values.iter().map(|v| v.to_bits()).eq(other.values.iter().map(|v| v.to_bits()))
    }
}

#[inline]
fn dot(a: [f64; 3], b: DVec3) -> f64 {
    (a[0] * b.x + a[1] * b.y) + a[2] * b.z
}

impl Guide {
    /// The guide of an elevation map on a planet of `radius`; None for continent bitmaps.
    pub fn from_map(map: &Map, radius: f64) -> Option<Guide> {
        if map.kind != MapKind::Elevation {
            return None;
        }
        let (dlon, dlat) = map.pixel_size_deg();
        let pixel = dlat.to_radians(); // tangent-plane units near a face's centre
        let b = map.bounds;
        // Grid cells no wider than the map's pixels in either direction (a regional map's
        // pixels are narrower east-west than north-south by the cosine of its latitude).
        let mid_lat = if b.is_global() { 0.0 } else { (b.north + b.south) * 0.5 };
        let cell = dlat.min(dlon * mid_lat.to_radians().cos()).to_radians();
        let (faces, side): (Vec<GuideFace>, u32) = if b.is_global() {
            let axes = [
                (DVec3::X, DVec3::Y, DVec3::Z),
                (DVec3::NEG_X, DVec3::NEG_Y, DVec3::Z),
                (DVec3::Y, DVec3::NEG_X, DVec3::Z),
                (DVec3::NEG_Y, DVec3::X, DVec3::Z),
                (DVec3::Z, DVec3::Y, DVec3::NEG_X),
                (DVec3::NEG_Z, DVec3::Y, DVec3::X),
            ];
            let side = ((2.0 / cell).ceil() as u32).clamp(2, MAX_SIDE);
            let faces = axes
                .iter()
                .map(|&(c, e, n)| GuideFace {
                    centre: c.to_array(),
                    east: e.to_array(),
                    north: n.to_array(),
                    x0: -1.0,
                    y0: -1.0,
                    step: 2.0 / f64::from(side),
                })
                .collect();
            (faces, side)
        } else {
            let c = crate::geo::direction((b.north + b.south) * 0.5, (b.west + b.east) * 0.5);
            let e = DVec3::Z.cross(c).try_normalize().unwrap_or(DVec3::Y);
            let n = c.cross(e);
            // The bounds' extent on the plane, from points along its border.
            let (mut lo, mut hi) = (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN));
            for i in 0..=64 {
                let t = f64::from(i) / 64.0;
                for (lat, lon) in [
                    (b.south, b.west + t * (b.east - b.west)),
                    (b.north, b.west + t * (b.east - b.west)),
                    (b.south + t * (b.north - b.south), b.west),
                    (b.south + t * (b.north - b.south), b.east),
                ] {
                    let d = crate::geo::direction(lat, lon);
                    let k = d.dot(c);
                    if k <= 0.05 {
                        return None; // wider than the plane can hold
                    }
                    let p = DVec3::new(d.dot(e) / k, d.dot(n) / k, 0.0);
                    lo = lo.min(p);
                    hi = hi.max(p);
                }
            }
            let extent = (hi.x - lo.x).max(hi.y - lo.y);
            let side = ((extent / cell).ceil() as u32 + 2).clamp(2, MAX_SIDE);
            let step = extent / f64::from(side - 2);
            let face = GuideFace {
                centre: c.to_array(),
                east: e.to_array(),
                north: n.to_array(),
                x0: lo.x - step,
                y0: lo.y - step,
                step,
            };
            (vec![face], side)
        };
        // The pixels read as means over their areas (`Map::mean_preserving`), from the map
        // box-averaged to about the grid's cells where its pixels are finer than half of them
        // (the grid cannot hold more, and a 64-Mpixel map is not copied at full size).
        let k = (faces[0].step / cell).floor().max(1.0) as u32;
        let filtered;
        let source = if k > 1 {
            filtered = map.box_filtered(k);
            &filtered
        } else {
            map
        };
        let map = &source.mean_preserving();
        // Up to 6 x 1024^2 samples, each with its own trigonometry: in parallel, in order.
        let values: Vec<f32> = (0..faces.len() as u32 * side * side)
            .into_par_iter()
            .map(|j| {
                let (f, i) = (&faces[(j / (side * side)) as usize], j % (side * side));
                let (col, row) = (i % side, i / side);
                let x = f.x0 + (f64::from(col) + 0.5) * f.step;
                let y = f.y0 + (f64::from(row) + 0.5) * f.step;
                let d = (DVec3::from(f.centre) + DVec3::from(f.east) * x + DVec3::from(f.north) * y).normalize();
                let (lat, lon) = crate::geo::lat_lon(d);
                map.sample(lat, lon).filter(|v| v.is_finite()).unwrap_or(NO_DATA)
            })
            .collect();
        Some(Guide { faces, side, values, min_edge_m: pixel * radius })
    }

    /// The face whose centre unit direction `d` is nearest.
    fn face_of(&self, d: DVec3) -> usize {
        let mut best = 0usize;
        let mut best_k = f64::MIN;
        for (i, f) in self.faces.iter().enumerate() {
            let k = dot(f.centre, d);
            if k > best_k {
                best_k = k;
                best = i;
            }
        }
        best
    }

    /// The grid index of the cell at the lower corner of the four [`Guide::at`] interpolates
    /// between for unit direction `d`, and the fractions towards the other three.
    fn cell(&self, d: DVec3) -> Option<(usize, f64, f64)> {
        let best = self.face_of(d);
        let (gx, gy) = grid(&self.faces[best], d)?;
        let side = f64::from(self.side);
        // Clamped to the cell centres (a cube face's outer half cells; a regional grid's
        // margin holds NaN, so directions beyond it find no data).
        let (gx, gy) = (gx.max(0.0).min(side - 1.0), gy.max(0.0).min(side - 1.0));
        let (ix, iy) = (gx.floor().min(side - 2.0), gy.floor().min(side - 2.0));
        let (fx, fy) = (gx - ix, gy - iy);
        let at = best * (self.side * self.side) as usize + iy as usize * self.side as usize + ix as usize;
        Some((at, fx, fy))
    }

    /// The four cells around unit direction `d` (`[v00, v10, v01, v11]`) and the fractions
    /// towards the last three, if the map has data in all four.
    fn patch(&self, d: DVec3) -> Option<([f64; 4], f64, f64)> {
        let (at, fx, fy) = self.cell(d)?;
        let s = self.side as usize;
        let v = [at, at + 1, at + s, at + s + 1].map(|i| f64::from(self.values[i]));
        (!v.iter().any(|&x| x < -1.0e29)).then_some((v, fx, fy))
    }

    /// Metres relative to sea level the map asks for in unit direction `d`, if it has data there.
    pub fn at(&self, d: DVec3) -> Option<f64> {
        let ([v00, v10, v01, v11], fx, fy) = self.patch(d)?;
        // Written out as `split.wgsl` computes it.
        let a = v00 + (v10 - v00) * fx;
        let b = v01 + (v11 - v01) * fx;
        Some(a + (b - a) * fy)
    }

    /// Whether [`Guide::bend`] bends a split of an edge `edge_len` metres long (not one
    /// [`BEND_REACH`] times shorter than the map's pixel): a caller may skip making its
    /// arguments otherwise.
    pub fn bends(&self, edge_len: f64) -> bool {
        edge_len * BEND_REACH >= self.min_edge_m
    }

    /// The bend of the map's smooth surface over a diamond below its pixel: how far a
    /// Catmull-Rom bicubic through the cells stands at the new vertex `d` above the mean of its
    /// values at the diamond's corners `[a, t, b, d]` (unit directions), as `split.wgsl`'s
    /// `guide_bend` computes it. All five points are read on `d`'s face from one cubic piece,
    /// the 4 x 4 cells around `d`'s cell (clamped to the grid), so that the sum of the bends
    /// down a cascade of splits rebuilds that surface below the map's pixel: its crests
    /// rounded up, its valleys down, where a bilinear patch is flat (0 where a cell lacks data).
    ///
    /// A split edge shorter than the pixel by more than [`BEND_REACH`] gets none: the bend
    /// falls with the square of the edge, and what it has left there is centimetres.
    pub fn bend(&self, d: DVec3, corners: [DVec3; 4], edge_len: f64) -> f64 {
        if !self.bends(edge_len) {
            return 0.0;
        }
        let best = self.face_of(d);
        let f = &self.faces[best];
        let (Some((gx, gy)), Some(ca), Some(ct), Some(cb), Some(cd)) =
            (grid(f, d), grid(f, corners[0]), grid(f, corners[1]), grid(f, corners[2]), grid(f, corners[3]))
        else {
            return 0.0;
        };
        let side = f64::from(self.side);
        let ix = gx.max(0.0).min(side - 1.0).floor().min(side - 2.0);
        let iy = gy.max(0.0).min(side - 1.0).floor().min(side - 2.0);
        let s = self.side as usize;
        let face = best * s * s;
        let mut taps = [[0.0f64; 4]; 4];
        for (j, row) in taps.iter_mut().enumerate() {
            let y = (iy + j as f64 - 1.0).max(0.0).min(side - 1.0) as usize;
            for (i, tap) in row.iter_mut().enumerate() {
                let x = (ix + i as f64 - 1.0).max(0.0).min(side - 1.0) as usize;
                let v = self.values[face + y * s + x];
                if v < -1.0e29 {
                    return 0.0;
                }
                *tap = f64::from(v);
            }
        }
        let at = |(x, y): (f64, f64)| {
            let (u, v) = (x - ix, y - iy);
            let r = taps.map(|row| catmull_rom(row, u));
            catmull_rom(r, v)
        };
        let centre = at((gx, gy));
        centre - ((at(ca) + at(cb)) * 0.5 + (at(ct) + at(cd)) * 0.5) * 0.5
    }

    /// The map's roughness within one cell at unit direction `d`: the twist of the bilinear
    /// patch [`Guide::at`] interpolates on, `|v00 + v11 - v10 - v01|` — zero on a plane however
    /// steep, large across crests, saddles and valleys (0 without data). `split.wgsl`'s
    /// `guide_twist` is its twin.
    pub fn relief_at(&self, d: DVec3) -> f64 {
        self.patch(d).map_or(0.0, |([v00, v10, v01, v11], _, _)| ((v00 + v11) - (v10 + v01)).abs())
    }
}

/// Grid coordinates of unit direction `q` on face `f` (cell centres at whole numbers); None
/// behind the face.
fn grid(f: &GuideFace, q: DVec3) -> Option<(f64, f64)> {
    let k = dot(f.centre, q);
    (k > 0.0).then(|| ((dot(f.east, q) / k - f.x0) / f.step - 0.5, (dot(f.north, q) / k - f.y0) / f.step - 0.5))
}

/// The Catmull-Rom cubic through `p[1]` (at 0) and `p[2]` (at 1), at `t` (any real: read
/// beyond the two, it extends the same cubic), written with additions only where the textbook
/// form has constants, as `split.wgsl`'s `catmull_rom`.
#[inline]
fn catmull_rom(p: [f64; 4], t: f64) -> f64 {
    let [p0, p1, p2, p3] = p;
    let a = p2 - p0;
    let b = (((p0 + p0) - (((p1 + p1) + (p1 + p1)) + p1)) + ((p2 + p2) + (p2 + p2))) - p3;
    let c = (((p1 - p2) + (p1 - p2)) + (p1 - p2)) + (p3 - p0);
    p1 + (t * (a + t * (b + t * c))) * 0.5
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geo::direction;
    use crate::maps::GeoBounds;

    const R: f64 = 6_371_000.0;

    /// A field smooth on the sphere (linear in the direction), so that resampling errors stay
    /// small against its range (±2000 m).
    fn field(lat: f64, lon: f64) -> f32 {
        (2000.0 * direction(lat, lon).dot(glam::DVec3::new(0.3, 0.5, 0.8).normalize())) as f32
    }

    fn map(w: u32, h: u32, b: GeoBounds, hole: bool) -> Map {
        let values = (0..w * h)
            .map(|i| {
                let (lat, lon) = (b.lat_of(i / w, h), b.lon_of(i % w, w));
                if hole && (lat - 45.0).abs() < 3.0 && (lon - 10.0).abs() < 3.0 {
                    f32::NAN
                } else {
                    field(lat, lon)
                }
            })
            .collect();
        Map::from_values(MapKind::Elevation, w, h, b, values).unwrap()
    }

    #[test]
    fn a_global_guide_gives_the_map_everywhere() {
        let g = Guide::from_map(&map(512, 256, GeoBounds::GLOBE, true), R).unwrap();
        assert_eq!(g.faces.len(), 6);
        assert!((g.min_edge_m - R * (180.0f64 / 256.0).to_radians()).abs() < 1e-6);
        let mut worst = 0f64;
        for i in 0..4000 {
            let lat = -89.0 + 178.0 * ((i * 7919) % 4000) as f64 / 4000.0;
            let lon = -180.0 + 360.0 * ((i * 104_729) % 4000) as f64 / 4000.0;
            let at = g.at(direction(lat, lon));
            if (lat - 45.0).abs() < 4.0 && (lon - 10.0).abs() < 4.0 {
                continue; // next to the hole
            }
            worst = worst.max((at.unwrap() - f64::from(field(lat, lon))).abs());
        }
        // Two bilinear resamplings of a field with slopes up to 2000 m per radian, over cells
        // of ~0.012 radians: errors of a few metres (the map's own cells are tall near the poles).
        assert!(worst < 10.0, "{worst} m");
        assert_eq!(g.at(direction(45.0, 10.0)), None, "no data in the hole");
    }

    #[test]
    fn the_bend_rounds_crests_up_and_valleys_down_and_leaves_planes_flat() {
        let b = GeoBounds { west: 0.0, south: 0.0, east: 2.0, north: 2.0 };
        // 0.05° pixels (5.6 km); `f` of the longitude and latitude.
        let guide = |f: &dyn Fn(f64, f64) -> f64| {
            let values = (0..1600).map(|i| f(b.lon_of(i % 40, 40), b.lat_of(i / 40, 40)) as f32).collect::<Vec<f32>>();
            Guide::from_map(&Map::from_values(MapKind::Elevation, 40, 40, b, values).unwrap(), R).unwrap()
        };
        // A diamond 0.06° across at (1°, 1°): the split edge runs north-south, `t` and `d` lie
        // east and west of it.
        let at = |lat: f64, lon: f64| direction(lat, lon);
        let (m, corners) = (at(1.0, 1.0), [at(0.97, 1.0), at(1.0, 1.03), at(1.03, 1.0), at(1.0, 0.97)]);
        let ridge = |lon: f64, _: f64| 1000.0 * (-((lon - 1.0) / 0.2).powi(2)).exp();
        // Along a crest 1,000 m high, 0.2° wide: the corners across it stand ~22 m lower, so
        // the cubic surface at the centre is ~11 m above the corners' mean.
        let crest = guide(&ridge).bend(m, corners, 5_000.0);
        assert!(crest > 5.0 && crest < 20.0, "{crest}");
        // Splits of edges far below the pixel (5.6 km / 16) skip it.
        assert_eq!(guide(&ridge).bend(m, corners, 300.0), 0.0);
        let valley = guide(&|lon, lat| -ridge(lon, lat)).bend(m, corners, 5_000.0);
        assert!((valley + crest).abs() < 0.01 * crest, "{valley} vs {crest}");
        // A plane, however steep: no bend (the cubic reproduces it; the grid's gnomonic
        // resampling bends it by centimetres).
        let plane = guide(&|lon, lat| 2_000.0 * lon - 1_000.0 * lat).bend(m, corners, 5_000.0);
        assert!(plane.abs() < 0.5, "{plane}");
        // Without data under the taps: none.
        let hole = guide(&|lon, lat| if (lon - 1.0).abs() < 0.15 && lat > 1.0 { f64::NAN } else { ridge(lon, lat) });
        assert_eq!(hole.bend(m, corners, 5_000.0), 0.0);
    }

    #[test]
    fn a_regional_guide_ends_at_its_bounds() {
        let b = GeoBounds { west: 5.0, south: 40.0, east: 15.0, north: 50.0 };
        let g = Guide::from_map(&map(200, 200, b, false), R).unwrap();
        assert_eq!(g.faces.len(), 1);
        let inside = g.at(direction(44.0, 8.0)).unwrap();
        assert!((inside - f64::from(field(44.0, 8.0))).abs() < 10.0, "{inside}");
        for (lat, lon) in [(30.0, 8.0), (44.0, 25.0), (-44.0, -170.0), (60.0, 10.0)] {
            assert_eq!(g.at(direction(lat, lon)), None, "{lat},{lon}");
        }
        // Continent bitmaps have no ground to give.
        let values = vec![1.0; 16];
        let bitmap = Map::from_values(MapKind::Continents, 4, 4, b, values).unwrap();
        assert!(Guide::from_map(&bitmap, R).is_none());
    }
}
