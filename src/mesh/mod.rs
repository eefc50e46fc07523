//! The planet mesh (paper §3, Table 3): vertex, edge and face buffers, their types (§3.2), and
//! the two atomic operations, edge split and vertex collapse (Figure 2).
//!
//! Refinement follows newest-vertex bisection: every face's first corner `v0` is its newest
//! vertex, and the edge opposite it (`e[0]`) is the face's refinement edge — the edge with the
//! lowest split level in the face, as §3.1 demands. An edge may be split only when it is the
//! refinement edge of both of its faces, so each split always sees the same four vertices
//! `v_ev1, v_ev2, v_t, v_d`. That is what makes the terrain reproducible whatever the order of
//! refinement.
//!
//! Positions are `f64` metres in the planet-centred frame (+Z = north pole, longitude 0 on +X): at
//! Earth radius an `f64` resolves ~1 nm, so the paper's 1 cm minimum edge length is far above the
//! rounding error.

mod batch;
pub mod channels;
mod collapse;
mod compact;
mod diamond;
pub mod guide;
mod kinds;
mod packed;
pub mod precipitation;
pub mod prefetch;
pub mod raster;
pub mod split;
pub mod validate;

pub use collapse::CollapseSite;
pub use compact::Renumbering;
pub use diamond::Diamond;
pub use kinds::{EdgeKind, FaceKind, VertexFlags};
pub use packed::{Lod, Tangent};
pub use split::{split_kinds, Split, SplitSite};

use glam::DVec3;

/// Marks an absent index.
pub const NONE: u32 = u32::MAX;
/// Marks an entity removed by a collapse until the buffers are compacted.
pub(crate) const DEAD: u32 = NONE - 1;

/// Most faces [`Mesh::edge_between`] walks around a vertex (a bisection mesh's vertices have
/// at most a few dozen).
const MAX_WALK: usize = 256;

/// One vertex (Table 3, "active vertices"): 56 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::NoUninit, bytemuck::AnyBitPattern)]
pub struct Vertex {
    /// Position, planet-centred metres.
    pub pos: [f64; 3],
    /// Ground altitude above the base sphere, metres. An `f64`, like the position: at the
    /// highest springs (12 km) an `f32` is only good to a millimetre, and a river drops less
    /// than that along a 1 cm edge (1 m/km), so its water would stop descending.
    pub ground: f64,
    /// Water altitude above the base sphere, metres (equals `ground` where dry).
    pub water: f64,
    /// An incident edge. For a vertex made by a split this is the half `e1` of the split edge,
    /// which tells a collapse which two edges to merge.
    pub edge: u32,
    /// Level-of-detail bounds of the edge whose split made this vertex, restored to that edge
    /// when the vertex collapses (see [`Edge::lod`]).
    pub parent_lod: Lod,
    /// Per-vertex random seed; a split vertex gets `s_ev1 + s_ev2` (§3.1).
    pub seed: u32,
    /// River vertices: the unit tangent pointing downstream (§4.2).
    pub tangent: Tangent,
    /// Types of the incident edges when the vertex was made (§3.2), and whether a split made it.
    pub flags: VertexFlags,
}

/// One edge (Table 3, "active edges"): 24 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::NoUninit, bytemuck::CheckedBitPattern)]
pub struct Edge {
    /// End points. `f[0]` is the face that walks `v[0] -> v[1]` counter-clockwise.
    pub v: [u32; 2],
    /// The two faces: left of `v[0] -> v[1]`, then right.
    pub f: [u32; 2],
    /// Bounds used by the refinement criterion `l/d > c`. The length is the edge's own, but
    /// never more than that of the edge whose split made it, so the criterion can only weaken
    /// from parent to child. The radius is that of a ball around the edge's midpoint that lies
    /// inside the parent edge's ball (it may be negative): distances are measured to this ball,
    /// so a child is never nearer than its parent. Together they make "wants to split"
    /// hereditary, and the adapted mesh for a camera the same whatever was adapted before.
    pub lod: Lod,
    /// Split level: incremented by each split, decremented by each collapse.
    pub level: u16,
    pub kind: EdgeKind,
    /// Which of the two faces are land: bit `i` for `f[i]`. A face's kind (§3.2) lives in its
    /// three edges, each on the face's side, rather than in the face (see [`Mesh::face_kind`]).
    pub land: u8,
}

/// One triangle (Table 3, "active faces"): 12 bytes.
///
/// A face names its edges only; its kind is kept by the edges ([`Edge::land`]). Its corners
/// `v0, v1, v2` (counter-clockwise seen from outside the planet, `v0` the newest vertex) follow
/// from them: `e[i]` is the edge opposite corner `i`, running `v[i+1] -> v[i+2]` as the face
/// walks it, so `e[0]` gives `v1, v2` (in its own order when the face is on its left, reversed
/// otherwise) and `e[1]` joins `v2` to `v0` (see [`Mesh::corners`]). Storing the corners too
/// would cost 12 bytes a face, 24 a vertex.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Face {
    /// `e[i]` is the edge opposite corner `i`; `e[0]` is the refinement edge.
    pub e: [u32; 3],
}

/// The planet mesh: flat buffers, indices are `u32`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub radius: f64,
    pub vertices: Vec<Vertex>,
    pub edges: Vec<Edge>,
    pub faces: Vec<Face>,
    /// The elevation map's ground for splits below the base mesh (elevation-map planets).
    pub guide: Option<std::sync::Arc<guide::Guide>>,
    /// The base mesh's river widths, for the water surface (planets with a climate).
    pub channels: Option<std::sync::Arc<channels::Channels>>,
    /// The climate's precipitation, for the colours (planets with a climate).
    pub precipitation: Option<std::sync::Arc<precipitation::Precipitation>>,
}

impl Mesh {
    /// Bytes of the buffers' capacity.
    pub fn capacity_bytes(&self) -> usize {
        self.vertices.capacity() * std::mem::size_of::<Vertex>()
            + self.edges.capacity() * std::mem::size_of::<Edge>()
            + self.faces.capacity() * std::mem::size_of::<Face>()
    }
}

impl Vertex {
    pub fn new(pos: DVec3, seed: u32) -> Vertex {
        Vertex {
            pos: pos.to_array(),
            ground: 0.0,
            water: 0.0,
            edge: NONE,
            parent_lod: Lod::default(),
            seed,
            tangent: Tangent::ZERO,
            flags: VertexFlags::empty(),
        }
    }

    #[inline]
    pub fn p(&self) -> DVec3 {
        DVec3::from_array(self.pos)
    }
    /// Whether water stands above the ground here.
    #[inline]
    pub fn submerged(&self) -> bool {
        self.water > self.ground
    }
}

impl Edge {
    #[inline]
    pub fn other(&self, v: u32) -> u32 {
        if self.v[0] == v {
            self.v[1]
        } else {
            self.v[0]
        }
    }

    /// The edge's face other than `f`.
    #[inline]
    pub fn other_face(&self, f: u32) -> u32 {
        if self.f[0] == f {
            self.f[1]
        } else {
            self.f[0]
        }
    }

    /// Kinds of the faces `f[0]` and `f[1]`.
    #[inline]
    pub fn face_kinds(&self) -> [FaceKind; 2] {
        [0, 1].map(|i| if self.land >> i & 1 == 1 { FaceKind::Land } else { FaceKind::Sea })
    }

    /// [`Edge::land`] for faces of kinds `kinds`.
    #[inline]
    pub fn land_bits(kinds: [FaceKind; 2]) -> u8 {
        kinds[0] as u8 | (kinds[1] as u8) << 1
    }

    /// Kind of face `f`, one of the edge's two faces.
    #[inline]
    pub fn face_kind(&self, f: u32) -> FaceKind {
        self.face_kinds()[usize::from(self.f[0] != f)]
    }
}

/// Ball radius of a root edge, in edge lengths: large enough that the balls of the edges its
/// splits make usually fit inside without shrinking.
pub const LOD_RADIUS: f32 = 1.0;

/// Bytes one vertex, one edge and one face take in the buffers.
pub const VERTEX_BYTES: usize = std::mem::size_of::<Vertex>();
pub const EDGE_BYTES: usize = std::mem::size_of::<Edge>();
pub const FACE_BYTES: usize = std::mem::size_of::<Face>();

// The WGSL twins of these structs (`shaders/adapt/layout.wgsl`) spell the same layouts out.
const _: () = assert!(VERTEX_BYTES == 56 && EDGE_BYTES == 24 && FACE_BYTES == 12);

impl Mesh {
    pub fn pos(&self, v: u32) -> DVec3 {
        self.vertices[v as usize].p()
    }

    /// Corners `[v0, v1, v2]` of face `f` (see [`Face`]): counter-clockwise, `v0` the newest.
    #[inline]
    pub fn corners(&self, f: u32) -> [u32; 3] {
        let face = &self.faces[f as usize];
        let e0 = &self.edges[face.e[0] as usize];
        let [v1, v2] = if e0.f[0] == f { e0.v } else { [e0.v[1], e0.v[0]] };
        [self.edges[face.e[1] as usize].other(v2), v1, v2]
    }

    /// The edge joining vertices `a` and `b`, if there is one: found by walking the faces
    /// around `a` from its edge link (at most [`MAX_WALK`] of them), without an index.
    pub fn edge_between(&self, a: u32, b: u32) -> Option<u32> {
        let start = self.vertices[a as usize].edge;
        if start >= DEAD {
            return None;
        }
        let (mut e, mut f) = (start, self.edges[start as usize].f[0]);
        for _ in 0..MAX_WALK {
            let edge = &self.edges[e as usize];
            if edge.other(a) == b {
                return Some(e);
            }
            // The face's other edge at `a`, then the face across it.
            let face = &self.faces[f as usize];
            let mut next = NONE;
            for x in face.e {
                if x != e && self.edges[x as usize].v.contains(&a) {
                    next = x;
                    break;
                }
            }
            if next == NONE || next == start {
                return None;
            }
            f = self.edges[next as usize].other_face(f);
            e = next;
        }
        None
    }

    /// Kind of face `f`, as its refinement edge keeps it.
    #[inline]
    pub fn face_kind(&self, f: u32) -> FaceKind {
        self.edges[self.faces[f as usize].e[0] as usize].face_kind(f)
    }

    /// Makes face `f` of kind `kind`: marks it so in each of its edges.
    pub fn set_face_kind(&mut self, f: u32, kind: FaceKind) {
        for e in self.faces[f as usize].e {
            let edge = &mut self.edges[e as usize];
            let bit = 1 << usize::from(edge.f[0] != f);
            edge.land = if kind == FaceKind::Land { edge.land | bit } else { edge.land & !bit };
        }
    }

    /// The corners of every face, in face order (the triangle list of the mesh).
    pub fn triangles(&self) -> Vec<[u32; 3]> {
        use rayon::prelude::*;
        (0..self.faces.len() as u32).into_par_iter().map(|f| self.corners(f)).collect()
    }

    /// Total buffer memory divided by the vertex count (the paper's "bytes per vertex").
    pub fn bytes_per_vertex(&self) -> f64 {
        let total = self.vertices.len() * VERTEX_BYTES + self.edges.len() * EDGE_BYTES + self.faces.len() * FACE_BYTES;
        total as f64 / self.vertices.len().max(1) as f64
    }

    /// Builds a mesh from corner triangles (CCW from outside, the first corner the newest),
    /// creating the edges. Used for the octahedron, where every edge is shared by two faces,
    /// and for surface patches, whose border edges have one face (the other is [`NONE`]).
    pub fn from_triangles(radius: f64, vertices: Vec<Vertex>, tris: &[[u32; 3]]) -> Mesh {
        use std::collections::HashMap;
        let mut mesh = Mesh {
            radius,
            vertices,
            edges: Vec::new(),
            faces: Vec::new(),
            guide: None,
            channels: None,
            precipitation: None,
        };
        let mut by_pair: HashMap<(u32, u32), u32> = HashMap::new();
        for (fi, t) in tris.iter().enumerate() {
            let mut face = Face { e: [NONE; 3] };
            for i in 0..3 {
                // Edge opposite corner i runs from corner i+1 to corner i+2.
                let (a, b) = (t[(i + 1) % 3], t[(i + 2) % 3]);
                let id = if let Some(&id) = by_pair.get(&(b, a)) {
                    mesh.edges[id as usize].f[1] = fi as u32;
                    id
                } else {
                    let id = mesh.edges.len() as u32;
                    mesh.edges.push(Edge {
                        v: [a, b],
                        f: [fi as u32, NONE],
                        lod: Lod::default(),
                        level: 0,
                        kind: EdgeKind::Sea,
                        land: 0,
                    });
                    by_pair.insert((a, b), id);
                    id
                };
                face.e[i] = id;
                mesh.vertices[a as usize].edge = id;
            }
            mesh.faces.push(face);
        }
        mesh.reset_lod_roots();
        mesh
    }

    /// Makes every edge a root of the level-of-detail hierarchy: its bounds are its length
    /// and [`LOD_RADIUS`] times that.
    pub fn reset_lod_roots(&mut self) {
        let verts = &self.vertices;
        for e in self.edges.iter_mut() {
            let length = verts[e.v[0] as usize].p().distance(verts[e.v[1] as usize].p());
            e.lod = Lod::new(length, LOD_RADIUS as f64 * length);
        }
    }

    /// Length of edge `e`, metres.
    pub fn edge_length(&self, e: u32) -> f64 {
        let edge = &self.edges[e as usize];
        self.pos(edge.v[0]).distance(self.pos(edge.v[1]))
    }

    /// Midpoint of edge `e`.
    pub fn midpoint(&self, e: u32) -> DVec3 {
        let edge = &self.edges[e as usize];
        (self.pos(edge.v[0]) + self.pos(edge.v[1])) * 0.5
    }

    /// Vertex-to-vertex adjacency in compressed rows: `(offsets, neighbours, edges)`; the
    /// neighbours of `v` are `neighbours[offsets[v]..offsets[v+1]]`, joined by the matching edges.
    pub fn adjacency(&self) -> Adjacency {
        let n = self.vertices.len();
        let mut offsets = vec![0u32; n + 1];
        for e in &self.edges {
            offsets[e.v[0] as usize + 1] += 1;
            offsets[e.v[1] as usize + 1] += 1;
        }
        for i in 0..n {
            offsets[i + 1] += offsets[i];
        }
        let mut fill = offsets.clone();
        let mut neighbours = vec![0u32; offsets[n] as usize];
        let mut edges = vec![0u32; offsets[n] as usize];
        for (ei, e) in self.edges.iter().enumerate() {
            for k in 0..2 {
                let a = e.v[k] as usize;
                let slot = fill[a] as usize;
                neighbours[slot] = e.v[1 - k];
                edges[slot] = ei as u32;
                fill[a] += 1;
            }
        }
        Adjacency { offsets, neighbours, edges }
    }

    /// Unit normal of face `f` (counter-clockwise winding), unnormalised area vector halved.
    pub fn face_area_vector(&self, f: u32) -> DVec3 {
        self.triangle_area_vector(self.corners(f))
    }

    /// Area vector of the triangle with corners `v` (counter-clockwise): normal times area.
    pub fn triangle_area_vector(&self, v: [u32; 3]) -> DVec3 {
        let [a, b, c] = v.map(|v| self.pos(v));
        (b - a).cross(c - a) * 0.5
    }
}

/// Vertex adjacency in compressed rows (see [`Mesh::adjacency`]).
#[derive(Clone, Debug)]
pub struct Adjacency {
    pub offsets: Vec<u32>,
    pub neighbours: Vec<u32>,
    pub edges: Vec<u32>,
}

impl Adjacency {
    /// `(neighbour, edge)` pairs around `v`.
    pub fn around(&self, v: u32) -> impl Iterator<Item = (u32, u32)> + '_ {
        let r = self.offsets[v as usize] as usize..self.offsets[v as usize + 1] as usize;
        self.neighbours[r.clone()].iter().copied().zip(self.edges[r].iter().copied())
    }
    pub fn degree(&self, v: u32) -> usize {
        (self.offsets[v as usize + 1] - self.offsets[v as usize]) as usize
    }
}

#[cfg(test)]
mod tests;
