//! Parallel edge splits (paper §5.3, Algorithm 2 steps 3–6): one parallel pass in which each
//! split of the ready list (`select.rs`) computes its new vertex from its four neighbours
//! (positions by eq. 2 / eq. 7–9, altitudes by step 6 and eq. 10–12: `crate::mesh::split`) and
//! makes the topology change. The device twin is `adapt/gpu/split.rs` with
//! `shaders/adapt/split.wgsl`.
//!
//! The paper's step 7 (normals of `f1..f4` and of the new vertex) is not a split's work here: the
//! paper keeps normals for its renderer (12 bytes a face, 24 a vertex), while every consumer of
//! the adapted mesh (view glb, tiles, snapshots) takes area-weighted vertex normals of the final
//! mesh from its `f64` positions (`export::surface_normals`), which costs no memory per vertex
//! and cannot go stale after a collapse.

use super::state::wants_edge;
use crate::adapt::camera::View;
use crate::mesh::split::altitude::split_vertex;
use crate::mesh::Mesh;
use crate::params::Params;

/// Splits the given ready edges (see [`Mesh::split_edges`]): each new vertex is computed from its
/// diamond and written with its edges and faces in the same parallel pass, and each of the four
/// edges is asked right there whether it wants a split for `view` (the state update of the
/// edges a split makes or changes, while their end points are in cache). Returns the answers
/// for `[e1, e2, e3, e4]`, split by split; the split edges' slots now hold their first halves.
pub fn apply_splits(mesh: &mut Mesh, ready: &[u32], params: &Params, view: &View) -> Vec<[bool; 4]> {
    super::compact::make_room(mesh, ready.len());
    // SAFETY: the split list holds distinct ready edges of this mesh ([`Selection::select`]).
    let guide = mesh.guide.clone();
    let guide = guide.as_deref();
    unsafe {
        mesh.split_edges_judged(ready, |d| split_vertex(d, params, guide), |edge, mid| wants_edge(view, edge, mid))
    }
}
