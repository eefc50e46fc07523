//! Edge split (paper §3, Figure 2; §5.3 steps 2–4): one edge becomes two, its two faces four.
//!
//! Naming follows Figure 2: the split edge runs `a = v_ev1 -> b = v_ev2`; `t = v_t` is the corner
//! opposite it in the face `f1` on its left, `d = v_d` the corner opposite it in `f2` on its right.
//! After the split the new vertex `m = v_nv` joins `e1 = (a, m)` (the old edge's slot),
//! `e3 = (m, b)`, `e2 = (m, t)` and `e4 = (m, d)`; `f1` and `f2` keep the halves at `a`, the new
//! faces `f3` and `f4` take the halves at `b`.

use super::{Edge, EdgeKind, Face, FaceKind, Mesh, Vertex, VertexFlags, LOD_RADIUS, NONE};

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
        Some(SplitSite { edge: e, a: edge.v[0], b: edge.v[1], t: x.v[0], d: y.v[0], f1, f2 })
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

    /// Splits the edge at `site`, inserting `vertex` with inner edge kinds `kinds` (`[e1..e4]`).
    /// Lengths and level-of-detail bounds of the four edges are set; the new vertex keeps the
    /// split edge's bounds for its collapse.
    pub fn split_edge(&mut self, site: &SplitSite, mut vertex: Vertex, kinds: [EdgeKind; 4]) -> Split {
        let SplitSite { edge: e1, a, b, t, d, f1, f2 } = *site;
        let m = self.vertices.len() as u32;
        let (e2, e3, e4) = {
            let n = self.edges.len() as u32;
            (n, n + 1, n + 2)
        };
        let (f3, f4) = {
            let n = self.faces.len() as u32;
            (n, n + 1)
        };
        let old1 = self.faces[f1 as usize];
        let old2 = self.faces[f2 as usize];
        let parent = self.edges[e1 as usize];
        let level = parent.level + 1;
        let parent_mid = (self.pos(a) + self.pos(b)) * 0.5;

        // Faces: f1 = (m, t, a), f3 = (m, b, t), f2 = (m, a, d), f4 = (m, d, b).
        let face = |v: [u32; 3], e: [u32; 3], kind| Face { v, e, kind, _pad: [0; 3] };
        self.faces[f1 as usize] = face([m, t, a], [old1.e[2], e1, e2], old1.kind);
        self.faces.push(face([m, b, t], [old1.e[1], e2, e3], old1.kind));
        self.faces[f2 as usize] = face([m, a, d], [old2.e[1], e4, e1], old2.kind);
        self.faces.push(face([m, d, b], [old2.e[2], e3, e4], old2.kind));

        // Outer edges that moved to the new faces.
        self.replace_face(old1.e[1], f1, f3);
        self.replace_face(old2.e[2], f2, f4);

        // Edges.
        let mk = |v: [u32; 2], f: [u32; 2], kind| Edge {
            v,
            f,
            length: 0.0,
            lod_len: 0.0,
            lod_radius: 0.0,
            level,
            kind,
            _pad: 0,
        };
        self.edges[e1 as usize] = mk([a, m], [f1, f2], kinds[0]);
        self.edges.push(mk([m, t], [f1, f3], kinds[1]));
        self.edges.push(mk([m, b], [f3, f4], kinds[2]));
        self.edges.push(mk([m, d], [f4, f2], kinds[3]));

        // Vertices.
        vertex.edge = e1;
        vertex.parent_lod = [parent.lod_len, parent.lod_radius];
        vertex.flags.insert(kinds.iter().fold(VertexFlags::empty(), |acc, k| acc | k.flag()));
        self.vertices.push(vertex);
        if self.vertices[b as usize].edge == e1 {
            self.vertices[b as usize].edge = e3;
        }
        for e in [e1, e2, e3, e4] {
            let [p, q] = self.edges[e as usize].v.map(|v| self.pos(v));
            let len = p.distance(q);
            let offset = ((p + q) * 0.5).distance(parent_mid);
            let edge = &mut self.edges[e as usize];
            edge.length = len as f32;
            edge.lod_len = edge.length.min(parent.lod_len);
            edge.lod_radius = (LOD_RADIUS * edge.length).min(round_down(parent.lod_radius as f64 - offset));
        }
        Split { v: m, e: [e1, e2, e3, e4], f: [f1, f2, f3, f4] }
    }

    /// In edge `e`, replaces face `from` by face `to`.
    pub(super) fn replace_face(&mut self, e: u32, from: u32, to: u32) {
        let edge = &mut self.edges[e as usize];
        if edge.f[0] == from {
            edge.f[0] = to;
        } else {
            debug_assert_eq!(edge.f[1], from);
            edge.f[1] = to;
        }
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

/// `x` as the largest `f32` not above it, so nested balls stay nested after rounding.
fn round_down(x: f64) -> f32 {
    let v = x as f32;
    if v as f64 > x {
        v.next_down()
    } else {
        v
    }
}

/// Marks an entity removed by a collapse until the buffers are compacted.
pub(super) const DEAD: u32 = NONE - 1;
