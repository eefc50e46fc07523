//! The base mesh's faces binned by latitude and longitude, so that sampling a small region of a
//! large planet (a DEM, an elevation or terrain tile) looks at the faces near it instead of all
//! of them.
//!
//! A face is listed in every cell its bounds meet, widened by [`DESCENDANT_REACH`] of its
//! longest edge: the faces that splits below it make stay inside that. (It was half the edge,
//! on the belief that eq. 2 moves a split's vertex off its edge by far less than the edge; it
//! may move it about 0.19 of it.) [`FaceIndex::candidates`] is therefore a superset of the faces
//! and descendants that meet a rectangle; callers still test each candidate.

use crate::maps::GeoBounds;
use crate::mesh::raster::triangle_bounds;
use crate::mesh::split::position::DESCENDANT_REACH;
use crate::mesh::Mesh;

/// Faces binned on a grid of square cells in degrees.
pub struct FaceIndex {
    /// Cell side in degrees (180 / `rows`).
    cell: f64,
    rows: usize,
    cols: usize,
    /// Faces of cell `k` are `faces[start[k]..start[k + 1]]`, ascending.
    start: Vec<u32>,
    faces: Vec<u32>,
    /// Faces of the indexed mesh (faces at or past this index are a refinement's).
    base_faces: usize,
    /// The longest edge of its faces, as a chord of the unit sphere.
    longest: f64,
}

impl FaceIndex {
    /// Indexes the faces of `mesh`, on cells about twice its mean edge length.
    ///
    /// On one thread: the index is made inside a `OnceLock` that threads of rayon's pool may be
    /// the first to reach (a terrain tile's rows); a parallel loop there lets the waiting
    /// thread take up another job that reaches the same lock, which then never opens.
    pub fn new(mesh: &Mesh) -> FaceIndex {
        let n = mesh.faces.len().max(1) as f64;
        // Mean edge of equilateral faces tiling the sphere, in degrees.
        let edge = (4.0 * std::f64::consts::PI / n * 4.0 / 3f64.sqrt()).sqrt().to_degrees();
        let rows = ((180.0 / (2.0 * edge)).floor() as usize).clamp(1, 720);
        let (cell, cols) = (180.0 / rows as f64, 2 * rows);
        let mut pairs: Vec<(u32, u32)> = Vec::new();
        let mut longest_edge = 0f64;
        for f in 0..mesh.faces.len() {
            let u = mesh.corners(f as u32).map(|v| mesh.pos(v).normalize());
            let nrm = [u[1].cross(u[2]), u[2].cross(u[0]), u[0].cross(u[1])];
            let (lo, hi, lon) = triangle_bounds(u, &nrm);
            let longest = u[0].distance(u[1]).max(u[1].distance(u[2])).max(u[2].distance(u[0]));
            longest_edge = longest_edge.max(longest);
            let pad = DESCENDANT_REACH * longest.to_degrees();
            let row = |lat: f64| (((90.0 - lat) / cell).floor().max(0.0) as usize).min(rows - 1);
            let (r0, r1) = (row(hi + pad), row(lo - pad));
            for r in r0..=r1 {
                // Longitudes shrink towards the poles: widen by the pad at the row's poleward side.
                let polar = (90.0 - r as f64 * cell).abs().max((90.0 - (r + 1) as f64 * cell).abs());
                let squeeze = polar.min(89.0).to_radians().cos();
                let cells: Box<dyn Iterator<Item = usize>> = match lon {
                    Some((a, b)) if (b - a) + 2.0 * pad / squeeze < 180.0 => {
                        let widen = pad / squeeze;
                        let c0 = ((a - widen + 180.0) / cell).floor() as i64;
                        let c1 = ((b + widen + 180.0) / cell).floor() as i64;
                        Box::new((c0..=c1).map(move |c| c.rem_euclid(cols as i64) as usize))
                    }
                    _ => Box::new(0..cols),
                };
                for c in cells {
                    pairs.push(((r * cols + c) as u32, f as u32));
                }
            }
        }
        pairs.sort_unstable();
        pairs.dedup();
        let mut start = vec![0u32; rows * cols + 1];
        for &(k, _) in &pairs {
            start[k as usize + 1] += 1;
        }
        for k in 0..rows * cols {
            start[k + 1] += start[k];
        }
        let faces = pairs.into_iter().map(|(_, f)| f).collect();
        FaceIndex { cell, rows, cols, start, faces, base_faces: mesh.faces.len(), longest: longest_edge }
    }

    /// The longest edge of the indexed mesh's faces, as a chord of the unit sphere.
    pub fn longest_edge(&self) -> f64 {
        self.longest
    }

    /// Bytes held.
    pub fn bytes(&self) -> usize {
        4 * (self.start.len() + self.faces.len())
    }

    /// Faces of the indexed mesh that may meet `rect` (longitudes may run past ±180°), ascending,
    /// followed by the faces a refinement of it added (`base_faces..faces`).
    pub fn candidates(&self, rect: &GeoBounds, faces: usize) -> Vec<u32> {
        let row = |lat: f64| (((90.0 - lat) / self.cell).floor().max(0.0) as usize).min(self.rows - 1);
        let (r0, r1) = (row(rect.north), row(rect.south));
        let (c0, c1) =
            (((rect.west + 180.0) / self.cell).floor() as i64, ((rect.east + 180.0) / self.cell).floor() as i64);
        let all_cols = c1 - c0 + 1 >= self.cols as i64;
        let mut out = Vec::new();
        for r in r0..=r1 {
            let mut push = |c: usize| {
                let k = r * self.cols + c;
                out.extend_from_slice(&self.faces[self.start[k] as usize..self.start[k + 1] as usize]);
            };
            if all_cols {
                (0..self.cols).for_each(&mut push);
            } else {
                (c0..=c1).for_each(|c| push(c.rem_euclid(self.cols as i64) as usize));
            }
        }
        out.sort_unstable();
        out.dedup();
        out.extend(self.base_faces as u32..faces as u32);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::test_planet;
    use crate::geo::lat_lon;
    use glam::DVec3;

    #[test]
    fn candidates_hold_every_face_that_meets_a_rectangle() {
        let mesh = &test_planet().mesh;
        let index = FaceIndex::new(mesh);
        for rect in [
            GeoBounds { west: 10.0, south: 40.0, east: 12.0, north: 41.0 },
            GeoBounds { west: -185.0, south: -10.0, east: -170.0, north: 5.0 },
            GeoBounds { west: 60.0, south: 70.0, east: 170.0, north: 90.5 },
            GeoBounds { west: -180.0, south: -90.0, east: 180.0, north: 90.0 },
        ] {
            let got = index.candidates(&rect, mesh.faces.len());
            assert!(got.windows(2).all(|w| w[0] < w[1]));
            // Each face with a corner or its centre inside the rectangle is listed.
            let inside = |d: DVec3| {
                let (lat, lon) = lat_lon(d);
                let lon = if lon < rect.west {
                    lon + 360.0
                } else if lon > rect.east {
                    lon - 360.0
                } else {
                    lon
                };
                (rect.south..=rect.north).contains(&lat) && (rect.west..=rect.east).contains(&lon)
            };
            let mut meeting = 0;
            for f in 0..mesh.faces.len() as u32 {
                let p = mesh.corners(f).map(|v| mesh.pos(v).normalize());
                if p.iter().any(|&d| inside(d)) || inside((p[0] + p[1] + p[2]).normalize()) {
                    meeting += 1;
                    assert!(got.binary_search(&f).is_ok(), "face {f} meets {rect:?} but is not listed");
                }
            }
            assert!(meeting > 0, "{rect:?}");
            // A small rectangle lists a small part of the planet.
            if rect.east - rect.west < 20.0 {
                assert!(got.len() < mesh.faces.len() / 10, "{} of {}", got.len(), mesh.faces.len());
            }
        }
        // Faces a refinement added are always listed.
        let rect = GeoBounds { west: 0.0, south: 0.0, east: 1.0, north: 1.0 };
        let got = index.candidates(&rect, mesh.faces.len() + 3);
        assert_eq!(
            &got[got.len() - 3..],
            &[mesh.faces.len() as u32, mesh.faces.len() as u32 + 1, mesh.faces.len() as u32 + 2]
        );
    }
}
