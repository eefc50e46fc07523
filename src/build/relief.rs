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
    /// Depressions breached and kept.
    pub breached: usize,
    pub lakes: usize,
}

/// The flood tree and the map over it: `order` lists the inland river vertices downstream
/// first, `downstream[v]`/`edge_len[v]` the vertex each drains to and the length of that edge,
/// `route[v]` the altitude the flood ordered it by (the lowest ground around it) and
/// `height[v]` the altitude of its water before carving (m relative to sea level; coast
/// vertices drain nowhere and stand at 0), `area[v]` the area a vertex stands for.
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

/// Water levels and lakes of a relief map's network (see the module doc).
pub fn levels(flood: &Flood) -> Levels {
    let n = flood.height.len();
    let Flood { order, downstream, edge_len, route, height, area, .. } = *flood;
    // 1. Fill levels and depressions: pieces of the tree at one spill level above the map.
    let mut fill = vec![0.0f64; n];
    let mut comp = vec![NONE; n];
    let mut spill: Vec<f64> = Vec::new();
    let mut floor: Vec<f64> = Vec::new();
    let mut size: Vec<f64> = Vec::new();
    for &v in order {
        let (v, u) = (v as usize, downstream[v as usize] as usize);
        fill[v] = route[v].max(fill[u]);
        if fill[v] > route[v] {
            let c = if comp[u] != NONE && fill[u] == fill[v] {
                comp[u]
            } else {
                spill.push(fill[v]);
                floor.push(route[v]);
                size.push(0.0);
                spill.len() as u32 - 1
            };
            comp[v] = c;
            floor[c as usize] = floor[c as usize].min(route[v]);
            size[c as usize] += area[v];
        }
    }
    // 2. Breach or keep.
    let kept: Vec<bool> =
        (0..spill.len()).map(|c| spill[c] - floor[c] > BREACH_DEPTH_M && size[c] >= flood.min_lake_area_m2).collect();
    let mut lake_id = vec![NONE; spill.len()];
    let mut lakes = 0u32;
    for (c, &k) in kept.iter().enumerate() {
        if k {
            lake_id[c] = lakes;
            lakes += 1;
        }
    }
    let lake: Vec<u32> = comp.iter().map(|&c| if c == NONE { NONE } else { lake_id[c as usize] }).collect();
    // 3a. Start from the map, lakes at their spill level; carve upstream first.
    let mut water: Vec<f64> =
        (0..n).map(|v| if lake[v] != NONE { spill[comp[v] as usize] } else { height[v] }).collect();
    for &v in order.iter().rev() {
        let (v, u) = (v as usize, downstream[v as usize] as usize);
        if lake[u] == NONE {
            water[u] = water[u].min(water[v] - flood.river_slope * edge_len[v]);
        }
    }
    // 3b. Strictly falling: at least the least slope (a millimetre an edge inside a lake) above
    // the vertex downstream, downstream first; the coast stays at sea level.
    let mut out = vec![0.0f64; n];
    for &v in order {
        let (v, u) = (v as usize, downstream[v as usize] as usize);
        let step = if lake[v] != NONE && lake[v] == lake[u] { LAKE_STEP_M } else { flood.river_slope * edge_len[v] };
        out[v] = water[v].max(out[u] + step.max(LAKE_STEP_M));
    }
    Levels { water: out, lake, breached: kept.iter().filter(|&&k| !k).count(), lakes: lakes as usize }
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
        levels(&Flood {
            order: &order,
            downstream: &downstream,
            edge_len: &edge_len,
            route: height,
            height,
            area: &area,
            min_lake_area_m2: 1.5e8,
            river_slope: 1.0e-5,
        })
    }

    #[test]
    fn water_follows_the_map_without_lifting_it() {
        let h = [0.0, 20.0, 35.0, 80.0, 200.0];
        let l = line(&h);
        for v in 1..h.len() {
            assert!(l.water[v] <= h[v] + 1e-9, "{v}: {} over {}", l.water[v], h[v]);
            assert!(l.water[v] > l.water[v - 1]);
        }
        assert_eq!((l.lakes, l.breached), (0, 0));
    }

    #[test]
    fn a_shallow_dam_is_breached() {
        // A 30 m dam at vertex 2 in front of a pit at vertex 3.
        let h = [0.0, 10.0, 60.0, 30.0, 100.0];
        let l = line(&h);
        assert_eq!((l.lakes, l.breached), (0, 1));
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
        assert_eq!((l.lakes, l.breached), (1, 0));
        assert_eq!(l.lake[3], l.lake[4]);
        assert_ne!(l.lake[3], NONE);
        assert_eq!(l.lake[5], NONE);
        for v in [3, 4] {
            assert!((l.water[v] - 300.0).abs() < 0.01, "lake level {}", l.water[v]);
        }
        assert!(l.water[2] < l.water[3] && l.water[2] > 299.0);
        // One vertex alone is too small to keep, however deep.
        let l = line(&[0.0, 50.0, 300.0, 100.0, 400.0]);
        assert_eq!((l.lakes, l.breached), (0, 1));
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
