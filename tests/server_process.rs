//! The `riverworld serve` process: killed with SIGKILL in the middle of a build or an upload it
//! leaves a store in which every planet is complete or absent, and two processes sharing one
//! store serve each other's planets with identical bytes.

mod server_common;

use serde_json::Value;
use server_common::*;
use std::path::Path;
use std::time::{Duration, Instant};

const VIEW: &str = "eye=7e6,0,3e6&target=0,0,0&width=320&height=180&land_px=8&max_faces=400000";

async fn post_json(p: &Process, body: &str) -> (u16, Value) {
    let res = p
        .client
        .post(p.url("/v1/planets"))
        .header("content-type", "application/json")
        .body(body.to_string())
        .send()
        .await
        .unwrap();
    (res.status().as_u16(), res.json().await.unwrap())
}

/// Every folder under `planets/` is either a complete planet (a parsable `request.json`, and a
/// `map.bin` of the recorded size when it has a map) or has no `request.json`; returns the ids
/// of the complete ones.
fn complete_planets(data: &Path) -> Vec<String> {
    let mut ids = Vec::new();
    let Ok(dirs) = std::fs::read_dir(data.join("planets")) else { return ids };
    for dir in dirs {
        let dir = dir.unwrap().path();
        let Ok(text) = std::fs::read(dir.join("request.json")) else { continue };
        let input: Value = serde_json::from_slice(&text).expect("a request.json is never half-written");
        if let Some(bytes) = input["map"]["bytes"].as_u64() {
            let len = std::fs::metadata(dir.join("map.bin")).expect("a planet's map is stored before it").len();
            assert_eq!(len, bytes, "{}", dir.display());
        }
        ids.push(dir.file_name().unwrap().to_str().unwrap().to_string());
    }
    ids.sort();
    ids
}

async fn listed(p: &Process) -> Vec<String> {
    let list: Value = p.get("/v1/planets").await.json().await.unwrap();
    list["planets"].as_array().unwrap().iter().map(|r| r["id"].as_str().unwrap().to_string()).collect()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_killed_server_leaves_whole_planets_that_rebuild_on_demand() {
    let data = scratch("crash");
    let p = spawn_server(&data, &[], &[]);
    // A finished planet, then one killed mid-build.
    let (status, small) = post_json(&p, r#"{"seed": 1, "params": {"base_faces": 500}}"#).await;
    assert_eq!(status, 202);
    let small = small["id"].as_str().unwrap().to_string();
    p.wait_ready(&small).await;
    let (status, big) = post_json(&p, r#"{"seed": 2, "params": {"base_faces": 150000}}"#).await;
    assert_eq!(status, 202);
    let big = big["id"].as_str().unwrap().to_string();
    let start = Instant::now();
    loop {
        let rec: Value = p.get(&format!("/v1/planets/{big}")).await.json().await.unwrap();
        match rec["status"].as_str().unwrap() {
            "building" => break,
            "queued" => {}
            other => panic!("the build should still be running: {other}"),
        }
        assert!(start.elapsed() < Duration::from_secs(60));
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    p.kill9();
    assert_eq!(complete_planets(&data), {
        let mut ids = vec![small.clone(), big.clone()];
        ids.sort();
        ids
    });

    // Killed in the middle of a large upload: the server had not stored anything of it.
    let p = spawn_server(&data, &[], &[]);
    let (tx, rx) = tokio::sync::mpsc::channel::<Result<Vec<u8>, std::io::Error>>(4);
    let boundary = "riverworld-crash-boundary";
    let head = format!(
        "--{boundary}\r\ncontent-disposition: form-data; name=\"map\"; filename=\"big.png\"\r\n\
         content-type: image/png\r\n\r\n"
    );
    let body = reqwest::Body::wrap_stream(tokio_stream(rx));
    let upload = tokio::spawn(
        p.client
            .post(p.url("/v1/planets"))
            .header("content-type", format!("multipart/form-data; boundary={boundary}"))
            .header("content-length", (head.len() + (32 << 20)).to_string())
            .body(body)
            .send(),
    );
    tx.send(Ok(head.into_bytes())).await.unwrap();
    let mut png = small_map();
    png.resize(1 << 20, 0x5a);
    for _ in 0..4 {
        tx.send(Ok(png.clone())).await.unwrap();
    }
    // The client is megabytes into a 32 MiB body (the channel holds only a few chunks): the
    // server is reading the upload and cannot have all of it.
    p.kill9();
    drop(tx);
    assert!(upload.await.unwrap().is_err(), "the upload cannot have completed");
    let mut expected = vec![small.clone(), big.clone()];
    expected.sort();
    assert_eq!(complete_planets(&data), expected);

    // A crash between the map and request.json leaves a folder without request.json (and an
    // unfinished staging file): that planet does not exist.
    let orphan = "00000000deadbeef";
    std::fs::create_dir_all(data.join("planets").join(orphan)).unwrap();
    std::fs::write(data.join(format!("planets/{orphan}/map.bin")), small_map()).unwrap();
    std::fs::write(data.join(format!("planets/{orphan}/request.json#1")), b"{\"seed\": 1, \"par").unwrap();

    let p = spawn_server(&data, &[], &[]);
    assert_eq!(listed(&p).await, expected);
    expect_error(p.get(&format!("/v1/planets/{orphan}")).await, 404, "not_found").await;
    let rec: Value = p.get(&format!("/v1/planets/{big}")).await.json().await.unwrap();
    assert!(matches!(rec["status"].as_str(), Some("queued" | "building")), "{rec}");
    // Reading the planets starts their builds again; both become ready and serve files.
    for id in [&small, &big] {
        p.wait_ready(id).await;
        let glb = get_built(&p.client, &p.url(&format!("/v1/planets/{id}/view.glb?{VIEW}"))).await;
        assert_eq!(&glb[..4], b"glTF");
    }
}

/// A stream of the chunks sent into `rx`.
fn tokio_stream(
    mut rx: tokio::sync::mpsc::Receiver<Result<Vec<u8>, std::io::Error>>,
) -> impl futures::Stream<Item = Result<Vec<u8>, std::io::Error>> {
    futures::stream::poll_fn(move |cx| rx.poll_recv(cx))
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn two_servers_on_one_store_serve_each_others_planets_identically() {
    let data = scratch("replicas");
    let a = spawn_server(&data, &[], &[]);
    let b = spawn_server(&data, &[], &[]);
    let (status, rec) = post_json(&a, r#"{"seed": 77, "params": {"base_faces": 2000, "continents": 2}}"#).await;
    assert_eq!(status, 202);
    let id = rec["id"].as_str().unwrap().to_string();
    let upload = a
        .client
        .post(a.url("/v1/planets"))
        .multipart(
            reqwest::multipart::Form::new()
                .part("map", reqwest::multipart::Part::bytes(small_map()).file_name("map.png"))
                .text("params", r#"{"base_faces": 1000}"#),
        )
        .send()
        .await
        .unwrap();
    assert_eq!(upload.status().as_u16(), 202);
    let mapped = upload.json::<Value>().await.unwrap()["id"].as_str().unwrap().to_string();

    // B never saw the POSTs: it finds the planets in the store.
    let mut both = vec![id.clone(), mapped.clone()];
    both.sort();
    assert_eq!(listed(&b).await, both);
    for planet in [&id, &mapped] {
        let url = format!("/v1/planets/{planet}/view.glb?{VIEW}");
        let from_b = get_built(&b.client, &b.url(&url)).await;
        let from_a = get_built(&a.client, &a.url(&url)).await;
        assert_eq!(&from_a[..4], b"glTF");
        assert!(from_a == from_b, "{planet}: the replicas' views differ");
        let rivers = format!("/v1/planets/{planet}/rivers.geojson");
        assert!(get_built(&a.client, &a.url(&rivers)).await == get_built(&b.client, &b.url(&rivers)).await);
    }
    // Posting the same inputs to B creates nothing new.
    let (status, again) = post_json(&b, r#"{"seed": 77, "params": {"base_faces": 2000, "continents": 2}}"#).await;
    assert_eq!((status, again["id"].as_str()), (200, Some(id.as_str())));
    // A planet deleted through A is gone from B too.
    let res = a.client.delete(a.url(&format!("/v1/planets/{mapped}"))).send().await.unwrap();
    assert_eq!(res.status().as_u16(), 204);
    expect_error(b.get(&format!("/v1/planets/{mapped}")).await, 404, "not_found").await;
    assert_eq!(listed(&b).await, vec![id.clone()]);
    // A planet B has never heard of, even by listing, is found by its id alone.
    let (status, rec) = post_json(&a, r#"{"seed": 78, "params": {"base_faces": 500}}"#).await;
    assert_eq!(status, 202);
    let late = rec["id"].as_str().unwrap().to_string();
    let url = format!("/v1/planets/{late}/rivers.geojson");
    assert!(get_built(&b.client, &b.url(&url)).await == get_built(&a.client, &a.url(&url)).await);
}

#[tokio::test]
async fn each_request_logs_one_bounded_line_at_info() {
    let data = scratch("logs");
    let p = spawn_server(&data, &[], &[]);
    let marker = "x".repeat(1000);
    let res = p.get(&format!("/v1/planets/needle-{marker}")).await;
    assert_eq!(res.status().as_u16(), 404);
    // The line is written when the answer is: poll briefly.
    let mut lines = Vec::new();
    for _ in 0..50 {
        lines = p.log().lines().filter(|l| l.contains("needle-")).map(str::to_string).collect();
        if !lines.is_empty() {
            break;
        }
        tokio::time::sleep(std::time::Duration::from_millis(100)).await;
    }
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(lines[0].len() < 600 && lines[0].contains("404") && lines[0].contains("INFO"), "{}", lines[0]);
}
