//! River channels carved into the ground where the mesh is finer than they are wide.
//!
//! The paper's rivers are lines: eq. 11 raises every vertex beside a river vertex to its bank,
//! so a view close to a river, whose edges beside it are far shorter than the channel is wide,
//! shows the water only in the faces around the river's own vertices (`export/water.rs`), a
//! few edges wide. Here the vertices within half the channel's width of a flowing river vertex
//! take a bed below that vertex's water level: a parabolic cross-section, as deep as hydraulic
//! geometry makes the channel (`planet/network.rs`, `0.36 Q^0.37`) on its centre line and
//! nothing at its banks. The water surface then covers them flat at the river's level, and the
//! shore lies where the banks rise above it: a 600 m river is 600 m wide seen from 2 km.
//!
//! Each vertex takes the river vertex whose channel reaches farthest past it (its half width
//! minus the distance): every channel reaches the vertices within its half width that the
//! mesh's edges connect to its river vertex through such vertices. Only channels shown as
//! water ([`super::water::shows_channel`]) and wider than an edge at their vertex carve:
//! elsewhere nothing is reached and the mesh is returned as it is. Vertices already under
//! water (the sea, lakes, a river's own channel where the split rule put them below its
//! surface) keep theirs.
//!
//! A function of the mesh near each vertex alone, without vertex ids: the same bits whichever
//! backend adapted the mesh, and the same for a part of a triangulation given a margin around
//! it (twice the widest flooding channel's half width and a ring of faces). Views and renders
//! carve the adapted mesh, 3D Tiles their cell with its surroundings (`tiles/carve.rs`), DEMs
//! and elevation tiles their refined surface past its rectangle (`dem.rs`). Tiles and DEMs far
//! finer than a channel (its half width over [`MAX_CARVE_EDGES`] of their edges) do not flood
//! it: the vertices of its course (`tiles/course.rs`) reach every vertex within their half
//! width, by the same rule.

use super::water::{channel_halves, river_level, shows_channel};
use crate::mesh::split::position::lift;
use crate::mesh::{Mesh, Vertex, VertexFlags};
use glam::DVec3;
use std::borrow::Cow;

/// `mesh` with its wide rivers' channels carved (see the module's doc); `triangles` are its
/// faces ([`Mesh::triangles`]). Borrowed when nothing is carved.
pub fn carved<'a>(mesh: &'a Mesh, triangles: &[[u32; 3]]) -> Cow<'a, Mesh> {
    let beds = channel_beds(mesh, triangles, None, &[]);
    if beds.is_empty() {
        return Cow::Borrowed(mesh);
    }
    let mut out = mesh.clone();
    for (v, ground, water) in beds {
        lay_bed(&mut out.vertices[v as usize], mesh.radius, ground, water);
    }
    Cow::Owned(out)
}

/// Lays `vert` on a channel's bed: its ground at `ground`, its water at `water` (m above the
/// base sphere of `radius`).
pub fn lay_bed(vert: &mut Vertex, radius: f64, ground: f64, water: f64) {
    vert.pos = lift(vert.p(), radius, ground).to_array();
    vert.ground = ground;
    vert.water = water;
}

/// Most nominal edges a channel's half width spans for tiles and DEMs to carve it by flooding
/// their own triangulation: that refines the leaves within twice the half width of their region
/// at their own resolution, so without a bound a tile or DEM finer than a great river by
/// thousands would refine millions of leaves. Wider channels carve by their course
/// (`tiles/course.rs`; 3D Tiles: past level 11 for the Amazon's 1.3 km channel, 15 for a 100 m
/// river). At 8, a tile beside a great river refines at most about six times its own leaves
/// (at 32, 60 times: 73-113 ms a tile at the bound).
pub const MAX_CARVE_EDGES: f64 = 8.0;

/// Depth (m) of a channel `half` metres wide on each side of its centre line.
fn centre_depth(half: f64) -> f64 {
    use crate::planet::network::{channel_depth_m, discharge_of_width};
    channel_depth_m(discharge_of_width(2.0 * half))
}

/// A river vertex of a course too wide for the mesh's own carving (`tiles/course.rs`): its
/// channel carves the vertices within its half width by their distance alone.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CourseVertex {
    /// Unit direction.
    pub dir: DVec3,
    /// Half the channel's width (m).
    pub half: f64,
    /// Its water level (m above the base sphere, [`river_level`]).
    pub level: f64,
    /// Its position's bits (the last tie-break).
    pub bits: [u64; 3],
}

impl CourseVertex {
    pub fn new(v: &Vertex, half: f64) -> CourseVertex {
        CourseVertex { dir: v.p().normalize(), half, level: river_level(v), bits: v.pos.map(f64::to_bits) }
    }
}

/// The carved vertices: `(vertex, ground, water)`, in vertex order.
///
/// Each channel that carves (shown as water and wider than the shortest edge at its vertex)
/// reaches the vertices within its half width that the mesh's edges connect to it through
/// others within that width; a vertex takes the channel whose margin (half width minus
/// distance) is largest, ties going to the lower water level and then to the river vertex
/// whose position's bits sort first. Nothing here depends on vertex ids or on the mesh
/// beyond twice the widest flooding channel's half width and one ring of faces, so a part of a
/// triangulation with that margin around it carves its inside exactly as the whole would
/// (3D Tiles, `tiles/carve.rs`). With `limits`, a channel carves only where its half width
/// lies between the two it gives for its river vertex's unit direction (tiles and DEMs: from
/// their nominal edge there, so that whether a tile carves at all is known before it is
/// refined, and [`MAX_CARVE_EDGES`] of it at most); without, wherever it is wider than the
/// shortest edge at its vertex (views, whose size their budget bounds). The `course` vertices
/// of channels wider than that (`tiles/course.rs`) reach every vertex within their half width,
/// by the same rule, and keep their own bed as a flooding channel's vertex does.
pub fn channel_beds(
    mesh: &Mesh,
    triangles: &[[u32; 3]],
    limits: Option<&dyn Fn(DVec3) -> (f64, f64)>,
    course: &[CourseVertex],
) -> Vec<(u32, f64, f64)> {
    let (half, shortest) = channel_halves(mesh, triangles);
    let vs = &mesh.vertices;
    let sources: Vec<(u32, f64)> = (0..vs.len())
        .filter_map(|v| {
            let (h, e) = (half[v]?, shortest[v]);
            let (lo, hi) = limits.map_or((e, f64::INFINITY), |f| f(vs[v].p().normalize()));
            (shows_channel(h, e) && h > lo && h <= hi).then_some((v as u32, h))
        })
        .collect();
    if sources.is_empty() && course.is_empty() {
        return Vec::new();
    }
    // Every channel: the flooding sources', then the course's.
    let channels: Vec<CourseVertex> =
        sources.iter().map(|&(s, h)| CourseVertex::new(&vs[s as usize], h)).chain(course.iter().copied()).collect();
    let around = Neighbours::new(vs.len(), triangles);
    let unit = |v: u32| vs[v as usize].p().normalize();
    // The order channels win a vertex in: larger margin, lower level, position bits.
    let beats = |m: f64, k: usize, (bm, bk): (f64, usize)| {
        m > bm
            || (m == bm && {
                let (a, b) = (&channels[k], &channels[bk]);
                a.level.total_cmp(&b.level).then(a.bits.cmp(&b.bits)).is_lt()
            })
    };
    let mut best: Vec<(f64, usize)> = vec![(f64::NEG_INFINITY, usize::MAX); vs.len()];
    let mut seen = vec![usize::MAX; vs.len()];
    let mut stack = Vec::new();
    for (k, &(s, h)) in sources.iter().enumerate() {
        let centre = channels[k].dir;
        let margin = |v: u32| h - unit(v).distance(centre) * mesh.radius;
        seen[s as usize] = k;
        stack.push((s, h));
        while let Some((v, m)) = stack.pop() {
            if beats(m, k, best[v as usize]) {
                best[v as usize] = (m, k);
            }
            for &u in around.of(v) {
                if seen[u as usize] != k {
                    seen[u as usize] = k;
                    let mu = margin(u);
                    if mu > 0.0 {
                        stack.push((u, mu));
                    }
                }
            }
        }
    }
    // The course's channels, by distance: in runs of consecutive vertices (near each other
    // along a course), each passed over where the vertex lies beyond its run's reach.
    let runs: Vec<(DVec3, f64, std::ops::Range<usize>)> = (0..course.len())
        .step_by(COURSE_RUN)
        .map(|i0| {
            let run = i0..(i0 + COURSE_RUN).min(course.len());
            let centre = course[run.clone()].iter().map(|c| c.dir).sum::<DVec3>().normalize();
            let reach =
                course[run.clone()].iter().map(|c| c.dir.distance(centre) + c.half / mesh.radius).fold(0.0, f64::max);
            (centre, reach, run.start + sources.len()..run.end + sources.len())
        })
        .collect();
    if !runs.is_empty() {
        use rayon::prelude::*;
        best.par_iter_mut().enumerate().for_each(|(v, slot)| {
            let u = unit(v as u32);
            for (centre, reach, ks) in &runs {
                if u.distance(*centre) > *reach {
                    continue;
                }
                for k in ks.clone() {
                    let m = channels[k].half - u.distance(channels[k].dir) * mesh.radius;
                    if m > 0.0 && beats(m, k, *slot) {
                        *slot = (m, k);
                    }
                }
            }
        });
    }
    let mut beds = Vec::new();
    for (v, &(margin, k)) in best.iter().enumerate() {
        let vert = &vs[v];
        if k == usize::MAX
            || sources.get(k).is_some_and(|s| s.0 == v as u32)
            || channels[k].bits == vert.pos.map(f64::to_bits)
            || vert.submerged()
            || vert.flags.contains(VertexFlags::LAKE)
        {
            continue;
        }
        let (h, level) = (channels[k].half, channels[k].level);
        let across = (h - margin) / h;
        let bed = level - centre_depth(h) * (1.0 - across * across);
        let ground = vert.ground.min(bed);
        if ground < level {
            beds.push((v as u32, ground, level));
        }
    }
    beds
}

/// Course vertices tested together against a vertex ([`channel_beds`]).
const COURSE_RUN: usize = 16;

/// Vertex neighbours over a list of triangles, in compressed rows (an edge shared by two faces
/// is listed twice; the search does not mind). Not [`Mesh::adjacency`]: that lists the mesh's
/// edges, while the search follows the faces its caller draws.
struct Neighbours {
    offsets: Vec<u32>,
    list: Vec<u32>,
}

impl Neighbours {
    fn new(n: usize, triangles: &[[u32; 3]]) -> Neighbours {
        let mut offsets = vec![0u32; n + 1];
        for t in triangles {
            for &v in t {
                offsets[v as usize + 1] += 2;
            }
        }
        for i in 0..n {
            offsets[i + 1] += offsets[i];
        }
        let mut fill = offsets.clone();
        let mut list = vec![0u32; offsets[n] as usize];
        for t in triangles {
            for k in 0..3 {
                let v = t[k] as usize;
                let slot = fill[v] as usize;
                list[slot] = t[(k + 1) % 3];
                list[slot + 1] = t[(k + 2) % 3];
                fill[v] += 2;
            }
        }
        Neighbours { offsets, list }
    }

    fn of(&self, v: u32) -> &[u32] {
        &self.list[self.offsets[v as usize] as usize..self.offsets[v as usize + 1] as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// A strip of ground 2 km long and 1 km across on a planet of radius 1,000 km, vertices
    /// every 25 m, banks 4 m above the water of a river along its middle row with channels
    /// `width` metres wide.
    fn strip(width: f32) -> (Mesh, Vec<[u32; 3]>, usize) {
        let r = 1_000_000.0;
        let (cols, rows, step) = (81usize, 41usize, 25.0);
        let mid = rows / 2;
        let mut vs = Vec::new();
        let mut points = Vec::new();
        for i in 0..rows {
            for j in 0..cols {
                let (x, y) = (j as f64 * step / r, (i as f64 - mid as f64) * step / r);
                let dir = DVec3::new(1.0, x, y).normalize();
                let mut v = Vertex::new(dir * r, (i * cols + j) as u32);
                v.ground = 10.0;
                v.water = 10.0;
                if i == mid {
                    v.ground = 3.0;
                    v.water = 6.0;
                    v.flags = VertexFlags::RIVER;
                    points.push((dir, width));
                }
                vs.push(v);
            }
        }
        let mut tris = Vec::new();
        for i in 0..rows - 1 {
            for j in 0..cols - 1 {
                let (a, b, c, d) = (i * cols + j, i * cols + j + 1, (i + 1) * cols + j, (i + 1) * cols + j + 1);
                tris.push([a as u32, b as u32, d as u32]);
                tris.push([a as u32, d as u32, c as u32]);
            }
        }
        let channels = crate::mesh::channels::Channels::new(&points, 100.0, 100.0, r).unwrap();
        let mesh = Mesh { radius: r, vertices: vs, channels: Some(std::sync::Arc::new(channels)), ..Mesh::default() };
        (mesh, tris, cols)
    }

    #[test]
    fn a_wide_channel_is_carved_to_its_width() {
        let (mesh, tris, cols) = strip(390.0);
        let carved = carved(&mesh, &tris);
        let vs = &carved.vertices;
        // Down the middle column: under water within 195 m of the river, dry beyond.
        let column = 40;
        let mid = vs.len() / cols / 2;
        for i in 0..vs.len() / cols {
            let v = &vs[i * cols + column];
            let off = (i as f64 - mid as f64).abs() * 25.0;
            if off == 0.0 {
                assert_eq!((v.ground, v.water), (3.0, 6.0), "the river vertex keeps its bed");
            } else if off < 195.0 {
                assert_eq!(v.water, 6.0, "{off} m out");
                // A parabola under the river's level, the channel's depth at the middle.
                let depth = centre_depth(195.0) * (1.0 - (off / 195.0).powi(2));
                assert!((v.ground - (6.0 - depth)).abs() < 1e-3, "{off} m out: {}", v.ground);
                assert!((v.p().length() - (mesh.radius + v.ground)).abs() < 1e-6);
            } else {
                assert_eq!((v.ground, v.water), (10.0, 10.0), "{off} m out");
            }
        }
        // The water surface covers the channel flat at the river's level; the shore lies
        // between the last carved vertex and the first bank.
        let levels = super::super::water::water_levels(&carved, &tris);
        let wet = (0..vs.len() / cols).filter(|&i| levels[i * cols + column] > vs[i * cols + column].ground).count();
        assert_eq!(wet, 15, "7 carved vertices on each side and the river's");
        // The same bits again, and nothing carved for a channel narrower than the edges.
        assert_eq!(carved.vertices, super::carved(&mesh, &tris).vertices);
        let (narrow, tris, _) = strip(40.0);
        assert!(matches!(super::carved(&narrow, &tris), Cow::Borrowed(_)));
        assert!(channel_beds(&narrow, &tris, None, &[]).is_empty());
        // Limits on the half width (195 m) leave it out or in.
        assert!(channel_beds(&mesh, &tris, Some(&|_| (10.0, 190.0)), &[]).is_empty());
        assert!(channel_beds(&mesh, &tris, Some(&|_| (200.0, 400.0)), &[]).is_empty());
        assert_eq!(channel_beds(&mesh, &tris, Some(&|_| (10.0, 200.0)), &[]), channel_beds(&mesh, &tris, None, &[]));
    }
}
