//! Rivers on an elevation map drain downhill on it (beyond the paper's §4.2, whose networks
//! grow over synthetic terrain): the flood that grows the network is ordered by the lowest
//! ground around each vertex, and a vertex takes two tributaries, so a valley's water is often
//! drained through a vertex on the valley's side (a fifth of Jacksboro's river edges ran uphill
//! on the map, one in twenty by over 25 m); the relief levels would then carve that vertex down
//! to the valley, a trench across the spur. [`drain_downhill`] relinks such vertices.

use crate::mesh::{Adjacency, NONE};
use std::collections::BinaryHeap;

/// The river tree as `build_rivers` holds it: each inland vertex's downstream vertex and edge,
/// its count of tributaries, and the order of the network's vertices, downstream first.
pub struct Tree<'a> {
    pub downstream: &'a mut [u32],
    pub down_edge: &'a mut [u32],
    pub tributaries: &'a mut [u8],
    pub order: &'a mut Vec<u32>,
}

/// Which neighbours a tier of [`drain_downhill`] looks among, and which of them take one more
/// tributary.
type Among<'a> = &'a dyn Fn(u32) -> bool;
type Room<'a> = &'a dyn Fn(usize) -> bool;

/// What [`drain_downhill`] moved.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Drained {
    /// Vertices relinked to a lower neighbour.
    pub moved: usize,
    /// Of those, vertices that became a third tributary (every lower way out took two).
    pub third: usize,
    /// Of those, vertices relinked to a neighbour the flood reached after them (the order is
    /// then rebuilt, downstream first).
    pub against_flood: usize,
}

/// A vertex whose downstream stands higher (by `h`, the map at the vertex; 0 on the coast) than
/// itself drains instead to its lowest neighbour lower than that downstream: among those the
/// flood reached before it (or the coast) that take a tributary; failing that, one of them
/// that would take its third (inland only: a coast vertex keeps its one river, a mouth);
/// failing that, the same among those the flood reached after it that do not drain through
/// it. The paper merges more than two rivers in a vertex only where no alternative exists,
/// and draining uphill is none a river has. Where a vertex is relinked to one the flood
/// reached later, the order is rebuilt downstream first, keeping the flood's order wherever
/// the links allow it.
pub fn drain_downhill(adj: &Adjacency, coast: &[bool], h: &dyn Fn(u32) -> f64, tree: Tree<'_>) -> Drained {
    let Tree { downstream, down_edge, tributaries, order } = tree;
    let n = downstream.len();
    let mut rank = vec![u32::MAX; n];
    for (i, &v) in order.iter().enumerate() {
        rank[v as usize] = i as u32;
    }
    let mut drained = Drained::default();
    for (i, &v) in order.iter().enumerate() {
        let u = downstream[v as usize];
        if u == NONE || h(u) <= h(v) {
            continue;
        }
        let earlier = |w: u32| coast[w as usize] || rank[w as usize] < i as u32;
        let later = |w: u32| !coast[w as usize] && rank[w as usize] != u32::MAX && rank[w as usize] > i as u32;
        // Whether `w` drains through `v` (linking `v` to it would close a loop).
        let through_v = |w: u32, downstream: &[u32]| {
            let mut x = w;
            for _ in 0..n {
                if x == v {
                    return true;
                }
                if coast[x as usize] || downstream[x as usize] == NONE {
                    return false;
                }
                x = downstream[x as usize];
            }
            true
        };
        let lowest = |among: Among, room: Room, downstream: &[u32]| {
            let mut ways: Vec<(u32, u32)> =
                adj.around(v).filter(|&(w, _)| w != u && among(w) && room(w as usize) && h(w) < h(u)).collect();
            ways.sort_by(|x, y| h(x.0).total_cmp(&h(y.0)).then(x.0.cmp(&y.0)));
            ways.into_iter().find(|&(w, _)| !through_v(w, downstream))
        };
        let two = |w: usize| if coast[w] { tributaries[w] == 0 } else { tributaries[w] < 2 };
        let three = |w: usize| !coast[w] && tributaries[w] < 3;
        let tiers: [(Among, Room); 4] = [(&earlier, &two), (&earlier, &three), (&later, &two), (&later, &three)];
        let found =
            tiers.iter().enumerate().find_map(|(t, (among, room))| lowest(*among, *room, downstream).map(|w| (t, w)));
        if let Some((tier, (w, we))) = found {
            tributaries[u as usize] = tributaries[u as usize].saturating_sub(1);
            tributaries[w as usize] = tributaries[w as usize].saturating_add(1);
            downstream[v as usize] = w;
            down_edge[v as usize] = we;
            drained.moved += 1;
            drained.third += usize::from(tier % 2 == 1);
            drained.against_flood += usize::from(tier >= 2);
        }
    }
    if drained.against_flood > 0 {
        *order = downstream_first(order, downstream, &rank);
    }
    drained
}

/// The network's vertices downstream first, each as early as the links allow in the flood's
/// order `rank` (Kahn's algorithm taking the lowest rank ready): the flood's order itself
/// wherever it already runs downstream first.
fn downstream_first(order: &[u32], downstream: &[u32], rank: &[u32]) -> Vec<u32> {
    let (offsets, children) = super::network::upstream_lists(downstream);
    let in_order = |v: u32| rank[v as usize] != u32::MAX;
    let mut ready: BinaryHeap<std::cmp::Reverse<(u32, u32)>> = order
        .iter()
        .filter(|&&v| downstream[v as usize] == NONE || !in_order(downstream[v as usize]))
        .map(|&v| std::cmp::Reverse((rank[v as usize], v)))
        .collect();
    let mut out = Vec::with_capacity(order.len());
    while let Some(std::cmp::Reverse((_, v))) = ready.pop() {
        out.push(v);
        let r = offsets[v as usize] as usize..offsets[v as usize + 1] as usize;
        ready.extend(children[r].iter().map(|&c| std::cmp::Reverse((rank[c as usize], c))));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_floods_order_is_kept_where_it_runs_downstream_first() {
        // 0 is the coast; 1 <- 2 <- 3 and 1 <- 4 in the flood's order 1, 2, 3, 4.
        let downstream = [NONE, 0, 1, 2, 1];
        let order = [1, 2, 3, 4];
        let mut rank = vec![u32::MAX; 5];
        for (i, &v) in order.iter().enumerate() {
            rank[v as usize] = i as u32;
        }
        assert_eq!(downstream_first(&order, &downstream, &rank), order);
        // 2 relinked to 4, which the flood reached after it: 4 comes first.
        let downstream = [NONE, 0, 4, 2, 1];
        assert_eq!(downstream_first(&order, &downstream, &rank), [1, 4, 2, 3]);
    }
}
