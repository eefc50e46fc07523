//! HTTP load benchmark of `riverworld serve` on loopback.
//!
//! Starts the release server as a child process (built-in planet `earth`, a scratch data
//! directory, a free port), then measures:
//!
//! - cold view latency: the first request for each of a few new cameras, one at a time;
//! - cached `view.glb` for a fixed camera, `--connections` concurrent connections;
//! - cached `rivers.geojson`, the same way;
//! - a mix for `--duration` seconds: planet records and the list, views, rivers, rasters, cached
//!   3D tiles, renders (one cached camera, one camera that moves with every request, so it is
//!   drawn each time or refused with 429 when the render permits are taken) and a few
//!   (idempotent) planet POSTs;
//! - 3D Tiles (`http_load/tiles.rs`): cold tile latency and size per level, cached tiles.
//!
//! For each: requests/s, p50/p99/max latency, 5xx and other non-2xx answers, and the server's
//! peak resident memory (VmHWM from /proc/PID/status) after the phase. The run fails (exit 1)
//! if any answer was a 5xx or the peak exceeds `--max-rss-mib` (default 2816: the bound that
//! SECURITY.md states for the default settings).
//!
//! ```sh
//! cargo bench --bench http_load                                 # 64 connections, 20 s + 20 s + 60 s
//! cargo bench --bench http_load -- --connections 16 --phase 5 --duration 10
//! cargo bench --bench http_load -- --tiles-only                 # only the 3D Tiles phases
//! cargo bench --bench http_load -- --replicas --duration 30      # three replicas behind HAProxy
//! cargo bench --bench http_load -- --adversarial --connections 12
//! ```
//!
//! `--adversarial` runs only the phase of `http_load/adversarial.rs`: one hostile client's
//! worst requests at once, against the same bound.
//!
//! `--replicas` runs only the phases of `http_load/replicas.rs`: three replicas on one store
//! behind HAProxy (installed: `apt-get install haproxy`), one killed and restarted mid-run.

#[path = "http_load/adversarial.rs"]
mod adversarial;
#[path = "http_load/replicas.rs"]
mod replicas;
#[path = "http_load/tiles.rs"]
mod tiles;

use std::io::BufRead;
use std::process::{Child, Command, Stdio};
use std::sync::Arc;
use std::time::{Duration, Instant};

const RENDER: &str = "eye=2e7,1e7,5e6&target=0,0,0&width=640&height=360";
const VIEW: &str = "eye=7e6,0,3e6&target=0,0,0&width=1280&height=720&max_faces=400000";

struct Args {
    connections: usize,
    phase: f64,
    duration: f64,
    tiles_only: bool,
    replicas: bool,
    adversarial: bool,
    max_rss_mib: f64,
    /// More options for the server, e.g. to compare its limits.
    serve_args: Vec<String>,
}

fn args() -> Args {
    let mut a = Args {
        connections: 64,
        phase: 20.0,
        duration: 60.0,
        tiles_only: false,
        replicas: false,
        adversarial: false,
        max_rss_mib: 2816.0,
        serve_args: Vec::new(),
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        if arg == "--serve-arg" {
            a.serve_args.push(it.next().unwrap_or_else(|| usage(&arg)));
            continue;
        }
        let mut value = || it.next().and_then(|v| v.parse::<f64>().ok()).unwrap_or_else(|| usage(&arg));
        match arg.as_str() {
            "--connections" => a.connections = value() as usize,
            "--phase" => a.phase = value(),
            "--duration" => a.duration = value(),
            "--tiles-only" => a.tiles_only = true,
            "--replicas" => a.replicas = true,
            "--adversarial" => a.adversarial = true,
            "--max-rss-mib" => a.max_rss_mib = value(),
            "--bench" => {}
            _ => usage(&arg),
        }
    }
    a
}

fn usage(arg: &str) -> ! {
    eprintln!("http_load: bad argument {arg:?}; options: --connections N --phase SECS --duration SECS --tiles-only --replicas --adversarial --max-rss-mib MIB --serve-arg ARG");
    std::process::exit(2)
}

/// The server child process; killed when dropped.
struct Server {
    child: Child,
    base: String,
    _data: TempDir,
}

struct TempDir(std::path::PathBuf);

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Server {
    fn start(extra: &[String]) -> Server {
        let data = TempDir(std::env::temp_dir().join(format!("riverworld-http-load-{}", std::process::id())));
        let _ = std::fs::remove_dir_all(&data.0);
        let mut child =
            serve("127.0.0.1:0", &data.0).args(extra).stderr(Stdio::piped()).spawn().expect("start riverworld serve");
        let stderr = child.stderr.take().expect("stderr");
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            for line in std::io::BufReader::new(stderr).lines().map_while(Result::ok) {
                if let Some(addr) = line.strip_prefix("riverworld: serving on ") {
                    let _ = tx.send(addr.trim().to_string());
                }
            }
        });
        let base = rx.recv_timeout(Duration::from_secs(60)).expect("the server listens");
        Server { child, base, _data: data }
    }

    /// Peak resident set size so far, MiB.
    fn peak_rss_mib(&self) -> f64 {
        peak_rss_mib(self.child.id())
    }
}

/// `riverworld serve` on `addr` over the data directory `data`: logs at `warn`, no API token,
/// stdout dropped (the caller decides what becomes of stderr).
fn serve(addr: &str, data: &std::path::Path) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_riverworld"));
    cmd.args(["serve", "--addr", addr, "--data"])
        .arg(data)
        .env("RUST_LOG", "warn")
        .env_remove("RIVERWORLD_API_TOKEN")
        .stdout(Stdio::null());
    cmd
}

/// Peak resident set size so far of process `pid`, MiB (NaN if it is gone).
fn peak_rss_mib(pid: u32) -> f64 {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
    let kb = status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<f64>().ok())
        .unwrap_or(f64::NAN);
    kb / 1024.0
}

/// One request of a load: method, path and body (POST bodies are JSON). A `{n}` in the path is
/// replaced by a number that differs between requests (a new camera each time), `{m}` by its
/// last two digits.
#[derive(Clone)]
struct Req {
    post: Option<&'static str>,
    path: String,
    /// A map to POST as multipart with a `{n}` seed.
    map: Option<Arc<Vec<u8>>>,
}

fn get(path: impl Into<String>) -> Req {
    Req { post: None, path: path.into(), map: None }
}

/// Requests sent so far, for `{n}` in paths.
static SENT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

async fn send(client: &reqwest::Client, base: &str, req: &Req) -> (u16, usize) {
    let n = SENT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let url = format!("{base}{}", req.path.replace("{n}", &n.to_string()).replace("{m}", &format!("{:02}", n % 100)));
    let builder = match (req.post, &req.map) {
        (_, Some(map)) => {
            let part = reqwest::multipart::Part::bytes(map.to_vec()).file_name("map.png");
            client.post(url).multipart(reqwest::multipart::Form::new().part("map", part).text("seed", n.to_string()))
        }
        (Some(body), None) => {
            client.post(url).header("content-type", "application/json").body(body.replace("{n}", &n.to_string()))
        }
        (None, None) => client.get(url),
    };
    match builder.send().await {
        Ok(res) => {
            let status = res.status().as_u16();
            if req.path.contains("/render.") {
                let counter = if status == 200 { &RENDERS[0] } else { &RENDERS[1] };
                counter.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            }
            let len = res.bytes().await.map(|b| b.len()).unwrap_or(0);
            (status, len)
        }
        // A transport error counts as a server error.
        Err(_) => (599, 0),
    }
}

#[derive(Default)]
struct Outcome {
    latencies_us: Vec<u64>,
    server_errors: usize,
    refused: usize,
    bytes: usize,
    elapsed: f64,
    /// Answers by status code.
    statuses: std::collections::HashMap<u16, usize>,
}

/// `connections` clients, each with one keep-alive connection, send the requests of `mix` in
/// turn (each starting at its own offset) until `secs` have passed.
async fn load(base: &str, connections: usize, secs: f64, mix: &[Req]) -> Outcome {
    let start = Instant::now();
    gather(spawn_load(base, connections, secs, mix), start).await
}

/// The clients of [`load`], started; [`gather`] collects their outcomes.
fn spawn_load(base: &str, connections: usize, secs: f64, mix: &[Req]) -> Vec<tokio::task::JoinHandle<Outcome>> {
    let mix = Arc::new(mix.to_vec());
    let deadline = Instant::now() + Duration::from_secs_f64(secs);
    (0..connections)
        .map(|c| {
            let (mix, base) = (Arc::clone(&mix), base.to_string());
            tokio::spawn(async move {
                let client = reqwest::Client::builder()
                    .pool_max_idle_per_host(1)
                    .timeout(Duration::from_secs(300))
                    .build()
                    .expect("client");
                let mut out = Outcome::default();
                let mut i = c * 7;
                while Instant::now() < deadline {
                    let req = &mix[i % mix.len()];
                    i += 1;
                    let t = Instant::now();
                    let (status, len) = send(&client, &base, req).await;
                    out.latencies_us.push(t.elapsed().as_micros() as u64);
                    out.bytes += len;
                    *out.statuses.entry(status).or_insert(0) += 1;
                    if status >= 500 {
                        out.server_errors += 1;
                    } else if !(200..300).contains(&status) {
                        out.refused += 1;
                    }
                }
                out
            })
        })
        .collect()
}

/// Waits for the connections' outcomes and adds them up, latencies sorted.
async fn gather(tasks: Vec<tokio::task::JoinHandle<Outcome>>, start: Instant) -> Outcome {
    let mut all = Outcome::default();
    for t in tasks {
        let o = t.await.expect("load task");
        all.latencies_us.extend(o.latencies_us);
        all.server_errors += o.server_errors;
        SERVER_ERRORS.fetch_add(o.server_errors, std::sync::atomic::Ordering::Relaxed);
        all.refused += o.refused;
        all.bytes += o.bytes;
        for (status, n) in o.statuses {
            *all.statuses.entry(status).or_insert(0) += n;
        }
    }
    all.elapsed = start.elapsed().as_secs_f64();
    all.latencies_us.sort_unstable();
    all
}

fn percentile_ms(sorted_us: &[u64], p: f64) -> f64 {
    if sorted_us.is_empty() {
        return f64::NAN;
    }
    let i = ((sorted_us.len() as f64 - 1.0) * p).round() as usize;
    sorted_us[i] as f64 / 1000.0
}

fn row(name: &str, o: &Outcome, rss: f64) -> String {
    let n = o.latencies_us.len();
    format!(
        "| {name} | {n} | {:.0} | {:.1} | {:.1} | {:.1} | {:.1} | {} | {} | {rss:.0} |",
        n as f64 / o.elapsed,
        o.bytes as f64 / o.elapsed / (1 << 20) as f64,
        percentile_ms(&o.latencies_us, 0.5),
        percentile_ms(&o.latencies_us, 0.99),
        percentile_ms(&o.latencies_us, 1.0),
        o.server_errors,
        o.refused,
    )
}

/// Fetches `path` until it answers 200 (the built-in planet may still be building).
async fn warm(client: &reqwest::Client, base: &str, req: &Req) -> usize {
    let start = Instant::now();
    loop {
        let (status, len) = send(client, base, req).await;
        if (200..300).contains(&status) {
            return len;
        }
        assert!(start.elapsed() < Duration::from_secs(300), "{} answers {status}", req.path);
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
}

fn main() {
    let args = args();
    let runtime = tokio::runtime::Runtime::new().expect("runtime");
    if args.replicas {
        let errors = runtime.block_on(replicas::run(&mixed(), args.connections, args.duration));
        println!("\n{errors} answers 5xx with every replica up");
        if errors > 0 {
            eprintln!("http_load: FAILED");
            std::process::exit(1);
        }
        return;
    }
    let server = Server::start(&args.serve_args);
    let base = server.base.clone();
    runtime.block_on(async {
        let client = reqwest::Client::new();
        let t = Instant::now();
        warm(&client, &base, &get("/readyz")).await;
        println!("server ready (built-in planet earth built) after {:.1} s", t.elapsed().as_secs_f64());
        if args.tiles_only {
            tiles::run(&server, args.connections, args.phase).await;
            return;
        }
        if args.adversarial {
            adversarial::run(&server, args.connections, args.duration).await;
            return;
        }

        // Cold views: the first request for a camera never asked for before.
        let mut cold = Vec::new();
        for lon in [0.0f64, 60.0, 120.0, 180.0, 240.0, 300.0] {
            let (s, c) = lon.to_radians().sin_cos();
            let path = format!(
                "/v1/planets/earth/view.glb?eye={:.0},{:.0},3e6&target=0,0,0&width=1280&height=720&max_faces=400000",
                7e6 * c,
                7e6 * s
            );
            let t = Instant::now();
            let len = warm(&client, &base, &get(path)).await;
            cold.push((t.elapsed().as_secs_f64() * 1000.0, len));
        }
        let mut ms: Vec<f64> = cold.iter().map(|c| c.0).collect();
        ms.sort_by(f64::total_cmp);
        println!(
            "cold view.glb (1280x720, max_faces 400000), {} cameras one at a time: min {:.0} ms, median {:.0} ms, \
             max {:.0} ms; {:.1} MB each on average",
            ms.len(),
            ms[0],
            ms[ms.len() / 2],
            ms[ms.len() - 1],
            cold.iter().map(|c| c.1 as f64).sum::<f64>() / cold.len() as f64 / 1e6
        );
        println!("peak RSS after cold views: {:.0} MiB\n", server.peak_rss_mib());

        let view = get(format!("/v1/planets/earth/view.glb?{VIEW}"));
        let rivers = get("/v1/planets/earth/rivers.geojson");
        let mix = mixed();
        for req in mix.iter().filter(|r| r.post.is_none() && !r.path.contains("{n}")) {
            warm(&client, &base, req).await;
        }

        let header =
            "| load | requests | req/s | MiB/s | p50 ms | p99 ms | max ms | 5xx | other non-2xx | peak RSS MiB |\n\
                      |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|";
        println!("{} connections\n\n{header}", args.connections);
        let o = load(&base, args.connections, args.phase, std::slice::from_ref(&view)).await;
        println!("{}", row(&format!("cached view.glb, {:.0} s", args.phase), &o, server.peak_rss_mib()));
        let o = load(&base, args.connections, args.phase, std::slice::from_ref(&rivers)).await;
        println!("{}", row(&format!("cached rivers.geojson, {:.0} s", args.phase), &o, server.peak_rss_mib()));
        let before = RENDERS.each_ref().map(|c| c.load(std::sync::atomic::Ordering::Relaxed));
        let o = load(&base, args.connections, args.duration, &mix).await;
        println!("{}", row(&format!("mixed ({} kinds), {:.0} s", mix.len(), args.duration), &o, server.peak_rss_mib()));
        let [drawn, refused] = RENDERS.each_ref().map(|c| c.load(std::sync::atomic::Ordering::Relaxed));
        println!(
            "\nrenders in the mix: {} answered 200 (cached or drawn), {} refused (429, permits taken)",
            drawn - before[0],
            refused - before[1]
        );
        tiles::run(&server, args.connections, args.phase).await;
    });
    let peak = server.peak_rss_mib();
    let errors = SERVER_ERRORS.load(std::sync::atomic::Ordering::Relaxed);
    println!("\npeak RSS {peak:.0} MiB (bound {:.0} MiB), {errors} answers 5xx", args.max_rss_mib);
    if errors > 0 || peak.is_nan() || peak > args.max_rss_mib {
        eprintln!("http_load: FAILED");
        std::process::exit(1);
    }
}

/// The mixed load: planet records and the list, views, rivers, rasters, cached 3D tiles, renders
/// (one cached camera, one that moves with every request) and a few planet POSTs (the first of
/// each builds a planet, the repeats answer the existing one).
fn mixed() -> Vec<Req> {
    let view = get(format!("/v1/planets/earth/view.glb?{VIEW}"));
    let rivers = get("/v1/planets/earth/rivers.geojson");
    let mut mix = vec![
        get("/v1/planets/earth"),
        get("/v1/planets"),
        view.clone(),
        rivers.clone(),
        get("/v1/planets/earth/landmask.png?width=1024"),
        get("/v1/planets/earth/preview.png?width=1024"),
        get("/v1/planets/earth/elevation.tif?width=512"),
        get("/v1/planets/earth"),
        get("/v1/planets/earth/view.glb?eye=-5e6,5e6,2e6&target=0,0,0&width=1280&height=720&max_faces=400000"),
        get("/v1/planets/earth/landmask.png?width=256"),
        get("/healthz"),
        rivers.clone(),
        get("/v1/planets/earth/tiles/0.glb"),
        get("/v1/planets/earth/tiles/5.glb"),
        get("/v1/planets/earth/tiles/312.glb"),
        get("/v1/planets/earth/tiles/6013.glb"),
        get("/v1/planets/earth/tileset.json"),
        get(format!("/v1/planets/earth/render.png?{RENDER}")),
    ];
    mix.push(get(format!("/v1/planets/earth/render.jpg?{RENDER}&sun=1,{{n}},0")));
    mix.extend(mix.clone());
    let posts: [&'static str; 3] = [
        r#"{"seed": 1, "params": {"base_faces": 2000}}"#,
        r#"{"seed": 2, "params": {"base_faces": 2000}}"#,
        r#"{"seed": 3, "params": {"base_faces": 2000, "continents": 3}}"#,
    ];
    for (i, body) in posts.into_iter().enumerate() {
        mix.insert(1 + 8 * i, Req { post: Some(body), path: "/v1/planets".into(), map: None });
    }
    mix
}

/// Render requests answered 200, and otherwise (429 when the render permits are taken).
static RENDERS: [std::sync::atomic::AtomicUsize; 2] =
    [std::sync::atomic::AtomicUsize::new(0), std::sync::atomic::AtomicUsize::new(0)];

/// 5xx answers over every phase.
static SERVER_ERRORS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
