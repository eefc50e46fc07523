// Edge helpers of the stages that bind the `edges` buffer (split, state, collapse), added to
// their sources (`EDGE_HELPERS` in `src/adapt/gpu/mod.rs`).

// The end of edge `e` that is not `v`.
fn far_end(e: u32, v: u32) -> u32 {
    let first = edges[e].v[0];
    return select(first, edges[e].v[1], first == v);
}
