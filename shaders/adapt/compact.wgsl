// Buffer compaction (paper §5.5): the twin of `Mesh::compact` in `src/mesh/order.rs`. For each
// of the vertex, edge and face buffers, the live entities are flagged (`live_*`), numbered in
// their old order by the block prefix sum of `scan.wgsl` (appended), the number written
// over the flag (`number`; dead ones get `DEAD`), and every live entity moved to its number in
// fresh buffers with its references renumbered (`move_*`). Layouts: `layout.wgsl`.

@group(0) @binding(0) var<storage, read> old_vertices: array<Vertex>;
@group(0) @binding(1) var<storage, read> old_edges: array<Edge>;
@group(0) @binding(2) var<storage, read> old_faces: array<Face>;
@group(0) @binding(3) var<storage, read_write> new_vertices: array<Vertex>;
@group(0) @binding(4) var<storage, read_write> new_edges: array<Edge>;
@group(0) @binding(5) var<storage, read_write> new_faces: array<Face>;
@group(0) @binding(6) var<storage, read> vmap: array<u32>;
@group(0) @binding(7) var<storage, read> emap: array<u32>;
@group(0) @binding(8) var<storage, read> fmap: array<u32>;
// The map being numbered: live flags in, new ids out.
@group(0) @binding(9) var<storage, read_write> map: array<u32>;
@group(0) @binding(10) var<storage, read_write> sums: array<u32>;
@group(0) @binding(11) var<uniform> grid: Grid;

fn scan_flag(i: u32) -> u32 {
    return map[i];
}

// The live counts are known on the host (collapses remove a vertex, three edges and two faces).
fn scan_total(total: u32) {}

fn item(id: vec3<u32>) -> u32 {
    return id.x + id.y * grid.row;
}

@compute @workgroup_size(256)
fn live_vertices(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = item(id);
    if i < grid.items {
        map[i] = select(0u, 1u, old_vertices[i].edge != DEAD);
    }
}

@compute @workgroup_size(256)
fn live_edges(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = item(id);
    if i < grid.items {
        map[i] = select(0u, 1u, old_edges[i].v[0] != DEAD);
    }
}

@compute @workgroup_size(256)
fn live_faces(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = item(id);
    if i < grid.items {
        map[i] = select(0u, 1u, old_faces[i].e[0] != DEAD);
    }
}

// New id of each live item (its rank among the live ones), `DEAD` for the others. Each
// invocation reads its own items' flags before writing their ids.
@compute @workgroup_size(256)
fn number(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
    let s = share(wg, lid);
    if !s.valid {
        return;
    }
    var at = s.at;
    for (var k = 0u; k < PER_THREAD; k++) {
        let i = s.base + k;
        if i < grid.items {
            if map[i] != 0u {
                map[i] = at;
                at += 1u;
            } else {
                map[i] = DEAD;
            }
        }
    }
}

fn new_vertex(v: u32) -> u32 {
    if v == NONE {
        return NONE;
    }
    return vmap[v];
}

fn new_edge(e: u32) -> u32 {
    if e == NONE {
        return NONE;
    }
    return emap[e];
}

fn new_face(f: u32) -> u32 {
    if f == NONE {
        return NONE;
    }
    return fmap[f];
}

@compute @workgroup_size(256)
fn move_vertices(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = item(id);
    if i >= grid.items || vmap[i] == DEAD {
        return;
    }
    var x = old_vertices[i];
    x.edge = new_edge(x.edge);
    new_vertices[vmap[i]] = x;
}

@compute @workgroup_size(256)
fn move_edges(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = item(id);
    if i >= grid.items || emap[i] == DEAD {
        return;
    }
    var x = old_edges[i];
    x.v = array<u32, 2>(new_vertex(x.v[0]), new_vertex(x.v[1]));
    x.f = array<u32, 2>(new_face(x.f[0]), new_face(x.f[1]));
    new_edges[emap[i]] = x;
}

@compute @workgroup_size(256)
fn move_faces(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = item(id);
    if i >= grid.items || fmap[i] == DEAD {
        return;
    }
    var x = old_faces[i];
    x.e = array<u32, 3>(new_edge(x.e[0]), new_edge(x.e[1]), new_edge(x.e[2]));
    new_faces[fmap[i]] = x;
}
