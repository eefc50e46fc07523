//! A planet's climate: mean annual precipitation, temperature, evaporation and runoff, from its
//! land, its altitudes and its latitudes, on a 1° latitude/longitude grid. It decides which
//! basins hold water enough to overflow to the sea and which end in a terminal lake
//! ([`super::basins`]). The model is deliberately small and works for any planet:
//!
//! 1. **Zonal precipitation** `P0(lat)` over and next to the ocean: wet tropics, dry
//!    subtropics (20-30°), wet mid-latitudes, dry poles (key points in [`ZONAL_MM`], after the
//!    zonal means of the GPCP climatology).
//! 2. **Moisture carried by the prevailing winds**: the trades blow from the east between the
//!    equator and 30°, the westerlies from the west between 30° and 60°, polar easterlies
//!    beyond. Along each row of the grid, in the wind's direction, the air's moisture `m` is 1
//!    over the ocean and decays over land with distance (e-folding [`TROPICAL_DECAY_KM`] in the
//!    tropics, where rain evaporates and falls again, [`DECAY_KM`] in the subtropics and
//!    mid-latitudes, [`BOREAL_DECAY_KM`] in the boreal zone, blended between) and with uplift:
//!    air that climbs `dh` keeps `exp(-dh / UPLIFT_M)` of its moisture and rains the rest on the
//!    windward slope ([`OROGRAPHIC_GAIN`]). Leeward of a range is a rain shadow.
//! 3. **Poleward flow** between 10° and 50°: along each column from the equator, tropical
//!    moist air ([`POLEWARD_MM`]) carried and rained out the same way, a stand-in for the
//!    monsoons and the continents' wet eastern flanks. It takes its moisture from seas east of
//!    land (warm currents); off west coasts (cold currents) it gets [`COLD_SEA`] of it. It
//!    reaches [`MONSOON_REACH_KM`] west of the open ocean to the east (a sea at least
//!    [`OPEN_OCEAN_KM`] wide along the row), fading beyond over [`MONSOON_FADE_KM`]: the
//!    summer monsoons are the western flanks of the subtropical highs, and the land far west of
//!    them lies under their sinking air (Arabia, Iran and the Thar behind the Indian monsoon,
//!    whose Arabian Sea the columns would otherwise carry north onto them).
//! 4. **Distance to the sea** in any direction stands for the other winds: moisture is at
//!    least `NEAR_SEA * exp(-d / NEAR_SEA_KM)` (0.8 and 2,000 km in the tropics; 0.3 of it
//!    under the subtropics' sinking air), times the warmth of that sea outside the inner
//!    tropics: coasts beside cold currents (Atacama, Namib) stay dry.
//! 5. `P = P0(lat) * m` plus the orographic rain, or what the poleward flow brings if more,
//!    times up to [`LAND_GAIN`] where it is wet; then smoothed over land ([`SMOOTH_KM`]) so
//!    that rows and columns of the grid do not show.
//! 6. **Temperature** `T = 28 °C - 30 °C * sin²(lat) - 6.5 °C/km * altitude`; potential
//!    (open-water) evaporation `E0 = 50 mm * T * (1 + 0.8 exp(-P / 400 mm))` per year for
//!    `T > 0`: dry air takes up more.
//! 7. **Runoff** from land: `P - AET` with actual evaporation by Budyko's curve in Fu's form
//!    (`AET / P = 1 + E0/P - (1 + (E0/P)^w)^(1/w)`, `w = 2.6`).

use crate::geo::{direction, lat_lon};
use crate::mesh::raster::SphereRaster;
use crate::mesh::Mesh;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// Zonal precipitation (mm/yr) at key absolute latitudes (°), interpolated linearly.
const ZONAL_MM: [(f64, f64); 12] = [
    (0.0, 2400.0),
    (10.0, 1900.0),
    (20.0, 850.0),
    (25.0, 450.0),
    (30.0, 550.0),
    (35.0, 800.0),
    (40.0, 1000.0),
    (50.0, 1000.0),
    (60.0, 800.0),
    (70.0, 450.0),
    (80.0, 180.0),
    (90.0, 100.0),
];
const TROPICAL_DECAY_KM: f64 = 12000.0;
const DECAY_KM: f64 = 3000.0;
const BOREAL_DECAY_KM: f64 = 15000.0;
/// Over open water the air regains moisture over this fetch; the poleward flow over warm
/// seas, faster.
const FETCH_KM: f64 = 2000.0;
const MONSOON_FETCH_KM: f64 = 1500.0;
/// How fast the air sinks back after a crest (m per km).
const SETTLE_M_PER_KM: f64 = 1.0;
/// Latitudes of the poleward flow, and the share of its moisture that counts.
const POLEWARD_LAT: std::ops::Range<f64> = 10.0..50.0;
const POLEWARD: f64 = 0.8;
/// Sea east of land within this distance feeds the poleward flow fully; other sea this much.
const WARM_KM: f64 = 1500.0;
const COLD_SEA: f64 = 0.3;
/// What the poleward flow rains where it is saturated (mm/yr): tropical air.
const POLEWARD_MM: f64 = 1400.0;
/// Width along a row (km) of a sea that counts as open ocean for the poleward flow's reach.
const OPEN_OCEAN_KM: f64 = 2000.0;
/// Distance (km) west of the open ocean to which the poleward flow reaches fully, and the
/// e-folding length of its fade beyond (Karachi, 5,200 km west of the Pacific along its row,
/// got 900 mm of monsoon without it, 170 mm in reality; Patna, 3,300 km, 1,100 mm).
const MONSOON_REACH_KM: f64 = 4500.0;
const MONSOON_FADE_KM: f64 = 500.0;
/// The wet land's precipitation over what the winds carry: rain that forests give back and that
/// falls again, rising from 1 at 500 mm to this at 1,200 mm. The model's land north of 60°S had
/// a mean of 575 mm against an observed ~800-820 mm (Trenberth et al. 2007: 113,000 km³ a year
/// on the land, Antarctica's ~2,300 km³ on 14 M km² left out), most of the gap in the humid
/// subtropics and tropics (the station table of docs/realism.md). A gain on dry land too
/// (1.4 everywhere: land mean 781 mm) filled the Caspian and the Aral to overflowing.
const LAND_GAIN: f64 = 1.4;
const UPLIFT_M: f64 = 3000.0;
const OROGRAPHIC_GAIN: f64 = 1.5;
const NEAR_SEA: f64 = 0.5;
const TROPICAL_NEAR_SEA: f64 = 0.8;
const TROPICAL_NEAR_SEA_KM: f64 = 2000.0;
const NEAR_SEA_KM: f64 = 800.0;
/// The floor's share under the subtropics' sinking air (20-30°; blended over 10-20° and
/// 25-40°): their other winds bring little rain.
const SUBTROPICAL_NEAR_SEA: f64 = 0.3;
/// Evaporation's rise in dry air, and the rain (mm/yr) below which the air counts as dry.
const DRY_AIR: f64 = 0.5;
const DRY_MM: f64 = 400.0;
/// Standard deviation of the smoothing of the land's precipitation (km).
const SMOOTH_KM: f64 = 200.0;
/// Fu's Budyko parameter.
const FU_W: f64 = 2.6;
const EARTH_RADIUS_KM: f64 = 6371.0;

/// Grid cells per degree, and the grid's size.
const CELLS_PER_DEG: usize = 1;
pub const WIDTH: usize = 360 * CELLS_PER_DEG;
pub const HEIGHT: usize = 180 * CELLS_PER_DEG;

/// Mean annual climate on a global latitude/longitude grid (row 0 at the north pole).
#[derive(Clone, Debug)]
pub struct Climate {
    pub width: usize,
    pub height: usize,
    /// Precipitation, mm per year.
    pub precip_mm: Vec<f32>,
}

/// Zonal precipitation (mm/yr) at a latitude.
pub fn zonal_mm(lat: f64) -> f64 {
    let a = lat.abs().min(90.0);
    let i = ZONAL_MM.iter().position(|&(l, _)| l >= a).unwrap_or(ZONAL_MM.len() - 1).max(1);
    let ((l0, p0), (l1, p1)) = (ZONAL_MM[i - 1], ZONAL_MM[i]);
    p0 + (p1 - p0) * ((a - l0) / (l1 - l0)).clamp(0.0, 1.0)
}

/// Mean annual temperature (°C) at a latitude and altitude above sea level (m).
pub fn temperature_c(lat: f64, altitude_m: f64) -> f64 {
    let s = lat.to_radians().sin();
    28.0 - 30.0 * s * s - 0.0065 * altitude_m.max(0.0)
}

/// Potential (open-water) evaporation, mm per year, where `precip_mm` falls: dry air takes up
/// more (up to [`DRY_AIR`] more in a desert).
pub fn potential_evaporation_mm(lat: f64, altitude_m: f64, precip_mm: f64) -> f64 {
    50.0 * temperature_c(lat, altitude_m).max(0.0) * (1.0 + DRY_AIR * (-precip_mm / DRY_MM).exp())
}

/// Runoff (mm/yr) of land with precipitation `p` and potential evaporation `e0` (Budyko-Fu).
pub fn runoff_mm(p: f64, e0: f64) -> f64 {
    if p <= 0.0 {
        return 0.0;
    }
    let x = e0 / p;
    let aet = p * (1.0 + x - (1.0 + x.powf(FU_W)).powf(1.0 / FU_W));
    (p - aet).max(0.0)
}

/// What a river's floodplain and bed lose a year (mm) where `precip_mm` falls and open water
/// would evaporate `e0_mm`: the net evaporation `e0 - p`, weighted by the square of the
/// aridity `1 - p / e0`, so that deserts take most (the Tarim, Cooper Creek, the Nile through
/// Nubia lose much of their flow on the way) and humid or semi-arid plains little (their
/// floodplains are fed by rain and groundwater too). Nothing where rain exceeds evaporation.
pub fn channel_loss_mm(precip_mm: f64, e0_mm: f64) -> f64 {
    if e0_mm <= precip_mm || e0_mm <= 0.0 {
        return 0.0;
    }
    let aridity = 1.0 - precip_mm.max(0.0) / e0_mm;
    (e0_mm - precip_mm) * aridity * aridity
}

/// Decay length of moisture over land (km) carried by the prevailing winds: long in the inner
/// tropics, where rain evaporates and falls again, and in the boreal zone, whose forests give
/// back much of the rain (Siberia's interior gets 400-500 mm); shorter between. Blended
/// between the zones (10-20° and 40-50°), so that no latitude draws a line across a continent.
fn decay_km(lat: f64) -> f64 {
    let a = lat.abs();
    TROPICAL_DECAY_KM
        + (DECAY_KM - TROPICAL_DECAY_KM) * smoothstep(10.0, 20.0, a)
        + (BOREAL_DECAY_KM - DECAY_KM) * smoothstep(40.0, 50.0, a)
}

/// 0 in the inner tropics, 1 poleward of 20°, smooth between.
fn extratropical(lat: f64) -> f64 {
    smoothstep(10.0, 20.0, lat.abs())
}

/// Hermite step from 0 at `lo` to 1 at `hi`.
pub(crate) fn smoothstep(lo: f64, hi: f64, x: f64) -> f64 {
    let t = ((x - lo) / (hi - lo)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Wind direction along a row: +1 towards the east (westerlies), -1 towards the west.
fn wind(lat: f64) -> i64 {
    if (35.0..60.0).contains(&lat.abs()) {
        1
    } else {
        -1
    }
}

impl Climate {
    /// The climate of a planet from whether each cell of the [`WIDTH`] x [`HEIGHT`] grid is
    /// land and its altitude (m above sea level), row-major from the north-west corner, cell
    /// centres as [`crate::mesh::raster::SphereRaster`] places them.
    pub fn new(cells: &[(bool, f64)]) -> Climate {
        let (w, h) = (WIDTH, HEIGHT);
        assert_eq!(cells.len(), w * h, "one cell per grid cell");
        let step = 1.0 / CELLS_PER_DEG as f64;
        let lat_of = |r: usize| 90.0 - (r as f64 + 0.5) * step;
        let (near, nearest) = sea_distance_km(cells, w, h, step);
        // Moisture along the rows (prevailing winds), then along the columns from the
        // equator (the poleward flow on the continents' eastern flanks).
        // Moisture of the sea: full for the prevailing winds; for the poleward flow only on a
        // continent's eastern flank (land within WARM_KM to the west: warm western boundary
        // currents), not off west coasts, where cold currents flow.
        let full = vec![1.0f64; w * h];
        let mut warm = vec![COLD_SEA; w * h];
        for r in 0..h {
            let dx = step.to_radians() * EARTH_RADIUS_KM * lat_of(r).to_radians().cos().max(0.01);
            let mut since_land = f64::INFINITY;
            for k in 0..2 * w {
                let i = r * w + k % w;
                since_land = if cells[i].0 { 0.0 } else { since_land + dx };
                if k >= w && !cells[i].0 && since_land <= WARM_KM {
                    warm[i] = 1.0;
                }
            }
        }
        let mut zonal = vec![(0.0f64, 0.0f64); w * h];
        for r in 0..h {
            let lat = lat_of(r);
            let dx = step.to_radians() * EARTH_RADIUS_KM * lat.to_radians().cos().max(0.01);
            let mut path: Vec<usize> = (0..w).map(|c| r * w + c).collect();
            if wind(lat) < 0 {
                path.reverse();
            }
            let decay = decay_km(lat);
            advect(cells, &full, &path, true, 1.0, dx, (&|_| decay, FETCH_KM), &mut zonal);
        }
        let mut meridional = vec![(0.0f64, 0.0f64); w * h];
        let dy = step.to_radians() * EARTH_RADIUS_KM;
        for c in 0..w {
            for north in [true, false] {
                let mut path: Vec<usize> = (0..h)
                    .map(|r| r * w + c)
                    .filter(|&i| (lat_of(i / w) > 0.0) == north && POLEWARD_LAT.contains(&lat_of(i / w).abs()))
                    .collect();
                if north {
                    path.reverse();
                }
                if let Some(&first) = path.first() {
                    let m0 = if cells[first].0 { zonal[first].0 } else { 1.0 };
                    advect(cells, &warm, &path, false, m0, dy, (&|_| DECAY_KM, MONSOON_FETCH_KM), &mut meridional);
                }
            }
        }
        let east = east_to_open_ocean_km(cells, w, h, step);
        let mut precip = vec![0.0f32; w * h];
        for (i, cell) in cells.iter().enumerate() {
            let p0 = zonal_mm(lat_of(i / w));
            precip[i] = if cell.0 {
                let lat = lat_of(i / w);
                // Coasts beside cold currents stay dry, outside the inner tropics.
                let warmth = 1.0 + (warm[nearest[i]] - 1.0) * smoothstep(4.0, 12.0, lat.abs());
                let tropical_floor = TROPICAL_NEAR_SEA * (-near[i] / TROPICAL_NEAR_SEA_KM).exp();
                let mid_floor = NEAR_SEA * (-near[i] / NEAR_SEA_KM).exp();
                let sub_floor = SUBTROPICAL_NEAR_SEA * mid_floor;
                let floor = warmth
                    * (tropical_floor
                        + (sub_floor - tropical_floor) * extratropical(lat)
                        + (mid_floor - sub_floor) * smoothstep(25.0, 40.0, lat.abs()));
                let own = p0 * (zonal[i].0.max(floor) + OROGRAPHIC_GAIN * zonal[i].1);
                let reach = (-(east[i] - MONSOON_REACH_KM).max(0.0) / MONSOON_FADE_KM).exp();
                let tropical = POLEWARD_MM * POLEWARD * (meridional[i].0 + OROGRAPHIC_GAIN * meridional[i].1) * reach;
                let p = own.max(tropical);
                (p * (1.0 + (LAND_GAIN - 1.0) * smoothstep(500.0, 1200.0, p))) as f32
            } else {
                p0 as f32
            };
        }
        smooth_over_land(&mut precip, cells, w, h, step);
        Climate { width: w, height: h, precip_mm: precip }
    }

    /// The climate of a mesh whose vertex `v` is land when `land(v)`, at `altitude(v)` metres
    /// above sea level (interpolated on the grid over the mesh's faces).
    pub fn of_mesh(
        mesh: &Mesh,
        land: impl Fn(usize) -> bool + Sync,
        altitude: impl Fn(usize) -> f64 + Sync,
    ) -> Climate {
        let raster = SphereRaster::new(mesh, WIDTH as u32, HEIGHT as u32);
        let is_land = raster.interpolate(mesh, |v| if land(v) { 1.0 } else { 0.0 });
        let alt = raster.interpolate(mesh, |v| if land(v) { altitude(v).max(0.0) } else { 0.0 });
        let cells: Vec<(bool, f64)> = is_land.iter().zip(&alt).map(|(&l, &a)| (l > 0.5, f64::from(a))).collect();
        Climate::new(&cells)
    }

    /// The same climate with the precipitation of a user's map, as [`precipitation_grid`] puts
    /// it on the grid: NaN cells (outside the map or under its nodata) keep the model's.
    pub fn with_precipitation(mut self, grid: Option<&[f32]>) -> Climate {
        if let Some(grid) = grid {
            assert_eq!(grid.len(), self.precip_mm.len(), "one value per grid cell");
            for (p, &g) in self.precip_mm.iter_mut().zip(grid) {
                if !g.is_nan() {
                    *p = g;
                }
            }
        }
        self
    }

    /// Precipitation and potential evaporation (mm/yr) at every vertex of `mesh`, at
    /// `altitude(v)` metres above sea level.
    pub fn at_vertices(&self, mesh: &Mesh, altitude: impl Fn(usize) -> f64) -> Vec<(f64, f64)> {
        (0..mesh.vertices.len())
            .map(|v| {
                let (lat, lon) = lat_lon(mesh.pos(v as u32));
                let p = self.precip_at(lat, lon);
                (p, potential_evaporation_mm(lat, altitude(v), p))
            })
            .collect()
    }

    /// Precipitation (mm/yr) in the cell holding a latitude and longitude.
    pub fn precip_at(&self, lat: f64, lon: f64) -> f64 {
        let step = 1.0 / CELLS_PER_DEG as f64;
        let r = (((90.0 - lat) / step) as usize).min(self.height - 1);
        let c = (((lon + 180.0) / step).floor() as i64).rem_euclid(self.width as i64) as usize;
        f64::from(self.precip_mm[r * self.width + c])
    }
}

/// Carries moisture along `path`, cells listed in the wind's direction `step_km` apart:
/// `source[i]` over the ocean (recharged over a fetch of [`FETCH_KM`]), decaying over land by `decay_km` and
/// by uplift. A `ring` (a row) starts where the air leaves the ocean and goes round twice to
/// settle; an open path starts with moisture `m0`. Writes, per land cell, the moisture and the
/// share rained out by uplift there.
#[allow(clippy::too_many_arguments)]
fn advect(
    cells: &[(bool, f64)],
    source: &[f64],
    path: &[usize],
    ring: bool,
    m0: f64,
    step_km: f64,
    (decay_km, fetch_km): (&dyn Fn(usize) -> f64, f64),
    out: &mut [(f64, f64)],
) {
    let n = path.len();
    let recharge = 1.0 - (-step_km / fetch_km).exp();
    let ocean = path.iter().position(|&i| !cells[i].0);
    let (start, laps, mut m) = match (ring, ocean) {
        (true, Some(o)) => (o, 2, 1.0),
        (true, None) => (0, 2, NEAR_SEA),
        (false, _) => (0, 1, m0),
    };
    let mut air = 0.0f64;
    for k in 0..laps * n {
        let i = path[(start + k) % n];
        let (land, alt) = cells[i];
        if !land {
            m += (source[i] - m) * recharge;
            air = 0.0;
            continue;
        }
        let alt = alt.max(0.0);
        // The air rides over the terrain, settling back slowly after a crest: only ground that
        // rises above it lifts it (small bumps of a plateau count once).
        let carried = m * (-step_km / decay_km(i)).exp();
        let rise = (alt - air).max(0.0);
        m = carried * (-rise / UPLIFT_M).exp();
        air = alt.max(air - SETTLE_M_PER_KM * step_km);
        if k + n >= laps * n {
            out[i] = (m, carried - m);
        }
    }
}

/// A user's precipitation map (mm/yr, [`crate::maps::decode_precipitation`]) on the climate's
/// grid: each cell the mean of up to 16 x 16 samples over it, one per map pixel or more, where
/// the map covers most of the cell; NaN elsewhere (outside its bounds, under its nodata).
pub fn precipitation_grid(map: &crate::maps::Map) -> Vec<f32> {
    let step = 1.0 / CELLS_PER_DEG as f64;
    let (dx, dy) = map.pixel_size_deg();
    let n = ((step / dx.min(dy)).ceil() as usize).clamp(2, 16);
    (0..WIDTH * HEIGHT)
        .map(|i| {
            let (north, west) = (90.0 - (i / WIDTH) as f64 * step, -180.0 + (i % WIDTH) as f64 * step);
            let (mut sum, mut count) = (0.0f64, 0u32);
            for a in 0..n {
                for b in 0..n {
                    let lat = north - (a as f64 + 0.5) * step / n as f64;
                    let lon = west + (b as f64 + 0.5) * step / n as f64;
                    if let Some(v) = map.sample(lat, lon) {
                        sum += f64::from(v);
                        count += 1;
                    }
                }
            }
            if 2 * count as usize >= n * n {
                (sum / f64::from(count)) as f32
            } else {
                f32::NAN
            }
        })
        .collect()
}

/// Distance (km) from every cell eastward along its row to open ocean: sea at least
/// [`OPEN_OCEAN_KM`] wide along the row (narrow seas such as the Red Sea or the Gulf of
/// California are crossed as land); infinite on a row without one.
fn east_to_open_ocean_km(cells: &[(bool, f64)], w: usize, h: usize, step: f64) -> Vec<f64> {
    let mut east = vec![f64::INFINITY; w * h];
    for r in 0..h {
        let row = &cells[r * w..(r + 1) * w];
        let lat = 90.0 - (r as f64 + 0.5) * step;
        let dx = step.to_radians() * EARTH_RADIUS_KM * lat.to_radians().cos().max(0.01);
        // Runs of sea along the (cyclic) row; the wide ones are open ocean.
        let mut open = vec![false; w];
        let Some(start) = row.iter().position(|c| c.0) else {
            continue; // a row of sea alone: nothing to reach
        };
        let mut k = 0;
        while k < w {
            let c = (start + k) % w;
            if row[c].0 {
                k += 1;
                continue;
            }
            let run = (k..w).take_while(|&j| !row[(start + j) % w].0).count();
            if run as f64 * dx >= OPEN_OCEAN_KM {
                for j in k..k + run {
                    open[(start + j) % w] = true;
                }
            }
            k += run;
        }
        // Walk west twice round the row so that every cell sees the ocean east of it.
        let mut d = f64::INFINITY;
        for k in (0..2 * w).rev() {
            let c = k % w;
            d = if open[c] { 0.0 } else { d + dx };
            if k < w {
                east[r * w + c] = d;
            }
        }
    }
    east
}

/// Smooths the land's precipitation with a Gaussian of [`SMOOTH_KM`] (separable: along rows,
/// then columns, weights from land cells only, so coasts keep their land's value and seas
/// theirs): the winds' rows and columns become weather, not stripes one grid cell wide.
fn smooth_over_land(field: &mut [f32], cells: &[(bool, f64)], w: usize, h: usize, step: f64) {
    let kernel = |sigma: f64| -> Vec<f64> {
        let reach = (3.0 * sigma).ceil() as i64;
        (-reach..=reach).map(|k| (-0.5 * (k as f64 / sigma).powi(2)).exp()).collect()
    };
    let pass = |src: &[f32], along_rows: bool| -> Vec<f32> {
        let mut out = src.to_vec();
        for r in 0..h {
            let lat = 90.0 - (r as f64 + 0.5) * step;
            let cell_km = if along_rows {
                step.to_radians() * EARTH_RADIUS_KM * lat.to_radians().cos().max(0.01)
            } else {
                step.to_radians() * EARTH_RADIUS_KM
            };
            let weights = kernel((SMOOTH_KM / cell_km).min(w as f64 / 8.0));
            let reach = (weights.len() / 2) as i64;
            for c in 0..w {
                let i = r * w + c;
                if !cells[i].0 {
                    continue;
                }
                let (mut sum, mut total) = (0.0f64, 0.0f64);
                for (k, wt) in weights.iter().enumerate() {
                    let d = k as i64 - reach;
                    let j = if along_rows {
                        r * w + (c as i64 + d).rem_euclid(w as i64) as usize
                    } else {
                        let rr = r as i64 + d;
                        if rr < 0 || rr >= h as i64 {
                            continue;
                        }
                        rr as usize * w + c
                    };
                    if cells[j].0 {
                        sum += wt * f64::from(src[j]);
                        total += wt;
                    }
                }
                out[i] = (sum / total) as f32;
            }
        }
        out
    };
    let rows = pass(field, true);
    let both = pass(&rows, false);
    field.copy_from_slice(&both);
}

/// Great-circle distance (km) from every cell to the nearest sea cell, along 8-connected steps,
/// and that sea cell.
fn sea_distance_km(cells: &[(bool, f64)], w: usize, h: usize, step: f64) -> (Vec<f64>, Vec<usize>) {
    #[derive(PartialEq)]
    struct Item(f64, usize);
    impl Eq for Item {}
    impl PartialOrd for Item {
        fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
            Some(self.cmp(o))
        }
    }
    impl Ord for Item {
        fn cmp(&self, o: &Self) -> Ordering {
            o.0.total_cmp(&self.0).then(o.1.cmp(&self.1))
        }
    }
    let centre = |i: usize| direction(90.0 - ((i / w) as f64 + 0.5) * step, -180.0 + ((i % w) as f64 + 0.5) * step);
    let mut dist = vec![f64::INFINITY; w * h];
    let mut from: Vec<usize> = (0..w * h).collect();
    let mut heap = BinaryHeap::new();
    for (i, c) in cells.iter().enumerate() {
        if !c.0 {
            dist[i] = 0.0;
            heap.push(Item(0.0, i));
        }
    }
    while let Some(Item(d, i)) = heap.pop() {
        if d > dist[i] {
            continue;
        }
        let (r, c) = ((i / w) as i64, (i % w) as i64);
        for (dr, dc) in [(-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1)] {
            let rr = r + dr;
            if rr < 0 || rr >= h as i64 {
                continue;
            }
            let j = rr as usize * w + (c + dc).rem_euclid(w as i64) as usize;
            let nd = d + centre(i).angle_between(centre(j)) * EARTH_RADIUS_KM;
            if nd < dist[j] {
                dist[j] = nd;
                from[j] = from[i];
                heap.push(Item(nd, j));
            }
        }
    }
    (dist, from)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runoff_follows_budyko() {
        // Wet and cool: most rain runs off; dry and hot: almost none does.
        assert!(runoff_mm(2000.0, 500.0) > 1400.0);
        assert!(runoff_mm(200.0, 2000.0) < 5.0);
        assert_eq!(runoff_mm(0.0, 1000.0), 0.0);
        let r = runoff_mm(1000.0, 1000.0);
        assert!((200.0..400.0).contains(&r), "{r}");
    }

    #[test]
    fn a_range_casts_a_rain_shadow_and_interiors_dry_out() {
        // Westerlies at 45°: an ocean west of 0°, a 3 km range at 5-7° E, plains beyond.
        let cells: Vec<(bool, f64)> = (0..WIDTH * HEIGHT)
            .map(|i| {
                let lon = -180.0 + (i % WIDTH) as f64 + 0.5;
                let land = lon > 0.0 && lon < 120.0;
                (land, if (5.0..7.0).contains(&lon) { 3000.0 } else { 200.0 })
            })
            .collect();
        let c = Climate::new(&cells);
        let (windward, lee, far) = (c.precip_at(45.0, 5.5), c.precip_at(45.0, 9.5), c.precip_at(45.0, 60.0));
        assert!(windward > 1.5 * lee, "windward {windward} lee {lee}");
        assert!(far < 0.5 * c.precip_at(45.0, 1.5), "interior {far}");
        // Trades at 15°: the same coast is downwind of the continent.
        assert!(c.precip_at(15.0, 118.5) > c.precip_at(15.0, 1.5));
    }

    #[test]
    fn the_monsoon_reaches_only_so_far_west_of_the_open_ocean() {
        // A continent 0-120° E at 0-40° N, the Pacific east of it; a narrow sea (3° wide) at
        // 60-63° E is crossed as land.
        let cells: Vec<(bool, f64)> = (0..WIDTH * HEIGHT)
            .map(|i| {
                let (lat, lon) = (89.5 - (i / WIDTH) as f64, -179.5 + (i % WIDTH) as f64);
                ((0.0..40.0).contains(&lat) && (0.0..120.0).contains(&lon) && !(60.0..63.0).contains(&lon), 100.0)
            })
            .collect();
        let east = east_to_open_ocean_km(&cells, WIDTH, HEIGHT, 1.0);
        let at = |lat: f64, lon: f64| east[(89.5 - lat) as usize * WIDTH + (lon + 179.5) as usize];
        let km_per_deg = 111.19 * 25.5f64.to_radians().cos();
        assert!((at(25.5, 110.5) - 10.0 * km_per_deg).abs() < 1.0, "{}", at(25.5, 110.5));
        assert!((at(25.5, 50.5) - 70.0 * km_per_deg).abs() < 1.0, "{}", at(25.5, 50.5));
        assert_eq!(at(25.5, 150.5), 0.0);
        assert!(at(-45.5, 50.5).is_infinite() || at(-45.5, 50.5) == 0.0);
        let c = Climate::new(&cells);
        // The eastern flank is wet, the land far west of the ocean dry.
        assert!(
            c.precip_at(25.5, 110.5) > 3.0 * c.precip_at(25.5, 30.5),
            "{} {}",
            c.precip_at(25.5, 110.5),
            c.precip_at(25.5, 30.5)
        );
    }

    #[test]
    fn a_precipitation_map_replaces_the_models_rain_where_it_covers_the_planet() {
        use crate::maps::{GeoBounds, Map, MapKind};
        let cells: Vec<(bool, f64)> =
            (0..WIDTH * HEIGHT).map(|i| ((i % WIDTH) < WIDTH / 2 && (20..160).contains(&(i / WIDTH)), 300.0)).collect();
        let model = Climate::new(&cells);
        // A regional map over 10-30° E, 0-20° N: 3,000 mm in its west half, nodata in its east.
        let bounds = GeoBounds { west: -170.0, south: 0.0, east: -150.0, north: 20.0 };
        let values: Vec<f32> = (0..40 * 40).map(|i| if i % 40 < 20 { 3000.0 } else { f32::NAN }).collect();
        let map = Map::from_values(MapKind::Elevation, 40, 40, bounds, values).unwrap();
        let c = model.clone().with_precipitation(Some(&precipitation_grid(&map)));
        assert_eq!(c.precip_at(10.5, -165.5), 3000.0);
        assert_eq!(c.precip_at(0.5, -160.5), 3000.0);
        // Nodata, and cells outside the bounds, keep the model's rain.
        assert_eq!(c.precip_at(10.5, -155.5), model.precip_at(10.5, -155.5));
        assert_eq!(c.precip_at(25.5, -165.5), model.precip_at(25.5, -165.5));
        assert_eq!(c.precip_at(-0.5, -165.5), model.precip_at(-0.5, -165.5));
        assert_ne!(model.precip_at(10.5, -165.5), 3000.0);
        // No map: the model's.
        assert_eq!(model.clone().with_precipitation(None).precip_mm, model.precip_mm);
    }
}
