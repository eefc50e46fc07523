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
async fn a_planet_over_the_face_limits_is_refused_before_it_is_stored() {
    // Admission by the base mesh's estimated faces: over --max-planet-faces, and over
    // --max-faces-cap (every view holds at least the base mesh), nothing is stored or built.
    let dir = scratch("planet-faces");
    let s = start(Config { max_planet_faces: 20_000, ..config(&dir) }).await;
    let err = expect_error(s.post_json(r#"{"seed": 5, "params": {"base_faces": 40000}}"#).await, 422, "too_large");
    let err = err.await;
    assert_eq!(err["field"], "params.base_faces");
    assert!(err["message"].as_str().unwrap().contains("at most 20000 faces"), "{err}");
    // A map whose refinement makes the planet large names the map: the shipped land mask asks
    // for ~350 km edges over the globe, about 65,000 faces.
    let mask = std::fs::read("maps/earth_landmask_ne10m_1024x512.png").unwrap();
    let err = expect_error(s.post_map(mask, &[("params", FAST)]).await, 422, "too_large").await;
    assert_eq!(err["field"], "map");
    let listed: Value = s.get("/v1/planets").await.json().await.unwrap();
    assert_eq!(listed["planets"].as_array().unwrap().len(), 0, "{listed}");
    assert!(std::fs::read_dir(dir.join("planets")).map_or(true, |mut d| d.next().is_none()));
    let ok = s.post_json(r#"{"seed": 5, "params": {"base_faces": 2000}}"#).await;
    assert_eq!(ok.status().as_u16(), 202);
    s.stop().await;

    let s = start(Config { max_faces_cap: 100, ..config(&scratch("over-cap")) }).await;
    let err = expect_error(s.post_json(r#"{"seed": 5, "params": {"base_faces": 200}}"#).await, 422, "too_large");
    assert_eq!(err.await["field"], "params.base_faces");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_stored_planet_above_a_lowered_face_cap_has_no_view() {
    // Created under one cap, served after a restart under a lower one: its views are refused
    // by name instead of exceeding the cap.
    let dir = scratch("lowered-cap");
    let s = start(config(&dir)).await;
    let id = ready_planet(&s, r#"{"seed": 5, "params": {"base_faces": 200}}"#).await;
    s.stop().await;
    let s = start(Config { max_faces_cap: 100, ..config(&dir) }).await;
    let rec = s.wait_ready(&id).await;
    let base_faces = rec["stats"]["faces"].as_u64().unwrap();
    assert!(base_faces > 100, "{rec}");
    let view = format!("/v1/planets/{id}/view.glb?eye=0,0,2e7&target=0,0,0&width=320&height=180");
    let err = expect_error(s.get(&view).await, 422, "too_large").await;
    assert_eq!(err["field"], "max_faces");
    assert!(err["message"].as_str().unwrap().contains(&format!("has {base_faces} faces")), "{err}");
    s.stop().await;
}
