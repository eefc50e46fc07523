use super::*;
use crate::export::test_planet;
use crate::geo::lat_lon;
use crate::mesh::raster::*;
use crate::mesh::NONE;
use crate::planet::continents::{classify, land_fraction};
use crate::planet::shape::{octahedron, refine_to};
use glam::DVec3;
use std::io::Cursor;
use tiff::decoder::{Decoder, DecodingResult};
use tiff::tags::Tag;

/// Smallest face whose closed spherical triangle holds `d` (brute force, exact test).
fn brute_force(mesh: &Mesh, d: DVec3) -> Option<u32> {
    (0..mesh.faces.len()).find(|&f| inside(&edge_planes(mesh, f), d)).map(|f| f as u32)
}

/// Normalised distance of `d` outside face `f` (<= 0 inside).
fn outside_by(mesh: &Mesh, f: u32, d: DVec3) -> f64 {
    let n = edge_planes(mesh, f as usize);
    n.iter().map(|m| -d.dot(*m) / m.length()).fold(f64::NEG_INFINITY, f64::max)
}

fn check_against_brute_force(mesh: &Mesh, w: u32, h: u32) {
    let r = SphereRaster::new(mesh, w, h);
    assert_eq!(r.faces.len(), (w * h) as usize);
    for row in 0..h {
        for col in 0..w {
            let i = (row * w + col) as usize;
            let d = r.direction(col, row);
            assert_ne!(r.faces[i], NONE, "pixel {col},{row} has no face");
            let expected = brute_force(mesh, d);
            assert_eq!(Some(r.faces[i]), expected, "pixel {col},{row}: smallest containing face");
            let wts = r.weights[i];
            assert!(wts.iter().all(|&x| (0.0..=1.0).contains(&x)));
            assert!((wts.iter().sum::<f32>() - 1.0).abs() < 1e-5);
            // The weights reproduce the pixel's direction on the face's plane.
            let p: DVec3 = (0..3).map(|k| wts[k] as f64 * mesh.pos(mesh.corners(r.faces[i])[k])).sum();
            assert!(p.normalize().dot(d) > 1.0 - 1e-9, "pixel {col},{row}: weights point elsewhere");
        }
    }
}

#[test]
fn every_pixel_of_the_planet_gets_the_smallest_containing_face() {
    check_against_brute_force(&test_planet().mesh, 180, 90);
    // Odd sizes put pixel centres exactly on the equator, the prime meridian and base vertices.
    check_against_brute_force(&test_planet().mesh, 181, 91);
}

#[test]
fn large_faces_poles_and_antimeridian() {
    // The bare octahedron: four faces meet at each pole, two faces touch 180° at a vertex.
    let mut mesh = octahedron(1000.0, 3);
    check_against_brute_force(&mesh, 64, 33);
    let r = SphereRaster::new(&mesh, 64, 32);
    for (i, &f) in r.faces.iter().enumerate() {
        let d = r.direction(i as u32 % 64, i as u32 / 64);
        // Every corner of the pixel's octant face lies on the pixel's side of each axis.
        for v in mesh.corners(f) {
            let p = mesh.pos(v);
            for k in 0..3 {
                assert!(p[k] * d[k] >= 0.0, "pixel {i} in the wrong octant");
            }
        }
    }
    // A lightly refined octahedron has faces straddling the antimeridian away from vertices.
    refine_to(&mut mesh, 40, 3);
    check_against_brute_force(&mesh, 97, 49);
    refine_to(&mut mesh, 300, 3);
    check_against_brute_force(&mesh, 120, 61);
}

#[test]
fn pole_and_antimeridian_pixels_get_containing_faces() {
    let mesh = &test_planet().mesh;
    let (w, h) = (400u32, 200u32);
    let r = SphereRaster::new(mesh, w, h);
    for (col, row) in [(0, 0), (w - 1, 0), (w / 2, 0), (0, h - 1), (w - 1, h - 1), (0, h / 2), (w - 1, h / 2)] {
        let f = r.faces[(row * w + col) as usize];
        assert!(outside_by(mesh, f, r.direction(col, row)) <= 1e-12, "pixel {col},{row}");
    }
    // Pole rows: the faces around the pole share the row; the antimeridian columns see faces
    // from both sides of 180°.
    let top: std::collections::BTreeSet<u32> = r.faces[..w as usize].iter().copied().collect();
    assert!(top.len() >= 3, "faces around the north pole: {top:?}");
}

#[test]
fn least_outside_falls_back_to_the_nearest_face() {
    let mesh = octahedron(1.0, 1);
    let d = DVec3::new(0.3, 0.4, 0.5).normalize();
    let f = least_outside(&mesh, d);
    assert!(outside_by(&mesh, f, d) <= 0.0);
}

#[test]
fn landmask_matches_the_land_fraction() {
    let mesh = &test_planet().mesh;
    let (w, h) = (720u32, 360u32);
    let png = landmask_png(mesh, w, h);
    let img = image::load_from_memory(&png).unwrap();
    assert_eq!(img.color(), image::ColorType::L8);
    let img = img.to_luma8();
    assert_eq!(img.dimensions(), (w, h));
    let (mut land, mut total) = (0.0, 0.0);
    for (_, row, p) in img.enumerate_pixels() {
        assert!(p.0[0] == 0 || p.0[0] == 255);
        let area = SphereRaster::lat_of(row, h).to_radians().cos();
        total += area;
        if p.0[0] == 255 {
            land += area;
        }
    }
    let expected = land_fraction(mesh);
    assert!((land / total - expected).abs() < 0.02, "mask {} vs mesh {expected}", land / total);
    assert_eq!(png, landmask_png(mesh, w, h));
}

#[test]
fn landmask_of_a_hand_made_mesh() {
    // Land in the northern hemisphere only: the mask's upper half is white.
    let mut mesh = octahedron(6_371_000.0, 5);
    refine_to(&mut mesh, 200, 5);
    for f in 0..mesh.faces.len() {
        let z: f64 = mesh.corners(f as u32).iter().map(|&v| mesh.pos(v).z).sum();
        mesh.set_face_kind(f as u32, if z > 0.0 { FaceKind::Land } else { FaceKind::Sea });
    }
    classify(&mut mesh);
    let img = image::load_from_memory(&landmask_png(&mesh, 40, 20)).unwrap().to_luma8();
    assert_eq!(img.get_pixel(5, 0).0[0], 255);
    assert_eq!(img.get_pixel(5, 19).0[0], 0);
}

#[test]
fn elevation_tiff_is_georeferenced_and_matches_the_mesh() {
    let planet = test_planet();
    let mesh = &planet.mesh;
    let params = Params::default();
    let (w, h) = (721u32, 361u32);
    let bytes = elevation_tiff(mesh, &params, w, h);
    assert_eq!(bytes, elevation_tiff(mesh, &params, w, h), "deterministic");
    let mut dec = Decoder::new(Cursor::new(&bytes)).unwrap();
    assert_eq!(dec.dimensions().unwrap(), (w, h));
    assert_eq!(dec.get_tag_unsigned::<u16>(Tag::SampleFormat).unwrap(), 3, "IEEE float");
    assert_eq!(dec.get_tag_unsigned::<u16>(Tag::BitsPerSample).unwrap(), 32);
    assert_eq!(dec.get_tag_unsigned::<u16>(Tag::SamplesPerPixel).unwrap(), 1);
    assert_eq!(dec.get_tag_f64_vec(Tag::ModelPixelScaleTag).unwrap(), vec![360.0 / w as f64, 180.0 / h as f64, 0.0]);
    assert_eq!(dec.get_tag_f64_vec(Tag::ModelTiepointTag).unwrap(), vec![0.0, 0.0, 0.0, -180.0, 90.0, 0.0]);
    let keys = dec.get_tag_u16_vec(Tag::GeoKeyDirectoryTag).unwrap();
    assert_eq!(keys[3] as usize * 4 + 4, keys.len());
    let key = |id: u16| keys[4..].chunks(4).find(|k| k[0] == id).map(|k| k[3]);
    assert_eq!(key(1024), Some(2), "geographic model");
    assert_eq!(key(1025), Some(1), "pixel is area");
    assert_eq!(key(2048), Some(4326));
    assert_eq!(key(2054), Some(9102));
    let data = match dec.read_image().unwrap() {
        DecodingResult::F32(v) => v,
        other => panic!("not float32: {other:?}"),
    };
    assert_eq!(data.len(), (w * h) as usize);
    let alt = |v: usize| mesh.vertices[v].ground - params.sea_level_m;

    // Pixel (360, 180) of a 721 x 361 grid is centred exactly on (0°N, 0°E), a base vertex.
    let on_x = |v: &usize| {
        let p = mesh.pos(*v as u32);
        p.x > 0.0 && p.y == 0.0 && p.z == 0.0
    };
    let v0 = (0..mesh.vertices.len()).find(on_x).expect("vertex on +X");
    let got = data[(180 * w + 360) as usize] as f64;
    assert!((got - alt(v0)).abs() < 1e-2, "pixel {got} vs vertex {}", alt(v0));

    // Near any vertex, the value lies within the range of the vertex's one-ring.
    let mut ring: Vec<(f64, f64)> = vec![(f64::INFINITY, f64::NEG_INFINITY); mesh.vertices.len()];
    for f in mesh.triangles() {
        for &v in &f {
            for &u in &f {
                let e = &mut ring[v as usize];
                *e = (e.0.min(alt(u as usize)), e.1.max(alt(u as usize)));
            }
        }
    }
    for v in (0..mesh.vertices.len()).step_by(7) {
        let (lat, lon) = lat_lon(mesh.pos(v as u32));
        let col = (((lon + 180.0) / 360.0 * w as f64) as u32).min(w - 1);
        let row = (((90.0 - lat) / 180.0 * h as f64) as u32).min(h - 1);
        let got = data[(row * w + col) as usize] as f64;
        let (lo, hi) = ring[v];
        assert!(got >= lo - 0.01 && got <= hi + 0.01, "vertex {v}: {got} outside [{lo}, {hi}]");
    }
    // Sea is below sea level somewhere and land above it somewhere.
    assert!(data.iter().any(|&x| x < -100.0) && data.iter().any(|&x| x > 100.0));
}
