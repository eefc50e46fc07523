//! The HTTP service end to end: a real server on a free port, a real client, a scratch store.

mod server_common;

use serde_json::Value;
use server_common::*;
use std::time::Duration;

async fn created_id(res: reqwest::Response) -> String {
    assert_eq!(res.status().as_u16(), 202);
    let loc = res.headers()["location"].to_str().unwrap().to_string();
    let rec: Value = res.json().await.unwrap();
    let id = rec["id"].as_str().unwrap().to_string();
    assert_eq!(loc, format!("/v1/planets/{id}"));
    assert!(id.len() == 16 && id.bytes().all(|b| b.is_ascii_hexdigit() && !b.is_ascii_uppercase()), "{id}");
    assert!(matches!(rec["status"].as_str(), Some("queued" | "building" | "ready")), "{rec}");
    id
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn map_upload_builds_and_serves_every_file() {
    let s = start(config(&scratch("happy"))).await;
    let id =
        created_id(s.post_map(small_map(), &[("params", FAST), ("seed", "1"), ("map_kind", "continents")]).await).await;
    let rec = s.wait_ready(&id).await;
    assert_eq!(rec["progress"], 1.0);
    assert_eq!(rec["seed"], 1);
    assert_eq!(rec["params"]["base_faces"], 2000);
    assert_eq!(rec["map"]["kind"], "continents");
    assert_eq!((rec["map"]["width"].as_u64(), rec["map"]["height"].as_u64()), (Some(256), Some(128)));
    assert!(rec["stats"]["faces"].as_u64().unwrap() >= 2000);
    // No wall-clock time: every replica answers a planet's record with the same bytes.
    assert!(rec["stats"].get("build_ms").is_none(), "{}", rec["stats"]);
    assert!(rec["error"].is_null());
    assert!(s.dir.join(format!("planets/{id}/request.json")).is_file());
    assert!(s.dir.join(format!("planets/{id}/map.bin")).is_file());

    // The same inputs again: same id, nothing new.
    let again = s.post_map(small_map(), &[("params", FAST), ("seed", "1")]).await;
    assert_eq!(again.status().as_u16(), 200);
    assert_eq!(again.headers()["location"].to_str().unwrap(), format!("/v1/planets/{id}"));
    assert_eq!(again.json::<Value>().await.unwrap()["id"], id.as_str());
    let list: Value = s.get("/v1/planets").await.json().await.unwrap();
    let ids: Vec<&str> = list["planets"].as_array().unwrap().iter().map(|p| p["id"].as_str().unwrap()).collect();
    assert_eq!(ids, vec![id.as_str()]);

    let res = s.get(&format!("/v1/planets/{id}/view.glb?{CAMERA}")).await;
    assert_eq!(res.status().as_u16(), 200);
    let h = res.headers().clone();
    assert_eq!(h["content-type"], "model/gltf-binary");
    assert_eq!(h["cache-control"], "public, max-age=31536000, immutable");
    let etag = h["etag"].to_str().unwrap().to_string();
    assert!(etag.starts_with('"') && etag.ends_with('"') && etag.len() > 10, "{etag}");
    let glb = res.bytes().await.unwrap();
    assert_eq!(&glb[..4], b"glTF");

    // Revalidation: 304 with the same validator, no body.
    let res = s
        .client
        .get(s.url(&format!("/v1/planets/{id}/view.glb?{CAMERA}")))
        .header("if-none-match", &etag)
        .send()
        .await
        .unwrap();
    assert_eq!(res.status().as_u16(), 304);
    assert_eq!(res.headers()["etag"].to_str().unwrap(), etag);
    assert!(res.bytes().await.unwrap().is_empty());
    // `*` asks whether any answer exists: this one does; one whose budget is below the base
    // mesh does not, and is refused as without the header.
    let star = |q: String| s.client.get(s.url(&q)).header("if-none-match", "*").send();
    let res = star(format!("/v1/planets/{id}/view.glb?{CAMERA}")).await.unwrap();
    assert_eq!(res.status().as_u16(), 304);
    assert_eq!(res.headers()["etag"].to_str().unwrap(), etag);
    let low = CAMERA.replace("max_faces=50000", "max_faces=100");
    let res = star(format!("/v1/planets/{id}/view.glb?{low}")).await.unwrap();
    assert_eq!(res.status().as_u16(), 422);
    assert!(res.text().await.unwrap().contains("max_faces"));
    // Key order does not matter: the query is normalised.
    let reordered = "max_faces=50000&land_px=8&height=180&width=320&target=0,0,0&eye=7e6,0,3e6";
    let res = s.get(&format!("/v1/planets/{id}/view.glb?{reordered}")).await;
    assert_eq!(res.headers()["etag"].to_str().unwrap(), etag);
    assert_eq!(res.bytes().await.unwrap(), glb);
    // Compressed by default (EXT_meshopt_compression, required); `compression=none` gives the
    // plain file, larger, under its own tag; `compression=meshopt` is the default's.
    let required = |b: &[u8]| -> Value {
        let len = u32::from_le_bytes(b[12..16].try_into().unwrap()) as usize;
        serde_json::from_slice::<Value>(&b[20..20 + len]).unwrap()["extensionsRequired"].clone()
    };
    assert!(required(&glb).as_array().unwrap().iter().any(|e| e == "EXT_meshopt_compression"));
    let res = s.get(&format!("/v1/planets/{id}/view.glb?{CAMERA}&compression=none")).await;
    assert_ne!(res.headers()["etag"].to_str().unwrap(), etag);
    let plain = res.bytes().await.unwrap();
    assert!(required(&plain).is_null() && plain.len() > 2 * glb.len(), "{} vs {}", plain.len(), glb.len());
    let res = s.get(&format!("/v1/planets/{id}/view.glb?{CAMERA}&compression=meshopt")).await;
    assert_eq!(res.headers()["etag"].to_str().unwrap(), etag);
    let res = s.get(&format!("/v1/planets/{id}/view.glb?{CAMERA}&compression=gzip")).await;
    assert_eq!(res.status().as_u16(), 422);
    assert!(res.text().await.unwrap().contains("neither meshopt nor none"));

    let res = s.get(&format!("/v1/planets/{id}/rivers.geojson")).await;
    assert_eq!(res.status().as_u16(), 200);
    assert_eq!(res.headers()["content-type"], "application/geo+json");
    assert!(res.headers().contains_key("etag"));
    let rivers: Value = res.json().await.unwrap();
    assert_eq!(rivers["type"], "FeatureCollection");
    assert!(!rivers["features"].as_array().unwrap().is_empty());

    for (file, ctype) in [("landmask.png", "image/png"), ("preview.png", "image/png"), ("elevation.tif", "image/tiff")]
    {
        let res = s.get(&format!("/v1/planets/{id}/{file}?width=128")).await;
        assert_eq!(res.status().as_u16(), 200, "{file}");
        assert_eq!(res.headers()["content-type"], ctype, "{file}");
        assert_eq!(res.headers()["cache-control"], "public, max-age=31536000, immutable");
        let bytes = res.bytes().await.unwrap();
        if ctype == "image/png" {
            let img = image::load_from_memory(&bytes).unwrap();
            assert_eq!((img.width(), img.height()), (128, 64), "{file}");
        } else {
            assert!(bytes.starts_with(b"II*\0") || bytes.starts_with(b"MM\0*"));
        }
    }
    // A DEM of a region: a two-band COG, cached under its normal query (key order and
    // percent-encoding do not matter).
    let res = s.get(&format!("/v1/planets/{id}/dem.tif?bbox=-20,-10,20,10&width=160")).await;
    assert_eq!(res.status().as_u16(), 200);
    assert_eq!(res.headers()["content-type"], "image/tiff");
    let etag = res.headers()["etag"].to_str().unwrap().to_string();
    let dem = res.bytes().await.unwrap();
    assert!(dem.starts_with(b"II*\0"));
    let res = s.get(&format!("/v1/planets/{id}/dem.tif?width=160&height=80&bbox=-20%2C-10%2C20%2C10")).await;
    assert_eq!(res.headers()["etag"].to_str().unwrap(), etag);
    assert_eq!(res.bytes().await.unwrap(), dem);
    // Elevation tiles for MapLibre: TileJSON with absolute tile URLs; a tile is a 512x512 PNG
    // whose colours decode to the ground's heights, alike in both encodings.
    let tj: Value = s.get(&format!("/v1/planets/{id}/dem/tilejson.json")).await.json().await.unwrap();
    assert_eq!((tj["tilejson"].as_str(), tj["encoding"].as_str()), (Some("3.0.0"), Some("terrarium")));
    assert_eq!(
        (tj["tileSize"].as_u64(), tj["minzoom"].as_u64(), tj["maxzoom"].as_u64()),
        (Some(512), Some(0), Some(14))
    );
    let url = tj["tiles"][0].as_str().unwrap().to_string();
    assert!(
        url.starts_with("http://127.0.0.1:") && url.ends_with(&format!("/v1/planets/{id}/dem/{{z}}/{{x}}/{{y}}.png")),
        "{url}"
    );
    let heights = |bytes: &[u8], mapbox: bool| -> Vec<f64> {
        let img = image::load_from_memory(bytes).unwrap().to_rgb8();
        assert_eq!(img.dimensions(), (512, 512));
        img.pixels()
            .map(|p| {
                let [r, g, b] = p.0.map(f64::from);
                if mapbox {
                    -10000.0 + (r * 65536.0 + g * 256.0 + b) * 0.1
                } else {
                    r * 256.0 + g + b / 256.0 - 32768.0
                }
            })
            .collect()
    };
    let res = s.client.get(url.replace("{z}/{x}/{y}", "1/1/0")).send().await.unwrap();
    assert_eq!(res.status().as_u16(), 200);
    assert_eq!(res.headers()["content-type"], "image/png");
    let terrarium = heights(&res.bytes().await.unwrap(), false);
    let (lo, hi) = terrarium.iter().fold((f64::MAX, f64::MIN), |(a, b), &h| (a.min(h), b.max(h)));
    assert!(-12_000.0 < lo && lo < hi && hi < 12_000.0, "{lo}..{hi}");
    let tj: Value = s.get(&format!("/v1/planets/{id}/dem/tilejson.json?encoding=mapbox")).await.json().await.unwrap();
    let url = tj["tiles"][0].as_str().unwrap().to_string();
    assert!(url.ends_with(".png?encoding=mapbox"), "{url}");
    let mapbox =
        heights(&s.client.get(url.replace("{z}/{x}/{y}", "1/1/0")).send().await.unwrap().bytes().await.unwrap(), true);
    let worst = terrarium.iter().zip(&mapbox).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    assert!(worst <= 0.06, "{worst} m between the encodings");
    // Cesium terrain: layer.json names relative quantized-mesh tiles; a tile carries the
    // extensions its Accept asks for, varies by Accept, and is gzipped when accepted.
    let layer: Value = s.get(&format!("/v1/planets/{id}/terrain/layer.json")).await.json().await.unwrap();
    assert_eq!(layer["format"], "quantized-mesh-1.0");
    assert_eq!(layer["scheme"], "tms");
    let tile_url = |t: &str| {
        let v = layer["version"].as_str().unwrap();
        let rel = layer["tiles"][0].as_str().unwrap().replace("{z}/{x}/{y}", t).replace("{version}", v);
        s.url(&format!("/v1/planets/{id}/terrain/{rel}"))
    };
    let plain = s.client.get(tile_url("1/2/1")).send().await.unwrap();
    assert_eq!(plain.status().as_u16(), 200);
    assert_eq!(plain.headers()["content-type"], "application/vnd.quantized-mesh");
    assert!(plain.headers().get_all("vary").iter().any(|v| v.to_str().unwrap().contains("accept")));
    let plain_tag = plain.headers()["etag"].clone();
    let plain = plain.bytes().await.unwrap();
    let accept = "application/vnd.quantized-mesh;extensions=octvertexnormals-watermask-metadata,*/*;q=0.01";
    let full = s.client.get(tile_url("1/2/1")).header("accept", accept).send().await.unwrap();
    assert_ne!(full.headers()["etag"], plain_tag);
    let full = full.bytes().await.unwrap();
    // The extensions follow the plain tile's bytes: normals (2 bytes per vertex) first.
    assert!(full.len() > plain.len() && full.starts_with(&plain));
    let vertices = u32::from_le_bytes(plain[88..92].try_into().unwrap()) as usize;
    assert_eq!(vertices, 65 * 65);
    assert_eq!(full[plain.len()], 1);
    assert_eq!(u32::from_le_bytes(full[plain.len() + 1..plain.len() + 5].try_into().unwrap()) as usize, 2 * vertices);
    let gz = s.client.get(tile_url("1/2/1")).header("accept-encoding", "gzip").send().await.unwrap();
    assert_eq!(gz.headers()["content-encoding"], "gzip");
    let res = s.client.get(tile_url("1/2/1")).header("if-none-match", plain_tag).send().await.unwrap();
    assert_eq!(res.status().as_u16(), 304);
    // Rivers as vector tiles: TileJSON with both layers, tiles gzipped on request.
    let tj: Value = s.get(&format!("/v1/planets/{id}/rivers/tilejson.json")).await.json().await.unwrap();
    assert_eq!(tj["vector_layers"][0]["id"], "rivers");
    let url = tj["tiles"][0].as_str().unwrap().to_string();
    assert!(url.ends_with(&format!("/v1/planets/{id}/rivers/{{z}}/{{x}}/{{y}}.mvt")), "{url}");
    let res = s.client.get(url.replace("{z}/{x}/{y}", "0/0/0")).send().await.unwrap();
    assert_eq!(res.status().as_u16(), 200);
    assert_eq!(res.headers()["content-type"], "application/vnd.mapbox-vector-tile");
    let size = res.bytes().await.unwrap().len();
    let res = s.client.get(url.replace("{z}/{x}/{y}", "0/0/0")).header("accept-encoding", "gzip").send().await.unwrap();
    // Bodies of 256 bytes or less are not worth compressing.
    assert_eq!(res.headers().get("content-encoding").is_some(), size > 256, "{size} bytes");
    // JSON is compressed when the client accepts it.
    let res = s
        .client
        .get(s.url(&format!("/v1/planets/{id}/rivers.geojson")))
        .header("accept-encoding", "gzip")
        .send()
        .await
        .unwrap();
    assert_eq!(res.headers()["content-encoding"], "gzip");

    let metrics = s.get("/metrics").await.text().await.unwrap();
    assert!(metrics.contains("riverworld_builds_finished_total 1"), "{metrics}");
    assert!(metrics
        .contains(r#"riverworld_http_requests_total{route="/v1/planets/{id}/view.glb",method="GET",status="304"} 2"#));
    assert!(metrics.contains("riverworld_http_request_duration_seconds_bucket"));
    assert!(metrics.contains(r#"riverworld_cache_hits_total{cache="response"}"#));

    // Methods beyond the standard ones count as `other`: clients cannot grow the metrics.
    let odd = reqwest::Method::from_bytes(b"FROBNICATE-0123456789").unwrap();
    for _ in 0..3 {
        s.client.request(odd.clone(), s.url("/v1/planets")).send().await.unwrap();
    }
    let metrics = s.get("/metrics").await.text().await.unwrap();
    assert!(!metrics.contains("FROBNICATE") && metrics.contains(r#"method="other""#), "{metrics}");

    // Delete: 204, then gone everywhere, its directory too.
    assert!(s.dir.join("planets").join(&id).is_dir());
    let res = s.client.delete(s.url(&format!("/v1/planets/{id}"))).send().await.unwrap();
    assert_eq!(res.status().as_u16(), 204);
    assert!(!s.dir.join("planets").join(&id).exists(), "the planet's directory stays after DELETE");
    expect_error(s.get(&format!("/v1/planets/{id}")).await, 404, "not_found").await;
    expect_error(s.get(&format!("/v1/planets/{id}/rivers.geojson")).await, 404, "not_found").await;
    assert!(!s.dir.join(format!("planets/{id}/request.json")).exists());
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn restart_lists_stored_planets_and_rebuilds_them_identically() {
    let dir = scratch("restart");
    let s = start(config(&dir)).await;
    let id = created_id(s.post_json(r#"{"seed": 7, "params": {"base_faces": 2000, "continents": 3}}"#).await).await;
    s.wait_ready(&id).await;
    let url = format!("/v1/planets/{id}/view.glb?{CAMERA}");
    let first = s.get(&url).await.bytes().await.unwrap();
    let preview = s.get(&format!("/v1/planets/{id}/preview.png?width=64")).await.bytes().await.unwrap();
    s.stop().await;

    let s = start(config(&dir)).await;
    let list: Value = s.get("/v1/planets").await.json().await.unwrap();
    assert_eq!(list["planets"][0]["id"], id.as_str());
    assert_eq!(list["planets"][0]["status"], "queued");
    assert_eq!(list["planets"][0]["params"]["continents"], 3);
    // A derived file of a planet not in memory starts its build and asks to retry.
    let res = s.get(&url).await;
    assert_eq!(res.headers()["retry-after"], "1");
    expect_error(res, 409, "not_ready").await;
    s.wait_ready(&id).await;
    assert_eq!(s.get(&url).await.bytes().await.unwrap(), first);
    let again = s.get(&format!("/v1/planets/{id}/preview.png?width=64")).await.bytes().await.unwrap();
    assert_eq!(again, preview);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn concurrent_requests_all_succeed() {
    let s = start(config(&scratch("concurrent"))).await;
    let id = created_id(s.post_json(r#"{"seed": 11, "params": {"base_faces": 2000}}"#).await).await;
    s.wait_ready(&id).await;
    let paths: Vec<String> = (0..16)
        .map(|i| match i % 4 {
            0 | 1 => format!("/v1/planets/{id}/view.glb?{CAMERA}"),
            2 => format!("/v1/planets/{id}/rivers.geojson"),
            _ => format!("/v1/planets/{id}/landmask.png?width={}", 64 + 2 * i),
        })
        .collect();
    let tasks: Vec<_> = paths
        .iter()
        .map(|p| {
            let (client, url) = (s.client.clone(), s.url(p));
            tokio::spawn(async move {
                let res = client.get(url).send().await.unwrap();
                (res.status().as_u16(), res.bytes().await.unwrap())
            })
        })
        .collect();
    let mut views = Vec::new();
    for (t, p) in tasks.into_iter().zip(&paths) {
        let (status, body) = t.await.unwrap();
        assert_eq!(status, 200, "{p}");
        if p.contains("view.glb") {
            views.push(body);
        }
    }
    assert!(views.windows(2).all(|w| w[0] == w[1]));
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_full_queue_answers_429_and_stores_nothing() {
    let dir = scratch("queue");
    let cfg = riverworld::server::Config {
        workers: 1,
        max_queue: 1,
        max_builds_per_client: 0,
        build_delay: Duration::from_secs(10),
        ..config(&dir)
    };
    let s = start(cfg).await;
    created_id(s.post_json(r#"{"seed": 1, "params": {"base_faces": 200}}"#).await).await;
    created_id(s.post_json(r#"{"seed": 2, "params": {"base_faces": 200}}"#).await).await;
    let res = s.post_json(r#"{"seed": 3, "params": {"base_faces": 200}}"#).await;
    assert!(res.headers()["retry-after"].to_str().unwrap().parse::<u32>().unwrap() >= 1);
    expect_error(res, 429, "queue_full").await;
    let list: Value = s.get("/v1/planets").await.json().await.unwrap();
    assert_eq!(list["planets"].as_array().unwrap().len(), 2);
    assert_eq!(std::fs::read_dir(dir.join("planets")).unwrap().count(), 2);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn one_client_cannot_fill_the_build_queue() {
    // Two builds per client address; behind a trusted proxy the address is the last
    // X-Forwarded-For entry, so each client behind it has its own share.
    let dir = scratch("per-client");
    let cfg = riverworld::server::Config {
        max_builds_per_client: 2,
        trust_forwarded_for: true,
        build_delay: Duration::from_secs(10),
        ..config(&dir)
    };
    let s = start(cfg).await;
    let post = |seed: u32, client: &'static str| {
        s.client
            .post(s.url("/v1/planets"))
            .header("content-type", "application/json")
            .header("x-forwarded-for", format!("203.0.113.9, {client}"))
            .body(format!(r#"{{"seed": {seed}, "params": {{"base_faces": 200}}}}"#))
            .send()
    };
    created_id(post(1, "198.51.100.1").await.unwrap()).await;
    created_id(post(2, "198.51.100.1").await.unwrap()).await;
    let res = post(3, "198.51.100.1").await.unwrap();
    assert!(res.headers()["retry-after"].to_str().unwrap().parse::<u32>().unwrap() >= 1);
    let err = expect_error(res, 429, "client_queue_full").await;
    assert!(err["message"].as_str().unwrap().contains("2 planets of yours"), "{err}");
    // Another client is served; a POST of a planet that exists takes no share.
    created_id(post(3, "198.51.100.2").await.unwrap()).await;
    assert_eq!(post(1, "198.51.100.1").await.unwrap().status().as_u16(), 202);
    assert_eq!(std::fs::read_dir(dir.join("planets")).unwrap().count(), 3);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn builtin_earth_becomes_ready_and_cannot_be_deleted() {
    // A cache far smaller than earth: the built-in planet is pinned, so uploads cannot evict it.
    let cfg = riverworld::server::Config { default_planet: true, cache_bytes: 1 << 20, ..config(&scratch("earth")) };
    let s = start(cfg).await;
    assert_eq!(s.get("/healthz").await.status().as_u16(), 200);
    let start = std::time::Instant::now();
    loop {
        let res = s.get("/readyz").await;
        if res.status().as_u16() == 200 {
            break;
        }
        expect_error(res, 503, "not_ready").await;
        assert!(start.elapsed() < Duration::from_secs(40), "earth not ready");
        tokio::time::sleep(Duration::from_millis(100)).await;
    }
    let rec = s.wait_ready("earth").await;
    assert_eq!(rec["seed"], 42);
    assert_eq!((rec["map"]["width"].as_u64(), rec["map"]["kind"].as_str()), (Some(1024), Some("elevation")));
    // Built from the Earth DEM, it keeps the map's heights and says so.
    let f = &rec["stats"]["map_fidelity"];
    assert!(f["r"].as_f64().unwrap() >= 0.97 && f["bias_m"].as_f64().unwrap().abs() <= 30.0, "{f}");
    let err = expect_error(s.client.delete(s.url("/v1/planets/earth")).send().await.unwrap(), 403, "protected_planet");
    err.await;
    let res = s.get("/v1/planets/earth/landmask.png?width=64").await;
    assert_eq!(res.status().as_u16(), 200);
    let other = created_id(s.post_json(r#"{"seed": 5, "params": {"base_faces": 2000}}"#).await).await;
    s.wait_ready(&other).await;
    let builds = |m: String| m.lines().find(|l| l.starts_with("riverworld_builds_finished_total")).map(str::to_string);
    let before = builds(s.get("/metrics").await.text().await.unwrap());
    let res = s.get("/v1/planets/earth/landmask.png?width=32").await;
    assert_eq!(res.status().as_u16(), 200, "earth answers at once, without a rebuild");
    assert_eq!(s.get("/readyz").await.status().as_u16(), 200);
    assert_eq!(builds(s.get("/metrics").await.text().await.unwrap()), before);
    let yaml = s.get("/openapi.yaml").await;
    assert_eq!(yaml.headers()["content-type"], "application/yaml");
    assert!(yaml.text().await.unwrap().starts_with("openapi: 3.1"));
    s.stop().await;
}
