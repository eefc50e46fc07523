use super::*;
use crate::export::test_planet;
use crate::export::tiles::PlanetTiles;
use crate::params::Params;
use std::sync::{Arc, OnceLock};

fn tiles() -> &'static PlanetTiles {
    static TILES: OnceLock<PlanetTiles> = OnceLock::new();
    TILES.get_or_init(|| {
        let params = Params { base_faces: 2000, ..Params::default() };
        PlanetTiles::new(Arc::new(test_planet().clone()), params).expect("a bisection refinement")
    })
}

/// A bbox of the test planet holding both land and sea.
fn coast_bbox() -> String {
    let planet = test_planet();
    let sea = planet.mesh.vertices.iter().find(|v| v.ground < Params::default().sea_level_m - 100.0).unwrap();
    let (lat, lon) = lat_lon(sea.p());
    let (lat, lon) = (lat.clamp(-60.0, 60.0), lon.clamp(-150.0, 150.0));
    format!("{},{},{},{}", lon - 20.0, lat - 15.0, lon + 20.0, lat + 15.0)
}

#[test]
fn requests_are_checked_field_by_field() {
    let max = DEFAULT_MAX_DEM_PIXELS;
    let ok = DemRequest::new("10,40,12,41", 400, None, max).unwrap();
    assert_eq!((ok.width, ok.height), (400, 200), "square cells in degrees");
    assert_eq!(ok.pixel(), [0.005, 0.005]);
    for (bbox, w, h, field) in [
        ("10,40,12", 10, None, "bbox"),
        ("10,40,10,41", 10, None, "bbox"),
        ("-181,40,12,41", 10, None, "bbox"),
        ("10,-91,12,41", 10, None, "bbox"),
        ("12,40,10,41", 10, None, "bbox"),
        ("10,40,12,41", 0, None, "width"),
        ("10,40,12,41", 8193, None, "width"),
        ("10,40,12,41", 10, Some(0), "height"),
        ("10,40,12,41", 8192, Some(8192), "width"),
        ("0,-80,0.001,80", 8192, None, "height"),
    ] {
        let e = DemRequest::new(bbox, w, h, max).unwrap_err();
        assert_eq!(e.field, field, "{bbox} {w} {h:?}: {e}");
    }
}

#[test]
fn the_cog_holds_ground_and_water_bands_georeferenced() {
    let req = DemRequest::new(&coast_bbox(), 300, Some(220), DEFAULT_MAX_DEM_PIXELS).unwrap();
    let dem = super::sample_dem(tiles(), &req);
    let bytes = dem_tiff(&dem);
    assert_eq!(bytes, dem_tiff(&super::sample_dem(tiles(), &req)), "deterministic");
    assert_eq!(&bytes[..4], b"II*\0");
    // The file's two bands are read by GDAL in CI (`.ci/check_outputs.py`); the `tiff` crate
    // reads single-band COGs only (see `cog.rs`).
    let (ground, water) = (&dem.ground, &dem.water);
    assert!(ground.iter().all(|g| g.is_finite()), "ground everywhere, the sea floor included");
    let sea = ground.iter().zip(water).filter(|(g, _)| **g < -50.0).count();
    let land = ground.iter().zip(water).filter(|(g, w)| **g > 50.0 && w.is_nan()).count();
    assert!(sea > 1000 && land > 1000, "sea {sea}, dry land {land}");
    // The sea's surface is at sea level; wherever water stands it is above the ground.
    for (g, w) in ground.iter().zip(water) {
        if *g < -50.0 {
            assert!(w.abs() < 1e-3, "{g} {w}");
        }
        assert!(w.is_nan() || w > g, "{g} {w}");
    }
}

#[test]
fn finer_grids_refine_and_agree_with_the_base_mesh_on_it() {
    let t = tiles();
    let bbox = coast_bbox();
    // 10° cells: coarser than the base mesh's edges (~500 km), so no split below it but a few
    // in the ring of leaves refined past the bbox for the water (22: nodes reaching 60°N and
    // S, where cells narrow, in a ring two of the base mesh's longest edges wide).
    let coarse = super::sample_dem(t, &DemRequest::new(&bbox, 4, Some(3), DEFAULT_MAX_DEM_PIXELS).unwrap());
    assert!(coarse.splits < 100, "{}", coarse.splits);
    let fine = super::sample_dem(t, &DemRequest::new(&bbox, 1000, Some(750), DEFAULT_MAX_DEM_PIXELS).unwrap());
    assert!(fine.splits > 100_000, "{}", fine.splits);
    // Cells coarser than the base mesh sample the base mesh as the elevation raster does.
    let req = coarse.request;
    let raster = crate::mesh::raster::SphereRaster::new_in(&t.planet().mesh, req.bounds, req.width, req.height);
    let sea = t.params().sea_level_m;
    let base = raster.interpolate(&t.planet().mesh, |v| t.planet().mesh.vertices[v].ground - sea);
    let worst = base.iter().zip(&coarse.ground).map(|(a, b)| (a - b).abs()).fold(0f32, f32::max);
    assert!(worst < 0.01, "{worst} m");
}

#[test]
fn a_window_of_a_dem_is_the_dem_of_the_window() {
    // Same cells, different blocks: 600 x 400 cells, and the window of 230 x 150 cells starting
    // at column 300, row 170 (crossing the 256-cell block borders of the larger one).
    let t = tiles();
    let (w0, s0, e0, n0) = (-30.0, -10.0, 30.0, 30.0);
    let big = super::sample_dem(
        t,
        &DemRequest::new(&format!("{w0},{s0},{e0},{n0}"), 600, Some(400), DEFAULT_MAX_DEM_PIXELS).unwrap(),
    );
    let d = 0.1;
    let (c0, r0, cw, rh) = (300u32, 170u32, 230u32, 150u32);
    let bbox = format!(
        "{},{},{},{}",
        w0 + f64::from(c0) * d,
        n0 - f64::from(r0 + rh) * d,
        w0 + f64::from(c0 + cw) * d,
        n0 - f64::from(r0) * d
    );
    let small = super::sample_dem(t, &DemRequest::new(&bbox, cw, Some(rh), DEFAULT_MAX_DEM_PIXELS).unwrap());
    let mut worst = 0f32;
    for r in 0..rh {
        for c in 0..cw {
            let a = big.ground[((r0 + r) * 600 + c0 + c) as usize];
            let b = small.ground[(r * cw + c) as usize];
            worst = worst.max((a - b).abs());
        }
    }
    // Cell centres agree to the last bits of the bbox arithmetic, so values to a millimetre.
    assert!(worst < 1e-3, "{worst} m");
}

/// Every face of a refined region is as fine as the rule asks, whatever the region's bounds:
/// a node's descendants reach past it (eq. 2 puts a split's vertex anywhere in the middle of
/// its diamond), so a walk that passed over nodes lying just outside the region left base faces
/// inside it unsplit. On the Earth DEM's planet by the antimeridian at 68°N (an octahedron
/// edge, where the base vertices of one root lie up to 1.4° inside the other): the longest
/// face edge was 95 times the cell there, with 4,664 splits for a region that takes 23,628;
/// now 5.3-5.8 (non-refinement edges of faces whose refinement edges are within 2.83).
#[test]
fn regions_are_refined_whatever_lies_outside_them() {
    let Some(planet) = crate::planet::tests_relief::earth() else { return };
    let tiles = PlanetTiles::new(Arc::new(planet.clone()), Params::default()).unwrap();
    let r = tiles.params().radius_m;
    let step = 180.0 / 128.0 / 64.0;
    for (west, east) in [(-179.99, -178.0), (178.0, 179.99), (-180.01, -178.0)] {
        let rect = GeoBounds { west, east, north: 69.0, south: 67.4 };
        let surface = Surface::refine(&tiles, rect, [step, step], Rows::Degrees);
        let mesh = surface.refiner().mesh();
        let region = Region::new(rect);
        let worst = surface
            .leaves
            .iter()
            .map(|f| f.map(|v| mesh.pos(v).normalize()))
            .filter(|u| region.may_meet(u))
            .map(|u| {
                let polar = u.iter().map(|x| x.z.abs()).fold(0.0, f64::max);
                let ew = step.to_radians() * r * (1.0 - polar * polar).sqrt();
                let target = ew.max(0.25 * step.to_radians() * r);
                u[0].distance(u[1]).max(u[1].distance(u[2])).max(u[2].distance(u[0])) * r / target
            })
            .fold(0.0, f64::max);
        // The rule: refinement edges up to 2.83 cells; a face's other edges may be up to about
        // twice that (its vertices sit anywhere in the middle of their diamonds).
        assert!(worst < 8.0, "{west}..{east}: a face edge {worst:.1} cells long");
    }
}

/// Longest run of `wet` cells in each row (or column with `columns`) of a `w x h` grid, for
/// the rows that have any.
fn wet_runs(wet: &[bool], w: usize, h: usize, columns: bool) -> Vec<usize> {
    let (lines, along) = if columns { (w, h) } else { (h, w) };
    let at = |line: usize, k: usize| if columns { wet[k * w + line] } else { wet[line * w + k] };
    (0..lines)
        .map(|line| {
            let (mut best, mut run) = (0, 0);
            for k in 0..along {
                run = if at(line, k) { run + 1 } else { 0 };
                best = best.max(run);
            }
            best
        })
        .filter(|&b| b > 0)
        .collect()
}

/// The direction of the base mesh's river vertex with the widest channel away from the sea,
/// and the channel's width (m).
fn widest_inland_river(t: &PlanetTiles) -> (DVec3, f64) {
    use crate::export::water::channel_width;
    let base = &t.planet().mesh;
    let sea = t.params().sea_level_m;
    base.vertices
        .iter()
        .filter(|v| v.ground > sea + 20.0)
        .filter_map(|v| Some((v.p(), channel_width(base, v)?)))
        .fold((DVec3::ZERO, 0.0), |a, b| if b.1 > a.1 { b } else { a })
}

/// Land cells (ground over 5 m) with water, and land cells, of a DEM.
fn wet_land(dem: &Dem) -> (usize, usize) {
    let land = dem.ground.iter().filter(|&&g| g > 5.0).count();
    (dem.ground.iter().zip(&dem.water).filter(|(g, w)| **g > 5.0 && !w.is_nan()).count(), land)
}

/// Water on land stands in rivers' channels at their width, as views draw it: around the test
/// planet's widest river away from the sea, on cells as wide as its channel, the river shows
/// as water along its course and the land beside it stays dry.
#[test]
fn a_river_as_wide_as_the_cells_shows_along_its_course() {
    let t = tiles();
    let (dir, width) = widest_inland_river(t);
    let (lat, lon) = lat_lon(dir);
    let cell = (width / t.params().radius_m).to_degrees();
    let (w, h) = (300.0, 200.0);
    let bbox =
        format!("{},{},{},{}", lon - 0.5 * w * cell, lat - 0.5 * h * cell, lon + 0.5 * w * cell, lat + 0.5 * h * cell);
    let req = DemRequest::new(&bbox, w as u32, Some(h as u32), DEFAULT_MAX_DEM_PIXELS).unwrap();
    let dem = super::sample_dem(t, &req);
    let (wet, land) = wet_land(&dem);
    let share = wet as f64 / land as f64;
    eprintln!("{wet} of {land} land cells wet ({:.2} %), channel {width:.0} m", share * 100.0);
    assert!(land > 10_000, "{land} land cells");
    // The river crosses the grid: at least a cell of water per column it spans...
    assert!(wet >= 100, "{wet} wet cells");
    // ... and the land beside it stays dry.
    assert!(share < 0.03, "{:.2} % of the land is water", share * 100.0);
}

/// A DEM of a regional map at the map's own 90 m is dry beside its streams (10-60 m wide,
/// under an eighth of the cells' edges): every inland vertex of the map's base mesh is a river
/// vertex with its water at the map, and each face beside one used to flood to its level
/// (45.7 % of the land cells were water; now 7 of 138,632).
#[test]
fn a_regional_dem_is_dry_beside_its_streams() {
    let Some(planet) = crate::planet::tests_relief::jacksboro() else { return };
    let tiles = PlanetTiles::new(Arc::new(planet.clone()), Params::default()).unwrap();
    let bbox = "-84.41375,36.44625,-84.07791666666667,36.73291666666667";
    let req = DemRequest::new(bbox, 403, Some(344), DEFAULT_MAX_DEM_PIXELS).unwrap();
    let dem = super::sample_dem(&tiles, &req);
    let (wet, land) = wet_land(&dem);
    eprintln!("{wet} of {land} land cells wet");
    assert!(land > 130_000, "{land} land cells");
    assert!(wet * 100 < land, "{wet} of {land} land cells are water");
}

#[test]
fn dems_carve_wide_rivers_to_their_width_whatever_their_blocks() {
    // Cells a tenth of the channel (its half width 5 target edges): the DEM floods its own
    // surface (measured: 10.5 cells across; 1.7 without carving).
    carves_to_width(10.0, (700, 200), (450, 50, 600, 150));
}

#[test]
fn dems_far_finer_than_a_wide_river_carve_it_by_its_course() {
    // Cells a 40th and a 240th of the channel (its half width 20 and 120 target edges, past
    // MAX_CARVE_EDGES): the DEM carves by the distance to the river's course (measured:
    // 35.6 and 202 cells across; 1.7 and 6.7 without).
    carves_to_width(40.0, (800, 400), (450, 100, 600, 300));
    carves_to_width(240.0, (800, 720), (450, 300, 600, 420));
}

/// The test planet's widest river away from the sea, on a grid of `cols x rows` cells of a
/// `per_width`th of its channel, its vertex on the border between two blocks of 512 columns
/// and half way down: its water is as wide as its channel, and a `window` (first and last
/// columns and rows) across the blocks' border has the same cells.
fn carves_to_width(per_width: f64, (cols, rows): (u32, u32), (c0, r0, c1, r1): (u32, u32, u32, u32)) {
    let t = tiles();
    let (dir, width) = widest_inland_river(t);
    let (lat, lon) = lat_lon(dir);
    let cell = (width / per_width / t.params().radius_m).to_degrees();
    let (w0, n0) = (lon - 512.0 * cell, lat + f64::from(rows / 2) * cell);
    let bbox = |c0: u32, r0: u32, c1: u32, r1: u32| {
        let (w, e) = (w0 + f64::from(c0) * cell, w0 + f64::from(c1) * cell);
        format!("{w},{},{e},{}", n0 - f64::from(r1) * cell, n0 - f64::from(r0) * cell)
    };
    let req = |c0, r0, c1, r1| DemRequest::new(&bbox(c0, r0, c1, r1), c1 - c0, Some(r1 - r0), DEFAULT_MAX_DEM_PIXELS);
    let big = super::sample_dem(t, &req(0, 0, cols, rows).unwrap());
    // Across the river the water is as wide as its channel: a straight band of width `W`
    // crossing rows and columns at any angle has runs `r` and `c` with `1/r² + 1/c² = 1/W²`.
    let wet: Vec<bool> = big.water.iter().zip(&big.ground).map(|(w, g)| !w.is_nan() && *w > 0.0 && w > g).collect();
    let median = |mut v: Vec<usize>| {
        v.sort_unstable();
        v.get(v.len() / 2).copied().unwrap_or(0) as f64
    };
    let (w, h) = (cols as usize, rows as usize);
    let (r, c) = (median(wet_runs(&wet, w, h, false)), median(wet_runs(&wet, w, h, true)));
    let across = (r.powi(-2) + c.powi(-2)).powf(-0.5);
    assert!(
        (0.7 * per_width..=1.3 * per_width).contains(&across),
        "{across} cells across a channel of {per_width} ({width} m): runs {r}, {c}"
    );
    // A window across the blocks' border has the same cells, the carving included.
    let small = super::sample_dem(t, &req(c0, r0, c1, r1).unwrap());
    let (mut worst, mut differ, mut wet_cells) = (0f32, 0, 0);
    for r in 0..r1 - r0 {
        for c in 0..c1 - c0 {
            let (i, j) = (((r0 + r) * cols + c0 + c) as usize, (r * (c1 - c0) + c) as usize);
            worst = worst.max((big.ground[i] - small.ground[j]).abs());
            differ += usize::from(big.water[i].is_nan() != small.water[j].is_nan());
            wet_cells += usize::from(wet[i]);
        }
    }
    assert!(worst < 1e-3 && differ == 0, "{worst} m apart, {differ} cells wet in one only");
    assert!(wet_cells > 200, "{wet_cells} wet cells in the window");
}
