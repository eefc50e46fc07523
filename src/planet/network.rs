//! The river network read back from a mesh (paper §4.2): downstream links, reaches between
//! confluences, Strahler orders, drainage areas and the network's invariants.
//!
//! It is derived from the mesh alone — river edges and water altitudes — so it describes a base
//! mesh and an adapted mesh alike.

use crate::mesh::{EdgeKind, FaceKind, Mesh, VertexFlags, NONE};

/// Downstream structure of the river edges of a mesh.
#[derive(Clone, Debug)]
pub struct RiverGraph {
    /// For each vertex, the river neighbour its water flows to (`NONE` at mouths and off-river).
    pub downstream: Vec<u32>,
    up_offsets: Vec<u32>,
    up: Vec<u32>,
    /// River vertices, upstream before downstream (decreasing water altitude).
    pub order: Vec<u32>,
    /// Coast vertices where a river meets the sea.
    pub mouths: Vec<u32>,
    /// Pits of closed basins, where rivers end inland: lake vertices ([`VertexFlags::LAKE`])
    /// with no lower river neighbour.
    pub sinks: Vec<u32>,
    /// River vertices with no lower river neighbour, plus river edges that are not a downstream
    /// link (water level equal at both ends, or a second outflow).
    pub monotone_violations: usize,
}

/// Seconds in a mean year.
pub const SECONDS_PER_YEAR: f64 = 365.25 * 86_400.0;

/// A stretch of river between confluences, ordered downstream.
#[derive(Clone, Debug, PartialEq)]
pub struct Reach {
    pub id: usize,
    pub vertices: Vec<u32>,
    pub downstream_id: Option<usize>,
    pub strahler: u32,
    pub upstream_area_m2: f64,
    /// Mean discharge where the reach ends (m³/s; 0 without a climate's runoff).
    pub discharge_m3s: f64,
    pub length_m: f64,
}

/// Least mean discharge (m³/s) and runoff over the upstream area (mm/yr) of a river that flows
/// all year; below either it is a wadi that runs only after rain.
const PERENNIAL_M3S: f64 = 0.5;
const PERENNIAL_RUNOFF_MM: f64 = 5.0;

/// Hydraulic geometry at mean discharge `Q`: Leopold & Maddock's (1953) downstream relations
/// with the coefficients Knighton (1998) quotes, width `3.5 Q^0.51` m and depth `0.36 Q^0.37` m.
impl Reach {
    pub fn width_m(&self) -> f64 {
        channel_width_m(self.discharge_m3s)
    }
    pub fn depth_m(&self) -> f64 {
        channel_depth_m(self.discharge_m3s)
    }
    /// Whether the reach flows all year (see [`PERENNIAL_M3S`]).
    pub fn perennial(&self) -> bool {
        perennial(self.discharge_m3s, self.upstream_area_m2)
    }
}

/// Channel widths of floodplain, banks and bed that lose a river's water where it crosses dry
/// land (transmission losses: evaporation from the floodplain and riparian belt, seepage into
/// the bed). Calibrated on the Nile: a river of its natural flow (2,830 m³/s) loses about 5 % over
/// 1,000 km of hyper-arid desert, the order of the natural Nile's losses between Khartoum (with
/// the Atbara) and Aswan; relatively more the smaller the river (`w ~ Q^0.51`), so desert
/// streams dry up (docs/realism.md).
pub const LOSING_WIDTHS: f64 = 10.0;

/// What the climate gives and takes per base-mesh vertex: runoff from its land and the net
/// evaporation of open water there (mm per year; empty vectors for none).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct WaterBudget {
    /// Runoff over the vertex's land (0 at sea): what the rivers' discharge sums.
    pub runoff_mm: Vec<f32>,
    /// What a river's floodplain loses per unit of its area
    /// ([`super::climate::channel_loss_mm`], [`LOSING_WIDTHS`]).
    pub channel_loss_mm: Vec<f32>,
}

impl WaterBudget {
    /// The discharge (m³/s) left of `q` after `length_m` of channel at vertex `v`.
    pub fn after_losses(&self, v: usize, q: f64, length_m: f64) -> f64 {
        let loss_mm = self.channel_loss_mm.get(v).map_or(0.0, |&e| f64::from(e));
        after_channel_losses(q, length_m, loss_mm)
    }
}

/// The discharge (m³/s) left of `q` after `length_m` of channel where a floodplain loses
/// `loss_mm` a year ([`super::climate::channel_loss_mm`]): `LOSING_WIDTHS` channel widths of
/// floodplain and bed lose it.
pub fn after_channel_losses(q: f64, length_m: f64, loss_mm: f64) -> f64 {
    let net = loss_mm.max(0.0) * 1e-3 / SECONDS_PER_YEAR;
    (q - LOSING_WIDTHS * channel_width_m(q) * length_m * net).max(0.0)
}

/// Channel width (m) at mean discharge `q` (m³/s): `3.5 Q^0.51` (see [`Reach`]).
pub fn channel_width_m(q: f64) -> f64 {
    3.5 * q.max(0.0).powf(0.51)
}

/// Channel depth (m) at mean discharge `q` (m³/s): `0.36 Q^0.37` (see [`Reach`]).
pub fn channel_depth_m(q: f64) -> f64 {
    0.36 * q.max(0.0).powf(0.37)
}

/// The mean discharge (m³/s) whose channel is `width_m` wide: the inverse of
/// [`channel_width_m`].
pub fn discharge_of_width(width_m: f64) -> f64 {
    (width_m.max(0.0) / 3.5).powf(1.0 / 0.51)
}

/// Whether a river with mean discharge `q` (m³/s) from `area_m2` flows all year (see
/// [`PERENNIAL_M3S`]).
pub fn perennial(q: f64, area_m2: f64) -> bool {
    let runoff_mm = q * SECONDS_PER_YEAR / area_m2.max(1.0) * 1e3;
    q >= PERENNIAL_M3S && runoff_mm >= PERENNIAL_RUNOFF_MM
}

/// The channels of a built mesh's rivers (see [`crate::mesh::channels`]): at each river vertex
/// off lakes, the width of its channel at the discharge `flow` through it (from
/// [`RiverGraph::discharge`]), 0 where the river does not flow all year. `None` without rivers.
pub fn channels(mesh: &Mesh, graph: &RiverGraph, flow: &[f64]) -> Option<crate::mesh::channels::Channels> {
    let area = graph.drainage_area(mesh);
    let river = |v: usize| {
        let f = mesh.vertices[v].flags;
        f.contains(VertexFlags::RIVER) && !f.contains(VertexFlags::LAKE)
    };
    let points: Vec<(glam::DVec3, f32)> = (0..mesh.vertices.len())
        .filter(|&v| river(v))
        .map(|v| {
            let w = if perennial(flow[v], area[v]) { channel_width_m(flow[v]) } else { 0.0 };
            (mesh.vertices[v].p().normalize(), w as f32)
        })
        .collect();
    // Grid cells of a median river edge; the longest one is as far as a width reaches.
    let mut lens: Vec<f64> = mesh
        .edges
        .iter()
        .filter(|e| e.kind == EdgeKind::River)
        .map(|e| mesh.vertices[e.v[0] as usize].p().distance(mesh.vertices[e.v[1] as usize].p()))
        .collect();
    lens.sort_by(f64::total_cmp);
    let (median, longest) = (lens.get(lens.len() / 2).copied()?, lens.last().copied()?);
    crate::mesh::channels::Channels::new(&points, median, longest, mesh.radius)
}

impl RiverGraph {
    pub fn from_mesh(mesh: &Mesh) -> RiverGraph {
        let n = mesh.vertices.len();
        let mut downstream = vec![NONE; n];
        let mut used = 0usize;
        let mut river_edges = 0usize;
        let mut violations = 0;
        let mut mouths = Vec::new();
        let mut sinks = Vec::new();
        let adj = mesh.adjacency();
        for v in 0..n as u32 {
            let vert = &mesh.vertices[v as usize];
            if !vert.flags.contains(VertexFlags::RIVER) {
                continue;
            }
            if vert.flags.contains(VertexFlags::MOUTH) {
                mouths.push(v);
                continue;
            }
            let mut best: Option<(f64, u32)> = None;
            for (w, e) in adj.around(v) {
                if mesh.edges[e as usize].kind != EdgeKind::River {
                    continue;
                }
                let ww = mesh.vertices[w as usize].water;
                if ww < vert.water && best.is_none_or(|(bw, bv)| (ww, w) < (bw, bv)) {
                    best = Some((ww, w));
                }
            }
            match best {
                Some((_, w)) => {
                    downstream[v as usize] = w;
                    used += 1;
                }
                None if vert.flags.contains(VertexFlags::LAKE) => sinks.push(v),
                None => violations += 1,
            }
        }
        for e in &mesh.edges {
            if e.kind == EdgeKind::River {
                river_edges += 1;
            }
        }
        violations += river_edges.saturating_sub(used);
        let (up_offsets, up) = upstream_lists(&downstream);
        let mut order: Vec<u32> =
            (0..n as u32).filter(|&v| mesh.vertices[v as usize].flags.contains(VertexFlags::RIVER)).collect();
        order.sort_by(|&a, &b| {
            let (wa, wb) = (mesh.vertices[a as usize].water, mesh.vertices[b as usize].water);
            wb.total_cmp(&wa).then(a.cmp(&b))
        });
        RiverGraph { downstream, up_offsets, up, order, mouths, sinks, monotone_violations: violations }
    }

    /// Vertices whose water flows directly into `v`.
    pub fn upstream_of(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        let r = self.up_offsets[v as usize] as usize..self.up_offsets[v as usize + 1] as usize;
        self.up[r].iter().copied()
    }

    pub fn tributaries(&self, v: u32) -> usize {
        (self.up_offsets[v as usize + 1] - self.up_offsets[v as usize]) as usize
    }

    /// Area drained through each vertex: every land vertex owns a third of its land faces, and
    /// vertices off the network drain into their lowest neighbour on it.
    pub fn drainage_area(&self, mesh: &Mesh) -> Vec<f64> {
        self.accumulate(mesh, |_| 1.0, |_, _, a| a)
    }

    /// Mean discharge through each vertex (m³/s): the runoff (`water.runoff_mm[v]`, mm per year
    /// over vertex `v`'s land) of the area it drains, less what the channel lost on its way
    /// where it crossed dry land ([`WaterBudget::after_losses`]). Lakes pass their inflow on; a
    /// closed basin's pit takes in all of its own.
    pub fn discharge(&self, mesh: &Mesh, water: &WaterBudget) -> Vec<f64> {
        let per_area = |v: usize| water.runoff_mm.get(v).map_or(0.0, |&r| f64::from(r) * 1e-3 / SECONDS_PER_YEAR);
        let lose = |v: u32, d: u32, q: f64| {
            if mesh.vertices[v as usize].flags.contains(VertexFlags::LAKE) {
                return q;
            }
            water.after_losses(v as usize, q, mesh.pos(v).distance(mesh.pos(d)))
        };
        self.accumulate(mesh, per_area, lose)
    }

    /// Sums `per_area(v)` times each land vertex's area down the network, as for
    /// [`RiverGraph::drainage_area`]; `pass(v, d, q)` is what of `q` through `v` reaches `d`.
    fn accumulate(
        &self,
        mesh: &Mesh,
        per_area: impl Fn(usize) -> f64,
        pass: impl Fn(u32, u32, f64) -> f64,
    ) -> Vec<f64> {
        let n = mesh.vertices.len();
        let mut own = vec![0.0f64; n];
        for f in 0..mesh.faces.len() as u32 {
            if mesh.face_kind(f) == FaceKind::Land {
                let a = mesh.face_area_vector(f).length() / 3.0;
                for v in mesh.corners(f) {
                    own[v as usize] += a * per_area(v as usize);
                }
            }
        }
        let adj = mesh.adjacency();
        let mut acc = vec![0.0f64; n];
        for v in 0..n as u32 {
            let flags = mesh.vertices[v as usize].flags;
            if flags.contains(VertexFlags::RIVER) {
                acc[v as usize] += own[v as usize];
            } else if let Some(t) = self.drain_target(mesh, &adj, v) {
                acc[t as usize] += own[v as usize];
            }
        }
        for &v in &self.order {
            let d = self.downstream[v as usize];
            if d != NONE {
                acc[d as usize] += pass(v, d, acc[v as usize]);
            }
        }
        acc
    }

    /// The river or coast neighbour with the lowest water that an off-river land vertex drains to.
    fn drain_target(&self, mesh: &Mesh, adj: &crate::mesh::Adjacency, v: u32) -> Option<u32> {
        let vert = &mesh.vertices[v as usize];
        if !vert.flags.is_inland() {
            return None;
        }
        adj.around(v)
            .filter(|&(w, _)| {
                let f = mesh.vertices[w as usize].flags;
                f.contains(VertexFlags::RIVER) || f.contains(VertexFlags::COAST)
            })
            .min_by(|a, b| {
                let (wa, wb) = (mesh.vertices[a.0 as usize].water, mesh.vertices[b.0 as usize].water);
                wa.total_cmp(&wb).then(a.0.cmp(&b.0))
            })
            .map(|(w, _)| w)
    }

    /// Share of the land area (by vertex) whose water reaches the sea, or a closed basin's
    /// pit, through the network.
    pub fn drained_fraction(&self, mesh: &Mesh) -> f64 {
        let n = mesh.vertices.len();
        let mut reaches_sea = vec![false; n];
        for &m in self.mouths.iter().chain(&self.sinks) {
            reaches_sea[m as usize] = true;
        }
        for &v in self.order.iter().rev() {
            let d = self.downstream[v as usize];
            if d != NONE && reaches_sea[d as usize] {
                reaches_sea[v as usize] = true;
            }
        }
        let adj = mesh.adjacency();
        let (mut drained, mut total) = (0.0, 0.0);
        for f in 0..mesh.faces.len() as u32 {
            if mesh.face_kind(f) != FaceKind::Land {
                continue;
            }
            let a = mesh.face_area_vector(f).length() / 3.0;
            for v in mesh.corners(f) {
                let flags = mesh.vertices[v as usize].flags;
                let ok = if flags.contains(VertexFlags::COAST) {
                    true
                } else if flags.contains(VertexFlags::RIVER) {
                    reaches_sea[v as usize]
                } else {
                    self.drain_target(mesh, &adj, v).is_some_and(|t| {
                        reaches_sea[t as usize] || mesh.vertices[t as usize].flags.contains(VertexFlags::COAST)
                    })
                };
                total += a;
                if ok {
                    drained += a;
                }
            }
        }
        if total > 0.0 {
            drained / total
        } else {
            1.0
        }
    }

    /// Splits the network into reaches between springs, confluences and mouths, with their
    /// discharge from `water` (empty for none).
    pub fn reaches(&self, mesh: &Mesh, water: &WaterBudget) -> Vec<Reach> {
        let n = mesh.vertices.len();
        let area = self.drainage_area(mesh);
        let flow = self.discharge(mesh, water);
        let mut strahler = vec![0u32; n];
        for &v in &self.order {
            let mut best = 0;
            let mut count = 0;
            for u in self.upstream_of(v) {
                let s = strahler[u as usize];
                match s.cmp(&best) {
                    std::cmp::Ordering::Greater => (best, count) = (s, 1),
                    std::cmp::Ordering::Equal => count += 1,
                    _ => {}
                }
            }
            strahler[v as usize] = if best == 0 {
                1
            } else if count >= 2 {
                best + 1
            } else {
                best
            };
        }
        let ends = |v: u32| {
            mesh.vertices[v as usize].flags.contains(VertexFlags::MOUTH) || self.sinks.binary_search(&v).is_ok()
        };
        let is_start = |v: u32| {
            let f = mesh.vertices[v as usize].flags;
            f.contains(VertexFlags::RIVER) && !ends(v) && self.tributaries(v) != 1
        };
        let mut start_id = vec![usize::MAX; n];
        let starts: Vec<u32> = self.order.iter().copied().filter(|&v| is_start(v)).collect();
        for (i, &s) in starts.iter().enumerate() {
            start_id[s as usize] = i;
        }
        starts
            .iter()
            .enumerate()
            .map(|(id, &s)| {
                let mut path = vec![s];
                let mut length = 0.0;
                let mut v = s;
                loop {
                    let d = self.downstream[v as usize];
                    if d == NONE {
                        break;
                    }
                    length += mesh.pos(v).distance(mesh.pos(d));
                    path.push(d);
                    if self.tributaries(d) >= 2 || ends(d) {
                        break;
                    }
                    v = d;
                }
                let last = *path.last().unwrap_or(&s);
                let downstream_id =
                    (last != s && start_id[last as usize] != usize::MAX).then(|| start_id[last as usize]);
                let own_end = path[path.len().saturating_sub(2)];
                Reach {
                    id,
                    downstream_id,
                    strahler: strahler[s as usize].max(1),
                    upstream_area_m2: area[own_end as usize],
                    discharge_m3s: flow[own_end as usize],
                    length_m: length,
                    vertices: path,
                }
            })
            .collect()
    }
}

/// Each vertex's upstream neighbours (those whose `downstream` it is), as the list of all of
/// them and each vertex's offsets into it (`offsets[v]..offsets[v + 1]`), in vertex order.
pub fn upstream_lists(downstream: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let n = downstream.len();
    let mut offsets = vec![0u32; n + 1];
    for &d in downstream {
        if d != NONE {
            offsets[d as usize + 1] += 1;
        }
    }
    for i in 0..n {
        offsets[i + 1] += offsets[i];
    }
    let mut fill = offsets.clone();
    let mut up = vec![0u32; offsets[n] as usize];
    for (v, &d) in downstream.iter().enumerate() {
        if d != NONE {
            up[fill[d as usize] as usize] = v as u32;
            fill[d as usize] += 1;
        }
    }
    (offsets, up)
}

#[cfg(test)]
mod loss_tests {
    use super::*;
    use crate::planet::climate::channel_loss_mm;

    /// Rivers lose water on their way where it is dry, relatively more the smaller they are, and
    /// nothing where rain exceeds evaporation.
    #[test]
    fn desert_channels_lose_water_and_humid_ones_none() {
        assert_eq!(channel_loss_mm(1500.0, 1200.0), 0.0);
        let (desert, steppe) = (channel_loss_mm(30.0, 2500.0), channel_loss_mm(500.0, 1000.0));
        assert!(desert > 2000.0 && steppe < 150.0, "{desert} {steppe}");
        assert_eq!(after_channel_losses(100.0, 1e5, 0.0), 100.0);
        // 1,000 km of hyper-arid desert: a Nile-sized river keeps about 95 %, a Tarim-sized one
        // about four fifths, a desert stream of 1 m³/s dries up.
        let through = |q: f64| (0..100).fold(q, |q, _| after_channel_losses(q, 1e4, desert));
        let (nile, tarim) = (through(2800.0) / 2800.0, through(150.0) / 150.0);
        assert!((0.9..0.98).contains(&nile) && (0.6..0.9).contains(&tarim), "{nile} {tarim}");
        assert_eq!(through(1.0), 0.0);
        assert!(after_channel_losses(1.0, 1e6, desert) == 0.0);
        assert!((channel_width_m(discharge_of_width(300.0)) - 300.0).abs() < 1e-9);
    }
}
