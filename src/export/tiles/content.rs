//! A tile's content: the planet inside the tile's cell, refined to a uniform bisection depth
//! along the tree (`tree.rs`), with skirts along the cell's border and the water surface, as a
//! `.glb` whose positions are `f32` offsets from the tile's origin (the centre of its box).
//!
//! Two tiles of one level refine their common border edge by the same tree nodes, so they share
//! its vertices bit for bit; between levels, the skirts — walls hanging from the border towards
//! the planet's centre — hide the gaps. A border vertex's normal is taken over its whole ring in
//! the level's uniform triangulation, the faces of the neighbouring cells included (`ring.rs`),
//! so neighbouring tiles light their common border alike, bit for bit.

use super::bounds::{local_axes, OrientedBox};
use super::carve::cell_beds;
use super::key::TileKey;
use super::ring::border_normals;
use super::tree::{holds, surface_mesh, Refiner, ROOTS};
use crate::export::carve::lay_bed;
use crate::export::colour_mip::ColourMip;
use crate::export::glb::{encode_glb, terrain_mesh_with_normals, to_gltf_axes, Compression, GlbMesh};
use crate::export::view::water_mesh;
use crate::export::water::water_levels;
use crate::mesh::split::position::lift;
use crate::mesh::Mesh;
use crate::params::Params;
use glam::{DQuat, DVec3};
use std::collections::{HashMap, HashSet};

/// How a level's content is made: bisections from the cell to its triangles, skirt length,
/// the pad its box leaves for the levels below, and the radius of ground a vertex's colour
/// stands for (`colour_mip.rs`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContentSpec {
    pub content_depth: u32,
    pub skirt_m: f64,
    pub pad_m: f64,
    pub footprint_m: f64,
}

/// A tile's content and where it sits.
#[derive(Clone, Debug, PartialEq)]
pub struct TileContent {
    pub glb: Vec<u8>,
    /// A box around the content (terrain, skirts and water) and, with its pad, the content of
    /// the levels below, along the cell's axes (see [`cell_frame`]).
    pub bounds: OrientedBox,
    /// The terrain surface: planet-frame vertex positions and triangles (without skirts).
    pub surface: Mesh,
    /// Unit normals of the surface's vertices, planet frame.
    pub normals: Vec<DVec3>,
    /// How many splits below the base mesh the content needed.
    pub splits: usize,
}

impl TileContent {
    /// The point the `.glb` positions are relative to.
    pub fn origin(&self) -> DVec3 {
        self.bounds.centre
    }
}

/// The cell of `key` — its tree node (vertices of `refiner`'s mesh) — and its box axes: east,
/// north and up at the root cell's centre, carried down cell by cell with the rotation that
/// takes each parent's up to its child's (so a child's axes differ from its parent's only by
/// the small tilt between their centres, even near the poles).
pub fn cell_frame(refiner: &mut Refiner, key: TileKey) -> ([u32; 3], [DVec3; 3]) {
    let centre = |r: &Refiner, node: [u32; 3]| node.iter().map(|&v| r.mesh().pos(v)).sum::<DVec3>().normalize();
    let mut node = ROOTS[key.root as usize];
    let mut axes = local_axes(centre(refiner, node));
    for q in key.quadrants() {
        let half = refiner.children(node)[usize::from(q >> 1)];
        node = refiner.children(half)[usize::from(q & 1)];
        let turn = DQuat::from_rotation_arc(axes[2], centre(refiner, node));
        axes = axes.map(|a| (turn * a).normalize());
    }
    (node, axes)
}

/// The content of `key`, its `.glb` stored as `compression` says; with `colours`, each vertex
/// coloured as the mean of the base mesh's within the spec's footprint.
pub fn tile_content(
    refiner: &mut Refiner,
    key: TileKey,
    spec: &ContentSpec,
    params: &Params,
    colours: Option<&ColourMip>,
    compression: Compression,
) -> TileContent {
    let (cell, axes) = cell_frame(refiner, key);
    let mut leaves = Vec::with_capacity(1 << spec.content_depth);
    refiner.descendants(cell, spec.content_depth, &mut leaves);
    let (mut surface, ids) = surface_mesh(refiner.mesh(), &leaves);
    let depth = 2 * u32::from(key.level) + spec.content_depth;
    // The river edges of the cell before the carving refines along wide rivers' courses.
    let river_edges = cell_river_edges(refiner.mesh(), cell);
    // Wide rivers' channels, carved as the level's whole triangulation would carve them.
    let beds = cell_beds(refiner, cell, &leaves, depth, super::edge_length(params, key.level));
    let radius = surface.radius;
    for (vert, id) in surface.vertices.iter_mut().zip(&ids) {
        if let Some(&(ground, water)) = beds.get(id) {
            lay_bed(vert, radius, ground, water);
        }
    }
    let moved: HashMap<u32, DVec3> =
        beds.iter().map(|(&id, &(ground, _))| (id, lift(refiner.mesh().pos(id), radius, ground))).collect();
    let triangles = surface.triangles();
    let border = border_edges(&triangles);
    let normals = border_normals(refiner, (cell, depth), (&surface, &triangles, &ids), &border, &moved);

    let levels = water_levels(&surface, &triangles);
    let mut hull: Vec<DVec3> = Vec::with_capacity(surface.vertices.len() + border.len());
    for (v, &level) in surface.vertices.iter().zip(&levels) {
        hull.push(v.p());
        if level != v.ground {
            hull.push(lift(v.p(), surface.radius, level));
        }
    }
    hull.extend(border.iter().map(|&(a, _)| skirt_foot(surface.vertices[a as usize].p(), spec.skirt_m)));
    let bounds = OrientedBox::fit(hull, axes, spec.pad_m);

    let origin = bounds.centre;
    let mut terrain = terrain_mesh_with_normals(&surface, params, Some(origin), &triangles, &normals);
    terrain.translation = None;
    if let Some(mip) = colours {
        for (c, v) in terrain.colors.iter_mut().zip(&surface.vertices) {
            *c = mip.mean(v.p(), spec.footprint_m, *c);
        }
    }
    add_skirts(&mut terrain, &surface, &border, origin, spec.skirt_m);
    let mut water = water_mesh(&surface, origin, &triangles, &levels);
    water.translation = None;
    let rivers = river_lines(refiner, (cell, river_edges), spec, (&surface, &ids, &levels), origin);
    // A tile holds 1,024 triangles (plus skirts, water and rivers): far below the container's
    // limit.
    let glb = encode_glb(&[terrain, water, rivers], compression).expect("a tile fits a .glb");
    TileContent { glb, bounds, surface, normals, splits: refiner.splits() }
}

/// Pixels a tile's geometric error (its nominal edge) spans where a client shows it: clients
/// refine a tile once its error passes their screen-space error target (our viewer's 6 pixels,
/// CesiumJS's 16), so it is drawn with the error between about that and half of it.
pub const PIXELS_PER_EDGE: f64 = 4.0;

/// Least share of its nominal pixel a river's channel covers for a tile to carry it as a line
/// (drawn at a tenth of full opacity).
pub const MIN_TILE_LINE_COVERAGE: f64 = 0.01;

/// The river edges of the mesh with both ends in tree node `cell`, as the mesh is now.
fn cell_river_edges(mesh: &Mesh, cell: [u32; 3]) -> Vec<(u32, u32)> {
    let dir = |v: u32| mesh.pos(v).normalize();
    let corners = cell.map(dir);
    mesh.edges
        .iter()
        .filter(|e| e.kind == crate::mesh::EdgeKind::River)
        .map(|e| (e.v[0], e.v[1]))
        .filter(|&(a, b)| holds(corners, dir(a)) && holds(corners, dir(b)))
        .collect()
}

/// The perennial rivers inside the cell as lines, like `view.glb`'s
/// ([`crate::export::view::river_lines_mesh`]): the `candidates` river edges of the refined
/// mesh with both ends in the cell (the base mesh's above its resolution, the refined ones
/// below; [`cell_river_edges`] before the carving refines along rivers' courses), each end
/// laid on the tile's own surface (the plane of the leaf holding it through its corners at
/// their ground or water level, lifted by a hundredth of an edge so the line stays above the
/// triangles it crosses), as opaque as the square root of the share of a pixel the channel covers at the
/// level's nominal pixel (its edge over [`PIXELS_PER_EDGE`]). Segments under
/// [`MIN_TILE_LINE_COVERAGE`] at both ends are left out, so a level carries the rivers it can
/// show (at level 0 those wider than ~800 m) and tiles stay small; positions relative to
/// `origin`.
fn river_lines(
    refiner: &mut Refiner,
    (cell, candidates): ([u32; 3], Vec<(u32, u32)>),
    spec: &ContentSpec,
    (surface, ids, levels): (&Mesh, &[u32], &[f64]),
    origin: DVec3,
) -> GlbMesh {
    use crate::export::view::line_colour;
    use crate::export::water::flowing_channel;
    let pixel = 2.0 * spec.footprint_m / PIXELS_PER_EDGE;
    let raise = 0.02 * spec.footprint_m;
    let slot: HashMap<u32, usize> = ids.iter().enumerate().map(|(i, &v)| (v, i)).collect();
    let visible = |i: usize| levels[i].max(surface.vertices[i].ground);
    let mut ends: HashMap<u32, u32> = HashMap::new();
    let mut out = GlbMesh { lines: true, ..Default::default() };
    for (a, b) in candidates {
        let end = |v: u32, refiner: &Refiner| {
            let (width, depth) = flowing_channel(refiner.mesh(), v)?;
            Some(((width / pixel).min(1.0), depth))
        };
        let (Some(ea), Some(eb)) = (end(a, refiner), end(b, refiner)) else { continue };
        if ea.0 < MIN_TILE_LINE_COVERAGE && eb.0 < MIN_TILE_LINE_COVERAGE {
            continue;
        }
        for (v, (coverage, depth)) in [(a, ea), (b, eb)] {
            let index = match ends.get(&v) {
                Some(&i) => i,
                None => {
                    // The leaf holding the vertex, and the tile's surface there.
                    let p = refiner.mesh().pos(v).normalize();
                    let mut node = cell;
                    for _ in 0..spec.content_depth {
                        let [c0, c1] = refiner.children(node);
                        let m = refiner.mesh();
                        node = if holds(c0.map(|u| m.pos(u).normalize()), p) { c0 } else { c1 };
                    }
                    // On the leaf's plane through its corners at their ground or water level
                    // (the surface the tile draws there), lifted.
                    let m = refiner.mesh();
                    let [x, y, z] = node.map(|u| {
                        let level = slot.get(&u).map_or(m.vertices[u as usize].ground, |&i| visible(i));
                        lift(m.pos(u), m.radius, level)
                    });
                    let n = (y - x).cross(z - x);
                    let at = p * (x.dot(n) / p.dot(n)) + p * raise - origin;
                    out.positions.push(to_gltf_axes(at.to_array()).map(|c| c as f32));
                    out.colors.push(line_colour(coverage, depth));
                    let i = out.positions.len() as u32 - 1;
                    ends.insert(v, i);
                    i
                }
            };
            out.indices.push(index);
        }
    }
    out
}

/// The border of a surface with `triangles` ([`Mesh::triangles`]): directed edges `(a, b)` of
/// faces (counter-clockwise) whose reverse no face has, in face order.
pub(super) fn border_edges(triangles: &[[u32; 3]]) -> Vec<(u32, u32)> {
    let directed: HashSet<(u32, u32)> =
        triangles.iter().flat_map(|f| [0, 1, 2].map(|i| (f[i], f[(i + 1) % 3]))).collect();
    triangles
        .iter()
        .flat_map(|f| [0, 1, 2].map(|i| (f[i], f[(i + 1) % 3])))
        .filter(|&(a, b)| !directed.contains(&(b, a)))
        .collect()
}

/// Where the skirt below `p` ends: `skirt_m` towards the planet's centre.
fn skirt_foot(p: DVec3, skirt_m: f64) -> DVec3 {
    p - p.normalize() * skirt_m
}

/// Appends a skirt below every border edge: a wall from the edge down to its feet, facing out
/// of the tile, with the colours and normals of the edge's vertices.
fn add_skirts(terrain: &mut GlbMesh, surface: &Mesh, border: &[(u32, u32)], origin: DVec3, skirt_m: f64) {
    let mut foot: HashMap<u32, u32> = HashMap::with_capacity(border.len());
    let mut foot_of = |t: &mut GlbMesh, v: u32| {
        *foot.entry(v).or_insert_with(|| {
            let p = skirt_foot(surface.vertices[v as usize].p(), skirt_m) - origin;
            t.positions.push(to_gltf_axes(p.to_array()).map(|x| x as f32));
            t.normals.push(t.normals[v as usize]);
            t.colors.push(t.colors[v as usize]);
            t.positions.len() as u32 - 1
        })
    };
    for &(a, b) in border {
        let (fa, fb) = (foot_of(terrain, a), foot_of(terrain, b));
        terrain.indices.extend_from_slice(&[a, fa, fb, a, fb, b]);
    }
}
