//! The HTTP service's refusals: every 4xx carries the JSON error shape with `Cache-Control:
//! no-store`, and names the field at fault where there is one.

mod server_common;

use server_common::*;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bad_requests_name_their_problem() {
    let s = start(config(&scratch("errors"))).await;
    let res = s.post_json(r#"{"seed": 5, "params": {"base_faces": 200}}"#).await;
    assert_eq!(res.status().as_u16(), 202);
    let id = res.json::<serde_json::Value>().await.unwrap()["id"].as_str().unwrap().to_string();

    // 404: unknown ids, ids of the wrong shape, unknown routes.
    for path in [
        "/v1/planets/0123456789abcdef".to_string(),
        "/v1/planets/..%2F..%2Fetc%2Fpasswd".to_string(),
        "/v1/planets/EARTH".to_string(),
        format!("/v1/planets/{}/view.glb?{CAMERA}", id.to_uppercase()),
        "/v1/planets/0123456789abcdef/rivers.geojson".to_string(),
        "/v2/planets".to_string(),
    ] {
        expect_error(s.get(&path).await, 404, "not_found").await;
    }
    // 405 on known routes.
    let res = s.client.put(s.url("/v1/planets")).send().await.unwrap();
    assert!(res.headers().contains_key("allow"));
    expect_error(res, 405, "method_not_allowed").await;
    let res = s.client.post(s.url(&format!("/v1/planets/{id}/view.glb"))).send().await.unwrap();
    expect_error(res, 405, "method_not_allowed").await;
    let res = s.client.delete(s.url("/healthz")).send().await.unwrap();
    expect_error(res, 405, "method_not_allowed").await;

    // 415: a content type that is neither JSON nor multipart; a map that is no image.
    let res = s.client.post(s.url("/v1/planets")).header("content-type", "text/plain").body("hi").send().await.unwrap();
    expect_error(res, 415, "unsupported_media_type").await;
    let html = b"<!doctype html><html><body>not a map</body></html>".to_vec();
    let err = expect_error(s.post_map(html, &[]).await, 415, "unsupported_format").await;
    assert_eq!(err["field"], "map");

    // 422: parameters out of range or unknown, bad multipart parts, bad maps.
    let err = expect_error(s.post_json(r#"{"params": {"land_percent": 0}}"#).await, 422, "invalid_params").await;
    assert_eq!(err["field"], "params.land_percent");
    let err = expect_error(s.post_json(r#"{"params": {"radius": 5}}"#).await, 422, "invalid_params").await;
    assert!(err["message"].as_str().unwrap().contains("radius"));
    let err = expect_error(s.post_json("not json").await, 422, "invalid_params").await;
    assert_eq!(err["field"], "body");
    let err = expect_error(s.post_map(small_map(), &[("params", r#"{"base_faces": 4}"#)]).await, 422, "invalid_params");
    assert_eq!(err.await["field"], "params.base_faces");
    let err = expect_error(s.post_map(small_map(), &[("seed", "-3")]).await, 422, "invalid_params").await;
    assert_eq!(err["field"], "seed");
    let err = expect_error(s.post_map(small_map(), &[("map_kind", "lava")]).await, 422, "invalid_map_kind").await;
    assert_eq!(err["field"], "map_kind");
    let err = expect_error(s.post_map(small_map(), &[("map_bounds", "10,0,5,20")]).await, 422, "invalid_bounds").await;
    assert_eq!(err["field"], "map_bounds");
    let err = expect_error(s.post_map(small_map(), &[("map_kind", "elevation")]).await, 422, "missing_map_range").await;
    assert_eq!(err["field"], "map_range");
    let err = expect_error(s.post_map(small_map(), &[("colour", "red")]).await, 422, "unknown_field").await;
    assert_eq!(err["field"], "colour");
    // A part or a JSON key given twice is refused by name, not settled by the last one.
    let twice = [("seed", "1"), ("seed", "2")];
    let err = expect_error(s.post_map(small_map(), &twice).await, 422, "duplicate_field").await;
    assert_eq!(err["field"], "seed");
    let err = expect_error(s.post_map(small_map(), &[("map", "x")]).await, 422, "duplicate_field").await;
    assert_eq!(err["field"], "map");
    let err = expect_error(s.post_json(r#"{"seed": 1, "seed": 2}"#).await, 422, "invalid_params").await;
    assert_eq!(
        (err["field"].as_str(), err["message"].as_str()),
        (Some("seed"), Some("the key is given twice; give it once"))
    );
    let mut cut = small_map();
    cut.truncate(cut.len() / 2);
    let err = expect_error(s.post_map(cut, &[]).await, 422, "corrupt_image").await;
    assert_eq!(err["field"], "map");

    // 422: cameras and queries.
    let view = format!("/v1/planets/{id}/view.glb");
    for (query, code, field) in [
        ("eye=0,0,1e6&target=0,0,0", "invalid_camera", "eye"),
        ("eye=0,0,2e7", "invalid_camera", "target"),
        ("eye=0,0,2e7&target=0,0,0&width=0", "invalid_camera", "width"),
        ("eye=0,0,2e7&target=0,0,0&fov=abc", "invalid_camera", "fov"),
        ("eye=0,0,2e7&target=0,0,0&zoom=2", "unknown_parameter", "zoom"),
        ("eye=0,0,2e7&target=0,0,0&max_faces=0", "invalid_parameter", "max_faces"),
        ("eye=0,0,2e7&target=0,0,0&max_faces=2000001", "invalid_parameter", "max_faces"),
        ("eye=0,0,2e7&target=0,0,0&eye=0,0,3e7", "invalid_camera", "eye"),
        ("eye=0,0,2e7&target=0,0,0&max_faces=9000&max_faces=9000", "invalid_camera", "max_faces"),
    ] {
        let err = expect_error(s.get(&format!("{view}?{query}")).await, 422, code).await;
        assert_eq!(err["field"], field, "{query}");
    }
    for (path, code, field) in [
        (format!("/v1/planets/{id}/preview.png?width=1"), "invalid_parameter", "width"),
        (format!("/v1/planets/{id}/landmask.png?width=9000"), "invalid_parameter", "width"),
        (format!("/v1/planets/{id}/elevation.tif?height=5"), "unknown_parameter", "height"),
        (format!("/v1/planets/{id}/rivers.geojson?width=5"), "unknown_parameter", "width"),
        (format!("/v1/planets/{id}/dem.tif?width=5"), "missing_parameter", "bbox"),
        (format!("/v1/planets/{id}/dem.tif?bbox=1,2,3,4&width=5&width=6"), "duplicate_parameter", "width"),
        (format!("/v1/planets/{id}/dem.tif?bbox=1,2,3,4&width=8193"), "invalid_parameter", "width"),
        (format!("/v1/planets/{id}/dem.tif?bbox=1,2,3,4&width=8192&height=8192"), "invalid_parameter", "width"),
        (format!("/v1/planets/{id}/dem.tif?bbox=1,2,3,4&width=5&height=0"), "invalid_parameter", "height"),
        (format!("/v1/planets/{id}/dem.tif?bbox=170,2,190,4&width=5"), "invalid_bbox", "bbox"),
        (format!("/v1/planets/{id}/dem.tif?bbox=1,2,1,4&width=5"), "invalid_bbox", "bbox"),
        (format!("/v1/planets/{id}/dem.tif?bbox=1,2,3,4&width=5&crs=3857"), "unknown_parameter", "crs"),
        (format!("/v1/planets/{id}/dem/a/0/0.png"), "invalid_tile", "tile"),
        (format!("/v1/planets/{id}/dem/1/0/0.jpg"), "invalid_tile", "tile"),
        (format!("/v1/planets/{id}/dem/1/0/-1.png"), "invalid_tile", "tile"),
        (format!("/v1/planets/{id}/dem/1/0/0.png?encoding=rgb"), "invalid_parameter", "encoding"),
        (format!("/v1/planets/{id}/dem/1/0/0.png?encoding=mapbox&encoding=mapbox"), "duplicate_parameter", "encoding"),
        (format!("/v1/planets/{id}/dem/tilejson.json?format=png"), "unknown_parameter", "format"),
        (format!("/v1/planets/{id}/terrain/1/0/0.png"), "invalid_tile", "tile"),
        (format!("/v1/planets/{id}/terrain/1/0/0.terrain?v=1&v=2"), "duplicate_parameter", "v"),
        (format!("/v1/planets/{id}/terrain/1/0/0.terrain?extensions=watermask"), "unknown_parameter", "extensions"),
        (format!("/v1/planets/{id}/terrain/layer.json?v=1"), "unknown_parameter", "v"),
        (format!("/v1/planets/{id}/rivers/1/0/0.pbf"), "invalid_tile", "tile"),
        (format!("/v1/planets/{id}/rivers/1/0/0.mvt?layers=rivers"), "unknown_parameter", "layers"),
        (format!("/v1/planets/{id}/elevation.tif?width=64&width=128"), "duplicate_parameter", "width"),
        (format!("/v1/planets/{id}/tileset.json?v=1"), "unknown_parameter", "v"),
        (format!("/v1/planets/{id}/tiles/0.glb?v=1"), "unknown_parameter", "v"),
        (format!("/v1/planets/{id}?fields=all"), "unknown_parameter", "fields"),
    ] {
        let err = expect_error(s.get(&path).await, 422, code).await;
        assert_eq!(err["field"], field, "{path}");
    }
    // Tiles outside the scheme, or deeper than its deepest zoom: 404.
    // Ten digits may pass 2^32 (the spec's pattern allows them): still no tile, 404.
    for tile in ["15/0/0", "2/4/0", "2/0/4", "1/5167920898/637968", "1/0/9999999999", "99999999999/0/0"] {
        let path = format!("/v1/planets/{id}/dem/{tile}.png");
        let res = s.get(&path).await;
        let want = if tile.starts_with("9999") { 422 } else { 404 };
        assert_eq!(res.status().as_u16(), want, "{path}");
    }
    for tile in ["15/0/0", "2/4/0", "2/0/4"] {
        let path = format!("/v1/planets/{id}/rivers/{tile}.mvt");
        assert_eq!(s.get(&path).await.status().as_u16(), 404, "{path}");
    }
    // Cesium's geographic scheme: 2^(z+1) x 2^z tiles, down to zoom 14.
    for (tile, outside) in [("15/0/0", true), ("1/4/0", true), ("1/0/2", true), ("1/3/1", false), ("300/0/0", true)] {
        let path = format!("/v1/planets/{id}/terrain/{tile}.terrain");
        assert_eq!(s.get(&path).await.status().as_u16() == 404, outside, "{path}");
    }
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bodies_over_the_limit_answer_413() {
    let cfg = riverworld::server::Config { body_limit: 4096, ..config(&scratch("limit")) };
    let s = start(cfg).await;
    let big = small_map();
    assert!(big.len() > 4096);
    let res = s.post_map(big, &[]).await;
    expect_error(res, 413, "body_too_large").await;
    let json = format!(r#"{{"seed": 1, "params": {{}}, "pad": "{}"}}"#, "x".repeat(5000));
    expect_error(s.post_json(&json).await, 413, "body_too_large").await;
    // A chunked body (no Content-Length) is cut off at the limit too.
    let chunks: Vec<Result<Vec<u8>, std::io::Error>> = (0..10).map(|_| Ok(vec![b' '; 1000])).collect();
    let body = reqwest::Body::wrap_stream(futures::stream::iter(chunks));
    let res =
        s.client.post(s.url("/v1/planets")).header("content-type", "application/json").body(body).send().await.unwrap();
    expect_error(res, 413, "body_too_large").await;
    s.stop().await;
}

/// A PNG of `w`x`h` 16-bit grayscale pixels.
fn png16(w: u32, h: u32) -> Vec<u8> {
    let img = image::ImageBuffer::<image::Luma<u16>, Vec<u16>>::from_fn(w, h, |x, _| image::Luma([(x * 500) as u16]));
    let mut out = std::io::Cursor::new(Vec::new());
    img.write_to(&mut out, image::ImageFormat::Png).unwrap();
    out.into_inner()
}

/// A PNG of `w`x`h` RGB pixels.
fn png_rgb(w: u32, h: u32) -> Vec<u8> {
    let img = image::RgbImage::from_fn(w, h, |x, _| image::Rgb([x as u8, 0, 0]));
    let mut out = std::io::Cursor::new(Vec::new());
    img.write_to(&mut out, image::ImageFormat::Png).unwrap();
    out.into_inner()
}

/// POSTs `bytes` as the map part with the given part content type.
async fn post_typed(s: &TestServer, bytes: Vec<u8>, mime: &str, parts: &[(&str, &str)]) -> reqwest::Response {
    let part = reqwest::multipart::Part::bytes(bytes).file_name("map.png").mime_str(mime).unwrap();
    let mut form = reqwest::multipart::Form::new().part("map", part);
    for (k, v) in parts {
        form = form.text(k.to_string(), v.to_string());
    }
    s.client.post(s.url("/v1/planets")).multipart(form).send().await.unwrap()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn hostile_uploads_and_values_are_refused_and_the_server_keeps_serving() {
    let dir = scratch("hostile");
    let s = start(config(&dir)).await;
    let id = s.posted_id(r#"{"seed": 8, "params": {"base_faces": 200}}"#).await;
    s.wait_ready(&id).await;

    // Content sniffing: the bytes decide, whatever the declared content type.
    let jpeg = [&[0xFF, 0xD8, 0xFF, 0xE0, 0, 16][..], b"JFIF\0", &[0u8; 64]].concat();
    let gif = [&b"GIF89a"[..], &[1, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0]].concat();
    for (bytes, mime) in [
        (jpeg, "image/png"),
        (gif, "image/png"),
        (b"%PDF-1.7 not a map".to_vec(), "image/tiff"),
        (vec![0u8; 2048], "image/png"),
        (Vec::new(), "image/png"),
    ] {
        let err = expect_error(post_typed(&s, bytes, mime, &[]).await, 415, "unsupported_format").await;
        assert_eq!(err["field"], "map");
    }
    // A real PNG labelled as something else is accepted (here: refused later only for its content).
    let err = expect_error(post_typed(&s, png_rgb(64, 32), "text/plain", &[]).await, 422, "wrong_color_type").await;
    assert_eq!(err["field"], "map");

    // A map with no sea or no land is refused at upload, naming why, and nothing is stored.
    let gray = |w: u32, h: u32, v: u8| {
        let mut out = std::io::Cursor::new(Vec::new());
        image::GrayImage::from_pixel(w, h, image::Luma([v])).write_to(&mut out, image::ImageFormat::Png).unwrap();
        out.into_inner()
    };
    let err = expect_error(s.post_map(gray(1, 1, 255), &[]).await, 422, "no_sea").await;
    assert_eq!(err["field"], "map");
    let err = expect_error(s.post_map(gray(64, 32, 0), &[]).await, 422, "no_land").await;
    assert_eq!(err["field"], "map");
    let listed = s.get("/v1/planets").await.json::<serde_json::Value>().await.unwrap();
    assert_eq!(listed["planets"].as_array().unwrap().len(), 1, "only the first planet is stored: {listed}");
    // A regional map that is all land is an island: accepted.
    let res = s.post_map(gray(32, 32, 255), &[("map_bounds", "10,10,12,12")]).await;
    assert_eq!(res.status().as_u16(), 202);

    // Bit depth and colour model that the map kind does not take.
    let err = expect_error(s.post_map(png16(64, 32), &[("map_kind", "continents")]).await, 422, "wrong_bit_depth");
    assert_eq!(err.await["field"], "map");
    let err = expect_error(s.post_map(png16(64, 32), &[]).await, 422, "wrong_bit_depth").await;
    assert!(err["message"].as_str().unwrap().contains("16-bit"), "{err}");

    // Decompression bombs: the header's size is refused before any pixel is decoded.
    let mut bomb = small_map();
    bomb[16..20].copy_from_slice(&65_535u32.to_be_bytes());
    bomb[20..24].copy_from_slice(&65_535u32.to_be_bytes());
    let err = expect_error(s.post_map(bomb, &[]).await, 422, "image_too_large").await;
    assert_eq!(err["field"], "map");
    // A header that promises more pixels than the file could hold is corrupt.
    let mut liar = small_map();
    liar[16..20].copy_from_slice(&4096u32.to_be_bytes());
    liar[20..24].copy_from_slice(&2048u32.to_be_bytes());
    expect_error(s.post_map(liar, &[]).await, 422, "corrupt_image").await;

    // Truncated and damaged PNG and TIFF.
    let mut bad_png = small_map();
    let mid = bad_png.len() / 2;
    bad_png[mid..mid + 64].fill(0xA5);
    expect_error(s.post_map(bad_png, &[]).await, 422, "corrupt_image").await;
    expect_error(s.post_map(small_map()[..40].to_vec(), &[]).await, 422, "corrupt_image").await;
    let tif = s.get(&format!("/v1/planets/{id}/elevation.tif?width=64")).await.bytes().await.unwrap().to_vec();
    assert_eq!(s.post_map(tif.clone(), &[("params", r#"{"base_faces": 200}"#)]).await.status().as_u16(), 202);
    // A GeoTIFF is an elevation map: as continents it is refused by its kind, not as no image.
    let err = expect_error(s.post_map(tif.clone(), &[("map_kind", "continents")]).await, 422, "wrong_map_kind").await;
    assert_eq!(err["field"], "map_kind");
    for cut in [8, 100, tif.len() / 2, tif.len() - 10] {
        let err = expect_error(s.post_map(tif[..cut].to_vec(), &[]).await, 422, "corrupt_image").await;
        assert_eq!(err["field"], "map", "cut at {cut}");
    }
    let mut garbled = tif.clone();
    garbled[4..8].copy_from_slice(&u32::MAX.to_le_bytes()); // the first IFD's offset
    expect_error(s.post_map(garbled, &[]).await, 422, "corrupt_image").await;

    // NaN, infinities and absurd numbers name their field.
    for (body, field) in [
        (r#"{"params": {"radius_m": 1e999}}"#, "params.radius_m"),
        (r#"{"params": {"radius_m": -1e308}}"#, "params.radius_m"),
        (r#"{"params": {"land_percent": -0.0}}"#, "params.land_percent"),
        (r#"{"params": {"continents": 1e9}}"#, "params.continents"),
        (r#"{"params": {"base_faces": 99999999999}}"#, "params.base_faces"),
        (r#"{"params": {"sea_level_m": "NaN"}}"#, "params.sea_level_m"),
        (r#"{"seed": -1}"#, "seed"),
        (r#"{"seed": 1.5}"#, "seed"),
        (r#"{"seed": 18446744073709551616}"#, "seed"),
        (r#"{""seedparams"m{"seed"#, "body"),
        (r#"{"": 1}"#, "body"),
    ] {
        let err = expect_error(s.post_json(body).await, 422, "invalid_params").await;
        assert_eq!(err["field"], field, "{body}: {err}");
    }
    for (parts, code, field) in [
        (&[("map_range", "NaN,100")][..], "invalid_map_range", "map_range"),
        (&[("map_range", "-inf,100")], "invalid_map_range", "map_range"),
        (&[("map_range", "1e400,2")], "invalid_map_range", "map_range"),
        (&[("map_bounds", "nan,0,10,10")], "invalid_bounds", "map_bounds"),
        (&[("map_bounds", "0,0,1e999,10")], "invalid_bounds", "map_bounds"),
        (&[("params", r#"{"land_percent": NaN}"#)], "invalid_params", "params"),
        (&[("seed", "1e3")], "invalid_params", "seed"),
    ] {
        let err = expect_error(s.post_map(small_map(), parts).await, 422, code).await;
        assert_eq!(err["field"], field, "{parts:?}: {err}");
    }
    let view = format!("/v1/planets/{id}/view.glb");
    for (query, code, field) in [
        ("eye=NaN,0,2e7&target=0,0,0", "invalid_camera", "eye"),
        ("eye=0,0,inf&target=0,0,0", "invalid_camera", "eye"),
        ("eye=0,0,2e7&target=0,0,0&fov=inf", "invalid_camera", "fov"),
        ("eye=0,0,2e7&target=0,0,0&land_px=1e308", "invalid_camera", "land_px"),
        ("eye=0,0,2e7&target=0,0,0&width=99999999999999999999", "invalid_camera", "width"),
        ("eye=0,0,2e7&target=0,0,0&max_faces=1e9", "invalid_parameter", "max_faces"),
        ("eye=0,0,2e7&target=0,0,0&max_faces=-1", "invalid_parameter", "max_faces"),
        ("eye=0,8e6,1e206&target=5,0,1", "invalid_camera", "eye"),
        ("eye=0,0,2e7&target=0,0,0&up=1e300,0,0", "invalid_camera", "up"),
    ] {
        let err = expect_error(s.get(&format!("{view}?{query}")).await, 422, code).await;
        assert_eq!(err["field"], field, "{query}");
    }
    let err = expect_error(s.get(&format!("/v1/planets/{id}/preview.png?width=NaN")).await, 422, "invalid_parameter");
    assert_eq!(err.await["field"], "width");

    // Ids of the wrong shape never reach the store, however they are spelled.
    for path in [
        "/v1/planets/%2e%2e",
        "/v1/planets/..%2f..%2fplanets",
        "/v1/planets/0123456789abcde%00",
        "/v1/planets/0123456789abcdef0",
        "/v1/planets/%30123456789abcdef",
        "/v1/planets/earth%2f..%2f..",
    ] {
        expect_error(s.get(path).await, 404, "not_found").await;
        expect_error(s.client.delete(s.url(path)).send().await.unwrap(), 404, "not_found").await;
    }

    // Still serving: reads and a good upload work, and nothing refused was stored.
    assert_eq!(s.get("/healthz").await.status().as_u16(), 200);
    assert_eq!(s.get(&format!("/v1/planets/{id}/rivers.geojson")).await.status().as_u16(), 200);
    let res = s.post_map(small_map(), &[("params", r#"{"base_faces": 500}"#)]).await;
    assert_eq!(res.status().as_u16(), 202);
    let stored = std::fs::read_dir(dir.join("planets")).unwrap().count();
    assert_eq!(stored, 4, "the JSON planet, the regional island, the GeoTIFF planet and the good upload");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn oversized_request_heads_answer_in_the_error_shape() {
    let s = start(config(&scratch("heads"))).await;
    // A 60 KB camera: refused by length, not echoed back.
    let long = format!("/v1/planets/earth/view.glb?eye={}&target=0,0,0", "1".repeat(60_000));
    let err = expect_error(s.get(&long).await, 414, "uri_too_long").await;
    let message = err["message"].as_str().unwrap();
    assert!(message.contains("at most 8192") && message.len() < 200, "{err}");
    let mut many = s.client.get(s.url("/healthz"));
    for i in 0..70 {
        many = many.header(format!("x-filler-{i}"), "1");
    }
    expect_error(many.send().await.unwrap(), 431, "headers_too_large").await;
    let big = s.client.get(s.url("/healthz")).header("x-filler", "a".repeat(20_000));
    let err = expect_error(big.send().await.unwrap(), 431, "headers_too_large").await;
    assert!(err["message"].as_str().unwrap().contains("16384 bytes"), "{err}");
    // Within the limits, and after, the server answers as usual.
    let fine = s.client.get(s.url("/healthz")).header("x-filler", "a".repeat(8_000));
    assert_eq!(fine.send().await.unwrap().status().as_u16(), 200);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn errors_never_echo_a_long_input_whole() {
    let s = start(config(&scratch("echo"))).await;
    let id = s.posted_id(r#"{"seed": 8, "params": {"base_faces": 200}}"#).await;
    let width = "9".repeat(7000);
    let err =
        expect_error(s.get(&format!("/v1/planets/{id}/landmask.png?width={width}")).await, 422, "invalid_parameter");
    let err = err.await;
    assert!(err["message"].as_str().unwrap().chars().count() <= 601, "{err}");
    let body = format!(r#"{{"seed": "{}"}}"#, "y".repeat(5000));
    let err = expect_error(s.post_json(&body).await, 422, "invalid_params").await;
    let message = err["message"].as_str().unwrap();
    assert!(message.chars().count() <= 601 && message.ends_with('…'), "{err}");
    s.stop().await;
}

/// Sends raw bytes on a new connection and reads the answer until the server closes it.
fn raw_exchange(addr: &str, request: &[u8]) -> String {
    use std::io::{Read, Write};
    let mut stream = std::net::TcpStream::connect(addr).unwrap();
    stream.set_read_timeout(Some(std::time::Duration::from_secs(10))).unwrap();
    stream.write_all(request).unwrap();
    let mut out = Vec::new();
    let _ = stream.read_to_end(&mut out);
    String::from_utf8_lossy(&out).into_owned()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn requests_the_http_layer_cannot_read_answer_in_the_error_shape() {
    let s = start(config(&scratch("unreadable"))).await;
    let addr = s.url("").trim_start_matches("http://").trim_end_matches('/').to_string();
    let long_target = [b"GET /".as_slice(), &vec![b'a'; 70_000], b" HTTP/1.1\r\nHost: x\r\n\r\n"].concat();
    let mut many_headers = b"GET /healthz HTTP/1.1\r\nHost: x\r\n".to_vec();
    for i in 0..150 {
        many_headers.extend_from_slice(format!("x-h{i}: 1\r\n").as_bytes());
    }
    many_headers.extend_from_slice(b"\r\n");
    let cases: [(&[u8], u16, &str); 4] = [
        (b"GARBAGE\r\n\r\n", 400, "bad_request"),
        (b"GET /healthz HTTP/1.1\r\nHost: x\r\nno colon here\r\n\r\n", 400, "bad_request"),
        (&long_target, 414, "uri_too_long"),
        (&many_headers, 431, "headers_too_large"),
    ];
    for (request, status, code) in cases {
        let addr = addr.clone();
        let request = request.to_vec();
        let answer = tokio::task::spawn_blocking(move || raw_exchange(&addr, &request)).await.unwrap();
        let (head, body) = answer.split_once("\r\n\r\n").unwrap_or_else(|| panic!("{answer:?}"));
        assert!(head.starts_with(&format!("HTTP/1.1 {status} ")), "{answer:?}");
        assert!(head.contains("content-type: application/json"), "{answer:?}");
        let json: serde_json::Value = serde_json::from_str(body).unwrap_or_else(|_| panic!("{answer:?}"));
        assert_eq!(json["error"]["code"], code, "{answer:?}");
    }
    // The server keeps serving, answers of its own untouched.
    assert_eq!(s.get("/healthz").await.status().as_u16(), 200);
    expect_error(s.get("/v1/planets/nope").await, 404, "not_found").await;
    s.stop().await;
}
