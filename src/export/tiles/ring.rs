//! Normals along a tile's border: the rest of each border vertex's ring in the uniform
//! bisection triangulation of the tile's level, found in the neighbouring cells.
//!
//! A tile's content is the uniform triangulation `depth` bisections below the octahedron,
//! restricted to its cell. A vertex inside the cell has its whole ring there; a border vertex
//! shares its ring with the neighbouring cells. Its normal is the area-weighted sum over the
//! whole ring, summed in an order fixed by the faces' positions, so every tile holding the
//! vertex computes the same bits.
//!
//! The outside faces are found by descending the tree from the roots through the nodes that can
//! hold a border vertex: a node is entered when a candidate vertex lies within `slack` times
//! the node's angular radius of its centre (split positions wander inside their diamond, eq. 2
//! and 7, so a node's region is not exactly its triangle). Each ring is then checked to close
//! around its vertex; a ring that does not is searched again with twice the slack.

use super::tree::{Refiner, ROOTS};
use crate::export::surface_normals;
use crate::mesh::Mesh;
use glam::DVec3;
use std::collections::HashMap;

/// First slack of the search, in node radii (measured: enough below level 0 on the default planet).
const SLACK: f64 = 1.0;
/// Searches before a ring that does not close is accepted as found.
const ATTEMPTS: usize = 4;

/// Unit normals of `surface`'s vertices: area-weighted over the surface's faces inside, over the
/// whole ring of the uniform depth-`depth` triangulation on the border. `triangles` are the
/// surface's faces ([`Mesh::triangles`]), `ids` its vertices' indices in `refiner`'s mesh;
/// `cell` is the tile's node; `border` its border edges; `moved` the positions of `refiner`'s
/// vertices that the surface's carving moved (`carve.rs`), its own and its neighbours'.
pub fn border_normals(
    refiner: &mut Refiner,
    (cell, depth): ([u32; 3], u32),
    (surface, triangles, ids): (&Mesh, &[[u32; 3]], &[u32]),
    border: &[(u32, u32)],
    moved: &HashMap<u32, DVec3>,
) -> Vec<DVec3> {
    let mut normals = surface_normals(surface, triangles);
    if border.is_empty() {
        return normals;
    }
    // Each border vertex (refiner id) and its inside faces (as refiner-id triples).
    let mut ring: HashMap<u32, Vec<[u32; 3]>> = border.iter().map(|&(a, _)| (ids[a as usize], Vec::new())).collect();
    for &corners in triangles {
        let tri = corners.map(|v| ids[v as usize]);
        for v in tri {
            if let Some(faces) = ring.get_mut(&v) {
                faces.push(tri);
            }
        }
    }
    let mut outside = Vec::new();
    let mut slack = SLACK;
    for _ in 0..ATTEMPTS {
        outside.clear();
        let candidates: Vec<(u32, DVec3)> = ring.keys().map(|&v| (v, refiner.mesh().pos(v).normalize())).collect();
        for root in ROOTS {
            descend(refiner, root, depth, &candidates, cell, slack, &mut outside);
        }
        if ring.iter().all(|(&v, inside)| closed(v, inside.iter().chain(&outside))) {
            break;
        }
        slack *= 2.0;
    }
    for leaf in outside {
        for v in leaf {
            if let Some(faces) = ring.get_mut(&v) {
                faces.push(leaf);
            }
        }
    }
    let mesh = refiner.mesh();
    for (s, &id) in ids.iter().enumerate() {
        if let Some(faces) = ring.get(&id) {
            let pos = |v: u32| moved.get(&v).copied().unwrap_or_else(|| mesh.pos(v));
            let area = |t: [u32; 3]| {
                let [a, b, c] = t.map(pos);
                (b - a).cross(c - a) * 0.5
            };
            let mut areas: Vec<DVec3> = faces.iter().map(|&t| area(t)).collect();
            areas.sort_by_key(|n| n.to_array().map(f64::to_bits));
            let n = areas.iter().fold(DVec3::ZERO, |acc, &n| acc + n).normalize_or_zero();
            normals[s] = if n == DVec3::ZERO { mesh.pos(id).normalize_or_zero() } else { n };
        }
    }
    normals
}

/// Collects into `out` the leaves `left` bisections below `node`, outside `cell`, that have one
/// of `candidates` (refiner ids and unit directions) as a vertex.
fn descend(
    refiner: &mut Refiner,
    node: [u32; 3],
    left: u32,
    candidates: &[(u32, DVec3)],
    cell: [u32; 3],
    slack: f64,
    out: &mut Vec<[u32; 3]>,
) {
    if node == cell {
        return;
    }
    if left == 0 {
        if candidates.iter().any(|(v, _)| node.contains(v)) {
            out.push(node);
        }
        return;
    }
    let dirs = node.map(|v| refiner.mesh().pos(v).normalize());
    let centre = (dirs[0] + dirs[1] + dirs[2]).normalize();
    let radius = dirs.iter().map(|&d| angle(centre, d)).fold(0.0, f64::max);
    let near: Vec<(u32, DVec3)> =
        candidates.iter().copied().filter(|&(v, d)| node.contains(&v) || angle(centre, d) <= slack * radius).collect();
    if near.is_empty() {
        return;
    }
    for child in refiner.children(node) {
        descend(refiner, child, left - 1, &near, cell, slack, out);
    }
}

/// Angle between two unit vectors, accurate for tiny angles.
pub(super) fn angle(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// Whether the faces containing `v` (counter-clockwise triples; others are ignored) close a fan
/// around it: every edge leaving `v` is also an edge arriving at it.
fn closed<'a>(v: u32, faces: impl Iterator<Item = &'a [u32; 3]>) -> bool {
    let mut balance: HashMap<u32, i32> = HashMap::new();
    for t in faces {
        if let Some(i) = t.iter().position(|&x| x == v) {
            *balance.entry(t[(i + 1) % 3]).or_default() += 1;
            *balance.entry(t[(i + 2) % 3]).or_default() -= 1;
        }
    }
    !balance.is_empty() && balance.values().all(|&b| b == 0)
}
