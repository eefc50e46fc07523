//! Rivers' channels carved into a tile's content as into a view (`export/carve.rs`), the same
//! bits in every tile that holds a vertex.
//!
//! A channel floods the vertices within its half width of its river vertex that the
//! triangulation's edges reach through such vertices, and a channel carves at all only if it is
//! wide enough for the level. So a vertex's bed depends on the triangulation within twice the
//! widest flooding channel's half width of it and one ring of faces beyond. A tile carves its
//! cell together with the leaves of its level's uniform triangulation out to that distance and
//! a few edges more, and keeps its own vertices' beds: two tiles carve their common border
//! alike, bit for bit, and every tile carves as the level's whole triangulation would.
//!
//! The widest channels near a cell come from the base mesh's channel widths
//! ([`crate::mesh::channels::Channels::widest_near`]). A channel floods a tile where its half
//! width is between half the level's nominal edge and [`MAX_CARVE_EDGES`] of them, a rule of
//! the level alone; a wider one carves the vertices within its half width of its course
//! (`course.rs`), which the tile refines along the river alone. Where no channel near the cell
//! is wider than half an edge (every coarse level, and fine ones away from great rivers),
//! nothing is carved and nothing more is refined; where none floods, only a ring of faces
//! around the cell is, for the border's normals. A tile's work stays bounded at every level.

use super::course::wide_course;
use super::ring::angle;
use super::tree::{holds, leaf_vertices, Refiner, ROOTS};
use crate::export::carve::{channel_beds, MAX_CARVE_EDGES};
use crate::export::water::SMALL_STREAM_M;
use crate::mesh::split::position::DESCENDANT_REACH;
use glam::DVec3;
use std::collections::HashMap;

/// Least half width of a channel that carves a tile, in its level's nominal edges.
const LEAST_HALF_EDGES: f64 = 0.5;
/// Most share of its level's nominal edge a leaf's edge has (measured under 4.2, split
/// positions wandering inside their diamonds: `tiles_carve_wide_rivers_alike_across_their_borders`).
pub(super) const LONGEST_EDGE_SHARE: f64 = 6.0;

/// The carved `(ground, water)` of the vertices (ids in `refiner`'s mesh) of tree node `cell`'s
/// `leaves`, `depth` bisections below the octahedron (and of some around them), whose nominal
/// edge is `edge_m`; empty where no channel near the cell is wide enough to carve.
pub fn cell_beds(
    refiner: &mut Refiner,
    cell: [u32; 3],
    leaves: &[[u32; 3]],
    depth: u32,
    edge_m: f64,
) -> HashMap<u32, (f64, f64)> {
    let mesh = refiner.mesh();
    let Some(channels) = mesh.channels.clone() else { return HashMap::new() };
    let radius = mesh.radius;
    let corners = cell.map(|v| mesh.pos(v).normalize());
    let (centre, cell_r) = disc(corners);
    // How far the cell's leaves wander outside its triangle (eq. 2 and 7).
    let wander = leaves.iter().flatten().map(|&v| outside(mesh.pos(v).normalize(), corners)).fold(0.0, f64::max);
    // Sources near the cell are at most this wide: those within the widest channel's width
    // (and two edges) of it.
    let near = cell_r + wander + (f64::from(channels.widest()) + 2.0 * edge_m) / radius;
    let half = 0.5 * f64::from(channels.widest_near(centre, near).max(SMALL_STREAM_M));
    let limits = (LEAST_HALF_EDGES * edge_m, MAX_CARVE_EDGES * edge_m);
    if half <= limits.0 {
        return HashMap::new();
    }
    // The widest channel that floods the level's triangulation (no wider than the limits):
    // the leaves are gathered out to twice its half width; where none does, a ring of faces
    // for the border's normals.
    let cap = (2.0 * limits.1) as f32 * (1.0 + 1e-6);
    let flood = 0.5 * f64::from(channels.widest_near_under(centre, near, cap).max(SMALL_STREAM_M));
    let spread = if flood > limits.0 { 2.0 * flood } else { 0.0 };
    let reach = wander + (spread + LONGEST_EDGE_SHARE * edge_m) / radius;
    let mut around = Vec::new();
    for root in ROOTS {
        gather(refiner, root, depth, (corners, reach), &mut around);
    }
    // Wider channels carve by their distance to their course.
    let course = if half > limits.1 {
        // The gathered leaves' vertices lie within `reach` and a leaf's diameter of the cell.
        let slack = reach + 2.0 * LONGEST_EDGE_SHARE * edge_m / radius;
        let meets = |u: &[DVec3; 3], extra: f64| {
            let (c, r) = disc(*u);
            outside(c, corners) <= slack + r + extra
        };
        wide_course(refiner, &meets, half, &|_| limits.1)
    } else {
        Vec::new()
    };
    let (points, triangles, ids) = leaf_vertices(refiner.mesh(), &around);
    channel_beds(&points, &triangles, Some(&|_| limits), &course)
        .into_iter()
        .map(|(v, ground, water)| (ids[v as usize], (ground, water)))
        .collect()
}

/// Centre and angular radius of the spherical triangle of unit `corners`.
fn disc(corners: [DVec3; 3]) -> (DVec3, f64) {
    let centre = (corners[0] + corners[1] + corners[2]).normalize();
    (centre, corners.iter().map(|&d| angle(centre, d)).fold(0.0, f64::max))
}

/// Angle from unit direction `p` to the spherical triangle of unit `corners` (counter-clockwise
/// seen from outside): 0 inside, else to its nearest side.
fn outside(p: DVec3, corners: [DVec3; 3]) -> f64 {
    if holds(corners, p) {
        return 0.0;
    }
    (0..3)
        .map(|k| {
            let (a, b) = (corners[k], corners[(k + 1) % 3]);
            let n = a.cross(b).normalize();
            let q = p - n * p.dot(n);
            if a.cross(q).dot(n) >= 0.0 && q.cross(b).dot(n) >= 0.0 {
                p.dot(n).abs().clamp(0.0, 1.0).asin()
            } else {
                angle(p, a).min(angle(p, b))
            }
        })
        .fold(f64::INFINITY, f64::min)
}

/// Collects into `out` the leaves `left` bisections below `node` that may lie within angle
/// `reach` of the spherical triangle of unit `corners`.
fn gather(
    refiner: &mut Refiner,
    node: [u32; 3],
    left: u32,
    (corners, reach): ([DVec3; 3], f64),
    out: &mut Vec<[u32; 3]>,
) {
    let u = node.map(|v| refiner.mesh().pos(v).normalize());
    let (c, r) = disc(u);
    // A leaf's vertices are its corners; an inner node's descendants lie within
    // DESCENDANT_REACH of its longest edge past it (eq. 2 and 7).
    let longest = u[0].distance(u[1]).max(u[1].distance(u[2])).max(u[2].distance(u[0]));
    let r = if left == 0 { r } else { r + DESCENDANT_REACH * longest };
    if outside(c, corners) > reach + r {
        return;
    }
    if left == 0 {
        out.push(node);
        return;
    }
    for child in refiner.children(node) {
        gather(refiner, child, left - 1, (corners, reach), out);
    }
}
