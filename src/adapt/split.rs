//! Parallel edge splits (paper §5.3, Algorithm 2): compaction of the split list, new vertices
//! computed in parallel from their four neighbours (positions by eq. 2 / eq. 7–9, altitudes by
//! step 6 and eq. 10–12), then the topology changes.

use crate::mesh::altitude::split_vertex;
use crate::mesh::Mesh;
use crate::params::Params;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// Follows the blocker chain of every wanted edge. A chain stops where it meets an edge another
/// chain already reached (an atomic flag per edge): the rest of that chain is walked once, by
/// whoever reached it first, so chains that merge cost their shared part once. Returns, sorted
/// and without repeats, every edge on a chain (`all`) or only the chain ends, which are ready.
pub fn wanted_chains(mesh: &Mesh, wants: &[bool], all: bool) -> Vec<u32> {
    let wanted = set_flags(wants);
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

/// Indices of the set flags, in order. Most flags are clear after the first passes, so blocks
/// of them are tested with one branchless OR before their set ones are looked for.
pub fn set_flags(flags: &[bool]) -> Vec<u32> {
    const CHUNK: usize = 1 << 15;
    const BLOCK: usize = 64;
    flags
        .par_chunks(CHUNK)
        .enumerate()
        .flat_map_iter(|(c, chunk)| {
            let mut found = Vec::new();
            for (b, block) in chunk.chunks(BLOCK).enumerate() {
                if block.iter().fold(false, |any, &f| any | f) {
                    let base = (c * CHUNK + b * BLOCK) as u32;
                    found.extend(block.iter().enumerate().filter(|(_, &f)| f).map(|(k, _)| base + k as u32));
                }
            }
            found
        })
        .collect()
}

/// The edges to split this pass: every wanted edge that is the refinement edge of both its
/// faces, and for the others the refinement edge that blocks them (followed until one is
/// ready). Sorted and without repeats, so the pass is deterministic.
pub fn select_splits(mesh: &Mesh, wants: &[bool]) -> Vec<u32> {
    wanted_chains(mesh, wants, false)
}

/// Splits the given ready edges (see [`Mesh::split_edges`]): each new vertex is computed from its
/// diamond and written with its edges and faces in the same parallel pass. Returns the number of
/// splits; the split edges' slots now hold their first halves.
pub fn apply_splits(mesh: &mut Mesh, ready: &[u32], params: &Params) -> usize {
    mesh.split_edges(ready, |d| split_vertex(d, params))
}

#[cfg(test)]
mod tests {
    use super::set_flags;

    #[test]
    fn set_flags_lists_every_set_flag_in_order() {
        assert!(set_flags(&[]).is_empty());
        // Sparse and dense stretches across block and chunk boundaries.
        let n = 3 * (1 << 15) + 77;
        let flags: Vec<bool> = (0..n).map(|i| i % 1000 == 999 || (40_000..40_200).contains(&i) || i == n - 1).collect();
        let expected: Vec<u32> = (0..n as u32).filter(|&i| flags[i as usize]).collect();
        assert_eq!(set_flags(&flags), expected);
        assert_eq!(set_flags(&[true; 130]), (0..130).collect::<Vec<u32>>());
        assert!(set_flags(&vec![false; 70_000]).is_empty());
    }
}
