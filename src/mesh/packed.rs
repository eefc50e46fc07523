//! Compact fields of the mesh buffers (paper Table 3, §5.2's memory budget): level-of-detail
//! bounds as two bfloat16 numbers rounded down, and river tangents as octahedral unit vectors in
//! two 12-bit fractions (about 0.05° apart, which moves a river vertex by less than 1e-4 of its
//! edge's length).
//!
//! Both are exact functions of what they encode, so the terrain stays reproducible; rounding the
//! bounds down keeps a child's bounds inside its parent's, which is what the refinement criterion
//! needs (see [`super::Edge::lod`]).

use glam::DVec3;

/// Level-of-detail bounds of an edge: a length and the radius of a ball around the edge's
/// midpoint, each a bfloat16 (the upper half of an `f32`), rounded towards minus infinity.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, bytemuck::NoUninit, bytemuck::AnyBitPattern)]
pub struct Lod {
    len: u16,
    radius: u16,
}

impl Lod {
    /// Bounds `len` and `radius`, each rounded down to the next bfloat16.
    pub fn new(len: f64, radius: f64) -> Lod {
        Lod { len: bf16_down(len), radius: bf16_down(radius) }
    }
    #[inline]
    pub fn len(self) -> f32 {
        f32::from_bits(u32::from(self.len) << 16)
    }
    #[inline]
    pub fn radius(self) -> f32 {
        f32::from_bits(u32::from(self.radius) << 16)
    }
}

/// The largest bfloat16 not above `x` (finite), as its bits.
fn bf16_down(x: f64) -> u16 {
    let f = x as f32;
    let f = if f as f64 > x { f.next_down() } else { f };
    let bits = f.to_bits();
    let high = (bits >> 16) as u16;
    // Dropping the low half moves a value towards zero: down for positive values, up for
    // negative ones, which then take the next bfloat16 away from zero.
    if f < 0.0 && bits & 0xffff != 0 {
        high + 1
    } else {
        high
    }
}

/// A unit vector in octahedral coordinates `x, y` in `[-1, 1]`, each stored as
/// `2048 + round(2047 c)` in 12 bits (x in the low bits of three little-endian bytes); the code
/// 0, which no unit vector takes, is no direction.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, bytemuck::NoUninit, bytemuck::AnyBitPattern)]
pub struct Tangent([u8; 3]);

const SCALE: f64 = 2047.0;
const OFFSET: f64 = 2048.0;

impl Tangent {
    /// Codes per unit of an octahedral coordinate, and the code of zero.
    pub const SCALE: f64 = SCALE;
    pub const OFFSET: f64 = OFFSET;

    /// No direction.
    pub const ZERO: Tangent = Tangent([0; 3]);

    /// Encodes the direction of `t`; a zero or non-finite vector gives [`Tangent::ZERO`].
    pub fn new(t: DVec3) -> Tangent {
        let l1 = t.x.abs() + t.y.abs() + t.z.abs();
        if !(l1 > 0.0 && l1.is_finite()) {
            return Tangent::ZERO;
        }
        let (mut x, mut y) = (t.x / l1, t.y / l1);
        if t.z < 0.0 {
            (x, y) = ((1.0 - y.abs()) * sign(x), (1.0 - x.abs()) * sign(y));
        }
        let [x, y] = [x, y].map(|c| (OFFSET + (c * SCALE).round().clamp(-SCALE, SCALE)) as u32);
        let [b0, b1, b2, _] = (x | y << 12).to_le_bytes();
        Tangent([b0, b1, b2])
    }

    /// The unit vector (zero for [`Tangent::ZERO`]).
    pub fn get(self) -> DVec3 {
        if self == Tangent::ZERO {
            return DVec3::ZERO;
        }
        let [b0, b1, b2] = self.0;
        let bits = u32::from_le_bytes([b0, b1, b2, 0]);
        let [x, y] = [bits & 0xfff, bits >> 12].map(|c| (c as f64 - OFFSET) / SCALE);
        let z = 1.0 - x.abs() - y.abs();
        let (x, y) = if z < 0.0 { ((1.0 - y.abs()) * sign(x), (1.0 - x.abs()) * sign(y)) } else { (x, y) };
        DVec3::new(x, y, z).normalize()
    }
}

fn sign(x: f64) -> f64 {
    if x < 0.0 {
        -1.0
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_round_down_to_nearby_values() {
        for x in [0.0, 1e-3, 0.01, 1.0, 3.3, 1234.567, 6.4e6, -0.5, -77.7, -6.4e6] {
            let l = Lod::new(x, x);
            assert!(l.len() as f64 <= x && l.radius() as f64 <= x, "{x}: {l:?}");
            assert!((x - l.len() as f64).abs() <= x.abs() / 128.0, "{x}: {}", l.len());
        }
        // Rounding down is monotonic: a smaller value never gets a larger code.
        let xs: Vec<f64> = (-2000..2000).map(|i| i as f64 * 0.37).collect();
        for w in xs.windows(2) {
            assert!(Lod::new(w[0], 0.0).len() <= Lod::new(w[1], 0.0).len());
        }
        assert_eq!(Lod::new(2.0, -2.0).len(), 2.0);
        assert_eq!(Lod::new(2.0, -2.0).radius(), -2.0);
    }

    #[test]
    fn tangents_survive_encoding() {
        let mut worst: f64 = 0.0;
        for i in 0..2000 {
            let (a, b) = (i as f64 * 0.7137, i as f64 * 1.3311);
            let t = DVec3::new(a.cos() * b.sin(), a.sin() * b.sin(), b.cos());
            let back = Tangent::new(t).get();
            assert!((back.length() - 1.0).abs() < 1e-12);
            worst = worst.max(back.angle_between(t));
        }
        assert!(worst < 1e-3, "worst angle {worst}");
        for t in [DVec3::Z, DVec3::NEG_Z, DVec3::X, DVec3::NEG_Y, DVec3::new(-1.0, -1.0, -1.0)] {
            assert!(Tangent::new(t).get().angle_between(t.normalize()) < 1e-3, "{t}");
        }
        assert_eq!(Tangent::new(DVec3::ZERO), Tangent::ZERO);
        assert_eq!(Tangent::new(DVec3::NAN).get(), DVec3::ZERO);
    }
}
