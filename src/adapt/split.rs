//! Parallel edge splits (paper §5.3, Algorithm 2): compaction of the split list, then one
//! parallel pass in which each split computes its new vertex from its four neighbours
//! (positions by eq. 2 / eq. 7–9, altitudes by step 6 and eq. 10–12) and makes the topology
//! change.

use super::camera::View;
use super::state::wants_edge;
use crate::mesh::altitude::split_vertex;
use crate::mesh::Mesh;
use crate::params::Params;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// Follows the blocker chain of every wanted edge: returns flags of the edges the chains
/// reached besides the wanted ones, and the chain ends, which are ready (unordered, possibly
/// repeated).
///
/// The chains are followed all at once, one step per round: each round looks up the blocking
/// edges of the whole frontier in one parallel, prefetching loop (the lookups wait on scattered
/// reads; chains are short, so there are few rounds). An edge that joins a frontier is flagged,
/// and a chain that reaches a wanted or flagged edge stops there: the rest of it is followed
/// once, by whichever chain got there first. (Two chains that reach an edge in the same round
/// may both take it; that only repeats work.)
fn follow_chains(mesh: &Mesh, wants: &[bool]) -> (Vec<AtomicBool>, Vec<u32>) {
    // Written out, not left to zero pages: scattered first touches of fresh pages would each
    // fault (measured: 4-12 ms a pass instead of 0.4-5 on a mesh of 2.6M edges).
    let reached: Vec<AtomicBool> = (0..wants.len()).into_par_iter().map(|_| AtomicBool::new(false)).collect();
    let mut frontier = set_flags(wants);
    let mut ends = Vec::new();
    while !frontier.is_empty() {
        let blockers = mesh.blocking_edges(&frontier);
        let (done, next): (Vec<u32>, Vec<u32>) = frontier
            .par_iter()
            .zip(&blockers)
            .with_min_len(1024)
            .fold(
                || (Vec::new(), Vec::new()),
                |(mut done, mut next), (&x, &b)| {
                    if b == x {
                        done.push(x);
                    } else if !wants[b as usize] && !reached[b as usize].load(Ordering::Relaxed) {
                        reached[b as usize].store(true, Ordering::Relaxed);
                        next.push(b);
                    }
                    (done, next)
                },
            )
            .reduce(
                || (Vec::new(), Vec::new()),
                |(mut a, mut b), (c, d)| {
                    a.extend(c);
                    b.extend(d);
                    (a, b)
                },
            );
        ends.extend(done);
        frontier = next;
    }
    (reached, ends)
}

/// Whether each edge is wanted or on a wanted edge's blocker chain.
pub fn chain_flags(mesh: &Mesh, wants: &[bool]) -> Vec<bool> {
    let (reached, _) = follow_chains(mesh, wants);
    reached.into_par_iter().zip(wants).map(|(r, &w)| w || r.into_inner()).collect()
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
    let (_, mut ends) = follow_chains(mesh, wants);
    ends.par_sort_unstable();
    ends.dedup();
    ends
}

/// Splits the given ready edges (see [`Mesh::split_edges`]): each new vertex is computed from its
/// diamond and written with its edges and faces in the same parallel pass, and each of the four
/// edges is asked right there whether it wants a split for `view` (the state update of the
/// edges a split makes or changes, while their end points are in cache). Returns the answers
/// for `[e1, e2, e3, e4]`, split by split; the split edges' slots now hold their first halves.
pub fn apply_splits(mesh: &mut Mesh, ready: &[u32], params: &Params, view: &View) -> Vec<[bool; 4]> {
    mesh.split_edges_judged(ready, |d| split_vertex(d, params), |edge, mid| wants_edge(view, edge, mid))
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
