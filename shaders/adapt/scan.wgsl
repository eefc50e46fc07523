// Block prefix sum (paper §5.3 and §5.5 compact buffers with it): the items `0..grid.items`
// carry a 0/1 flag (`scan_flag`, defined by the stage), the flags of each block of `BLOCK` items
// are summed (`block_sums`), and the block sums turned into exclusive offsets in one workgroup
// (`scan_sums`, which hands the total to the stage's `scan_total`). A stage's own scatter then
// calls `count_block` again to find each item's offset within its block, so whatever the
// scheduling the flagged items keep their order. Appended to the stages that compact: each
// declares `grid` and `sums`.

const GROUP: u32 = 256u;
const PER_THREAD: u32 = 4u;
const BLOCK: u32 = 1024u;

var<workgroup> part: array<u32, 256>;

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

fn flag_at(base: u32, k: u32) -> u32 {
    let i = base + k;
    if i < grid.items {
        return scan_flag(i);
    }
    return 0u;
}

// The flagged items this invocation covers in its block (`PER_THREAD` from `base`), with their
// inclusive prefix sum over the workgroup left in `part`.
fn count_block(base: u32, lid: u32) -> u32 {
    var c = 0u;
    for (var k = 0u; k < PER_THREAD; k++) {
        c += flag_at(base, k);
    }
    part[lid] = c;
    scan_part(lid);
    return c;
}

// Flagged items per block.
@compute @workgroup_size(256)
fn block_sums(@builtin(workgroup_id) wg: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
    let block = wg.x + wg.y * grid.block_row;
    count_block(block * BLOCK + lid * PER_THREAD, lid);
    if lid == GROUP - 1u && block < grid.blocks {
        sums[block] = part[lid];
    }
}

// Exclusive prefix sum of the block sums, in one workgroup; the total goes to `scan_total`.
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
        scan_total(carry);
    }
}

// The items one invocation of a block-wise scatter covers: the first (`base`), the offset of
// the first flagged one among all flagged items (its block's offset plus those before it in the
// block), and whether the block exists. Called in uniform control flow (it synchronises).
struct Share {
    base: u32,
    at: u32,
    valid: bool,
}

fn share(wg: vec3<u32>, lid: u32) -> Share {
    let block = wg.x + wg.y * grid.block_row;
    let base = block * BLOCK + lid * PER_THREAD;
    let c = count_block(base, lid);
    if block >= grid.blocks {
        return Share(base, 0u, false);
    }
    return Share(base, sums[block] + part[lid] - c, true);
}
