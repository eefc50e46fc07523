//! Where a split puts its new vertex (paper §4.1 eq. 1–2, §5.3 step 5, eq. 7–9).
//!
//! All random numbers come from the new vertex's seed `s_nv = s_ev1 + s_ev2`, so the same edge
//! always yields the same vertex.

use super::{Diamond, EdgeKind};
use crate::rng::{salt, uniform, unit};
use glam::DVec3;

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
/// below ~0.15, at every level we measured) while most splits keep a random offset.
pub const MIN_SPLIT_QUALITY: f64 = 0.4;

/// The randomised position `p` (eq. 2 or eq. 7), or, when that would make one of the four new
/// faces worse than [`MIN_SPLIT_QUALITY`], `p` pulled halfway and then three quarters of the
/// way back to the split edge's centre; the centre itself when neither is good enough (it
/// never folds a face: it halves both old faces). A function of the same four vertices and
/// seed, so still reproducible.
pub fn well_shaped(diamond: &Diamond, p: DVec3) -> DVec3 {
    let [a, b, t, d] = diamond.positions().map(|p| p.normalize());
    let c = edge_centre(diamond);
    for scale in [1.0, 0.5, 0.25] {
        // `p` itself at full scale (`c + (p - c)` can differ from `p` in the last bit).
        let x = if scale == 1.0 { p } else { c + (p - c) * scale };
        let m = x.normalize();
        let q = face_quality(m, t, a).min(face_quality(m, b, t)).min(face_quality(m, a, d)).min(face_quality(m, d, b));
        if q >= MIN_SPLIT_QUALITY {
            return x;
        }
    }
    c
}

/// Shape quality of the triangle `x, y, z` (unit vectors, counter-clockwise seen from outside):
/// `4 sqrt(3) area / (sum of squared sides)`, 1 for an equilateral triangle, 0 for a degenerate
/// one, negative when the triangle is folded over (clockwise).
pub fn face_quality(x: DVec3, y: DVec3, z: DVec3) -> f64 {
    let twice_area = x.cross(y).dot(z);
    2.0 * 3f64.sqrt() * twice_area / (x.distance_squared(y) + y.distance_squared(z) + z.distance_squared(x))
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
    let up = from.normalize();
    let d = to - from;
    (d - up * d.dot(up)).normalize_or_zero()
}
