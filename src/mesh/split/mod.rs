//! Edge split (paper §3, Figure 2; §5.3 steps 2–4): one edge becomes two, its two faces four.
//!
//! Naming follows Figure 2: the split edge runs `a = v_ev1 -> b = v_ev2`; `t = v_t` is the corner
//! opposite it in the face `f1` on its left, `d = v_d` the corner opposite it in `f2` on its right.
//! After the split the new vertex `m = v_nv` joins `e1 = (a, m)` (the old edge's slot),
//! `e3 = (m, b)`, `e2 = (m, t)` and `e4 = (m, d)`; `f1` and `f2` keep the halves at `a`, the new
//! faces `f3` and `f4` take the halves at `b`.

pub mod altitude;
pub mod landform;
pub mod position;

use crate::mesh::batch::Buffers;
use crate::mesh::{Diamond, Edge, EdgeKind, FaceKind, Mesh, Vertex};
use glam::DVec3;

/// Where a split happens: the edge, its end points and the corners opposite it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SplitSite {
    pub edge: u32,
    pub a: u32,
    pub b: u32,
    pub t: u32,
    pub d: u32,
    pub f1: u32,
    pub f2: u32,
}

/// Entities touched by a split: the new vertex, edges `[e1, e2, e3, e4]`, faces `[f1, f2, f3, f4]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Split {
    pub v: u32,
    pub e: [u32; 4],
    pub f: [u32; 4],
}

/// Kinds of `[e1, e2, e3, e4]` after splitting an edge of kind `kind` between faces `f1`, `f2`
/// (§3.2): halves keep the kind; the new inner edges take their face's kind (land faces give
/// continent edges).
pub fn split_kinds(kind: EdgeKind, f1: FaceKind, f2: FaceKind) -> [EdgeKind; 4] {
    let inner = |f: FaceKind| match f {
        FaceKind::Sea => EdgeKind::Sea,
        FaceKind::Land => EdgeKind::Continent,
    };
    [kind, inner(f1), kind, inner(f2)]
}

impl Mesh {
    /// The split site of edge `e`, if `e` is the refinement edge of both its faces.
    pub fn split_site(&self, e: u32) -> Option<SplitSite> {
        let edge = &self.edges[e as usize];
        let (f1, f2) = (edge.f[0], edge.f[1]);
        let (x, y) = (&self.faces[f1 as usize], &self.faces[f2 as usize]);
        if x.e[0] != e || y.e[0] != e {
            return None;
        }
        // f1 = (t, a, b) with `e[1] = (b, t)`, f2 = (d, b, a) with `e[2] = (d, b)`.
        let [a, b] = edge.v;
        let (t, d) = (self.edges[x.e[1] as usize].other(b), self.edges[y.e[2] as usize].other(b));
        Some(SplitSite { edge: e, a, b, t, d, f1, f2 })
    }

    /// The refinement edge that must be split before `e` can be: `e` itself when it is ready.
    pub fn blocking_edge(&self, e: u32) -> u32 {
        let edge = &self.edges[e as usize];
        for &f in &edge.f {
            let r = self.faces[f as usize].e[0];
            if r != e {
                return r;
            }
        }
        e
    }

    /// [`Mesh::blocking_edge`] of each of `edges`, in parallel, asking for each edge's memory
    /// 16 edges ahead and for its faces 8 ahead (the loop waits on those scattered reads).
    pub fn blocking_edges(&self, edges: &[u32]) -> Vec<u32> {
        use super::prefetch::prefetch;
        use rayon::prelude::*;
        let mut out = vec![0u32; edges.len()];
        out.par_chunks_mut(512).zip(edges.par_chunks(512)).for_each(|(out, chunk)| {
            for (k, (o, &e)) in out.iter_mut().zip(chunk).enumerate() {
                if let Some(&x) = chunk.get(k + 16) {
                    prefetch(self.edges.as_ptr().wrapping_add(x as usize));
                }
                if let Some(&x) = chunk.get(k + 8) {
                    for f in self.edges[x as usize].f {
                        prefetch(self.faces.as_ptr().wrapping_add(f as usize));
                    }
                }
                *o = self.blocking_edge(e);
            }
        });
        out
    }

    /// Splits the edge at `site`, inserting `vertex` with inner edge kinds `kinds` (`[e1..e4]`).
    /// Lengths and level-of-detail bounds of the four edges are set; the new vertex keeps the
    /// split edge's bounds for its collapse.
    pub fn split_edge(&mut self, site: &SplitSite, vertex: Vertex, kinds: [EdgeKind; 4]) -> Split {
        let split = self.split_ids(site, 0);
        assert_eq!(self.split_site(site.edge).as_ref(), Some(site), "not a split site of this mesh");
        // SAFETY: the one edge is ready, checked just above.
        unsafe { self.split_edges_judged(&[site.edge], |_| (vertex, kinds), |_, _| ()) };
        split
    }

    /// Splits many ready edges at once (each the refinement edge of both its faces, so no two
    /// share a face; a batch holds each edge once), in parallel: the `i`-th split gets the ids
    /// of [`Mesh::split_ids`] and the new vertex and edge kinds `make` computes from its
    /// [`Diamond`]. Each split reads its diamond once, then computes and writes while it is in
    /// cache. It owns its edge, its two faces and its new slots; the only entities two splits
    /// can share are an outer edge (each relinks the face slot of its own face) and a corner
    /// vertex (only the split whose edge it points to moves its edge link), so those two writes
    /// are single-word atomic stores and everything else is plain. Returns the number of splits.
    ///
    /// # Panics
    /// When the edges are not distinct and in increasing order, or one is not ready; nothing
    /// is split then.
    pub fn split_edges<F>(&mut self, edges: &[u32], make: F) -> usize
    where
        F: Fn(&Diamond) -> (Vertex, [EdgeKind; 4]) + Sync,
    {
        assert!(edges.windows(2).all(|w| w[0] < w[1]), "the edges to split must be distinct, in increasing order");
        if let Some(&e) = edges.iter().find(|&&e| self.split_site(e).is_none()) {
            panic!("edge {e} is not ready to split");
        }
        // SAFETY: checked just above.
        unsafe { self.split_edges_judged(edges, make, |_, _| ()).len() }
    }

    /// [`Mesh::split_edges`], asking `judge` about each split's four edges `[e1, e2, e3, e4]`
    /// as written, with their midpoints, while they are at hand: returns its answers, split by
    /// split in the order of `edges`. It does not check the edges first.
    ///
    /// # Safety
    /// The edges must be distinct ids of this mesh, each ready ([`Mesh::split_site`] is
    /// `Some`): a split reads ahead the diamonds of the splits after it, and two splits of one
    /// edge would race.
    pub unsafe fn split_edges_judged<F, J, T>(&mut self, edges: &[u32], make: F, judge: J) -> Vec<[T; 4]>
    where
        F: Fn(&Diamond) -> (Vertex, [EdgeKind; 4]) + Sync,
        J: Fn(&Edge, DVec3) -> T + Sync,
        T: Send,
    {
        use rayon::prelude::*;
        let n = edges.len();
        self.vertices.reserve(n);
        self.edges.reserve(3 * n);
        self.faces.reserve(2 * n);
        let (nv, ne, nf) = (self.vertices.len(), self.edges.len(), self.faces.len());
        let radius = self.radius;
        let bufs = Buffers {
            v: self.vertices.as_mut_ptr(),
            e: self.edges.as_mut_ptr(),
            f: self.faces.as_mut_ptr(),
            sizes: (nv, ne, nf),
        };
        // Each thread splits whole chunks in order, so it can ask for the memory of the next
        // splits of its chunk ahead of time (see `Buffers::prefetch_split`).
        const CHUNK: usize = 512;
        // The `k`-th split of chunk `c`.
        let split = |c: usize, chunk: &[u32], k: usize| {
            // SAFETY: see `Buffers::split` and `Buffers::prefetch_split`; the reservations
            // above hold the new slots, and no other split writes this split's diamond.
            let made = unsafe {
                bufs.prefetch_split(chunk, k);
                let diamond = bufs.diamond(chunk[k], radius);
                let (vertex, kinds) = make(&diamond);
                bufs.split(&diamond, vertex, kinds, c * CHUNK + k)
            };
            made.map(|(edge, mid)| judge(&edge, mid))
        };
        let answers: Vec<[T; 4]> = if n <= CHUNK {
            // One chunk (single splits while building the base mesh, the last passes of an
            // adaption): no threads to wake.
            (0..n).map(|k| split(0, edges, k)).collect()
        } else {
            edges
                .par_chunks(CHUNK)
                .enumerate()
                .flat_map_iter(|(c, chunk)| (0..chunk.len()).map(move |k| split(c, chunk, k)))
                .collect()
        };
        // SAFETY: every slot up to the new lengths was written by exactly one split above.
        unsafe {
            self.vertices.set_len(nv + n);
            self.edges.set_len(ne + 3 * n);
            self.faces.set_len(nf + 2 * n);
        }
        answers
    }

    /// Entities of the `i`-th split of a batch at `site`: new vertex `m`, edges `e1` (the split
    /// edge's slot) and appended `e2, e3, e4`, faces `f1, f2` and appended `f3, f4`.
    pub fn split_ids(&self, site: &SplitSite, i: usize) -> Split {
        let i = i as u32;
        let (m, e2, f3) =
            (self.vertices.len() as u32 + i, self.edges.len() as u32 + 3 * i, self.faces.len() as u32 + 2 * i);
        Split { v: m, e: [site.edge, e2, e2 + 1, e2 + 2], f: [site.f1, site.f2, f3, f3 + 1] }
    }

    /// Splits edge `e`, first splitting whatever refinement edges block it (newest-vertex
    /// bisection closure). `make` gives the new vertex and edge kinds for each split site.
    /// Returns the splits in the order performed.
    pub fn refine_edge<F>(&mut self, e: u32, make: &mut F) -> Vec<Split>
    where
        F: FnMut(&Mesh, &SplitSite) -> (Vertex, [EdgeKind; 4]),
    {
        let mut done = Vec::new();
        let mut stack = vec![e];
        while let Some(&top) = stack.last() {
            let blocker = self.blocking_edge(top);
            if blocker != top {
                stack.push(blocker);
                continue;
            }
            let site = self.split_site(top).expect("refinement edge of both faces");
            let (v, kinds) = make(self, &site);
            done.push(self.split_edge(&site, v, kinds));
            stack.pop();
        }
        done
    }
}
