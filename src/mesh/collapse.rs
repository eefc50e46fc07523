//! Vertex collapse (paper §3, Figure 2; §5.4): the exact inverse of an edge split, and buffer
//! compaction (§5.5).
//!
//! A vertex `m` may be collapsed when it was made by a split (not a base vertex) and its four
//! faces are still the four faces that split made: each has `m` as its newest vertex. Then the
//! incident edges `e1..e4` necessarily share one split level, the paper's collapse condition.

use super::split::DEAD;
use super::{EdgeKind, Face, Mesh};

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
        if vert.level == 0 || vert.edge >= DEAD {
            return None;
        }
        let e1 = vert.edge;
        let edge1 = &self.edges[e1 as usize];
        if edge1.v[1] != m {
            return None;
        }
        let (f1, f2) = (edge1.f[0], edge1.f[1]);
        let (x1, x2) = (&self.faces[f1 as usize], &self.faces[f2 as usize]);
        if x1.v[0] != m || x2.v[0] != m {
            return None;
        }
        let e2 = x1.e[2];
        let f3 = self.edges[e2 as usize].f[1];
        let x3 = &self.faces[f3 as usize];
        let e4 = x2.e[1];
        let f4 = self.edges[e4 as usize].f[0];
        let x4 = &self.faces[f4 as usize];
        if x3.v[0] != m || x4.v[0] != m || x3.e[2] != x4.e[1] || x4.e[2] != e4 {
            return None;
        }
        let e3 = x3.e[2];
        let level = edge1.level;
        if [e2, e3, e4].iter().any(|&e| self.edges[e as usize].level != level) {
            return None;
        }
        Some(CollapseSite {
            v: m,
            e: [e1, e2, e3, e4],
            f: [f1, f2, f3, f4],
            a: edge1.v[0],
            b: x3.v[1],
            t: x1.v[1],
            d: x2.v[2],
        })
    }

    /// Collapses the vertex at `site`, restoring the edge and the two faces it was split from.
    /// The removed vertex, edges and faces are marked dead until [`Mesh::compact`].
    pub fn collapse_vertex(&mut self, site: &CollapseSite) {
        let CollapseSite { v: m, e: [e1, e2, e3, e4], f: [f1, f2, f3, f4], a, b, t, d } = *site;
        let (x1, x2, x3, x4) =
            (self.faces[f1 as usize], self.faces[f2 as usize], self.faces[f3 as usize], self.faces[f4 as usize]);
        let (bt, ta, ad, db) = (x3.e[0], x1.e[0], x2.e[0], x4.e[0]);
        self.faces[f1 as usize] = Face { v: [t, a, b], e: [e1, bt, ta], ..x1 };
        self.faces[f2 as usize] = Face { v: [d, b, a], e: [e1, ad, db], ..x2 };
        self.replace_face(bt, f3, f1);
        self.replace_face(db, f4, f2);

        let k1 = self.edges[e1 as usize].kind;
        let k3 = self.edges[e3 as usize].kind;
        let kind = if k1 == k3 || k3 == EdgeKind::River { k1 } else { k3 };
        let length = self.pos(a).distance(self.pos(b)) as f32;
        let [lod_len, lod_radius] = self.vertices[m as usize].parent_lod;
        let edge = &mut self.edges[e1 as usize];
        edge.v = [a, b];
        edge.lod_len = lod_len;
        edge.lod_radius = lod_radius;
        edge.level -= 1;
        edge.kind = kind;
        edge.length = length;

        for (v, gone, keep) in [(b, e3, e1), (t, e2, ta), (d, e4, ad)] {
            if self.vertices[v as usize].edge == gone {
                self.vertices[v as usize].edge = keep;
            }
        }
        self.vertices[m as usize].edge = DEAD;
        for e in [e2, e3, e4] {
            self.edges[e as usize].v = [DEAD; 2];
        }
        for f in [f3, f4] {
            self.faces[f as usize].v = [DEAD; 3];
        }
    }

    /// Removes dead vertices, edges and faces, keeping the order of the live ones and renumbering
    /// every reference.
    pub fn compact(&mut self) {
        fn remap<T>(items: &mut Vec<T>, dead: impl Fn(&T) -> bool) -> Vec<u32> {
            let mut map = vec![DEAD; items.len()];
            let mut next = 0u32;
            for (i, item) in items.iter().enumerate() {
                if !dead(item) {
                    map[i] = next;
                    next += 1;
                }
            }
            items.retain(|x| !dead(x));
            map
        }
        let vmap = remap(&mut self.vertices, |v| v.edge == DEAD);
        let emap = remap(&mut self.edges, |e| e.v[0] == DEAD);
        let fmap = remap(&mut self.faces, |f| f.v[0] == DEAD);
        if vmap.len() == self.vertices.len() && emap.len() == self.edges.len() && fmap.len() == self.faces.len() {
            return;
        }
        for v in &mut self.vertices {
            v.edge = emap[v.edge as usize];
        }
        for e in &mut self.edges {
            e.v = e.v.map(|x| vmap[x as usize]);
            e.f = e.f.map(|x| fmap[x as usize]);
        }
        for f in &mut self.faces {
            f.v = f.v.map(|x| vmap[x as usize]);
            f.e = f.e.map(|x| emap[x as usize]);
        }
    }
}
