//! Basins with no outlet to the sea (endorheic), by water balance.
//!
//! A real depression of the map ([`super::relief`]) fills until it spills, unless its water
//! evaporates first: its lake at the spill level must take in, as runoff from its whole
//! catchment ([`super::climate`]), at least what evaporates from its surface beyond the rain
//! that falls on it. If it cannot, the depression has no outlet and its lake stands lower, at
//! the level where inflow and net evaporation balance (Mason et al. 1994's closed-lake
//! balance; with little inflow only a dry pan remains). Depressions are decided upstream
//! first, so a closed basin's catchment stops feeding the ones below it.
//!
//! The flood tree then drains a closed depression to its lowest vertex, its *pit*: the path
//! from the pit to where the depression used to spill is reversed.

use super::network::{after_channel_losses, SECONDS_PER_YEAR};
use super::relief::{Depressions, Flood, BREACH_DEPTH_M};
use crate::mesh::NONE;

/// The surplus at which an overflowing depression [`BREACH_DEPTH_M`] deep is breached (m³/yr).
const GORGE_FLOW_M3: f64 = 1.0e10;

/// Level of each depression's terminal lake, `None` where it overflows to the sea.
/// `runoff[v]` is the water a land vertex yields (m³/yr); `net_loss[v]` what open water at the
/// vertex loses, evaporation less precipitation (m³/yr, negative where rain exceeds it);
/// `channel_loss_mm[v]` what a river's floodplain loses there (mm/yr).
///
/// On its way, inside a depression too, a river loses water where it crosses dry land
/// ([`after_channel_losses`]), so a desert basin's terminal lake gets what its rivers still carry
/// when they reach it.
///
/// A depression that overflows with a surplus `Q` (m³/yr) is breached instead of kept as a
/// lake when it is at most `BREACH_DEPTH_M * sqrt(Q / 10 km³/yr)` deep: a river of that size
/// cuts a gorge through its dam (the Congo's through the Crystal Mountains, which a 9 km DEM
/// loses), so its depression is the map's artefact, not a lake. `dep.kept` records it.
pub fn terminal_levels(
    flood: &Flood,
    dep: &mut Depressions,
    runoff: &[f64],
    net_loss: &[f64],
    channel_loss_mm: &[f64],
) -> Vec<Option<f64>> {
    let n = flood.height.len();
    let count = dep.spill.len();
    // Each depression's vertices, lowest first.
    let mut members: Vec<Vec<u32>> = vec![Vec::new(); count];
    for v in 0..n {
        if dep.comp[v] != NONE {
            members[dep.comp[v] as usize].push(v as u32);
        }
    }
    for m in &mut members {
        m.sort_by(|&a, &b| flood.route[a as usize].total_cmp(&flood.route[b as usize]).then(a.cmp(&b)));
    }
    let mut acc: Vec<f64> = runoff.to_vec();
    let mut terminal = vec![None; count];
    for &v in flood.order.iter().rev() {
        let (vi, u) = (v as usize, flood.downstream[v as usize] as usize);
        let c = dep.comp[vi];
        if c != NONE && dep.root[c as usize] == v && dep.kept[c as usize] {
            let c = c as usize;
            let inflow = acc[vi];
            let mut loss = 0.0;
            let mut level = None;
            for (k, &w) in members[c].iter().enumerate() {
                loss += runoff[w as usize] + net_loss[w as usize];
                // A flat of the map (a lake's surface in the map) floods as one.
                let here = flood.route[w as usize];
                if members[c].get(k + 1).is_some_and(|&x| flood.route[x as usize] == here) {
                    continue;
                }
                if loss >= inflow {
                    // The lake covers this vertex and the ones below it.
                    level = Some(here);
                    break;
                }
            }
            match level {
                Some(l) => {
                    terminal[c] = Some(l);
                    acc[vi] = 0.0;
                }
                None => {
                    let surplus = inflow - loss;
                    let cut = BREACH_DEPTH_M * (surplus / GORGE_FLOW_M3).max(0.0).sqrt();
                    dep.kept[c] = dep.spill[c] - dep.floor[c] > cut;
                }
            }
        }
        // The channel loses water on its way where it crosses dry land (inside a depression too:
        // its rivers cross the basin's floor before they reach the lake).
        let lost_mm = channel_loss_mm.get(vi).copied().unwrap_or(0.0);
        acc[u] += after_channel_losses(acc[vi] / SECONDS_PER_YEAR, flood.edge_len[vi], lost_mm) * SECONDS_PER_YEAR;
    }
    terminal
}

/// Reverses the flood tree's path from each closed depression's pit to the vertex it drained
/// out through, so that the depression drains to its pit, which then drains nowhere. Returns
/// the vertices the depressions drained into before (one each), and the new downstream-first
/// order of the vertices that drain somewhere.
pub fn drain_to_pits(
    downstream: &mut [u32],
    down_edge: &mut [u32],
    order: &[u32],
    dep: &Depressions,
    terminal: &[Option<f64>],
) -> (Vec<u32>, Vec<u32>) {
    let mut outlets = Vec::new();
    for c in (0..terminal.len()).filter(|&c| terminal[c].is_some()) {
        let (pit, root) = (dep.pit[c], dep.root[c]);
        let mut path = vec![pit];
        while *path.last().unwrap_or(&pit) != root {
            path.push(downstream[*path.last().unwrap_or(&pit) as usize]);
        }
        outlets.push(downstream[root as usize]);
        let edges: Vec<u32> = path.iter().map(|&v| down_edge[v as usize]).collect();
        for i in (1..path.len()).rev() {
            downstream[path[i] as usize] = path[i - 1];
            down_edge[path[i] as usize] = edges[i - 1];
        }
        downstream[pit as usize] = NONE;
        down_edge[pit as usize] = NONE;
    }
    // Downstream first: by the number of edges to the coast or a pit.
    let mut depth = vec![u32::MAX; downstream.len()];
    let mut stack = Vec::new();
    for &v in order {
        let mut x = v;
        while depth[x as usize] == u32::MAX && downstream[x as usize] != NONE {
            stack.push(x);
            x = downstream[x as usize];
        }
        let mut d = if depth[x as usize] == u32::MAX { 0 } else { depth[x as usize] };
        depth[x as usize] = d;
        while let Some(y) = stack.pop() {
            d += 1;
            depth[y as usize] = d;
        }
    }
    let mut new_order: Vec<u32> = order.iter().copied().filter(|&v| downstream[v as usize] != NONE).collect();
    new_order.sort_by_key(|&v| depth[v as usize]);
    (outlets, new_order)
}

#[cfg(test)]
mod tests {
    use super::super::relief::{depressions, levels};
    use super::*;

    /// A coast (0), a 300 m pass (1), and a basin of four vertices 10 km apart whose floor is
    /// vertex 3 at 100 m: the flood reaches 2..5 over the pass, so they drain 5 -> 4 -> 3 -> 2 -> 1.
    fn basin(runoff_each: f64, loss_each: f64) -> (Vec<Option<f64>>, Vec<u32>, Vec<u32>, Vec<f64>) {
        let route = [0.0, 300.0, 150.0, 100.0, 200.0, 250.0];
        let order: Vec<u32> = (1..6).collect();
        let mut downstream: Vec<u32> = vec![NONE, 0, 1, 2, 3, 4];
        let mut down_edge: Vec<u32> = vec![NONE, 0, 1, 2, 3, 4];
        let edge_len = vec![10_000.0; 6];
        let area = vec![1.0e8; 6];
        let terrain = Flood {
            order: &[],
            downstream: &[],
            edge_len: &edge_len,
            route: &route,
            height: &route,
            area: &area,
            min_lake_area_m2: 1.5e8,
            river_slope: 1.0e-5,
        };
        let flood = Flood { order: &order, downstream: &downstream, ..terrain };
        let mut dep = depressions(&flood);
        assert_eq!((dep.spill.len(), dep.pit[0], dep.root[0]), (1, 3, 2));
        let runoff = vec![runoff_each; 6];
        let loss = vec![loss_each; 6];
        let terminal = terminal_levels(&flood, &mut dep, &runoff, &loss, &[]);
        let (outlets, new_order) = drain_to_pits(&mut downstream, &mut down_edge, &order, &dep, &terminal);
        let flood = Flood { order: &new_order, downstream: &downstream, ..terrain };
        let l = levels(&flood, &dep, &terminal);
        assert_eq!(outlets.len(), terminal.iter().flatten().count());
        (terminal, downstream, new_order, l.water)
    }

    #[test]
    fn a_wet_basin_overflows_to_the_sea() {
        // Rain on the lake exceeds its evaporation.
        let (terminal, downstream, _, water) = basin(1.0e7, -1.0e6);
        assert_eq!(terminal, vec![None]);
        assert_eq!(downstream[3], 2);
        assert!((water[3] - 300.0).abs() < 0.1, "lake at the pass: {}", water[3]);
    }

    #[test]
    fn a_dry_basin_ends_in_a_terminal_lake_at_its_pit() {
        // Four vertices yield 4 units; open water loses 3 per vertex besides its own runoff:
        // the lake covers the pit only (4 units lost at the second vertex: 2 * (1 + 3) >= 4).
        let (terminal, downstream, order, water) = basin(1.0, 3.0);
        let level = terminal[0].expect("closed");
        assert!((100.0..150.0).contains(&level), "{level}");
        assert_eq!(downstream[3], NONE, "the pit drains nowhere");
        assert_eq!((downstream[2], downstream[4], downstream[5]), (3, 3, 4));
        assert!(!order.contains(&3));
        // Water falls to the pit from both sides; the pass drains to the sea on its own.
        assert!(water[2] > water[3] && water[4] > water[3] && water[5] > water[4]);
        assert!(water[1] > 0.0 && water[1] <= 300.0);
    }
}
