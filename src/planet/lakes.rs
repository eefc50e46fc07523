//! Lakes of a planet built from an elevation map: the depressions [`super::relief`] keeps
//! and the terminal lakes of closed basins ([`super::basins`]), as features with a level, an
//! area and an outline on the base mesh.
//!
//! **Outline.** A lake is the set of base-mesh vertices under its water. Its shore runs
//! through the middle of every edge from a lake vertex to one off the lake, joined inside each
//! face that has both (marching triangles with the indicator at 0.5), so the outline is the
//! boundary of the union of the lake vertices' cells. Walked with the lake on the left, an
//! outer shore turns counter-clockwise seen from above and an island's shore clockwise, as
//! RFC 7946 asks of polygon rings.

use super::relief::LakeLevel;
use crate::mesh::{Mesh, NONE};
use glam::DVec3;
use std::collections::HashMap;

/// One lake.
#[derive(Clone, Debug, PartialEq)]
pub struct Lake {
    pub id: u32,
    /// Surface altitude, m relative to sea level.
    pub water_altitude_m: f64,
    /// Area of its vertices' cells (a third of each face around each), m².
    pub area_m2: f64,
    /// No outlet to the sea: the terminal lake of a closed basin.
    pub endorheic: bool,
}

/// The lakes of `lake_of` (lake per vertex, `NONE` off lakes) at `levels`.
pub fn lakes(mesh: &Mesh, lake_of: &[u32], levels: &[LakeLevel]) -> Vec<Lake> {
    let mut area = vec![0.0f64; levels.len()];
    for f in 0..mesh.faces.len() as u32 {
        let a = mesh.face_area_vector(f).length() / 3.0;
        for v in mesh.corners(f) {
            if let Some(&l) = lake_of.get(v as usize).filter(|&&l| l != NONE) {
                area[l as usize] += a;
            }
        }
    }
    levels
        .iter()
        .enumerate()
        .map(|(i, l)| Lake { id: i as u32, water_altitude_m: l.level, area_m2: area[i], endorheic: l.endorheic })
        .collect()
}

/// The shores of every lake: closed rings of points on the base sphere (the last point
/// repeats the first), the lake on the left.
pub fn outlines(mesh: &Mesh, lake_of: &[u32], count: usize) -> Vec<Vec<Vec<DVec3>>> {
    let in_lake = |v: u32| lake_of.get(v as usize).copied().unwrap_or(NONE);
    // Each face with a shore: from the midpoint of the edge where (counter-clockwise) the
    // lake ends, to the midpoint of the edge where it begins. Keyed by the entry edge.
    let mut next: HashMap<(u32, u32), ((u32, u32), u32)> = HashMap::new();
    for f in 0..mesh.faces.len() as u32 {
        let c = mesh.corners(f);
        let ids = c.map(in_lake);
        for (k, &l) in ids.iter().enumerate() {
            if l == NONE || ids[..k].contains(&l) {
                continue;
            }
            let wet = ids.map(|x| x == l);
            // Edge k runs c[k] -> c[k+1]: the lake ends on it when c[k] is wet and c[k+1] dry.
            let ends = (0..3).find(|&k| wet[k] && !wet[(k + 1) % 3]);
            let begins = (0..3).find(|&k| !wet[k] && wet[(k + 1) % 3]);
            if let (Some(a), Some(b)) = (ends, begins) {
                next.insert((c[a], c[(a + 1) % 3]), ((c[b], c[(b + 1) % 3]), l));
            }
        }
    }
    let mid =
        |(a, b): (u32, u32)| ((mesh.pos(a).normalize() + mesh.pos(b).normalize()) * 0.5).normalize() * mesh.radius;
    let mut rings: Vec<Vec<Vec<DVec3>>> = vec![Vec::new(); count];
    let mut keys: Vec<(u32, u32)> = next.keys().copied().collect();
    keys.sort_unstable();
    let mut seen = std::collections::HashSet::new();
    for start in keys {
        if seen.contains(&start) {
            continue;
        }
        let lake = next[&start].1;
        let mut ring = Vec::new();
        let mut edge = start;
        // The exit edge (b, c) of one face is the entry edge (c, b) of the face across it.
        while seen.insert(edge) {
            ring.push(mid(edge));
            match next.get(&edge) {
                Some(&((a, b), _)) => edge = (b, a),
                None => break,
            }
        }
        if ring.len() >= 3 {
            ring.push(ring[0]);
            rings[lake as usize].push(ring);
        }
    }
    rings
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planet::shape::octahedron;

    #[test]
    fn a_lake_at_a_vertex_is_ringed_by_its_edge_midpoints() {
        let mesh = octahedron(1.0, 1);
        let mut lake_of = vec![NONE; mesh.vertices.len()];
        lake_of[0] = 0;
        let rings = outlines(&mesh, &lake_of, 1);
        assert_eq!(rings[0].len(), 1);
        let ring = &rings[0][0];
        assert_eq!(ring.len(), 5, "four neighbours' midpoints, closed");
        assert_eq!(ring[0], ring[4]);
        // Counter-clockwise around the lake's vertex seen from outside.
        let p = mesh.pos(0);
        let turn: f64 = (0..4).map(|i| ring[i].cross(ring[i + 1]).dot(p)).sum();
        assert!(turn > 0.0);
        let l = lakes(&mesh, &lake_of, &[LakeLevel { depression: 0, level: 12.0, endorheic: true }]);
        // A third of the four faces around it: an eighth of the sphere's area, over 3, times 4.
        let want = 4.0 * std::f64::consts::PI / 8.0 / 3.0 * 4.0;
        assert!(l[0].area_m2 > 0.5 * want && l[0].area_m2 < want, "{}", l[0].area_m2);
    }
}
