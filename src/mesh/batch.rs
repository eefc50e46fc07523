//! Batches of splits and collapses written from many threads at once (paper §5.3 Algorithm 2,
//! §5.4 Algorithm 3).
//!
//! The paper's conflict rules make a batch race-free: a split owns its edge and its two faces, a
//! collapse its vertex, four edges and four faces, and no two operations of a batch own the same
//! entity. What neighbours can share is an outer edge, of which each operation relinks only the
//! face slot of its own face, and a corner vertex, whose edge link only the operation that owns
//! the linked edge moves. Those two writes are single-word atomic stores (and both read the word
//! atomically first); every other access touches owned entities or reads the other fields of
//! corner vertices or the end points of outer edges, which no operation of a batch changes.

use super::prefetch::{prefetch, prefetch_vertex};
use super::DEAD;
use super::{CollapseSite, Diamond, Edge, EdgeKind, Face, Lod, SplitSite, Vertex, VertexFlags, LOD_RADIUS, NONE};
use glam::DVec3;
use std::ptr::{addr_of, addr_of_mut};
use std::sync::atomic::{AtomicU32, Ordering::Relaxed};

/// Raw pointers to the three buffers, shared by the threads of one batch.
pub(super) struct Buffers {
    pub v: *mut Vertex,
    pub e: *mut Edge,
    pub f: *mut Face,
    /// Lengths of the vertex, edge and face buffers before the batch (where new slots start).
    pub sizes: (usize, usize, usize),
}

// SAFETY: the threads of a batch write disjoint entities (module doc) or single atomic words.
unsafe impl Sync for Buffers {}
unsafe impl Send for Buffers {}

impl Buffers {
    /// The edge link of vertex `v`, as an atomic word.
    unsafe fn link(&self, v: u32) -> &AtomicU32 {
        &*(addr_of_mut!((*self.v.add(v as usize)).edge) as *const AtomicU32)
    }

    /// In edge `e`, replaces face `from` by face `to` (atomically: the other slot may belong to
    /// a neighbour of the same batch).
    unsafe fn relink(&self, e: u32, from: u32, to: u32) {
        let slots = addr_of_mut!((*self.e.add(e as usize)).f) as *mut u32;
        let first = &*(slots as *const AtomicU32);
        if first.load(Relaxed) == from {
            first.store(to, Relaxed);
        } else {
            (*(slots.add(1) as *const AtomicU32)).store(to, Relaxed);
        }
    }

    /// Moves vertex `v`'s edge link from `gone` to `keep` if it points to `gone`. A plain load
    /// and store, not a compare-and-swap: only the operation that owns `gone` ever finds the
    /// link pointing to it, so no other thread of the batch writes the word while it does
    /// (and a locked instruction would stall every other memory access of the batch's loop).
    unsafe fn move_link(&self, v: u32, gone: u32, keep: u32) {
        let link = self.link(v);
        if link.load(Relaxed) == gone {
            link.store(keep, Relaxed);
        }
    }

    /// Asks for the cache lines that split `k + 16`, `k + 8`, `k + 4` and `k + 2` of `chunk`
    /// will read. Splits wait on memory, not arithmetic: each reads its edge, then the edge's
    /// faces and ends, then the outer edges those faces name, then the apexes at their far ends,
    /// all scattered over the buffers. So while split `k` runs, the edge of split `k + 16` is
    /// requested, the faces and ends of `k + 8` (whose edge has arrived by then), the outer
    /// edges of `k + 4` and the apexes of `k + 2`.
    ///
    /// # Safety
    /// `chunk` holds ready edges of a batch that this thread splits in order, and split `k` is
    /// the next: the entities read here belong to later splits of this thread, which no other
    /// thread writes, or are outer edges' end points, which no split of a batch changes.
    pub unsafe fn prefetch_split(&self, chunk: &[u32], k: usize) {
        if let Some(&e) = chunk.get(k + 16) {
            prefetch(self.e.add(e as usize));
        }
        if let Some(&e) = chunk.get(k + 8) {
            let edge = self.e.add(e as usize);
            for f in addr_of!((*edge).f).read() {
                prefetch(self.f.add(f as usize));
            }
            for v in addr_of!((*edge).v).read() {
                prefetch_vertex(self.v.add(v as usize));
            }
        }
        if let Some(&e) = chunk.get(k + 4) {
            for outer in self.outer_edges(e) {
                prefetch(self.e.add(outer as usize));
            }
        }
        if let Some(&e) = chunk.get(k + 2) {
            let b = addr_of!((*self.e.add(e as usize)).v[1]).read();
            for outer in self.outer_edges(e) {
                prefetch_vertex(self.v.add(self.far_end(outer, b) as usize));
            }
        }
    }

    /// The outer edges `bt` (of `f1`) and `db` (of `f2`) of ready edge `e`'s diamond.
    unsafe fn outer_edges(&self, e: u32) -> [u32; 2] {
        let [f1, f2] = addr_of!((*self.e.add(e as usize)).f).read();
        [addr_of!((*self.f.add(f1 as usize)).e[1]).read(), addr_of!((*self.f.add(f2 as usize)).e[2]).read()]
    }

    /// The end of edge `e` that is not `v`. End points are the one part of an outer edge that
    /// no split of a batch writes.
    unsafe fn far_end(&self, e: u32, v: u32) -> u32 {
        let ends = addr_of!((*self.e.add(e as usize)).v).read();
        if ends[0] == v {
            ends[1]
        } else {
            ends[0]
        }
    }

    /// A corner of a split: vertex `v` without its edge link, field by field (another split
    /// of the batch may be moving the link; nothing else of an existing vertex changes).
    unsafe fn corner(&self, v: u32) -> Vertex {
        let p = self.v.add(v as usize);
        Vertex {
            pos: addr_of!((*p).pos).read(),
            ground: addr_of!((*p).ground).read(),
            water: addr_of!((*p).water).read(),
            edge: NONE,
            parent_lod: addr_of!((*p).parent_lod).read(),
            seed: addr_of!((*p).seed).read(),
            tangent: addr_of!((*p).tangent).read(),
            flags: addr_of!((*p).flags).read(),
        }
    }

    /// The diamond of edge `e` (as [`Diamond::new`] of its split site).
    ///
    /// # Safety
    /// No other operation of the batch owns `e` or its faces.
    ///
    /// # Panics
    /// When `e` is not ready: the refinement edge of both its faces.
    pub unsafe fn diamond(&self, e: u32, radius: f64) -> Diamond {
        let edge = self.e.add(e as usize).read();
        let [f1, f2] = edge.f;
        let faces = [self.f.add(f1 as usize).read(), self.f.add(f2 as usize).read()];
        assert!(faces[0].e[0] == e && faces[1].e[0] == e, "edge {e} is not ready to split");
        let [a, b] = edge.v;
        let (t, d) = (self.far_end(faces[0].e[1], b), self.far_end(faces[1].e[2], b));
        let site = SplitSite { edge: e, a, b, t, d, f1, f2 };
        Diamond { site, edge, faces, corners: [site.a, site.b, site.t, site.d].map(|v| self.corner(v)), radius }
    }

    /// The `i`-th split of a batch (see [`super::Mesh::split_ids`] for its ids): the diamond's
    /// edge and faces become four and four around `vertex`. Returns the edges `[e1, e2, e3,
    /// e4]` as written, each with its midpoint (as [`super::Mesh::midpoint`] computes it).
    ///
    /// # Safety
    /// The buffers hold room for the batch's new slots, `diamond` was read from them for a
    /// ready edge, and no other operation of the batch owns that edge or its faces.
    pub unsafe fn split(
        &self,
        diamond: &Diamond,
        mut vertex: Vertex,
        kinds: [EdgeKind; 4],
        i: usize,
    ) -> [(Edge, DVec3); 4] {
        let SplitSite { edge: e1, a, b, t, d, f1, f2 } = diamond.site;
        let (nv, ne, nf) = self.sizes;
        let m = (nv + i) as u32;
        let e2 = (ne + 3 * i) as u32;
        let (e3, e4) = (e2 + 1, e2 + 2);
        let f3 = (nf + 2 * i) as u32;
        let f4 = f3 + 1;
        let [old1, old2] = diamond.faces;
        let parent = diamond.edge;
        let level = parent.level + 1;
        let [pa, pb, pt, pd] = diamond.positions();
        let pm = vertex.p();
        let parent_mid = (pa + pb) * 0.5;

        // Faces: f1 = (m, t, a), f3 = (m, b, t), f2 = (m, a, d), f4 = (m, d, b).
        self.f.add(f1 as usize).write(Face { e: [old1.e[2], e1, e2] });
        self.f.add(f2 as usize).write(Face { e: [old2.e[1], e4, e1] });
        self.f.add(f3 as usize).write(Face { e: [old1.e[1], e2, e3] });
        self.f.add(f4 as usize).write(Face { e: [old2.e[2], e3, e4] });
        let edge = |v: [u32; 2], f: [u32; 2], kind, land, p: DVec3, q: DVec3| {
            let length = p.distance(q);
            let mid = (p + q) * 0.5;
            let offset = mid.distance(parent_mid);
            let (len, radius) = (parent.lod.len() as f64, parent.lod.radius() as f64);
            let lod = Lod::new(length.min(len), (LOD_RADIUS as f64 * length).min(radius - offset));
            (Edge { v, f, lod, level, kind, land }, mid)
        };
        // f1 and f3 are of f1's kind, f2 and f4 of f2's.
        let [k1, k2] = parent.face_kinds();
        let (inner1, inner2) = (Edge::land_bits([k1, k1]), Edge::land_bits([k2, k2]));
        let made = [
            edge([a, m], [f1, f2], kinds[0], parent.land, pa, pm),
            edge([m, t], [f1, f3], kinds[1], inner1, pm, pt),
            edge([m, b], [f3, f4], kinds[2], parent.land, pm, pb),
            edge([m, d], [f4, f2], kinds[3], inner2, pm, pd),
        ];
        for (e, (made, _)) in [e1, e2, e3, e4].into_iter().zip(&made) {
            self.e.add(e as usize).write(*made);
        }
        vertex.edge = e1;
        vertex.parent_lod = parent.lod;
        vertex.flags.insert(kinds.iter().fold(VertexFlags::empty(), |acc, k| acc | k.flag()));
        self.v.add(m as usize).write(vertex);
        self.relink(old1.e[1], f1, f3);
        self.relink(old2.e[2], f2, f4);
        self.move_link(b, e1, e3);
        made
    }

    /// Collapses the vertex at `site`, restoring the edge and the two faces it was split from;
    /// the removed vertex, edges and faces are marked dead.
    ///
    /// # Safety
    /// `site` is a collapse site of the mesh and no other operation of the batch owns its
    /// vertex, edges or faces.
    pub unsafe fn collapse(&self, site: &CollapseSite) {
        let CollapseSite { v: m, e: [e1, e2, e3, e4], f: [f1, f2, f3, f4], a, b, t, d } = *site;
        // Faces before: f1 = (m, t, a), f3 = (m, b, t), f2 = (m, a, d), f4 = (m, d, b).
        let face = |f: u32| self.f.add(f as usize);
        let (x1, x2, x3, x4) = (face(f1).read(), face(f2).read(), face(f3).read(), face(f4).read());
        let (bt, ta, ad, db) = (x3.e[0], x1.e[0], x2.e[0], x4.e[0]);
        // After: f1 = (t, a, b), f2 = (d, b, a).
        face(f1).write(Face { e: [e1, bt, ta] });
        face(f2).write(Face { e: [e1, ad, db] });
        self.relink(bt, f3, f1);
        self.relink(db, f4, f2);

        let edge1 = self.e.add(e1 as usize);
        let (k1, k3) = ((*edge1).kind, (*self.e.add(e3 as usize)).kind);
        let kind = if k1 == k3 || k3 == EdgeKind::River { k1 } else { k3 };
        let lod = addr_of!((*self.v.add(m as usize)).parent_lod).read();
        let old = edge1.read();
        edge1.write(Edge { v: [a, b], lod, level: old.level - 1, kind, ..old });
        for (v, gone, keep) in [(b, e3, e1), (t, e2, ta), (d, e4, ad)] {
            self.move_link(v, gone, keep);
        }
        self.link(m).store(DEAD, Relaxed);
        for e in [e2, e3, e4] {
            addr_of_mut!((*self.e.add(e as usize)).v).write([DEAD; 2]);
        }
        for f in [f3, f4] {
            addr_of_mut!((*self.f.add(f as usize)).e).write([DEAD; 3]);
        }
    }
}
