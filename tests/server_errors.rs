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
    ] {
        let err = expect_error(s.get(&format!("{view}?{query}")).await, 422, code).await;
        assert_eq!(err["field"], field, "{query}");
    }
    for (path, code, field) in [
        (format!("/v1/planets/{id}/preview.png?width=1"), "invalid_parameter", "width"),
        (format!("/v1/planets/{id}/landmask.png?width=9000"), "invalid_parameter", "width"),
        (format!("/v1/planets/{id}/elevation.tif?height=5"), "unknown_parameter", "height"),
        (format!("/v1/planets/{id}/rivers.geojson?width=5"), "unknown_parameter", "width"),
    ] {
        let err = expect_error(s.get(&path).await, 422, code).await;
        assert_eq!(err["field"], field, "{path}");
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
