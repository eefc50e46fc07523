//! `riverworld generate` end to end: real maps, determinism, and bad input (exit code 2).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_riverworld"))
}

fn maps(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("maps").join(name)
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("riverworld-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("binary runs")
}

/// Runs a command that must fail with exit code 2 and name `needle` on stderr.
fn refused(args: &[&str], needle: &str) {
    let o = run(args);
    assert_eq!(o.status.code(), Some(2), "{args:?}");
    assert!(String::from_utf8_lossy(&o.stderr).contains(needle), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
}

fn stats(dir: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(dir.join("stats.json")).unwrap()).unwrap()
}

#[test]
fn continent_bitmap_gives_a_planet_shaped_like_the_map() {
    let out = scratch("bitmap");
    let map = maps("earth_landmask_ne10m_1024x512.png");
    let o = run(&["generate", "--map", map.to_str().unwrap(), "--out", out.to_str().unwrap(), "--raster-width", "512"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = stats(&out);
    let land = s["land_fraction"].as_f64().unwrap();
    assert!((land - 0.288).abs() < 0.02, "land fraction {land}");
    assert_eq!(s["monotone_violations"], 0);
    assert!(s["drained_fraction"].as_f64().unwrap() > 0.999);
    assert!(s["faces"].as_u64().unwrap() > 50_000);
    // The exported land mask agrees with the input map on most pixels.
    let ours = image::load_from_memory(&std::fs::read(out.join("landmask.png")).unwrap()).unwrap().to_luma8();
    let theirs = image::open(&map).unwrap().resize_exact(512, 256, image::imageops::FilterType::Triangle).to_luma8();
    let agree = ours.pixels().zip(theirs.pixels()).filter(|(a, b)| (a.0[0] >= 128) == (b.0[0] >= 128)).count();
    let share = agree as f64 / (512.0 * 256.0);
    assert!(share > 0.97, "landmask agrees on {share:.3} of pixels");
    for f in ["planet.glb", "rivers.geojson", "landmask.png", "elevation.tif", "preview.png", "stats.json"] {
        assert!(std::fs::metadata(out.join(f)).unwrap().len() > 0, "{f}");
    }
}

#[test]
fn same_inputs_give_identical_files() {
    let (a, b) = (scratch("det-a"), scratch("det-b"));
    for dir in [&a, &b] {
        let o = run(&[
            "generate",
            "--seed",
            "7",
            "--faces",
            "3000",
            "--out",
            dir.to_str().unwrap(),
            "--raster-width",
            "256",
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    for f in ["planet.glb", "rivers.geojson", "landmask.png", "elevation.tif", "preview.png"] {
        assert!(std::fs::read(a.join(f)).unwrap() == std::fs::read(b.join(f)).unwrap(), "{f} differs");
    }
    let (mut sa, mut sb) = (stats(&a), stats(&b));
    sa["build_ms"] = 0.into();
    sb["build_ms"] = 0.into();
    assert_eq!(sa, sb);
    let c = scratch("det-c");
    assert!(run(&[
        "generate",
        "--seed",
        "8",
        "--faces",
        "3000",
        "--out",
        c.to_str().unwrap(),
        "--raster-width",
        "256"
    ])
    .status
    .success());
    assert!(std::fs::read(a.join("planet.glb")).unwrap() != std::fs::read(c.join("planet.glb")).unwrap());
}

#[test]
fn elevation_maps_shape_the_relief() {
    // ETOPO5 as GeoTIFF (real metres): sea where the map is below sea level, high land where it is high.
    let out = scratch("etopo");
    let map = maps("earth_etopo5_1024x512.tif");
    let o = run(&["generate", "--map", map.to_str().unwrap(), "--faces", "20000", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = stats(&out);
    assert!((s["land_fraction"].as_f64().unwrap() - 0.29).abs() < 0.03, "{s}");
    assert_eq!(s["monotone_violations"], 0);
    let tif = std::fs::read(out.join("elevation.tif")).unwrap();
    let mut dec = tiff::decoder::Decoder::new(std::io::Cursor::new(tif)).unwrap();
    let (w, h) = dec.dimensions().unwrap();
    let tiff::decoder::DecodingResult::F32(px) = dec.read_image().unwrap() else { panic!("float32 expected") };
    let at = |lat: f64, lon: f64| {
        let col = (((lon + 180.0) / 360.0) * w as f64) as usize;
        let row = (((90.0 - lat) / 180.0) * h as f64) as usize;
        px[row * w as usize + col]
    };
    assert!(at(32.0, 85.0) > 2000.0, "Tibet at {}", at(32.0, 85.0));
    assert!(at(-15.0, -140.0) < -2000.0, "Pacific at {}", at(-15.0, -140.0));
    assert!(at(-80.0, 60.0) > 1000.0, "Antarctica at {}", at(-80.0, 60.0));
    // The same map as a 16-bit PNG with its metre range.
    let png = scratch("etopo-png");
    let o = run(&[
        "generate",
        "--map",
        maps("earth_etopo5_1024x512.png").to_str().unwrap(),
        "--map-range",
        "-9010,6125",
        "--faces",
        "20000",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let land_png = stats(&png)["land_fraction"].as_f64().unwrap();
    assert!((land_png - s["land_fraction"].as_f64().unwrap()).abs() < 0.01);
}

#[test]
fn a_regional_map_becomes_a_refined_island() {
    let out = scratch("region");
    let map = maps("region_jacksboro_tn_403x344.tif");
    let o = run(&["generate", "--map", map.to_str().unwrap(), "--out", out.to_str().unwrap(), "--raster-width", "256"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = stats(&out);
    // The region (~36 x 32 km) is land, the rest of the planet sea.
    let land = s["land_fraction"].as_f64().unwrap();
    assert!(land > 0.0 && land < 1e-4, "land fraction {land}");
    assert!(s["faces"].as_u64().unwrap() > 20_000, "region not refined: {s}");
    assert!(s["river_edges"].as_u64().unwrap() > 100, "{s}");
    assert_eq!(s["monotone_violations"], 0);
}

#[test]
fn bad_input_is_refused_with_exit_code_2() {
    let dir = scratch("bad");
    let html = dir.join("page.png");
    std::fs::write(&html, b"<html><body>not a map</body></html>").unwrap();
    let full = std::fs::read(maps("earth_landmask_ne10m_1024x512.png")).unwrap();
    let truncated = dir.join("truncated.png");
    std::fs::write(&truncated, &full[..full.len() / 2]).unwrap();
    let all_land = dir.join("all_land.png");
    image::GrayImage::from_pixel(64, 32, image::Luma([255])).save(&all_land).unwrap();
    let all_sea = dir.join("all_sea.png");
    image::GrayImage::from_pixel(64, 32, image::Luma([0])).save(&all_sea).unwrap();
    let params = dir.join("params.json");
    std::fs::write(&params, r#"{"seed": 1, "params": {"land_percent": 150}}"#).unwrap();
    let unknown = dir.join("unknown.json");
    std::fs::write(&unknown, r#"{"params": {"radius": 1}}"#).unwrap();
    let s = |p: &Path| p.to_str().unwrap().to_string();
    let etopo16 = maps("earth_etopo5_1024x512.png");
    let cases: Vec<(Vec<String>, &str)> = vec![
        (vec!["--map".into(), s(&dir.join("missing.png"))], "cannot read"),
        (vec!["--map".into(), s(&html)], "not a PNG or TIFF"),
        (vec!["--map".into(), s(&truncated)], "corrupt"),
        (vec!["--map".into(), s(&all_land)], "no sea"),
        (vec!["--map".into(), s(&all_sea)], "no land"),
        (vec!["--map".into(), s(&etopo16), "--map-kind".into(), "continents".into()], "16-bit"),
        (vec!["--map".into(), s(&etopo16), "--map-kind".into(), "elevation".into()], "map_range"),
        (vec!["--params".into(), s(&params)], "land_percent"),
        (vec!["--params".into(), s(&unknown)], "radius"),
        (vec!["--faces".into(), "2".into()], "base_faces"),
        (vec!["--precipitation".into(), s(&html)], "precipitation: map is not a PNG or TIFF"),
        (vec!["--precipitation".into(), s(&all_land)], "precipitation: a precipitation PNG needs a range"),
        (
            vec!["--precipitation".into(), s(&all_land), "--precipitation-range".into(), "-900,-100".into()],
            "precipitation must lie in 0..=30000",
        ),
    ];
    let out = dir.join("out");
    for (args, needle) in cases {
        let mut all = vec!["generate".to_string(), "--out".into(), s(&out)];
        all.extend(args.iter().cloned());
        let o = bin().args(&all).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err:?} lacks {needle:?}");
    }
    // Nothing was written for refused inputs.
    assert!(!out.join("planet.glb").exists());
}

#[test]
fn view_writes_a_deterministic_glb_and_refuses_bad_cameras() {
    let dir = scratch("view");
    let cam = "eye=6500000,0,400000&target=6374000,0,300000&width=320&height=180&land_px=6";
    let run_view = |out: &Path, backend: &str, extra: &[&str]| {
        let mut args = vec![
            "view",
            "--faces",
            "2000",
            "--camera",
            cam,
            "--max-faces",
            "100000",
            "--out",
            out.to_str().unwrap(),
            "--stats",
            "--backend",
            backend,
        ];
        args.extend_from_slice(extra);
        run(&args)
    };
    let (a, b, g) = (dir.join("a.glb"), dir.join("b.glb"), dir.join("g.glb"));
    let o = run_view(&a, "cpu", &[]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("adaption on the CPU (--backend cpu)"));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stats: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(stats["faces"].as_u64().unwrap() > 2000 && stats["faces"].as_u64().unwrap() <= 100_000, "{stats}");
    assert_eq!(stats["converged"], true);
    for key in ["vertices", "splits", "passes"] {
        assert!(stats[key].as_u64().unwrap() > 0, "{key}: {stats}");
    }
    assert_eq!(stats["collapses"], 0, "refined from the base mesh: {stats}");
    assert!(stats["adapt_ms"].as_f64().unwrap() > 0.0, "{stats}");
    let bpv = stats["bytes_per_vertex"].as_f64().unwrap();
    assert!((100.0..200.0).contains(&bpv), "{stats}");
    assert!(run_view(&b, "auto", &[]).status.success());
    let bytes = std::fs::read(&a).unwrap();
    assert_eq!(&bytes[..4], b"glTF");
    assert!(bytes == std::fs::read(&b).unwrap(), "view.glb differs between runs");
    // Cameras are visited in order and the last one is output: the mesh is the same whichever
    // cameras came before it.
    let via = dir.join("via.glb");
    let before = "eye=6600000,300000,600000&target=6374000,150000,300000&width=320&height=180&land_px=3";
    let o = run(&[
        "view",
        "--faces",
        "2000",
        "--camera",
        before,
        "--camera",
        cam,
        "--max-faces",
        "100000",
        "--out",
        via.to_str().unwrap(),
        "--stats",
        "--backend",
        "cpu",
        "--compression",
        "none",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let via_stats: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(via_stats["faces"], stats["faces"]);
    // (A plain file lists the vertices and triangles in the order the mesh holds them.)
    let plain = dir.join("plain.glb");
    let o = run_view(&plain, "cpu", &["--compression", "none"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let plain = std::fs::read(&plain).unwrap();
    assert!(plain.len() > 2 * bytes.len(), "compressed by default: {} of {} bytes", bytes.len(), plain.len());
    assert_eq!(glb_triangles(&plain), glb_triangles(&std::fs::read(&via).unwrap()), "the mesh depends on the path");
    // The wgpu compute backend (lavapipe in CI) writes the same bytes.
    let o = run_view(&g, "gpu", &[]);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && log.contains("adaption on the GPU"), "{log}");
    assert!(bytes == std::fs::read(&g).unwrap(), "view.glb differs between the CPU and GPU backends");
    refused(&["view", "--faces", "200", "--camera", cam, "--backend", "cuda"], "cpu, gpu or auto");
    refused(&["render", "--faces", "200", "--camera", cam, "--backend", "metal"], "cpu, gpu or auto");
    refused(&["serve", "--backend", "opencl"], "cpu, gpu or auto");
    for (bad, needle) in [
        ("eye=0,0,100&target=0,0,0", "inside the planet"),
        ("eye=0,0,1e7&target=0,0,1e7", "equals the eye"),
        ("eye=0,0,1e7&target=0,0,0&width=0", "width"),
        ("eye=nan,0,1e7&target=0,0,0", "eye"),
        ("eye=0,0,1e7&target=0,0,0&fvo=30", "unknown camera parameter \"fvo\""),
        ("eye=0,0,1e7&target=0,0,0&max_faces=10", "use --max-faces"),
    ] {
        refused(&["view", "--faces", "200", "--camera", bad, "--out", dir.join("x.glb").to_str().unwrap()], needle);
    }
    // A budget below the base mesh, the coarsest view there is.
    let x = dir.join("x.glb");
    refused(
        &["view", "--faces", "200", "--camera", cam, "--max-faces", "10", "--out", x.to_str().unwrap()],
        "--max-faces: 10 faces is below the",
    );
    assert!(!x.exists());
    for budget in ["0", "3000000000"] {
        refused(&["view", "--faces", "200", "--camera", cam, "--max-faces", budget], "--max-faces");
    }
    // An output path that names no file.
    let up = format!("{}/..", dir.join("sub").display());
    refused(&["view", "--faces", "200", "--camera", cam, "--out", &up], "names no file");
    refused(&["render", "--faces", "200", "--camera", cam, "--out", &up], "names no file");
    assert!(!dir.join("view.glb").exists() && !dir.join("render.png").exists());
}

#[test]
fn render_writes_identical_images_in_the_asked_format_and_refuses_bad_input() {
    let dir = scratch("render");
    let cam = "eye=2e7,0,5e6&target=0,0,0&width=200&height=150&fov=40";
    let render = |out: &Path, extra: &[&str]| {
        let mut args = vec!["render", "--faces", "2000", "--camera", cam, "--max-faces", "50000"];
        args.extend_from_slice(extra);
        args.extend_from_slice(&["--out", out.to_str().unwrap()]);
        run(&args)
    };
    let (a, b, c) = (dir.join("a.png"), dir.join("b.png"), dir.join("c.jpg"));
    for (out, extra) in [(&a, &[][..]), (&b, &[][..]), (&c, &[][..])] {
        let o = render(out, extra);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let png = std::fs::read(&a).unwrap();
    assert!(png == std::fs::read(&b).unwrap(), "render differs between runs");
    let img = image::load_from_memory(&png).unwrap();
    assert_eq!((img.width(), img.height()), (200, 150));
    assert_eq!(&std::fs::read(&c).unwrap()[..2], &[0xFF, 0xD8], "a .jpg name gives JPEG");
    for (bad, needle) in [
        ("eye=2e7,0,0&target=0,0,0&width=9000", "width"),
        ("eye=2e7,0,0&target=0,0,0&sun=0,0,0", "sun"),
        ("eye=2e7,0,0&target=0,0,0&zoom=3", "zoom"),
    ] {
        refused(&["render", "--faces", "200", "--camera", bad, "--out", dir.join("x.png").to_str().unwrap()], needle);
    }
    let x = dir.join("x.png").to_str().unwrap().to_string();
    refused(&["render", "--faces", "200", "--camera", cam, "--max-faces", "10", "--out", &x], "base mesh");
    assert!(!dir.join("x.png").exists());
}

/// Every mesh's triangles (or line segments) in a glb, each as its corners' position bits
/// starting from the least, sorted: what the file shows whatever order it lists vertices and
/// triangles in.
fn glb_triangles(glb: &[u8]) -> Vec<Vec<[[u32; 3]; 3]>> {
    let word = |at: usize| u32::from_le_bytes(glb[at..at + 4].try_into().unwrap()) as usize;
    let json_len = word(12);
    let json: serde_json::Value = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    let bin = &glb[20 + json_len + 8..];
    let words = |accessor: &serde_json::Value| -> Vec<u32> {
        let a = &json["accessors"][accessor.as_u64().unwrap() as usize];
        let view = &json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
        let start = (view["byteOffset"].as_u64().unwrap_or(0) + a["byteOffset"].as_u64().unwrap_or(0)) as usize;
        let per = match a["type"].as_str().unwrap() {
            "SCALAR" => 1,
            "VEC3" => 3,
            t => panic!("{t}"),
        };
        let n = a["count"].as_u64().unwrap() as usize * per;
        match a["componentType"].as_u64().unwrap() {
            5123 => (0..n).map(|i| u16::from_le_bytes([bin[start + 2 * i], bin[start + 2 * i + 1]]) as u32).collect(),
            5125 | 5126 => {
                (0..n).map(|i| u32::from_le_bytes(bin[start + 4 * i..start + 4 * i + 4].try_into().unwrap())).collect()
            }
            t => panic!("component type {t}"),
        }
    };
    let meshes = json["meshes"].as_array().unwrap();
    meshes
        .iter()
        .map(|m| {
            let p = &m["primitives"][0];
            let pos = words(&p["attributes"]["POSITION"]);
            let corner = |i: u32| -> [u32; 3] { pos[3 * i as usize..3 * i as usize + 3].try_into().unwrap() };
            // A LINES primitive (the rivers): each segment as its ends, least first, the last
            // repeated.
            let per = if p["mode"].as_u64() == Some(1) { 2 } else { 3 };
            let mut tris: Vec<[[u32; 3]; 3]> = words(&p["indices"])
                .chunks(per)
                .map(|t| {
                    if per == 2 {
                        let (a, b) = (corner(t[0]).min(corner(t[1])), corner(t[0]).max(corner(t[1])));
                        return [a, b, b];
                    }
                    let c = [corner(t[0]), corner(t[1]), corner(t[2])];
                    let first = (0..3).min_by_key(|&k| c[k]).unwrap();
                    [c[first], c[(first + 1) % 3], c[(first + 2) % 3]]
                })
                .collect();
            tris.sort_unstable();
            tris
        })
        .collect()
}

#[test]
fn dem_writes_a_region_and_refuses_bad_grids() {
    let out = scratch("dem");
    std::fs::create_dir_all(&out).unwrap();
    let file = out.join("alps.tif");
    let map = maps("earth_etopo5_1024x512.tif");
    let args = |bbox: &str, width: &str| {
        vec![
            "dem".to_string(),
            "--map".into(),
            map.to_str().unwrap().into(),
            "--faces".into(),
            "20000".into(),
            format!("--bbox={bbox}"),
            "--width".into(),
            width.into(),
            "--out".into(),
            file.to_str().unwrap().into(),
        ]
    };
    let o = run(&args("5,44,11,47", "300").iter().map(String::as_str).collect::<Vec<_>>());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stats: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!((stats["width"].as_u64(), stats["height"].as_u64()), (Some(300), Some(150)));
    assert!(std::fs::read(&file).unwrap().starts_with(b"II*\0"));
    for (bbox, width, what) in
        [("5,44,11", "300", "bbox"), ("5,44,11,47", "9000", "width"), ("11,44,5,47", "30", "bbox")]
    {
        let o = run(&args(bbox, width).iter().map(String::as_str).collect::<Vec<_>>());
        assert_eq!(o.status.code(), Some(2), "{bbox} {width}");
        assert!(String::from_utf8_lossy(&o.stderr).contains(what), "{}", String::from_utf8_lossy(&o.stderr));
    }
}

/// One exit-code rule for every command: 2 for input it refuses, 1 for a failure while running
/// (here: an output path under a regular file), the reason on stderr either way.
#[test]
fn write_failures_exit_1_and_bad_input_2() {
    let dir = scratch("exit-codes");
    let blocker = dir.join("file");
    std::fs::write(&blocker, b"not a directory").unwrap();
    let under = |name: &str| blocker.join(name).to_str().unwrap().to_string();
    let cam = "eye=6500000,0,400000&target=6374000,0,300000&width=64&height=48";
    for args in [
        vec!["generate", "--faces", "200", "--out", &under("planet")],
        vec!["view", "--faces", "200", "--camera", cam, "--backend", "cpu", "--out", &under("v.glb")],
        vec!["tiles", "--faces", "200", "--levels", "1", "--out", &under("tiles")],
        vec!["dem", "--faces", "200", "--bbox=5,44,11,47", "--width", "20", "--out", &under("d.tif")],
    ] {
        let o = run(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {err}");
        assert!(err.contains("error:") && err.contains("file"), "{args:?}: {err}");
    }
    // The same commands with bad input: 2, and nothing written.
    refused(&["tiles", "--faces", "2", "--out", dir.join("t").to_str().unwrap()], "base_faces");
    refused(&["dem", "--faces", "200", "--bbox=5,44,11", "--width", "20", "--out", &under("d.tif")], "bbox");
    assert!(!dir.join("t").exists());
    let help = String::from_utf8(run(&["--help"]).stdout).unwrap();
    assert!(help.contains("Exit status: 0 done; 2 input refused"), "{help}");
}

/// A precipitation map replaces the climate model's rain: its rivers carry what it gives.
#[test]
fn a_precipitation_map_sets_the_rivers_discharge() {
    let dir = scratch("precipitation");
    let rain = dir.join("rain.png");
    image::GrayImage::from_pixel(36, 18, image::Luma([255])).save(&rain).unwrap();
    let total = |extra: &[&str], name: &str| -> f64 {
        let out = dir.join(name);
        let mut args = vec!["generate", "--faces", "2000", "--seed", "3", "--raster-width", "64", "--out"];
        args.push(out.to_str().unwrap());
        args.extend_from_slice(extra);
        let o = run(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let json: serde_json::Value =
            serde_json::from_slice(&std::fs::read(out.join("rivers.geojson")).unwrap()).unwrap();
        json["features"].as_array().unwrap().iter().filter_map(|f| f["properties"]["discharge_m3s"].as_f64()).sum()
    };
    let model = total(&[], "model");
    let wet = total(&["--precipitation", rain.to_str().unwrap(), "--precipitation-range", "0,5000"], "wet");
    assert!(model > 0.0 && wet > 2.0 * model, "model {model} m³/s, 5,000 mm everywhere {wet}");
}
