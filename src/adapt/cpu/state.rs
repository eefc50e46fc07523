//! Vertex and edge state update (paper §5.1, Algorithm 1), data-parallel over the buffers.
//!
//! An edge wants a split when the criterion of [`View::wants_split`] holds for its bounds. The
//! paper's conflict rules follow from newest-vertex bisection: only a face's refinement edge —
//! its lowest split level — is split (other wanted edges wait for it, see `split.rs`), and a
//! vertex collapses only when its four faces are still those of its own split, i.e. all of
//! `e1..e4` share one split level, and when no edge of those faces wants a split.

use crate::adapt::camera::View;
use crate::mesh::prefetch::{prefetch, prefetch_vertex};
use crate::mesh::{CollapseSite, Edge, EdgeKind, Mesh, VertexFlags};
use glam::DVec3;
use rayon::prelude::*;

/// Whether edge `e` wants to be split for `view` (always inlined, like the criterion: the
/// state update's loop is this and nothing else).
#[inline(always)]
pub fn wants(mesh: &Mesh, view: &View, e: u32) -> bool {
    wants_edge(view, &mesh.edges[e as usize], mesh.midpoint(e))
}

/// Whether `edge`, with midpoint `mid`, wants to be split for `view`.
#[inline(always)]
pub fn wants_edge(view: &View, edge: &Edge, mid: DVec3) -> bool {
    view.wants_split(edge.lod.len() as f64, mid, edge.lod.radius() as f64, edge.kind == EdgeKind::Sea)
}

/// [`wants`] of the edges `edge_at(0..n)`, in order. Chunks run in parallel; each asks for the
/// end points of the edge 8 ahead, as the ends of a mesh's edges lie scattered over the vertex
/// buffer and the criterion needs their positions.
fn wants_of(mesh: &Mesh, view: &View, n: usize, edge_at: impl Fn(usize) -> u32 + Sync) -> Vec<bool> {
    const CHUNK: usize = 4096;
    const AHEAD: usize = 8;
    let mut out = vec![false; n];
    out.par_chunks_mut(CHUNK).enumerate().for_each(|(c, out)| {
        let base = c * CHUNK;
        for k in 0..out.len() {
            if k + AHEAD < out.len() {
                for v in mesh.edges[edge_at(base + k + AHEAD) as usize].v {
                    prefetch_vertex(mesh.vertices.as_ptr().wrapping_add(v as usize));
                }
            }
            out[k] = wants(mesh, view, edge_at(base + k));
        }
    });
    out
}

/// Whether each edge wants to be split for `view`.
pub fn edge_wants(mesh: &Mesh, view: &View) -> Vec<bool> {
    wants_of(mesh, view, mesh.edges.len(), |k| k as u32)
}

/// Brings `flags` up to date after the splits of `split` (in order): `answers` are the
/// splits' own state updates of their edges `[e1, e2, e3, e4]` (see
/// [`super::split::apply_splits`]); `e1` took the split edge's slot, the others were appended
/// three by three.
pub fn record_splits(flags: &mut Vec<bool>, split: &[u32], answers: &[[bool; 4]]) {
    for (&e, a) in split.iter().zip(answers) {
        flags[e as usize] = a[0];
    }
    flags.extend(answers.iter().flat_map(|a| [a[1], a[2], a[3]]));
}

/// Brings `flags` up to date after collapses: the removed edges want nothing, and each restored
/// edge (`e1` of its site) gets its answer again.
pub fn update_after_collapses(mesh: &Mesh, view: &View, flags: &mut [bool], sites: &[CollapseSite]) {
    let redo: Vec<(u32, bool)> = sites.par_iter().map(|s| (s.e[0], wants(mesh, view, s.e[0]))).collect();
    for s in sites {
        for e in &s.e[1..] {
            flags[*e as usize] = false;
        }
    }
    for (e, w) in redo {
        flags[e as usize] = w;
    }
}

/// Vertices that may collapse now: made by a split, their four faces untouched since, no edge of
/// those faces demanded (see [`super::select::demanded`]), and the edge they were split from no longer wanting one.
/// Looks at the vertices `among`, or at all of them.
pub fn collapse_candidates(mesh: &Mesh, view: &View, demanded: &[bool], among: Option<&[u32]>) -> Vec<CollapseSite> {
    let check = |v: u32| {
        if !mesh.vertices[v as usize].flags.contains(VertexFlags::REFINED) {
            return None;
        }
        let site = mesh.collapse_site(v)?;
        let faces_quiet = site.f.iter().all(|&f| mesh.faces[f as usize].e.iter().all(|&e| !demanded[e as usize]));
        if !faces_quiet {
            return None;
        }
        let lod = mesh.vertices[v as usize].parent_lod;
        let centre = (mesh.pos(site.a) + mesh.pos(site.b)) * 0.5;
        let sea = mesh.edges[site.e[0] as usize].kind == EdgeKind::Sea;
        (!view.wants_split(lod.len() as f64, centre, lod.radius() as f64, sea)).then_some(site)
    };
    // Each check chases a vertex's edge, that edge's faces and theirs: ask for the first links
    // of that chain a few vertices ahead.
    let ahead = |v: u32, depth: usize| {
        let vert = &mesh.vertices[v as usize];
        if depth == 0 {
            prefetch_vertex(vert);
        } else if vert.flags.contains(VertexFlags::REFINED) && (vert.edge as usize) < mesh.edges.len() {
            let edge = &mesh.edges[vert.edge as usize];
            if depth == 1 {
                prefetch(edge);
            } else {
                for f in edge.f.into_iter().filter(|&f| (f as usize) < mesh.faces.len()) {
                    prefetch(&mesh.faces[f as usize]);
                }
            }
        }
    };
    let n = among.map_or(mesh.vertices.len(), <[u32]>::len);
    let vertex_at = |k: usize| among.map_or(k as u32, |a| a[k]);
    const CHUNK: usize = 4096;
    (0..n.div_ceil(CHUNK))
        .into_par_iter()
        .flat_map_iter(|c| {
            let range = c * CHUNK..((c + 1) * CHUNK).min(n);
            let end = range.end;
            range.filter_map(move |k| {
                for (depth, distance) in [(0, 12), (1, 8), (2, 4)] {
                    if k + distance < end {
                        ahead(vertex_at(k + distance), depth);
                    }
                }
                check(vertex_at(k))
            })
        })
        .collect()
}

/// The vertices that collapsing `sites` can have made collapsible: the newest vertices `t` and
/// `d` of the two faces each collapse restored, sorted and without repeats.
pub fn restored_apexes(sites: &[CollapseSite]) -> Vec<u32> {
    let mut out: Vec<u32> = sites.iter().flat_map(|s| [s.t, s.d]).collect();
    out.par_sort_unstable();
    out.dedup();
    out
}
