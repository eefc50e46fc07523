// Vertex collapses (paper §5.4, Algorithm 3): the twin of `Buffers::collapse` in
// `src/mesh/batch.rs`, one invocation per vertex marked `MARK_COLLAPSE` by the state update
// (`collapse_candidates` in `state.wgsl`). Race-free as the paper argues: a candidate owns
// its vertex, four edges and four faces, disjoint from every other candidate's; what neighbours
// share is an outer edge, of which each collapse relinks only its own face's slot, and a corner
// vertex, whose edge link only the owner of the linked edge moves. The restored faces' newest
// vertices get `MARK_LOOK`: only they can have become collapsible. Split wishes are brought up
// to date as by `update_after_collapses` (`src/adapt/cpu/state.rs`): the removed edges want nothing
// and the restored edge is decided by the criterion of `view.wgsl` (appended). Layouts:
// `layout.wgsl` (prepended).

@group(0) @binding(0) var<storage, read_write> vertices: array<Vertex>;
@group(0) @binding(1) var<storage, read_write> edges: array<Edge>;
@group(0) @binding(2) var<storage, read_write> faces: array<Face>;
@group(0) @binding(3) var<storage, read_write> marks: array<atomic<u32>>;
@group(0) @binding(4) var<uniform> sweep: Sweep;
@group(0) @binding(5) var<storage, read> view: View;
@group(0) @binding(6) var<storage, read_write> wants: array<u32>;

// In edge `e`, replaces face `old` by `new_face` (the other slot may be a neighbour's).
fn relink(e: u32, old: u32, new_face: u32) {
    if edges[e].f[0] == old {
        edges[e].f[0] = new_face;
    } else {
        edges[e].f[1] = new_face;
    }
}

// Moves vertex `v`'s edge link from `gone` to `keep` if it points to `gone`.
fn move_link(v: u32, gone: u32, keep: u32) {
    if vertices[v].edge == gone {
        vertices[v].edge = keep;
    }
}

@compute @workgroup_size(256)
fn collapse_vertices(@builtin(global_invocation_id) id: vec3<u32>) {
    let m = id.x + id.y * sweep.row;
    if m >= sweep.vertices || (atomicLoad(&marks[m]) & MARK_COLLAPSE) == 0u {
        return;
    }
    // The site (`Mesh::collapse_site`, checked by the state update), read before any write.
    let e1 = vertices[m].edge;
    let edge1 = edges[e1];
    let f1 = edge1.f[0];
    let f2 = edge1.f[1];
    let x1 = faces[f1];
    let x2 = faces[f2];
    let e2 = x1.e[2];
    let f3 = edges[e2].f[1];
    let x3 = faces[f3];
    let e4 = x2.e[1];
    let f4 = edges[e4].f[0];
    let x4 = faces[f4];
    let e3 = x3.e[2];
    let a = edge1.v[0];
    let b = far_end(e3, m);
    let t = far_end(e2, m);
    let d = far_end(e4, m);
    let bt = x3.e[0];
    let ta = x1.e[0];
    let ad = x2.e[0];
    let db = x4.e[0];

    faces[f1] = Face(array<u32, 3>(e1, bt, ta));
    faces[f2] = Face(array<u32, 3>(e1, ad, db));
    relink(bt, f3, f1);
    relink(db, f4, f2);
    let k1 = edge_kind(edge1);
    let k3 = edge_kind(edges[e3]);
    var kind = k3;
    if k1 == k3 || k3 == KIND_RIVER {
        kind = k1;
    }
    let bits = (edge_level(edge1) - 1u) | (kind << 16u) | (edge1.bits & 0xff000000u);
    edges[e1] = Edge(array<u32, 2>(a, b), edge1.f, vertices[m].parent_lod, bits);
    move_link(b, e3, e1);
    move_link(t, e2, ta);
    move_link(d, e4, ad);
    vertices[m].edge = DEAD;
    edges[e2].v = array<u32, 2>(DEAD, DEAD);
    edges[e3].v = array<u32, 2>(DEAD, DEAD);
    edges[e4].v = array<u32, 2>(DEAD, DEAD);
    faces[f3].e = array<u32, 3>(DEAD, DEAD, DEAD);
    faces[f4].e = array<u32, 3>(DEAD, DEAD, DEAD);
    let centre = (position(a) + position(b)) * f64(0.5);
    let lod = vertices[m].parent_lod;
    wants[e1] = select(0u, 1u, wants_split(f64(lod_len(lod)), centre, f64(lod_radius(lod)), kind == KIND_SEA));
    wants[e2] = 0u;
    wants[e3] = 0u;
    wants[e4] = 0u;
    atomicOr(&marks[t], MARK_LOOK);
    atomicOr(&marks[d], MARK_LOOK);
}
