//! Replicas behind a real load balancer (`--replicas`): three release servers on one store (a
//! shared data directory) behind HAProxy (round robin, health checks on `/readyz`, as
//! `deploy/haproxy.cfg` but on loopback ports), measured with the mixed load:
//!
//! 1. throughput through HAProxy with one replica, then with three;
//! 2. the same load while one replica is killed with SIGKILL a third of the way in and started
//!    again at two thirds: 5xx and transport errors counted (HAProxy retries a request whose
//!    connection failed on another replica; what was in flight on the killed one is lost);
//! 3. every GET of the mix fetched from each replica directly: the same bytes from all three
//!    (the list of planets aside: it shows each planet's build state on the answering replica).

use super::{gather, load, peak_rss_mib, row, send, warm, Req, TempDir};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A free loopback port (bound, then released for the child to take).
fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0").expect("bind").local_addr().expect("addr").port()
}

/// One replica: `riverworld serve` on a fixed port over the shared data directory.
struct Replica {
    port: u16,
    child: Option<Child>,
}

impl Replica {
    fn start(port: u16, data: &std::path::Path) -> Replica {
        let child = super::serve(&format!("127.0.0.1:{port}"), data)
            .stderr(Stdio::null())
            .spawn()
            .expect("start riverworld serve");
        Replica { port, child: Some(child) }
    }
    fn base(&self) -> String {
        format!("http://127.0.0.1:{}", self.port)
    }
    /// Peak resident set size of this run of the replica, MiB.
    fn peak_rss_mib(&self) -> f64 {
        self.child.as_ref().map_or(f64::NAN, |c| peak_rss_mib(c.id()))
    }
    fn kill(&mut self) {
        if let Some(mut c) = self.child.take() {
            let _ = c.kill(); // SIGKILL
            let _ = c.wait();
        }
    }
}

impl Drop for Replica {
    fn drop(&mut self) {
        self.kill();
    }
}

/// HAProxy in the foreground with a configuration for `replicas` on `port`; killed when dropped.
struct Balancer {
    child: Child,
    _cfg: TempDir,
}

impl Balancer {
    fn start(port: u16, replicas: &[&Replica]) -> Balancer {
        let dir = TempDir(std::env::temp_dir().join(format!("riverworld-haproxy-{}-{port}", std::process::id())));
        std::fs::create_dir_all(&dir.0).expect("haproxy dir");
        let servers: String = replicas
            .iter()
            .enumerate()
            .map(|(i, r)| format!("    server replica{} 127.0.0.1:{} check\n", i + 1, r.port))
            .collect();
        let cfg = format!(
            "global\n    maxconn 4096\n\
             defaults\n    mode http\n    timeout connect 2s\n    timeout client 300s\n    timeout server 300s\n\
             \x20   retries 3\n    option redispatch 1\n    retry-on conn-failure empty-response response-timeout\n\
             \x20   default-server inter 500ms fall 2 rise 2\n\
             frontend http\n    bind 127.0.0.1:{port}\n    default_backend riverworld\n\
             backend riverworld\n    balance roundrobin\n    option httpchk GET /readyz\n\
             \x20   http-check expect status 200\n{servers}"
        );
        let path = dir.0.join("haproxy.cfg");
        std::fs::write(&path, cfg).expect("write haproxy.cfg");
        let child = Command::new("haproxy")
            .args(["-db", "-f"])
            .arg(&path)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("start haproxy (apt-get install haproxy)");
        Balancer { child, _cfg: dir }
    }
}

impl Drop for Balancer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Waits until every replica is healthy as HAProxy sees it: `/readyz` answers 200 through the
/// balancer as many times in a row as there are replicas (round robin visits each).
async fn balanced(client: &reqwest::Client, base: &str, replicas: usize) {
    let start = Instant::now();
    let mut ok = 0;
    while ok < 3 * replicas {
        let (status, _) = send(client, base, &super::get("/readyz")).await;
        ok = if status == 200 { ok + 1 } else { 0 };
        assert!(start.elapsed() < Duration::from_secs(300), "the balancer never found its replicas healthy");
        tokio::time::sleep(Duration::from_millis(100)).await;
    }
    // Past the health checks' rise (2 x 500 ms), so no replica is still on its way in.
    tokio::time::sleep(Duration::from_millis(1500)).await;
}

/// Runs the replicas phases with `mix` (the main phase's mix, warmed on any server) for `secs`
/// per phase over `connections`; returns the 5xx count outside the kill phase.
pub async fn run(mix: &[Req], connections: usize, secs: f64) -> usize {
    let data = TempDir(std::env::temp_dir().join(format!("riverworld-replicas-{}", std::process::id())));
    let _ = std::fs::remove_dir_all(&data.0);
    let mut replicas: Vec<Replica> = (0..3).map(|_| Replica::start(free_port(), &data.0)).collect();
    let client = reqwest::Client::new();
    for r in &replicas {
        warm(&client, &r.base(), &super::get("/readyz")).await;
        for req in mix.iter().filter(|r| r.post.is_none() && !r.path.contains("{n}")) {
            warm(&client, &r.base(), req).await;
        }
    }
    let header = "| load through HAProxy | requests | req/s | MiB/s | p50 ms | p99 ms | max ms | 5xx | other non-2xx | peak RSS MiB, sum |\n\
                  |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|";
    println!(
        "\nreplicas on one store behind HAProxy (round robin, /readyz checks), {connections} connections\n\n{header}"
    );
    let mut errors = 0;
    for n in [1usize, 3] {
        let port = free_port();
        let lb = Balancer::start(port, &replicas.iter().take(n).collect::<Vec<_>>());
        let base = format!("http://127.0.0.1:{port}");
        balanced(&client, &base, n).await;
        let o = load(&base, connections, secs, mix).await;
        errors += o.server_errors;
        let rss: f64 = replicas.iter().take(n).map(Replica::peak_rss_mib).sum();
        println!("{}", row(&format!("mixed, {n} replica{}, {secs:.0} s", if n > 1 { "s" } else { "" }), &o, rss));
        drop(lb);
    }

    // One replica killed a third of the way in and started again at two thirds.
    let port = free_port();
    let _lb = Balancer::start(port, &replicas.iter().collect::<Vec<_>>());
    let base = format!("http://127.0.0.1:{port}");
    balanced(&client, &base, 3).await;
    let start = Instant::now();
    let tasks = super::spawn_load(&base, connections, secs, mix);
    tokio::time::sleep(Duration::from_secs_f64(secs / 3.0)).await;
    let killed_at = start.elapsed().as_secs_f64();
    replicas[1].kill();
    tokio::time::sleep(Duration::from_secs_f64(secs / 3.0)).await;
    let restarted_at = start.elapsed().as_secs_f64();
    let port1 = replicas[1].port;
    replicas[1] = Replica::start(port1, &data.0);
    let o = gather(tasks, start).await;
    let rss: f64 = replicas.iter().map(Replica::peak_rss_mib).sum();
    println!("{}", row(&format!("mixed, 3 replicas, one killed, {secs:.0} s"), &o, rss));
    println!(
        "\nreplica 2 killed (SIGKILL) at {killed_at:.1} s and started again at {restarted_at:.1} s: {} answers 5xx \
         or lost connections in that run (requests in flight on the killed replica)",
        o.server_errors
    );

    // Every GET of the mix, from each replica directly: the same bytes. (Not the list: it shows
    // each planet's build state on the answering replica, and the planets POSTed during the
    // load were built by whichever replica took the POST; `earth` is built on all of them.)
    warm(&client, &replicas[1].base(), &super::get("/readyz")).await;
    let mut compared = 0;
    let same =
        |r: &&Req| r.post.is_none() && !r.path.contains("{n}") && !r.path.ends_with('z') && r.path != "/v1/planets";
    for req in mix.iter().filter(same) {
        let mut bodies = Vec::new();
        for r in &replicas {
            let url = format!("{}{}", r.base(), req.path);
            let body = loop {
                let res = client.get(&url).send().await.expect("replica answers");
                if res.status() == 200 {
                    break res.bytes().await.expect("body");
                }
                tokio::time::sleep(Duration::from_millis(100)).await;
            };
            bodies.push(body);
        }
        for (i, b) in bodies.iter().enumerate().skip(1) {
            if *b != bodies[0] {
                let at = b.iter().zip(bodies[0].iter()).position(|(x, y)| x != y).unwrap_or(0);
                let show =
                    |x: &[u8]| String::from_utf8_lossy(&x[at.saturating_sub(120)..(at + 80).min(x.len())]).into_owned();
                panic!(
                    "replicas 1 and {} differ on {} at byte {at}: {:?} / {:?}",
                    i + 1,
                    req.path,
                    show(&bodies[0]),
                    show(b)
                );
            }
        }
        compared += 1;
    }
    println!("{compared} resources fetched from each of the 3 replicas: byte-identical");
    errors
}
