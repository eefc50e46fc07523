//! The colour preview: an equirectangular RGB PNG for people.
//!
//! Sea pixels take `water_colour` of the interpolated depth below sea level; lake pixels (where
//! the corners under a lake, [`VertexFlags::LAKE`], weigh at least half) that of the lake's
//! interpolated depth; land pixels take the
//! climate colour of their latitude and interpolated altitude, hillshaded with light from the
//! north-west, 45° high, on the interpolated surface normal (its slope exaggerated
//! `RELIEF_EXAGGERATION` times, since planetary relief is gentle at preview scale). Rivers are
//! drawn on top as polylines of their reaches in longitude/latitude, lowest Strahler order first:
//! 1 px wide for orders 1-2, 2 px for 3-4, 3 px from 5, from light to dark blue with the order;
//! not across lakes (a segment between two lake vertices).
//! Segments crossing the antimeridian are drawn the short way, wrapping around the image.

use super::climate::{climate_colour, precipitation_mm, water_colour, Palette};
use super::raster::{encode_png, SphereRaster};
use super::surface_normals;
use crate::geo::lat_lon;
use crate::mesh::{FaceKind, Mesh, VertexFlags};
use crate::params::Params;
use crate::planet::RiverGraph;
use glam::DVec3;
use rayon::prelude::*;

/// Slope exaggeration for hillshading.
pub const RELIEF_EXAGGERATION: f64 = 10.0;

/// Hillshade factor (1 on flat ground) for a surface normal at direction `d`.
fn shade(d: DVec3, normal: DVec3, lat_deg: f64, lon_deg: f64) -> f64 {
    let (sl, cl) = lat_deg.to_radians().sin_cos();
    let (so, co) = lon_deg.to_radians().sin_cos();
    let east = DVec3::new(-so, co, 0.0);
    let north = DVec3::new(-sl * co, -sl * so, cl);
    let tangential = normal - d * normal.dot(d);
    let n = (d + tangential * RELIEF_EXAGGERATION).normalize_or_zero();
    let h = std::f64::consts::FRAC_1_SQRT_2;
    // Azimuth 315° (north-west), altitude 45°.
    let light = (north - east) * (h * h) + d * h;
    let s = n.dot(light.normalize()) / h;
    (0.55 + 0.45 * s).clamp(0.35, 1.35)
}

fn river_style(strahler: u32) -> ([u8; 3], i64) {
    let t = ((strahler.max(1) - 1) as f64 / 5.0).min(1.0);
    let (light, dark) = ([110.0, 165.0, 240.0], [15.0, 45.0, 140.0]);
    let c = [0, 1, 2].map(|k| (light[k] + (dark[k] - light[k]) * t).round() as u8);
    let width = match strahler {
        0..=2 => 1,
        3..=4 => 2,
        _ => 3,
    };
    (c, width)
}

/// Draws a polyline of `(lon, lat)` points onto an RGB image.
fn draw_line(img: &mut [u8], width: u32, height: u32, pts: &[(f64, f64)], colour: [u8; 3], px: i64) {
    let (w, h) = (width as f64, height as f64);
    let to_xy = |lon: f64, lat: f64| ((lon + 180.0) / 360.0 * w, (90.0 - lat) / 180.0 * h);
    let mut stamp = |x: f64, y: f64| {
        let x0 = (x - (px - 1) as f64 / 2.0).floor() as i64;
        let y0 = (y - (px - 1) as f64 / 2.0).floor() as i64;
        for yy in y0..y0 + px {
            let row = yy.clamp(0, height as i64 - 1) as usize;
            for xx in x0..x0 + px {
                let col = xx.rem_euclid(width as i64) as usize;
                let i = (row * width as usize + col) * 3;
                img[i..i + 3].copy_from_slice(&colour);
            }
        }
    };
    if pts.len() == 1 {
        let (x, y) = to_xy(pts[0].0, pts[0].1);
        stamp(x, y);
    }
    for seg in pts.windows(2) {
        let (lon0, lat0) = seg[0];
        let lon1 = lon0 + wrap180(seg[1].0 - lon0);
        let (x0, y0) = to_xy(lon0, lat0);
        let (x1, y1) = to_xy(lon1, seg[1].1);
        let steps = ((x1 - x0).abs().max((y1 - y0).abs()) * 2.0).ceil().max(1.0) as usize;
        for i in 0..=steps {
            let t = i as f64 / steps as f64;
            stamp(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t);
        }
    }
}

fn wrap180(d: f64) -> f64 {
    (d + 180.0).rem_euclid(360.0) - 180.0
}

/// RGB equirectangular preview (same grid as the other rasters): sea by depth, land by climate
/// with hillshading, rivers drawn by Strahler order.
pub fn preview_png(mesh: &Mesh, graph: &RiverGraph, params: &Params, width: u32, height: u32) -> Vec<u8> {
    let raster = SphereRaster::new(mesh, width, height);
    let normals = surface_normals(mesh, &mesh.triangles());
    let sea = params.sea_level_m;
    let w = width as usize;
    let mut img = vec![0u8; w * height as usize * 3];
    img.par_chunks_mut(w * 3).enumerate().for_each(|(r, row)| {
        let lat = SphereRaster::lat_of(r as u32, height);
        for c in 0..w {
            let i = r * w + c;
            let kind = mesh.face_kind(raster.faces[i]);
            let wts = raster.weights[i];
            let mut alt = 0.0;
            let mut normal = DVec3::ZERO;
            let (mut lake, mut lake_depth) = (0.0, 0.0);
            for (&v, &wt) in mesh.corners(raster.faces[i]).iter().zip(&wts) {
                let (vert, wt) = (&mesh.vertices[v as usize], wt as f64);
                alt += wt * (vert.ground - sea);
                normal += wt * normals[v as usize];
                if vert.flags.contains(VertexFlags::LAKE) {
                    lake += wt;
                    lake_depth += wt * (vert.water - vert.ground);
                }
            }
            let rgb = if kind == FaceKind::Sea {
                water_colour(-alt)
            } else if lake >= 0.5 {
                water_colour(lake_depth / lake)
            } else {
                let lon = SphereRaster::lon_of(c as u32, width);
                let d = raster.direction(c as u32, r as u32);
                let s = shade(d, normal.normalize_or_zero(), lat, lon);
                climate_colour(Palette::of(params), lat, alt, precipitation_mm(mesh, lat, lon))
                    .map(|x| (x as f64 * s).round().clamp(0.0, 255.0) as u8)
            };
            row[c * 3..c * 3 + 3].copy_from_slice(&rgb);
        }
    });
    let mut reaches = graph.reaches(mesh, &Default::default());
    reaches.sort_by_key(|r| (r.strahler, r.id));
    let in_lake = |v: u32| mesh.vertices[v as usize].flags.contains(VertexFlags::LAKE);
    for r in &reaches {
        let (colour, px) = river_style(r.strahler);
        // Runs of the reach outside lakes.
        for run in r.vertices.windows(2).collect::<Vec<_>>().split(|w| in_lake(w[0]) && in_lake(w[1])) {
            let mut pts: Vec<(f64, f64)> = Vec::with_capacity(run.len() + 1);
            for (k, w) in run.iter().enumerate() {
                for &v in if k == 0 { &w[..] } else { &w[1..] } {
                    let (lat, lon) = lat_lon(mesh.pos(v));
                    pts.push((lon, lat));
                }
            }
            if !pts.is_empty() {
                draw_line(&mut img, width, height, &pts, colour, px);
            }
        }
    }
    encode_png(&img, width, height, image::ExtendedColorType::Rgb8)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::test_planet;

    fn rgb_at(img: &image::RgbImage, lat: f64, lon: f64) -> [u8; 3] {
        let x = ((lon + 180.0) / 360.0 * img.width() as f64).floor() as u32;
        let y = ((90.0 - lat) / 180.0 * img.height() as f64).floor() as u32;
        img.get_pixel(x.min(img.width() - 1), y.min(img.height() - 1)).0
    }

    #[test]
    fn preview_shows_sea_land_and_rivers() {
        let planet = test_planet();
        let params = Params::default();
        let (w, h) = (720, 360);
        let png = preview_png(&planet.mesh, &planet.rivers, &params, w, h);
        let img = image::load_from_memory(&png).unwrap();
        assert_eq!(img.color(), image::ColorType::Rgb8);
        let img = img.to_rgb8();
        assert_eq!(img.dimensions(), (w, h));
        let mut land_checked = 0;
        for i in 0..planet.mesh.faces.len() as u32 {
            let kind = planet.mesh.face_kind(i);
            let corners = planet.mesh.corners(i);
            let c: DVec3 = corners.iter().map(|&v| planet.mesh.pos(v)).sum::<DVec3>() / 3.0;
            let (lat, lon) = lat_lon(c);
            let px = rgb_at(&img, lat, lon);
            if kind == FaceKind::Sea && corners.iter().all(|&v| planet.mesh.vertices[v as usize].flags.is_pure_sea()) {
                assert!(px[2] > px[0], "sea is blue at {lat},{lon}: {px:?}");
            }
            if kind == FaceKind::Land && px[2] <= px[1] {
                land_checked += 1;
            }
        }
        assert!(land_checked > 0, "some land is not blue");
        // A river vertex in the middle of a reach is painted with a river colour.
        let reaches = planet.rivers.reaches(&planet.mesh, &Default::default());
        let r = reaches.iter().find(|r| r.vertices.len() >= 3).expect("a reach of 3 vertices");
        let (lat, lon) = lat_lon(planet.mesh.pos(r.vertices[1]));
        let px = rgb_at(&img, lat, lon);
        assert!((1..=12).any(|s| river_style(s).0 == px), "river pixel {px:?}");
    }

    #[test]
    fn preview_is_deterministic() {
        let planet = test_planet();
        let params = Params { climate: crate::params::Climate::Arid, ..Default::default() };
        let a = preview_png(&planet.mesh, &planet.rivers, &params, 200, 100);
        assert_eq!(a, preview_png(&planet.mesh, &planet.rivers, &params, 200, 100));
        let b = preview_png(&planet.mesh, &planet.rivers, &Params::default(), 200, 100);
        assert_ne!(a, b, "the climate changes the colours");
    }

    #[test]
    fn river_lines_wrap_across_the_antimeridian() {
        let (w, h) = (36u32, 18u32);
        let mut img = vec![0u8; (w * h * 3) as usize];
        draw_line(&mut img, w, h, &[(175.0, 0.5), (-175.0, 0.5)], [1, 2, 3], 1);
        let lit: Vec<u32> = (0..w).filter(|&c| img[((8 * w + c) * 3) as usize] == 1).collect();
        assert_eq!(lit, vec![0, 35], "only the short way is drawn");
        assert_eq!(river_style(1).1, 1);
        assert_eq!(river_style(6).1, 3);
        assert!(river_style(6).0[2] < river_style(1).0[2], "higher orders are darker");
    }
}
