//! River water levels on an elevation map (paper §4.2 with a relief map): depressions breached
//! or kept as lakes, and water that falls to the sea without lifting the land.
//!
//! The network of [`super::rivers`] is a priority flood from the coast over the map's altitudes
//! (Barnes et al. 2014): every vertex drains towards the vertex it was reached from, so a
//! depression drains out over its lowest pass. Filling that depression to its pass, as the flood
//! alone would, lifts whole basins wherever the map lost a narrow gorge. Here, as hydrology
//! tools do (Lindsay 2016, least-cost breaching), the levels follow the map instead:
//!
//! 1. The fill level `F` of every vertex is the highest altitude on its way to the sea (the
//!    flood's spill level), both measured on the ground the flood was ordered by. Vertices with
//!    `F` above their own altitude lie in a depression; depressions are the connected pieces of
//!    the flood tree at one spill level.
//! 2. A depression at most [`BREACH_DEPTH_M`] deep, or covering no more than about two map
//!    pixels, is an artefact of the map's sampling: it is *breached*, the channel cut through its
//!    dam down to the depression's floor. A deeper and wider one is real and *kept*: its water
//!    stands at the spill level, a lake over the map's floor.
//! 3. Water then falls downstream by at least `min_river_slope` per metre of river (a lake by a
//!    millimetre per edge, flat to the eye), carved below the map where a breach needs it, never
//!    lifted above the map except by that least slope. Ground between rivers keeps the map.

use crate::mesh::NONE;

/// Deepest depression (below its spill level) treated as a sampling artefact and breached.
pub const BREACH_DEPTH_M: f64 = 50.0;
/// How much a lake's surface falls per edge towards its outlet, so that the network still
/// descends strictly (m).
pub const LAKE_STEP_M: f64 = 1.0e-3;

/// The levels of a relief map's network.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Levels {
    /// Water level per vertex, metres relative to sea level (river vertices and mouths).
    pub water: Vec<f64>,
    /// Lake id per vertex (`NONE` off lakes).
    pub lake: Vec<u32>,
    /// Per lake: its depression, and whether it has no outlet (a terminal lake).
    pub lakes: Vec<LakeLevel>,
    /// Depressions breached.
    pub breached: usize,
    /// Depressions with no outlet to the sea (with or without a standing lake).
    pub endorheic: usize,
}

/// A lake of [`Levels`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LakeLevel {
    pub depression: u32,
    /// Surface level, m relative to sea level.
    pub level: f64,
    pub endorheic: bool,
}

/// The flood tree and the map over it: `order` lists the inland river vertices downstream
/// first, `downstream[v]`/`edge_len[v]` the vertex each drains to and the length of that edge,
/// `route[v]` the altitude the flood ordered it by (the lowest ground around it) and
/// `height[v]` the altitude of its water before carving (m relative to sea level; coast
/// vertices drain nowhere and stand at 0), `area[v]` the area a vertex stands for.
#[derive(Clone, Copy)]
pub struct Flood<'a> {
    pub order: &'a [u32],
    pub downstream: &'a [u32],
    pub edge_len: &'a [f64],
    pub route: &'a [f64],
    pub height: &'a [f64],
    pub area: &'a [f64],
    /// Least area of a kept depression (m²): about two map pixels.
    pub min_lake_area_m2: f64,
    /// Least slope of the water surface (m per m).
    pub river_slope: f64,
}

/// The depressions of a flood tree (step 1 of the module doc) and which are kept (step 2).
#[derive(Clone, Debug, Default)]
pub struct Depressions {
    /// Depression per vertex (`NONE` outside any).
    pub comp: Vec<u32>,
    /// Per depression: spill level, floor (m relative to sea level), area (m²).
    pub spill: Vec<f64>,
    pub floor: Vec<f64>,
    pub size: Vec<f64>,
    /// Per depression: the vertex it drains out through, and its lowest vertex.
    pub root: Vec<u32>,
    pub pit: Vec<u32>,
    /// Per depression: real (kept), not an artefact of the map's sampling (breached).
    pub kept: Vec<bool>,
}

/// Fill levels and depressions: pieces of the tree at one spill level above the map.
pub fn depressions(flood: &Flood) -> Depressions {
    let n = flood.height.len();
    let Flood { order, downstream, route, area, .. } = *flood;
    let mut fill = vec![0.0f64; n];
    let mut d = Depressions { comp: vec![NONE; n], ..Depressions::default() };
    for &v in order {
        let (v, u) = (v as usize, downstream[v as usize] as usize);
        fill[v] = route[v].max(fill[u]);
        if fill[v] > route[v] {
            let c = if d.comp[u] != NONE && fill[u] == fill[v] {
                d.comp[u]
            } else {
                d.spill.push(fill[v]);
                d.floor.push(route[v]);
                d.size.push(0.0);
                d.root.push(v as u32);
                d.pit.push(v as u32);
                d.spill.len() as u32 - 1
            };
            d.comp[v] = c;
            let c = c as usize;
            if route[v] < d.floor[c] {
                (d.floor[c], d.pit[c]) = (route[v], v as u32);
            }
            d.size[c] += area[v];
        }
    }
    d.kept = (0..d.spill.len())
        .map(|c| d.spill[c] - d.floor[c] > BREACH_DEPTH_M && d.size[c] >= flood.min_lake_area_m2)
        .collect();
    d
}

/// Water levels and lakes of a relief map's network (see the module doc). `terminal[c]` is the
/// level of depression `c`'s terminal lake when it has no outlet: the flood tree must then
/// already drain it to its pit ([`super::basins::drain_to_pits`]), and `order` leave the pits out.
pub fn levels(flood: &Flood, dep: &Depressions, terminal: &[Option<f64>]) -> Levels {
    let n = flood.height.len();
    let Flood { order, downstream, edge_len, route, height, area, .. } = *flood;
    // Lakes: a kept depression's water at its spill level; a terminal one's up to its level,
    // when that covers about two map pixels.
    let mut lakes = Vec::new();
    let mut lake_of_comp = vec![NONE; dep.spill.len()];
    let mut wet_area = vec![0.0f64; dep.spill.len()];
    for v in 0..n {
        let c = dep.comp[v];
        if c != NONE && terminal[c as usize].is_some_and(|l| route[v] <= l) {
            wet_area[c as usize] += area[v];
        }
    }
    for c in 0..dep.spill.len() {
        let (level, endorheic) = match terminal[c] {
            Some(l) => (l, true),
            None => (dep.spill[c], false),
        };
        let lake = if endorheic { wet_area[c] >= flood.min_lake_area_m2 } else { dep.kept[c] };
        if lake {
            lake_of_comp[c] = lakes.len() as u32;
            lakes.push(LakeLevel { depression: c as u32, level, endorheic });
        }
    }
    let lake: Vec<u32> = (0..n)
        .map(|v| {
            let c = dep.comp[v];
            match c {
                NONE => NONE,
                c if terminal[c as usize].is_some_and(|l| route[v] > l) => NONE,
                c => lake_of_comp[c as usize],
            }
        })
        .collect();
    // Start from the map, lakes at their level; carve upstream first.
    let mut water: Vec<f64> =
        (0..n).map(|v| if lake[v] != NONE { lakes[lake[v] as usize].level } else { height[v] }).collect();
    for (c, t) in terminal.iter().enumerate() {
        if let Some(l) = t {
            let pit = dep.pit[c] as usize;
            water[pit] = water[pit].min(*l);
        }
    }
    for &v in order.iter().rev() {
        let (v, u) = (v as usize, downstream[v as usize] as usize);
        if lake[u] == NONE {
            water[u] = water[u].min(water[v] - flood.river_slope * edge_len[v]);
        }
    }
    // Strictly falling: at least the least slope (a millimetre an edge inside a lake) above
    // the vertex downstream, downstream first; the coast stays at sea level, a terminal pit at
    // its lake's level.
    let mut out = vec![0.0f64; n];
    for (c, t) in terminal.iter().enumerate() {
        if t.is_some() {
            out[dep.pit[c] as usize] = water[dep.pit[c] as usize];
        }
    }
    for &v in order {
        let (v, u) = (v as usize, downstream[v as usize] as usize);
        let step = if lake[v] != NONE && lake[v] == lake[u] { LAKE_STEP_M } else { flood.river_slope * edge_len[v] };
        out[v] = water[v].max(out[u] + step.max(LAKE_STEP_M));
    }
    let breached = (0..dep.spill.len()).filter(|&c| !dep.kept[c] && terminal[c].is_none()).count();
    Levels { water: out, lake, lakes, breached, endorheic: terminal.iter().filter(|t| t.is_some()).count() }
}

#[cfg(test)]
#[allow(clippy::needless_range_loop)]
mod tests {
    use super::*;

    /// A line of vertices draining to vertex 0 (the coast), 10 km apart.
    fn line(height: &[f64]) -> Levels {
        let n = height.len();
        let order: Vec<u32> = (1..n as u32).collect();
        let downstream: Vec<u32> = (0..n as u32).map(|v| v.saturating_sub(1)).collect();
        let edge_len = vec![10_000.0; n];
        let area = vec![1.0e8; n];
        let flood = Flood {
            order: &order,
            downstream: &downstream,
            edge_len: &edge_len,
            route: height,
            height,
            area: &area,
            min_lake_area_m2: 1.5e8,
            river_slope: 1.0e-5,
        };
        let dep = depressions(&flood);
        levels(&flood, &dep, &vec![None; dep.spill.len()])
    }

    #[test]
    fn water_follows_the_map_without_lifting_it() {
        let h = [0.0, 20.0, 35.0, 80.0, 200.0];
        let l = line(&h);
        for v in 1..h.len() {
            assert!(l.water[v] <= h[v] + 1e-9, "{v}: {} over {}", l.water[v], h[v]);
            assert!(l.water[v] > l.water[v - 1]);
        }
        assert_eq!((l.lakes.len(), l.breached), (0, 0));
    }

    #[test]
    fn a_shallow_dam_is_breached() {
        // A 30 m dam at vertex 2 in front of a pit at vertex 3.
        let h = [0.0, 10.0, 60.0, 30.0, 100.0];
        let l = line(&h);
        assert_eq!((l.lakes.len(), l.breached), (0, 1));
        assert!(l.water[2] < 30.0, "the dam is cut to the pit: {}", l.water[2]);
        assert!(l.water[3] <= 30.0 && l.water[4] <= 100.0);
        for v in 1..h.len() {
            assert!(l.water[v] > l.water[v - 1]);
        }
    }

    #[test]
    fn a_deep_wide_depression_keeps_a_lake_at_its_spill_level() {
        // Pass at 300 m; floor at 100 m over two vertices.
        let h = [0.0, 50.0, 300.0, 100.0, 120.0, 400.0];
        let l = line(&h);
        assert_eq!((l.lakes.len(), l.breached), (1, 0));
        assert_eq!(l.lake[3], l.lake[4]);
        assert_ne!(l.lake[3], NONE);
        assert_eq!(l.lake[5], NONE);
        for v in [3, 4] {
            assert!((l.water[v] - 300.0).abs() < 0.01, "lake level {}", l.water[v]);
        }
        assert!(l.water[2] < l.water[3] && l.water[2] > 299.0);
        // One vertex alone is too small to keep, however deep.
        let l = line(&[0.0, 50.0, 300.0, 100.0, 400.0]);
        assert_eq!((l.lakes.len(), l.breached), (0, 1));
    }

    #[test]
    fn land_below_sea_level_drains_above_the_sea() {
        let l = line(&[0.0, -20.0, -30.0, 5.0]);
        for v in 1..4 {
            assert!(l.water[v] > l.water[v - 1]);
        }
        assert!(l.water[1] > 0.0 && l.water[1] < 1.0);
    }
}
