//! The water surface (paper §3.3): the level it takes at every vertex of the faces it covers.
//!
//! Water stands where a vertex's water altitude is above its ground. A face with wet and dry
//! corners is partly flooded: its dry corners take a level below their ground, so the surface
//! meets the linearly interpolated ground inside the face (the depth test, or the renderer's
//! signed depth, draws the shore) instead of ramping up to the dry corners' ground.
//!
//! Beside the sea and lakes that level is the water's own (a flat surface). Beside a river it
//! is set so that the shore crosses each edge from the river vertex at half the channel's width
//! ([`crate::mesh::channels`]): a 300 m river is about 300 m wide however large the faces
//! beside it, and a river that does not flow all year is a dry bed. A river narrower than
//! 1/[`EDGES_PER_WIDTH`] of the shortest edge at its vertex is not drawn at all (about a pixel
//! at views' default 8-pixel edges): in a coarse face between several river vertices the
//! surface would otherwise span the whole face, and a coarse tile or view would show land
//! crossed by streams as water.

use crate::mesh::{EdgeKind, Mesh, Vertex, VertexFlags};
use glam::DVec3;
use rayon::prelude::*;

/// One end of a river line ([`river_lines`]): the mesh's vertex, a point of the water surface
/// (planet frame), its local up, the share of a pixel the channel covers there (0-1) and the
/// channel's depth (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineEnd {
    pub vertex: u32,
    pub position: DVec3,
    pub up: DVec3,
    pub coverage: f64,
    pub depth_m: f64,
}

/// Width and depth (m) of the flowing channel at vertex `v`: `None` off rivers, for lakes and
/// for rivers that do not flow all year (a dry bed).
pub fn flowing_channel(mesh: &Mesh, v: u32) -> Option<(f64, f64)> {
    let width = channel_width(mesh, &mesh.vertices[v as usize]).filter(|&w| w > 0.0)?;
    Some((width, crate::planet::network::channel_depth_m(crate::planet::network::discharge_of_width(width))))
}

/// Rivers narrower than a pixel as lines, so that they stay visible at their true width: each
/// river edge between two channelled vertices ([`flowing_channel`]) becomes a line along its
/// water surface, with the share of one of `cam`'s pixels its channel covers at each end for
/// the line's opacity: its width over the pixel's footprint there, at most 1. Renders draw
/// them one pixel wide (`render/scene.rs`), `view.glb` as a LINES primitive.
pub fn river_lines(mesh: &Mesh, cam: &crate::adapt::Camera) -> Vec<[LineEnd; 2]> {
    let eye = cam.eye;
    // Metres a pixel spans per metre of distance.
    let pixel_per_m = 2.0 * (cam.fov_deg.to_radians() * 0.5).tan() / f64::from(cam.height);
    let end = |v: u32| -> Option<LineEnd> {
        let (width, depth_m) = flowing_channel(mesh, v)?;
        let vert = &mesh.vertices[v as usize];
        let up = vert.p().normalize_or(DVec3::Z);
        let position = vert.p() + up * (vert.water - vert.ground).max(0.0);
        let footprint = (position - eye).length() * pixel_per_m;
        Some(LineEnd { vertex: v, position, up, coverage: (width / footprint.max(1e-9)).min(1.0), depth_m })
    };
    mesh.edges
        .par_iter()
        .filter(|e| e.kind == EdgeKind::River)
        .filter_map(|e| Some([end(e.v[0])?, end(e.v[1])?]))
        .collect()
}

/// Whether any corner of triangle `t` stands under water (its ground below its water
/// altitude): the faces whose water [`water_levels`] looks at.
#[inline]
pub fn is_wet(mesh: &Mesh, t: &[u32; 3]) -> bool {
    t.iter().any(|&v| mesh.vertices[v as usize].submerged())
}

/// Whether triangle `t` shows water at the `levels` of [`water_levels`]: a corner's level is
/// above its ground. The faces the water surface covers.
#[inline]
pub fn shows_water(mesh: &Mesh, levels: &[f64], t: &[u32; 3]) -> bool {
    t.iter().any(|&v| levels[v as usize] > mesh.vertices[v as usize].ground)
}

/// The channel width (m) of a river vertex off lakes (see [`half_width`]).
pub fn channel_width(mesh: &Mesh, v: &Vertex) -> Option<f64> {
    half_width(mesh, v).map(|h| 2.0 * h)
}

/// Half the channel width (m) of a river vertex off lakes, where the mesh knows its rivers'
/// widths; `None` for the sea, lakes, land, or without widths. A river vertex of a fine view
/// far from the base mesh's rivers (a new arm) is a small stream.
pub(crate) fn half_width(mesh: &Mesh, v: &Vertex) -> Option<f64> {
    let channels = mesh.channels.as_deref()?;
    let f = v.flags;
    if !f.contains(VertexFlags::RIVER) || f.contains(VertexFlags::LAKE) {
        return None;
    }
    Some(f64::from(channels.width_at(v.p().normalize()).unwrap_or(SMALL_STREAM_M)) * 0.5)
}

/// A river shows water where its channel is at least the shortest edge at its vertex over this.
pub const EDGES_PER_WIDTH: f64 = 8.0;

/// The shortest edge (m) at each vertex among `triangles`' edges; infinite for vertices of
/// none.
fn shortest_edges(mesh: &Mesh, triangles: &[[u32; 3]]) -> Vec<f64> {
    let mut shortest = vec![f64::INFINITY; mesh.vertices.len()];
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
            let len = mesh.vertices[a].p().distance(mesh.vertices[b].p());
            shortest[a] = shortest[a].min(len);
            shortest[b] = shortest[b].min(len);
        }
    }
    shortest
}

/// Half the channel width (m) of every vertex ([`half_width`]: `None` off rivers) and the
/// shortest edge (m) at it among `triangles`' edges (infinite for vertices of none).
pub fn channel_halves(mesh: &Mesh, triangles: &[[u32; 3]]) -> (Vec<Option<f64>>, Vec<f64>) {
    (mesh.vertices.par_iter().map(|v| half_width(mesh, v)).collect(), shortest_edges(mesh, triangles))
}

/// Whether a channel `half` metres wide on each side shows as water at a vertex whose shortest
/// edge is `shortest` metres: it flows, and is at least 1/[`EDGES_PER_WIDTH`] of that edge.
pub fn shows_channel(half: f64, shortest: f64) -> bool {
    half > 0.0 && 2.0 * half * EDGES_PER_WIDTH >= shortest
}

/// The water level (m above the base sphere) a flowing river vertex carries: its own water,
/// [`SHALLOW_RIVER_M`] over its ground where the mesh gives it none.
pub fn river_level(v: &Vertex) -> f64 {
    if v.submerged() {
        v.water
    } else {
        v.ground + SHALLOW_RIVER_M
    }
}

/// Width (m) of a river vertex with no base-mesh river near it.
pub const SMALL_STREAM_M: f32 = 2.0;

/// Depth (m) of the water drawn at a flowing river's vertex where the mesh gives it none (its
/// water at its ground). Where the shore lies does not depend on it, only the water's colour.
pub const SHALLOW_RIVER_M: f64 = 1.0;

/// Level of the water surface at every vertex, metres above the base sphere: its own water
/// altitude where it is submerged (a river's dry bed excepted), else the highest level the
/// water of the faces of `triangles` it shares with submerged vertices gives it (see the
/// module's doc), else its own water (its ground). Deterministic: a maximum does not depend on
/// the order it is taken in.
pub fn water_levels(mesh: &Mesh, triangles: &[[u32; 3]]) -> Vec<f64> {
    let vertices = &mesh.vertices;
    let (half, shortest) = channel_halves(mesh, triangles);
    // A flowing river's vertex carries its channel's water, SHALLOW_RIVER_M deep where the
    // mesh gives it none; a dry bed carries none, nor a river too narrow for the faces at it.
    let shown = |v: usize| half[v].is_none_or(|h| shows_channel(h, shortest[v]));
    let wet = |v: usize| (vertices[v].submerged() || half[v].is_some()) && shown(v);
    let own = |v: usize| if half[v].is_some() { river_level(&vertices[v]) } else { vertices[v].water };
    let mut level: Vec<f64> =
        (0..vertices.len()).into_par_iter().map(|v| if wet(v) { own(v) } else { f64::NEG_INFINITY }).collect();
    // The level each face's water gives each of its dry corners, in parallel; the highest per
    // vertex, in face order.
    let offers: Vec<(u32, f64)> = triangles
        .par_iter()
        .filter(|corners| corners.iter().any(|&v| wet(v as usize)))
        .flat_map_iter(|&corners| {
            let mut out = [(0u32, f64::NEG_INFINITY); 3];
            for (slot, &v) in out.iter_mut().zip(&corners) {
                if wet(v as usize) {
                    continue;
                }
                let dry = &vertices[v as usize];
                let best = corners
                    .iter()
                    .filter(|&&u| wet(u as usize))
                    .map(|&u| {
                        // A wet corner's level is its own water (`level` holds it until the
                        // offers are merged below).
                        let (river, water) = (&vertices[u as usize], level[u as usize]);
                        match half[u as usize] {
                            None => water,
                            Some(h) => {
                                let along = river.p().normalize().distance(dry.p().normalize()) * mesh.radius;
                                if h >= along {
                                    water
                                } else {
                                    // The signed depth, linear along the edge, is zero `h` from
                                    // the river vertex.
                                    dry.ground - (water - river.ground) * (along / h - 1.0)
                                }
                            }
                        }
                    })
                    .fold(f64::NEG_INFINITY, f64::max);
                *slot = (v, best);
            }
            out.into_iter().filter(|&(_, l)| l > f64::NEG_INFINITY)
        })
        .collect();
    for (v, offer) in offers {
        level[v as usize] = level[v as usize].max(offer);
    }
    level.par_iter_mut().zip(vertices.par_iter()).for_each(|(l, v)| {
        if *l == f64::NEG_INFINITY {
            *l = v.water.min(v.ground);
        }
    });
    level
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Vertex;
    use glam::DVec3;

    /// A fan of two faces: a river vertex (water 10 m over ground 7 m) between a low bank at
    /// 12 m and a high one at 30 m, and a far vertex that shares no face with the river.
    fn fan() -> (Mesh, Vec<[u32; 3]>) {
        let mut vs: Vec<Vertex> = (0..5).map(|i| Vertex::new(DVec3::new(1.0, i as f64, 0.0), i)).collect();
        for (v, (g, w)) in vs.iter_mut().zip([(7.0, 10.0), (12.0, 12.0), (30.0, 30.0), (20.0, 20.0), (3.0, 5.0)]) {
            v.ground = g;
            v.water = w;
        }
        let mesh = Mesh { radius: 1.0, vertices: vs, ..Mesh::default() };
        (mesh, vec![[0, 1, 2], [1, 3, 2], [4, 3, 2]])
    }

    #[test]
    fn banks_take_the_level_of_the_water_they_border() {
        let (mesh, tris) = fan();
        let level = water_levels(&mesh, &tris);
        // Wet vertices keep their own water; dry ones in wet faces the highest bordering water
        // (vertex 2 borders 10 m and 5 m); a dry vertex in dry faces only keeps its ground.
        assert_eq!(level, vec![10.0, 10.0, 10.0, 5.0, 5.0]);
        assert_eq!(tris.iter().map(|t| is_wet(&mesh, t)).collect::<Vec<_>>(), [true, false, true]);
        let dry = water_levels(&mesh, &tris[1..2]);
        assert_eq!(dry, vec![10.0, 12.0, 30.0, 20.0, 5.0]);
        // The order of the faces does not matter.
        let mut reversed = tris.clone();
        reversed.reverse();
        assert_eq!(water_levels(&mesh, &reversed), level);
    }

    /// A river vertex between two dry banks 100 m away, with the base mesh's channels of
    /// `width` metres at its place; its water 3 m over its bed, or none.
    fn channel(width: f32, depth: f64) -> (Mesh, Vec<[u32; 3]>) {
        let r = 1000.0;
        let dirs = [DVec3::X, DVec3::new(0.1f64.cos(), 0.1f64.sin(), 0.0), DVec3::new(0.1f64.cos(), 0.0, 0.1f64.sin())];
        let mut vs: Vec<Vertex> = dirs.iter().enumerate().map(|(i, d)| Vertex::new(*d * r, i as u32)).collect();
        for (v, g) in vs.iter_mut().zip([7.0, 12.0, 30.0]) {
            v.ground = g;
            v.water = g;
        }
        vs[0].water = 7.0 + depth;
        vs[0].flags = VertexFlags::RIVER;
        let channels = crate::mesh::channels::Channels::new(&[(DVec3::X, width)], 100.0, 100.0, r).unwrap();
        let mesh = Mesh { radius: r, vertices: vs, channels: Some(std::sync::Arc::new(channels)), ..Mesh::default() };
        (mesh, vec![[0, 1, 2]])
    }

    #[test]
    fn a_river_is_as_wide_as_its_channel() {
        let (mesh, tris) = channel(50.0, 3.0);
        let level = water_levels(&mesh, &tris);
        assert_eq!(level[0], 10.0);
        // Along each edge from the river, the signed depth (linear) is zero 25 m out.
        for bank in [1, 2] {
            let along = mesh.vertices[0].p().distance(mesh.vertices[bank].p());
            let (d0, d1) = (level[0] - 7.0, level[bank] - mesh.vertices[bank].ground);
            let shore = along * d0 / (d0 - d1);
            assert!((shore - 25.0).abs() < 1e-9, "bank {bank}: shore {shore} m out");
        }
        assert!(shows_water(&mesh, &level, &tris[0]));
        // A channel wider than the faces covers them at the river's level (the banks' ground
        // draws the shore).
        let (wide, tris) = channel(500.0, 3.0);
        assert_eq!(water_levels(&wide, &tris), vec![10.0, 10.0, 10.0]);
        // A river with no depth in the mesh still carries water.
        let (shallow, tris) = channel(50.0, 0.0);
        assert_eq!(water_levels(&shallow, &tris)[0], 7.0 + SHALLOW_RIVER_M);
        // A river narrower than an eighth of the shortest edge at it (10 m against 100 m) is
        // not drawn: the face shows land, as a coarse tile or view should.
        let (narrow, tris) = channel(10.0, 3.0);
        let level = water_levels(&narrow, &tris);
        assert_eq!(level, vec![7.0, 12.0, 30.0]);
        assert!(!shows_water(&narrow, &level, &tris[0]));
        // A dry bed (a river that does not flow all year) shows no water at all.
        let (wadi, tris) = channel(0.0, 3.0);
        let level = water_levels(&wadi, &tris);
        assert_eq!(level, vec![7.0, 12.0, 30.0]);
        assert!(!shows_water(&wadi, &level, &tris[0]));
    }
}
