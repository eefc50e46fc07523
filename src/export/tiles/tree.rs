//! The newest-vertex bisection tree behind a planet's mesh, and refinement along it.
//!
//! Every mesh of a planet — the base mesh, a view, a tile — is a cut through one binary tree:
//! the eight octahedron faces are its roots and each node `(v0, v1, v2)` (counter-clockwise,
//! `v0` newest) has the two children `(m, v0, v1)` and `(m, v2, v0)`, where `m` is the vertex
//! made by splitting the node's refinement edge `(v1, v2)`. [`BaseTree`] recovers which edges
//! the base mesh split (and into which vertex) by coarsening a copy of it back to the
//! octahedron; [`Refiner`] walks the tree below any node, splitting base-mesh leaves with the
//! adaption's split rule ([`split_vertex`]) on a copy of the base mesh made on the first split.
//! The same node therefore always gets the same vertices, bit for bit, as in a view.

use crate::mesh::split::altitude::split_vertex;
use crate::mesh::{Mesh, SplitSite, VertexFlags};
use crate::params::Params;
use rustc_hash::FxHashMap as HashMap;

/// The eight roots: the octahedron's faces as `octahedron()` makes them (vertices 0..4 on the
/// equator, 4 the north pole, 5 the south pole), newest vertex first.
pub const ROOTS: [[u32; 3]; 8] =
    [[4, 0, 1], [5, 1, 0], [4, 1, 2], [5, 2, 1], [4, 2, 3], [5, 3, 2], [4, 3, 0], [5, 0, 3]];

/// Key of an unordered vertex pair.
#[inline]
fn pair(a: u32, b: u32) -> u64 {
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    (u64::from(lo) << 32) | u64::from(hi)
}

/// Why a mesh is not a bisection refinement of the octahedron.
#[derive(Debug, thiserror::Error)]
#[error("the mesh does not coarsen to the octahedron ({faces} faces remain)")]
pub struct NotBisected {
    pub faces: usize,
}

/// Which edges of the tree the base mesh has split.
#[derive(Clone, Debug, Default)]
pub struct BaseTree {
    /// The vertex made by splitting each split edge, by the edge's ends.
    midpoints: HashMap<u64, u32>,
}

impl BaseTree {
    /// Recovers the tree from a base mesh by collapsing, pass after pass, every vertex whose
    /// four faces are still those of its split, until only the octahedron is left.
    pub fn new(base: &Mesh) -> Result<BaseTree, NotBisected> {
        let mut mesh = base.clone();
        for v in mesh.vertices.iter_mut().skip(6) {
            v.flags.insert(VertexFlags::REFINED); // let every vertex but the octahedron's collapse
        }
        let mut midpoints = HashMap::with_capacity_and_hasher(mesh.vertices.len(), Default::default());
        let mut alive: Vec<u32> = (6..mesh.vertices.len() as u32).collect();
        loop {
            let sites: Vec<_> = alive.iter().filter_map(|&v| mesh.collapse_site(v)).collect();
            if sites.is_empty() {
                break;
            }
            for site in &sites {
                midpoints.insert(pair(site.a, site.b), site.v);
            }
            // SAFETY: each site is its vertex's on this mesh, one per vertex.
            unsafe { mesh.collapse_vertices(&sites) };
            alive.retain(|&v| !collapsed(&mesh, v));
        }
        let faces = base.faces.len() - 2 * midpoints.len();
        if faces != 8 || midpoints.len() + 6 != base.vertices.len() {
            return Err(NotBisected { faces });
        }
        Ok(BaseTree { midpoints })
    }

    /// Bytes the maps hold (estimate: key, value and hash-table overhead per entry).
    pub fn bytes(&self) -> usize {
        self.midpoints.capacity() * 24
    }

    /// Whether the base mesh has split edge `(a, b)`.
    pub fn splits_edge(&self, a: u32, b: u32) -> bool {
        self.midpoints.contains_key(&pair(a, b))
    }

    /// How many splits the base mesh holds.
    pub fn splits(&self) -> usize {
        self.midpoints.len()
    }
}

/// Whether vertex `v` has been collapsed (a collapse marks its edge link dead, `NONE - 1`).
fn collapsed(mesh: &Mesh, v: u32) -> bool {
    mesh.vertices[v as usize].edge >= crate::mesh::NONE - 1
}

/// Refines along the tree below the base mesh: copy-on-write, so walks that stay above the base
/// mesh's leaves cost no copy.
pub struct Refiner<'a> {
    base: &'a Mesh,
    tree: &'a BaseTree,
    params: &'a Params,
    /// The base mesh with this refiner's splits, made on the first split.
    refined: Option<Mesh>,
    /// Buffers to copy the base mesh into on the first split (see [`Refiner::with_spare`]).
    spare: Option<Mesh>,
    midpoints: HashMap<u64, u32>,
    /// Base-mesh vertices, edges and faces the splits rewrote (see [`Refiner::take_buffers`]).
    touched: Touched,
    /// The sites of the last [`Refiner::midpoint`]'s splits (kept for its buffer).
    sites: Vec<SplitSite>,
}

/// Indices of the base mesh's entities that splits rewrote: a split rewrites its edge, the two
/// faces beside it, their outer edges (face links) and one end's edge link; all else it appends.
#[derive(Default)]
struct Touched {
    vertices: Vec<u32>,
    edges: Vec<u32>,
    faces: Vec<u32>,
}

impl<'a> Refiner<'a> {
    pub fn new(base: &'a Mesh, tree: &'a BaseTree, params: &'a Params) -> Refiner<'a> {
        Refiner {
            base,
            tree,
            params,
            refined: None,
            spare: None,
            midpoints: HashMap::default(),
            touched: Touched::default(),
            sites: Vec::new(),
        }
    }

    /// Refines `spare`, a copy of the base mesh that an earlier refiner gave back with
    /// [`Refiner::take_buffers`], instead of copying the base mesh on the first split: on a large
    /// planet the copy (30 MB for the Earth DEM's) costs more than a small region's splits.
    pub fn with_spare(mut self, spare: Option<Mesh>) -> Refiner<'a> {
        debug_assert!(spare.as_ref().is_none_or(|m| m.vertices.len() == self.base.vertices.len()));
        self.spare = spare;
        self
    }

    /// The buffers this refiner holds, restored to a copy of the base mesh (its appended
    /// entities dropped, the base entities its splits rewrote copied back), for another.
    pub fn take_buffers(&mut self) -> Option<Mesh> {
        let Some(mut mesh) = self.refined.take() else { return self.spare.take() };
        let base = self.base;
        mesh.vertices.truncate(base.vertices.len());
        mesh.edges.truncate(base.edges.len());
        mesh.faces.truncate(base.faces.len());
        let t = std::mem::take(&mut self.touched);
        fn restore<T: Copy>(to: &mut [T], from: &[T], ids: &[u32]) {
            for &i in ids.iter().filter(|&&i| (i as usize) < from.len()) {
                to[i as usize] = from[i as usize];
            }
        }
        restore(&mut mesh.vertices, &base.vertices, &t.vertices);
        restore(&mut mesh.edges, &base.edges, &t.edges);
        restore(&mut mesh.faces, &base.faces, &t.faces);
        Some(mesh)
    }

    /// Makes room for about `splits` more splits (their midpoints).
    pub fn reserve(&mut self, splits: usize) {
        self.midpoints.reserve(splits);
    }

    /// The mesh the node vertices index: the base mesh plus the splits made so far.
    pub fn mesh(&self) -> &Mesh {
        self.refined.as_ref().unwrap_or(self.base)
    }

    /// Vertices of the base mesh: those the refiner adds come after them.
    pub fn base_vertices(&self) -> usize {
        self.base.vertices.len()
    }

    /// Splits made so far.
    pub fn splits(&self) -> usize {
        self.midpoints.len()
    }

    /// The vertex that splits edge `(a, b)` of the tree, splitting it (with its bisection
    /// closure) if no split has yet.
    pub fn midpoint(&mut self, a: u32, b: u32) -> u32 {
        // A tree edge was split by the base mesh (only edges between its vertices may be),
        // by this refiner (a small map, in cache) or not at all: then it is still in the mesh,
        // found around `a` (a walk that fails around the whole fan when the edge was split).
        let key = pair(a, b);
        let n = self.base.vertices.len() as u32;
        let known = if a < n && b < n { self.tree.midpoints.get(&key) } else { None };
        if let Some(&m) = known.or_else(|| self.midpoints.get(&key)) {
            return m;
        }
        let e = self.mesh().edge_between(a, b).expect("a tree edge is in the mesh or split into a known vertex");
        let params = self.params;
        // Borrowed from the base mesh (not cloned: an `Arc`'s count shared by the threads that
        // refine in parallel would bounce between their caches on every split).
        let base: &'a Mesh = self.base;
        let guide = base.guide.as_deref();
        let spare = &mut self.spare;
        let mesh = self.refined.get_or_insert_with(|| spare.take().unwrap_or_else(|| base.clone()));
        let sites = &mut self.sites;
        sites.clear();
        let touched = &mut self.touched;
        // Only the base mesh's entities are restored (the appended ones are dropped): most
        // splits, below the base mesh, touch few or none.
        let (nv, ne, nf) = (base.vertices.len() as u32, base.edges.len() as u32, base.faces.len() as u32);
        let splits = mesh.refine_edge(e, &mut |m: &Mesh, site: &SplitSite| {
            sites.push(*site);
            touched.vertices.extend([site.a, site.b].into_iter().filter(|&v| v < nv));
            touched.faces.extend([site.f1, site.f2].into_iter().filter(|&f| f < nf));
            // (A face the refiner made may still have a base edge, whose links the split rewrites.)
            for f in [site.f1, site.f2] {
                touched.edges.extend(m.faces[f as usize].e.into_iter().filter(|&e| e < ne));
            }
            split_vertex(&crate::mesh::Diamond::new(m, site), params, guide)
        });
        for (site, split) in self.sites.iter().zip(&splits) {
            self.midpoints.insert(pair(site.a, site.b), split.v);
        }
        // The edge asked for is split last, after the edges its closure needed first.
        splits.last().expect("refining an edge splits it").v
    }

    /// Whether the base mesh splits `node` (a node with a vertex this refiner made lies below
    /// the base mesh's leaves).
    pub fn base_splits(&self, node: [u32; 3]) -> bool {
        let n = self.base.vertices.len() as u32;
        node.iter().all(|&v| v < n) && self.tree.splits_edge(node[1], node[2])
    }

    /// The kind of the base mesh's edge `(a, b)`, if the base mesh has that edge.
    pub fn base_edge_kind(&self, a: u32, b: u32) -> Option<crate::mesh::EdgeKind> {
        let n = self.base.vertices.len() as u32;
        if a >= n || b >= n {
            return None;
        }
        self.base.edge_between(a, b).map(|e| self.base.edges[e as usize].kind)
    }

    /// The two children of `node`.
    pub fn children(&mut self, node: [u32; 3]) -> [[u32; 3]; 2] {
        let [v0, v1, v2] = node;
        let m = self.midpoint(v1, v2);
        [[m, v0, v1], [m, v2, v0]]
    }

    /// The descendants of `node` `depth` bisections below it, in tree order.
    pub fn descendants(&mut self, node: [u32; 3], depth: u32, out: &mut Vec<[u32; 3]>) {
        if depth == 0 {
            out.push(node);
            return;
        }
        for child in self.children(node) {
            self.descendants(child, depth - 1, out);
        }
    }
}

/// The leaves as a mesh of their own (vertices in order of first use, faces in leaf order,
/// edges along the border with one face), enough for normals, colours and the water surface,
/// and each of its vertices' index in `mesh`.
pub(crate) fn surface_mesh(mesh: &Mesh, leaves: &[[u32; 3]]) -> (Mesh, Vec<u32>) {
    let (points, triangles, ids) = leaf_vertices(mesh, leaves);
    let surface = Mesh::from_triangles(mesh.radius, points.vertices, &triangles);
    (Mesh { channels: points.channels, precipitation: points.precipitation, ..surface }, ids)
}

/// The leaves' vertices (in order of first use) as a mesh without faces or edges, the leaves
/// as triangles over them, and each vertex's index in `mesh`: enough to carve channels
/// (`export/carve.rs`) without the cost of a mesh's edges.
pub(crate) fn leaf_vertices(mesh: &Mesh, leaves: &[[u32; 3]]) -> (Mesh, Vec<[u32; 3]>, Vec<u32>) {
    leaf_vertices_from(mesh, leaves, mesh.vertices.len())
}

/// [`leaf_vertices`], finding the vertices from `dense` on (a refinement's, most of the leaves'
/// corners) in a table instead of a map: the same result, faster for many leaves.
pub(crate) fn leaf_vertices_from(mesh: &Mesh, leaves: &[[u32; 3]], dense: usize) -> (Mesh, Vec<[u32; 3]>, Vec<u32>) {
    let mut slot: HashMap<u32, u32> = HashMap::default();
    let mut table = vec![u32::MAX; mesh.vertices.len().saturating_sub(dense)];
    let mut vertices = Vec::with_capacity(leaves.len() / 2 + 16);
    let mut ids = Vec::with_capacity(leaves.len() / 2 + 16);
    let mut add = |v: u32| {
        vertices.push(mesh.vertices[v as usize]);
        ids.push(v);
        vertices.len() as u32 - 1
    };
    let triangles: Vec<[u32; 3]> = leaves
        .iter()
        .map(|leaf| {
            leaf.map(|v| match (v as usize).checked_sub(dense) {
                Some(i) => {
                    if table[i] == u32::MAX {
                        table[i] = add(v);
                    }
                    table[i]
                }
                None => *slot.entry(v).or_insert_with(|| add(v)),
            })
        })
        .collect();
    let points = Mesh {
        radius: mesh.radius,
        vertices,
        channels: mesh.channels.clone(),
        precipitation: mesh.precipitation.clone(),
        ..Mesh::default()
    };
    (points, triangles, ids)
}

/// Whether the spherical triangle of unit `corners` (counter-clockwise seen from outside) holds
/// unit direction `p`, its sides included.
pub(super) fn holds(corners: [glam::DVec3; 3], p: glam::DVec3) -> bool {
    let [a, b, c] = corners;
    a.cross(b).dot(p) >= 0.0 && b.cross(c).dot(p) >= 0.0 && c.cross(a).dot(p) >= 0.0
}
