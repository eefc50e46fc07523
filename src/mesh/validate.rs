//! Structural checks of the mesh: a closed, consistently wound 2-manifold of genus 0 whose
//! buffers reference each other correctly, with face and edge types that agree (§3.2). Used by
//! tests and by `--check` style diagnostics.

use super::{EdgeKind, Mesh, NONE};

impl Mesh {
    /// Checks connectivity and winding; returns the first problem found.
    pub fn validate(&self) -> Result<(), String> {
        let nv = self.vertices.len() as u32;
        let ne = self.edges.len() as u32;
        let nf = self.faces.len() as u32;
        let mut uses = vec![0u32; ne as usize];
        for (fi, f) in self.faces.iter().enumerate() {
            let fi = fi as u32;
            if f.e.iter().any(|&e| e >= ne) {
                return Err(format!("face {fi} references a missing edge"));
            }
            // The corners as the edges give them (every edge index is in range now), then every
            // edge checked against them.
            let v = self.corners(fi);
            if v.iter().any(|&v| v >= nv) {
                return Err(format!("face {fi} references a missing vertex"));
            }
            if v[0] == v[1] || v[1] == v[2] || v[0] == v[2] {
                return Err(format!("face {fi} repeats a vertex"));
            }
            for i in 0..3 {
                let (a, b) = (v[(i + 1) % 3], v[(i + 2) % 3]);
                let edge = &self.edges[f.e[i] as usize];
                let side = if edge.v == [a, b] {
                    0
                } else if edge.v == [b, a] {
                    1
                } else {
                    return Err(format!("face {fi} slot {i}: edge {} does not join {a},{b}", f.e[i]));
                };
                if edge.f[side] != fi {
                    return Err(format!("edge {} does not point back to face {fi}", f.e[i]));
                }
                if edge.face_kind(fi) != self.face_kind(fi) {
                    return Err(format!("edges of face {fi} disagree on its kind"));
                }
                uses[f.e[i] as usize] += 1;
            }
            // Newest-vertex bisection: the two edges at the newest corner were made by the same
            // split (or both belong to the base shape), and the refinement edge is never of a
            // higher split level than they are.
            let [l0, l1, l2] = f.e.map(|e| self.edges[e as usize].level);
            if l1 != l2 || l0 > l1 {
                return Err(format!("face {fi} has edges of split levels {l0}, {l1}, {l2}"));
            }
            let n = self.face_area_vector(fi);
            let centre = (self.pos(v[0]) + self.pos(v[1]) + self.pos(v[2])) / 3.0;
            // Degenerate: no area, or a sliver whose area is a vanishing part of its longest
            // side's square (a well-shaped triangle has about a quarter).
            let longest = (0..3).map(|i| self.pos(v[i]).distance_squared(self.pos(v[(i + 1) % 3]))).fold(0.0, f64::max);
            if !n.is_finite() || !longest.is_finite() || n.length() <= 1e-9 * longest {
                return Err(format!("face {fi} is degenerate"));
            }
            if n.dot(centre) <= 0.0 {
                return Err(format!("face {fi} faces inwards"));
            }
        }
        for (ei, e) in self.edges.iter().enumerate() {
            if uses[ei] != 2 || e.f.contains(&NONE) {
                return Err(format!("edge {ei} is used by {} faces, not 2", uses[ei]));
            }
            if e.land > 3 {
                return Err(format!("edge {ei} has land bits {:#b} beyond its two faces", e.land));
            }
            let [a, b] = e.face_kinds();
            let expected = EdgeKind::between(a, b);
            if e.kind != expected && !(e.kind == EdgeKind::River && expected == EdgeKind::Continent) {
                return Err(format!("edge {ei} of kind {:?} lies between faces of kinds {a:?} and {b:?}", e.kind));
            }
        }
        for (vi, v) in self.vertices.iter().enumerate() {
            if v.edge >= ne || !self.edges[v.edge as usize].v.contains(&(vi as u32)) {
                return Err(format!("vertex {vi} points at edge {} that does not touch it", v.edge));
            }
            if !v.p().is_finite() || !v.ground.is_finite() || !v.water.is_finite() {
                return Err(format!("vertex {vi} has a non-finite position or altitude"));
            }
        }
        let euler = nv as i64 - ne as i64 + nf as i64;
        if euler != 2 {
            return Err(format!("Euler characteristic is {euler}, not 2 (V={nv}, E={ne}, F={nf})"));
        }
        self.check_edges_distinct()?;
        self.check_vertex_fans()
    }
}

impl Mesh {
    /// No two edges join the same two vertices.
    pub(super) fn check_edges_distinct(&self) -> Result<(), String> {
        let mut ends: Vec<(u32, u32, usize)> =
            self.edges.iter().enumerate().map(|(i, e)| (e.v[0].min(e.v[1]), e.v[0].max(e.v[1]), i)).collect();
        ends.sort_unstable();
        match ends.windows(2).find(|w| (w[0].0, w[0].1) == (w[1].0, w[1].1)) {
            Some(w) => Err(format!("edges {} and {} both join vertices {} and {}", w[0].2, w[1].2, w[0].0, w[0].1)),
            None => Ok(()),
        }
    }

    /// Around every vertex its faces form one fan: walking from face to face across the edges
    /// at the vertex comes back to the start after visiting every edge that touches it (no
    /// pinched vertex joining two sheets). And every vertex can be reached from vertex 0 (one
    /// piece). With the Euler characteristic, the surface is a sphere.
    pub(super) fn check_vertex_fans(&self) -> Result<(), String> {
        let adj = self.adjacency();
        for (vi, vert) in self.vertices.iter().enumerate() {
            let vi = vi as u32;
            let start = vert.edge;
            let (mut e, mut steps, degree) = (start, 0, adj.degree(vi));
            loop {
                // The face on the left of `e` as it leaves `vi`, then that face's other edge at `vi`.
                let edge = &self.edges[e as usize];
                let f = if edge.v[0] == vi { edge.f[0] } else { edge.f[1] };
                let next =
                    self.faces[f as usize].e.into_iter().find(|&x| x != e && self.edges[x as usize].v.contains(&vi));
                e = next.ok_or_else(|| format!("face {f} has one edge at vertex {vi}"))?;
                steps += 1;
                if e == start || steps > degree {
                    break;
                }
            }
            if e != start || steps != degree {
                return Err(format!("the faces around vertex {vi} do not form one fan of its {degree} edges"));
            }
        }
        let mut seen = vec![false; self.vertices.len()];
        let mut stack = vec![0u32];
        while let Some(v) = stack.pop() {
            if !std::mem::replace(&mut seen[v as usize], true) {
                stack.extend(adj.around(v).map(|(w, _)| w).filter(|&w| !seen[w as usize]));
            }
        }
        match seen.iter().position(|&s| !s) {
            Some(v) => Err(format!("vertex {v} cannot be reached from vertex 0: the mesh is in pieces")),
            None => Ok(()),
        }
    }
}
