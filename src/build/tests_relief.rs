//! A planet from a real elevation map keeps the map's heights and drains its great basins
//! through their real mouths.

use super::*;
use crate::geo::lat_lon;
use crate::maps::GeoBounds;
use crate::maps::MapLimits;
use crate::mesh::raster::SphereRaster;

fn from_map(path: &str) -> Option<Planet> {
    let bytes = std::fs::read(path).ok()?;
    let map = Map::decode(&bytes, MapKind::Elevation, None, None, &MapLimits::default()).unwrap();
    let spec = PlanetSpec { seed: 42, params: Params::default(), map: Some(Arc::new(map)) };
    Some(build_planet(&spec, &mut |_, _| {}).unwrap())
}

fn check_fidelity(planet: &Planet, min_r: f64) {
    let f = planet.stats.map_fidelity.as_ref().expect("an elevation map reports its fidelity");
    assert!(f.r >= min_r, "{f:?}");
    assert!(f.bias_m.abs() <= 30.0, "{f:?}");
    assert!(f.median_abs_error_m <= 80.0, "{f:?}");
    assert!(planet.stats.drained_fraction >= 0.99, "{:?}", planet.stats);
    assert_eq!(planet.stats.monotone_violations, 0);
}

/// Great river basins: mouth (latitude, longitude) and drainage area (km²), from the rivers'
/// reference entries (Wikipedia infoboxes after GRDC and national surveys).
const BASINS: [(&str, f64, f64, f64); 4] = [
    ("Congo", -6.08, 12.45, 4_014_500.0),
    ("Nile", 31.5, 31.1, 3_254_555.0),
    ("Mackenzie", 69.3, -134.9, 1_805_200.0),
    ("Murray-Darling", -35.56, 138.88, 1_061_469.0),
];

fn distance_km(a: (f64, f64), b: (f64, f64)) -> f64 {
    let (p, q) = (crate::geo::direction(a.0, a.1), crate::geo::direction(b.0, b.1));
    p.angle_between(q) * 6371.0
}

/// Each basin has a mouth within 150 km of the real one draining its area within 35 %.
fn check_basins(planet: &Planet) {
    let area = planet.rivers.drainage_area(&planet.mesh);
    for (name, lat, lon, km2) in BASINS {
        let best = planet
            .rivers
            .mouths
            .iter()
            .filter(|&&m| distance_km(lat_lon(planet.mesh.pos(m)), (lat, lon)) <= 150.0)
            // As rivers.geojson reports it: the area drained by the river's last reach.
            .flat_map(|&m| planet.rivers.upstream_of(m).map(|u| area[u as usize] / 1e6))
            .fold(0.0f64, f64::max);
        let ratio = best / km2;
        assert!((0.65..=1.35).contains(&ratio), "{name}: {best:.0} km² at the mouth, {km2} real");
    }
}

#[test]
fn the_shipped_earth_dem_keeps_its_heights_and_basins() {
    let planet = from_map("maps/earth_etopo5_1024x512.tif").expect("the shipped DEM");
    check_fidelity(&planet, 0.97);
    check_basins(&planet);
    // The Caspian (its surface 28 m below sea level) and the Qattara Depression are no sea.
    let raster =
        SphereRaster::new_in(&planet.mesh, GeoBounds { west: 49.0, south: 41.0, east: 51.0, north: 43.0 }, 1, 1);
    assert_eq!(planet.mesh.face_kind(raster.faces[0]), FaceKind::Land);
    let raster =
        SphereRaster::new_in(&planet.mesh, GeoBounds { west: 26.5, south: 29.5, east: 27.5, north: 30.0 }, 1, 1);
    assert_eq!(planet.mesh.face_kind(raster.faces[0]), FaceKind::Land);
}

#[test]
fn the_earth_dem_at_twice_the_resolution_and_a_regional_dem_keep_their_heights() {
    // The larger map ships beside the repository (../shared/maps); without it this half is moot.
    if let Some(planet) = from_map("../shared/maps/earth_etopo5_2048x1024.tif") {
        check_fidelity(&planet, 0.97);
        check_basins(&planet);
    }
    let planet = from_map("maps/region_jacksboro_tn_403x344.tif").expect("the shipped regional DEM");
    check_fidelity(&planet, 0.97);
}

#[test]
fn a_continent_bitmap_reports_no_fidelity() {
    let bytes = std::fs::read("maps/earth_landmask_ne10m_1024x512.png").unwrap();
    let map = Map::decode(&bytes, MapKind::Continents, None, None, &MapLimits::default()).unwrap();
    let spec = PlanetSpec { seed: 1, params: Params::default(), map: Some(Arc::new(map)) };
    let planet = build_planet(&spec, &mut |_, _| {}).unwrap();
    assert!(planet.stats.map_fidelity.is_none() && planet.stats.lakes.is_none());
}
