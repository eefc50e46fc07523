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
        let mut uses = vec![0u8; ne as usize];
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
            let n = self.face_area_vector(fi);
            let centre = (self.pos(v[0]) + self.pos(v[1]) + self.pos(v[2])) / 3.0;
            if n.length() <= 0.0 || !n.is_finite() {
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
        Ok(())
    }
}
