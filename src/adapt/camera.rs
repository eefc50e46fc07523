//! Cameras and the refinement criterion of view-dependent adaption (paper §5.1).
//!
//! One syntax for the command line and HTTP, a query string:
//! `eye=X,Y,Z&target=X,Y,Z&up=X,Y,Z&fov=DEG&width=PX&height=PX&land_px=PX&water_px=PX`, metres in
//! the planet-centred frame (+Z = north pole, longitude 0 on +X). `fov` is vertical.
//!
//! The criterion is the paper's `l / d > c`, with `c` from a target projected edge length in
//! pixels. To make the adapted mesh independent of the path that led to it, `l` and `d` are taken
//! from per-edge bounds that only weaken from parent edge to child (see `Edge::lod`): `d` is
//! the distance to a ball that contains every child's ball, eq. 6's
//! slow-down outside the frustum uses how far that ball lies outside the frustum planes (and
//! behind the eye), and back-face culling drops balls entirely behind the planet's horizon.

use crate::query::{cut, pairs, percent_decode};
use glam::DVec3;

/// Paper's constant for the level-of-detail falloff outside the frustum (eq. 6).
pub const C_LOD: f64 = 20.0;
/// Default target projected edge length on land, pixels. The paper used 0.5 px at 1920x1080 on a
/// GPU; the criterion measures edge length over distance, so grazing ground views carry many
/// faces per pixel, and 8 px keeps a full-HD ground view near two million faces on a CPU.
pub const DEFAULT_LAND_PX: f64 = 8.0;
/// Default target projected edge length on the sea, pixels (the paper: ten times the land's).
pub const DEFAULT_WATER_PX: f64 = 40.0;
/// Largest accepted image side, pixels.
pub const MAX_SIDE: u32 = 8192;
/// Largest accepted coordinate magnitude, metres (about 7 AU): lengths and normals of vectors
/// this large are still exact enough, where 1e200 would overflow to infinity.
pub const MAX_COORD: f64 = 1e12;

/// A validated camera.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    pub eye: DVec3,
    pub target: DVec3,
    pub up: DVec3,
    pub fov_deg: f64,
    pub width: u32,
    pub height: u32,
    pub land_px: f64,
    pub water_px: f64,
}

/// A camera query that cannot be used, with the parameter at fault.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("camera {field}: {message}")]
pub struct CameraError {
    pub field: &'static str,
    pub message: String,
}

fn err(field: &'static str, message: impl Into<String>) -> CameraError {
    CameraError { field, message: message.into() }
}

fn vec3(field: &'static str, s: &str) -> Result<DVec3, CameraError> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(err(field, format!("expected X,Y,Z, got {:?}", cut(s))));
    }
    let mut v = [0.0; 3];
    for (i, p) in parts.iter().enumerate() {
        v[i] = p.parse::<f64>().map_err(|_| err(field, not_a_number(p)))?;
        if !v[i].is_finite() {
            return Err(err(field, format!("{p:?} is not finite")));
        }
        if v[i].abs() > MAX_COORD {
            return Err(err(field, format!("{p:?} is out of range (at most {MAX_COORD:e} m in magnitude)")));
        }
    }
    Ok(DVec3::from_array(v))
}

/// "... is not a number", with a hint where a `+` of an exponent was decoded as a space.
fn not_a_number(s: &str) -> String {
    match s.trim().contains(' ') {
        true => format!("{:?} is not a number (a query decodes + as a space: write it %2B, or leave it out)", cut(s)),
        false => format!("{:?} is not a number", cut(s)),
    }
}

fn number(field: &'static str, s: &str) -> Result<f64, CameraError> {
    let v: f64 = s.trim().parse().map_err(|_| err(field, not_a_number(s)))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(err(field, format!("{:?} is not finite", cut(s))))
    }
}

impl Camera {
    /// Parses a camera query (keys in any order; `&` or `;` separated). Keys that are not
    /// camera keys are returned for the caller (e.g. `max_faces`), unknown to the camera.
    pub fn parse_query(query: &str, radius: f64) -> Result<(Camera, Vec<(String, String)>), CameraError> {
        let (mut eye, mut target, mut up, mut fov, mut width, mut height) = (None, None, None, 60.0, 1920, 1080);
        let (mut land_px, mut water_px) = (DEFAULT_LAND_PX, DEFAULT_WATER_PX);
        let mut rest = Vec::new();
        let mut seen: Vec<&str> = Vec::new();
        for (k, v) in pairs(query.trim_start_matches('?')) {
            if seen.contains(&k) {
                // Keys the camera and its callers know are named; others were refused anyway.
                const KEYS: [&str; 10] =
                    ["eye", "target", "up", "fov", "width", "height", "land_px", "water_px", "max_faces", "sun"];
                let field = KEYS.iter().find(|&&n| n == k).copied().unwrap_or("query");
                let shown: String = k.chars().take(40).collect();
                return Err(err(field, format!("{shown:?} is given more than once")));
            }
            seen.push(k);
            let v = percent_decode(v);
            match k {
                "eye" => eye = Some(vec3("eye", &v)?),
                "target" => target = Some(vec3("target", &v)?),
                "up" => up = Some(vec3("up", &v)?),
                "fov" => fov = number("fov", &v)?,
                "width" => width = size("width", &v)?,
                "height" => height = size("height", &v)?,
                "land_px" => land_px = number("land_px", &v)?,
                "water_px" => water_px = number("water_px", &v)?,
                _ => rest.push((k.to_string(), v)),
            }
        }
        let eye = eye.ok_or_else(|| err("eye", "missing (eye=X,Y,Z in metres, planet-centred)"))?;
        let target = target.ok_or_else(|| err("target", "missing (target=X,Y,Z)"))?;
        let cam = Camera::new(eye, target, up, fov, width, height, land_px, water_px, radius)?;
        Ok((cam, rest))
    }

    /// Builds and validates a camera; `up` defaults to the local vertical across the view (north
    /// for views straight down), see `default_up`.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        eye: DVec3,
        target: DVec3,
        up: Option<DVec3>,
        fov_deg: f64,
        width: u32,
        height: u32,
        land_px: f64,
        water_px: f64,
        radius: f64,
    ) -> Result<Camera, CameraError> {
        // (The scalars' range checks below also refuse NaN.)
        for (name, v) in [("eye", Some(eye)), ("target", Some(target)), ("up", up)] {
            if let Some(v) = v.filter(|v| !v.is_finite()) {
                return Err(err(name, format!("is not finite ({v})")));
            }
        }
        if eye.length() < radius {
            return Err(err(
                "eye",
                format!(
                    "is inside the planet's base sphere ({:.0} m from the centre; its radius is {radius:.0} m)",
                    eye.length()
                ),
            ));
        }
        let dir = target - eye;
        if dir.length() < 1e-6 {
            return Err(err("target", "equals the eye"));
        }
        if !(fov_deg > 0.1 && fov_deg < 179.0) {
            return Err(err("fov", format!("must be in (0.1, 179) degrees, got {fov_deg}")));
        }
        for (name, v) in [("width", width), ("height", height)] {
            if v == 0 || v > MAX_SIDE {
                return Err(err(name, format!("must be in 1..={MAX_SIDE}, got {v}")));
            }
        }
        for (name, v) in [("land_px", land_px), ("water_px", water_px)] {
            if !(0.05..=1000.0).contains(&v) {
                return Err(err(name, format!("must be in [0.05, 1000] pixels, got {v}")));
            }
        }
        let fwd = dir.normalize();
        let up = match up {
            Some(u) => {
                if u.cross(fwd).length() < 1e-9 * u.length().max(1e-300) || u.length() == 0.0 {
                    return Err(err("up", "is zero or parallel to the view direction"));
                }
                u
            }
            None => default_up(eye, fwd),
        };
        Ok(Camera { eye, target, up, fov_deg, width, height, land_px, water_px })
    }

    /// The query string that parses back to this camera.
    pub fn to_query(&self) -> String {
        let v = |d: DVec3| format!("{},{},{}", d.x, d.y, d.z);
        format!(
            "eye={}&target={}&up={}&fov={}&width={}&height={}&land_px={}&water_px={}",
            v(self.eye),
            v(self.target),
            v(self.up),
            self.fov_deg,
            self.width,
            self.height,
            self.land_px,
            self.water_px
        )
    }

    /// Orthonormal view basis: forward, right, true up.
    pub fn basis(&self) -> (DVec3, DVec3, DVec3) {
        let f = (self.target - self.eye).normalize();
        let r = f.cross(self.up).normalize();
        (f, r, r.cross(f))
    }

    /// Pixels per unit of `l/d` on screen: `(height/2) / tan(fov/2)`.
    pub fn pixels_per_radian(&self) -> f64 {
        self.height as f64 * 0.5 / (self.fov_deg.to_radians() * 0.5).tan()
    }
}

/// The default image up: the local vertical (away from the planet centre) projected across the
/// view, so ground views keep the horizon level; where the view is within about 6 degrees of
/// straight down or up (orbit views of the planet's centre), north projected across the view.
fn default_up(eye: DVec3, fwd: DVec3) -> DVec3 {
    let vertical = eye.normalize_or(DVec3::Z);
    let level = vertical - fwd * vertical.dot(fwd);
    if level.length() > 0.1 {
        return level.normalize();
    }
    for cand in [DVec3::Z, DVec3::X] {
        let u = cand - fwd * cand.dot(fwd);
        if u.length() > 1e-3 {
            return u.normalize();
        }
    }
    DVec3::Y
}

fn size(field: &'static str, s: &str) -> Result<u32, CameraError> {
    s.trim().parse::<u32>().map_err(|e| match e.kind() {
        std::num::IntErrorKind::PosOverflow => err(field, format!("must be in 1..={MAX_SIDE}, got {}", cut(s.trim()))),
        _ => err(field, format!("{:?} is not a whole number of pixels", cut(s))),
    })
}

/// Everything the state update needs from a camera, precomputed once per adaption.
#[derive(Clone, Debug)]
pub struct View {
    pub eye: DVec3,
    /// Inward normals of the frustum's side planes (left, right, bottom, top) and of the plane
    /// facing forward, all through the eye.
    pub(crate) planes: [DVec3; 5],
    /// Eq. 6's unit for each plane: one over the tangent of the half field of view across it
    /// (horizontal for left and right, vertical for bottom and top, the narrower behind the
    /// eye), as clip space measures each axis in its own half field of view.
    pub(crate) per_unit: [f64; 5],
    /// Split when `lod_len / distance > c`.
    pub c_land: f64,
    pub c_water: f64,
    /// Horizon plane: a ball whose support along `eye_dir` is below this is behind the horizon.
    pub(crate) eye_dir: DVec3,
    pub(crate) horizon: f64,
    /// Never split edges shorter than twice this.
    pub min_len: f64,
}

impl View {
    /// `radius` is the base sphere; `min_len` the minimum edge length; `top` the highest
    /// altitude above the base sphere that terrain may reach (see [`super::terrain_top`]):
    /// horizon culling keeps whatever could stand that high.
    pub fn new(cam: &Camera, radius: f64, min_len: f64, top: f64) -> View {
        let (f, r, u) = cam.basis();
        let tan_v = (cam.fov_deg.to_radians() * 0.5).tan();
        let tan_h = tan_v * cam.width as f64 / cam.height as f64;
        // Side planes through the eye, normals pointing into the frustum; then the plane through
        // the eye facing forward, outside of which lies everything behind the eye.
        let planes = [
            (f * tan_h - r).normalize(),
            (f * tan_h + r).normalize(),
            (f * tan_v - u).normalize(),
            (f * tan_v + u).normalize(),
            f,
        ];
        let per_unit = [tan_h, tan_h, tan_v, tan_v, tan_h.min(tan_v)].map(|t| 1.0 / t);
        let ppr = cam.pixels_per_radian();
        // Horizon: a point `top` above the base sphere is hidden once its angle from the eye's
        // direction exceeds the eye's horizon angle plus its own, `beyond` (under 180°). The
        // plane lies below every point from the base sphere up to `top` within that angle: at
        // `radius` while `beyond` is under 90°, at `radius + top` past it (far eyes), where
        // the cosine is negative.
        let d_eye = cam.eye.length();
        let highest = radius + top.max(0.0);
        let beyond = (radius / d_eye).clamp(-1.0, 1.0).acos() + (radius / highest).acos();
        let horizon_plane = (radius * beyond.cos()).min(highest * beyond.cos());
        View {
            eye: cam.eye,
            planes,
            per_unit,
            c_land: cam.land_px / ppr,
            // Never finer on the sea than on land: the sea edges a coast split makes are judged
            // by `c_water`, their parent by `c_land`, and a child may not want a split that its
            // parent did not (the mesh would depend on the path).
            c_water: cam.water_px.max(cam.land_px) / ppr,
            eye_dir: cam.eye / d_eye,
            horizon: horizon_plane,
            min_len: min_len.max(0.0),
        }
    }

    /// Whether an edge with bounds (`lod_len`, ball `centre`, `radius`) should be split; the
    /// answer can only turn from yes to no going from a parent edge to its children. Always
    /// inlined: it is the body of the state update's loop, and as a call (which the compiler
    /// chose in some builds) that loop ran at half speed.
    #[inline(always)]
    pub fn wants_split(&self, lod_len: f64, centre: DVec3, radius: f64, sea: bool) -> bool {
        if lod_len < 2.0 * self.min_len {
            return false;
        }
        // Back-face culling: the whole ball lies behind the horizon plane.
        if centre.dot(self.eye_dir) + radius < self.horizon {
            return false;
        }
        let rel = centre - self.eye;
        let dist = rel.length();
        let d = (dist - radius).max(1e-3);
        let c = if sea { self.c_water } else { self.c_land };
        // Eq. 6 below only lengthens `d` (by a factor >= 1, and rounding is monotonic), so an
        // edge short enough already is refused without it — the same answer, sooner.
        if lod_len <= c * d {
            return false;
        }
        let mut outside: f64 = 0.0;
        for (n, unit) in self.planes.iter().zip(&self.per_unit) {
            outside = outside.max((-n.dot(rel) - radius) * unit);
        }
        // Eq. 6 measures how far outside the frustum a point is in projected units, each axis in
        // its own half field of view; here the ball's distance outside each plane in units of
        // that plane's half field of view, over the ball's farthest distance from the eye (an
        // angle-like ratio that can only grow from a ball to a ball inside it).
        let q = outside / (dist + radius).max(1e-3);
        let d = d * (1.0 + C_LOD * q * q); // eq. 6
        lod_len > c * d
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    const R: f64 = 6_371_000.0;
    /// Highest terrain of the default parameters, horizon margin included.
    const TOP: f64 = 20_000.0;

    /// The camera of `query` and its view (1 cm minimum edge length).
    fn camera_and_view(query: &str) -> (Camera, View) {
        let cam = Camera::parse_query(query, R).unwrap().0;
        let view = View::new(&cam, R, 0.01, TOP);
        (cam, view)
    }

    #[test]
    fn parses_a_query_with_defaults() {
        let (c, rest) = Camera::parse_query("eye=0,0,2e7&target=0,0,0&max_faces=10", R).unwrap();
        assert_eq!((c.width, c.height, c.fov_deg), (1920, 1080, 60.0));
        assert_eq!(rest, vec![("max_faces".to_string(), "10".to_string())]);
        assert!(c.up.dot(c.target - c.eye).abs() < 1e-6);
        let back = Camera::parse_query(&c.to_query(), R).unwrap().0;
        assert_eq!(back, c);
        let (c, _) = Camera::parse_query("eye=1e7%2C0%2C0&target=0,0,0&fov=30&width=640&height=480", R).unwrap();
        assert_eq!(c.eye, DVec3::new(1e7, 0.0, 0.0));
    }

    #[test]
    fn rejects_bad_cameras_naming_the_field() {
        let bad = [
            ("eye=0,0,1e6&target=0,0,0", "eye"),
            ("eye=NaN,0,2e7&target=0,0,0", "eye"),
            ("eye=0,0,2e7&target=0,0,2e7", "target"),
            ("eye=0,0,2e7&target=0,0,0&width=0", "width"),
            ("eye=0,0,2e7&target=0,0,0&height=9000", "height"),
            ("eye=0,0,2e7&target=0,0,0&fov=0", "fov"),
            ("eye=0,0,2e7&target=0,0,0&fov=abc", "fov"),
            ("eye=0,0,2e7&target=0,0,0&up=0,0,1", "up"),
            ("eye=0,0,2e7", "target"),
            ("target=0,0,0", "eye"),
            ("eye=1,2&target=0,0,0", "eye"),
            ("eye=0,0,2e7&target=0,0,0&land_px=0", "land_px"),
        ];
        for (q, field) in bad {
            let e = Camera::parse_query(q, R).unwrap_err();
            assert_eq!(e.field, field, "{q}: {e}");
        }
        // Messages that say what to do.
        for (q, needle) in [
            ("eye=6.4e+6,0,0&target=0,0,0", "write it %2B"),
            ("eye=2e7,0,0&target=0,0,0&fov=1e+1", "write it %2B"),
            ("eye=2e7,0,0&target=0,0,0&width=99999999999", "must be in 1..=8192, got 99999999999"),
            ("eye=2e7,0,0&target=0,0,0&height=1.5", "not a whole number of pixels"),
        ] {
            let e = Camera::parse_query(q, R).unwrap_err().to_string();
            assert!(e.contains(needle), "{q}: {e}");
        }
        // Inputs of any size come back cut, and a key given twice is named.
        let long = format!("eye={}&target=0,0,0", "9".repeat(60_000));
        let e = Camera::parse_query(&long, R).unwrap_err().to_string();
        assert!(e.len() < 400 && e.contains('…'), "{} bytes", e.len());
        let e = Camera::parse_query("eye=0,0,2e7&target=0,0,0&fov=50&fov=60", R).unwrap_err();
        assert_eq!(e.field, "fov");
        assert!(Camera::parse_query("eye=6.4e%2B6,0,0&target=0,0,0", R).is_ok());
    }

    #[test]
    fn built_cameras_refuse_what_a_query_cannot_spell() {
        let (eye, target, nan) = (DVec3::new(0.0, 0.0, 2e7), DVec3::ZERO, f64::NAN);
        let new = |eye, target, up, fov, land_px| Camera::new(eye, target, up, fov, 1920, 1080, land_px, 40.0, R);
        let bad = [
            (new(DVec3::new(nan, 0.0, 2e7), target, None, 60.0, 8.0), "eye"),
            (new(DVec3::new(0.0, 0.0, f64::INFINITY), target, None, 60.0, 8.0), "eye"),
            (new(eye, DVec3::new(0.0, nan, 0.0), None, 60.0, 8.0), "target"),
            (new(eye, target, Some(DVec3::new(1.0, nan, 0.0)), 60.0, 8.0), "up"),
            (new(eye, target, None, nan, 8.0), "fov"),
            (new(eye, target, None, 60.0, nan), "land_px"),
        ];
        for (made, field) in bad {
            assert_eq!(made.unwrap_err().field, field);
        }
        assert!(new(eye, target, None, 60.0, 8.0).is_ok());
    }

    #[test]
    fn criterion_is_hereditary_for_nested_balls() {
        // Looking at the planet; along its surface, with much of it behind the eye; and through
        // a sliver of a view, wide or tall.
        for (query, far) in [
            ("eye=7e6,0,0&target=0,0,0&fov=40", 1e9),
            ("eye=6.38e6,0,0&target=6.38e6,1e5,0&fov=10", 1e9),
            ("eye=6.4e6,0,0&target=0,0,0&fov=2&width=8192&height=1", 1e12),
            ("eye=6.4e6,0,0&target=0,0,0&fov=170&width=1&height=4000", 1e9),
        ] {
            nested_balls_agree(&camera_and_view(query).1, far);
        }
    }

    /// A child ball inside its parent with a shorter length never splits where the parent does
    /// not; `far` scales the edge lengths tried.
    fn nested_balls_agree(view: &View, far: f64) {
        let mut rng = crate::rng::Sequence::new(1, 1);
        let mut splits = 0;
        for _ in 0..20_000 {
            // Around the point under the eye, on both sides of the horizon.
            let jitter = DVec3::new(rng.unit() - 0.5, rng.unit() - 0.5, rng.unit() - 0.5) * 0.3;
            let c = (view.eye_dir + jitter).normalize() * R;
            let r = rng.unit() * 200_000.0;
            let len = far.powf(rng.unit());
            let off = DVec3::new(rng.unit() - 0.5, rng.unit() - 0.5, rng.unit() - 0.5) * r;
            let rc = r - off.length() - rng.unit() * 1000.0;
            let lc = len * rng.unit();
            if view.wants_split(lc, c + off, rc, false) {
                assert!(view.wants_split(len, c, r, false));
                splits += 1;
            }
        }
        assert!(splits > 100, "only {splits} children split");
    }

    #[test]
    fn frustum_planes_point_inwards() {
        let (cam, view) = camera_and_view("eye=7e6,0,0&target=0,0,0&fov=40&width=800&height=400");
        let (f, r, u) = cam.basis();
        for n in &view.planes {
            assert!(n.dot(f) > 0.0);
        }
        // Just inside and just outside each side of the frustum.
        let tan_v = (20.0f64).to_radians().tan();
        let tan_h = tan_v * 2.0;
        for (side, tan) in [(r, tan_h), (-r, tan_h), (u, tan_v), (-u, tan_v)] {
            let inside = f + side * tan * 0.99;
            let outside = f + side * tan * 1.01;
            assert!(view.planes.iter().all(|n| n.dot(inside) > 0.0));
            assert!(view.planes.iter().any(|n| n.dot(outside) < 0.0));
        }
    }

    /// Eq. 6 with c_LOD = 20: outside the frustum an edge needs to be `1 + 20 q²` times longer
    /// to split, `q` how far outside it is (here the sine of its angle beyond the frustum's top
    /// over the tangent of the half field of view); inside, the plain `l/d > c`.
    #[test]
    fn outside_the_frustum_distance_grows_by_eq_6() {
        let (cam, view) = camera_and_view("eye=0,0,2e7&target=0,0,0&fov=60");
        let (f, _, u) = cam.basis();
        let dist = 1.0e7;
        let mut last = 0.0;
        for deg in [0.0f64, 20.0, 29.9, 31.0, 40.0, 60.0, 80.0] {
            let t = deg.to_radians();
            let centre = cam.eye + (f * t.cos() + u * t.sin()) * dist;
            let beyond = (t - 30f64.to_radians()).max(0.0);
            let q = beyond.sin() / 30f64.to_radians().tan();
            let threshold = view.c_land * dist * (1.0 + 20.0 * q * q);
            assert!(view.wants_split(threshold * 1.000_001, centre, 0.0, false), "{deg}°");
            assert!(!view.wants_split(threshold * 0.999_999, centre, 0.0, false), "{deg}°");
            assert!(threshold >= last, "{deg}°");
            last = threshold;
        }
        // 80° off the axis is 50° beyond the top (q = 1.327): edges must be 36.2 times longer.
        assert!((last / (view.c_land * dist) - 36.2).abs() < 0.05, "{}", last / (view.c_land * dist));
    }

    /// The threshold factor `1 + 20 q²` of eq. 6 at `centre` (a point, radius 0), from when a
    /// split starts: the smallest `lod_len` that splits, over `c_land` times the distance.
    fn eq6_factor(view: &View, centre: DVec3) -> f64 {
        let d = centre.distance(view.eye);
        let (mut lo, mut hi) = (view.c_land * d * 0.5, view.c_land * d * 1e6);
        for _ in 0..200 {
            let mid = (lo * hi).sqrt();
            if view.wants_split(mid, centre, 0.0, false) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        hi / (view.c_land * d)
    }

    /// Left and right of the frustum, eq. 6 counts in the horizontal half field of view (clip
    /// space's x), above and below in the vertical one.
    #[test]
    fn each_side_counts_in_its_own_half_field_of_view() {
        let (cam, view) = camera_and_view("eye=0,0,2e7&target=0,0,0&fov=60&width=1920&height=1080");
        let (f, r, u) = cam.basis();
        let tan_v = 30f64.to_radians().tan();
        let tan_h = tan_v * 1920.0 / 1080.0;
        let (half_h, dist) = (tan_h.atan(), 1.0e7);
        for beyond in [5f64, 10.0, 20.0] {
            let b = beyond.to_radians();
            let t = half_h + b;
            let right = cam.eye + (f * t.cos() + r * t.sin()) * dist;
            let q = b.sin() / tan_h;
            assert!((eq6_factor(&view, right) - (1.0 + C_LOD * q * q)).abs() < 1e-6, "{beyond}° right");
            let t = 30f64.to_radians() + b;
            let above = cam.eye + (f * t.cos() + u * t.sin()) * dist;
            let q = b.sin() / tan_v;
            assert!((eq6_factor(&view, above) - (1.0 + C_LOD * q * q)).abs() < 1e-6, "{beyond}° above");
        }
    }

    /// Behind the eye the falloff stays as strong as beside it: ground behind a telephoto
    /// camera needs edges about as long as ground at right angles to the view (the side planes
    /// alone asked 40 times less right behind it), and right behind, longer.
    #[test]
    fn behind_the_eye_is_as_coarse_as_beside_it() {
        let (cam, view) = camera_and_view("eye=0,0,2e7&target=0,0,0&fov=10");
        let (f, _, u) = cam.basis();
        let dist = 1.0e6;
        let factor = |deg: f64| {
            let t = deg.to_radians();
            eq6_factor(&view, cam.eye + (f * t.cos() + u * t.sin()) * dist)
        };
        let beside = factor(90.0);
        for deg in (91..=180).step_by(3) {
            // The least, ~137.5°, where the top plane's excess (sin(θ - 5°)) meets the
            // behind plane's (-cos θ): q is 0.74 of its value at 90°.
            assert!(factor(deg as f64) > 0.5 * beside, "{deg}°");
        }
        // Right behind: q = 1 / tan(5°).
        let q = 1.0 / 5f64.to_radians().tan();
        let behind = factor(180.0);
        assert!((behind - (1.0 + C_LOD * q * q)).abs() / behind < 1e-6, "{behind}");
        assert!(behind > beside);
    }

    /// Seen from far away (more than a hemisphere's worth of horizon angle), terrain as high as
    /// `top` at the limb is still in view; beyond the limb it is culled.
    #[test]
    fn the_horizon_of_a_far_eye_keeps_the_limb() {
        let d = 1.0e8;
        let (_, view) = camera_and_view(&format!("eye={d},0,0&target=0,0,0"));
        let beyond = (R / d).acos() + (R / (R + TOP)).acos();
        assert!(beyond > std::f64::consts::FRAC_PI_2);
        let at = |angle: f64, height: f64| DVec3::new(angle.cos(), angle.sin(), 0.0) * (R + height);
        let long = 1e9;
        assert!(view.wants_split(long, at(beyond - 1e-4, TOP), 0.0, false));
        assert!(view.wants_split(long, at(beyond - 1e-4, TOP * 0.5), 0.0, false));
        assert!(!view.wants_split(long, at(beyond + 1e-3, TOP), 0.0, false));
        assert!(!view.wants_split(long, at(beyond + 1e-3, 0.0), 0.0, false));
    }

    #[test]
    fn nearer_and_longer_edges_split_first() {
        let (_, view) = camera_and_view("eye=7e6,0,0&target=0,0,0");
        let near = DVec3::new(R, 0.0, 0.0);
        assert!(view.wants_split(100_000.0, near, 0.0, false));
        assert!(!view.wants_split(100.0, near, 0.0, false));
        // Behind the planet: never.
        assert!(!view.wants_split(1.0e6, -near, 0.0, false));
        // Sea needs longer edges than land.
        let l = 12_000.0;
        assert!(view.wants_split(l, near, 0.0, false) && !view.wants_split(l, near, 0.0, true));
    }
}
