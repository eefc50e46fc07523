//! Mountain belts of planets without an elevation map: where a planet's crust is lifted into
//! long, narrow ranges (the Andes, the Alpine-Himalayan belt), as a field over the sphere.
//!
//! Earth's land is mostly low (median ~440 m) with its high ground in a few belts along plate
//! boundaries: 1-2 % of it above 4 km. The paper's rivers rise evenly from the coast, which gives
//! either high land everywhere or none. Here a belt field `b` in `[0, 1]` marks ridges: the
//! zero lines of a low-frequency gradient noise (Perlin's, on the unit sphere, seeded), widened
//! to [`WIDTH`] on either side (a ridged noise, Musgrave's "ridged multifractal" with one
//! octave), of which a second, coarser noise keeps about half, so that belts end and do not
//! ring every plate. [`super::rivers`] lifts river water by `b * mountain_belt_uplift_m` downstream
//! first, so a river still falls to the sea: behind a range its upper course stays on the
//! range's height, as on a plateau.

use crate::rng::mix32;
use glam::DVec3;

/// Frequency of the ridges over the unit sphere (about 5 lines across a hemisphere).
const RIDGE_FREQUENCY: f64 = 2.2;
/// Half-width of a belt in noise units (the noise's gradient is about 1 per unit).
const WIDTH: f64 = 0.12;
/// Frequency of the mask that keeps some belts and ends others.
const MASK_FREQUENCY: f64 = 1.1;

/// A unit-ish gradient for a lattice point.
fn gradient(seed: u32, x: i64, y: i64, z: i64) -> DVec3 {
    let h = mix32(
        seed ^ mix32(
            (x as u32).wrapping_mul(0x8da6_b343) ^ mix32((y as u32).wrapping_mul(0xd816_3841) ^ mix32(z as u32)),
        ),
    );
    // One of the 12 edge directions of a cube (Perlin 2002).
    const G: [[f64; 3]; 12] = [
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
        [1.0, -1.0, 0.0],
        [-1.0, -1.0, 0.0],
        [1.0, 0.0, 1.0],
        [-1.0, 0.0, 1.0],
        [1.0, 0.0, -1.0],
        [-1.0, 0.0, -1.0],
        [0.0, 1.0, 1.0],
        [0.0, -1.0, 1.0],
        [0.0, 1.0, -1.0],
        [0.0, -1.0, -1.0],
    ];
    DVec3::from_array(G[(h % 12) as usize])
}

/// Perlin's gradient noise at `p`, about within [-1, 1].
pub fn noise(seed: u32, p: DVec3) -> f64 {
    let c = p.floor();
    let f = p - c;
    let fade = |t: f64| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let (u, v, w) = (fade(f.x), fade(f.y), fade(f.z));
    let (x, y, z) = (c.x as i64, c.y as i64, c.z as i64);
    let corner = |dx: i64, dy: i64, dz: i64| {
        gradient(seed, x + dx, y + dy, z + dz).dot(f - DVec3::new(dx as f64, dy as f64, dz as f64))
    };
    let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
    let x00 = lerp(corner(0, 0, 0), corner(1, 0, 0), u);
    let x10 = lerp(corner(0, 1, 0), corner(1, 1, 0), u);
    let x01 = lerp(corner(0, 0, 1), corner(1, 0, 1), u);
    let x11 = lerp(corner(0, 1, 1), corner(1, 1, 1), u);
    lerp(lerp(x00, x10, v), lerp(x01, x11, v), w)
}

/// The belt field at a direction from the planet's centre: 1 on a belt's crest line, falling
/// to 0 at [`WIDTH`] from it, and 0 where the mask ends belts.
pub fn belt(seed: u64, dir: DVec3) -> f64 {
    let d = dir.normalize();
    let s = (seed ^ (seed >> 32)) as u32;
    let ridge = (1.0 - noise(mix32(s ^ 0xb31f), d * RIDGE_FREQUENCY).abs() / WIDTH).max(0.0);
    let m = noise(mix32(s ^ 0x5a5c), d * MASK_FREQUENCY);
    let mask = ((m + 0.05) / 0.2).clamp(0.0, 1.0);
    let mask = mask * mask * (3.0 - 2.0 * mask);
    ridge * ridge * (3.0 - 2.0 * ridge) * mask
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn belts_are_narrow_and_cover_a_small_share_of_the_sphere() {
        // Fibonacci points over the sphere.
        let n = 20_000;
        let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
        let dirs: Vec<DVec3> = (0..n)
            .map(|i| {
                let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
                let r = (1.0 - z * z).sqrt();
                DVec3::new(r * (golden * i as f64).cos(), r * (golden * i as f64).sin(), z)
            })
            .collect();
        let b: Vec<f64> = dirs.iter().map(|&d| belt(42, d)).collect();
        let high = b.iter().filter(|&&x| x > 0.5).count() as f64 / n as f64;
        let any = b.iter().filter(|&&x| x > 0.0).count() as f64 / n as f64;
        assert!((0.02..0.12).contains(&high), "{high}");
        assert!(any < 0.3, "{any}");
        assert!(b.iter().all(|x| (0.0..=1.0).contains(x)));
        // Another seed, other belts; the same seed, the same belts.
        assert_ne!(b[..100], dirs[..100].iter().map(|&d| belt(43, d)).collect::<Vec<_>>()[..]);
        assert_eq!(b[7], belt(42, dirs[7]));
    }
}
