//! The adversarial phase of the HTTP load benchmark (`--adversarial`): what a hostile client
//! without a token can send a server with the default settings, all at once, for `--duration`
//! seconds. Planets of the largest `base_faces` (refused: too large) and of the largest that is
//! admitted, each with a new seed; an 8192x8192 land mask of ~100 KB compressed (the most
//! pixels an upload may have), each with a new seed; views that ask for the default face cap
//! (2,000,000 faces) from new cameras; 4096x4096 renders at that cap; the widest rasters and
//! large DEMs. The run fails (exit 1) on any 5xx or if the server's peak resident memory
//! passes `--max-rss-mib` (the bound SECURITY.md states for the default settings).

use super::{gather, get, row, spawn_load, warm, Req, Server};
use std::sync::Arc;
use std::time::Instant;

/// An 8192x8192 8-bit land mask: sea with a few rectangular continents, PNG-compressed.
fn huge_mask() -> Vec<u8> {
    let (w, h) = (8192u32, 8192u32);
    let img = image::GrayImage::from_fn(w, h, |x, y| {
        let land = (x / 1024 + y / 1024) % 3 == 0 && (1000..7000).contains(&y);
        image::Luma([if land { 255 } else { 0 }])
    });
    let mut png = Vec::new();
    img.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png).expect("encode the mask");
    png
}

/// A camera `{n}`-dependent low over the Himalaya, wide and large, that wants every face it
/// may have.
fn deep_camera(extra: &str) -> String {
    format!(
        "eye=300000,5600000,3100000.{{n}}&target=0,5300000,2900000&fov=100&width=3840&height=2160&land_px=1\
         &max_faces=2000000{extra}"
    )
}

pub fn mix() -> Vec<Req> {
    let map = Arc::new(huge_mask());
    println!("adversarial upload: an 8192x8192 land mask of {} KB", map.len() / 1024);
    vec![
        Req {
            post: Some(r#"{"seed": {n}, "params": {"base_faces": 4194304}}"#),
            path: "/v1/planets".into(),
            map: None,
        },
        Req { post: Some(r#"{"seed": {n}, "params": {"base_faces": 440000}}"#), path: "/v1/planets".into(), map: None },
        Req { post: None, path: "/v1/planets".into(), map: Some(map) },
        get(format!("/v1/planets/earth/view.glb?{}", deep_camera(""))),
        get(format!("/v1/planets/earth/view.glb?{}", deep_camera(""))),
        get(format!(
            "/v1/planets/earth/render.png?{}",
            deep_camera("").replace("3840", "4096").replace("2160", "4096")
        )),
        get("/v1/planets/earth/landmask.png?width=80{m}"),
        get("/v1/planets/earth/elevation.tif?width=80{m}"),
        get("/v1/planets/earth/dem.tif?bbox=60,20,100,45&width=4096&height=40{m}"),
        get(format!("/v1/planets/earth/view.glb?{}", deep_camera(""))),
    ]
}

/// Runs the phase; the caller checks 5xx and the peak.
pub async fn run(server: &Server, connections: usize, secs: f64) {
    let client = reqwest::Client::new();
    warm(&client, &server.base, &get("/readyz")).await;
    let mix = mix();
    println!(
        "\n| load | requests | req/s | MiB/s | p50 ms | p99 ms | max ms | 5xx | other non-2xx | peak RSS MiB |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    );
    let start = Instant::now();
    let o = gather(spawn_load(&server.base, connections, secs, &mix), start).await;
    println!("{}", row(&format!("adversarial ({} kinds), {secs:.0} s", mix.len()), &o, server.peak_rss_mib()));
    let mut statuses: Vec<_> = o.statuses.iter().collect();
    statuses.sort();
    println!("\nanswers by status: {statuses:?}");
}
