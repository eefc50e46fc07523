//! The courses of rivers too wide for a tile's or a DEM's own carving: their river edges
//! bisected along the tree, and nothing else, until they are short beside the channel.
//!
//! A tile or DEM carves a channel by flooding its own triangulation out to twice the channel's
//! half width (`export/carve.rs`), which stays cheap only while that half width spans at most
//! [`crate::export::carve::MAX_CARVE_EDGES`] of its edges. Finer than that (3D Tiles past level
//! 11 beside the Amazon, 15 beside a 100 m river), its vertices take the channel by their
//! distance to the river's course instead: the base mesh's river edges near the region, each
//! bisected ([`Refiner::midpoint`], the split of views and tiles, so the course's vertices are
//! theirs bit for bit) while it is longer than its narrower end's half width, or the least half
//! width that carves by the course there, over [`COURSE_EDGES_PER_HALF`]. The course is a line:
//! a few dozen vertices per channel width whatever the region's resolution, and the same for
//! every tile of a level and every block of a grid, so they carve alike wherever they meet.

use super::tree::{Refiner, ROOTS};
use crate::export::carve::CourseVertex;
use crate::export::water::{half_width, SMALL_STREAM_M};
use crate::mesh::split::position::DESCENDANT_REACH;
use crate::mesh::EdgeKind;
use glam::DVec3;

/// Course edges per channel half width: a course edge stops being bisected once it is no
/// longer than its narrower end's half width (or the least that carves by the course there)
/// over this. Its vertices' channels then overlap so much that their union's banks waver by at
/// most 1/512 of the half width.
pub const COURSE_EDGES_PER_HALF: f64 = 8.0;

/// The river vertices of the courses of channels whose half width exceeds `least(dir)` (m, at
/// the vertex's unit direction) and that may reach the region `meets` describes: `meets(u,
/// reach)` says whether anything within angle `reach` of the spherical triangle of unit
/// corners `u` may lie in it. `widest` (m) bounds the half width of any channel near it. Refines
/// `refiner` along the courses; in the order found, each vertex once.
pub fn wide_course(
    refiner: &mut Refiner,
    meets: &dyn Fn(&[DVec3; 3], f64) -> bool,
    widest: f64,
    least: &dyn Fn(DVec3) -> f64,
) -> Vec<CourseVertex> {
    let Some(channels) = refiner.mesh().channels.clone() else { return Vec::new() };
    let radius = refiner.mesh().radius;
    let longest = |u: &[DVec3; 3]| u[0].distance(u[1]).max(u[1].distance(u[2])).max(u[2].distance(u[0]));
    // The base mesh's river edges near the region: edges of its leaves there.
    let unit = |r: &Refiner, v: u32| r.mesh().pos(v).normalize();
    let mut edges: Vec<(u32, u32)> = Vec::new();
    let mut stack: Vec<[u32; 3]> = ROOTS.to_vec();
    while let Some(node) = stack.pop() {
        let u = node.map(|v| unit(refiner, v));
        if !meets(&u, DESCENDANT_REACH * longest(&u) + widest / radius) {
            continue;
        }
        if refiner.base_splits(node) {
            stack.extend(refiner.children(node));
            continue;
        }
        for k in 0..3 {
            let (a, b) = (node[k], node[(k + 1) % 3]);
            if refiner.base_edge_kind(a, b) == Some(EdgeKind::River) {
                edges.push((a.min(b), a.max(b)));
            }
        }
    }
    edges.sort_unstable();
    edges.dedup();
    // The widest channel any vertex of a base edge's course can take: a point of it lies
    // within DESCENDANT_REACH of the edge's length from the edge, so within (1 +
    // DESCENDANT_REACH) of it from either end (a mouth's end is no river vertex), and the base
    // river vertex nearest to it (whose width it takes) at most that far: within (3/2 + 2
    // DESCENDANT_REACH) of the edge's midpoint.
    let mut stack: Vec<(u32, u32, f64)> = edges
        .into_iter()
        .map(|(a, b)| {
            let (ua, ub) = (unit(refiner, a), unit(refiner, b));
            let within = ((1.5 + 2.0 * DESCENDANT_REACH) * ua.distance(ub)).to_degrees();
            let w = channels.widest_within((ua + ub).normalize(), within, f32::INFINITY).max(SMALL_STREAM_M);
            (a, b, (0.5 * f64::from(w)).min(widest))
        })
        .collect();
    // Each bisected while longer than its ends' half width allows and wider than `least`.
    let mut seen = rustc_hash::FxHashSet::default();
    let mut out = Vec::new();
    while let Some((a, b, reach)) = stack.pop() {
        let mesh = refiner.mesh();
        let (va, vb) = (&mesh.vertices[a as usize], &mesh.vertices[b as usize]);
        let (ha, hb) = (half_width(mesh, va), half_width(mesh, vb));
        let Some((narrow, wide)) = span(ha, hb) else { continue };
        let (ua, ub) = (va.p().normalize(), vb.p().normalize());
        let edge = [ua, ub, ub];
        if !meets(&edge, DESCENDANT_REACH * longest(&edge) + reach / radius) {
            continue;
        }
        for (v, h, u) in [(a, ha, ua), (b, hb, ub)] {
            if let Some(h) = h.filter(|&h| h > least(u)) {
                if seen.insert(v) {
                    out.push(CourseVertex::new(&mesh.vertices[v as usize], h));
                }
            }
        }
        // No finer than the least half width that carves here allows: a great river's edge
        // to a tributary's vertex stops there.
        let floor = least((ua + ub).normalize());
        if wide > floor && ua.distance(ub) * radius > narrow.max(floor) / COURSE_EDGES_PER_HALF {
            let m = refiner.midpoint(a, b);
            stack.extend([(a, m, reach), (m, b, reach)]);
        }
    }
    out
}

/// The lesser and the greater of two optional values (the one given twice if only one is).
fn span(a: Option<f64>, b: Option<f64>) -> Option<(f64, f64)> {
    match (a, b) {
        (Some(x), Some(y)) => Some((x.min(y), x.max(y))),
        (Some(x), None) | (None, Some(x)) => Some((x, x)),
        (None, None) => None,
    }
}
