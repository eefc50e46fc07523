//! The climate lookup of paper §3.3, with the planet's moisture: ground colour from geographic
//! latitude, altitude (metres relative to sea level) and the climate's mean annual
//! precipitation, and sea colour from water depth.
//!
//! A land colour is made in three steps. First a *zone* colour comes from the absolute
//! latitude, interpolated linearly between the key latitudes of the climate's row below:
//! vegetation, tundra or ice. The *vegetation* colour follows the climate's moisture, not the
//! latitude: the aridity index `AI = P / E0` (precipitation over potential evaporation, both
//! from [`crate::planet::climate`], so that the colours agree with the rivers' runoff) picks
//! desert below 0.15, steppe from 0.3 to 0.35 and forest above 0.75, blended smoothly in
//! between; forest
//! with `AI` above 1.2 turns to tropical forest where the mean temperature passes 20-24 °C.
//! The model's `E0` (from temperature alone) falls short of a Penman estimate in hot dry air,
//! so its `AI` runs high: the bounds sit above UNEP's (arid 0.05-0.2, semi-arid 0.2-0.5,
//! humid above 0.65): the desert's, placed so that 25 arid places of known Köppen class get
//! their colour where the climate gives them little rain (measured in docs/realism.md).
//! So the Sahara is desert and the Ganges plain green, both at 25°N. Then altitude tints the
//! colour slowly towards bare rock (at most 35% by the tree line), blends it fully to rock
//! above the tree line and to snow above the snow line. The paper preset's snow line falls with
//! latitude, `snow(lat) = snow_eq * (1 - (|lat| / ice_lat)^3)`: nearly flat in the tropics, 0 m
//! at `ice_lat` and below sea level poleward of it, so ice caps are white down to the coast.
//! The tree line lies at three quarters of the snow line's altitude. Both blends are smooth,
//! over ±300 m (rock) and ±150 m (snow), so the colours have no hard bands.
//!
//! For the paper's preset the lines sit higher than Earth's because its planets are higher: with
//! Table 2's defaults land reaches `a_max_mountain - epsilon_sea` = 10 km above sea level and
//! half of it lies above about 4.5 km, so an Earth snow line would whiten most continents. The
//! Earth preset, whose land lies at Earth's altitudes (a real DEM's, or a random planet's median
//! of ~580 m), takes Earth's climatic snow line instead ([`EARTH_SNOW_LINE`]: ~4.9 km at the
//! equator, ~5.6 km in the dry subtropics and Tibet, ~2.9 km at the Alps' 46°, ~1.2 km at 62°, sea level
//! near 76°), scaled for the other climates by their `snow_eq` against the temperate one's.
//!
//! | climate   | zones by absolute latitude (key points, °)            | rain  | snow_eq | ice_lat |
//! |-----------|-------------------------------------------------------|-------|---------|---------|
//! | Temperate | 0-58 vegetation, 64-69 tundra, 72-90 ice cap          | x1    | 7500 m  | 72°     |
//! | Arid      | 0-62 vegetation, 66-78 tundra, 82-90 ice cap          | x0.35 | 8500 m  | 82°     |
//! | Frozen    | 0-18 vegetation, 28-48 tundra, 55-90 ice cap          | x1    | 4000 m  | 55°     |
//!
//! (The arid climate's colours take a third of the model's rain: deserts spread to 45°.) A mesh
//! without a climate ([`crate::mesh::Mesh::precipitation`] `None`) takes the model's zonal
//! precipitation (over land and sea: steppe in the subtropics, forest elsewhere).
//!
//! Colours (sRGB): tropical forest (30, 95, 40), forest (50, 110, 45), steppe (145, 160, 85),
//! desert (215, 190, 130), tundra (150, 150, 120), ice (235, 242, 250), rock (125, 110, 100),
//! snow (250, 250, 252); steep land, whatever grows or lies on it, is bare rock
//! ([`on_slope`]: 30-45°, in views, tiles and renders alike). Sea: `water_colour` runs from
//! (120, 190, 215) at the coast to (10, 30, 90) at 6000 m depth along a square-root curve
//! (shelves stay light).

use crate::mesh::Mesh;
use crate::params::{Climate, Params, Preset};
use crate::planet::climate::{potential_evaporation_mm, smoothstep, temperature_c, zonal_mm};

type Rgb = [f64; 3];

const TROPICAL: Rgb = [30.0, 95.0, 40.0];
const FOREST: Rgb = [50.0, 110.0, 45.0];
const STEPPE: Rgb = [145.0, 160.0, 85.0];
const DESERT: Rgb = [215.0, 190.0, 130.0];
const TUNDRA: Rgb = [150.0, 150.0, 120.0];
const ICE: Rgb = [235.0, 242.0, 250.0];
const ROCK: Rgb = [125.0, 110.0, 100.0];
const SNOW: Rgb = [250.0, 250.0, 252.0];
const SHALLOW: Rgb = [120.0, 190.0, 215.0];
const DEEP: Rgb = [10.0, 30.0, 90.0];

/// Depth at which the sea reaches its darkest colour.
pub const DEEPEST_M: f64 = 6000.0;
/// Tree line altitude as a share of the snow line's.
const TREE_SHARE: f64 = 0.75;
/// Share of rock in the colour just below the tree line.
const HIGHLAND_TINT: f64 = 0.35;

/// Altitude range of `climate_texture`'s x axis.
pub const TEXTURE_MIN_ALTITUDE_M: f64 = -500.0;
pub const TEXTURE_MAX_ALTITUDE_M: f64 = 9000.0;
/// Precipitation at the end of `climate_texture`'s z axis (mm/yr), which runs over
/// `sqrt(P / TEXTURE_MAX_PRECIP_MM)`: finer where the colours change (deserts to steppe).
pub const TEXTURE_MAX_PRECIP_MM: f64 = 4000.0;

/// Aridity index (P / E0) spans of the vegetation's blends: desert to steppe, steppe to
/// forest, forest to tropical forest (where warm); and the mean temperatures (°C) over which
/// wet forest turns tropical.
const DESERT_AI: (f64, f64) = (0.15, 0.3);
const STEPPE_AI: (f64, f64) = (0.35, 0.75);
const RAINFOREST_AI: (f64, f64) = (0.8, 1.2);
const RAINFOREST_C: (f64, f64) = (20.0, 24.0);

/// What covers the ground at a latitude, before altitude.
#[derive(Clone, Copy)]
enum Zone {
    /// Desert, steppe or forest by the climate's moisture ([`vegetation`]).
    Vegetation,
    Tundra,
    Ice,
}

struct Profile {
    zones: &'static [(f64, Zone)],
    /// Share of the climate model's precipitation the colours take.
    rain: f64,
    snow_eq: f64,
    ice_lat: f64,
}

fn profile(climate: Climate) -> Profile {
    use Zone::{Ice, Tundra, Vegetation};
    match climate {
        Climate::Temperate => Profile {
            zones: &[(0.0, Vegetation), (58.0, Vegetation), (64.0, Tundra), (69.0, Tundra), (72.0, Ice), (90.0, Ice)],
            rain: 1.0,
            snow_eq: 7500.0,
            ice_lat: 72.0,
        },
        Climate::Arid => Profile {
            zones: &[(0.0, Vegetation), (62.0, Vegetation), (66.0, Tundra), (78.0, Tundra), (82.0, Ice), (90.0, Ice)],
            rain: 0.35,
            snow_eq: 8500.0,
            ice_lat: 82.0,
        },
        Climate::Frozen => Profile {
            zones: &[(0.0, Vegetation), (18.0, Vegetation), (28.0, Tundra), (48.0, Tundra), (55.0, Ice), (90.0, Ice)],
            rain: 1.0,
            snow_eq: 4000.0,
            ice_lat: 55.0,
        },
    }
}

/// The vegetation's colour where `precip_mm` falls a year at a latitude and altitude: by the
/// aridity index and, for rain forest, the mean temperature (see the module's doc).
fn vegetation(lat: f64, altitude_m: f64, precip_mm: f64) -> Rgb {
    let p = precip_mm.max(0.0);
    let e0 = potential_evaporation_mm(lat, altitude_m, p);
    let ai = if e0 > 0.0 { p / e0 } else { f64::INFINITY };
    let dry = mix(DESERT, STEPPE, smoothstep(DESERT_AI.0, DESERT_AI.1, ai));
    let green = mix(dry, FOREST, smoothstep(STEPPE_AI.0, STEPPE_AI.1, ai));
    let warm = smoothstep(RAINFOREST_C.0, RAINFOREST_C.1, temperature_c(lat, altitude_m));
    mix(green, TROPICAL, smoothstep(RAINFOREST_AI.0, RAINFOREST_AI.1, ai) * warm)
}

fn mix(a: Rgb, b: Rgb, t: f64) -> Rgb {
    let t = t.clamp(0.0, 1.0);
    [0, 1, 2].map(|i| a[i] + (b[i] - a[i]) * t)
}

fn to_u8(c: Rgb) -> [u8; 3] {
    c.map(|x| x.round().clamp(0.0, 255.0) as u8)
}

/// The zone colour at an absolute latitude, `veg` standing for the vegetation's.
fn zone_colour(zones: &[(f64, Zone)], lat: f64, veg: Rgb) -> Rgb {
    let colour = |z: Zone| match z {
        Zone::Vegetation => veg,
        Zone::Tundra => TUNDRA,
        Zone::Ice => ICE,
    };
    let lat = lat.abs().min(90.0);
    for w in zones.windows(2) {
        let ((l0, z0), (l1, z1)) = (w[0], w[1]);
        if lat <= l1 {
            return mix(colour(z0), colour(z1), (lat - l0) / (l1 - l0));
        }
    }
    colour(zones[zones.len() - 1].1)
}

/// What the colours depend on besides latitude and altitude: the climate, and the preset whose
/// altitudes the snow line must suit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Palette {
    pub climate: Climate,
    pub preset: Preset,
}

impl Palette {
    pub fn of(params: &Params) -> Palette {
        Palette { climate: params.climate, preset: params.preset }
    }

    /// Every palette, for renderers that prepare their textures once.
    pub const ALL: [Palette; 6] = {
        let (e, p) = (Preset::Earth, Preset::Paper);
        [
            Palette { climate: Climate::Temperate, preset: e },
            Palette { climate: Climate::Arid, preset: e },
            Palette { climate: Climate::Frozen, preset: e },
            Palette { climate: Climate::Temperate, preset: p },
            Palette { climate: Climate::Arid, preset: p },
            Palette { climate: Climate::Frozen, preset: p },
        ]
    };
}

/// Earth's climatic snow line (m above sea level) by absolute latitude (°), linear between:
/// ~4.9 km in the wet tropics, ~5.6 km in the dry subtropics and continental interiors to 35°
/// (the Andes' Puna and Tibet reach 6 km), ~2.9 km in the Alps, ~1.2 km in southern Norway, sea level
/// in the high Arctic (after the compilations in Benn & Evans, *Glaciers and Glaciation*, 2010,
/// and Ohmura et al. 1992). Below sea level poleward of 76°, so ice caps are white to the coast.
pub const EARTH_SNOW_LINE: [(f64, f64); 11] = [
    (0.0, 4_900.0),
    (15.0, 5_200.0),
    (25.0, 5_600.0),
    (35.0, 5_600.0),
    (40.0, 4_300.0),
    (46.0, 2_900.0),
    (55.0, 1_900.0),
    (62.0, 1_200.0),
    (70.0, 400.0),
    (76.0, 0.0),
    (90.0, -2_000.0),
];

/// Snow line altitude (m relative to sea level; negative poleward of the ice-cap latitude).
pub fn snow_line_m(palette: Palette, lat_deg: f64) -> f64 {
    let p = profile(palette.climate);
    let lat = lat_deg.abs().min(90.0);
    match palette.preset {
        Preset::Paper => {
            let x = lat / p.ice_lat;
            p.snow_eq * (1.0 - x * x * x)
        }
        Preset::Earth => {
            let scale = p.snow_eq / profile(Climate::Temperate).snow_eq;
            let line = EARTH_SNOW_LINE
                .windows(2)
                .find(|w| lat <= w[1].0)
                .map_or(EARTH_SNOW_LINE[10].1, |w| w[0].1 + (w[1].1 - w[0].1) * (lat - w[0].0) / (w[1].0 - w[0].0));
            line * scale
        }
    }
}

/// Land colour for a latitude (degrees), a ground altitude (metres relative to sea level) and
/// the climate's precipitation there (mm/yr, [`precipitation_mm`]).
pub fn climate_colour(palette: Palette, lat_deg: f64, altitude_m: f64, precip_mm: f64) -> [u8; 3] {
    let p = profile(palette.climate);
    let lat = if lat_deg.is_finite() { lat_deg } else { 0.0 };
    let alt = if altitude_m.is_finite() { altitude_m } else { 0.0 };
    let rain = if precip_mm.is_finite() { precip_mm * p.rain } else { 0.0 };
    let base = zone_colour(p.zones, lat, vegetation(lat, alt, rain));
    let snow = snow_line_m(palette, lat);
    let tree = snow * TREE_SHARE;
    let tinted = if tree > 0.0 { mix(base, ROCK, HIGHLAND_TINT * smoothstep(0.0, tree, alt)) } else { base };
    let rocky = mix(tinted, ROCK, smoothstep(tree - 300.0, tree + 300.0, alt));
    to_u8(mix(rocky, SNOW, smoothstep(snow - 150.0, snow + 150.0, alt)))
}

/// Slopes (degrees from the horizontal) over which land turns to bare rock: none below the
/// first, all above the second (cliffs and rock walls, on which neither plants nor snow hold).
/// Loose rock and soil rest up to about 35° (their angle of repose); the mesh's slopes at a
/// view's resolution are 0.7-0.8 of real ones at the same spacing (docs/realism.md), hence
/// five degrees less.
pub const BARE_ROCK_SLOPE_DEG: [f64; 2] = [30.0, 45.0];

/// The share of bare rock on land whose normal makes an angle of cosine `cos_slope` with the
/// local up: 1 - smoothstep(cos 50°, cos 35°, cos_slope), as the renderer computes it.
pub fn bare_rock_share(cos_slope: f64) -> f64 {
    let [gentle, steep] = BARE_ROCK_SLOPE_DEG.map(|d| d.to_radians().cos());
    if cos_slope.is_finite() {
        1.0 - smoothstep(steep, gentle, cos_slope)
    } else {
        0.0
    }
}

/// Bare rock's colour in linear light (the renderer's uniform; `ROCK` is sRGB).
pub fn rock_linear() -> [f64; 3] {
    ROCK.map(|c| srgb_to_linear(c / 255.0))
}

/// An sRGB component (0-1) in linear light.
pub(crate) fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

fn linear_to_srgb(l: f64) -> f64 {
    if l <= 0.003_130_8 {
        l * 12.92
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    }
}

/// A land colour (sRGB) on a slope of cosine `cos_slope`: mixed towards bare rock by
/// [`bare_rock_share`], in linear light as the renderer mixes it.
pub fn on_slope(srgb: [u8; 3], cos_slope: f64) -> [u8; 3] {
    let t = bare_rock_share(cos_slope);
    if t <= 0.0 {
        return srgb;
    }
    let rock = rock_linear();
    std::array::from_fn(|i| {
        let l = srgb_to_linear(f64::from(srgb[i]) / 255.0);
        (linear_to_srgb(l + (rock[i] - l) * t) * 255.0).round().clamp(0.0, 255.0) as u8
    })
}

/// The climate's mean annual precipitation (mm) at a latitude and longitude of `mesh`: its
/// planet's ([`crate::mesh::Mesh::precipitation`]), else the climate model's zonal mean.
pub fn precipitation_mm(mesh: &Mesh, lat_deg: f64, lon_deg: f64) -> f64 {
    match mesh.precipitation.as_deref() {
        Some(field) => field.at(lat_deg, lon_deg),
        None => zonal_mm(lat_deg),
    }
}

/// Land colour of a point `p` (planet frame) of `mesh` at a ground altitude (metres relative
/// to sea level), with the mesh's climate.
pub fn ground_colour(mesh: &Mesh, palette: Palette, p: glam::DVec3, altitude_m: f64) -> [u8; 3] {
    let (lat, lon) = crate::geo::lat_lon(p);
    climate_colour(palette, lat, altitude_m, precipitation_mm(mesh, lat, lon))
}

/// Whether vertex `v` of `mesh` is coloured as land: a land kind's vertex (rivers included)
/// unless, under an elevation map, it lies in the sea (a land or shore split the map put under
/// it), or a sea split's above sea level. (Under an elevation map the coast follows the map,
/// not the base mesh's coast edges: `mesh/split/altitude.rs`.)
fn on_land(mesh: &Mesh, vert: &crate::mesh::Vertex, sea: f64) -> bool {
    use crate::mesh::VertexFlags;
    let land = VertexFlags(VertexFlags::COAST.0 | VertexFlags::CONTINENT.0 | VertexFlags::RIVER.0);
    if vert.ground > sea {
        return true;
    }
    let in_sea = mesh.guide.is_some() && crate::mesh::split::altitude::at_sea(vert, sea);
    vert.flags.intersects(land) && !in_sea
}

/// The colour a view or tile gives vertex `v` of `mesh` (sRGB): water by depth off land, the
/// climate's ground colour on land (river vertices included).
pub fn vertex_colour(mesh: &Mesh, params: &Params, v: usize) -> [u8; 3] {
    let vert = &mesh.vertices[v];
    let sea = params.sea_level_m;
    if on_land(mesh, vert, sea) {
        ground_colour(mesh, Palette::of(params), vert.p(), vert.ground - sea)
    } else {
        water_colour(sea - vert.ground)
    }
}

/// [`vertex_colour`] on the vertex's slope: land whose unit `normal` (planet frame) is steep
/// turns to bare rock ([`on_slope`]); water keeps its colour.
pub fn surface_colour(mesh: &Mesh, params: &Params, v: usize, normal: glam::DVec3) -> [u8; 3] {
    let vert = &mesh.vertices[v];
    let colour = vertex_colour(mesh, params, v);
    if on_land(mesh, vert, params.sea_level_m) {
        on_slope(colour, normal.normalize_or_zero().dot(vert.p().normalize_or_zero()))
    } else {
        colour
    }
}

/// Sea colour for a water depth in metres (light at the coast, dark in the deep sea).
pub fn water_colour(depth_m: f64) -> [u8; 3] {
    let d = if depth_m.is_finite() { depth_m.max(0.0) } else { 0.0 };
    to_u8(mix(SHALLOW, DEEP, (d / DEEPEST_M).min(1.0).sqrt()))
}

/// The lookup as an RGBA8 3D texture (`width * height * depth * 4` bytes, x fastest, then y,
/// then z): x runs over the altitude from -500 m to 9000 m, y over the absolute latitude from
/// 90° (row 0) to 0°, z over `sqrt(P / 4000 mm)` from 0 to 1, all sampled at texel centres.
/// Alpha is 255.
pub fn climate_texture(palette: Palette, width: u32, height: u32, depth: u32) -> Vec<u8> {
    use rayon::prelude::*;
    let (w, h, d) = (width as usize, height as usize, depth as usize);
    let span = TEXTURE_MAX_ALTITUDE_M - TEXTURE_MIN_ALTITUDE_M;
    (0..d * h)
        .into_par_iter()
        .flat_map_iter(|zy| {
            let (z, y) = (zy / h, zy % h);
            let lat = 90.0 - (y as f64 + 0.5) * 90.0 / h as f64;
            let root = (z as f64 + 0.5) / d as f64;
            let precip = root * root * TEXTURE_MAX_PRECIP_MM;
            (0..w).flat_map(move |x| {
                let alt = TEXTURE_MIN_ALTITUDE_M + (x as f64 + 0.5) * span / w as f64;
                let [r, g, b] = climate_colour(palette, lat, alt, precip);
                [r, g, b, 255]
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The paper preset's palette of `climate`.
    fn paper(climate: Climate) -> Palette {
        Palette { climate, preset: Preset::Paper }
    }

    fn earth(climate: Climate) -> Palette {
        Palette { climate, preset: Preset::Earth }
    }

    fn close(a: [u8; 3], b: Rgb, tol: i32) -> bool {
        a.iter().zip(b).all(|(&x, y)| (x as i32 - y as i32).abs() <= tol)
    }

    /// Land colour at sea level-ish altitudes in the temperate palette.
    fn temperate(lat: f64, alt: f64, precip: f64) -> [u8; 3] {
        climate_colour(paper(Climate::Temperate), lat, alt, precip)
    }

    #[test]
    fn vegetation_follows_moisture_and_zones_latitude() {
        // The Sahara and the Ganges plain lie at the same latitude.
        assert!(close(temperate(25.0, 200.0, 30.0), DESERT, 1));
        assert!(close(temperate(-25.0, 200.0, 30.0), DESERT, 1), "symmetric in latitude");
        let ganges = temperate(25.5, 60.0, 1100.0);
        assert!(ganges[1] > ganges[0] + 30, "{ganges:?}");
        // Semi-arid: steppe (the Sahel, the Great Plains' west).
        assert!(close(temperate(14.0, 300.0, 400.0), STEPPE, 25), "{:?}", temperate(14.0, 300.0, 400.0));
        // Wet and warm: rain forest; wet and cool: forest.
        assert!(close(temperate(0.0, 100.0, 2400.0), TROPICAL, 1));
        assert!(close(temperate(50.0, 100.0, 800.0), FOREST, 1));
        // Cold zones by latitude, whatever the rain.
        assert!(close(temperate(66.0, 10.0, 300.0), TUNDRA, 1));
        let pole = temperate(85.0, 0.0, 100.0);
        assert!(close(pole, SNOW, 20) || close(pole, ICE, 20));
        // More rain is never browner.
        let mut last = i32::MIN + 1;
        for p in (0..4000).step_by(50) {
            let g = i32::from(temperate(30.0, 100.0, p as f64)[1]) - i32::from(temperate(30.0, 100.0, p as f64)[0]);
            assert!(g >= last - 1, "{p} mm");
            last = g;
        }
        // Without a climate, the zonal mean: green tropics.
        let mesh = Mesh::default();
        assert!(close(temperate(0.0, 100.0, precipitation_mm(&mesh, 0.0, 10.0)), TROPICAL, 1));
        assert_eq!(temperate(10.0, 10.0, f64::NAN), temperate(10.0, 10.0, 0.0));
    }

    #[test]
    fn snow_line_falls_with_latitude_and_mountains_turn_white() {
        for c in [Climate::Temperate, Climate::Arid, Climate::Frozen] {
            let mut last = f64::INFINITY;
            for lat in 0..=90 {
                let s = snow_line_m(paper(c), lat as f64);
                assert!(s <= last);
                last = s;
            }
            assert!(close(climate_colour(paper(c), 0.0, 9000.0, 1000.0), SNOW, 1), "{c:?}");
        }
        // Rock between tree line and snow line at the equator.
        assert!(close(climate_colour(paper(Climate::Temperate), 0.0, 6500.0, 1000.0), ROCK, 1));
    }

    #[test]
    fn the_earth_preset_has_earths_snow_line() {
        let t = earth(Climate::Temperate);
        // Alps (46°N): snow at 3,200 m, none at 2,400 m; the paper's line is far higher there.
        assert!(close(climate_colour(t, 46.0, 3_200.0, 800.0), SNOW, 30));
        assert!(!close(climate_colour(t, 46.0, 2_400.0, 800.0), SNOW, 30));
        assert!(!close(climate_colour(paper(Climate::Temperate), 46.0, 3_200.0, 800.0), SNOW, 30));
        // Himalaya (28°N): snow on the 6 km crests, none on a 4.8 km plateau.
        assert!(close(climate_colour(t, 28.0, 6_000.0, 800.0), SNOW, 30));
        assert!(!close(climate_colour(t, 28.0, 4_800.0, 800.0), SNOW, 30));
        // Norway (62°N): snow at 1,500 m. Greenland's coast (78°N): ice.
        assert!(close(climate_colour(t, 62.0, 1_500.0, 800.0), SNOW, 30));
        assert!(snow_line_m(t, 78.0) < 0.0);
        // Poleward of the subtropics the line only falls; drier climates raise it.
        let mut last = f64::INFINITY;
        for lat in 25..=90 {
            let s = snow_line_m(t, lat as f64);
            assert!(s <= last, "{lat}");
            last = s;
        }
        assert!(snow_line_m(earth(Climate::Arid), 30.0) > snow_line_m(t, 30.0));
        assert!(snow_line_m(earth(Climate::Frozen), 30.0) < snow_line_m(t, 30.0));
    }

    /// Forest and snow stay on slopes up to 30°, are half rock at 38° and all rock from 45°;
    /// the mix is in linear light (as the renderer's), and only land turns to rock.
    #[test]
    fn steep_land_is_bare_rock() {
        let cos = |deg: f64| deg.to_radians().cos();
        let forest = to_u8(FOREST);
        let snow = to_u8(SNOW);
        for c in [forest, snow] {
            assert_eq!(on_slope(c, 1.0), c);
            assert_eq!(on_slope(c, cos(29.9)), c);
            assert!(close(on_slope(c, cos(45.0)), ROCK, 0), "{:?}", on_slope(c, cos(45.0)));
            assert!(close(on_slope(c, cos(80.0)), ROCK, 0));
        }
        assert!((bare_rock_share((cos(30.0) + cos(45.0)) / 2.0) - 0.5).abs() < 1e-9);
        assert!((0.4..0.5).contains(&bare_rock_share(cos(37.5))));
        let mut last = 0.0;
        for deg in 0..=90 {
            let share = bare_rock_share(cos(f64::from(deg)));
            assert!(share >= last, "{deg}°");
            last = share;
        }
        assert_eq!(bare_rock_share(f64::NAN), 0.0);
        // Half way, in linear light: brighter than the mean of the sRGB bytes.
        let half = on_slope(snow, cos(37.5));
        let bytes_mean = (f64::from(snow[0]) + ROCK[0]) / 2.0;
        assert!(f64::from(half[0]) > bytes_mean + 5.0, "{half:?}");
        // A steep vertex of a planet: rock on land, the sea floor keeps the sea's colour.
        let planet = crate::export::test_planet();
        let params = crate::params::Params::default();
        let mesh = &planet.mesh;
        let land = (0..mesh.vertices.len())
            .find(|&v| mesh.vertices[v].flags.intersects(crate::mesh::VertexFlags::CONTINENT))
            .unwrap();
        let sea = (0..mesh.vertices.len()).find(|&v| mesh.vertices[v].flags == crate::mesh::VertexFlags::SEA).unwrap();
        for (v, rock) in [(land, true), (sea, false)] {
            let up = mesh.pos(v as u32).normalize();
            let side = up.any_orthonormal_vector();
            assert_eq!(surface_colour(mesh, &params, v, up), vertex_colour(mesh, &params, v));
            let cliff = surface_colour(mesh, &params, v, (up + 3.0 * side).normalize());
            assert_eq!(close(cliff, ROCK, 0), rock, "vertex {v}: {cliff:?}");
        }
    }

    #[test]
    fn climates_shift_the_belts() {
        // Arid has desert where temperate has steppe; frozen has ice where temperate has forest.
        let c = |climate, lat, alt, p| climate_colour(paper(climate), lat, alt, p);
        assert!(close(c(Climate::Arid, 40.0, 100.0, 300.0), DESERT, 1));
        assert!(!close(c(Climate::Temperate, 40.0, 100.0, 300.0), DESERT, 30));
        assert!(close(c(Climate::Frozen, 60.0, 100.0, 800.0), SNOW, 1));
        assert!(close(c(Climate::Arid, 0.0, 7200.0, 800.0), ROCK, 1));
        assert!(close(c(Climate::Temperate, 0.0, 8000.0, 800.0), SNOW, 1));
        assert!(close(c(Climate::Temperate, 55.0, 100.0, 800.0), FOREST, 1));
        assert!(close(c(Climate::Temperate, 66.0, 10.0, 800.0), TUNDRA, 1));
    }

    #[test]
    fn water_darkens_with_depth() {
        let mut last = 255 * 3 + 1;
        for d in (0..8000).step_by(250) {
            let c = water_colour(d as f64);
            let sum: u32 = c.iter().map(|&x| x as u32).sum();
            assert!(sum <= last, "depth {d}");
            last = sum;
        }
        assert!(close(water_colour(0.0), SHALLOW, 0));
        assert!(close(water_colour(10_000.0), DEEP, 0));
        assert_eq!(water_colour(f64::NAN), water_colour(0.0));
    }

    #[test]
    fn texture_axes() {
        let (w, h, d) = (64u32, 16u32, 8u32);
        let tex = climate_texture(paper(Climate::Temperate), w, h, d);
        assert_eq!(tex.len(), (w * h * d * 4) as usize);
        assert!(tex.chunks(4).all(|p| p[3] == 255));
        let at = |x: u32, y: u32, z: u32| {
            let i = (((z * h + y) * w + x) * 4) as usize;
            [tex[i], tex[i + 1], tex[i + 2]]
        };
        // Row 0 is the pole: ice at any altitude; the last column is above the snow line.
        assert!(close(at(0, 0, 3), ICE, 20) || close(at(0, 0, 3), SNOW, 20));
        assert!(close(at(w - 1, h - 1, 3), SNOW, 1));
        // Low altitude at 25° (row ~ 11): desert in the first layer, green in the last.
        let y = ((90.0 - 25.0) / 90.0 * h as f64) as u32;
        assert!(close(at(3, y, 0), DESERT, 1));
        assert!(at(3, y, d - 1)[1] > at(3, y, d - 1)[0] + 30);
        // Texel centres: the layer's precipitation.
        let root = 2.5 / f64::from(d);
        let lat = 90.0 - (f64::from(y) + 0.5) * 90.0 / f64::from(h);
        let alt = TEXTURE_MIN_ALTITUDE_M + 3.5 * (TEXTURE_MAX_ALTITUDE_M - TEXTURE_MIN_ALTITUDE_M) / f64::from(w);
        let direct = climate_colour(paper(Climate::Temperate), lat, alt, root * root * TEXTURE_MAX_PRECIP_MM);
        assert_eq!(at(3, y, 2), direct);
        assert_eq!(tex, climate_texture(paper(Climate::Temperate), w, h, d));
    }
}
