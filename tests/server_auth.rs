//! Access control: with an API token, POST and DELETE need `Authorization: Bearer <token>`
//! (401 without a usable header, 403 for a wrong token), reads stay public, and the token never
//! shows in the logs.

mod server_common;

use riverworld::server::auth::ApiToken;
use riverworld::server::Config;
use serde_json::Value;
use server_common::*;

const TOKEN: &str = "rw-test-token-5f1c0b9e";
const BODY: &str = r#"{"seed": 31, "params": {"base_faces": 200}}"#;

fn post(client: &reqwest::Client, url: String) -> reqwest::RequestBuilder {
    client.post(url).header("content-type", "application/json").body(BODY)
}

async fn expect_401(res: reqwest::Response) {
    assert_eq!(res.headers()["www-authenticate"], "Bearer realm=\"riverworld\"");
    let err = expect_error(res, 401, "unauthorized").await;
    assert_eq!(err["field"], "Authorization");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn writes_need_the_token_and_reads_stay_public() {
    let dir = scratch("auth");
    let cfg = Config { api_token: Some(ApiToken::new(TOKEN).unwrap()), ..config(&dir) };
    let s = start(cfg).await;
    let planets = s.url("/v1/planets");

    for header in [None, Some("Basic cnc6dG9rZW4="), Some("Bearer"), Some("Bearer "), Some(TOKEN), Some("Bearer a b")] {
        let mut req = post(&s.client, planets.clone());
        if let Some(h) = header {
            req = req.header("authorization", h);
        }
        expect_401(req.send().await.unwrap()).await;
    }
    for wrong in ["x", "rw-test-token-5f1c0b9", "rw-test-token-5f1c0b9e0", "RW-TEST-TOKEN-5F1C0B9E"] {
        let res = post(&s.client, planets.clone()).bearer_auth(wrong).send().await.unwrap();
        assert!(!res.headers().contains_key("www-authenticate"));
        expect_error(res, 403, "forbidden").await;
    }
    // Nothing was stored by the refused requests.
    assert!(!dir.join("planets").exists() || std::fs::read_dir(dir.join("planets")).unwrap().count() == 0);

    let res = post(&s.client, planets.clone()).header("authorization", format!("bearer  {TOKEN}")).send().await;
    let res = res.unwrap();
    assert_eq!(res.status().as_u16(), 202);
    let id = res.json::<Value>().await.unwrap()["id"].as_str().unwrap().to_string();
    // Reads need nothing.
    s.wait_ready(&id).await;
    assert_eq!(s.get("/v1/planets").await.status().as_u16(), 200);
    assert_eq!(s.get(&format!("/v1/planets/{id}/rivers.geojson")).await.status().as_u16(), 200);
    assert_eq!(s.get("/healthz").await.status().as_u16(), 200);

    let doomed = s.url(&format!("/v1/planets/{id}"));
    expect_401(s.client.delete(&doomed).send().await.unwrap()).await;
    expect_error(s.client.delete(&doomed).bearer_auth("nope").send().await.unwrap(), 403, "forbidden").await;
    assert_eq!(s.get(&format!("/v1/planets/{id}")).await.status().as_u16(), 200);
    assert_eq!(s.client.delete(&doomed).bearer_auth(TOKEN).send().await.unwrap().status().as_u16(), 204);
    assert_eq!(s.get(&format!("/v1/planets/{id}")).await.status().as_u16(), 404);

    // A CORS preflight for a write passes without a token and allows the header.
    let res = s
        .client
        .request(reqwest::Method::OPTIONS, &planets)
        .header("origin", "https://example.org")
        .header("access-control-request-method", "POST")
        .header("access-control-request-headers", "authorization,content-type")
        .send()
        .await
        .unwrap();
    assert_eq!(res.status().as_u16(), 200);
    let allowed = res.headers()["access-control-allow-headers"].to_str().unwrap().to_ascii_lowercase();
    assert!(allowed.contains("authorization"), "{allowed}");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn without_a_token_writes_are_open() {
    let s = start(config(&scratch("auth-open"))).await;
    let res = post(&s.client, s.url("/v1/planets")).bearer_auth("anything").send().await.unwrap();
    assert_eq!(res.status().as_u16(), 202);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_command_takes_the_token_from_the_environment_and_never_logs_it() {
    let dir = scratch("auth-process");
    let verbose = [("RUST_LOG", "trace"), ("RIVERWORLD_API_TOKEN", TOKEN)];
    let p = spawn_server(&dir, &[], &verbose);
    expect_401(post(&p.client, p.url("/v1/planets")).send().await.unwrap()).await;
    expect_error(post(&p.client, p.url("/v1/planets")).bearer_auth("wrong").send().await.unwrap(), 403, "forbidden")
        .await;
    let res = post(&p.client, p.url("/v1/planets")).bearer_auth(TOKEN).send().await.unwrap();
    assert_eq!(res.status().as_u16(), 202);
    let id = res.json::<Value>().await.unwrap()["id"].as_str().unwrap().to_string();
    p.wait_ready(&id).await;
    let log = p.log();
    assert!(log.contains("POST"), "the trace log should show requests: {log}");
    assert!(!log.contains(TOKEN) && !log.contains("5f1c0b9e"), "the token is in the log:\n{log}");
    assert!(!log.contains("no API token"), "{log}");
    p.kill9();

    // --api-token works too; without any token the server warns at start.
    let p = spawn_server(&dir, &["--api-token", TOKEN], &[]);
    expect_401(post(&p.client, p.url("/v1/planets")).send().await.unwrap()).await;
    p.kill9();
    let p = spawn_server(&dir, &[], &[]);
    assert!(p.log().contains("no API token"), "{}", p.log());
    p.kill9();

    // An empty token is refused at start rather than silently leaving the server open.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_riverworld"))
        .args(["serve", "--addr", "127.0.0.1:0", "--no-default-planet", "--data"])
        .arg(&dir)
        .env("RIVERWORLD_API_TOKEN", "")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("API token is empty"));

    let help = std::process::Command::new(env!("CARGO_BIN_EXE_riverworld")).args(["serve", "--help"]).output().unwrap();
    let help = String::from_utf8(help.stdout).unwrap();
    for flag in ["--api-token", "RIVERWORLD_API_TOKEN", "--render-permits", "--render-queue", "--max-raster-width"] {
        assert!(help.contains(flag), "{flag} missing from --help:\n{help}");
    }
    assert!(help.contains("--max-map-mpixels"), "{help}");
}
