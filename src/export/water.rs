//! The water surface (paper §3.3): the level it takes at every vertex of the faces it covers.
//!
//! Water stands where a vertex's water altitude is above its ground. A face with wet and dry
//! corners is partly flooded: its dry corners take the level of the water they border, below
//! their ground, so a flat surface meets the linearly interpolated ground inside the face (the
//! depth test draws the shore) instead of ramping up to the dry corners' ground.

use crate::mesh::Mesh;
use rayon::prelude::*;

/// Whether any corner of triangle `t` stands under water: the faces the water surface covers.
#[inline]
pub fn is_wet(mesh: &Mesh, t: &[u32; 3]) -> bool {
    t.iter().any(|&v| mesh.vertices[v as usize].submerged())
}

/// Level of the water surface at every vertex, metres above the base sphere: its own water
/// altitude where it is submerged, else the highest water altitude of the submerged vertices it
/// shares one of `triangles` with, else its own water (its ground). Deterministic: a maximum
/// does not depend on the order it is taken in.
pub fn water_levels(mesh: &Mesh, triangles: &[[u32; 3]]) -> Vec<f64> {
    let vertices = &mesh.vertices;
    let mut level: Vec<f64> =
        vertices.par_iter().map(|v| if v.submerged() { v.water } else { f64::NEG_INFINITY }).collect();
    // Each face's highest standing water, in parallel; spread to its dry corners in face order.
    let wet_faces: Vec<([u32; 3], f64)> = triangles
        .par_iter()
        .filter_map(|&corners| {
            let wet = corners
                .iter()
                .map(|&v| &vertices[v as usize])
                .filter(|v| v.submerged())
                .map(|v| v.water)
                .fold(f64::NEG_INFINITY, f64::max);
            (wet > f64::NEG_INFINITY).then_some((corners, wet))
        })
        .collect();
    for &(corners, wet) in &wet_faces {
        for v in corners {
            if !vertices[v as usize].submerged() {
                level[v as usize] = level[v as usize].max(wet);
            }
        }
    }
    level.par_iter_mut().zip(vertices.par_iter()).for_each(|(l, v)| {
        if *l == f64::NEG_INFINITY {
            *l = v.water;
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
}
