//! Continents (paper §4.1): faces labelled sea or land, either grown at random face by face to a
//! land percentage, or read from a user's map (Figure 8 mode); then edges and vertices typed.

use crate::maps::{Map, MapKind};
use crate::mesh::{EdgeKind, FaceKind, Mesh, VertexFlags};
use crate::rng::Sequence;
use glam::DVec3;

use crate::geo::lat_lon;

/// Centroid of a face.
pub fn face_centre(mesh: &Mesh, f: u32) -> DVec3 {
    mesh.corners(f).iter().map(|&v| mesh.pos(v)).sum::<DVec3>() / 3.0
}

/// Grows `count` continents from random start faces until land covers `land_percent` of the
/// surface. A face may join a continent when its vertices already belong to that continent,
/// except at most one pure sea vertex, so two continents never share a vertex (§4.1).
/// Returns the land fraction reached.
pub fn grow_random(mesh: &mut Mesh, count: u32, land_percent: f64, seed: u64) -> f64 {
    const FREE: u16 = u16::MAX;
    let nf = mesh.faces.len();
    let areas: Vec<f64> = (0..nf as u32).map(|f| mesh.face_area_vector(f).length()).collect();
    let total: f64 = areas.iter().sum();
    let target = total * land_percent / 100.0;
    let mut owner = vec![FREE; mesh.vertices.len()];
    let mut rng = Sequence::new(seed, 0xc0_7713);
    let mut frontier: Vec<Vec<u32>> = Vec::new();
    let mut land = 0.0;
    for e in mesh.edges.iter_mut() {
        e.land = 0;
    }

    let add = |mesh: &mut Mesh, owner: &mut [u16], frontier: &mut Vec<u32>, f: u32, c: u16| {
        let face = mesh.faces[f as usize];
        mesh.set_face_kind(f, FaceKind::Land);
        for v in mesh.corners(f) {
            owner[v as usize] = c;
        }
        for &e in &face.e {
            let g = mesh.edges[e as usize].other_face(f);
            if mesh.face_kind(g) == FaceKind::Sea {
                frontier.push(g);
            }
        }
        areas[f as usize]
    };

    for c in 0..count.min(u16::MAX as u32 - 1) as u16 {
        for _ in 0..10_000 {
            let f = rng.below(nf) as u32;
            if mesh.corners(f).iter().all(|&v| owner[v as usize] == FREE) {
                let mut list = Vec::new();
                land += add(mesh, &mut owner, &mut list, f, c);
                frontier.push(list);
                break;
            }
        }
    }
    let mut active: Vec<usize> = (0..frontier.len()).collect();
    while land < target && !active.is_empty() {
        let k = rng.below(active.len());
        let c = active[k];
        let list = &mut frontier[c];
        if list.is_empty() {
            active.swap_remove(k);
            continue;
        }
        let i = rng.below(list.len());
        let f = list.swap_remove(i);
        if mesh.face_kind(f) == FaceKind::Land {
            continue;
        }
        let corners = mesh.corners(f);
        let free = corners.iter().filter(|&&v| owner[v as usize] == FREE).count();
        let ours = corners.iter().filter(|&&v| owner[v as usize] == c as u16).count();
        if free <= 1 && free + ours == 3 {
            let mut list = std::mem::take(&mut frontier[c]);
            land += add(mesh, &mut owner, &mut list, f, c as u16);
            frontier[c] = list;
        }
    }
    classify(mesh);
    land / total
}

/// Labels faces from a map: land where the map says so at the face centre; sea outside the
/// map's bounds and where it has no data. On an elevation map, ground below sea level is sea
/// only where it joins the ocean ([`Map::ocean_pixels`]: an ocean pixel within one pixel of the
/// face centre); elsewhere (the Caspian, the Qattara Depression) it is land, and the rivers
/// make it a lake or drain it.
pub fn from_map(mesh: &mut Mesh, map: &Map) {
    let ocean = (map.kind == MapKind::Elevation).then(|| map.ocean_pixels());
    let kinds: Vec<FaceKind> = (0..mesh.faces.len() as u32)
        .map(|f| {
            let (lat, lon) = lat_lon(face_centre(mesh, f));
            let land = match map.sample(lat, lon) {
                Some(v) if is_land(map.kind, v) => true,
                Some(_) => ocean.as_ref().is_some_and(|o| !map.window(lat, lon, 1).any(|i| o[i])),
                None => false,
            };
            if land {
                FaceKind::Land
            } else {
                FaceKind::Sea
            }
        })
        .collect();
    for (f, k) in kinds.into_iter().enumerate() {
        mesh.set_face_kind(f as u32, k);
    }
    classify(mesh);
}

/// Whether a map value means land: half white in a bitmap, at or above sea level in metres.
pub fn is_land(kind: MapKind, value: f32) -> bool {
    match kind {
        MapKind::Continents => value >= 0.5,
        MapKind::Elevation => value >= 0.0,
    }
}

/// Types every edge from its faces and every vertex from its edges (§3.2); clears rivers.
pub fn classify(mesh: &mut Mesh) {
    for e in mesh.edges.iter_mut() {
        let [a, b] = e.face_kinds();
        e.kind = EdgeKind::between(a, b);
    }
    for v in mesh.vertices.iter_mut() {
        v.flags = VertexFlags::empty();
    }
    for e in &mesh.edges {
        for &v in &e.v {
            mesh.vertices[v as usize].flags.insert(e.kind.flag());
        }
    }
}

/// Share of the surface covered by land faces.
pub fn land_fraction(mesh: &Mesh) -> f64 {
    let mut land = 0.0;
    let mut total = 0.0;
    for f in 0..mesh.faces.len() as u32 {
        let a = mesh.face_area_vector(f).length();
        total += a;
        if mesh.face_kind(f) == FaceKind::Land {
            land += a;
        }
    }
    land / total
}

/// Number of continents: groups of land faces joined through edges or shared vertices.
pub fn count_continents(mesh: &Mesh) -> usize {
    let n = mesh.vertices.len();
    let mut parent: Vec<u32> = (0..n as u32).collect();
    fn find(p: &mut [u32], mut x: u32) -> u32 {
        while p[x as usize] != x {
            p[x as usize] = p[p[x as usize] as usize];
            x = p[x as usize];
        }
        x
    }
    let mut on_land = vec![false; n];
    for f in 0..mesh.faces.len() as u32 {
        if mesh.face_kind(f) == FaceKind::Land {
            let corners = mesh.corners(f);
            for &v in &corners {
                on_land[v as usize] = true;
            }
            let r0 = find(&mut parent, corners[0]);
            for &v in &corners[1..] {
                let r = find(&mut parent, v);
                parent[r as usize] = r0;
            }
        }
    }
    (0..n as u32).filter(|&v| on_land[v as usize] && find(&mut parent, v) == v).count()
}
