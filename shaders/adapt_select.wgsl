// Split-list compaction (paper §5.3, Algorithm 2 steps 1-2): the twin of `wanted_chains` in
// `src/adapt/split.rs`. Every wanted edge follows its chain of blocking refinement edges to the
// edge that is ready (the refinement edge of both its faces); a chain stops where it meets an
// edge another chain already took (one atomic flag per edge), so shared parts are walked once.
// The ready edges are then compacted into a list in edge order by a prefix sum over blocks of
// `BLOCK` edges, so the list, and the slots the splits take, are the CPU's whatever the
// scheduling. Layouts: `adapt_mesh.wgsl` (prepended) and `Grid` of `src/adapt/gpu/select.rs`.

struct Grid {
    // Edges in the mesh.
    edges: u32,
    // Invocations per row of the edge-wise dispatch (edge = x + y * row).
    row: u32,
    // Blocks of `BLOCK` edges, and workgroups per row of the block-wise dispatch.
    blocks: u32,
    block_row: u32,
}

@group(0) @binding(0) var<storage, read> edges: array<Edge>;
@group(0) @binding(1) var<storage, read> faces: array<Face>;
@group(0) @binding(2) var<storage, read> wants: array<u32>;
@group(0) @binding(3) var<storage, read_write> seen: array<atomic<u32>>;
@group(0) @binding(4) var<storage, read_write> ready: array<u32>;
@group(0) @binding(5) var<storage, read_write> sums: array<u32>;
@group(0) @binding(6) var<storage, read_write> list: array<u32>;
// [ready edges, wanted edges]
@group(0) @binding(7) var<storage, read_write> counts: array<atomic<u32>, 2>;
@group(0) @binding(8) var<uniform> grid: Grid;

const GROUP: u32 = 256u;
const PER_THREAD: u32 = 4u;
const BLOCK: u32 = 1024u;
// Longer than any chain: a chain's levels fall by one per step.
const MAX_CHAIN: u32 = 65536u;

var<workgroup> part: array<u32, 256>;

// `Mesh::blocking_edge`: the refinement edge that must be split before `e`; `e` when ready.
fn blocking_edge(e: u32) -> u32 {
    let edge = edges[e];
    for (var k = 0u; k < 2u; k++) {
        let r = faces[edge.f[k]].e[0];
        if r != e {
            return r;
        }
    }
    return e;
}

@compute @workgroup_size(256)
fn walk_chains(@builtin(global_invocation_id) id: vec3<u32>) {
    let e = id.x + id.y * grid.row;
    if e >= grid.edges || wants[e] == 0u {
        return;
    }
    atomicAdd(&counts[1], 1u);
    var x = e;
    for (var n = 0u; n < MAX_CHAIN; n++) {
        if atomicExchange(&seen[x], 1u) != 0u {
            break;
        }
        let b = blocking_edge(x);
        if b == x {
            ready[x] = 1u;
            break;
        }
        x = b;
    }
}

// Inclusive prefix sum of `part` across the workgroup (Hillis-Steele).
fn scan_part(lid: u32) {
    for (var d = 1u; d < GROUP; d <<= 1u) {
        workgroupBarrier();
        var add = 0u;
        if lid >= d {
            add = part[lid - d];
        }
        workgroupBarrier();
        part[lid] += add;
    }
    workgroupBarrier();
}

fn ready_in(base: u32, k: u32) -> u32 {
    let e = base + k;
    if e < grid.edges {
        return ready[e];
    }
    return 0u;
}

// The ready edges this invocation covers in its block, with their inclusive prefix sum over
// the workgroup left in `part`.
fn count_block(base: u32, lid: u32) -> u32 {
    var c = 0u;
    for (var k = 0u; k < PER_THREAD; k++) {
        c += ready_in(base, k);
    }
    part[lid] = c;
    scan_part(lid);
    return c;
}

// Ready edges per block.
@compute @workgroup_size(256)
fn block_sums(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
    let block = wg.x + wg.y * grid.block_row;
    count_block(block * BLOCK + lid * PER_THREAD, lid);
    if lid == GROUP - 1u && block < grid.blocks {
        sums[block] = part[lid];
    }
}

// Exclusive prefix sum of the block sums, in one workgroup; the total is the split count.
@compute @workgroup_size(256)
fn scan_sums(@builtin(local_invocation_index) lid: u32) {
    var carry = 0u;
    let chunks = (grid.blocks + GROUP - 1u) / GROUP;
    for (var chunk = 0u; chunk < chunks; chunk++) {
        let i = chunk * GROUP + lid;
        var v = 0u;
        if i < grid.blocks {
            v = sums[i];
        }
        part[lid] = v;
        scan_part(lid);
        if i < grid.blocks {
            sums[i] = carry + part[lid] - v;
        }
        carry += part[GROUP - 1u];
        // Everyone has read the total before the next chunk overwrites it.
        workgroupBarrier();
    }
    if lid == 0u {
        atomicStore(&counts[0], carry);
    }
}

// Writes each ready edge at its offset: the list in edge order.
@compute @workgroup_size(256)
fn scatter(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
    let block = wg.x + wg.y * grid.block_row;
    let base = block * BLOCK + lid * PER_THREAD;
    let c = count_block(base, lid);
    if block >= grid.blocks {
        return;
    }
    var at = sums[block] + part[lid] - c;
    for (var k = 0u; k < PER_THREAD; k++) {
        if ready_in(base, k) != 0u {
            list[at] = base + k;
            at += 1u;
        }
    }
}
