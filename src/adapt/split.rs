//! Parallel edge splits (paper §5.3, Algorithm 2): compaction of the split list, new vertices
//! computed in parallel from their four neighbours (positions by eq. 2 / eq. 7–9, altitudes by
//! step 6 and eq. 10–12), then the topology changes.

use crate::mesh::altitude::split_vertex;
use crate::mesh::{EdgeKind, Mesh, SplitSite, Vertex};
use crate::params::Params;
use rayon::prelude::*;

/// Follows the blocking refinement edges from edge `e` (newest-vertex bisection closure),
/// calling `visit` on each edge of the chain; returns the last one, which is ready to split.
pub fn blocker_chain(mesh: &Mesh, e: u32, mut visit: impl FnMut(u32)) -> u32 {
    let mut x = e;
    loop {
        visit(x);
        let b = mesh.blocking_edge(x);
        if b == x {
            return x;
        }
        x = b;
    }
}

/// The edges to split this pass: every wanted edge that is the refinement edge of both its
/// faces, and for the others the refinement edge that blocks them (followed until one is
/// ready). Sorted and without repeats, so the pass is deterministic.
pub fn select_splits(mesh: &Mesh, wants: &[bool]) -> Vec<u32> {
    let mut list: Vec<u32> =
        wants.par_iter().enumerate().filter(|(_, &w)| w).map(|(e, _)| blocker_chain(mesh, e as u32, |_| {})).collect();
    list.par_sort_unstable();
    list.dedup();
    list
}

/// Splits the given ready edges; each owns its two faces, so the new vertices are computed in
/// parallel and the topology is then changed edge by edge. Returns the number of splits; the
/// split edges' slots now hold their first halves.
pub fn apply_splits(mesh: &mut Mesh, edges: &[u32], params: &Params) -> usize {
    let made: Vec<(SplitSite, Vertex, [EdgeKind; 4])> = edges
        .par_iter()
        .filter_map(|&e| mesh.split_site(e))
        .map(|site| {
            let (v, kinds) = split_vertex(mesh, &site, params);
            (site, v, kinds)
        })
        .collect();
    mesh.split_edges(&made).len()
}
