//! Parallel edge splits (paper §5.3, Algorithm 2): compaction of the split list, new vertices
//! computed in parallel from their four neighbours (positions by eq. 2 / eq. 7–9, altitudes by
//! step 6 and eq. 10–12), then the topology changes.

use crate::mesh::altitude::split_vertex;
use crate::mesh::{EdgeKind, Mesh, SplitSite, Vertex};
use crate::params::Params;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// Follows the blocker chain of every wanted edge. A chain stops where it meets an edge another
/// chain already reached (an atomic flag per edge): the rest of that chain is walked once, by
/// whoever reached it first, so chains that merge cost their shared part once. Returns, sorted
/// and without repeats, every edge on a chain (`all`) or only the chain ends, which are ready.
pub fn wanted_chains(mesh: &Mesh, wants: &[bool], all: bool) -> Vec<u32> {
    let wanted: Vec<u32> = (0..wants.len() as u32).into_par_iter().filter(|&e| wants[e as usize]).collect();
    let seen: Vec<AtomicBool> = (0..mesh.edges.len()).into_par_iter().map(|_| AtomicBool::new(false)).collect();
    let mut list: Vec<u32> = wanted
        .par_iter()
        .fold(Vec::new, |mut found, &e| {
            let mut x = e;
            while !seen[x as usize].swap(true, Ordering::Relaxed) {
                let b = mesh.blocking_edge(x);
                if all || b == x {
                    found.push(x);
                }
                if b == x {
                    break;
                }
                x = b;
            }
            found
        })
        .flatten_iter()
        .collect();
    list.par_sort_unstable();
    list.dedup();
    list
}

/// The edges to split this pass: every wanted edge that is the refinement edge of both its
/// faces, and for the others the refinement edge that blocks them (followed until one is
/// ready). Sorted and without repeats, so the pass is deterministic.
pub fn select_splits(mesh: &Mesh, wants: &[bool]) -> Vec<u32> {
    wanted_chains(mesh, wants, false)
}

/// Splits the given ready edges; each owns its two faces, so the new vertices are computed in
/// parallel and then written in parallel (see [`Mesh::split_edges`]). Returns the number of splits; the
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
    mesh.split_edges(&made)
}
