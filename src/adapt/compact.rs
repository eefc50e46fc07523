//! Memory management and buffer compaction (paper §5.2, §5.5): dead entities are squeezed out,
//! and buffer capacity follows the face count with `n_alloc` slack — grown to `n + n_alloc`
//! when short, shrunk back when above `n + 2 n_alloc`.

use crate::mesh::Mesh;

/// Slack kept in the buffers, in faces (vertices and edges scale with it).
pub const N_ALLOC: usize = 65_536;

/// Removes dead entities and keeps capacities within the slack policy.
pub fn compact(mesh: &mut Mesh) {
    mesh.compact();
    fit(&mut mesh.faces, N_ALLOC);
    fit(&mut mesh.edges, N_ALLOC * 3 / 2);
    fit(&mut mesh.vertices, N_ALLOC / 2);
}

fn fit<T>(buf: &mut Vec<T>, slack: usize) {
    let n = buf.len();
    if buf.capacity() < n + slack / 4 {
        buf.reserve_exact(n + slack - buf.len());
    } else if buf.capacity() > n + 2 * slack {
        buf.shrink_to(n + slack);
    }
}
