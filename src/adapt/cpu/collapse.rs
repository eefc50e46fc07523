//! Parallel vertex collapses (paper §5.4, Algorithm 3). Candidates come from the state update;
//! their four faces are disjoint, so the collapses do not interfere.

use crate::mesh::{CollapseSite, Mesh};

/// Collapses every site; the removed entities stay marked dead until compaction.
pub fn apply_collapses(mesh: &mut Mesh, sites: &[CollapseSite]) -> usize {
    // SAFETY: the state update found each site on this mesh ([`Mesh::collapse_site`]), one per
    // candidate vertex.
    unsafe { mesh.collapse_vertices(sites) };
    sites.len()
}
