//! Snapshots of the shipped Earth map checked against the map and the mesh (needs a wgpu
//! adapter: lavapipe in CI).

use super::*;
use crate::geo::direction;
use crate::maps::{Map, MapKind, MapLimits};
use crate::mesh::VertexFlags;
use crate::planet::{build_planet, Planet, PlanetSpec};
use std::sync::OnceLock;

fn earth() -> &'static (Planet, Params) {
    static EARTH: OnceLock<(Planet, Params)> = OnceLock::new();
    EARTH.get_or_init(|| {
        let bytes =
            std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/maps/earth_landmask_ne10m_1024x512.png")).unwrap();
        let map = Map::decode(&bytes, MapKind::Continents, None, None, &MapLimits::default()).unwrap();
        let params = Params::default();
        let spec = PlanetSpec { seed: 42, params: params.clone(), map: Some(map.into()), precipitation: None };
        (build_planet(&spec, &mut |_, _| {}).unwrap(), params)
    })
}

fn renderer() -> &'static Renderer {
    shared().expect("a wgpu adapter (install mesa-vulkan-drivers for lavapipe)")
}

/// Pixel of a planet-frame point, if it is in front of the camera and inside the image.
fn pixel_of(cam: &Camera, p: DVec3) -> Option<(u32, u32)> {
    let c = scene::view_projection(cam) * (p - cam.eye).extend(1.0);
    if c.w <= 0.0 {
        return None;
    }
    let (x, y) = (c.x / c.w, c.y / c.w);
    let px = ((x + 1.0) * 0.5 * cam.width as f64).floor();
    let py = ((1.0 - y) * 0.5 * cam.height as f64).floor();
    (px >= 0.0 && py >= 0.0 && px < cam.width as f64 && py < cam.height as f64).then_some((px as u32, py as u32))
}

fn rgb(img: &[u8], cam: &Camera, (x, y): (u32, u32)) -> [i32; 3] {
    let i = ((y * cam.width + x) * 4) as usize;
    [img[i] as i32, img[i + 1] as i32, img[i + 2] as i32]
}

fn orbit(lat: f64, lon: f64, size: u32) -> Camera {
    let (_, params) = earth();
    let eye = direction(lat, lon) * params.radius_m * 3.2;
    let q = format!("eye={},{},{}&target=0,0,0&width={size}&height={size}&fov=40", eye.x, eye.y, eye.z);
    Camera::parse_query(&q, params.radius_m).unwrap().0
}

#[test]
fn orbit_view_shows_sea_land_and_ice_where_the_map_has_them() {
    let (planet, params) = earth();
    let sun = Some(DVec3::new(1.0, 0.0, 0.3));
    let cam = orbit(5.0, 10.0, 384);
    let shot = Shot { camera: cam.clone(), sun };
    let img = snapshot(renderer(), &planet.mesh, params, &shot, 300_000, None).unwrap();
    assert_eq!(img.len(), 384 * 384 * 4);
    let on_ground = |lat: f64, lon: f64| direction(lat, lon) * (params.radius_m + params.sea_level_m);
    // Share of water-coloured pixels in a 9x9 window around a point (rivers seen from orbit
    // are several pixels wide, so single pixels on land may be water).
    let watery = |lat: f64, lon: f64| {
        let (x, y) = pixel_of(&cam, on_ground(lat, lon)).unwrap();
        let mut n = 0;
        for dy in -4i32..=4 {
            for dx in -4i32..=4 {
                let [r, g, b] = rgb(&img, &cam, ((x as i32 + dx) as u32, (y as i32 + dy) as u32));
                n += (b > r + 20 && b > g) as u32;
            }
        }
        n as f64 / 81.0
    };
    // Sea (Gulf of Guinea, South Atlantic, off Senegal): blue.
    for (lat, lon) in [(-5.0, 0.0), (-20.0, -5.0), (10.0, -30.0)] {
        assert!(watery(lat, lon) > 0.99, "sea at {lat},{lon}: {}", watery(lat, lon));
    }
    // Land (Sahara, Congo basin, Sudan): mostly not blue.
    for (lat, lon) in [(23.0, 10.0), (0.0, 22.0), (15.0, 30.0)] {
        assert!(watery(lat, lon) < 0.5, "land at {lat},{lon}: {}", watery(lat, lon));
    }
    // Behind the limb: black space (the corner of the image).
    let [r, g, b] = rgb(&img, &cam, (2, 2));
    assert!(r + g + b < 60, "space: {r},{g},{b}");

    // Antarctica seen from above the south pole in sunlight: ice, white.
    let cam = orbit(-89.0, 0.0, 256);
    let shot = Shot { camera: cam.clone(), sun: Some(DVec3::new(0.2, 0.0, -1.0)) };
    let img = snapshot(renderer(), &planet.mesh, params, &shot, 300_000, None).unwrap();
    let [r, g, b] = rgb(&img, &cam, pixel_of(&cam, on_ground(-82.0, 40.0)).unwrap());
    assert!(r > 170 && g > 170 && b > 170, "ice: {r},{g},{b}");
}

#[test]
fn ground_view_shows_a_river_where_the_mesh_has_one() {
    let (planet, params) = earth();
    let mesh = &planet.mesh;
    // A river vertex with dry land all around it (not the mouth), on a long river, low in
    // the hills (snow is nearly as blue as water).
    let mut reaches = planet.rivers.reaches(mesh, &Default::default());
    reaches.sort_by(|a, b| b.upstream_area_m2.total_cmp(&a.upstream_area_m2));
    let middle = |r: &&crate::planet::network::Reach| r.vertices[r.vertices.len() / 2];
    let reach = reaches
        .iter()
        .find(|r| r.vertices.len() > 6 && mesh.vertices[middle(r) as usize].ground < params.sea_level_m + 2000.0)
        .expect("a long river");
    let river = middle(&reach);
    assert!(mesh.vertices[river as usize].flags.contains(VertexFlags::RIVER));
    let v = &mesh.vertices[river as usize];
    let up = v.p().normalize();
    let eye = v.p() + up * 1500.0 + up.any_orthonormal_vector() * 100.0;
    let q = format!(
        "eye={},{},{}&target={},{},{}&width=320&height=240&fov=50",
        eye.x, eye.y, eye.z, v.pos[0], v.pos[1], v.pos[2]
    );
    // Sun 50 degrees from the zenith, away from the camera: no glint on the water.
    let sun = (up + up.cross(eye - v.p()).normalize() * 1.2).normalize();
    let shot = Shot { camera: Camera::parse_query(&q, params.radius_m).unwrap().0, sun: Some(sun) };
    let mut adapter = Adapter::new(mesh.clone(), params.clone());
    adapter.adapt(&shot.camera, Some(400_000));
    let adapted = adapter.mesh();
    let img = draw(renderer(), adapted, params, &shot).unwrap();
    let cam = &shot.camera;
    // The river vertex keeps its index; its water stands above its bed, and it is drawn as water.
    let av = &adapted.vertices[river as usize];
    assert!(av.submerged());
    let (x, y) = pixel_of(cam, av.p()).unwrap();
    let [r, g, b] = rgb(&img, cam, (x, y));
    assert!(b > r + 15 && b > g, "river pixel: {r},{g},{b}");
    // Dry land around it is not water-coloured somewhere in the view.
    let dry = adapted
        .vertices
        .iter()
        .filter(|w| !w.submerged() && w.p().distance(av.p()) < 400.0 && w.p().distance(av.p()) > 150.0)
        .filter_map(|w| pixel_of(cam, w.p()))
        .map(|p| rgb(&img, cam, p))
        .filter(|[r, g, b]| r >= b || g >= b)
        .count();
    assert!(dry > 3, "land around the river: {dry}");
}

#[test]
fn the_same_shot_gives_the_same_bytes_and_formats_decode() {
    let (planet, params) = earth();
    let shot = Shot { camera: orbit(40.0, -100.0, 200), sun: None };
    let a = snapshot(renderer(), &planet.mesh, params, &shot, 100_000, None).unwrap();
    let b = snapshot(renderer(), &planet.mesh, params, &shot, 100_000, None).unwrap();
    assert!(a == b, "pixels differ between identical renders");
    let png = encode(&a, 200, 200, ImageFormat::Png);
    assert_eq!(png, encode(&b, 200, 200, ImageFormat::Png));
    let decoded = image::load_from_memory(&png).unwrap().to_rgba8();
    assert_eq!(decoded.as_raw(), &a);
    let jpeg = encode(&a, 200, 200, ImageFormat::Jpeg);
    assert_eq!(&jpeg[..2], &[0xFF, 0xD8]);
    assert_eq!(image::load_from_memory(&jpeg).unwrap().width(), 200);
}

#[test]
fn shots_parse_the_sun_and_reject_bad_values() {
    let r = 6_371_000.0;
    let base = "eye=20000000,0,0&target=0,0,0";
    let (shot, rest) = Shot::parse_query(&format!("{base}&sun=0,0,2&max_faces=10"), r).unwrap();
    assert_eq!(shot.sun, Some(DVec3::Z));
    assert_eq!(rest, vec![("max_faces".to_string(), "10".to_string())]);
    assert_eq!(Shot::parse_query(&shot.to_query(), r).unwrap().0, shot);
    for bad in ["sun=0,0,0", "sun=1,2", "sun=a,b,c", "sun=NaN,0,1", "sun=inf,0,0"] {
        let e = Shot::parse_query(&format!("{base}&{bad}"), r).unwrap_err();
        assert_eq!(e.field, "sun", "{bad}");
    }
    for (bad, field) in [("width=0", "width"), ("height=8193", "height"), ("width=-3", "width")] {
        let e = Shot::parse_query(&format!("{base}&{bad}"), r).unwrap_err();
        assert_eq!(e.field, field, "{bad}");
    }
    assert_eq!("JPG".parse::<ImageFormat>(), Ok(ImageFormat::Jpeg));
    assert!("gif".parse::<ImageFormat>().is_err());
}

#[test]
fn one_metre_above_the_ground_the_near_ground_and_the_sky_are_drawn() {
    let (planet, params) = earth();
    let mesh = &planet.mesh;
    // A dry land vertex in the Sahara; the eye 1 m above it, looking at the horizon ahead.
    let v = mesh
        .vertices
        .iter()
        .filter(|v| !v.submerged() && v.flags.contains(VertexFlags::CONTINENT))
        .min_by(|a, b| {
            a.p()
                .normalize()
                .distance(direction(22.0, 12.0))
                .total_cmp(&b.p().normalize().distance(direction(22.0, 12.0)))
        })
        .unwrap();
    let up = v.p().normalize();
    let east = DVec3::Z.cross(up).normalize();
    let eye = v.p() + up * 1.0;
    let target = eye + east * 1000.0 - up * 20.0;
    let q = format!(
        "eye={},{},{}&target={},{},{}&width=160&height=120&fov=60",
        eye.x, eye.y, eye.z, target.x, target.y, target.z
    );
    let shot = Shot { camera: Camera::parse_query(&q, params.radius_m).unwrap().0, sun: Some(up) };
    let img = snapshot(renderer(), mesh, params, &shot, 300_000, None).unwrap();
    let cam = &shot.camera;
    // The bottom row is ground right under the eye (not clipped by the near plane), the top row
    // is sky; every pixel is one or the other, no holes to space.
    for x in (0..160).step_by(8) {
        let [r, g, b] = rgb(&img, cam, (x, 119));
        assert!(r >= b, "ground at ({x}, 119): {r},{g},{b}");
        let [r, g, b] = rgb(&img, cam, (x, 0));
        assert!(b > r + 30, "sky at ({x}, 0): {r},{g},{b}");
    }
    assert!(img.chunks_exact(4).all(|p| p[0] as u32 + p[1] as u32 + p[2] as u32 > 60), "no black pixels");
}

/// The planet of the shipped Earth DEM.
fn earth_dem() -> &'static (Planet, Params) {
    static EARTH: OnceLock<(Planet, Params)> = OnceLock::new();
    EARTH.get_or_init(|| {
        let bytes = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/maps/earth_etopo5_1024x512.tif")).unwrap();
        let map = Map::decode(&bytes, MapKind::Elevation, None, None, &MapLimits::default()).unwrap();
        let params = Params::default();
        let spec = PlanetSpec { seed: 42, params: params.clone(), map: Some(map.into()), precipitation: None };
        (build_planet(&spec, &mut |_, _| {}).unwrap(), params)
    })
}

/// Share of water-coloured pixels (blue over red and green) of an image.
fn water_share(img: &[u8]) -> f64 {
    let px = img.chunks_exact(4).filter(|p| p[2] as i32 > p[0] as i32 + 20 && p[2] > p[1]).count();
    px as f64 / (img.len() / 4) as f64
}

/// Seen from 1,250 km above the Sahara, rivers are as wide as their channels (a wadi is a dry
/// bed, a perennial river far narrower than a pixel), so the desert does not look wet: under 2 %
/// of the image is water (the one terminal lake near Lake Chad's basin), against 8 % when every
/// face beside a river is flooded to the river's level (the planet without its channels).
#[test]
fn the_sahara_from_orbit_is_dry() {
    let (planet, params) = earth_dem();
    let (lat, lon, altitude) = (22.0, 12.0, 1_250_000.0);
    let (eye, target) = (direction(lat, lon) * (params.radius_m + altitude), direction(lat, lon) * params.radius_m);
    let q = format!(
        "eye={},{},{}&target={},{},{}&width=320&height=240&fov=60",
        eye.x, eye.y, eye.z, target.x, target.y, target.z
    );
    let shot = Shot { camera: Camera::parse_query(&q, params.radius_m).unwrap().0, sun: None };
    let img = snapshot(renderer(), &planet.mesh, params, &shot, 300_000, None).unwrap();
    let share = water_share(&img);
    let unchannelled = Mesh { channels: None, ..planet.mesh.clone() };
    let flooded = water_share(&snapshot(renderer(), &unchannelled, params, &shot, 300_000, None).unwrap());
    assert!(share <= 0.02, "water on {:.1} % of the Sahara view", share * 100.0);
    assert!(flooded > 2.0 * share, "without channels {:.1} %, with {:.1} %", flooded * 100.0, share * 100.0);
}

/// From 2,500 km above Amazonia the Amazon and its great tributaries, kilometres wide but far
/// narrower than a pixel (~8 km here), stay visible as lines at their true width (the share of
/// the pixel they cover), while the Sahara's wadis, dry beds, draw nothing.
#[test]
fn rivers_narrower_than_a_pixel_stay_visible_as_lines() {
    let (planet, params) = earth_dem();
    let view = |lat: f64, lon: f64| {
        let altitude = 2_500_000.0;
        let (eye, target) = (direction(lat, lon) * (params.radius_m + altitude), direction(lat, lon) * params.radius_m);
        let q = format!(
            "eye={},{},{}&target={},{},{}&width=320&height=240&fov=60",
            eye.x, eye.y, eye.z, target.x, target.y, target.z
        );
        let cam = Camera::parse_query(&q, params.radius_m).unwrap().0;
        let mut adapter = crate::adapt::Adapter::new(planet.mesh.clone(), params.clone());
        adapter.adapt(&cam, Some(300_000));
        let mut scene = scene::prepare(adapter.mesh(), params, &cam, scene::default_sun(&cam));
        let with = renderer().draw(&scene, crate::export::climate::Palette::of(params), cam.width, cam.height).unwrap();
        let lines = scene.rivers.len() / 2;
        let coverage: Vec<f32> = scene.rivers.iter().map(|v| v.coverage).collect();
        scene.rivers.clear();
        let without =
            renderer().draw(&scene, crate::export::climate::Palette::of(params), cam.width, cam.height).unwrap();
        // Pixels the lines changed visibly, and how much bluer (blue over the mean of red and green)
        // they became on average.
        let blue = |p: &[u8]| f64::from(p[2]) - 0.5 * (f64::from(p[0]) + f64::from(p[1]));
        let visibly = |a: &[u8], b: &[u8]| a.iter().zip(b).map(|(x, y)| u32::from(x.abs_diff(*y))).sum::<u32>() > 12;
        let sand = without.chunks_exact(4).filter(|p| p[0] as i32 > p[2] as i32 + 30).count();
        let sand_changed = with
            .chunks_exact(4)
            .zip(without.chunks_exact(4))
            .filter(|(a, b)| b[0] as i32 > b[2] as i32 + 30 && visibly(a, b))
            .count();
        let changed: Vec<f64> = with
            .chunks_exact(4)
            .zip(without.chunks_exact(4))
            .filter(|(a, b)| visibly(a, b))
            .map(|(a, b)| blue(a) - blue(b))
            .collect();
        let bluer = changed.iter().sum::<f64>() / changed.len().max(1) as f64;
        (lines, coverage, changed.len(), bluer, sand_changed as f64 / sand.max(1) as f64)
    };
    let (lines, coverage, changed, bluer, _) = view(-3.0, -60.0);
    assert!(lines > 100 && coverage.iter().all(|&c| c > 0.0 && c <= 1.0), "{lines} lines");
    // Sub-pixel: the great rivers cover a fraction of their pixels, not all of them.
    assert!(coverage.iter().any(|&c| c < 0.5) && coverage.iter().any(|&c| c > 0.2), "{coverage:?}");
    assert!(changed > 500 && bluer > 5.0, "{changed} pixels changed, {bluer:.1} bluer");
    // The Sahara's wadis are dry beds: its sand keeps its colour (the Sahel's rivers in the
    // same view draw).
    let (_, _, _, _, sand) = view(22.0, 12.0);
    assert!(sand < 0.01, "lines over {:.1} % of the Sahara's sand", sand * 100.0);
}

/// From 2 km above a river, looking straight down, its water should be as wide on screen as
/// its channel (`3.5 Q^0.51` m at the discharge through it), within 30 %: counted in pixels
/// across the river at the image's centre, on the line perpendicular to the river's edge there,
/// at ~4.8 m a pixel. Rivers of several widths, off lakes and coasts, on the Earth DEM planet.
///
/// `RIVER_SHOTS=DIR` keeps the pictures. A view this close refines the ground beside a river
/// to edges of metres; its channel is carved into them (`export/carve.rs`).
#[test]
fn a_river_seen_from_2_km_is_as_wide_as_its_channel() {
    let (planet, params) = earth_dem();
    let mesh = &planet.mesh;
    let (altitude, size, fov) = (2_000.0, 480u32, 60.0f64);
    // Base-mesh river vertices whose channels a 2 km view frames (300-1,500 m), the first six
    // of twelve spread over the list where the view's mesh joins no more than two river edges
    // (a confluence is left out).
    let rivers: Vec<u32> = (0..mesh.vertices.len() as u32)
        .filter(|&v| {
            let vert = &mesh.vertices[v as usize];
            vert.flags.contains(VertexFlags::RIVER)
                && !vert.flags.intersects(VertexFlags(VertexFlags::LAKE.0 | VertexFlags::COAST.0))
                && crate::export::water::channel_width(mesh, vert).is_some_and(|w| (300.0..1_500.0).contains(&w))
        })
        .collect();
    assert!(rivers.len() > 50, "{} wide river vertices", rivers.len());
    let mut ratios = Vec::new();
    for &v in rivers.iter().step_by(rivers.len() / 12) {
        if ratios.len() == 6 {
            break;
        }
        let vert = &mesh.vertices[v as usize];
        let (p, up) = (vert.p(), vert.p().normalize());
        let water = p + up * (vert.water - vert.ground).max(0.0);
        let eye = water + up * altitude;
        let q = format!(
            "eye={},{},{}&target={},{},{}&width={size}&height={size}&fov={fov}",
            eye.x, eye.y, eye.z, water.x, water.y, water.z
        );
        let cam = Camera::parse_query(&q, params.radius_m).unwrap().0;
        let mut adapter = crate::adapt::Adapter::new(mesh.clone(), params.clone());
        adapter.adapt(&cam, Some(1_000_000));
        let m = adapter.mesh();
        // The river's direction at the vertex: its river edges in the view's mesh.
        let at = (0..m.vertices.len())
            .min_by(|&a, &b| m.vertices[a].p().distance(p).total_cmp(&m.vertices[b].p().distance(p)));
        let at = at.unwrap() as u32;
        let ends: Vec<DVec3> = m
            .edges
            .iter()
            .filter(|e| e.kind == crate::mesh::EdgeKind::River && e.v.contains(&at))
            .map(|e| m.vertices[(e.v[0] + e.v[1] - at) as usize].p())
            .collect();
        if ends.len() != 2 {
            continue;
        }
        let width = crate::export::water::channel_width(m, &m.vertices[at as usize]).unwrap();
        let scene = scene::prepare(m, params, &cam, scene::default_sun(&cam));
        let img = renderer().draw(&scene, crate::export::climate::Palette::of(params), size, size).unwrap();
        if let Ok(dir) = std::env::var("RIVER_SHOTS") {
            std::fs::write(format!("{dir}/river-{v}.png"), encode(&img, size, size, ImageFormat::Png)).unwrap();
        }
        // Screen direction of the river, and the pixels across it from the centre.
        let towards = |e: DVec3| water + (e - p).normalize() * 100.0;
        let (a, b) = (pixel_of(&cam, towards(ends[0])), pixel_of(&cam, towards(ends[1])));
        let (Some(a), Some(b)) = (a, b) else { continue };
        let along = glam::DVec2::new(f64::from(b.0) - f64::from(a.0), f64::from(b.1) - f64::from(a.1)).normalize();
        let across = glam::DVec2::new(-along.y, along.x);
        let centre = glam::DVec2::splat(f64::from(size) * 0.5);
        let is_water = |q: glam::DVec2| {
            let (x, y) = (q.x.round() as i64, q.y.round() as i64);
            (0..i64::from(size)).contains(&x) && (0..i64::from(size)).contains(&y) && {
                let [r, g, b] = rgb(&img, &cam, (x as u32, y as u32));
                b > r + 20 && b > g
            }
        };
        let run = |dir: f64| (0..size).take_while(|&k| is_water(centre + across * dir * f64::from(k))).count();
        let pixels = (run(1.0) + run(-1.0)).saturating_sub(1) as f64;
        let metres_per_pixel = 2.0 * altitude * (fov.to_radians() * 0.5).tan() / f64::from(size);
        ratios.push((width.round(), (pixels * metres_per_pixel).round(), pixels * metres_per_pixel / width));
    }
    println!("channel width, width on screen (m), ratio: {ratios:?}");
    assert!(ratios.len() >= 4, "{ratios:?}");
    assert!(ratios.iter().all(|r| (0.7..=1.3).contains(&r.2)), "{ratios:?}");
}
