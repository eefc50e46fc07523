//! Coarse colours that summarise the fine surface, like a mipmap: a vertex of a coarse 3D Tiles
//! level stands for the ground around it, not for the one point it sits on.
//!
//! A level-0 tile's vertices lie ~300 km apart; coloured by their own ground alone, each shows
//! whatever its point holds (a snowy summit, a lake bed, a coast) and the planet's first picture
//! is a speckle. Here a vertex stands for its footprint, a disc of radius `r` (half the level's
//! edge), and takes the mean colour, in linear light, of the finest surface known inside it:
//! the elevation map's cells (its guide grid, `mesh/guide.rs`) where the planet has a map —
//! the splits below the base mesh follow the map itself, while the base mesh's vertices sample
//! it box-filtered over their spacing — and the base mesh's vertices elsewhere. Each sample is
//! weighted by the area it stands for (`a`: a cell's, or a third of a vertex's faces') times
//! how much finer it is than the footprint, `max(0, 1 - rho / r)` with `rho = sqrt(a / pi)`;
//! the vertex's own colour fills the rest of the disc. A footprint many samples wide is their
//! mean; one no wider than a sample keeps the vertex's own colour (the refined surface is
//! finer there), so deep levels are unchanged and the change between levels is gradual. A map
//! cell is land above sea level (a dry depression below it, such as Qattara, counts as water).
//!
//! The samples are bucketed by latitude and longitude ([`Buckets`], cells of about their
//! spacing). A lookup visits the cells of the disc's bounding box in
//! a fixed order, so the mean is a pure function of the planet, the position and `r`: the same
//! vertex on two tiles' common border gets the same colour, bit for bit.

use crate::export::climate::{climate_colour, precipitation_mm, vertex_colour, water_colour, Palette};
use crate::export::glb::linear_rgba;
use crate::geo::Buckets;
use crate::mesh::Mesh;
use crate::params::Params;
use glam::DVec3;

/// Most guide cells along a face's side the samples take (every `side / this`-th cell beyond).
const MAX_GUIDE_SIDE: usize = 512;

/// One base vertex or map cell: unit position, the area it stands for (m²) and its colour
/// (linear, as glTF's `COLOR_0` holds it).
#[derive(Clone, Copy, Debug)]
struct Sample {
    dir: [f32; 3],
    area: f32,
    rgb: [u8; 3],
}

/// The finest surface's colours and areas, bucketed for disc means.
pub struct ColourMip {
    radius: f64,
    samples: Buckets<Sample>,
}

fn linear(srgb: [u8; 3]) -> [u8; 3] {
    let l = linear_rgba(srgb, 255);
    [l[0], l[1], l[2]]
}

impl ColourMip {
    /// The samples of `base` (its map's guide cells and its vertices beyond them), coloured with
    /// `params`' palette and sea level.
    pub fn new(base: &Mesh, params: &Params) -> ColourMip {
        let n = base.vertices.len();
        let mut area = vec![0.0f64; n];
        for t in base.triangles() {
            let [a, b, c] = t.map(|v| base.pos(v));
            let third = (b - a).cross(c - a).length() / 6.0;
            for v in t {
                area[v as usize] += third;
            }
        }
        // Where an elevation map guides the splits below the base mesh, its cells are the finest
        // surface known (the base mesh's vertices sample the map box-filtered over their
        // spacing, the splits below it the map itself): they stand for the ground there.
        let mut points: Vec<(DVec3, f64, [u8; 3])> = Vec::new();
        let guide = base.guide.as_deref();
        if let Some(g) = guide {
            let palette = Palette::of(params);
            let side = g.side as usize;
            let stride = side.div_ceil(MAX_GUIDE_SIDE);
            for (fi, f) in g.faces.iter().enumerate() {
                let (c, e, nn) = (DVec3::from_array(f.centre), DVec3::from_array(f.east), DVec3::from_array(f.north));
                for iy in (0..side).step_by(stride) {
                    for ix in (0..side).step_by(stride) {
                        let v = g.values[fi * side * side + iy * side + ix];
                        if v < -1.0e29 {
                            continue;
                        }
                        let x = f.x0 + (ix as f64 + 0.5) * f.step;
                        let y = f.y0 + (iy as f64 + 0.5) * f.step;
                        let d = (c + e * x + nn * y).normalize();
                        let cell = stride as f64 * f.step * base.radius;
                        let a = cell * cell / (1.0 + x * x + y * y).powf(1.5);
                        let alt = f64::from(v);
                        let srgb = if alt > 0.0 {
                            let (lat, lon) = crate::geo::lat_lon(d);
                            climate_colour(palette, lat, alt, precipitation_mm(base, lat, lon))
                        } else {
                            water_colour(-alt)
                        };
                        points.push((d, a, linear(srgb)));
                    }
                }
            }
        }
        for (v, &a) in area.iter().enumerate() {
            let d = base.pos(v as u32).normalize();
            if a > 0.0 && guide.is_none_or(|g| g.at(d).is_none()) {
                points.push((d, a, linear(vertex_colour(base, params, v))));
            }
        }
        // Cells about as wide as the mean spacing of the points.
        let spacing = (4.0 * std::f64::consts::PI / points.len().max(1) as f64).sqrt().to_degrees();
        let items = points
            .into_iter()
            .map(|(d, a, rgb)| (d, Sample { dir: [d.x as f32, d.y as f32, d.z as f32], area: a as f32, rgb }))
            .collect();
        ColourMip { radius: base.radius, samples: Buckets::new(spacing, items) }
    }

    /// The colour (linear RGBA, as glTF's `COLOR_0`) of a vertex at `p` (planet frame) whose own
    /// colour is `own` (linear RGBA, [`linear_rgba`] of its sRGB colour), standing for
    /// the ground within `r` metres: the weighted mean, in linear light, of the samples within
    /// `r` and of `own` over the rest of the disc (see the module's doc).
    pub fn mean(&self, p: DVec3, r: f64, own: [u8; 4]) -> [u8; 4] {
        let own_lin = [0, 1, 2].map(|i| f64::from(own[i]) / 255.0);
        let dir = p.normalize();
        let ang = (r / self.radius).min(std::f64::consts::PI);
        // The disc's area on the sphere (a spherical cap).
        let disc = 2.0 * std::f64::consts::PI * self.radius * self.radius * (1.0 - ang.cos());
        if disc.is_nan() || disc <= 0.0 || !dir.is_finite() {
            return [own[0], own[1], own[2], 255];
        }
        let max_chord = (2.0 * (ang * 0.5).sin()) as f32;
        let d = [dir.x as f32, dir.y as f32, dir.z as f32];
        let g = &self.samples;
        let lat = crate::geo::lat_lon(dir).0;
        let ang_deg = ang.to_degrees();
        let (r0, r1) = (g.row_of(lat - ang_deg), g.row_of(lat + ang_deg));
        let polar = (lat.abs() + ang_deg).min(90.0);
        let span = if polar >= 89.0 {
            g.cols()
        } else {
            (ang_deg / polar.to_radians().cos() / g.cell_deg()).ceil() as usize + 1
        };
        let ranges = g.column_ranges(g.row_col(dir).1, span.min(g.cols()));
        let (mut sum, mut covered) = ([0.0f64; 3], 0.0f64);
        for row in r0..=r1 {
            for &(c0, c1) in ranges.iter().filter(|(c0, c1)| c0 <= c1) {
                for s in g.row_items(row, c0, c1) {
                    let chord2 = (0..3).map(|i| (s.dir[i] - d[i]).powi(2)).sum::<f32>();
                    if chord2 <= max_chord * max_chord {
                        let a = f64::from(s.area);
                        let w = a * (1.0 - (a / std::f64::consts::PI).sqrt() / r).max(0.0);
                        covered += w;
                        for (acc, &c) in sum.iter_mut().zip(&s.rgb) {
                            *acc += w * f64::from(c) / 255.0;
                        }
                    }
                }
            }
        }
        let rest = (disc - covered).max(0.0);
        let total = covered + rest;
        let rgb = [0, 1, 2].map(|i| ((sum[i] + rest * own_lin[i]) / total * 255.0).round().clamp(0.0, 255.0) as u8);
        [rgb[0], rgb[1], rgb[2], 255]
    }

    /// Bytes held.
    pub fn bytes(&self) -> usize {
        self.samples.bytes()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::test_planet;
    use crate::mesh::VertexFlags;

    #[test]
    fn a_small_footprint_keeps_the_own_colour_and_a_large_one_averages() {
        let planet = test_planet();
        let params = Params::default();
        let mip = ColourMip::new(&planet.mesh, &params);
        let v = planet.mesh.vertices.iter().position(|v| v.flags.contains(VertexFlags::CONTINENT)).unwrap();
        let own = linear_rgba(vertex_colour(&planet.mesh, &params, v), 255);
        let p = planet.mesh.pos(v as u32);
        // A footprint no wider than the base mesh's vertices keeps the own colour, whatever it is.
        for r in [0.0, 1.0, 1e3] {
            let red = linear_rgba([255, 0, 0], 255);
            assert_eq!(mip.mean(p, r, red), red, "{r} m");
        }
        // A footprint the size of the planet: the area-weighted mean of every sample, the own
        // colour filling only what the coarse test planet's samples, a few hundred km wide,
        // leave (their weight is 1 - rho / r of their area: ~2 % here).
        let whole = std::f64::consts::PI * params.radius_m;
        let (mut sum, mut area) = ([0.0f64; 3], 0.0);
        for s in mip.samples.items() {
            area += f64::from(s.area);
            for (acc, &c) in sum.iter_mut().zip(&s.rgb) {
                *acc += f64::from(s.area) * f64::from(c) / 255.0;
            }
        }
        let expected = sum.map(|x| x / area * 255.0);
        let red = mip.mean(p, whole, linear_rgba([255, 0, 0], 255));
        let blue = mip.mean(-p, whole, linear_rgba([0, 0, 255], 255));
        for (got, own) in [(red, 0), (blue, 2)] {
            for i in 0..3 {
                let tol = if i == own { 8.0 } else { 2.5 };
                assert!((f64::from(got[i]) - expected[i]).abs() <= tol, "channel {i}: {got:?} vs {expected:?}");
            }
        }
        // The same query gives the same bytes.
        assert_eq!(mip.mean(p, 2e5, own), mip.mean(p, 2e5, own));
    }
}
