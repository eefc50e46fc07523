//! Vertex collapse (paper §3, Figure 2; §5.4): the exact inverse of an edge split.
//!
//! A vertex `m` may be collapsed when it was made by a split (not a base vertex) and its four
//! faces are still the four faces that split made: each has `m` as its newest vertex, which a
//! face tells by the slots its edges to `m` take. Then the incident edges `e1..e4` necessarily
//! share one split level, the paper's collapse condition.

use super::batch::Buffers;
use super::DEAD;
use super::{Mesh, VertexFlags};

/// Entities of a collapsible vertex: `[e1, e2, e3, e4]`, `[f1, f2, f3, f4]`, and `(a, b, t, d)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CollapseSite {
    pub v: u32,
    pub e: [u32; 4],
    pub f: [u32; 4],
    pub a: u32,
    pub b: u32,
    pub t: u32,
    pub d: u32,
}

impl Mesh {
    /// The collapse site of vertex `m`, or `None` when `m` cannot be collapsed now.
    pub fn collapse_site(&self, m: u32) -> Option<CollapseSite> {
        let vert = &self.vertices[m as usize];
        if !vert.flags.contains(VertexFlags::REFINED) || vert.edge >= DEAD {
            return None;
        }
        let e1 = vert.edge;
        let edge1 = &self.edges[e1 as usize];
        // A split edge's halves are one level above it (a hand-built mesh that marks a base
        // vertex refined has none to undo).
        if edge1.v[1] != m || edge1.level == 0 {
            return None;
        }
        // The four faces still those of the split: f1 = (m, t, a) left of e1 = (a, m) holds e1
        // in slot 1, f2 = (m, a, d) on its right in slot 2, f3 = (m, b, t) holds e2 = (m, t)
        // in slot 1 and f4 = (m, d, b) holds e4 = (m, d) in slot 2; each slot puts m in
        // corner 0 (see `Face`), and f3 and f4 share e3 = (m, b).
        let (f1, f2) = (edge1.f[0], edge1.f[1]);
        let (x1, x2) = (&self.faces[f1 as usize], &self.faces[f2 as usize]);
        if x1.e[1] != e1 || x2.e[2] != e1 {
            return None;
        }
        let (e2, e4) = (x1.e[2], x2.e[1]);
        let (edge2, edge4) = (&self.edges[e2 as usize], &self.edges[e4 as usize]);
        let (f3, f4) = (edge2.f[1], edge4.f[0]);
        let (x3, x4) = (&self.faces[f3 as usize], &self.faces[f4 as usize]);
        if x3.e[1] != e2 || x4.e[2] != e4 || x3.e[2] != x4.e[1] {
            return None;
        }
        let e3 = x3.e[2];
        let edge3 = &self.edges[e3 as usize];
        let level = edge1.level;
        if [edge2, edge3, edge4].iter().any(|e| e.level != level) {
            return None;
        }
        Some(CollapseSite {
            v: m,
            e: [e1, e2, e3, e4],
            f: [f1, f2, f3, f4],
            a: edge1.v[0],
            b: edge3.other(m),
            t: edge2.other(m),
            d: edge4.other(m),
        })
    }

    /// Collapses the vertex at `site`, restoring the edge and the two faces it was split from.
    /// The removed vertex, edges and faces are marked dead until [`Mesh::compact`].
    ///
    /// # Panics
    /// When `site` is not the vertex's current [`Mesh::collapse_site`] (stale, or made by hand).
    pub fn collapse_vertex(&mut self, site: &CollapseSite) {
        assert!(self.collapse_site(site.v).as_ref() == Some(site), "vertex {} cannot collapse as {site:?}", site.v);
        // SAFETY: the one site is the vertex's current one.
        unsafe { self.collapse_vertices(std::slice::from_ref(site)) };
    }

    /// Collapses many vertices at once, in parallel.
    ///
    /// # Safety
    /// Each site must be [`Mesh::collapse_site`] of its vertex in the current mesh, and the
    /// vertices distinct: the collapses then own disjoint faces and edges (each vertex's four
    /// faces are its own). A stale or repeated site makes writes out of bounds or races.
    pub unsafe fn collapse_vertices(&mut self, sites: &[CollapseSite]) {
        use rayon::prelude::*;
        let bufs = Buffers {
            v: self.vertices.as_mut_ptr(),
            e: self.edges.as_mut_ptr(),
            f: self.faces.as_mut_ptr(),
            sizes: (self.vertices.len(), self.edges.len(), self.faces.len()),
        };
        // SAFETY: each site owns its vertex, edges and faces (see `Buffers::collapse`).
        sites.par_iter().with_min_len(256).for_each(|site| unsafe { bufs.collapse(site) });
    }
}
