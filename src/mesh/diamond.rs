//! What a split reads (paper §3 Figure 2, §5.3 steps 5–6): the split edge, its two faces and
//! the four corner vertices `a, b, t, d` of the diamond they form, gathered once.
//!
//! The new vertex is a function of these alone (that is what makes the terrain reproducible),
//! and the topology change that follows needs nothing else of the old mesh, so a batch of
//! splits reads each diamond once, computes its vertex and writes the result while the diamond
//! is still in cache.

use super::{Edge, Face, Mesh, SplitSite, Vertex};
use glam::DVec3;

/// The split edge, its faces and its corners, copied out of the mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Diamond {
    pub site: SplitSite,
    /// The split edge as it is before the split.
    pub edge: Edge,
    /// Faces `f1` (left of `a -> b`) and `f2` (right) before the split.
    pub faces: [Face; 2],
    /// Corners `a, b, t, d` (see [`SplitSite`]). Their edge links are not copied (other splits
    /// of a batch may move them) and read [`super::NONE`].
    pub corners: [Vertex; 4],
    /// Radius of the base sphere, metres.
    pub radius: f64,
}

impl Diamond {
    /// The diamond of `site` in `mesh`.
    pub fn new(mesh: &Mesh, site: &SplitSite) -> Diamond {
        let corner = |v: u32| Vertex { edge: super::NONE, ..mesh.vertices[v as usize] };
        Diamond {
            site: *site,
            edge: mesh.edges[site.edge as usize],
            faces: [mesh.faces[site.f1 as usize], mesh.faces[site.f2 as usize]],
            corners: [site.a, site.b, site.t, site.d].map(corner),
            radius: mesh.radius,
        }
    }

    /// The start `a` of the split edge.
    #[inline]
    pub fn a(&self) -> &Vertex {
        &self.corners[0]
    }
    /// The end `b` of the split edge.
    #[inline]
    pub fn b(&self) -> &Vertex {
        &self.corners[1]
    }
    /// The corner `t` of `f1` opposite the split edge.
    #[inline]
    pub fn t(&self) -> &Vertex {
        &self.corners[2]
    }
    /// The corner `d` of `f2` opposite the split edge.
    #[inline]
    pub fn d(&self) -> &Vertex {
        &self.corners[3]
    }

    /// Positions of `a, b, t, d`.
    #[inline]
    pub fn positions(&self) -> [DVec3; 4] {
        self.corners.map(|v| v.p())
    }

    /// Length of the split edge, metres (as [`Mesh::edge_length`]).
    #[inline]
    pub fn edge_length(&self) -> f64 {
        self.a().p().distance(self.b().p())
    }
}
