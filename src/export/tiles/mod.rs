//! 3D Tiles 1.1 streaming of a planet: a tile hierarchy over the newest-vertex bisection tree
//! of the planet's mesh, each tile's content a `.glb` refined inside its cell with the same
//! reproducible split rule as view adaption (so a vertex is the same at every level of detail
//! and in every view), and tileset JSON files that list it.
//!
//! - **Cells.** The eight octahedron faces are the level-0 cells; a cell's four children are its
//!   grandchildren in the bisection tree (two bisections halve its edges), named by quadrant
//!   digits (`key.rs`).
//! - **Content.** A level-`L` tile holds its cell refined `CONTENT_DEPTH` bisections deeper:
//!   1,024 triangles whose edges are about [`PlanetTiles::edge_length`] long, the edge length
//!   of the octahedron divided by `2^(L+5)`. Base-mesh vertices come from the base mesh; deeper
//!   ones are made by the adaption's split (`tree.rs`, `content.rs`).
//! - **Geometric error** is that nominal edge length, halving per level: at a screen-space error
//!   of 16 px, a tile is replaced by its children when its edges would span more than 16 px.
//! - **Skirts** hang from each tile's border towards the planet's centre, one geometric error
//!   long — more than the height by which a coarser neighbour's border can differ.
//! - **Bounding volumes** are boxes around the content along axes carried down from east,
//!   north and up at the root cell's centre (`content.rs`), grown by 1.5 edge lengths for what
//!   finer levels add and by room for the tilt between parent and child, so children's boxes
//!   lie inside their parent's; one that would not is replaced by one along the parent's axes,
//!   cut to it (`bounds.rs`). The contentless root's box is axis-aligned around level 0's.
//! - **Frames.** Positions are planet-centred metres (+Z north, longitude 0 on +X), which 3D
//!   Tiles reads as the frame of a sphere declared by `3DTILES_ellipsoid` (radius: sea level).
//!   Each tile's `.glb` holds `f32` offsets from the tile's origin in glTF's Y-up axes; the
//!   tile's `transform` is the translation to that origin relative to its parent's, and 3D Tiles'
//!   Y-up to Z-up rotation of glTF content undoes `to_gltf_axes`.
//! - **Files** (`tileset.rs`): `tileset.json` lists the root and level 0; levels 1, 3, 5, ...
//!   start external tilesets `tiles/{key}.json` of two levels each; contents are
//!   `tiles/{key}.glb`.

mod bounds;
mod carve;
mod content;
mod course;
mod files;
mod key;
mod ring;
mod tileset;
mod tree;

pub use bounds::{local_axes, OrientedBox};
pub use content::{ContentSpec, TileContent};
pub(crate) use course::wide_course;
pub use files::WriteStats;
pub use key::{KeyError, TileFile, TileKey};
pub use tileset::{is_subtree_root, TilesetFile};
pub(crate) use tree::leaf_vertices_from;
pub use tree::{BaseTree, NotBisected, Refiner, ROOTS};

use crate::export::glb::Compression;
use crate::params::Params;
use crate::planet::Planet;
use glam::DVec3;
use rayon::prelude::*;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Bisections between a tile's cell and the triangles of its content (1,024 per tile).
pub const CONTENT_DEPTH: u32 = 10;
/// Deepest level any planet serves.
pub const MAX_LEVEL: u8 = 21;
/// Box pad for the levels below, in edge lengths of the tile's level.
const PAD_EDGES: f64 = 1.5;
/// Most placements remembered before the memory is cleared.
const MAX_PLACEMENTS: usize = 1 << 17;

/// Nominal edge length of level-`level` content: the octahedron's edge (a quarter of a great
/// circle) over `2^(level + CONTENT_DEPTH / 2)`.
pub fn edge_length(params: &Params, level: u8) -> f64 {
    std::f64::consts::FRAC_PI_2 * params.radius_m / 2f64.powi(i32::from(level) + CONTENT_DEPTH as i32 / 2)
}

/// The deepest level of a planet: [`MAX_LEVEL`], or the deepest whose edges are still at least
/// the adaption's minimum edge length.
pub fn max_level(params: &Params) -> u8 {
    (0..=MAX_LEVEL).take_while(|&l| edge_length(params, l) >= params.min_edge_length_m).last().unwrap_or(0)
}

/// Where a tile sits: the origin of its `.glb` positions and its (nested) bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub origin: DVec3,
    pub bounds: OrientedBox,
}

/// A planet prepared for tiling: its mesh, the bisection tree behind it, and the placements
/// of the tiles made so far (each depends on its parent's).
pub struct PlanetTiles {
    planet: Arc<Planet>,
    params: Params,
    tree: BaseTree,
    max_level: u8,
    placements: Mutex<HashMap<TileKey, Placement>>,
    planet_bounds: OnceLock<OrientedBox>,
    /// The base mesh's faces by cell, made by the first DEM.
    faces: OnceLock<crate::export::face_index::FaceIndex>,
    /// The rivers and lakes as lines for vector tiles, made by the first.
    rivers: OnceLock<crate::export::vector_tiles::RiverLines>,
    /// The base mesh's colours for coarse levels' means, made by the first content.
    colours: OnceLock<crate::export::colour_mip::ColourMip>,
    /// The elevation tiles' overview grid (`terrain_rgb.rs`), made on first use.
    dem_overview: OnceLock<Vec<f32>>,
    /// Buffers of finished refinements, for the next ones (at most [`MAX_SPARES`]).
    spares: Mutex<Vec<crate::mesh::Mesh>>,
}

/// Most spare mesh buffers a tiling keeps.
const MAX_SPARES: usize = 2;

impl PlanetTiles {
    pub fn new(planet: Arc<Planet>, params: Params) -> Result<PlanetTiles, NotBisected> {
        let tree = BaseTree::new(&planet.mesh)?;
        let octant_edge = std::f64::consts::FRAC_PI_2 * params.radius_m;
        // Deepest level whose edges stay at least the minimum edge length of adaption.
        let max_level = (0..=MAX_LEVEL)
            .take_while(|&l| {
                octant_edge / 2f64.powi(i32::from(l) + CONTENT_DEPTH as i32 / 2) >= params.min_edge_length_m
            })
            .last()
            .unwrap_or(0);
        let placements = Mutex::new(HashMap::new());
        Ok(PlanetTiles {
            planet,
            params,
            tree,
            max_level,
            placements,
            planet_bounds: OnceLock::new(),
            faces: OnceLock::new(),
            rivers: OnceLock::new(),
            colours: OnceLock::new(),
            dem_overview: OnceLock::new(),
            spares: Mutex::new(Vec::new()),
        })
    }

    pub fn params(&self) -> &Params {
        &self.params
    }

    pub fn planet(&self) -> &Arc<Planet> {
        &self.planet
    }

    /// The rivers and lakes, cut into vector tiles by [`crate::export::vector_tiles`].
    pub fn rivers(&self) -> &crate::export::vector_tiles::RiverLines {
        self.rivers.get_or_init(|| crate::export::vector_tiles::RiverLines::new(&self.planet))
    }

    /// The elevation tiles' overview grid, made by `make` on first use (see
    /// [`crate::export::terrain_rgb`]).
    pub(crate) fn dem_overview(&self, make: impl FnOnce(&PlanetTiles) -> Vec<f32>) -> &[f32] {
        self.dem_overview.get_or_init(|| make(self))
    }

    /// The base mesh's faces by cell.
    pub(crate) fn faces(&self) -> &crate::export::face_index::FaceIndex {
        self.faces.get_or_init(|| crate::export::face_index::FaceIndex::new(&self.planet.mesh))
    }

    /// Makes the face index that DEMs and terrain and elevation tiles find their region's faces
    /// in, if not made yet (once per planet; otherwise the first of them makes it).
    pub fn index_faces(&self) {
        self.faces();
    }

    /// A refiner below this planet's base mesh, on spare buffers when there are some; give
    /// them back with [`PlanetTiles::recycle`].
    pub(crate) fn refiner(&self) -> Refiner<'_> {
        let spare = self.spares.lock().expect("spares lock").pop();
        Refiner::new(&self.planet.mesh, &self.tree, &self.params).with_spare(spare)
    }

    /// Keeps a finished refiner's buffers for the next one.
    pub(crate) fn recycle(&self, mut refiner: Refiner<'_>) {
        if let Some(mesh) = refiner.take_buffers() {
            let mut spares = self.spares.lock().expect("spares lock");
            if spares.len() < MAX_SPARES {
                spares.push(mesh);
            }
        }
    }

    /// The deepest level: [`MAX_LEVEL`], or less where edges would get shorter than
    /// `min_edge_length_m`.
    pub fn max_level(&self) -> u8 {
        self.max_level
    }

    /// Nominal edge length of level-`level` content (see [`edge_length`]).
    pub fn edge_length(&self, level: u8) -> f64 {
        edge_length(&self.params, level)
    }

    /// Bytes the tiling keeps: the tree's maps and the remembered placements (estimate).
    pub fn bytes(&self) -> usize {
        // The spares it may keep count from the start: each about the base mesh and a tile's
        // splits.
        self.tree.bytes()
            + self.placements.lock().expect("placements lock").len() * 256
            + self.faces.get().map_or(0, |f| f.bytes())
            + self.rivers.get().map_or(0, |r| r.bytes())
            + self.colours.get().map_or(0, |c| c.bytes())
            + self.dem_overview.get().map_or(0, |o| o.len() * 4)
            + MAX_SPARES * self.planet.mesh.capacity_bytes() * 5 / 4
    }

    /// Geometric error of a level, metres: its nominal edge length.
    pub fn geometric_error(&self, level: u8) -> f64 {
        self.edge_length(level)
    }

    /// The pad of a level's boxes: [`PAD_EDGES`] edge lengths for what finer levels add, plus
    /// room for a child's box to tilt against its parent's (at most about `s²/6R` for cells of
    /// edge `s` on a sphere of radius `R`).
    fn spec(&self, level: u8) -> ContentSpec {
        let cell_edge = self.edge_length(level) * 2f64.powi(CONTENT_DEPTH as i32 / 2);
        ContentSpec {
            content_depth: CONTENT_DEPTH,
            skirt_m: self.geometric_error(level),
            pad_m: PAD_EDGES * self.edge_length(level) + cell_edge * cell_edge / (4.0 * self.params.radius_m),
            footprint_m: 0.5 * self.edge_length(level),
        }
    }

    /// The content of tile `key`, which must be at most [`PlanetTiles::max_level`] deep, its
    /// `.glb` stored as `compression` says. A function of the key alone: no other tile is made
    /// or needed.
    pub fn content(&self, key: TileKey, compression: Compression) -> TileContent {
        assert!(key.level <= self.max_level, "tile {key} is deeper than level {}", self.max_level);
        let mut refiner = self.refiner();
        let colours =
            self.colours.get_or_init(|| crate::export::colour_mip::ColourMip::new(&self.planet.mesh, &self.params));
        let spec = self.spec(key.level);
        let content = content::tile_content(&mut refiner, key, &spec, &self.params, Some(colours), compression);
        self.recycle(refiner);
        content
    }

    /// The content of `key`, placed (which places its ancestors first).
    pub fn placed_content(&self, key: TileKey, compression: Compression) -> TileContent {
        let content = self.content(key, compression);
        self.place(key, &content);
        content
    }

    /// The box of the contentless root around the whole planet: axis-aligned around the boxes
    /// of the level-0 tiles.
    pub fn planet_bounds(&self) -> OrientedBox {
        *self.planet_bounds.get_or_init(|| {
            let roots: Vec<OrientedBox> =
                (0..8).into_par_iter().map(|r| self.content(TileKey::root(r), Compression::None).bounds).collect();
            OrientedBox::fit(roots.iter().flat_map(|b| b.corners()), [DVec3::X, DVec3::Y, DVec3::Z], 0.0)
        })
    }

    /// Where tile `key` sits, making its content (and its ancestors') if not known yet.
    pub fn placement(&self, key: TileKey) -> Placement {
        if let Some(p) = self.placements.lock().expect("placements lock").get(&key) {
            return *p;
        }
        self.place(key, &self.content(key, Compression::None))
    }

    /// Makes the placements of `keys` (parents before children), their contents in parallel;
    /// returns the contents made on the way, as `(key, glb)` stored as `compression` says.
    pub fn place_all(&self, keys: &[TileKey], compression: Compression) -> Vec<(TileKey, Vec<u8>)> {
        let mut made = Vec::new();
        let mut by_level: Vec<TileKey> = keys.to_vec();
        by_level.sort_by_key(|k| (k.level, *k));
        for group in by_level.chunk_by(|a, b| a.level == b.level) {
            let known = self.placements.lock().expect("placements lock");
            let todo: Vec<TileKey> = group.iter().copied().filter(|k| !known.contains_key(k)).collect();
            drop(known);
            for key in &todo {
                if let Some(parent) = key.parent() {
                    self.placement(parent);
                }
            }
            let contents: Vec<(TileKey, Vec<u8>)> =
                todo.par_iter().map(|&k| (k, self.placed_content(k, compression).glb)).collect();
            made.extend(contents);
        }
        made
    }

    /// Places a content just made (its parent's placement is made first) and remembers it.
    fn place(&self, key: TileKey, content: &TileContent) -> Placement {
        let placement =
            Placement { origin: content.origin(), bounds: content.bounds.nested_in(&self.parent_bounds(key)) };
        let mut memo = self.placements.lock().expect("placements lock");
        if memo.len() >= MAX_PLACEMENTS {
            memo.clear();
        }
        memo.insert(key, placement);
        placement
    }

    fn parent_bounds(&self, key: TileKey) -> OrientedBox {
        match key.parent() {
            Some(parent) => self.placement(parent).bounds,
            None => self.planet_bounds(),
        }
    }
}

#[cfg(test)]
mod tests;
