//! render.png / render.jpg over real HTTP: images of the camera's size, byte-identical across
//! servers and adaption backends, cached with ETags, bad cameras and sizes refused, concurrent renders on one device,
//! and a server without a graphics adapter that still serves everything else.

mod server_common;

use server_common::*;

const SHOT: &str = "eye=7e6,0,3e6&target=0,0,0&width=160&height=120&max_faces=30000";

async fn planet(s: &TestServer) -> String {
    let res = s.post_json(&format!(r#"{{"seed": 5, "params": {FAST}}}"#)).await;
    let id = res.json::<serde_json::Value>().await.unwrap()["id"].as_str().unwrap().to_string();
    s.wait_ready(&id).await;
    id
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn renders_are_images_of_the_camera_size_identical_across_servers() {
    let a = start(config(&scratch("render-a"))).await;
    let id = planet(&a).await;
    let res = a.get(&format!("/v1/planets/{id}/render.png?{SHOT}")).await;
    assert_eq!(res.status(), 200, "{:?}", res.text().await);
    assert_eq!(res.headers()["content-type"], "image/png");
    let tag = res.headers()["etag"].to_str().unwrap().to_string();
    assert!(res.headers()["cache-control"].to_str().unwrap().contains("immutable"));
    let png = res.bytes().await.unwrap();
    let img = image::load_from_memory(&png).unwrap();
    assert_eq!((img.width(), img.height()), (160, 120));
    // Not blank: the planet covers the middle, space the corner.
    let rgba = img.to_rgba8();
    assert_ne!(rgba.get_pixel(80, 60), rgba.get_pixel(1, 1));

    let again = a.client.get(a.url(&format!("/v1/planets/{id}/render.png?{SHOT}"))).header("if-none-match", &tag);
    assert_eq!(again.send().await.unwrap().status(), 304);

    let jpg = a.get(&format!("/v1/planets/{id}/render.jpg?{SHOT}")).await;
    assert_eq!(jpg.status(), 200);
    assert_eq!(jpg.headers()["content-type"], "image/jpeg");
    let jpg = image::load_from_memory(&jpg.bytes().await.unwrap()).unwrap();
    assert_eq!((jpg.width(), jpg.height()), (160, 120));

    // A second server, adapting on the wgpu compute backend, renders the same bytes from
    // scratch and adapts views to the same mesh.
    let gpu = riverworld::adapt::gpu::Backend::Gpu;
    let b = start(riverworld::server::Config { adapt_backend: gpu, ..config(&scratch("render-b")) }).await;
    assert_eq!(planet(&b).await, id);
    let other = b.get(&format!("/v1/planets/{id}/render.png?{SHOT}")).await.bytes().await.unwrap();
    assert!(other == png, "renders differ between servers");
    let view = format!("/v1/planets/{id}/view.glb?{SHOT}");
    let (va, vb) = (a.get(&view).await, b.get(&view).await);
    assert_eq!((va.status().as_u16(), vb.status().as_u16()), (200, 200));
    assert!(va.bytes().await.unwrap() == vb.bytes().await.unwrap(), "views differ between backends");

    // Concurrent different cameras queue on the one device and all succeed.
    let shots: Vec<String> = (0..4)
        .map(|i| format!("eye=7e6,{},3e6&target=0,0,0&width=96&height=64&max_faces=20000", i * 500_000))
        .collect();
    let answers = futures::future::join_all(shots.iter().map(|q| {
        let (client, url) = (b.client.clone(), b.url(&format!("/v1/planets/{id}/render.png?{q}")));
        async move {
            let res = client.get(url).send().await.unwrap();
            (res.status().as_u16(), res.bytes().await.unwrap())
        }
    }))
    .await;
    for (status, body) in answers {
        assert_eq!(status, 200);
        assert_eq!(image::load_from_memory(&body).unwrap().width(), 96);
    }
    a.stop().await;
    b.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bad_cameras_sizes_and_keys_are_refused() {
    let s = start(riverworld::server::Config { max_render_pixels: 640 * 480, ..config(&scratch("render-bad")) }).await;
    let id = planet(&s).await;
    let base = "eye=7e6,0,3e6&target=0,0,0";
    for (query, code, field) in [
        ("width=0&height=10", "invalid_camera", "width"),
        ("width=8193&height=10", "invalid_camera", "width"),
        ("width=10&height=0", "invalid_camera", "height"),
        ("width=641&height=480", "too_large", "width"),
        ("sun=0,0,0", "invalid_camera", "sun"),
        ("sun=1,nan,0", "invalid_camera", "sun"),
        ("fov=0", "invalid_camera", "fov"),
        ("max_faces=0", "invalid_parameter", "max_faces"),
        // Below the base mesh.
        ("width=64&height=48&max_faces=10", "invalid_parameter", "max_faces"),
        ("zoom=2", "unknown_parameter", "zoom"),
    ] {
        let res = s.get(&format!("/v1/planets/{id}/render.png?{base}&{query}")).await;
        let err = expect_error(res, 422, code).await;
        assert_eq!(err["field"], field, "{query}");
    }
    let res = s.get(&format!("/v1/planets/{id}/render.png?eye=1,0,0&target=0,0,0")).await;
    expect_error(res, 422, "invalid_camera").await;
    let res = s.get(&format!("/v1/planets/ffffffffffffffff/render.png?{SHOT}")).await;
    expect_error(res, 404, "not_found").await;
    // Still serving.
    assert_eq!(s.get(&format!("/v1/planets/{id}/render.png?{SHOT}")).await.status(), 200);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn without_an_adapter_renders_answer_503_and_the_rest_works() {
    let dir = scratch("render-none");
    // A backend this platform does not have: wgpu finds no adapter.
    let p = spawn_server(&dir, &[], &[("WGPU_BACKEND", "metal")]);
    let res = p
        .client
        .post(p.url("/v1/planets"))
        .header("content-type", "application/json")
        .body(format!(r#"{{"seed": 5, "params": {FAST}}}"#))
        .send()
        .await
        .unwrap();
    assert_eq!(res.status(), 202);
    let id = res.json::<serde_json::Value>().await.unwrap()["id"].as_str().unwrap().to_string();
    p.wait_ready(&id).await;
    let err = expect_error(p.get(&format!("/v1/planets/{id}/render.png?{SHOT}")).await, 503, "no_renderer").await;
    assert!(err["message"].as_str().unwrap().contains("adapter"), "{err}");
    assert_eq!(p.get(&format!("/v1/planets/{id}/view.glb?{CAMERA}")).await.status(), 200);
    assert_eq!(p.get("/healthz").await.status(), 200);
    assert!(p.log().contains("render.png and render.jpg will answer 503"), "{}", p.log());
}
