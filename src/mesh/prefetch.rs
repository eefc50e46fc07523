//! Cache hints for the adaption's scattered reads (paper §5: every stage gathers entities by
//! index). The loops that chase indices (an edge, then its faces, then their corners) wait on
//! memory, not arithmetic; asking for the lines of later iterations ahead of time overlaps
//! those waits.

use super::Vertex;

/// Asks for the cache line holding `p` (a hint: nothing happens where the target has none).
#[inline(always)]
pub fn prefetch<T>(p: *const T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch reads nothing into the program and never faults, whatever the address.
    unsafe {
        std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(p as *const i8)
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = p;
}

/// Asks for both cache lines a vertex may straddle (56 bytes, 8-byte aligned).
#[inline(always)]
pub fn prefetch_vertex(p: *const Vertex) {
    prefetch(p);
    prefetch((p as *const u8).wrapping_add(std::mem::size_of::<Vertex>() - 1));
}
