//! Sample a mesh on a latitude/longitude grid: for each cell centre of a grid over some
//! bounds (the whole sphere for the equirectangular rasters), the face holding it and weights.
//!
//! **Grid.** `width x height` pixels cover the bounds (the whole sphere by default): row 0
//! touches the north edge, column 0 the west edge, and pixel `(col, row)` is sampled at its
//! centre, longitude `west + (col + 0.5) * (east - west) / width` and latitude `north - (row +
//! 0.5) * (north - south) / height` (on the globe `-180 + (col + 0.5) * 360 / width` and `90 -
//! (row + 0.5) * 180 / height`).
//!
//! **Face search.** Every face is visited once (in parallel). Its latitude range comes from its
//! corners and the poleward bulge of its great-circle edges; its longitude range is the smallest
//! interval holding its corners, or all longitudes when it contains or nears a pole (so faces
//! across the antimeridian are handled by unwrapping). Each candidate pixel direction `d` is then
//! tested exactly against the three planes through the planet centre and each edge: `d` lies in
//! face `(A, B, C)` when `d·(B×C)`, `d·(C×A)` and `d·(A×B)` are all `>= 0`. A shared edge's plane
//! normal is computed from the same two vertices with opposite signs, which floating point keeps
//! exactly antisymmetric, so a pixel on an edge is claimed by at least one of its two faces; ties
//! go to the smallest face id. The three products, normalised, are also the barycentric weights
//! of the point where the ray along `d` meets the (planar) face, so values interpolate linearly
//! on the mesh's triangles. A pixel no face claims (only possible through rounding at a vertex,
//! or on an invalid mesh) takes the face it lies least outside of, found by a full scan.

use super::{Mesh, NONE};
use crate::geo::lat_lon;
use crate::maps::GeoBounds;
use glam::DVec3;
use rayon::prelude::*;
use std::sync::atomic::{AtomicU32, Ordering};

/// For each pixel of an equirectangular grid, the mesh face that holds its centre direction and
/// the barycentric weights of that face's corners `v[0], v[1], v[2]`.
#[derive(Clone, Debug, PartialEq)]
pub struct SphereRaster {
    /// What the grid covers (the globe for [`SphereRaster::new`]).
    pub bounds: GeoBounds,
    pub width: u32,
    pub height: u32,
    /// Face per pixel, row-major from the north-west corner.
    pub faces: Vec<u32>,
    /// Weights of the face's corners per pixel; non-negative, summing to 1.
    pub weights: Vec<[f32; 3]>,
}

/// Edge-plane normals `B×C, C×A, A×B` of a face (planet frame, unnormalised).
pub(crate) fn edge_planes(mesh: &Mesh, f: usize) -> [DVec3; 3] {
    let [a, b, c] = mesh.corners(f as u32).map(|v| mesh.pos(v));
    [b.cross(c), c.cross(a), a.cross(b)]
}

#[inline]
pub(crate) fn inside(n: &[DVec3; 3], d: DVec3) -> bool {
    d.dot(n[0]) >= 0.0 && d.dot(n[1]) >= 0.0 && d.dot(n[2]) >= 0.0
}

/// Wraps a longitude difference into (-180, 180].
pub(crate) fn wrap180(d: f64) -> f64 {
    let w = (d + 180.0).rem_euclid(360.0) - 180.0;
    if w == -180.0 {
        180.0
    } else {
        w
    }
}

/// Latitude range `[lo, hi]` and longitude interval (`None` = all longitudes) of a face.
pub(crate) fn face_bounds(mesh: &Mesh, f: usize, n: &[DVec3; 3]) -> (f64, f64, Option<(f64, f64)>) {
    triangle_bounds(mesh.corners(f as u32).map(|v| mesh.pos(v).normalize()), n)
}

/// [`face_bounds`] of the triangle with unit corner directions `u` and edge planes `n`.
pub(crate) fn triangle_bounds(u: [DVec3; 3], n: &[DVec3; 3]) -> (f64, f64, Option<(f64, f64)>) {
    let mut lo = 90.0f64;
    let mut hi = -90.0f64;
    for p in &u {
        let lat = p.z.clamp(-1.0, 1.0).asin().to_degrees();
        lo = lo.min(lat);
        hi = hi.max(lat);
    }
    // Poleward bulge of each edge arc a -> b: the highest (lowest) point of its great circle,
    // when it lies between a and b.
    for k in 0..3 {
        let (a, b) = (u[k], u[(k + 1) % 3]);
        let m = a.cross(b);
        if m.length_squared() < 1e-30 {
            continue;
        }
        let m = m.normalize();
        let top = DVec3::Z - m * m.z;
        if top.length_squared() < 1e-30 {
            continue;
        }
        let top = top.normalize();
        for q in [top, -top] {
            if a.cross(q).dot(m) >= 0.0 && q.cross(b).dot(m) >= 0.0 {
                let lat = q.z.clamp(-1.0, 1.0).asin().to_degrees();
                lo = lo.min(lat);
                hi = hi.max(lat);
            }
        }
    }
    let near = |d: DVec3| n.iter().all(|m| d.dot(*m) >= -1e-9 * m.length());
    if near(DVec3::Z) {
        hi = 90.0;
    }
    if near(-DVec3::Z) {
        lo = -90.0;
    }
    if hi > 89.5 || lo < -89.5 {
        return (lo, hi, None);
    }
    let la = lat_lon(u[0]).1;
    let lb = la + wrap180(lat_lon(u[1]).1 - la);
    let lc = la + wrap180(lat_lon(u[2]).1 - la);
    if (lc - lb).abs() >= 179.0 {
        return (lo, hi, None);
    }
    (lo, hi, Some((la.min(lb).min(lc), la.max(lb).max(lc))))
}

impl SphereRaster {
    /// Finds the face and weights of every pixel of the whole sphere. Panics if `width` or
    /// `height` is 0.
    pub fn new(mesh: &Mesh, width: u32, height: u32) -> SphereRaster {
        SphereRaster::new_in(mesh, GeoBounds::GLOBE, width, height)
    }

    /// The same for a grid of `width x height` cells over `bounds` (pixel centres as for the
    /// globe: cell `(col, row)` at `west + (col + 0.5) dx`, `north - (row + 0.5) dy`).
    pub fn new_in(mesh: &Mesh, bounds: GeoBounds, width: u32, height: u32) -> SphereRaster {
        assert!(width > 0 && height > 0, "raster needs at least one pixel");
        let (w, h) = (width as usize, height as usize);
        let (span_x, span_y) = (bounds.east - bounds.west, bounds.north - bounds.south);
        let global = bounds.spans_all_longitudes();
        let rows: Vec<(f64, f64)> = (0..height).map(|r| bounds.lat_of(r, height).to_radians().sin_cos()).collect();
        let cols: Vec<(f64, f64)> = (0..width).map(|c| bounds.lon_of(c, width).to_radians().sin_cos()).collect();
        let dir = |c: usize, r: usize| {
            let ((sl, cl), (so, co)) = (rows[r], cols[c]);
            DVec3::new(cl * co, cl * so, sl)
        };
        let owner: Vec<AtomicU32> = (0..w * h).map(|_| AtomicU32::new(NONE)).collect();
        const EPS: f64 = 1e-7;
        (0..mesh.faces.len()).into_par_iter().for_each(|f| {
            let n = edge_planes(mesh, f);
            let (lo, hi, lon) = face_bounds(mesh, f, &n);
            let r0 = ((bounds.north - hi - EPS) * h as f64 / span_y - 0.5).ceil().max(0.0);
            let r1 = ((bounds.north - lo + EPS) * h as f64 / span_y - 0.5).floor().min(h as f64 - 1.0);
            if r1 < r0 {
                return;
            }
            // Column ranges: on the globe columns wrap; a regional grid clips, and tries the
            // face's interval a turn either way too, as its longitudes may be unwrapped past ±180°.
            let all = (0, w as i64 - 1);
            let columns = |turn: f64, (a, b): (f64, f64)| {
                let c0 = ((a + turn - EPS - bounds.west) * w as f64 / span_x - 0.5).ceil() as i64;
                let c1 = ((b + turn + EPS - bounds.west) * w as f64 / span_x - 0.5).floor() as i64;
                (c0, c1)
            };
            let none = (0, -1);
            let ranges = match lon {
                None => [all, none, none],
                Some(ab) if global => {
                    let (c0, c1) = columns(0.0, ab);
                    [if c1 - c0 + 1 >= w as i64 { all } else { (c0, c1) }, none, none]
                }
                Some(ab) => [0.0, -360.0, 360.0].map(|turn| {
                    let (c0, c1) = columns(turn, ab);
                    (c0.max(0), c1.min(w as i64 - 1))
                }),
            };
            for r in r0 as usize..=r1 as usize {
                for &(c0, c1) in &ranges {
                    for c in c0..=c1 {
                        let c = c.rem_euclid(w as i64) as usize;
                        if inside(&n, dir(c, r)) {
                            owner[r * w + c].fetch_min(f as u32, Ordering::Relaxed);
                        }
                    }
                }
            }
        });
        let faces: Vec<u32> = owner.into_iter().map(AtomicU32::into_inner).collect();
        let mut out = SphereRaster { bounds, width, height, faces, weights: vec![[0.0; 3]; w * h] };
        out.faces.par_chunks_mut(w).zip(out.weights.par_chunks_mut(w)).enumerate().for_each(|(r, (fs, ws))| {
            for c in 0..w {
                let d = dir(c, r);
                if fs[c] == NONE {
                    fs[c] = least_outside(mesh, d);
                }
                ws[c] = weights(&edge_planes(mesh, fs[c] as usize), d);
            }
        });
        out
    }

    /// Latitude (degrees) of a row's pixel centres on the globe.
    pub fn lat_of(row: u32, height: u32) -> f64 {
        GeoBounds::GLOBE.lat_of(row, height)
    }

    /// Longitude (degrees) of a column's pixel centres on the globe.
    pub fn lon_of(col: u32, width: u32) -> f64 {
        GeoBounds::GLOBE.lon_of(col, width)
    }

    /// Unit direction of a pixel centre, as the face search computed it.
    pub fn direction(&self, col: u32, row: u32) -> DVec3 {
        let (sl, cl) = self.bounds.lat_of(row, self.height).to_radians().sin_cos();
        let (so, co) = self.bounds.lon_of(col, self.width).to_radians().sin_cos();
        DVec3::new(cl * co, cl * so, sl)
    }

    /// Interpolates a per-vertex value at every pixel (row-major).
    pub fn interpolate(&self, mesh: &Mesh, value: impl Fn(usize) -> f64 + Sync) -> Vec<f32> {
        self.faces
            .par_iter()
            .zip(&self.weights)
            .map(|(&f, w)| {
                let v = mesh.corners(f);
                (0..3).map(|k| w[k] as f64 * value(v[k] as usize)).sum::<f64>() as f32
            })
            .collect()
    }
}

/// Normalised barycentric weights of direction `d` in a face, clamped to the face.
pub(crate) fn weights(n: &[DVec3; 3], d: DVec3) -> [f32; 3] {
    let raw = n.map(|m| d.dot(m).max(0.0));
    let sum = raw[0] + raw[1] + raw[2];
    if sum > 0.0 && sum.is_finite() {
        raw.map(|x| (x / sum) as f32)
    } else {
        [1.0 / 3.0; 3]
    }
}

/// The face `d` lies least outside of (largest smallest normalised edge-plane distance).
pub(crate) fn least_outside(mesh: &Mesh, d: DVec3) -> u32 {
    let score = |f: usize| {
        let n = edge_planes(mesh, f);
        n.iter().map(|m| d.dot(*m) / m.length().max(f64::MIN_POSITIVE)).fold(f64::INFINITY, f64::min)
    };
    let mut best = (f64::NEG_INFINITY, 0u32);
    for f in 0..mesh.faces.len() {
        let s = score(f);
        if s > best.0 {
            best = (s, f as u32);
        }
    }
    best.1
}
