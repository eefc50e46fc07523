//! Buffer compaction (paper §5.5): dead entities are squeezed out and the live ones renumbered
//! in spatial order, so that neighbours in the mesh are neighbours in memory.
//!
//! Splits append their entities where the buffers end, so after a refinement the corners of a
//! face lie far apart in memory and every pass over the mesh waits on memory. Compaction sorts
//! the vertices along a Morton curve of their direction from the planet's centre (ties by
//! position), the edges by their ends' new indices and the faces by their corners', which makes
//! the order a function of the mesh alone: two paths to the same mesh compact to equal buffers.

use super::DEAD;
use super::{Mesh, NONE};
use rayon::prelude::*;

/// Morton code (21 bits per axis) of the direction of `p` from the planet's centre.
fn morton(p: [f64; 3]) -> u64 {
    let len = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt().max(f64::MIN_POSITIVE);
    let q = |x: f64| (((x / len) * 0.5 + 0.5).clamp(0.0, 1.0) * ((1u64 << 21) - 1) as f64) as u64;
    spread(q(p[0])) | spread(q(p[1])) << 1 | spread(q(p[2])) << 2
}

/// Moves bit `i` of the low 21 bits of `x` to bit `3 i`.
fn spread(x: u64) -> u64 {
    let mut x = x & 0x1f_ffff;
    x = (x | x << 32) & 0x001f_0000_0000_ffff;
    x = (x | x << 16) & 0x001f_0000_ff00_00ff;
    x = (x | x << 8) & 0x100f_00f0_0f00_f00f;
    x = (x | x << 4) & 0x10c3_0c30_c30c_30c3;
    x = (x | x << 2) & 0x1249_2492_4924_9249;
    x
}

/// Old ids `0..n` of the items with a key `(bucket, rank)`, in increasing key order (no two
/// items share a key). Buckets are below `buckets` and hold a few items each (an edge's or a
/// face's lowest new vertex id), so this is a counting sort by bucket and then a sort of each
/// bucket by rank, far cheaper than sorting millions of keys by comparison.
fn sorted_order(n: usize, buckets: usize, key: impl Fn(u32) -> Option<(u32, u64)> + Sync) -> Vec<u32> {
    const NO_BUCKET: u32 = u32::MAX;
    let keys: Vec<(u32, u64)> = (0..n as u32).into_par_iter().map(|x| key(x).unwrap_or((NO_BUCKET, 0))).collect();
    let mut start = vec![0u32; buckets + 1];
    for &(b, _) in &keys {
        if b != NO_BUCKET {
            start[b as usize + 1] += 1;
        }
    }
    for b in 0..buckets {
        start[b + 1] += start[b];
    }
    let mut order = vec![0u32; start[buckets] as usize];
    let mut fill = start[..buckets].to_vec();
    for (i, &(b, _)) in keys.iter().enumerate() {
        if b != NO_BUCKET {
            order[fill[b as usize] as usize] = i as u32;
            fill[b as usize] += 1;
        }
    }
    for b in 0..buckets {
        let bucket = &mut order[start[b] as usize..start[b + 1] as usize];
        if bucket.len() > 1 {
            // (Ties, which only a mesh with a doubled edge or face has, go by old id.)
            bucket.sort_unstable_by_key(|&i| (keys[i as usize].1, i));
        }
    }
    order
}

/// New id of each old id in `order` (dead ids map to [`DEAD`]).
fn inverse(order: &[u32], len: usize) -> Vec<u32> {
    let mut map = vec![DEAD; len];
    for (new, &old) in order.iter().enumerate() {
        map[old as usize] = new as u32;
    }
    map
}

/// The live items moved to their new ids (`map`, [`DEAD`] for dead ones; a bijection onto
/// `0..len`), each changed by `update`, in a buffer with room for `room` more. Reads the old
/// buffer in order and writes in parallel.
fn scatter<T: Copy + Send + Sync>(
    items: &[T],
    map: &[u32],
    len: usize,
    room: usize,
    update: impl Fn(&mut T) + Sync,
) -> Vec<T> {
    struct Out<T>(*mut T);
    // SAFETY: the threads write disjoint slots (the map is injective on live items).
    unsafe impl<T> Sync for Out<T> {}
    impl<T> Out<T> {
        /// SAFETY: `i` is within the capacity and written by no other thread.
        unsafe fn write(&self, i: usize, x: T) {
            self.0.add(i).write(x)
        }
    }
    let mut out: Vec<T> = Vec::with_capacity(len + room);
    let dst = &Out(out.as_mut_ptr());
    items.par_iter().zip(map.par_iter()).with_min_len(4096).for_each(|(x, &new)| {
        if new != DEAD {
            let mut x = *x;
            update(&mut x);
            assert!((new as usize) < len, "renumbered past the end");
            // SAFETY: `new < len` is within the capacity and no other item maps to it.
            unsafe { dst.write(new as usize, x) };
        }
    });
    // SAFETY: the map is onto `0..len`, so every slot was written.
    unsafe { out.set_len(len) };
    out
}

/// Moves the live items of `items` (`map` gives [`DEAD`] for the others, and for each live one
/// the number of live ones before it) to the front, each changed by `update`, and drops the
/// rest: `len` remain. Chunks squeeze their own items to their starts in parallel, then the
/// squeezed blocks move down into place one after another (each lands below the next one's
/// start, so none overwrites what is still to move).
fn squeeze<T: Copy + Send + Sync>(items: &mut Vec<T>, map: &[u32], len: usize, update: impl Fn(&mut T) + Sync) {
    const CHUNK: usize = 1 << 16;
    let kept: Vec<usize> = items
        .par_chunks_mut(CHUNK)
        .zip(map.par_chunks(CHUNK))
        .map(|(chunk, map)| {
            let mut k = 0;
            for i in 0..chunk.len() {
                if map[i] != DEAD {
                    let mut x = chunk[i];
                    update(&mut x);
                    chunk[k] = x;
                    k += 1;
                }
            }
            k
        })
        .collect();
    let mut at = 0;
    for (c, k) in kept.into_iter().enumerate() {
        items.copy_within(c * CHUNK..c * CHUNK + k, at);
        at += k;
    }
    assert_eq!(at, len, "the map's live count");
    items.truncate(len);
}

/// New ids of the vertices, edges and faces of a mesh: `vertices[old]` is the new id of vertex
/// `old`, or the dead marker (`u32::MAX - 1`) for a removed one (likewise edges and faces);
/// each map is a bijection from the kept ids onto `0..n`, with the kept counts `sizes`.
#[derive(Clone, Debug, PartialEq)]
pub struct Renumbering {
    pub vertices: Vec<u32>,
    pub edges: Vec<u32>,
    pub faces: Vec<u32>,
    pub sizes: (usize, usize, usize),
}

/// `map[x]`, keeping the absent marker.
#[inline]
fn renumbered(map: &[u32], x: u32) -> u32 {
    if x == NONE {
        NONE
    } else {
        map[x as usize]
    }
}

/// New ids keeping the order of the live items (`dead` ones map to [`DEAD`]), and their count.
fn kept_order<T: Sync>(items: &[T], dead: impl Fn(&T) -> bool + Sync) -> (Vec<u32>, usize) {
    let mut map: Vec<u32> = items.par_iter().map(|x| if dead(x) { DEAD } else { 0 }).collect();
    let mut next = 0u32;
    for m in map.iter_mut().filter(|m| **m != DEAD) {
        *m = next;
        next += 1;
    }
    (map, next as usize)
}

impl Mesh {
    /// Removes dead vertices, edges and faces, keeping the order of the live ones and updating
    /// every reference.
    pub fn compact(&mut self) {
        let (vmap, nv) = kept_order(&self.vertices, |v| v.edge == DEAD);
        let (emap, ne) = kept_order(&self.edges, |e| e.v[0] == DEAD);
        let (fmap, nf) = kept_order(&self.faces, |f| f.e[0] == DEAD);
        if (nv, ne, nf) == (self.vertices.len(), self.edges.len(), self.faces.len()) {
            return;
        }
        // The order is kept, so every live item moves down (or stays): squeezed in place,
        // without fresh buffers whose first touches would each fault (that cost more than the
        // moves themselves when a frame's collapses left holes all over a large mesh).
        let (vmap, emap, fmap) = (&vmap[..], &emap[..], &fmap[..]);
        squeeze(&mut self.vertices, vmap, nv, |x| x.edge = renumbered(emap, x.edge));
        squeeze(&mut self.edges, emap, ne, |x| {
            x.v = x.v.map(|v| renumbered(vmap, v));
            x.f = x.f.map(|f| renumbered(fmap, f));
        });
        squeeze(&mut self.faces, fmap, nf, |x| x.e = x.e.map(|e| renumbered(emap, e)));
    }

    /// Removes dead vertices, edges and faces and renumbers the live ones in spatial order
    /// (module doc), updating every reference. Returns the renumbering, for copies of the mesh
    /// kept elsewhere to follow.
    pub fn compact_in_spatial_order(&mut self) -> Renumbering {
        self.compact_in_spatial_order_with_room((0, 0, 0))
    }

    /// [`Mesh::compact_in_spatial_order`], leaving room for `room` more vertices, edges and
    /// faces in the new buffers (so that making room later does not copy them again).
    pub fn compact_in_spatial_order_with_room(&mut self, room: (usize, usize, usize)) -> Renumbering {
        let order = self.spatial_order();
        self.renumber(&order, room);
        order
    }

    /// The renumbering that removes dead entities and puts the live ones in spatial order.
    pub fn spatial_order(&self) -> Renumbering {
        let mut vorder: Vec<(u64, u32)> = (0..self.vertices.len() as u32)
            .into_par_iter()
            .filter(|&v| self.vertices[v as usize].edge != DEAD)
            .map(|v| (morton(self.vertices[v as usize].pos), v))
            .collect();
        let pos = |v: u32| self.vertices[v as usize].pos;
        vorder.par_sort_unstable_by(|x, y| {
            x.0.cmp(&y.0).then_with(|| {
                let (p, q) = (pos(x.1), pos(y.1));
                p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1])).then(p[2].total_cmp(&q[2]))
            })
        });
        let vorder: Vec<u32> = vorder.into_iter().map(|(_, v)| v).collect();
        let vmap = inverse(&vorder, self.vertices.len());
        let nv = vorder.len();
        let eorder = sorted_order(self.edges.len(), nv, |e| {
            let e = &self.edges[e as usize];
            let [a, b] = (e.v[0] != DEAD).then(|| e.v.map(|x| vmap[x as usize]))?;
            Some((a.min(b), a.max(b) as u64))
        });
        let emap = inverse(&eorder, self.edges.len());
        let forder = sorted_order(self.faces.len(), nv, |f| {
            let live = self.faces[f as usize].e[0] != DEAD;
            let mut c = live.then(|| self.corners(f).map(|x| vmap[x as usize]))?;
            c.sort_unstable();
            Some((c[0], (c[1] as u64) << 32 | c[2] as u64))
        });
        let fmap = inverse(&forder, self.faces.len());
        Renumbering { vertices: vmap, edges: emap, faces: fmap, sizes: (vorder.len(), eorder.len(), forder.len()) }
    }

    /// Moves every live entity to its new id in `order` (a bijection onto `0..sizes` of the
    /// live entities, as [`Mesh::spatial_order`] makes) and renumbers its references.
    fn renumber(&mut self, order: &Renumbering, room: (usize, usize, usize)) {
        let (nv, ne, nf) = order.sizes;
        let (vmap, emap, fmap) = (&order.vertices[..], &order.edges[..], &order.faces[..]);
        self.vertices = scatter(&self.vertices, vmap, nv, room.0, |x| x.edge = renumbered(emap, x.edge));
        self.edges = scatter(&self.edges, emap, ne, room.1, |x| {
            x.v = x.v.map(|v| renumbered(vmap, v));
            x.f = x.f.map(|f| renumbered(fmap, f));
        });
        self.faces = scatter(&self.faces, fmap, nf, room.2, |x| x.e = x.e.map(|e| renumbered(emap, e)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spread_moves_each_bit_three_apart() {
        for x in [0u64, 1, 2, 0x15_5555, 0x1f_ffff, 0x12_3456, 0xff_ffff] {
            let slow = (0..21).fold(0u64, |acc, i| acc | ((x >> i) & 1) << (3 * i));
            assert_eq!(spread(x), slow, "{x:#x}");
        }
    }

    /// Squeezing in place gives what moving to fresh buffers gives, across chunk boundaries,
    /// with no holes, only holes, and holes at either end.
    #[test]
    fn squeezing_in_place_matches_scattering() {
        let n = 3 * (1 << 16) + 123;
        let patterns: [&dyn Fn(usize) -> bool; 5] =
            [&|_| true, &|_| false, &|i| i % 7 != 3 && !(70_000..140_000).contains(&i), &|i| i >= 1000, &|i| {
                i < n - 5 && i % 2 == 0
            }];
        for live in patterns {
            let items: Vec<u64> = (0..n as u64).map(|i| i * 3).collect();
            let mut map = vec![DEAD; n];
            let mut len = 0;
            for (i, m) in map.iter_mut().enumerate() {
                if live(i) {
                    *m = len;
                    len += 1;
                }
            }
            let expected = scatter(&items, &map, len as usize, 0, |x| *x += 1);
            let mut squeezed = items.clone();
            squeeze(&mut squeezed, &map, len as usize, |x| *x += 1);
            assert_eq!(squeezed, expected);
        }
    }

    #[test]
    fn nearby_directions_get_nearby_codes() {
        let a = morton([6.4e6, 1.0, 2.0]);
        let b = morton([6.4e6, 3.0, 2.0]);
        let far = morton([-6.4e6, 1.0, 2.0]);
        assert!(a.abs_diff(b) < a.abs_diff(far));
        assert_eq!(morton([1.0, 2.0, 3.0]), morton([2.0, 4.0, 6.0]));
    }
}
