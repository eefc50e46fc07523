// State update (paper §5.1, Algorithm 1): the split wish of every edge for one view, the twin
// of `edge_wants` in `src/adapt/cpu/state.rs`, by the criterion of `view.wgsl` (appended):
// positions are the mesh's own f64 planet-centred metres, so the eye-relative vector, and with
// it the decision, are those of the CPU. Layouts: `layout.wgsl` (prepended).

@group(0) @binding(0) var<storage, read> vertices: array<Vertex>;
@group(0) @binding(1) var<storage, read> edges: array<Edge>;
@group(0) @binding(2) var<storage, read> view: View;
@group(0) @binding(3) var<storage, read_write> wants: array<u32>;

@compute @workgroup_size(256)
fn edge_wants(@builtin(global_invocation_id) id: vec3<u32>) {
    let e = id.x + id.y * view.row;
    if e >= view.edges {
        return;
    }
    let edge = edges[e];
    if edge.v[0] == DEAD {
        wants[e] = 0u;
        return;
    }
    let centre = (position(edge.v[0]) + position(edge.v[1])) * f64(0.5);
    let sea = edge_kind(edge) == KIND_SEA;
    wants[e] = select(0u, 1u, wants_split(f64(lod_len(edge.lod)), centre, f64(lod_radius(edge.lod)), sea));
}

// Collapse candidates (Algorithm 1's collapse flags; the twin of `collapse_candidates` in
// `src/adapt/cpu/state.rs`): a vertex made by a split whose four faces are still its split's
// (`Mesh::collapse_site`), none of whose faces' edges is demanded (wanted, or on a wanted edge's
// blocking chain: the chain flags the split-list compaction leaves in `seen`), and whose parent
// edge no longer wants a split. Each invocation rewrites its own vertex's mark: `MARK_COLLAPSE`
// when it is a candidate, and the `MARK_LOOK` of the last collapses (`collapse_vertices`) is
// consumed.

@group(0) @binding(4) var<storage, read> faces: array<Face>;
@group(0) @binding(5) var<storage, read> demanded: array<u32>;
@group(0) @binding(6) var<storage, read_write> marks: array<u32>;
// [ready edges, wanted edges, candidates, candidates of a full look]
@group(0) @binding(7) var<storage, read_write> counts: array<atomic<u32>, 4>;
@group(0) @binding(8) var<uniform> sweep: Sweep;

fn quiet(x: Face) -> bool {
    return demanded[x.e[0]] == 0u && demanded[x.e[1]] == 0u && demanded[x.e[2]] == 0u;
}

// `Mesh::collapse_site`: the four faces still those of m's split, each holding its edges to m
// in the slots that make m its newest corner.
fn collapsible(m: u32) -> bool {
    let vert = vertices[m];
    if (vertex_flags(vert) & FLAG_REFINED) == 0u || vert.edge >= DEAD {
        return false;
    }
    let e1 = vert.edge;
    let edge1 = edges[e1];
    if edge1.v[1] != m {
        return false;
    }
    let x1 = faces[edge1.f[0]];
    let x2 = faces[edge1.f[1]];
    if x1.e[1] != e1 || x2.e[2] != e1 {
        return false;
    }
    let e2 = x1.e[2];
    let x3 = faces[edges[e2].f[1]];
    let e4 = x2.e[1];
    let x4 = faces[edges[e4].f[0]];
    if x3.e[1] != e2 || x4.e[2] != e4 || x3.e[2] != x4.e[1] {
        return false;
    }
    let level = edge_level(edge1);
    if edge_level(edges[e2]) != level || edge_level(edges[x3.e[2]]) != level || edge_level(edges[e4]) != level {
        return false;
    }
    if !(quiet(x1) && quiet(x2) && quiet(x3) && quiet(x4)) {
        return false;
    }
    let centre = (position(edge1.v[0]) + position(far_end(x3.e[2], m))) * f64(0.5);
    let sea = edge_kind(edge1) == KIND_SEA;
    return !wants_split(f64(lod_len(vert.parent_lod)), centre, f64(lod_radius(vert.parent_lod)), sea);
}

@compute @workgroup_size(256)
fn collapse_candidates(@builtin(global_invocation_id) id: vec3<u32>) {
    let v = id.x + id.y * sweep.row;
    if v >= sweep.vertices {
        return;
    }
    var mark = 0u;
    if (sweep.among == 0u || (marks[v] & MARK_LOOK) != 0u) && collapsible(v) {
        mark = MARK_COLLAPSE;
        atomicAdd(&counts[2], 1u);
    }
    marks[v] = mark;
}

// After a look among the apexes found nothing in a pass that split nothing: every vertex, so
// that convergence is only declared after a full look (as on the CPU).
@compute @workgroup_size(256)
fn candidates_if_none(@builtin(global_invocation_id) id: vec3<u32>) {
    let v = id.x + id.y * sweep.row;
    if v >= sweep.vertices || atomicLoad(&counts[2]) != 0u {
        return;
    }
    if collapsible(v) {
        marks[v] = MARK_COLLAPSE;
        atomicAdd(&counts[3], 1u);
    }
}
