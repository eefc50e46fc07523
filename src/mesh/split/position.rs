//! Where a split puts its new vertex (paper §4.1 eq. 1–2, §5.3 step 5, eq. 7–9).
//!
//! All random numbers come from the new vertex's seed `s_nv = s_ev1 + s_ev2`, so the same edge
//! always yields the same vertex.

use crate::mesh::{Diamond, EdgeKind};
use crate::rng::{salt, uniform, unit};
use glam::DVec3;

/// How far past a node of the bisection tree its descendants may lie, in its longest edges:
/// eq. 2 puts a split's vertex anywhere in the middle of the diamond around the split edge
/// (weights 1/4 to 3/4), up to 3/8 of the way to the far apex, about 0.19 of the edge past the
/// node; the children's splits add as much of theirs, about 0.65 in all. Walks that look for the nodes near a region
/// (`export/dem.rs`) and the face index (`export/face_index.rs`) allow this much.
pub const DESCENDANT_REACH: f64 = 0.7;

/// Seed of the vertex a split of the diamond `d` creates (§3.1: the sum of the end points' seeds).
pub fn split_seed(d: &Diamond) -> u32 {
    d.a().seed.wrapping_add(d.b().seed)
}

/// Eq. 2: a randomised weighted sum of the four vertices around the edge, with
/// `xi, eta` uniform in `[0.25, 0.75)`. Returns an unprojected point.
pub fn weighted_position(diamond: &Diamond, seed: u32) -> DVec3 {
    let xi = uniform(seed, salt::XI, 0.25, 0.75);
    let eta = uniform(seed, salt::ETA, 0.25, 0.75);
    let [a, b, t, d] = diamond.positions();
    (1.0 - eta) * (xi * a + (1.0 - xi) * t) + eta * (xi * d + (1.0 - xi) * b)
}

/// Sea vertices sit at the centre of the split edge (§5.3 step 5).
pub fn edge_centre(d: &Diamond) -> DVec3 {
    (d.a().p() + d.b().p()) * 0.5
}

/// Eq. 7–9: a river vertex between `v_t` and `v_d`. For edges shorter than the minimum river
/// length the random `xi` is pulled towards the point `v_s` of the curve that the end points'
/// downstream tangents describe (eq. 9), which rounds rivers as they are refined.
///
/// Eq. 8 is printed garbled in the paper; we read it as: `v_s`'s projection onto `v_t -> v_d`
/// gives the curve's parameter `xi_s`, and the new `xi` is `xi_s` plus a quarter of the random
/// offset `xi - 1/2`, clamped to `[0.25, 0.75]` so the vertex stays inside the edge's diamond.
pub fn river_position(diamond: &Diamond, seed: u32, min_river_length: f64) -> DVec3 {
    let xi = uniform(seed, salt::XI, 0.25, 0.75);
    let [a, b, t, d] = diamond.positions();
    let length = a.distance(b);
    let xi = if length < min_river_length {
        // Eq. 9 assumes the river flows from ev1 to ev2; orient by water altitude.
        let (va, vb) = (diamond.a(), diamond.b());
        let (up, down) = if va.water >= vb.water { (va, vb) } else { (vb, va) };
        let (tu, td) = (up.tangent.get(), down.tangent.get());
        let vs = (a + b) * 0.5 + length * (tu - td) * 0.25;
        let td_line = t - d;
        let denom = td_line.length_squared();
        // Parameter measured from v_t, as eq. 7 weights v_d by xi.
        let s = if denom > 0.0 { 1.0 - (vs - d).dot(td_line) / denom } else { 0.5 };
        (s + 0.25 * (xi - 0.5)).clamp(0.25, 0.75)
    } else {
        xi
    };
    (1.0 - xi) * t + xi * d
}

/// Position of a new vertex on an edge of `kind` (before lifting to its altitude).
pub fn split_position(d: &Diamond, seed: u32, kind: EdgeKind, min_river_length: f64) -> DVec3 {
    let p = match kind {
        EdgeKind::Sea => return edge_centre(d),
        EdgeKind::River => river_position(d, seed, min_river_length),
        EdgeKind::Coast | EdgeKind::Continent => weighted_position(d, seed),
    };
    well_shaped(d, p)
}

/// Smallest shape quality ([`face_quality`]) a randomised split position may give the four new
/// faces. Eq. 2 moves each new vertex up to a quarter of the diamond away from its centre, and
/// with newest-vertex bisection those offsets compound from level to level: left alone, the
/// median face quality falls from ~0.75 to ~0.04 over 17 levels (slivers a thousand times longer
/// than wide), and sliver diamonds make the slope bounds of eq. 12 unsatisfiable. Holding each
/// split's faces at this quality keeps the distribution level (1 % of faces below ~0.25, none
/// below ~0.15, at every level we measured) while about half the splits keep a random offset
/// (continent splits of the benchmark's orbit view: 30 % the full one, 20 % one pulled back,
/// the rest the edge's centre).
pub const MIN_SPLIT_QUALITY: f64 = 0.4;

/// The randomised position `p` (eq. 2 or eq. 7), or, when that would make one of the four new
/// faces worse than [`MIN_SPLIT_QUALITY`], `p` pulled halfway and then three quarters of the
/// way back to the split edge's centre; the centre itself when neither is good enough (it
/// never folds a face: it halves both old faces). A function of the same four vertices and
/// seed, so still reproducible.
pub fn well_shaped(diamond: &Diamond, p: DVec3) -> DVec3 {
    well_shaped_towards(diamond, &corner_directions(diamond), p).0
}

/// Unit vectors from the planet's centre towards the diamond's corners `a, b, t, d`.
#[inline]
pub fn corner_directions(diamond: &Diamond) -> [DVec3; 4] {
    diamond.positions().map(DVec3::normalize)
}

/// [`well_shaped`] given the [`corner_directions`]: the point and its own direction (which
/// the shape test computes anyway, and lifting and horizontal distances need again).
pub fn well_shaped_towards(diamond: &Diamond, corners: &[DVec3; 4], p: DVec3) -> (DVec3, DVec3) {
    let [a, b, t, d] = *corners;
    let c = edge_centre(diamond);
    let pairs = [[t, a], [b, t], [a, d], [d, b]];
    // The three candidates' directions at once: they do not depend on each other, so their
    // square roots overlap.
    // (`p` itself at full scale: `c + (p - c)` can differ from `p` in the last bit.)
    let xs = [p, c + (p - c) * 0.5, c + (p - c) * 0.25];
    let ms = xs.map(DVec3::normalize);
    for (x, m) in xs.into_iter().zip(ms) {
        match shape_verdict(m, &pairs) {
            Some(true) => return (x, m),
            Some(false) => {}
            None => return well_shaped_by_quality(c, &xs, &ms, &pairs),
        }
    }
    (c, c.normalize())
}

/// Whether the triangles `m, y, z` for the `pairs` `[y, z]` all have a [`face_quality`] of
/// at least [`MIN_SPLIT_QUALITY`], decided without the qualities' four divisions where that
/// gives the same answer bit for bit: `q = k A / S` reaches the bound when `k A - MIN S > 0`,
/// and where that gap exceeds `1e-9 S` in size (`|q| <= 1`, so it is then at least 1e-9 of
/// either side) the roundings of the product, the difference and the division (~1e-16 each)
/// cannot change its sign. So all four surely pass, or one surely fails (the smallest quality
/// is then below the bound whatever the others); otherwise — a triangle within the margin,
/// degenerate or not finite — there is no verdict.
#[inline]
fn shape_verdict(m: DVec3, pairs: &[[DVec3; 2]; 4]) -> Option<bool> {
    let (mut pass, mut fail) = (true, false);
    for &[y, z] in pairs {
        let (scaled_area, sides) = quality_parts(m, y, z);
        let gap = scaled_area - MIN_SPLIT_QUALITY * sides;
        let margin = 1e-9 * sides;
        pass &= gap > margin;
        fail |= gap < -margin;
    }
    if pass {
        Some(true)
    } else if fail {
        Some(false)
    } else {
        None
    }
}

/// [`well_shaped_towards`] by the qualities themselves, for the rare candidate that
/// [`shape_verdict`] leaves open. Out of line and cold: inlined, it slowed every split.
#[cold]
#[inline(never)]
fn well_shaped_by_quality(c: DVec3, xs: &[DVec3; 3], ms: &[DVec3; 3], pairs: &[[DVec3; 2]; 4]) -> (DVec3, DVec3) {
    for (&x, &m) in xs.iter().zip(ms) {
        if qualities_reach_bound(m, pairs) {
            return (x, m);
        }
    }
    (c, c.normalize())
}

/// The shape rule itself: the smallest [`face_quality`] of the triangles `m, y, z` for the
/// `pairs` `[y, z]` is at least [`MIN_SPLIT_QUALITY`].
fn qualities_reach_bound(m: DVec3, pairs: &[[DVec3; 2]; 4]) -> bool {
    let q = pairs.map(|[y, z]| face_quality(m, y, z));
    q[0].min(q[1]).min(q[2]).min(q[3]) >= MIN_SPLIT_QUALITY
}

/// Shape quality of the triangle `x, y, z` (unit vectors, counter-clockwise seen from outside):
/// `4 sqrt(3) area / (sum of squared sides)`, 1 for an equilateral triangle, 0 for a degenerate
/// one, negative when the triangle is folded over (clockwise).
pub fn face_quality(x: DVec3, y: DVec3, z: DVec3) -> f64 {
    let (scaled_area, sides) = quality_parts(x, y, z);
    scaled_area / sides
}

/// The numerator and denominator of [`face_quality`].
#[inline]
fn quality_parts(x: DVec3, y: DVec3, z: DVec3) -> (f64, f64) {
    let twice_area = x.cross(y).dot(z);
    (2.0 * 3f64.sqrt() * twice_area, x.distance_squared(y) + y.distance_squared(z) + z.distance_squared(x))
}

/// Eq. 1: lifts a point onto the sphere of radius `radius + altitude` (centre at the origin).
#[inline]
pub fn lift(p: DVec3, radius: f64, altitude: f64) -> DVec3 {
    p.normalize() * (radius + altitude)
}

/// A uniform number in `[0, 1)` for altitude choices at a vertex.
#[inline]
pub fn altitude_random(seed: u32) -> f64 {
    unit(seed, salt::ALTITUDE)
}

/// Unit vector from `from` towards `to`, projected onto the tangent plane at `from`.
pub fn tangent_towards(from: DVec3, to: DVec3) -> DVec3 {
    tangent_along(from, to - from)
}

/// The direction `d` projected onto the tangent plane at `at`, as a unit vector (zero where `d`
/// is vertical there).
pub fn tangent_along(at: DVec3, d: DVec3) -> DVec3 {
    let up = at.normalize();
    (d - up * d.dot(up)).normalize_or_zero()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn unit(v: [f64; 3]) -> DVec3 {
        DVec3::from_array(v).normalize()
    }

    proptest! {
        /// Wherever the division-free test gives a verdict, it is the qualities' answer.
        #[test]
        fn shape_verdicts_agree_with_the_qualities(
            corners in prop::array::uniform4(prop::array::uniform3(-1.0f64..1.0)),
            m in prop::array::uniform3(-1.0f64..1.0),
            spread in 1e-7f64..1.0,
        ) {
            // A small diamond near +Z (edges from ~10 cm to ~6000 km at Earth radius).
            let [a, b, t, d] = corners.map(|c| unit([c[0] * spread, c[1] * spread, 1.0]));
            let m = unit([m[0] * spread, m[1] * spread, 1.0]);
            let pairs = [[t, a], [b, t], [a, d], [d, b]];
            if let Some(v) = shape_verdict(m, &pairs) {
                prop_assert_eq!(v, qualities_reach_bound(m, &pairs));
            }
        }
    }

    /// A square diamond (`a -> b` along x, `t` on +y, `d` on -y), 0.01 rad across, near +Z.
    fn square_diamond() -> [[DVec3; 2]; 4] {
        let [a, b, t, d] = [[-0.01, 0.0], [0.01, 0.0], [0.0, 0.01], [0.0, -0.01]].map(|[x, y]| unit([x, y, 1.0]));
        [[t, a], [b, t], [a, d], [d, b]]
    }

    /// A triangle whose quality is the bound to within rounding gets no verdict, and the
    /// qualities decide it.
    #[test]
    fn a_quality_at_the_bound_is_left_to_the_division() {
        let pairs = square_diamond();
        let [t, a] = pairs[0];
        // From the centre towards the middle of `t a`: `m, t, a` flattens from 0.87 to 0 while
        // the other three stay above 0.6.
        let at = |s: f64| unit([-0.01 * s, 0.01 * s, 1.0]);
        let quality = |s: f64| face_quality(at(s), t, a);
        let (mut lo, mut hi) = (0.45, 0.05);
        assert!(quality(lo) < MIN_SPLIT_QUALITY && quality(hi) > MIN_SPLIT_QUALITY);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if quality(mid) < MIN_SPLIT_QUALITY {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        for s in [lo, hi] {
            assert_eq!(shape_verdict(at(s), &pairs), None, "quality {}", quality(s));
        }
        assert!(!qualities_reach_bound(at(lo), &pairs) && qualities_reach_bound(at(hi), &pairs));
        // Clear cases get their verdict.
        assert_eq!(shape_verdict(at(0.45), &pairs), Some(false));
        assert_eq!(shape_verdict(at(0.05), &pairs), Some(true));
    }

    /// `well_shaped` takes the first candidate the qualities accept: the random point itself,
    /// pulled halfway or three quarters back, or the edge's centre.
    #[test]
    fn well_shaped_points_follow_the_quality_rule() {
        use crate::mesh::{Edge, EdgeKind, Face, Lod, SplitSite, Vertex};
        let pairs = square_diamond();
        let [[t, a], [b, _], [_, d], _] = pairs;
        let r = 6.371e6;
        let diamond = Diamond {
            site: SplitSite { edge: 0, a: 0, b: 1, t: 2, d: 3, f1: 0, f2: 1 },
            edge: Edge { v: [0, 1], f: [0, 1], lod: Lod::default(), level: 0, kind: EdgeKind::Continent, land: 3 },
            faces: [Face { e: [0, 1, 2] }, Face { e: [0, 3, 4] }],
            corners: [a, b, t, d].map(|u| Vertex::new(u * r, 0)),
            radius: r,
        };
        let c = edge_centre(&diamond);
        let mut outcomes = [0; 4];
        for k in 0..400 {
            let p = unit([-0.02 + 0.0001 * k as f64, 0.001 + 0.00001 * k as f64, 1.0]) * r;
            let xs = [p, c + (p - c) * 0.5, c + (p - c) * 0.25];
            let first = xs.iter().position(|x| qualities_reach_bound(x.normalize(), &pairs)).unwrap_or(3);
            let expected = xs.get(first).copied().unwrap_or(c);
            assert_eq!(well_shaped(&diamond, p), expected, "k = {k}");
            outcomes[first] += 1;
        }
        assert!(outcomes.iter().all(|&n| n > 0), "{outcomes:?}");
    }
}
