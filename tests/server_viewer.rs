//! The web viewer: the page at `/` and `/planets/{id}` and its embedded script.

mod server_common;

use server_common::*;

fn header(res: &reqwest::Response, name: &str) -> String {
    res.headers().get(name).map(|v| v.to_str().unwrap().to_string()).unwrap_or_default()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_page_and_its_script_are_served() {
    let s = start(config(&scratch("viewer"))).await;
    let hash = riverworld::server::viewer::VIEWER_JS_HASH.as_str();

    let res = s.get("/").await;
    assert_eq!(res.status(), 200);
    assert_eq!(header(&res, "content-type"), "text/html; charset=utf-8");
    assert_eq!(header(&res, "cache-control"), "no-cache");
    let html = res.text().await.unwrap();
    let tag = format!(r#"<script type="module" src="/assets/viewer.js?v={hash}"></script>"#);
    assert!(html.contains(&tag), "no {tag} in the page");
    assert!(!html.contains("http://") && !html.contains("https://"), "the page loads nothing from elsewhere");

    // A planet's page is the same page; malformed ids answer the JSON 404.
    let res = s.get("/planets/0123456789abcdef").await;
    assert_eq!(res.status(), 200);
    assert_eq!(res.text().await.unwrap(), html);
    expect_error(s.get("/planets/Earth").await, 404, "not_found").await;

    // The versioned script is immutable; the bare name must be revalidated.
    let res = s.get(&format!("/assets/viewer.js?v={hash}")).await;
    assert_eq!(res.status(), 200);
    assert_eq!(header(&res, "content-type"), "application/javascript; charset=utf-8");
    assert_eq!(header(&res, "cache-control"), "public, max-age=31536000, immutable");
    let etag = header(&res, "etag");
    assert_eq!(etag, format!("\"{hash}\""));
    let body = res.bytes().await.unwrap();
    assert_eq!(&body[..], riverworld::server::viewer::VIEWER_JS);

    let res = s.get("/assets/viewer.js").await;
    assert_eq!(res.status(), 200);
    assert_eq!(header(&res, "cache-control"), "no-cache");
    let res = s.client.get(s.url("/assets/viewer.js")).header("if-none-match", &etag).send().await.unwrap();
    assert_eq!(res.status(), 304);
    assert!(res.bytes().await.unwrap().is_empty());

    // Compressed on request.
    let res =
        s.client.get(s.url(&format!("/assets/viewer.js?v={hash}"))).header("accept-encoding", "gzip").send().await;
    assert_eq!(header(&res.unwrap(), "content-encoding"), "gzip");
    s.stop().await;
}
