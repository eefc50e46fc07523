//! Landform-dependent detail below the map's resolution (beyond the paper: Musgrave's hybrid
//! and ridged multifractals written as midpoint displacement, after Cortial et al. 2020's
//! amplification by landform). A continent split that no map resolves takes its diamond's mean
//! ground plus an offset whose size and sign follow the diamond's own landform:
//!
//! - **Relief.** The offset's range grows with the diamond's slope (its relief, highest corner
//!   less lowest, over the edge) times the edge, and with its altitude above the sea: mountains
//!   gain rugged detail (high plateaus more, with the square of their altitude), hills some,
//!   and plains, deltas and coastal lowlands little beyond a floor of a few metres at the
//!   scale of hillslopes (at most [`FLOOR_SLOPE`] `*` [`FLOOR_LENGTH`] metres, falling again
//!   beyond [`FLOOR_FADE`], and under an elevation map at most twice the map's roughness term
//!   below). Ground nearing the steepest slope allowed (eq. 12's `s_g`, by [`THRESHOLD`])
//!   gains less and at last none: a threshold hillslope, where landslides stop further
//!   steepening (and eq. 12 stays satisfiable). As one level's offsets steepen the diamonds of
//!   the next, roughness cascades as in a multifractal: steep ground grows steeper detail, flat
//!   ground stays flat.
//! - **The map's roughness.** Under an elevation map, the roughness of the map's pixel at the
//!   vertex (the twist of its bilinear patch, zero on planes: `Guide::relief_at`) adds
//!   [`MAP_RELIEF`] times itself at one pixel, falling with the square root of the edge: where
//!   the map is rugged, the ground stays rugged below its resolution, however gentle the
//!   diamond the splits have smoothed so far.
//! - **Hybrid.** The range is larger where the diamond's centre stands high in its own range
//!   than low in it ([`HYBRID`]): valley floors stay smooth, crests and summits rough (the hybrid
//!   multifractal weights each octave by the signal so far).
//! - **Ridged.** A split edge along a crest (its ends above the diamond's other two corners) is
//!   lifted further, one along a valley sunk further, by [`RIDGE`] of the difference, so crests
//!   sharpen and valleys deepen instead of rounding off.
//! - **Scale.** The range falls with the edge as real relief does below a map's pixel (the
//!   constants were fitted with `tools/landforms.py` against the Jacksboro 90 m DEM and crops of
//!   the Earth DEM: detail and median slope within the goals' ranges on most cases,
//!   docs/realism.md), and
//!   flattens for edges beyond [`RELIEF_LENGTH`], whose relief the base mesh already holds, and
//!   fades below [`SMOOTH_LENGTH`].
//!
//! Everything is a function of the four corners' ground, the edge's length, the sea level, the
//! map's pixel at the vertex and the vertex seed, with `+ - * /`, `sqrt`, `min`, `max` and `abs`
//! in `f64` only, so `split.wgsl`'s `landform_ground` gives the same bits, and views, tiles and
//! DEMs the same vertex whatever the path that made it.

use crate::rng::{salt, unit};

/// The floor's range per metre of a short edge (flat ground), the edge length at which it has
/// flattened to half of that, and the one beyond which it falls again (as one over the edge):
/// the floor is the roughness of flat ground at the scale of hillslopes; over tens of
/// kilometres a plain's relief is the map's and its slopes' business (a floor of ~120 m at
/// every level up to the base mesh added to the plains' shortest wavelengths, where the Great
/// Plains held 5.5 times the real power at 40-60 km).
pub const FLOOR_SLOPE: f64 = 0.3;
pub const FLOOR_LENGTH: f64 = 400.0;
pub const FLOOR_FADE: f64 = 5_000.0;
/// The relief term's range per metre of edge per unit of the diamond's slope.
pub const RELIEF: f64 = 1.6;
/// The relief term's range per metre of edge per metre of altitude above the sea, which grows
/// with the square of the altitude beyond [`ALTITUDE_LENGTH`]: 1.1 m per km of edge at 1,000 m
/// up, 33 m at 5,000 m. High plateaus are rough even where the map shows them flat, lowland
/// plains far less so: on the Earth DEM at 2048x1024 (20 km cells) the median slope is 181 m
/// per cell above 5 km in the Himalaya's crop and 65 m at 1-2 km in the Great Plains', while a
/// map of 80 km pixels resolves a smaller share of the plateau's relief (tools/landforms.py:
/// with a linear term the plateau's slopes came out 0.64 of the real ones, the foothills' 0.98).
pub const ALTITUDE: f64 = 0.9e-6;
pub const ALTITUDE_LENGTH: f64 = 2_000.0;
/// Weight of the relief term at the diamond's lowest point (`HYBRID + 1` at its highest).
pub const HYBRID: f64 = 0.5;
/// Edge length at which the whole range has flattened to half.
pub const RELIEF_LENGTH: f64 = 200_000.0;
/// The range per metre of the map's roughness within a pixel (`Guide::relief_at`), at an edge
/// one map pixel long; it falls with the square root of the edge below that. (3 since the base
/// mesh of an elevation map holds two map pixels per edge: with less relief cascading from
/// long edges, mountain slopes need more from the map's own roughness; 2 before.)
pub const MAP_RELIEF: f64 = 3.0;
/// The share of eq. 12's steepest slope `s_g` at which a diamond's detail has faded to nothing.
pub const THRESHOLD: f64 = 0.35;
/// Below about this edge length the range falls faster than the edge, so that the ground is
/// smooth at the scale of metres (soil-mantled hillslopes) instead of steepening without end
/// as views refine to centimetres.
pub const SMOOTH_LENGTH: f64 = 20.0;
/// How far a crest along the split edge is lifted (a valley sunk) beyond the diamond's mean,
/// per metre that the edge's ends stand above (below) the other two corners.
pub const RIDGE: f64 = 0.25;
/// The sea floor's detail below an elevation map's pixel as a share of the land's for the same
/// relief: sediment drapes the sea floor, and no rain cuts valleys into it. (With the land's
/// whole detail the Ligurian Sea's came out 1.3 times the real one and Norway's shelf 1.9 times
/// on the Earth DEM's crops; the paper's 2 % of the edge, before, put 4-12 times the real
/// relief on the North Sea's, the Gulf of Mexico's and Hudson Bay's shelves: docs/realism.md.)
pub const SEA_DETAIL: f64 = 0.5;

/// Full range of the offset at a continent split of an edge `edge_len` long whose diamond has
/// the ground `g` at `[a, t, b, d]` (the split edge runs `a -> b`), under an elevation map's
/// pixel whose roughness is `map[0]` metres and width `map[1]` metres (`[0, 0]` without a
/// map); also the diamond's mean and the share of the detail its steepness leaves (1 on flat
/// ground, 0 at a threshold hillslope).
pub fn landform_range(g: [f64; 4], edge_len: f64, sea: f64, max_slope: f64, map: [f64; 2]) -> (f64, f64, f64) {
    let [a, t, b, d] = g;
    let mean = ((a + b) * 0.5 + (t + d) * 0.5) * 0.5;
    let lo = a.min(t).min(b.min(d));
    let hi = a.max(t).max(b.max(d));
    // The diamond's relief over its diagonals (both about one edge long): a plane's gradient,
    // and a saddle's or a crest's steepness too.
    let slope = (hi - lo) / edge_len;
    // Where the diamond's mean stands in its range: 0 at its lowest corner, 1 at its highest.
    let height = if hi > lo { (mean - lo) / (hi - lo) } else { 0.5 };
    let floor = FLOOR_SLOPE * edge_len / (1.0 + edge_len / FLOOR_LENGTH) / (1.0 + edge_len / FLOOR_FADE);
    let up = (mean - sea).max(0.0);
    let high = up / ALTITUDE_LENGTH;
    let relief = edge_len * (RELIEF * slope + ALTITUDE * up * (1.0 + high * high)) * (HYBRID + height);
    // The map's own roughness within a pixel (`map[0]` metres, pixels `map[1]` metres wide),
    // carried down as real relief falls below a map's pixel: with the square root of the scale.
    // Under a map, the floor is no larger than twice what its roughness gives: ground the
    // map shows flat (the Amazon's) stays about as flat below its pixel.
    let (mapped, floor) = if map[1] > 0.0 {
        let mapped = MAP_RELIEF * map[0] * (edge_len / map[1]).sqrt();
        (mapped, floor.min(mapped + mapped))
    } else {
        (0.0, floor)
    };
    // Ground near the steepest slope allowed gains no more detail: a threshold hillslope.
    let threshold = (1.0 - slope / (THRESHOLD * max_slope)).max(0.0);
    let fade = edge_len / (edge_len + SMOOTH_LENGTH);
    ((floor + relief + mapped) * threshold / (1.0 + edge_len / RELIEF_LENGTH) * fade, mean, threshold)
}

/// The ground wanted at a continent split below the map's resolution: the diamond's mean, the
/// ridge term and the landform's random offset (triangular: the sum of two uniforms).
pub fn landform_ground(g: [f64; 4], edge_len: f64, seed: u32, sea: f64, max_slope: f64, map: [f64; 2]) -> f64 {
    let [mean, ridge, offset] = landform_parts(g, edge_len, seed, sea, max_slope, map);
    mean + ridge + offset
}

/// The sea floor wanted below the map's resolution (under an elevation map) at a sea or shore
/// split off the shore, or a land split the sea floods: the diamond's mean plus the land's ridge
/// term and offset at [`SEA_DETAIL`] of their size.
pub fn sea_floor_ground(g: [f64; 4], edge_len: f64, seed: u32, sea: f64, max_slope: f64, map: [f64; 2]) -> f64 {
    let [mean, ridge, offset] = landform_parts(g, edge_len, seed, sea, max_slope, map);
    mean + SEA_DETAIL * (ridge + offset)
}

/// [`landform_ground`]'s terms: the diamond's mean, the ridge term and the random offset
/// (triangular: the sum of two uniforms).
pub fn landform_parts(g: [f64; 4], edge_len: f64, seed: u32, sea: f64, max_slope: f64, map: [f64; 2]) -> [f64; 3] {
    let (range, mean, threshold) = landform_range(g, edge_len, sea, max_slope, map);
    let [a, t, b, d] = g;
    let ridge = (a + b) * 0.5 - (t + d) * 0.5;
    let n = unit(seed, salt::ALTITUDE) + unit(seed, salt::DETAIL) - 1.0;
    [mean, RIDGE * threshold * ridge, range * 0.5 * n]
}

#[cfg(test)]
mod tests {
    use super::*;

    const SEA: f64 = 3_000.0;
    const S_G: f64 = 1.0;

    #[test]
    fn steep_ground_gets_more_detail_than_flat_ground() {
        let len = 1_000.0;
        let (flat, ..) = landform_range([SEA + 100.0; 4], len, SEA, S_G, [0.0; 2]);
        let (hills, ..) = landform_range([SEA + 100.0, SEA + 130.0, SEA + 150.0, SEA + 120.0], len, SEA, S_G, [0.0; 2]);
        let (alps, ..) =
            landform_range([SEA + 1_500.0, SEA + 1_560.0, SEA + 1_620.0, SEA + 1_550.0], len, SEA, S_G, [0.0; 2]);
        assert!(flat < 100.0 && flat > 0.0, "{flat}");
        assert!(hills > 1.5 * flat, "{hills} vs {flat}");
        assert!(alps > 1.2 * hills, "{alps} vs {hills}");
        // A threshold hillslope gains nothing.
        let (cliff, ..) = landform_range([SEA, SEA + 200.0, SEA + 400.0, SEA + 200.0], len, SEA, S_G, [0.0; 2]);
        assert_eq!(cliff, 0.0);
        // A high plateau, flat on the map, is rougher than a lowland plain.
        let (tibet, ..) = landform_range([SEA + 4_500.0; 4], len, SEA, S_G, [0.0; 2]);
        assert!(tibet > 1.1 * flat, "{tibet} vs {flat}");
        // ... and the altitude term grows faster than the altitude: five times as high, more
        // than ten times the roughness.
        let (high, ..) = landform_range([SEA + 5_000.0; 4], len, SEA, S_G, [0.0; 2]);
        let (low, ..) = landform_range([SEA + 1_000.0; 4], len, SEA, S_G, [0.0; 2]);
        let (sea, ..) = landform_range([SEA; 4], len, SEA, S_G, [0.0; 2]);
        assert!(high - sea > 10.0 * (low - sea), "{high} {low} {sea}");
    }

    #[test]
    fn detail_falls_with_scale_and_flattens_for_long_edges() {
        let g = |len: f64| {
            // The same slope at every scale, about the same mean altitude.
            let half = 0.05 * len;
            landform_range(
                [SEA + 1_000.0 - half, SEA + 1_000.0 + half, SEA + 1_000.0 + half, SEA + 1_000.0 - half],
                len,
                SEA,
                S_G,
                [0.0; 2],
            )
            .0
        };
        assert!(g(100.0) < g(1_000.0) && g(1_000.0) < g(10_000.0));
        // Flattened beyond RELIEF_LENGTH: a 2,000 km edge gains less than ten times a 200 km one.
        assert!(g(2_000_000.0) < 10.0 * g(200_000.0));
    }

    #[test]
    fn a_lowland_plain_gains_its_floor_at_hillslope_scale_only() {
        let flat = |len: f64| landform_range([SEA + 100.0; 4], len, SEA, S_G, [0.0; 2]).0;
        // Rising with the edge up to about a kilometre and a half...
        assert!(flat(100.0) < flat(500.0) && flat(500.0) < flat(1_000.0));
        // ... falling beyond: a 50 km split of a plain gains less than a 5 km one.
        assert!(flat(50_000.0) < 0.5 * flat(5_000.0), "{} {}", flat(50_000.0), flat(5_000.0));
    }

    #[test]
    fn a_rugged_map_pixel_keeps_its_ground_rugged_below_it() {
        let g = [SEA + 500.0; 4];
        let pixel = 40_000.0;
        // Against the same ground without a map (the floor alone).
        let (plain, ..) = landform_range(g, 10_000.0, SEA, S_G, [0.0; 2]);
        let (rugged, ..) = landform_range(g, 10_000.0, SEA, S_G, [800.0, pixel]);
        assert!(rugged > plain + 0.9 * MAP_RELIEF * 800.0 * 0.5, "{rugged} vs {plain}");
        // With the square root of the edge: a quarter of the edge, half of the map's share.
        let (quarter, ..) = landform_range(g, 2_500.0, SEA, S_G, [800.0, pixel]);
        let (quarter_plain, ..) = landform_range(g, 2_500.0, SEA, S_G, [0.0; 2]);
        let (share, share_quarter) = (rugged - plain, quarter - quarter_plain);
        assert!((share_quarter / share - 0.5).abs() < 0.05, "{share} {share_quarter}");
        // A pixel the map shows flat keeps its ground flatter than the floor alone would: a few
        // metres of roughness give at most twice their share.
        let (flat, ..) = landform_range(g, 10_000.0, SEA, S_G, [0.0, pixel]);
        let (gentle, ..) = landform_range(g, 10_000.0, SEA, S_G, [2.0, pixel]);
        assert!(flat < gentle && gentle < 0.5 * plain, "{flat} {gentle} vs {plain}");
    }

    #[test]
    fn crests_rise_and_valleys_sink() {
        let len = 1_000.0;
        // The same four altitudes, the split edge once along the crest and once across it.
        let mean = |g: [f64; 4]| (0..256).map(|s| landform_ground(g, len, s, SEA, S_G, [0.0; 2])).sum::<f64>() / 256.0;
        let c = mean([SEA + 600.0, SEA + 500.0, SEA + 600.0, SEA + 500.0]);
        let v = mean([SEA + 500.0, SEA + 600.0, SEA + 500.0, SEA + 600.0]);
        let lift = RIDGE * (1.0 - 0.1 / THRESHOLD) * 50.0;
        assert!(c > SEA + 550.0 + 0.5 * lift, "crest {c}, lift {lift}");
        assert!(v < SEA + 550.0 - 0.5 * lift, "valley {v}, lift {lift}");
    }

    #[test]
    fn the_offset_stays_within_its_range() {
        let g = [SEA + 1_000.0, SEA + 1_300.0, SEA + 1_100.0, SEA + 1_250.0];
        let (range, mean, threshold) = landform_range(g, 5_000.0, SEA, S_G, [0.0; 2]);
        let ridge = RIDGE * threshold * ((g[0] + g[2]) * 0.5 - (g[1] + g[3]) * 0.5);
        for s in 0..1_000 {
            let x = landform_ground(g, 5_000.0, s, SEA, S_G, [0.0; 2]) - mean - ridge;
            assert!(x.abs() <= range * 0.5, "{x} {range}");
        }
    }
}
