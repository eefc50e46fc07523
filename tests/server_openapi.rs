//! `openapi.yaml` against the running service: every documented path and method is requested,
//! and the status and content type of each answer must be among the documented ones.

mod server_common;

use serde_json::Value;
use server_common::*;

/// Follows a local `$ref` (`#/components/...`).
fn resolve<'a>(doc: &'a Value, v: &'a Value) -> &'a Value {
    match v.get("$ref").and_then(Value::as_str) {
        Some(r) => {
            let target = doc.pointer(r.trim_start_matches('#')).unwrap_or_else(|| panic!("dangling $ref {r}"));
            resolve(doc, target)
        }
        None => v,
    }
}

/// The query from the query parameters' examples (every required one has one).
fn example_query(doc: &Value, op: &Value) -> String {
    let params = op["parameters"].as_array().cloned().unwrap_or_default();
    let mut pairs = Vec::new();
    for p in &params {
        let p = resolve(doc, p);
        if p["in"] != "query" {
            continue;
        }
        let ex = match &p["example"] {
            Value::String(s) => s.clone(),
            Value::Number(n) => n.to_string(),
            _ if p["required"] == true => panic!("required {} has no example", p["name"]),
            _ => continue,
        };
        pairs.push(format!("{}={ex}", p["name"].as_str().unwrap()));
    }
    pairs.join("&")
}

/// `path` with every path parameter but `{id}` replaced by its example.
fn fill_path(doc: &Value, op: &Value, path: &str) -> String {
    let mut out = path.to_string();
    for p in op["parameters"].as_array().into_iter().flatten() {
        let p = resolve(doc, p);
        if p["in"] == "path" && p["name"] != "id" {
            let ex = p["example"].as_str().unwrap_or_else(|| panic!("path parameter {} has no example", p["name"]));
            out = out.replace(&format!("{{{}}}", p["name"].as_str().unwrap()), ex);
        }
    }
    out
}

async fn check(doc: &Value, s: &TestServer, path: &str, method: &str, op: &Value, res: reqwest::Response) {
    let status = res.status().as_u16();
    let responses = op["responses"].as_object().unwrap();
    let documented = responses.get(&status.to_string()).unwrap_or_else(|| {
        panic!("{method} {path}: status {status} is not documented (documented: {:?})", responses.keys())
    });
    let documented = resolve(doc, documented);
    let ctype = res.headers().get("content-type").map(|v| v.to_str().unwrap().to_string());
    let body = res.bytes().await.unwrap();
    match documented.get("content").and_then(Value::as_object) {
        Some(content) => {
            let ctype = ctype.unwrap_or_else(|| panic!("{method} {path} {status}: no content type"));
            let mime = ctype.split(';').next().unwrap().trim();
            assert!(content.contains_key(mime), "{method} {path} {status}: {mime} not in {:?}", content.keys());
            if mime == "application/json" && status >= 400 {
                let v: Value = serde_json::from_slice(&body).unwrap();
                assert!(v["error"]["code"].is_string(), "{method} {path}: {v}");
            }
        }
        None => assert!(body.is_empty(), "{method} {path} {status}: undocumented body"),
    }
    let _ = s;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_documented_operation_answers_as_documented() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/openapi.yaml")).unwrap();
    let doc: Value = serde_yaml::from_str(&text).unwrap();
    assert!(doc["openapi"].as_str().unwrap().starts_with("3.1"));
    let s = start(config(&scratch("openapi"))).await;
    // The served document is the file.
    assert_eq!(s.get("/openapi.yaml").await.text().await.unwrap(), text);

    let id = s.post_json(r#"{"seed": 21, "params": {"base_faces": 500}}"#).await.json::<Value>().await.unwrap()["id"]
        .as_str()
        .unwrap()
        .to_string();
    s.wait_ready(&id).await;
    let doomed = s.post_json(r#"{"seed": 22, "params": {"base_faces": 200}}"#).await.json::<Value>().await.unwrap()
        ["id"]
        .as_str()
        .unwrap()
        .to_string();

    let mut operations = 0;
    for (path, item) in doc["paths"].as_object().unwrap() {
        for (method, op) in item.as_object().unwrap() {
            if !["get", "post", "delete", "put", "patch"].contains(&method.as_str()) {
                continue;
            }
            operations += 1;
            let planet = if method == "delete" { &doomed } else { &id };
            let mut merged = op.clone();
            let mut params = item["parameters"].as_array().cloned().unwrap_or_default();
            params.extend(op["parameters"].as_array().cloned().unwrap_or_default());
            merged["parameters"] = Value::Array(params);
            let query = example_query(&doc, &merged);
            let path = &fill_path(&doc, &merged, path);
            let concrete = path.replace("{id}", planet);
            let url = if query.is_empty() { s.url(&concrete) } else { s.url(&format!("{concrete}?{query}")) };
            let m = reqwest::Method::from_bytes(method.to_uppercase().as_bytes()).unwrap();
            let mut req = s.client.request(m.clone(), &url);
            if method == "post" {
                req = req
                    .header("content-type", "application/json")
                    .body(r#"{"seed": 23, "params": {"base_faces": 200}}"#);
            }
            check(&doc, &s, path, method, op, req.send().await.unwrap()).await;
            // Unknown planets answer a documented 404.
            if path.contains("{id}") {
                let unknown = path.replace("{id}", "ffffffffffffffff");
                let url = if query.is_empty() { s.url(&unknown) } else { s.url(&format!("{unknown}?{query}")) };
                check(&doc, &s, path, method, op, s.client.request(m, &url).send().await.unwrap()).await;
            }
        }
    }
    assert_eq!(operations, 27);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn refused_writes_answer_as_documented() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/openapi.yaml")).unwrap();
    let doc: Value = serde_yaml::from_str(&text).unwrap();
    let token = riverworld::server::auth::ApiToken::new("documented-token").unwrap();
    let s = start(riverworld::server::Config { api_token: Some(token), ..config(&scratch("openapi-auth")) }).await;
    let mut writes = 0;
    for (path, item) in doc["paths"].as_object().unwrap() {
        for (method, op) in item.as_object().unwrap() {
            if !["post", "delete"].contains(&method.as_str()) {
                continue;
            }
            writes += 1;
            assert!(op["security"].as_array().is_some_and(|s| !s.is_empty()), "{method} {path}: no security");
            let url = s.url(&path.replace("{id}", "0123456789abcdef"));
            let m = reqwest::Method::from_bytes(method.to_uppercase().as_bytes()).unwrap();
            let res = s.client.request(m.clone(), &url).send().await.unwrap();
            assert_eq!(res.status().as_u16(), 401);
            check(&doc, &s, path, method, op, res).await;
            let res = s.client.request(m, &url).bearer_auth("wrong").send().await.unwrap();
            assert_eq!(res.status().as_u16(), 403);
            check(&doc, &s, path, method, op, res).await;
        }
    }
    assert_eq!(writes, 2);
    s.stop().await;
}
