//! The service's limits and its behaviour at them: request timeouts, the render permits and
//! their wait queue, the cache budget, configured caps, and build progress.

mod server_common;

use riverworld::server::Config;
use serde_json::Value;
use server_common::*;
use std::time::Duration;

async fn ready_planet(s: &TestServer, body: &str) -> String {
    let res = s.post_json(body).await;
    assert_eq!(res.status().as_u16(), 202);
    let id = res.json::<Value>().await.unwrap()["id"].as_str().unwrap().to_string();
    s.wait_ready(&id).await;
    id
}

async fn gauge(s: &TestServer, name: &str) -> f64 {
    let text = s.get("/metrics").await.text().await.unwrap();
    let line = text.lines().find(|l| l.starts_with(&format!("{name} "))).unwrap_or_else(|| panic!("{name}: {text}"));
    line.rsplit(' ').next().unwrap().parse().unwrap()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_request_over_the_time_limit_answers_503_and_the_server_keeps_serving() {
    let cfg = Config {
        request_timeout: Duration::from_millis(1500),
        render_delay: Duration::from_secs(3600),
        ..config(&scratch("timeout"))
    };
    let s = start(cfg).await;
    let id = ready_planet(&s, r#"{"seed": 3, "params": {"base_faces": 200}}"#).await;
    let res = s.get(&format!("/v1/planets/{id}/view.glb?{CAMERA}")).await;
    let err = expect_error(res, 503, "timeout").await;
    assert!(err["message"].as_str().unwrap().contains("longer"), "{err}");
    // The abandoned render gave its permit back and the server answers everything else.
    assert_eq!(gauge(&s, "riverworld_renders_running").await, 0.0);
    assert_eq!(s.get("/healthz").await.status().as_u16(), 200);
    assert_eq!(s.get(&format!("/v1/planets/{id}")).await.status().as_u16(), 200);
    let again = s.get(&format!("/v1/planets/{id}/rivers.geojson")).await;
    expect_error(again, 503, "timeout").await;
    let metrics = s.get("/metrics").await.text().await.unwrap();
    assert!(metrics.contains(r#"route="/v1/planets/{id}/view.glb",method="GET",status="503"} 1"#), "{metrics}");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn renders_beyond_the_permits_and_queue_answer_429_busy() {
    let cfg = Config {
        render_permits: 1,
        render_queue: 1,
        render_delay: Duration::from_millis(1500),
        ..config(&scratch("busy"))
    };
    let s = start(cfg).await;
    let id = ready_planet(&s, r#"{"seed": 4, "params": {"base_faces": 200}}"#).await;
    let url = |w: u32| s.url(&format!("/v1/planets/{id}/landmask.png?width={w}"));
    let first = tokio::spawn(s.client.get(url(64)).send());
    while gauge(&s, "riverworld_renders_running").await < 1.0 {
        tokio::time::sleep(Duration::from_millis(10)).await;
    }
    let second = tokio::spawn(s.client.get(url(66)).send());
    while gauge(&s, "riverworld_renders_waiting").await < 1.0 {
        tokio::time::sleep(Duration::from_millis(10)).await;
    }
    let res = s.get(&format!("/v1/planets/{id}/landmask.png?width=68")).await;
    assert_eq!(res.headers()["retry-after"], "1");
    expect_error(res, 429, "busy").await;
    // The same answer as a running render joins it instead of queueing.
    let joined = s.get(&format!("/v1/planets/{id}/landmask.png?width=64")).await;
    assert_eq!(joined.status().as_u16(), 200);
    assert_eq!(first.await.unwrap().unwrap().status().as_u16(), 200);
    assert_eq!(second.await.unwrap().unwrap().status().as_u16(), 200);
    assert_eq!(
        (gauge(&s, "riverworld_renders_running").await, gauge(&s, "riverworld_renders_waiting").await),
        (0.0, 0.0)
    );
    // Free permits again: the refused answer renders now.
    assert_eq!(s.get(&format!("/v1/planets/{id}/landmask.png?width=68")).await.status().as_u16(), 200);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_tiny_cache_evicts_but_every_answer_stays_byte_identical() {
    let paths = |id: &str| {
        vec![
            format!("/v1/planets/{id}/view.glb?{CAMERA}"),
            format!("/v1/planets/{id}/rivers.geojson"),
            format!("/v1/planets/{id}/preview.png?width=96"),
            format!("/v1/planets/{id}/elevation.tif?width=64"),
            format!("/v1/planets/{id}/view.glb?eye=0,-9e6,1e6&target=0,0,0&width=200&height=100&max_faces=20000"),
        ]
    };
    let body = r#"{"seed": 12, "params": {"base_faces": 1000}}"#;
    let reference = start(config(&scratch("cache-ref"))).await;
    let id = ready_planet(&reference, body).await;
    let mut expected = Vec::new();
    for p in paths(&id) {
        expected.push(get_built(&reference.client, &reference.url(&p)).await);
    }
    reference.stop().await;

    let budget = 64 * 1024;
    let largest = expected.iter().map(|b| b.len()).max().unwrap() + 200;
    let s = start(Config { cache_bytes: budget, ..config(&scratch("cache-tiny")) }).await;
    assert_eq!(ready_planet(&s, body).await, id);
    for round in 0..2 {
        for (p, want) in paths(&id).iter().zip(&expected) {
            let got = get_built(&s.client, &s.url(p)).await;
            assert!(got == want, "round {round}: {p} differs from the reference");
            // Only the newest entry may exceed the budget, so the cache holds at most it.
            assert!(gauge(&s, "riverworld_cache_bytes").await <= (budget + largest) as f64);
        }
    }
    // The planet itself was evicted by the answers and rebuilt.
    let metrics = s.get("/metrics").await.text().await.unwrap();
    let rebuilt = gauge(&s, "riverworld_builds_finished_total").await;
    assert!(rebuilt >= 2.0, "{metrics}");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn progress_rises_from_zero_to_one_during_a_build() {
    let cfg = Config { build_delay: Duration::from_millis(300), ..config(&scratch("progress")) };
    let s = start(cfg).await;
    let res = s.post_json(r#"{"seed": 9, "params": {"base_faces": 300000}}"#).await;
    assert_eq!(res.status().as_u16(), 202);
    let rec: Value = res.json().await.unwrap();
    let id = rec["id"].as_str().unwrap().to_string();
    let mut samples = vec![(rec["status"].as_str().unwrap().to_string(), rec["progress"].as_f64().unwrap())];
    let started = std::time::Instant::now();
    while samples.last().unwrap().0 != "ready" {
        let rec: Value = s.get(&format!("/v1/planets/{id}")).await.json().await.unwrap();
        assert_ne!(rec["status"], "failed", "{rec}");
        samples.push((rec["status"].as_str().unwrap().to_string(), rec["progress"].as_f64().unwrap()));
        assert!(started.elapsed() < Duration::from_secs(120), "not ready: {rec}");
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    let rank = |status: &str| ["queued", "building", "ready"].iter().position(|s| *s == status).unwrap();
    assert_eq!(samples[0].0, "queued");
    assert!(samples.iter().any(|(st, _)| st == "building"), "{samples:?}");
    for w in samples.windows(2) {
        assert!(rank(&w[0].0) <= rank(&w[1].0), "status went back: {samples:?}");
        assert!(w[0].1 <= w[1].1, "progress went back: {samples:?}");
    }
    for (status, p) in &samples {
        assert!((0.0..=1.0).contains(p), "{samples:?}");
        assert_eq!(*p == 1.0, status == "ready", "{samples:?}");
        if status == "queued" {
            assert_eq!(*p, 0.0);
        }
    }
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn configured_caps_bound_faces_raster_width_and_map_pixels() {
    let cfg =
        Config { max_faces_cap: 1000, max_raster_width: 128, max_map_pixels: 100 * 50, ..config(&scratch("caps")) };
    let s = start(cfg).await;
    let id = ready_planet(&s, r#"{"seed": 5, "params": {"base_faces": 200}}"#).await;
    let view = format!("/v1/planets/{id}/view.glb?eye=0,0,2e7&target=0,0,0");
    let err = expect_error(s.get(&format!("{view}&max_faces=1001")).await, 422, "invalid_parameter").await;
    assert_eq!(err["field"], "max_faces");
    assert!(err["message"].as_str().unwrap().contains("1..=1000"), "{err}");
    assert_eq!(s.get(&format!("{view}&max_faces=1000")).await.status().as_u16(), 200);
    // Nor below the base mesh, the coarsest view there is: that is refused once the planet is
    // built, and nothing is cached for it.
    for _ in 0..2 {
        let err = expect_error(s.get(&format!("{view}&max_faces=10")).await, 422, "invalid_parameter").await;
        assert_eq!(err["field"], "max_faces");
        assert!(err["message"].as_str().unwrap().contains("10 faces is below the"), "{err}");
        assert!(err["message"].as_str().unwrap().contains("base mesh"), "{err}");
    }
    // Without max_faces the view is capped, not refused.
    assert_eq!(s.get(&view).await.status().as_u16(), 200);
    for file in ["landmask.png", "preview.png", "elevation.tif"] {
        let err = expect_error(s.get(&format!("/v1/planets/{id}/{file}?width=130")).await, 422, "invalid_parameter");
        assert_eq!(err.await["field"], "width");
        assert_eq!(s.get(&format!("/v1/planets/{id}/{file}?width=128")).await.status().as_u16(), 200);
    }
    // Without width the raster is as wide as the cap allows.
    let png = s.get(&format!("/v1/planets/{id}/landmask.png")).await.bytes().await.unwrap();
    let img = image::load_from_memory(&png).unwrap();
    assert_eq!((img.width(), img.height()), (128, 64));
    let err = expect_error(s.post_map(small_map(), &[]).await, 422, "image_too_large").await;
    assert_eq!(err["field"], "map");
    assert!(err["message"].as_str().unwrap().contains("256x128"), "{err}");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_planet_over_the_default_budget_is_viewed_whole_by_default() {
    // A cap below the base mesh: views without max_faces give the base mesh (the coarsest view
    // there is), views that ask for less are refused.
    let s = start(Config { max_faces_cap: 100, ..config(&scratch("over-default")) }).await;
    let id = ready_planet(&s, r#"{"seed": 5, "params": {"base_faces": 200}}"#).await;
    let rec: serde_json::Value = s.get(&format!("/v1/planets/{id}")).await.json().await.unwrap();
    let base_faces = rec["stats"]["faces"].as_u64().unwrap();
    assert!(base_faces > 100, "{rec}");
    let view = format!("/v1/planets/{id}/view.glb?eye=0,0,2e7&target=0,0,0&width=320&height=180");
    let res = s.get(&view).await;
    assert_eq!(res.status().as_u16(), 200);
    let glb = res.bytes().await.unwrap();
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let json: serde_json::Value = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    let indices = json["meshes"][0]["primitives"][0]["indices"].as_u64().unwrap() as usize;
    assert_eq!(json["accessors"][indices]["count"].as_u64().unwrap(), 3 * base_faces);
    let err = expect_error(s.get(&format!("{view}&max_faces=100")).await, 422, "invalid_parameter").await;
    assert_eq!(err["field"], "max_faces");
    assert!(err["message"].as_str().unwrap().contains(&format!("below the {base_faces} faces")), "{err}");
    s.stop().await;
}
