//! Shared by the server tests: a real server on 127.0.0.1 port 0 with a scratch data directory,
//! a real HTTP client, and a small Earth continent map.

#![allow(dead_code)]

use riverworld::server::{serve, Config, Server};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

/// A camera above the Atlantic off West Africa, small enough for quick views.
pub const CAMERA: &str = "eye=7e6,0,3e6&target=0,0,0&width=320&height=180&land_px=8&max_faces=50000";
/// Parameters that keep builds fast.
pub const FAST: &str = r#"{"base_faces": 2000}"#;

pub struct TestServer {
    pub base: String,
    pub dir: PathBuf,
    pub client: reqwest::Client,
    server: Option<Server>,
}

/// A fresh scratch directory.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("riverworld-server-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The test configuration: no built-in planet, inputs under `dir`.
pub fn config(dir: &Path) -> Config {
    // Tests are one client that posts many planets: no per-client share unless a test sets one.
    Config { data_dir: dir.to_path_buf(), default_planet: false, max_builds_per_client: 0, ..Config::default() }
}

pub async fn start(config: Config) -> TestServer {
    let dir = config.data_dir.clone();
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let server = serve(config, listener).await.expect("server starts");
    let base = format!("http://{}", server.local_addr());
    let client = reqwest::Client::builder().timeout(Duration::from_secs(60)).build().unwrap();
    TestServer { base, dir, client, server: Some(server) }
}

impl TestServer {
    pub fn url(&self, path: &str) -> String {
        format!("{}{}", self.base, path)
    }

    pub async fn get(&self, path: &str) -> reqwest::Response {
        self.client.get(self.url(path)).send().await.unwrap()
    }

    /// POSTs a map upload with the given parts besides the map.
    pub async fn post_map(&self, map: Vec<u8>, parts: &[(&str, &str)]) -> reqwest::Response {
        let mut form =
            reqwest::multipart::Form::new().part("map", reqwest::multipart::Part::bytes(map).file_name("map.png"));
        for (k, v) in parts {
            form = form.text(k.to_string(), v.to_string());
        }
        self.client.post(self.url("/v1/planets")).multipart(form).send().await.unwrap()
    }

    /// POSTs a JSON planet request and returns the id of the planet it names.
    pub async fn posted_id(&self, body: &str) -> String {
        let rec = self.post_json(body).await.json::<serde_json::Value>().await.unwrap();
        rec["id"].as_str().unwrap_or_else(|| panic!("no id in {rec}")).to_string()
    }

    pub async fn post_json(&self, body: &str) -> reqwest::Response {
        self.client
            .post(self.url("/v1/planets"))
            .header("content-type", "application/json")
            .body(body.to_string())
            .send()
            .await
            .unwrap()
    }

    /// Polls a planet's record until it is ready (panics on failure or after 60 s).
    pub async fn wait_ready(&self, id: &str) -> Value {
        wait_ready(&self.client, &self.url(&format!("/v1/planets/{id}"))).await
    }

    pub async fn stop(mut self) {
        if let Some(s) = self.server.take() {
            s.shutdown().await.unwrap();
        }
    }
}

/// The shipped 1024x512 Earth continent bitmap, downscaled to 256x128 and encoded as PNG.
pub fn small_map() -> Vec<u8> {
    static MAP: OnceLock<Vec<u8>> = OnceLock::new();
    MAP.get_or_init(|| {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("maps/earth_landmask_ne10m_1024x512.png");
        let img = image::open(path).unwrap().resize_exact(256, 128, image::imageops::FilterType::Triangle).to_luma8();
        let mut out = std::io::Cursor::new(Vec::new());
        img.write_to(&mut out, image::ImageFormat::Png).unwrap();
        out.into_inner()
    })
    .clone()
}

/// Checks the JSON error shape and headers; returns the error object.
pub async fn expect_error(res: reqwest::Response, status: u16, code: &str) -> Value {
    assert_eq!(res.status().as_u16(), status, "{:?}", res.url().path());
    let h = res.headers().clone();
    assert_eq!(h["content-type"], "application/json");
    assert_eq!(h["cache-control"], "no-store");
    let body: Value = res.json().await.unwrap();
    let err = body["error"].clone();
    assert_eq!(err["code"], code, "{body}");
    assert!(err["message"].as_str().is_some_and(|m| !m.is_empty()), "{body}");
    let keys: Vec<&String> = err.as_object().unwrap().keys().collect();
    assert!(keys.iter().all(|k| ["code", "message", "field"].contains(&k.as_str())), "{body}");
    assert_eq!(body.as_object().unwrap().len(), 1, "{body}");
    err
}

/// A `riverworld serve` child process on a free loopback port; killed (SIGKILL) when dropped.
pub struct Process {
    pub base: String,
    pub client: reqwest::Client,
    child: std::process::Child,
    log: std::sync::Arc<std::sync::Mutex<String>>,
}

/// Starts `riverworld serve --addr 127.0.0.1:0 --data DATA --no-default-planet ARGS...` with
/// extra environment variables and waits until it listens.
pub fn spawn_server(data: &Path, args: &[&str], env: &[(&str, &str)]) -> Process {
    use std::io::BufRead;
    let mut cmd = std::process::Command::new(env!("CARGO_BIN_EXE_riverworld"));
    cmd.args(["serve", "--addr", "127.0.0.1:0", "--no-default-planet", "--data"]).arg(data).args(args);
    cmd.env_remove("RIVERWORLD_API_TOKEN").env("RUST_LOG", "info");
    for (k, v) in env {
        cmd.env(k, v);
    }
    cmd.stdout(std::process::Stdio::null()).stderr(std::process::Stdio::piped());
    let mut child = cmd.spawn().expect("riverworld serve starts");
    let stderr = child.stderr.take().unwrap();
    let log = std::sync::Arc::new(std::sync::Mutex::new(String::new()));
    let (tx, rx) = std::sync::mpsc::channel();
    let sink = std::sync::Arc::clone(&log);
    std::thread::spawn(move || {
        for line in std::io::BufReader::new(stderr).lines() {
            let Ok(line) = line else { break };
            if let Some(addr) = line.strip_prefix("riverworld: serving on ") {
                let _ = tx.send(addr.trim().to_string());
            }
            let mut log = sink.lock().unwrap();
            log.push_str(&line);
            log.push('\n');
        }
    });
    let base = match rx.recv_timeout(Duration::from_secs(60)) {
        Ok(base) => base,
        Err(_) => {
            let _ = child.kill();
            panic!("the server did not start: {}", log.lock().unwrap());
        }
    };
    let client = reqwest::Client::builder().timeout(Duration::from_secs(60)).build().unwrap();
    Process { base, client, child, log }
}

impl Process {
    pub fn url(&self, path: &str) -> String {
        format!("{}{}", self.base, path)
    }

    pub async fn get(&self, path: &str) -> reqwest::Response {
        self.client.get(self.url(path)).send().await.unwrap()
    }

    pub fn pid(&self) -> u32 {
        self.child.id()
    }

    /// Everything the server wrote to stderr so far.
    pub fn log(&self) -> String {
        self.log.lock().unwrap().clone()
    }

    /// SIGKILL: no shutdown code runs.
    pub fn kill9(mut self) {
        self.child.kill().unwrap();
        self.child.wait().unwrap();
    }

    /// Polls a planet's record until it is ready (panics on failure or after 60 s).
    pub async fn wait_ready(&self, id: &str) -> Value {
        wait_ready(&self.client, &self.url(&format!("/v1/planets/{id}"))).await
    }
}

impl Drop for Process {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Polls the record at `url` until it is ready (panics on failure or after 60 s).
pub async fn wait_ready(client: &reqwest::Client, url: &str) -> Value {
    let start = Instant::now();
    loop {
        let rec: Value = client.get(url).send().await.unwrap().json().await.unwrap();
        match rec["status"].as_str().unwrap() {
            "ready" => return rec,
            "failed" => panic!("build failed: {rec}"),
            _ => {}
        }
        assert!(start.elapsed() < Duration::from_secs(60), "not ready after 60 s: {rec}");
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
}

/// Fetches `path` until it answers 200, waiting out 409 `not_ready` while the planet (re)builds.
pub async fn get_built(client: &reqwest::Client, url: &str) -> axum::body::Bytes {
    let start = Instant::now();
    loop {
        let res = client.get(url).send().await.unwrap();
        match res.status().as_u16() {
            200 => return res.bytes().await.unwrap(),
            409 => {
                let body: Value = res.json().await.unwrap();
                assert_eq!(body["error"]["code"], "not_ready", "{url}: {body}");
            }
            s => panic!("{url}: status {s}: {}", res.text().await.unwrap()),
        }
        assert!(start.elapsed() < Duration::from_secs(60), "{url} not built after 60 s");
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
}
