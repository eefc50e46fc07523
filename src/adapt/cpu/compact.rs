//! Memory management and buffer compaction (paper §5.2, §5.5): dead entities are squeezed out,
//! and buffer capacity follows the face count with `n_alloc` slack — grown to `n + n_alloc`
//! when a pass's splits need more than there is (`n` what they need), shrunk back when above
//! `n + 2 n_alloc` after a compaction.
//!
//! Compaction can also put the buffers in spatial order (`Mesh::compact_in_spatial_order`): a
//! pass over an ordered mesh reads its neighbours from nearby memory, ~3 times faster than over
//! a mesh whose entities were appended split by split, but ordering costs ~15 such passes. So a
//! mesh kept between cameras is ordered, before the next camera's passes, once the faces
//! appended since its last ordering outnumber the ordered ones ([`scattered`]); compactions
//! during a run keep the order. Between cameras the host holds the mesh (the previous output),
//! so on the GPU backend it computes the order and the device copy only follows the new ids.

use crate::mesh::{Mesh, Renumbering};

/// Slack kept in the buffers, in faces (vertices and edges scale with it).
pub const N_ALLOC: usize = 65_536;

/// The slack of the vertex, edge and face buffers: `N_ALLOC` faces' worth of each.
pub const SLACK: (usize, usize, usize) = (N_ALLOC / 2, N_ALLOC * 3 / 2, N_ALLOC);

/// Removes dead entities, keeping the order of the others, and keeps capacities within the
/// slack policy.
pub fn compact(mesh: &mut Mesh) {
    mesh.compact();
    fit_all(mesh);
}

/// Removes dead entities and puts the others in spatial order, keeping capacities within the
/// slack policy; returns the renumbering.
pub fn order(mesh: &mut Mesh) -> Renumbering {
    let order = mesh.compact_in_spatial_order_with_room(SLACK);
    fit_all(mesh);
    order
}

/// Makes room for `splits` more splits: a buffer too small for them grows to what they need
/// plus the slack (the paper's reallocation to `n_f + n_alloc`), not to twice its size.
pub fn make_room(mesh: &mut Mesh, splits: usize) {
    grow(&mut mesh.vertices, splits, SLACK.0);
    grow(&mut mesh.edges, 3 * splits, SLACK.1);
    grow(&mut mesh.faces, 2 * splits, SLACK.2);
}

fn grow<T>(buf: &mut Vec<T>, added: usize, slack: usize) {
    if buf.capacity() < buf.len() + added {
        buf.reserve_exact(added + slack);
    }
}

fn fit_all(mesh: &mut Mesh) {
    fit(&mut mesh.vertices, SLACK.0);
    fit(&mut mesh.edges, SLACK.1);
    fit(&mut mesh.faces, SLACK.2);
}

/// Whether a mesh of `faces` faces, `ordered` of which were in spatial order, is worth ordering
/// again: more of it appended than ordered.
pub fn scattered(faces: usize, ordered: usize) -> bool {
    faces > 2 * ordered
}

fn fit<T>(buf: &mut Vec<T>, slack: usize) {
    let n = buf.len();
    if buf.capacity() < n + slack / 4 {
        buf.reserve_exact(n + slack - buf.len());
    } else if buf.capacity() > n + 2 * slack {
        buf.shrink_to(n + slack);
    }
}
