// Split-list compaction (paper §5.3, Algorithm 2 steps 1-2): the twin of `Selection::select` in
// `src/adapt/split.rs` (which follows all chains a step per round instead of one thread per
// chain). Every wanted edge follows its chain of blocking refinement edges to the edge that is
// ready (the refinement edge of both its faces); a chain stops where it meets an edge another
// chain already took (one atomic flag per edge), so shared parts are walked once.
// The ready edges are then compacted into a list in edge order by a prefix sum over blocks of
// `BLOCK` edges, so the list, and the slots the splits take, are the CPU's whatever the
// scheduling. Layouts: `layout.wgsl` (prepended); the prefix sum and its `Grid` (the
// `ScanGrid` of `src/adapt/gpu/layout.rs`): `scan.wgsl` (appended).

@group(0) @binding(0) var<storage, read> edges: array<Edge>;
@group(0) @binding(1) var<storage, read> faces: array<Face>;
@group(0) @binding(2) var<storage, read> wants: array<u32>;
@group(0) @binding(3) var<storage, read_write> seen: array<atomic<u32>>;
@group(0) @binding(4) var<storage, read_write> ready: array<u32>;
@group(0) @binding(5) var<storage, read_write> sums: array<u32>;
@group(0) @binding(6) var<storage, read_write> list: array<u32>;
// [ready edges, wanted edges, collapse candidates, unused]
@group(0) @binding(7) var<storage, read_write> counts: array<atomic<u32>, 4>;
@group(0) @binding(8) var<uniform> grid: Grid;

// Longer than any chain: a chain's levels fall by one per step.
const MAX_CHAIN: u32 = 65536u;

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
    if e >= grid.items || wants[e] == 0u {
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

fn scan_flag(e: u32) -> u32 {
    return ready[e];
}

fn scan_total(total: u32) {
    atomicStore(&counts[0], total);
}

// Writes each ready edge at its offset: the list in edge order.
@compute @workgroup_size(256)
fn scatter(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
    let s = share(wg, lid);
    if !s.valid {
        return;
    }
    var at = s.at;
    for (var k = 0u; k < PER_THREAD; k++) {
        if flag_at(s.base, k) != 0u {
            list[at] = s.base + k;
            at += 1u;
        }
    }
}
