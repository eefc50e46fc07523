//! The 3D Tiles phases of the HTTP load benchmark, on the built-in planet `earth`: cold tile
//! latency and bytes per level (tiles nobody asked for before, one at a time), then cached
//! tiles — a few hundred tiles of levels 0 to 6, as a viewer would fetch them — with
//! `connections` concurrent connections: as fast as they go, then paced at 5,000 requests/s
//! (latency counted from when each request was due, so a stalled server is not hidden). Then
//! the GIS tiles the same way: Cesium terrain, MapLibre elevation PNGs and river vector tiles,
//! cold latency per kind and zoom, then cached.

use super::{gather, get, load, row, send, warm, Outcome, Req, Server};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// The head of a table of load phases.
const HEADER: &str =
    "| load | requests | req/s | MiB/s | p50 ms | p99 ms | max ms | 5xx | other non-2xx | peak RSS MiB |\n\
                      |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|";

/// Offered rate of the paced phase, requests per second.
const PACED_RATE: f64 = 5000.0;

/// Levels whose cold latency is measured.
const COLD_LEVELS: [u8; 11] = [0, 1, 2, 4, 6, 8, 10, 12, 14, 16, 20];
/// Cold tiles measured per level.
const COLD_SAMPLES: usize = 4;

/// A tile key: `root`, then `level` quadrant digits drawn from `salt`.
fn key(root: u8, level: u8, salt: usize) -> String {
    let mut k = root.to_string();
    for i in 0..level as usize {
        k.push(char::from(b'0' + ((salt * 7 + i * 3 + i * i) % 4) as u8));
    }
    k
}

fn tile(k: &str) -> Req {
    get(format!("/v1/planets/earth/tiles/{k}.glb"))
}

pub async fn run(server: &Server, connections: usize, secs: f64) {
    let base = &server.base;
    let client = reqwest::Client::new();
    // Build the tiling with a tile outside every sample.
    let t = Instant::now();
    warm(&client, base, &tile(&key(7, 3, 99))).await;
    println!("\nfirst tile (prepares the planet's tiling): {:.0} ms\n", t.elapsed().as_secs_f64() * 1000.0);

    println!("| level | cold ms (median of {COLD_SAMPLES}) | cold ms (max) | KiB per tile |\n|---:|---:|---:|---:|");
    for level in COLD_LEVELS {
        let mut ms = Vec::new();
        let mut bytes = 0;
        for s in 0..COLD_SAMPLES {
            let t = Instant::now();
            let (status, len) = send(&client, base, &tile(&key(s as u8 * 2, level, s))).await;
            assert_eq!(status, 200, "level {level}");
            ms.push(t.elapsed().as_secs_f64() * 1000.0);
            bytes += len;
        }
        ms.sort_by(f64::total_cmp);
        let kib = bytes as f64 / COLD_SAMPLES as f64 / 1024.0;
        println!("| {level} | {:.1} | {:.1} | {kib:.0} |", ms[COLD_SAMPLES / 2], ms[COLD_SAMPLES - 1]);
    }

    // What a viewer streams: the entry tileset, then tiles down a few levels.
    let mut mix = vec![get("/v1/planets/earth/tileset.json")];
    for level in 0..=6u8 {
        let count = if level < 2 { 8 * 4usize.pow(u32::from(level)) } else { 48 };
        mix.extend((0..count).map(|i| tile(&key((i % 8) as u8, level, i))));
    }
    cached(server, connections, secs, "tiles", &mix).await;
    gis(server, connections, secs).await;
}

/// The GIS tile routes of `earth` at zoom `z`, tile `i` of a sample: (kind, request).
fn gis_tile(kind: &str, z: u32, i: usize) -> Req {
    // A spread of tiles over the land-rich middle latitudes, different per sample.
    let n = 1usize << z;
    let x = (i * 7919 + n / 3) % n;
    let y = (n / 4 + (i * 104_729) % (n / 2).max(1)) % n;
    match kind {
        // Geographic TMS: 2^(z+1) x 2^z, rows from the south.
        "terrain" => get(format!("/v1/planets/earth/terrain/{z}/{}/{}.terrain?v=1", (2 * x + 1) % (2 * n), y)),
        "dem" => get(format!("/v1/planets/earth/dem/{z}/{x}/{y}.png")),
        _ => get(format!("/v1/planets/earth/rivers/{z}/{x}/{y}.mvt")),
    }
}

/// Cold latency of each GIS tile kind at a few zooms (new tiles, one at a time), then the
/// cached mix of all of them with `connections` connections, unpaced and paced.
async fn gis(server: &Server, connections: usize, secs: f64) {
    let base = &server.base;
    let client = reqwest::Client::new();
    // The first of each kind makes what the kind shares (the face index, the river lines).
    for kind in ["terrain", "dem", "mvt"] {
        warm(&client, base, &gis_tile(kind, 1, 99)).await;
    }
    println!(
        "
| GIS tile | zoom | cold ms (median of {COLD_SAMPLES}) | cold ms (max) | KiB per tile |
|---|---:|---:|---:|---:|"
    );
    for kind in ["terrain", "dem", "mvt"] {
        for z in [3u32, 6, 9, 12] {
            let mut ms = Vec::new();
            let mut bytes = 0;
            for s in 0..COLD_SAMPLES {
                let t = Instant::now();
                let (status, len) = send(&client, base, &gis_tile(kind, z, 1000 + s)).await;
                assert_eq!(status, 200, "{kind} zoom {z}");
                ms.push(t.elapsed().as_secs_f64() * 1000.0);
                bytes += len;
            }
            ms.sort_by(f64::total_cmp);
            let kib = bytes as f64 / COLD_SAMPLES as f64 / 1024.0;
            println!("| {kind} | {z} | {:.1} | {:.1} | {kib:.1} |", ms[COLD_SAMPLES / 2], ms[COLD_SAMPLES - 1]);
        }
    }
    // What a map streams: tiles of each kind over zooms 2-8.
    let mut mix = vec![
        get("/v1/planets/earth/terrain/layer.json"),
        get("/v1/planets/earth/dem/tilejson.json"),
        get("/v1/planets/earth/rivers/tilejson.json"),
    ];
    for z in 2..=8u32 {
        for i in 0..8 {
            mix.extend(["terrain", "dem", "mvt"].map(|kind| gis_tile(kind, z, i)));
        }
    }
    cached(server, connections, secs, "GIS tiles", &mix).await;
}

/// Warms every request of `mix`, then loads it with `connections` connections for `secs`,
/// as fast as they go and paced at [`PACED_RATE`], a table row each.
async fn cached(server: &Server, connections: usize, secs: f64, what: &str, mix: &[Req]) {
    let (base, client) = (&server.base, reqwest::Client::new());
    for req in mix {
        warm(&client, base, req).await;
    }
    println!("\n{connections} connections\n\n{HEADER}");
    let o = load(base, connections, secs, mix).await;
    println!("{}", row(&format!("cached {what} ({} files), {secs:.0} s", mix.len()), &o, server.peak_rss_mib()));
    let o = paced(base, connections, PACED_RATE, secs, mix).await;
    let name = format!("cached {what} paced at {PACED_RATE:.0}/s, {secs:.0} s");
    println!("{}", row(&name, &o, server.peak_rss_mib()));
}

/// Like `load`, but each connection sends on a fixed schedule, together `rate` requests/s;
/// latency runs from each request's due time.
async fn paced(base: &str, connections: usize, rate: f64, secs: f64, mix: &[Req]) -> Outcome {
    let mix = Arc::new(mix.to_vec());
    let start = Instant::now();
    let every = Duration::from_secs_f64(connections as f64 / rate);
    let tasks: Vec<_> = (0..connections)
        .map(|c| {
            let (mix, base) = (Arc::clone(&mix), base.to_string());
            tokio::spawn(async move {
                let client = reqwest::Client::builder().pool_max_idle_per_host(1).build().expect("client");
                let mut out = Outcome::default();
                let mut due = start + every.mul_f64(c as f64 / connections as f64);
                let mut i = c * 7;
                while due < start + Duration::from_secs_f64(secs) {
                    tokio::time::sleep_until(due.into()).await;
                    let (status, len) = send(&client, &base, &mix[i % mix.len()]).await;
                    out.latencies_us.push(due.elapsed().as_micros() as u64);
                    out.bytes += len;
                    out.server_errors += usize::from(status >= 500);
                    out.refused += usize::from(!(200..300).contains(&status) && status < 500);
                    i += 1;
                    due += every;
                }
                out
            })
        })
        .collect();
    gather(tasks, start).await
}
