//! Oriented bounding boxes for tiles (the 3D Tiles `box` volume): fitted to points along given
//! axes, and nested inside a parent's box.

use glam::DVec3;

/// A box: centre, three orthonormal axes and the half-length along each, planet frame (metres).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrientedBox {
    pub centre: DVec3,
    pub axes: [DVec3; 3],
    pub half: [f64; 3],
}

/// East, north and up at the direction `up` (east along the equator; at the poles, +Y).
pub fn local_axes(up: DVec3) -> [DVec3; 3] {
    let up = up.normalize();
    let east = DVec3::Z.cross(up).try_normalize().unwrap_or(DVec3::Y);
    [east, up.cross(east), up]
}

impl OrientedBox {
    /// The smallest box along `axes` holding every point, grown by `pad` on every side.
    pub fn fit(points: impl IntoIterator<Item = DVec3>, axes: [DVec3; 3], pad: f64) -> OrientedBox {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in points {
            for k in 0..3 {
                let x = p.dot(axes[k]);
                lo[k] = lo[k].min(x);
                hi[k] = hi[k].max(x);
            }
        }
        OrientedBox::from_ranges(axes, lo.map(|x| x - pad), hi.map(|x| x + pad))
    }

    fn from_ranges(axes: [DVec3; 3], lo: [f64; 3], hi: [f64; 3]) -> OrientedBox {
        let centre = (0..3).map(|k| axes[k] * ((lo[k] + hi[k]) * 0.5)).sum();
        OrientedBox { centre, axes, half: [0, 1, 2].map(|k| ((hi[k] - lo[k]) * 0.5).max(0.0)) }
    }

    /// The eight corners.
    pub fn corners(&self) -> [DVec3; 8] {
        std::array::from_fn(|i| {
            let s = |bit: usize| if i >> bit & 1 == 1 { 1.0 } else { -1.0 };
            self.centre + (0..3).map(|k| self.axes[k] * (self.half[k] * s(k))).sum::<DVec3>()
        })
    }

    /// Whether `p` lies inside, allowing `tol` metres.
    pub fn contains(&self, p: DVec3, tol: f64) -> bool {
        let d = p - self.centre;
        (0..3).all(|k| d.dot(self.axes[k]).abs() <= self.half[k] + tol)
    }

    /// Whether `other` lies inside, allowing `tol` metres.
    pub fn contains_box(&self, other: &OrientedBox, tol: f64) -> bool {
        other.corners().iter().all(|&c| self.contains(c, tol))
    }

    /// This box if it lies inside `parent`; otherwise the box along the parent's axes around
    /// it, cut to the parent. Either way the result lies inside `parent`, and it holds whatever
    /// this box holds that `parent` holds.
    pub fn nested_in(&self, parent: &OrientedBox) -> OrientedBox {
        if parent.contains_box(self, 0.0) {
            return *self;
        }
        let around = OrientedBox::fit(self.corners(), parent.axes, 0.0);
        let c = [0, 1, 2].map(|k| parent.centre.dot(parent.axes[k]));
        let lo = [0, 1, 2].map(|k| around.lo(k).max(c[k] - parent.half[k]));
        let hi = [0, 1, 2].map(|k| around.hi(k).min(c[k] + parent.half[k]));
        OrientedBox::from_ranges(parent.axes, lo, hi)
    }

    fn lo(&self, k: usize) -> f64 {
        self.centre.dot(self.axes[k]) - self.half[k]
    }

    fn hi(&self, k: usize) -> f64 {
        self.centre.dot(self.axes[k]) + self.half[k]
    }

    /// The 3D Tiles `box` array: centre relative to `origin`, then each axis times its half-length.
    pub fn to_tiles_box(&self, origin: DVec3) -> [f64; 12] {
        let c = self.centre - origin;
        let a = [0, 1, 2].map(|k| self.axes[k] * self.half[k]);
        [c.x, c.y, c.z, a[0].x, a[0].y, a[0].z, a[1].x, a[1].y, a[1].z, a[2].x, a[2].y, a[2].z]
    }

    /// The box of a 3D Tiles `box` array whose centre is relative to `origin`.
    pub fn from_tiles_box(b: &[f64; 12], origin: DVec3) -> OrientedBox {
        let v = |i: usize| DVec3::new(b[i], b[i + 1], b[i + 2]);
        let half = [v(3).length(), v(6).length(), v(9).length()];
        let axes = [v(3), v(6), v(9)].map(|a| a.normalize_or_zero());
        OrientedBox { centre: v(0) + origin, axes, half }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fitted_boxes_hold_their_points_and_nest() {
        let pts = [DVec3::new(1.0, 2.0, 3.0), DVec3::new(-4.0, 0.5, 9.0), DVec3::new(2.0, -1.0, 0.0)];
        let b = OrientedBox::fit(pts, local_axes(DVec3::new(1.0, 1.0, 1.0)), 0.5);
        assert!(pts.iter().all(|&p| b.contains(p, 1e-9)));
        let parent = OrientedBox::fit(pts, [DVec3::X, DVec3::Y, DVec3::Z], 0.0);
        let nested = b.nested_in(&parent);
        assert!(parent.contains_box(&nested, 1e-9));
        assert!(pts.iter().all(|&p| nested.contains(p, 1e-9)));
        let round = OrientedBox::from_tiles_box(&b.to_tiles_box(DVec3::new(5.0, 6.0, 7.0)), DVec3::new(5.0, 6.0, 7.0));
        assert!(round.centre.distance(b.centre) < 1e-12);
        assert!((0..3).all(|k| (round.half[k] - b.half[k]).abs() < 1e-12));
    }

    #[test]
    fn local_axes_are_east_north_up() {
        let [e, n, u] = local_axes(DVec3::X * 7.0);
        assert!(e.distance(DVec3::Y) < 1e-12 && n.distance(DVec3::Z) < 1e-12 && u.distance(DVec3::X) < 1e-12);
        let [e, _, u] = local_axes(DVec3::Z);
        assert_eq!((e, u), (DVec3::Y, DVec3::Z));
    }
}
