use super::*;
use crate::mesh::{EdgeKind, VertexFlags, NONE};

fn planet(seed: u64, faces: u32) -> Planet {
    let spec =
        PlanetSpec { seed, params: Params { base_faces: faces, ..Params::default() }, map: None, precipitation: None };
    build_planet(&spec, &mut |_, _| {}).unwrap()
}

#[test]
fn random_planet_is_valid_and_reproducible() {
    let a = planet(42, 5000);
    a.mesh.validate().unwrap();
    let b = planet(42, 5000);
    assert_eq!(a.mesh, b.mesh);
    let c = planet(43, 5000);
    assert_ne!(a.mesh, c.mesh);
    let s = &a.stats;
    assert!((s.land_fraction - 0.29).abs() < 0.06, "land {}", s.land_fraction);
    assert!(s.continents >= 1 && s.continents <= 6, "{}", s.continents);
    assert!(s.river_mouths > 0 && s.river_edges > s.river_mouths);
    assert!(s.faces >= 5000);
}

#[test]
fn river_invariants_hold() {
    for seed in [1u64, 2, 3] {
        let p = planet(seed, 3000);
        let (m, g) = (&p.mesh, &p.rivers);
        assert_eq!(g.monotone_violations, 0, "seed {seed}");
        // Every river vertex flows down to a mouth; water never rises downstream.
        for &v in &g.order {
            let mut x = v;
            let mut steps = 0;
            while g.downstream[x as usize] != NONE {
                let d = g.downstream[x as usize];
                assert!(m.vertices[d as usize].water < m.vertices[x as usize].water);
                x = d;
                steps += 1;
                assert!(steps < m.vertices.len());
            }
            assert!(m.vertices[x as usize].flags.contains(VertexFlags::MOUTH), "seed {seed}: {v} ends at {x}");
        }
        // Every inland vertex is on the network or a mountain next to it.
        let adj = m.adjacency();
        for (v, vert) in m.vertices.iter().enumerate() {
            if vert.flags.is_inland() && !vert.flags.contains(VertexFlags::RIVER) {
                assert!(vert.flags.contains(VertexFlags::MOUNTAIN), "inland vertex {v} is neither river nor mountain");
                // Mountains stand above the rivers around them.
                for (w, _) in adj.around(v as u32) {
                    let wv = &m.vertices[w as usize];
                    if wv.flags.contains(VertexFlags::RIVER) {
                        assert!(vert.ground > wv.water, "mountain {v} not above river {w}");
                    }
                }
            }
        }
        // No river edge touches a mountain vertex.
        for e in &m.edges {
            if e.kind == EdgeKind::River {
                for &v in &e.v {
                    assert!(!m.vertices[v as usize].flags.contains(VertexFlags::MOUNTAIN));
                }
            }
        }
        // Rivers never cross: each river vertex has at most one outflow (a forest).
        for &v in &g.order {
            let lower = adj
                .around(v)
                .filter(|&(w, e)| {
                    m.edges[e as usize].kind == EdgeKind::River
                        && m.vertices[w as usize].water < m.vertices[v as usize].water
                })
                .count();
            assert!(lower <= 1, "vertex {v} has {lower} outflows");
        }
        assert!(p.stats.drained_fraction > 0.999, "drained {}", p.stats.drained_fraction);
    }
}

#[test]
fn merges_of_more_than_two_rivers_are_rare() {
    let p = planet(5, 5000);
    let g = &p.rivers;
    let river = g.order.len();
    let crowded = g.order.iter().filter(|&&v| g.tributaries(v) > 2).count();
    assert!(crowded * 100 <= river, "{crowded} of {river} river vertices join more than two rivers");
}

#[test]
fn reaches_link_downstream() {
    let p = planet(9, 3000);
    let reaches = p.rivers.reaches(&p.mesh, &p.water);
    assert!(!reaches.is_empty());
    for r in &reaches {
        assert!(r.vertices.len() >= 2 || r.downstream_id.is_none());
        if let Some(d) = r.downstream_id {
            assert_eq!(reaches[d].vertices[0], *r.vertices.last().unwrap());
            assert!(reaches[d].strahler >= r.strahler);
            assert!(reaches[d].upstream_area_m2 >= r.upstream_area_m2);
        }
    }
}

#[test]
fn altitudes_respect_the_parameters() {
    let p = planet(4, 3000);
    let par = Params::default();
    for v in &p.mesh.vertices {
        if v.flags.contains(VertexFlags::MOUTH) {
            assert_eq!(v.ground, par.mouth_ground());
            assert_eq!(v.water, par.sea_level_m);
        } else if v.flags.is_pure_sea() {
            assert!(v.ground < par.sea_level_m && v.water == par.sea_level_m);
        }
        if v.flags.contains(VertexFlags::RIVER) {
            assert!(v.water >= v.ground);
        }
        assert!(v.ground <= par.max_mountain_altitude_m + 1.0, "{v:?}");
    }
}
