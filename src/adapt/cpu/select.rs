//! Split-list compaction (paper §5.3, Algorithm 2 steps 1–2): the edges a pass splits, every
//! wanted edge that is the refinement edge of both its faces and, for the others, the end of
//! their chain of blocking refinement edges; and the demanded edges (the wanted ones and their
//! chains) that no collapse may undo. The device twin is `adapt/gpu/select.rs` with
//! `shaders/adapt/select.wgsl`.

use crate::mesh::Mesh;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// The chain ends that [`follow_chains`] found: the wanted edges that are ready, in the order
/// of the wanted list, and the ends of longer chains (unordered, possibly repeated).
struct Ends {
    wanted: Vec<u32>,
    blocking: Vec<u32>,
}

/// Follows the blocker chain of every wanted edge (`wanted`, listing the set `wants`): returns
/// the chain ends, which are ready, and the edges the chains reached besides the wanted ones,
/// which are flagged in `reached` (all clear before).
///
/// The chains are followed all at once, one step per round: each round looks up the blocking
/// edges of the whole frontier in one parallel, prefetching loop (the lookups wait on scattered
/// reads; chains are short, so there are few rounds). An edge that joins a frontier is flagged,
/// and a chain that reaches a wanted or flagged edge stops there: the rest of it is followed
/// once, by whichever chain got there first. (Two chains that reach an edge in the same round
/// may both take it; that only repeats work.)
fn follow_chains(mesh: &Mesh, wants: &[bool], wanted: Vec<u32>, reached: &[AtomicBool]) -> (Ends, Vec<u32>) {
    let mut frontier = wanted;
    let mut ends = Ends { wanted: Vec::new(), blocking: Vec::new() };
    let mut visited = Vec::new();
    for round in 0.. {
        if frontier.is_empty() {
            break;
        }
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
        if round == 0 {
            ends.wanted = done;
        } else {
            ends.blocking.extend(done);
        }
        visited.extend_from_slice(&next);
        frontier = next;
    }
    (ends, visited)
}

/// `n` clear flags, written out rather than left to zero pages: scattered first touches of
/// fresh pages would each fault (measured: 4-12 ms a pass instead of 0.4-5 on a mesh of 2.6M
/// edges).
fn clear_flags(n: usize) -> Vec<AtomicBool> {
    (0..n).into_par_iter().map(|_| AtomicBool::new(false)).collect()
}

/// Whether each edge is wanted or on a wanted edge's blocker chain.
pub fn chain_flags(mesh: &Mesh, wants: &[bool]) -> Vec<bool> {
    let reached = clear_flags(wants.len());
    follow_chains(mesh, wants, set_flags(wants), &reached);
    reached.into_par_iter().zip(wants).map(|(r, &w)| w || r.into_inner()).collect()
}

/// Edges that must be split for the wanted ones to be: the wanted edges and every refinement
/// edge on their blocking chains ([`chain_flags`]). A vertex whose faces hold such an edge must
/// not collapse, or a forced split would be undone as soon as it is made.
pub fn demanded(mesh: &Mesh, wants: &[bool]) -> Vec<bool> {
    chain_flags(mesh, wants)
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

/// Picks the edges to split, pass after pass, keeping the chains' flags between passes (they
/// are cleared where a pass set them instead of made anew for every edge).
#[derive(Default)]
pub struct Selection {
    reached: Vec<AtomicBool>,
}

impl Selection {
    /// The edges to split this pass: every wanted edge that is the refinement edge of both its
    /// faces, and for the others the refinement edge that blocks them (followed until one is
    /// ready). Sorted and without repeats, so the pass is deterministic.
    pub fn select(&mut self, mesh: &Mesh, wants: &[bool]) -> Vec<u32> {
        if self.reached.len() < wants.len() {
            // Twice what is needed (at least the edge buffer's capacity), so that an adaption's
            // growing mesh makes the flags anew only a few times.
            self.reached = clear_flags(mesh.edges.capacity().max(2 * wants.len()));
        }
        let (ends, visited) = follow_chains(mesh, wants, set_flags(wants), &self.reached);
        visited.par_iter().for_each(|&e| self.reached[e as usize].store(false, Ordering::Relaxed));
        // The ready wanted edges come in order (the wanted list is); the ends of longer chains
        // are not wanted edges, so sorting them alone and merging gives the sorted union.
        let mut blocking = ends.blocking;
        blocking.par_sort_unstable();
        blocking.dedup();
        merge_sorted(&ends.wanted, &blocking)
    }
}

/// The sorted union of two sorted lists without common elements.
fn merge_sorted(a: &[u32], b: &[u32]) -> Vec<u32> {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        if a[i] < b[j] {
            out.push(a[i]);
            i += 1;
        } else {
            out.push(b[j]);
            j += 1;
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    out
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
