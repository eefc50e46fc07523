//! Decoding and sampling tests: real sample maps from `maps/`, and synthetic
//! images built with the `image`/`tiff` encoders that always run.

use image::ExtendedColorType;
use tiff::encoder::colortype;
use tiff::tags::Tag;

use super::test_support::{encode_png, encode_tiff, georef, png_l16, shared, Rng};
use super::*;

fn lim() -> MapLimits {
    MapLimits::default()
}

/// Centre latitude/longitude of pixel (col, row) on a global w x h grid.
fn centre(w: u32, h: u32, col: u32, row: u32) -> (f64, f64) {
    let lat = 90.0 - (f64::from(row) + 0.5) * 180.0 / f64::from(h);
    let lon = -180.0 + (f64::from(col) + 0.5) * 360.0 / f64::from(w);
    (lat, lon)
}

#[test]
fn earth_landmask_fraction_and_places() {
    let Some(bytes) = shared("earth_landmask_ne10m_1024x512.png") else {
        return;
    };
    let m = Map::decode(&bytes, MapKind::Continents, None, None, &lim()).expect("decode");
    assert_eq!((m.width, m.height, m.bounds), (1024, 512, GeoBounds::GLOBE));
    let f = m.land_fraction();
    assert!((0.26..0.32).contains(&f), "land fraction {f}");
    assert!(m.sample(48.85, 2.35).expect("Paris") >= 0.5, "Paris is land");
    assert!(m.sample(0.0, -30.0).expect("Atlantic") < 0.5, "mid-Atlantic is sea");
    assert!(m.sample(-80.0, 0.0).expect("Antarctica") >= 0.5, "Antarctica is land");
}

#[test]
fn synthetic_landmask_is_area_weighted_and_north_up() {
    // Land south of 60°S only: area share (1 - sin 60°)/2 = 0.067; an unweighted count gives 1/6.
    let (w, h) = (72u32, 36u32);
    let data: Vec<u8> = (0..h).flat_map(|r| (0..w).map(move |_| if r >= 30 { 255 } else { 0 })).collect();
    let png = encode_png(w, h, ExtendedColorType::L8, &data);
    let m = Map::decode(&png, MapKind::Continents, None, None, &lim()).expect("decode");
    let want = (1.0 - 60f64.to_radians().sin()) / 2.0;
    assert!((m.land_fraction() - want).abs() < 1e-9, "{}", m.land_fraction());
    assert_eq!(m.sample(-80.0, 10.0), Some(1.0));
    assert_eq!(m.sample(80.0, 10.0), Some(0.0), "row 0 must be the north edge");
    assert_eq!(m.value_at(0, 35), Some(1.0));
    // Grayscale+alpha is accepted with alpha ignored.
    let la: Vec<u8> = data.iter().flat_map(|&v| [v, 7]).collect();
    let png = encode_png(w, h, ExtendedColorType::La8, &la);
    let m2 = Map::decode(&png, MapKind::Continents, None, None, &lim()).expect("LA8");
    assert_eq!(m2.values(), m.values());
}

#[test]
fn etopo_png_and_tiff_agree() {
    let (Some(png), Some(tif)) = (shared("earth_etopo5_1024x512.png"), shared("earth_etopo5_1024x512.tif")) else {
        return;
    };
    let range = Some((-9010.0, 6125.0));
    let p = Map::decode(&png, MapKind::Elevation, range, None, &lim()).expect("png");
    let t = Map::decode(&tif, MapKind::Elevation, None, None, &lim()).expect("tif");
    assert_eq!(t.bounds, GeoBounds::GLOBE);
    assert_eq!(t.pixel_size_deg(), (0.3515625, 0.3515625));
    let mut rng = Rng(42);
    for _ in 0..100 {
        let (lat, lon) = (rng.next() * 179.8 - 89.9, rng.next() * 360.0 - 180.0);
        let (a, b) = (p.sample(lat, lon).expect("png"), t.sample(lat, lon).expect("tif"));
        assert!((a - b).abs() < 2.0, "at {lat},{lon}: png {a} tif {b}");
    }
    for m in [&p, &t] {
        let everest = m.sample(27.99, 86.93).expect("Everest");
        assert!(everest > 4000.0, "Everest area {everest}");
        let mariana = m.sample(11.35, 142.2).expect("Mariana");
        assert!(mariana < -5000.0, "Mariana {mariana}");
    }
    let lf = t.land_fraction();
    assert!((0.25..0.33).contains(&lf), "ETOPO land share {lf}");
}

#[test]
fn synthetic_elevation_png_and_tiff_agree() {
    let (w, h) = (90u32, 45u32);
    let f = |lat: f64, lon: f64| 3000.0 * lat.to_radians().sin() * lon.to_radians().cos();
    let (lo, hi) = (-4000.0, 4000.0);
    let mut v16 = Vec::new();
    let mut vf = Vec::new();
    for r in 0..h {
        for c in 0..w {
            let (lat, lon) = centre(w, h, c, r);
            let z = f(lat, lon);
            v16.push(((z - lo) / (hi - lo) * 65535.0).round() as u16);
            vf.push(z as f32);
        }
    }
    let png = png_l16(w, h, &v16);
    let geo = georef(GeoBounds::GLOBE, w, h);
    let tif = encode_tiff::<colortype::Gray32Float>(w, h, &vf, Some(geo), &[], None);
    let p = Map::decode(&png, MapKind::Elevation, Some((lo, hi)), None, &lim()).expect("png");
    let t = Map::decode(&tif, MapKind::Elevation, None, None, &lim()).expect("tif");
    assert_eq!(t.bounds, GeoBounds::GLOBE);
    let mut rng = Rng(7);
    for _ in 0..100 {
        let (lat, lon) = (rng.next() * 180.0 - 90.0, rng.next() * 720.0 - 360.0);
        let (a, b) = (p.sample(lat, lon).expect("png"), t.sample(lat, lon).expect("tif"));
        assert!((a - b).abs() < 0.2, "at {lat},{lon}: png {a} tif {b}");
    }
    // At a pixel centre the sample is that pixel's value.
    let (lat, lon) = centre(w, h, 17, 9);
    assert!((t.sample(lat, lon).expect("centre") - f(lat, lon) as f32).abs() < 1e-3);
    // 16-bit mapping: v = 65535 is the top of the range.
    let top = png_l16(1, 1, &[65535]);
    let m = Map::decode(&top, MapKind::Elevation, Some((lo, hi)), None, &lim()).expect("1px");
    assert_eq!(m.values(), &[4000.0]);
}

#[test]
fn jacksboro_tiff_bounds_and_samples() {
    let (Some(tif), Some(json)) =
        (shared("region_jacksboro_tn_403x344.tif"), shared("region_jacksboro_tn_403x344.json"))
    else {
        return;
    };
    let meta: serde_json::Value = serde_json::from_slice(&json).expect("json");
    let jb = &meta["bounds_deg"];
    let m = Map::decode(&tif, MapKind::Elevation, None, None, &lim()).expect("tif");
    assert_eq!((m.width, m.height), (403, 344));
    for (got, key) in
        [(m.bounds.west, "west"), (m.bounds.south, "south"), (m.bounds.east, "east"), (m.bounds.north, "north")]
    {
        let want = jb[key].as_f64().expect("bound");
        assert!((got - want).abs() < 1e-6, "{key}: {got} vs {want}");
    }
    assert!(!m.bounds.is_global());
    let mut rng = Rng(3);
    for _ in 0..50 {
        let lat = m.bounds.south + rng.next() * (m.bounds.north - m.bounds.south);
        let lon = m.bounds.west + rng.next() * (m.bounds.east - m.bounds.west);
        let z = m.sample(lat, lon).expect("inside");
        assert!((236.0..=1076.0).contains(&z), "{z} at {lat},{lon}");
    }
    assert_eq!(m.sample(36.6, -84.5), None, "west of the map");
    assert_eq!(m.sample(36.8, -84.2), None, "north of the map");
    let here = m.sample(36.6, -84.2);
    assert!(here.is_some());
    assert_eq!(m.sample(36.6, -84.2 + 360.0), here, "same place, lon + 360");
    assert_eq!(m.land_fraction(), 1.0);

    // The PNG with its range and the json bounds gives the same terrain.
    if let Some(png) = shared("region_jacksboro_tn_403x344.png") {
        let p = Map::decode(&png, MapKind::Elevation, Some((236.0, 1076.0)), Some(m.bounds), &lim()).expect("png");
        let (a, b) = (p.sample(36.6, -84.2).expect("p"), m.sample(36.6, -84.2).expect("t"));
        assert!((a - b).abs() < 1.0, "png {a} tif {b}");
    }
}

#[test]
fn synthetic_regional_tiff_georeference_and_nodata() {
    let b = GeoBounds { west: 10.0, south: 40.0, east: 12.0, north: 41.0 };
    let (w, h) = (4u32, 2u32);
    let v: Vec<i16> = vec![100, 200, 300, 400, 500, -9999, 700, 800];
    let tif = encode_tiff::<colortype::GrayI16>(w, h, &v, Some(georef(b, w, h)), &[], Some("-9999"));
    let m = Map::decode(&tif, MapKind::Elevation, None, Some(GeoBounds::GLOBE), &lim()).expect("tif");
    assert_eq!(m.bounds, b, "tags win over the bounds argument");
    assert_eq!(m.pixel_size_deg(), (0.5, 0.5));
    // Centres of row 0 are at lat 40.75, columns at lon 10.25, 10.75, ...
    assert_eq!(m.sample(40.75, 10.25), Some(100.0));
    assert_eq!(m.sample(40.75, 10.5), Some(150.0), "halfway between two centres");
    assert_eq!(m.sample(41.0, 10.0), Some(100.0), "clamped at the NW corner");
    assert_eq!(m.sample(40.5, 10.25), Some(300.0), "halfway between rows");
    assert_eq!(m.sample(40.1, 10.75), None, "inside the nodata pixel");
    assert_eq!(m.sample(40.25, 10.4), Some(500.0), "nodata neighbour left out");
    assert_eq!(m.sample(40.5, 9.99), None);
    assert_eq!(m.sample(41.01, 11.0), None);
    assert_eq!(m.sample(f64::NAN, 11.0), None);
    assert!(m.values()[5].is_nan());
    assert_eq!(m.value_range(), Some((100.0, 800.0)));

    // Without tags the bounds argument is used; pixel-is-point shifts half a pixel.
    let plain = encode_tiff::<colortype::GrayI16>(w, h, &v, None, &[], None);
    let m = Map::decode(&plain, MapKind::Elevation, None, Some(b), &lim()).expect("plain");
    assert_eq!(m.bounds, b);
    let m = Map::decode(&plain, MapKind::Elevation, None, None, &lim()).expect("plain");
    assert_eq!(m.bounds, GeoBounds::GLOBE);
    let keys = vec![1, 1, 0, 2, 1024, 0, 1, 2, 1025, 0, 1, 2];
    let point = ([0.5, 0.5, 0.0], [0.0, 0.0, 0.0, 10.25, 40.75, 0.0]);
    let tif = encode_tiff::<colortype::GrayI16>(w, h, &v, Some(point), &[(Tag::GeoKeyDirectoryTag, keys)], None);
    let m = Map::decode(&tif, MapKind::Elevation, None, None, &lim()).expect("point");
    assert_eq!(m.bounds, b);
}

#[test]
fn synthetic_tiff_sample_types() {
    let geo = Some(georef(GeoBounds::GLOBE, 2, 1));
    let cases = [
        encode_tiff::<colortype::Gray16>(2, 1, &[5u16, 65535], geo, &[], None),
        encode_tiff::<colortype::GrayI32>(2, 1, &[5i32, 65535], geo, &[], None),
        encode_tiff::<colortype::Gray64Float>(2, 1, &[5.0f64, 65535.0], geo, &[], None),
    ];
    for tif in cases {
        let m = Map::decode(&tif, MapKind::Elevation, None, None, &lim()).expect("decode");
        assert_eq!(m.values(), &[5.0, 65535.0]);
    }
    let f = encode_tiff::<colortype::Gray32Float>(2, 1, &[-0.1f32, f32::NAN], geo, &[], Some("-0.1"));
    let m = Map::decode(&f, MapKind::Elevation, None, None, &lim()).expect("f32");
    assert!(m.values().iter().all(|v| v.is_nan()), "float32 nodata and NaN");
    assert_eq!(m.value_range(), None);
    assert_eq!(m.land_fraction(), 0.0);
}

#[test]
fn global_maps_wrap_in_longitude_and_regional_ones_do_not() {
    // Values equal the column index: 0, 1, 2, 3.
    let g = Map::from_values(MapKind::Elevation, 4, 1, GeoBounds::GLOBE, vec![0.0, 1.0, 2.0, 3.0]).expect("map");
    // Column centres at -135, -45, 45, 135; at ±180 the sample blends the last and first column.
    assert_eq!(g.sample(0.0, -180.0), Some(1.5));
    assert_eq!(g.sample(0.0, 180.0), Some(1.5));
    assert_eq!(g.sample(0.0, -157.5), Some(0.75));
    assert_eq!(g.sample(0.0, 45.0 + 720.0), Some(2.0));
    assert_eq!(g.sample(90.0, 45.0), Some(2.0));
    assert_eq!(g.sample(-90.0, -135.0), Some(0.0));
    assert_eq!(g.sample(90.5, 0.0), None);
    let b = GeoBounds { west: -180.0, south: -10.0, east: -90.0, north: 10.0 };
    let r = Map::from_values(MapKind::Elevation, 4, 1, b, vec![0.0, 1.0, 2.0, 3.0]).expect("map");
    assert_eq!(r.sample(0.0, -180.0), Some(0.0), "clamped, no wrap");
    assert_eq!(r.sample(0.0, 180.0), Some(0.0), "180 E is 180 W");
    assert_eq!(r.sample(0.0, -90.0), Some(3.0));
    assert_eq!(r.sample(0.0, -89.0), None);
    assert_eq!(r.sample(0.0, 0.0), None);
}

#[test]
fn geo_bounds_parse_and_geometry() {
    let b = GeoBounds::parse(" -84.5, 36 ,-84,37").expect("parse");
    assert_eq!(b, GeoBounds { west: -84.5, south: 36.0, east: -84.0, north: 37.0 });
    assert!(!b.is_global());
    assert!(GeoBounds::parse("-180,-90,180,90").expect("globe").is_global());
    let four_pi = 4.0 * std::f64::consts::PI;
    assert!((GeoBounds::GLOBE.area_steradians() - four_pi).abs() < 1e-12);
    let north = GeoBounds { west: -180.0, south: 0.0, east: 180.0, north: 90.0 };
    assert!((north.area_steradians() - four_pi / 2.0).abs() < 1e-12);
    let dateline = GeoBounds { west: 170.0, south: -5.0, east: 180.0, north: 5.0 };
    assert!(dateline.contains(0.0, -180.0) && dateline.contains(0.0, 175.0 - 360.0));
    assert!(!dateline.contains(0.0, -179.0) && !dateline.contains(6.0, 175.0));
    assert!(GeoBounds::GLOBE.contains(-90.0, 1234.5));
    let json = serde_json::to_string(&b).expect("json");
    assert_eq!(serde_json::from_str::<GeoBounds>(&json).expect("back"), b);
}

#[test]
fn map_kind_names() {
    assert_eq!("continents".parse::<MapKind>().ok(), Some(MapKind::Continents));
    assert_eq!("Elevation".parse::<MapKind>().ok(), Some(MapKind::Elevation));
    let e = "height".parse::<MapKind>().expect_err("unknown kind");
    assert_eq!((e.code(), e.field()), ("invalid_map_kind", "map_kind"));
    assert_eq!(MapKind::Elevation.to_string(), "elevation");
    assert_eq!(serde_json::to_string(&MapKind::Continents).expect("json"), "\"continents\"");
    let k: MapKind = serde_json::from_str("\"elevation\"").expect("json");
    assert_eq!(k, MapKind::Elevation);
    assert_eq!(MapLimits::default().max_pixels, 16384 * 4096);
    assert_eq!(MapLimits::default().max_bytes, 64 * 1024 * 1024);
}

#[test]
fn ocean_pixels_join_through_straits_and_across_the_antimeridian() {
    // 8x4 globe, rows north to south. The ocean (-100 m) spans columns 7 and 0 across the
    // antimeridian and reaches column 2 by a diagonal strait; a shallow basin (-30 m) at column 4,
    // rows 0-1, is land-locked; a deep one (-2000 m) at column 5, row 3, is sea whatever joins it.
    let l = 100.0f32;
    #[rustfmt::skip]
    let values = vec![
        -100.0, l, l, l, -30.0, l, l, -100.0,
        -100.0, -100.0, l, l, -30.0, l, l, -100.0,
        -100.0, l, -100.0, l, l, l, l, -100.0,
        -100.0, l, l, l, l, -2000.0, l, -100.0,
    ];
    let map = Map::from_values(MapKind::Elevation, 8, 4, GeoBounds::GLOBE, values.clone()).unwrap();
    let ocean = map.ocean_pixels();
    let at = |c: usize, r: usize| ocean[r * 8 + c];
    assert!(at(0, 0) && at(7, 3) && at(2, 2), "the ocean and its strait");
    assert!(!at(4, 0) && !at(4, 1), "a land-locked basin above the ocean depth is no ocean");
    assert!(at(5, 3), "a basin deeper than OCEAN_DEPTH_M is ocean");
    assert!(!at(1, 0), "land is no ocean");
    // A regional map: a basin touching its edge joins the sea outside it.
    let b = GeoBounds { west: 0.0, south: 0.0, east: 8.0, north: 4.0 };
    let mut v = vec![l; 32];
    v[8] = -5.0; // row 1, column 0: on the west edge
    v[8 + 3] = -5.0; // row 1, column 3: inside
    let ocean = Map::from_values(MapKind::Elevation, 8, 4, b, v).unwrap().ocean_pixels();
    assert!(ocean[8] && !ocean[11]);
}
