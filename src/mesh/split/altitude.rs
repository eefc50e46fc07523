//! Altitudes of a vertex made by a split during adaption (paper §5.3 step 6, eq. 10–12): sea
//! floor, coast, river (interpolated), and continent vertices bounded by the riverbed and slope
//! rules, or made the spring of a new river arm.
//!
//! Everything here is a function of the split's diamond (its edge, faces and four corners) and
//! the new vertex's seed, so the same edge always yields the same vertex.

use super::landform::{landform_ground, landform_parts, sea_floor_ground, SEA_DETAIL};
use super::position::{
    altitude_random, corner_directions, lift, split_position, split_seed, tangent_along, tangent_towards,
    weighted_position, well_shaped_towards,
};
use super::split_kinds;
use crate::mesh::guide::Guide;
use crate::mesh::{Diamond, EdgeKind, Tangent, Vertex, VertexFlags};
use crate::params::Params;
use crate::rng::{salt, unit};
use glam::DVec3;

/// [`sea_roughness`]: the sea floor's offset range per metre of a short edge, and the edge
/// length at which it has flattened to half of that.
pub const SEA_ROUGHNESS: f64 = 0.02;
pub const SEA_ROUGHNESS_LENGTH: f64 = 50_000.0;

/// Full range of the random offset a sea split adds to the mean of its edge's ends: 2 % of the
/// edge (the paper's rule) for short edges, flattening to ~1,000 m for long ones. (Unflattened,
/// the splits of a coarse base mesh's 1,000 km edges piled up a sea floor 16 km deep.)
pub fn sea_roughness(edge_len: f64) -> f64 {
    SEA_ROUGHNESS * edge_len / (1.0 + edge_len / SEA_ROUGHNESS_LENGTH)
}
/// [`land_roughness`]: the offset range per metre of a short edge, and the edge length at which
/// it has flattened to half of that.
pub const LAND_ROUGHNESS: f64 = 0.15;
pub const LAND_ROUGHNESS_LENGTH: f64 = 2000.0;

/// Full range of the random offset a continent split adds to the mean of its four neighbours:
/// 15 % of the edge length for short edges, flattening to ~300 m for long ones, so relief grows
/// with detail but coarse splits cannot pile up kilometres of noise. The paper only asks for "a
/// random value inside the bounds"; this is our choice, documented.
pub fn land_roughness(edge_len: f64) -> f64 {
    LAND_ROUGHNESS * edge_len / (1.0 + edge_len / LAND_ROUGHNESS_LENGTH)
}

/// Eq. 11: the lowest ground a vertex `le` metres (horizontally) from the wet vertex `v` may
/// have — up the riverbed at `s_rb`, or `epsilon_rb` above the water plus `s_p`, whichever is
/// lower.
pub fn riverbank_floor(v: &Vertex, le: f64, p: &Params) -> f64 {
    (v.ground + le * p.riverbed_slope()).min(v.water + p.riverbed_edge_height_m + le * p.near_river_slope())
}

/// Whether the bank of the wet vertex `v` (eq. 11's floor `le` metres from it, and its water's
/// cover) gives way at a vertex where an elevation map shows the ground at `map` (m above the
/// base sphere): a river's (not a lake's or the sea's) does where the map is below the floor.
/// The base mesh's rivers run at its vertices only, and a vertex between a river high on a
/// plateau's rim and the foot of its escarpment, or across a divide from it, is not on that
/// river's bank; lifting it onto the river's water (the paper's rule) would smear every front
/// and terrace the land beside every river.
pub fn bank_gives_way(v: &Vertex, le: f64, map: Option<f64>, p: &Params) -> bool {
    v.flags.contains(VertexFlags::RIVER)
        && !v.flags.contains(VertexFlags::LAKE)
        && map.is_some_and(|m| m < riverbank_floor(v, le, p))
}

/// The altitude that minimises the steepest slope towards neighbours at `(ground, horizontal
/// distance)`: the bounds `ground ± k distance` meet for the smallest `k` at which the tightest
/// pair touches (in one dimension, intervals that meet pairwise meet all together), and that
/// point is the answer. Between two neighbours it interpolates, so a split of an edge steeper
/// than s_g halves its height instead of copying one end's altitude. Neighbours all at one
/// altitude give that altitude.
fn least_steep(neighbours: &[(f64, f64); 4]) -> f64 {
    let mut best = (f64::MIN, neighbours[0].0);
    for &(gi, li) in neighbours {
        for &(gj, lj) in neighbours {
            if gi > gj {
                let k = (gi - gj) / (li + lj).max(f64::MIN_POSITIVE);
                if k > best.0 {
                    best = (k, gi - k * li);
                }
            }
        }
    }
    best.1
}

/// The new vertex of a split during adaption, with the kinds of `[e1, e2, e3, e4]`; `guide`
/// is the planet's elevation map, if it has one (see [`super::guide`]).
pub fn split_vertex(d: &Diamond, p: &Params, guide: Option<&Guide>) -> (Vertex, [EdgeKind; 4]) {
    let seed = split_seed(d);
    let [f1, f2] = d.edge.face_kinds();
    let kinds = split_kinds(d.edge.kind, f1, f2);
    match d.edge.kind {
        EdgeKind::Continent => continent_vertex(d, p, guide, seed, kinds),
        kind => wet_vertex(d, p, guide, seed, split_position(d, seed, kind, p.min_river_length_m), kinds),
    }
}

/// Sea, coast and river splits (§5.3 step 6): the sea floor below sea level and a coast point
/// near it by midpoint displacement, or, under an elevation map, both by the sea floor's rule
/// (`guided_sea_floor`) on the side of sea level the map has at the new vertex (a sea split may
/// stand dry above it); or the river interpolated between its ends.
pub fn wet_vertex(
    d: &Diamond,
    p: &Params,
    guide: Option<&Guide>,
    seed: u32,
    pos: DVec3,
    kinds: [EdgeKind; 4],
) -> (Vertex, [EdgeKind; 4]) {
    let edge = &d.edge;
    let (va, vb) = (d.a(), d.b());
    let xi = altitude_random(seed);
    let sea = p.sea_level_m;
    let mid_ground = (va.ground + vb.ground) * 0.5;
    let (ground, water, flags) = match edge.kind {
        EdgeKind::Sea | EdgeKind::Coast => {
            // Under an elevation map, the shore is the map's: a sea or shore split takes the
            // sea floor's rule and stands on the side of sea level the map has at it, so that
            // the coast follows the map's zero contour below the base mesh's coast edges (tens
            // to hundreds of kilometres long) instead of running along them. Without a map (or
            // off a regional one) the paper's rules: the sea floor by the mean of the edge's
            // ends plus a random offset, the shore near sea level.
            let mapped = guide.and_then(|g| {
                let dir = pos.normalize();
                g.at(dir).map(|m| (g, dir, m))
            });
            let g = match mapped {
                Some((map, dir, m)) => {
                    let floor = guided_sea_floor(d, map, dir, d.edge_length(), m, seed, p);
                    if m < 0.0 {
                        floor.min(sea - 1.0)
                    } else {
                        floor.max(sea + 1.0)
                    }
                }
                None if edge.kind == EdgeKind::Sea => {
                    (mid_ground + (xi - 0.5) * sea_roughness(d.edge_length())).min(sea - 1.0)
                }
                None => coast_ground(d, xi, p),
            };
            (g, sea, VertexFlags::empty())
        }
        _ => {
            let w = (va.water + vb.water) * 0.5;
            // Between two vertices under a lake, the river runs under it too.
            let lake = VertexFlags(va.flags.0 & vb.flags.0 & VertexFlags::LAKE.0);
            (mid_ground.min(w), w, VertexFlags(VertexFlags::RIVER.0 | lake.0))
        }
    };
    let mut v = Vertex::new(lift(pos, d.radius, ground), seed);
    v.ground = ground;
    v.water = water;
    v.flags = flags | VertexFlags::REFINED;
    if edge.kind == EdgeKind::River {
        let (up, down) = if va.water >= vb.water { (va, vb) } else { (vb, va) };
        // Downstream along the split edge, in the new vertex's own tangent plane.
        v.tangent = Tangent::new(tangent_along(v.p(), down.p() - up.p()));
    }
    (v, kinds)
}

/// The sea floor a split under an elevation map takes at unit direction `dir`, where the map
/// reads `m` metres (sea, shore and flooded land splits): the map's where it resolves the split
/// edge; on a shore ([`straddles`]) the map's plus the landform's offset within
/// [`shore_offset`]; elsewhere below its pixel, the landform's detail at [`SEA_DETAIL`] of the
/// land's, shelves and abyssal plains flat, continental slopes, ridges and trenches rough (the
/// paper's 2 % of the edge everywhere put tens of metres of relief on flat shelves the map
/// shows a few metres deep), bent as the map's smooth surface (`Guide::bend`).
fn guided_sea_floor(d: &Diamond, g: &Guide, dir: DVec3, len: f64, m: f64, seed: u32, p: &Params) -> f64 {
    let sea = p.sea_level_m;
    if len >= g.min_edge_m {
        return sea + m;
    }
    let corners = [d.a(), d.t(), d.b(), d.d()].map(|v| v.ground);
    let map = [g.relief_at(dir), g.min_edge_m];
    if straddles(d, sea) {
        let [_, _, offset] = landform_parts(corners, len, seed, sea, p.ground_slope(), map);
        return (sea + m) + shore_offset(SEA_DETAIL * offset, m);
    }
    let bend = if g.bends(len) {
        let [a, b, t, e] = corner_directions(d);
        g.bend(dir, [a, t, b, e], len)
    } else {
        0.0
    };
    sea_floor_ground(corners, len, seed, sea, p.ground_slope(), map) + bend
}

/// A shore point without a map: the mean of its ends plus an offset of at most a riverbank's
/// height that shrinks with the edge (refining a shore flattens it instead of keeping
/// metre-high steps over ever shorter distances), no higher than a riverbank above sea level
/// and no deeper than a river mouth's bed, so that the shore beside a mouth deepens towards it
/// (an estuary) instead of standing as a wall over its bed.
fn coast_ground(d: &Diamond, xi: f64, p: &Params) -> f64 {
    let sea = p.sea_level_m;
    let mid_ground = (d.a().ground + d.b().ground) * 0.5;
    let rough = p.riverbed_edge_height_m.min(land_roughness(d.edge_length()));
    (mid_ground + (xi - 0.5) * rough).clamp(sea - p.max_river_depth_m, sea + p.riverbed_edge_height_m)
}

/// Whether the diamond's corners lie on both sides of sea level (some above it, some at or
/// below it): a split there, under an elevation map, takes the map's ground plus the
/// landform's random offset (not the diamond's mean, its ridge term or the map's bend), so
/// that the shore between the vertices, interpolated, runs where the map's does (from the
/// diamond's mean, a vertex a few metres from the shore on the map could stand hundreds of
/// metres off it, kept on its side of sea level at 1 m, and the shore snapped to the vertices
/// in a sawtooth).
fn straddles(d: &Diamond, sea: f64) -> bool {
    let corners = [d.a(), d.t(), d.b(), d.d()];
    corners.iter().any(|v| v.ground > sea) && corners.iter().any(|v| v.ground <= sea)
}

/// The landform's `offset` at a shore split where the map reads `m` metres: within half the
/// map's height above (or depth below) sea level, so that the detail fades towards the shore
/// and no vertex near it jumps across sea level (pinned there at 1 m, the shore between it and
/// its neighbours zigzagged with the vertices).
fn shore_offset(offset: f64, m: f64) -> f64 {
    let reach = 0.5 * m.abs();
    offset.clamp(-reach, reach)
}

/// Whether `v` stands in the sea (or on its shore, at its level): its water is the sea's and
/// no river's or lake's, and the ground is at most at sea level.
pub fn at_sea(v: &Vertex, sea: f64) -> bool {
    !v.flags.intersects(VertexFlags(VertexFlags::RIVER.0 | VertexFlags::LAKE.0)) && v.water == sea && v.ground <= sea
}

/// A continent split: ground altitude by midpoint displacement kept inside the riverbed bounds
/// (eq. 11) and the maximum ground slope (eq. 12); or, where the rules allow it, the spring of a
/// new river arm flowing into a neighbouring river vertex (eq. 10); or, under an elevation map
/// that shows the sea there beside the sea, a flooded sea-floor vertex (`guided_sea_floor`).
fn continent_vertex(
    d: &Diamond,
    p: &Params,
    guide: Option<&Guide>,
    seed: u32,
    mut kinds: [EdgeKind; 4],
) -> (Vertex, [EdgeKind; 4]) {
    let around = [d.a(), d.t(), d.b(), d.d()]; // the far ends of e1, e2, e3, e4
    let r = d.radius;
    // Eq. 2's position (see `split_position`) and its direction, from which the horizontal
    // distances to the neighbours (on the base sphere) and the lift of eq. 1 follow.
    let corners = corner_directions(d);
    let (_, dir) = well_shaped_towards(d, &corners, weighted_position(d, seed));
    let lens = [0, 2, 1, 3].map(|i| dir.distance(corners[i]) * r);
    // Eq. 1 (`lift`) for the direction at hand.
    let lifted = |g: f64| dir * (r + g);
    // A lake's bed: between two vertices under a lake the new vertex lies under it too, on the
    // mean of their beds (eq. 11's banks hold for rivers, not inside a lake).
    let (a, b) = (around[0], around[2]);
    if a.flags.contains(VertexFlags::LAKE) && b.flags.contains(VertexFlags::LAKE) {
        let surface = a.water.max(b.water);
        let g = ((a.ground + b.ground) * 0.5).min(surface);
        let mut v = Vertex::new(lifted(g), seed);
        v.ground = g;
        v.water = surface;
        v.flags = VertexFlags(VertexFlags::LAKE.0 | VertexFlags::REFINED.0);
        return (v, kinds);
    }
    let is_wet = |v: &Vertex| v.flags.contains(VertexFlags::RIVER) || v.submerged();
    // Under an elevation map, a river's bank gives way where the map shows lower ground.
    let map_m = guide.and_then(|g| g.at(dir));
    let at_map = map_m.map(|m| p.sea_level_m + m);
    // Under a map, the sea is no riverbank, and a split the map puts under the sea beside the
    // sea (or its shore) is under it: a bay the map has inside a land face of the base mesh
    // floods from its shore (an inland depression below sea level stays dry).
    let sea = p.sea_level_m;
    let by_sea = map_m.is_some() && around.iter().any(|v| at_sea(v, sea));
    let floods = by_sea && map_m.is_some_and(|m| m < 0.0);
    // A wet neighbour whose water covers the new vertex if it lies below it (the sea too), and
    // the ones whose banks bound it from below (not the sea's, under a map).
    let covers = |v: &Vertex, le: f64| is_wet(v) && !bank_gives_way(v, le, at_map, p);
    let holds = |v: &Vertex, le: f64| covers(v, le) && !(by_sea && at_sea(v, sea));

    // Eq. 11 (riverbanks) and 12 (slopes) give bounds from the neighbours; land stays above
    // sea level unless the slope bound wins. Eq. 11's floor is taken from the highest of the
    // wet neighbours (the paper's minimum would leave a bank under a higher river's floor).
    // Beyond the paper, the ground may not rise faster than s_g from a wet
    // neighbour's bed either (eq. 11 only bounds it from below): without that ceiling a bank
    // could stand any height above its river, and splitting such a wall copies its height to
    // the new vertex on the dry side, so the wall never shortens and refines without end.
    let mut bank_lo = sea + 1.0;
    let mut slope_lo = f64::MIN;
    let mut any_lo = f64::MIN;
    let mut hi = f64::MAX;
    for (v, le) in around.iter().zip(lens) {
        let below = v.ground - le * p.ground_slope();
        if holds(v, le) {
            bank_lo = bank_lo.max(riverbank_floor(v, le, p));
        } else {
            slope_lo = slope_lo.max(below);
        }
        any_lo = any_lo.max(below);
        hi = hi.min(v.ground + le * p.ground_slope());
    }
    let edge_len = d.edge_length();

    // A flooded split is a sea split: the sea floor's rule (the map's ground, or below its pixel
    // the sea's landform from the corners, bent as the map's surface), under sea level, without
    // the land's slope bounds (with them, the land's mean: a base land face reaching over the
    // map's deep sea flooded a metre deep, 1-2 km above the sea floor the map shows).
    if let (true, Some(map), Some(m)) = (floods, guide, map_m) {
        let g = guided_sea_floor(d, map, dir, edge_len, m, seed, p).min(sea - 1.0);
        let mut v = Vertex::new(lifted(g), seed);
        v.ground = g;
        v.water = sea;
        v.flags = VertexFlags::REFINED;
        return (v, kinds);
    }

    // Eq. 10: a new river arm, when the split edge and the new edge to a river vertex are both
    // at least l_rmin long and an altitude exists above that river (by s_r) yet below every dry
    // neighbour's bank; the spring is drawn from the lower half of that range (our choice, so
    // that arms start low rather than at the banks' tops).
    if edge_len >= p.min_river_length_m {
        let mut cap = f64::MAX;
        for (v, le) in around.iter().zip(lens) {
            if !is_wet(v) {
                cap = cap.min(
                    v.ground - (le * p.riverbed_slope()).min(p.riverbed_edge_height_m + le * p.near_river_slope()),
                );
            }
        }
        let best = (0..4)
            .filter(|&i| around[i].flags.contains(VertexFlags::RIVER) && lens[i] >= p.min_river_length_m)
            .map(|i| (i, around[i].water + lens[i] * p.river_slope()))
            .filter(|&(_, floor)| floor < cap && floor < p.max_river_altitude_m)
            .min_by(|x, y| x.1.total_cmp(&y.1).then(x.0.cmp(&y.0)));
        if let Some((i, floor)) = best {
            let top = cap.min(p.max_river_altitude_m);
            let g = floor + (top - floor) * unit(seed, salt::RIVER) * 0.5;
            kinds[i] = EdgeKind::River;
            let mut v = Vertex::new(lifted(g), seed);
            v.ground = g;
            v.water = g;
            v.flags = VertexFlags::RIVER | VertexFlags::REFINED;
            v.tangent = Tangent::new(tangent_towards(v.p(), around[i].p()));
            return (v, kinds);
        }
    }

    // Where the planet's elevation map resolves the split edge, its ground; on a shore beside
    // the sea, its ground plus a bounded offset; elsewhere below its pixel (or without a map),
    // the neighbours' mean plus the landform's offset.
    let mapped = guide.filter(|g| edge_len >= g.min_edge_m).and(at_map);
    let wanted = match mapped {
        Some(m) => m,
        None => {
            let map = guide.map_or([0.0; 2], |g| [g.relief_at(dir), g.min_edge_m]);
            let grounds = around.map(|v| v.ground);
            match map_m.filter(|_| by_sea && straddles(d, sea)) {
                // On a shore beside the sea, the map's ground plus the landform's offset.
                Some(m) => {
                    let [_, _, offset] = landform_parts(grounds, edge_len, seed, sea, p.ground_slope(), map);
                    (sea + m) + shore_offset(offset, m)
                }
                None => {
                    let ground = landform_ground(grounds, edge_len, seed, sea, p.ground_slope(), map);
                    // Under a map, its smooth surface bends the diamond's mean: crests below the
                    // map's pixel round up, valleys down, as the map's cubic surface does.
                    let [ca, cb, ct, cd] = corners;
                    guide.map_or(ground, |g| ground + g.bend(dir, [ca, ct, cb, cd], edge_len))
                }
            }
        }
    };
    let lo = bank_lo.max(slope_lo);
    let g = if any_lo > hi {
        // The neighbours (wet ones included) are steeper than s_g across the diamond, or the
        // split edge itself is: no altitude satisfies eq. 12, so take the one whose steepest
        // edge is least steep.
        least_steep(&std::array::from_fn(|i| (around[i].ground, lens[i])))
    } else if lo <= hi {
        wanted.clamp(lo, hi.min(p.max_mountain_altitude_m.max(lo)))
    } else {
        // A riverbank (or sea level) asks for more than the slope allows: the slope wins and
        // the vertex may end up under the river's water (below).
        hi
    };
    // Water: a vertex below a wet neighbour's water surface lies in that river's channel (eq.
    // 11 lets a bank near a deep river sit below the surface) or lake and is covered up to the
    // highest such surface; otherwise it is dry (so is one below a river whose bank gave way
    // to the map: it lies off that river's valley). (The paper averages the four neighbours'
    // water levels, which leaves a vertex below one river's surface dry when the others are
    // lower.)
    let surface =
        around.iter().zip(lens).filter(|(v, le)| covers(v, *le)).map(|(v, _)| v.water).fold(f64::MIN, f64::max);
    let water = if g < surface { surface } else { g };
    let mut v = Vertex::new(lifted(g), seed);
    v.ground = g;
    v.water = water;
    v.flags = VertexFlags::REFINED;
    (v, kinds)
}

#[cfg(test)]
mod tests {
    use super::{least_steep, riverbank_floor, split_vertex};
    use crate::geo::direction;
    use crate::maps::{GeoBounds, Map, MapKind};
    use crate::mesh::guide::Guide;
    use crate::mesh::{Diamond, Edge, EdgeKind, Face, Lod, SplitSite, Vertex, VertexFlags};
    use crate::params::Params;

    /// A continent diamond ~7 km across at (0°, 0°): the split edge `a -> b` runs east, `a` a
    /// river vertex `river` metres above sea level, the other corners dry ground 400 m up.
    fn beside_a_river(p: &Params, river: f64) -> Diamond {
        let r = p.radius_m;
        let at = |lat: f64, lon: f64, ground: f64| {
            let mut v = Vertex::new(direction(lat, lon) * (r + ground), 0);
            v.ground = ground;
            v.water = ground;
            v
        };
        let sea = p.sea_level_m;
        let mut a = at(0.0, -0.03, sea + river - 5.0);
        a.water = sea + river;
        a.flags = VertexFlags::RIVER;
        Diamond {
            site: SplitSite { edge: 0, a: 0, b: 1, t: 2, d: 3, f1: 0, f2: 1 },
            edge: Edge { v: [0, 1], f: [0, 1], lod: Lod::default(), level: 0, kind: EdgeKind::Continent, land: 3 },
            faces: [Face { e: [0, 1, 2] }, Face { e: [0, 3, 4] }],
            corners: [a, at(0.0, 0.03, sea + 400.0), at(0.03, 0.0, sea + 400.0), at(-0.03, 0.0, sea + 400.0)],
            radius: r,
        }
    }

    /// A regional elevation map of 0.1° pixels, `metres` everywhere.
    fn flat_map(p: &Params, metres: f32) -> Guide {
        let b = GeoBounds { west: -1.0, south: -1.0, east: 1.0, north: 1.0 };
        let map = Map::from_values(MapKind::Elevation, 20, 20, b, vec![metres; 400]).unwrap();
        Guide::from_map(&map, p.radius_m).unwrap()
    }

    #[test]
    fn a_riverbank_gives_way_where_the_map_has_lower_ground() {
        let p = Params::earth();
        // A river 1,000 m up beside ground 400 m up: without a map, eq. 11 lifts the new vertex
        // onto the river's bank.
        let d = beside_a_river(&p, 1_000.0);
        let bank = |v: &Vertex| {
            let le = v.p().normalize().distance(d.a().p().normalize()) * p.radius_m;
            riverbank_floor(d.a(), le, &p)
        };
        let (free, _) = split_vertex(&d, &p, None);
        assert!(free.ground >= bank(&free) - 1e-9 && free.ground > p.sea_level_m + 1_000.0, "{}", free.ground);
        // A map showing the ground 400 m up: the vertex takes the landform's value (the
        // corners' mean, 549 m, plus at most ~320 m of ridge and offset), below the river's
        // water, and stays dry, off the river's valley (the river is on a rim above it).
        let low = flat_map(&p, 400.0);
        let (v, _) = split_vertex(&d, &p, Some(&low));
        assert!(v.ground < d.a().water - 100.0, "{}", v.ground);
        assert_eq!(v.water, v.ground, "dry below the rim");
        // A map showing the ground above the bank: the bank holds (the landform's mean of the
        // corners is lower still).
        let high = flat_map(&p, 1_200.0);
        let (v, _) = split_vertex(&d, &p, Some(&high));
        assert!(v.ground >= bank(&v) - 1e-9, "{} under the bank {}", v.ground, bank(&v));
    }

    /// The sea split of a diamond ~7 km across at (0°, 0°) whose corners stand at the sea floor
    /// `floor` metres below sea level, `[a, t, b, d]`, under `guide`, for vertex seed `seed`.
    fn sea_split(p: &Params, floor: [f64; 4], guide: Option<&Guide>, seed: u32) -> f64 {
        let r = p.radius_m;
        let at = |lat: f64, lon: f64, depth: f64| {
            let ground = p.sea_level_m - depth;
            let mut v = Vertex::new(direction(lat, lon) * (r + ground), seed);
            v.ground = ground;
            v.water = p.sea_level_m;
            v
        };
        let d = Diamond {
            site: SplitSite { edge: 0, a: 0, b: 1, t: 2, d: 3, f1: 0, f2: 1 },
            edge: Edge { v: [0, 1], f: [0, 1], lod: Lod::default(), level: 0, kind: EdgeKind::Sea, land: 0 },
            faces: [Face { e: [0, 1, 2] }, Face { e: [0, 3, 4] }],
            corners: [
                at(0.0, -0.03, floor[0]),
                at(0.0, 0.03, floor[2]),
                at(0.03, 0.0, floor[1]),
                at(-0.03, 0.0, floor[3]),
            ],
            radius: r,
        };
        split_vertex(&d, p, guide).0.ground - p.sea_level_m
    }

    #[test]
    fn a_shelf_below_the_maps_pixel_stays_flat_and_a_slope_rough() {
        let p = Params::earth();
        let spread = |floor: [f64; 4], guide: Option<&Guide>| {
            let g: Vec<f64> = (0..200).map(|seed| sea_split(&p, floor, guide, seed)).collect();
            let lo = g.iter().copied().fold(f64::MAX, f64::min);
            (lo, g.iter().copied().fold(f64::MIN, f64::max) - lo)
        };
        // A shelf 60 m deep that the map (0.1° pixels, 11 km) shows flat: the sea floor keeps
        // within a few metres of it (the paper's rule spreads 2 % of the 6.7 km edge, ~130 m).
        let shelf = flat_map(&p, -60.0);
        let (_, flat) = spread([60.0; 4], Some(&shelf));
        assert!(flat < 5.0, "a flat shelf spreads {flat} m");
        let (_, paper) = spread([60.0; 4], None);
        assert!(paper > 100.0, "off the map, the paper's rule: {paper} m");
        // A continental slope falling 1,000 m across the diamond gains relief, at most
        // `SEA_DETAIL` of what land of that relief would, and stays under the sea.
        let (deepest, steep) = spread([500.0, 1_000.0, 1_500.0, 1_000.0], Some(&shelf));
        assert!(steep > 20.0 * flat.max(1.0), "a slope spreads {steep} m against the shelf's {flat} m");
        assert!(deepest > -1_600.0, "{deepest}");
    }

    #[test]
    fn under_a_map_the_coast_follows_the_map() {
        let p = Params::earth();
        let sea = p.sea_level_m;
        // Sea splits (corners 60 m deep) where the map shows land 50 m up stand above sea level,
        // dry; where it shows sea, below it.
        let land = flat_map(&p, 50.0);
        for seed in 0..50 {
            assert!(sea_split(&p, [60.0; 4], Some(&land), seed) >= 1.0, "seed {seed}");
            assert!(sea_split(&p, [60.0; 4], Some(&flat_map(&p, -5.0)), seed) <= -1.0, "seed {seed}");
        }
        // Without a map, the sea floor stays under the sea.
        assert!(sea_split(&p, [60.0; 4], None, 7) <= -1.0);
        // A land split beside the sea (`a` under it, at its level) where the map shows the sea
        // floor 30 m down floods at sea level; one whose corners are all dry stays dry, above
        // sea level (a depression the sea does not reach).
        let mut d = beside_a_river(&p, 0.0);
        for v in &mut d.corners {
            v.ground = sea + 5.0;
            v.water = v.ground;
        }
        let dry = d;
        d.corners[0].flags = crate::mesh::VertexFlags::SEA;
        d.corners[0].ground = sea - 20.0;
        d.corners[0].water = sea;
        let bay = flat_map(&p, -30.0);
        let (v, _) = split_vertex(&d, &p, Some(&bay));
        assert!(v.ground <= sea - 1.0 && v.water == sea, "{} / {}", v.ground - sea, v.water - sea);
        let (v, _) = split_vertex(&dry, &p, Some(&bay));
        assert!(v.ground >= sea + 1.0 && v.water == v.ground, "{} / {}", v.ground - sea, v.water - sea);
        // Where the map shows land, the split beside the sea is land.
        let (v, _) = split_vertex(&d, &p, Some(&flat_map(&p, 20.0)));
        assert!(v.ground >= sea + 1.0 && v.water == v.ground, "{}", v.ground - sea);
    }

    #[test]
    fn least_steep_balances_the_steepest_pair() {
        // Between a neighbour 100 m up at 10 m and one at 0 m, 30 m away, the point at 75 m
        // climbs 2.5 m/m to both; the flat pair in between does not matter.
        let g = least_steep(&[(100.0, 10.0), (0.0, 30.0), (60.0, 50.0), (40.0, 50.0)]);
        assert!((g - 75.0).abs() < 1e-9, "{g}");
        // The order of the neighbours does not matter.
        assert_eq!(g, least_steep(&[(40.0, 50.0), (0.0, 30.0), (60.0, 50.0), (100.0, 10.0)]));
        // Neighbours at one altitude give that altitude.
        assert_eq!(least_steep(&[(-12.5, 3.0); 4]), -12.5);
    }
}
