use super::*;
use crate::planet::shape::{octahedron, refine_to};
use glam::DVec3;

fn sphere(faces: usize) -> Mesh {
    let mut m = octahedron(6_371_000.0, 11);
    refine_to(&mut m, faces, 11);
    m
}

fn midpoint_vertex(m: &Mesh, site: &SplitSite) -> Vertex {
    let p = (m.pos(site.a) + m.pos(site.b)).normalize() * m.radius;
    Vertex { flags: VertexFlags::REFINED, ..Vertex::new(p, 7) }
}

#[test]
fn split_then_collapse_restores_the_mesh() {
    let base = sphere(500);
    let mut m = base.clone();
    let e = (0..m.edges.len() as u32).find(|&e| m.split_site(e).is_some()).unwrap();
    let site = m.split_site(e).unwrap();
    let v = midpoint_vertex(&m, &site);
    let s = m.split_edge(&site, v, [EdgeKind::Sea; 4]);
    m.validate().unwrap();
    assert_eq!(m.faces.len(), base.faces.len() + 2);
    assert_eq!(m.edges.len(), base.edges.len() + 3);
    let c = m.collapse_site(s.v).expect("fresh split vertex collapses");
    assert_eq!(c.e, s.e);
    m.collapse_vertex(&c);
    let mut spatial = m.clone();
    m.compact();
    m.validate().unwrap();
    assert_eq!(m, base);
    // Spatial order depends on the mesh alone: the base mesh compacts to the same buffers.
    spatial.compact_in_spatial_order();
    spatial.validate().unwrap();
    assert_ne!(spatial, base);
    let mut base = base;
    base.compact_in_spatial_order();
    assert_eq!(spatial, base);
}

#[test]
fn base_vertices_and_refined_neighbourhoods_do_not_collapse() {
    let mut m = sphere(200);
    assert!((0..m.vertices.len() as u32).all(|v| m.collapse_site(v).is_none()));
    let e = (0..m.edges.len() as u32).find(|&e| m.split_site(e).is_some()).unwrap();
    let site = m.split_site(e).unwrap();
    let v = midpoint_vertex(&m, &site);
    let s = m.split_edge(&site, v, [EdgeKind::Sea; 4]);
    // Splitting a child's refinement edge makes the first vertex uncollapsible until undone.
    let child_edge = m.faces[s.f[0] as usize].e[0];
    let mut make = |m: &Mesh, site: &SplitSite| (midpoint_vertex(m, site), [EdgeKind::Sea; 4]);
    let done = m.refine_edge(child_edge, &mut make);
    m.validate().unwrap();
    assert!(m.collapse_site(s.v).is_none());
    for split in done.iter().rev() {
        let c = m.collapse_site(split.v).unwrap();
        m.collapse_vertex(&c);
    }
    assert!(m.collapse_site(s.v).is_some());
}

#[test]
fn split_types_follow_section_3_2() {
    assert_eq!(
        split_kinds(EdgeKind::River, FaceKind::Land, FaceKind::Land),
        [EdgeKind::River, EdgeKind::Continent, EdgeKind::River, EdgeKind::Continent]
    );
    assert_eq!(
        split_kinds(EdgeKind::Coast, FaceKind::Sea, FaceKind::Land),
        [EdgeKind::Coast, EdgeKind::Sea, EdgeKind::Coast, EdgeKind::Continent]
    );
    assert_eq!(split_kinds(EdgeKind::Sea, FaceKind::Sea, FaceKind::Sea), [EdgeKind::Sea; 4]);
    assert_eq!(split_kinds(EdgeKind::Continent, FaceKind::Land, FaceKind::Land), [EdgeKind::Continent; 4]);
}

#[test]
fn random_refinement_and_coarsening_round_trips() {
    // Refine at random places, then collapse everything collapsible until nothing is: the base
    // mesh comes back exactly.
    let base = sphere(300);
    let mut m = base.clone();
    let mut rng = crate::rng::Sequence::new(3, 3);
    let mut make = |m: &Mesh, site: &SplitSite| (midpoint_vertex(m, site), [EdgeKind::Sea; 4]);
    for _ in 0..200 {
        let e = rng.below(m.edges.len()) as u32;
        m.refine_edge(e, &mut make);
    }
    m.validate().unwrap();
    assert!(m.vertices.len() > base.vertices.len() + 200);
    loop {
        let ready: Vec<u32> = (0..m.vertices.len() as u32).filter(|&v| m.collapse_site(v).is_some()).collect();
        if ready.is_empty() {
            break;
        }
        for v in ready {
            if let Some(c) = m.collapse_site(v) {
                m.collapse_vertex(&c);
            }
        }
    }
    m.compact();
    m.validate().unwrap();
    assert_eq!(m.faces.len(), base.faces.len());
    // Every buffer comes back, field for field (levels, bounds, kinds, links), once both are
    // in the same (spatial) order.
    let mut base = base;
    m.compact_in_spatial_order();
    base.compact_in_spatial_order();
    assert!(m == base, "the coarsened mesh differs from the base mesh");
}

#[test]
fn memory_per_vertex_is_reported() {
    let m = sphere(1000);
    let bpv = m.bytes_per_vertex();
    // V - E + F = 2 with E = 3V - 6, F = 2V - 4.
    let expected = (VERTEX_BYTES + 3 * EDGE_BYTES + 2 * FACE_BYTES) as f64;
    assert!((bpv - expected).abs() < 2.0, "{bpv} vs {expected}");
}

#[test]
fn adjacency_lists_every_edge_twice() {
    let m = sphere(400);
    let adj = m.adjacency();
    let total: usize = (0..m.vertices.len() as u32).map(|v| adj.degree(v)).sum();
    assert_eq!(total, 2 * m.edges.len());
    let v = 0u32;
    for (w, e) in adj.around(v) {
        assert_eq!(m.edges[e as usize].other(v), w);
    }
    assert!(DVec3::from_array(m.vertices[0].pos).length() > 0.0);
}

#[test]
fn batches_of_splits_and_collapses_equal_one_at_a_time() {
    // Every ready edge of a refined sphere split at once (many share outer edges and corners),
    // then every collapsible vertex collapsed at once: the same buffers as one by one in order.
    let mut m = sphere(4000);
    let mut make = |m: &Mesh, site: &SplitSite| (midpoint_vertex(m, site), [EdgeKind::Sea; 4]);
    let mut rng = crate::rng::Sequence::new(5, 5);
    for _ in 0..300 {
        let e = rng.below(m.edges.len()) as u32;
        m.refine_edge(e, &mut make);
    }
    // Land and sea faces mixed, so the splits have every kind of edge to pass on.
    for f in (0..m.faces.len() as u32).filter(|f| f % 3 == 0) {
        m.set_face_kind(f, FaceKind::Land);
    }
    crate::planet::continents::classify(&mut m);
    let sites: Vec<SplitSite> = (0..m.edges.len() as u32).filter_map(|e| m.split_site(e)).collect();
    assert!(sites.len() > 1000, "{}", sites.len());
    // Each vertex a function of its diamond: the edge's midpoint, seeded by the edge.
    let from_diamond = |d: &Diamond| {
        let p = (d.a().p() + d.b().p()).normalize() * d.radius;
        let [f1, f2] = d.edge.face_kinds();
        (Vertex { flags: VertexFlags::REFINED, ..Vertex::new(p, d.site.edge) }, split_kinds(d.edge.kind, f1, f2))
    };
    let (mut batch, mut single) = (m.clone(), m.clone());
    let edges: Vec<u32> = sites.iter().map(|s| s.edge).collect();
    assert_eq!(batch.split_edges(&edges, from_diamond), sites.len());
    for site in &sites {
        let (v, kinds) = from_diamond(&Diamond::new(&single, site));
        single.split_edge(site, v, kinds);
    }
    batch.validate().unwrap();
    assert!(batch == single, "split batch differs");

    let collapsible: Vec<CollapseSite> =
        (0..batch.vertices.len() as u32).filter_map(|v| batch.collapse_site(v)).collect();
    assert!(collapsible.len() >= edges.len(), "{}", collapsible.len());
    // SAFETY: the sites were found on this mesh, one per vertex.
    unsafe { batch.collapse_vertices(&collapsible) };
    for site in &collapsible {
        single.collapse_vertex(site);
    }
    assert!(batch == single, "collapse batch differs");
    batch.compact();
    batch.validate().unwrap();
}

#[test]
#[should_panic(expected = "is not ready to split")]
fn a_batch_refuses_an_edge_that_is_not_ready() {
    let mut m = sphere(400);
    let e = (0..m.edges.len() as u32).find(|&e| m.split_site(e).is_none()).unwrap();
    m.split_edges(&[e], |_| unreachable!("the diamond of an edge that is not ready is never made"));
}

#[test]
fn a_face_kind_is_kept_by_its_three_edges() {
    let mut m = sphere(400);
    let f = 7;
    assert!((0..m.faces.len() as u32).all(|g| m.face_kind(g) == FaceKind::Sea));
    m.set_face_kind(f, FaceKind::Land);
    for e in m.faces[f as usize].e {
        let edge = &m.edges[e as usize];
        assert_eq!(edge.face_kind(f), FaceKind::Land);
        // The neighbour across the edge is still sea.
        let g = edge.other_face(f);
        assert_eq!(edge.face_kind(g), FaceKind::Sea);
        assert_eq!(m.face_kind(g), FaceKind::Sea);
        assert_eq!(edge.face_kinds().iter().filter(|&&k| k == FaceKind::Land).count(), 1);
    }
    assert_eq!((0..m.faces.len() as u32).filter(|&g| m.face_kind(g) == FaceKind::Land).count(), 1);
    // Edge kinds not yet following the faces: validation names the mismatch.
    let err = m.validate().unwrap_err();
    assert!(err.contains("lies between faces of kinds"), "{err}");
    crate::planet::continents::classify(&mut m);
    m.validate().unwrap();
    m.set_face_kind(f, FaceKind::Sea);
    assert!(m.edges.iter().all(|e| e.land == 0));
    crate::planet::continents::classify(&mut m);
    m.validate().unwrap();
    // One edge alone saying a face is land: the face's edges disagree.
    let e = m.faces[f as usize].e[1] as usize;
    m.edges[e].land = if m.edges[e].f[0] == f { 1 } else { 2 };
    let err = m.validate().unwrap_err();
    assert!(err.contains("disagree on its kind"), "{err}");
    m.edges[e].land = 0b100;
    let err = m.validate().unwrap_err();
    assert!(err.contains("land bits 0b100"), "{err}");
}

#[test]
fn validation_finds_split_levels_out_of_order_pieces_and_twin_edges() {
    let m = sphere(200);
    m.validate().unwrap();
    // The refinement edge of a higher split level than the other two.
    let mut bad = m.clone();
    let [e0, e1, _] = bad.faces[0].e;
    bad.edges[e0 as usize].level = bad.edges[e1 as usize].level + 1;
    assert!(bad.validate().unwrap_err().contains("split levels"));
    // Two spheres side by side: every count is right but the mesh is in two pieces.
    let mut two = m.clone();
    let (nv, ne, nf) = (m.vertices.len() as u32, m.edges.len() as u32, m.faces.len() as u32);
    two.vertices.extend(m.vertices.iter().map(|v| Vertex { edge: v.edge + ne, ..*v }));
    two.edges.extend(m.edges.iter().map(|e| Edge { v: e.v.map(|v| v + nv), f: e.f.map(|f| f + nf), ..*e }));
    two.faces.extend(m.faces.iter().map(|f| Face { e: f.e.map(|e| e + ne) }));
    assert!(two.validate().unwrap_err().contains("Euler characteristic is 4"));
    // (The Euler count alone would pass a sphere beside a torus: the walk finds the pieces.)
    let err = two.check_vertex_fans().unwrap_err();
    assert!(err.contains("in pieces"), "{err}");
    // Two edges joining the same vertices (the faces would disagree first in a whole mesh).
    let mut twice = m.clone();
    let [a, b] = twice.edges[0].v;
    twice.edges[1].v = [b, a];
    let err = twice.check_edges_distinct().unwrap_err();
    assert!(err.contains("edges 0 and 1 both join"), "{err}");
    m.check_edges_distinct().unwrap();
    // An empty mesh is refused, not a panic.
    assert!(Mesh::default().validate().unwrap_err().contains("Euler"));
}

/// `edge_between` finds every edge from either end, and nothing between vertices that share
/// none: on a base mesh and after splits (which rewrite edge links and face links).
#[test]
fn edge_between_finds_every_edge_and_only_edges() {
    let mut m = sphere(800);
    let mut make = |m: &Mesh, site: &SplitSite| (midpoint_vertex(m, site), [EdgeKind::Sea; 4]);
    for e in (0..m.edges.len() as u32).step_by(37) {
        m.refine_edge(e, &mut make);
    }
    m.validate().unwrap();
    let mut adjacent = std::collections::HashSet::new();
    for (i, e) in m.edges.iter().enumerate() {
        let [a, b] = e.v;
        assert_eq!(m.edge_between(a, b), Some(i as u32), "edge {i} from {a}");
        assert_eq!(m.edge_between(b, a), Some(i as u32), "edge {i} from {b}");
        adjacent.insert((a.min(b), a.max(b)));
    }
    let n = m.vertices.len() as u32;
    let mut absent = 0;
    for a in (0..n).step_by(7) {
        for b in (0..n).step_by(11) {
            if a != b && !adjacent.contains(&(a.min(b), a.max(b))) {
                assert_eq!(m.edge_between(a, b), None, "{a} and {b} share no edge");
                absent += 1;
            }
        }
    }
    assert!(absent > 1000);
}
