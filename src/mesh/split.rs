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
    pub fn split_edge(&mut self, site: &SplitSite, vertex: Vertex, kinds: [EdgeKind; 4]) -> Split {
        let ids = self.split_ids(0);
        let plan = self.plan_split(site, vertex, kinds, ids);
        self.vertices.push(plan.vertex);
        self.edges.extend_from_slice(&plan.new_edges);
        self.faces.extend_from_slice(&plan.new_faces);
        self.write_split(&plan);
        plan.split
    }

    /// Splits many ready edges at once (each the refinement edge of both its faces, so no two
    /// share a face). The plans are made in parallel from the unchanged mesh, then written:
    /// entities each split owns go in parallel-friendly bulk, shared edges' face links after.
    pub fn split_edges(&mut self, items: &[(SplitSite, Vertex, [EdgeKind; 4])]) -> Vec<Split> {
        use rayon::prelude::*;
        let plans: Vec<SplitPlan> = items
            .par_iter()
            .enumerate()
            .map(|(i, (site, v, kinds))| self.plan_split(site, *v, *kinds, self.split_ids(i)))
            .collect();
        self.vertices.extend(plans.iter().map(|p| p.vertex));
        self.edges.extend(plans.iter().flat_map(|p| p.new_edges));
        self.faces.extend(plans.iter().flat_map(|p| p.new_faces));
        for plan in &plans {
            self.write_split(plan);
        }
        plans.into_iter().map(|p| p.split).collect()
    }

    /// Ids the `i`-th split of a batch gets: vertex, edges `e2, e3, e4`, faces `f3, f4`.
    fn split_ids(&self, i: usize) -> (u32, u32, u32) {
        let i = i as u32;
        (self.vertices.len() as u32 + i, self.edges.len() as u32 + 3 * i, self.faces.len() as u32 + 2 * i)
    }

    /// Everything a split writes, computed from the mesh before it.
    fn plan_split(
        &self,
        site: &SplitSite,
        mut vertex: Vertex,
        kinds: [EdgeKind; 4],
        ids: (u32, u32, u32),
    ) -> SplitPlan {
        let SplitSite { edge: e1, a, b, t, d, f1, f2 } = *site;
        let (m, e2, f3) = ids;
        let (e3, e4, f4) = (e2 + 1, e2 + 2, f3 + 1);
        let old1 = self.faces[f1 as usize];
        let old2 = self.faces[f2 as usize];
        let parent = self.edges[e1 as usize];
        let level = parent.level + 1;
        let (pa, pb, pm) = (self.pos(a), self.pos(b), vertex.p());
        let parent_mid = (pa + pb) * 0.5;

        // Faces: f1 = (m, t, a), f3 = (m, b, t), f2 = (m, a, d), f4 = (m, d, b).
        let face = |v: [u32; 3], e: [u32; 3], kind| Face { v, e, kind, _pad: [0; 3] };
        let faces = [
            face([m, t, a], [old1.e[2], e1, e2], old1.kind),
            face([m, a, d], [old2.e[1], e4, e1], old2.kind),
            face([m, b, t], [old1.e[1], e2, e3], old1.kind),
            face([m, d, b], [old2.e[2], e3, e4], old2.kind),
        ];
        let edge = |v: [u32; 2], f: [u32; 2], kind, p: glam::DVec3, q: glam::DVec3| {
            let length = p.distance(q) as f32;
            let offset = ((p + q) * 0.5).distance(parent_mid);
            Edge {
                v,
                f,
                length,
                lod_len: length.min(parent.lod_len),
                lod_radius: (LOD_RADIUS * length).min(round_down(parent.lod_radius as f64 - offset)),
                level,
                kind,
                _pad: 0,
            }
        };
        let edges = [
            edge([a, m], [f1, f2], kinds[0], pa, pm),
            edge([m, t], [f1, f3], kinds[1], pm, self.pos(t)),
            edge([m, b], [f3, f4], kinds[2], pm, pb),
            edge([m, d], [f4, f2], kinds[3], pm, self.pos(d)),
        ];
        vertex.edge = e1;
        vertex.parent_lod = [parent.lod_len, parent.lod_radius];
        vertex.flags.insert(kinds.iter().fold(VertexFlags::empty(), |acc, k| acc | k.flag()));
        SplitPlan {
            split: Split { v: m, e: [e1, e2, e3, e4], f: [f1, f2, f3, f4] },
            vertex,
            own_faces: [faces[0], faces[1]],
            new_faces: [faces[2], faces[3]],
            own_edge: edges[0],
            new_edges: [edges[1], edges[2], edges[3]],
            relinks: [(old1.e[1], f1, f3), (old2.e[2], f2, f4)],
            b,
        }
    }

    /// Writes the parts of a plan that touch existing entities.
    fn write_split(&mut self, plan: &SplitPlan) {
        let [e1, _, e3, _] = plan.split.e;
        let [f1, f2, _, _] = plan.split.f;
        self.faces[f1 as usize] = plan.own_faces[0];
        self.faces[f2 as usize] = plan.own_faces[1];
        self.edges[e1 as usize] = plan.own_edge;
        for (e, from, to) in plan.relinks {
            self.replace_face(e, from, to);
        }
        if self.vertices[plan.b as usize].edge == e1 {
            self.vertices[plan.b as usize].edge = e3;
        }
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

/// What one split writes (see [`Mesh::split_edges`]).
struct SplitPlan {
    split: Split,
    vertex: Vertex,
    /// New contents of `f1`, `f2` and `e1`.
    own_faces: [Face; 2],
    own_edge: Edge,
    /// `f3, f4` and `e2, e3, e4`, appended.
    new_faces: [Face; 2],
    new_edges: [Edge; 3],
    /// Outer edges whose face link moves to a new face: `(edge, from, to)`.
    relinks: [(u32, u32, u32); 2],
    /// The old edge's second end, whose `edge` link may need to move to `e3`.
    b: u32,
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
