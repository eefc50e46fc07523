//! The web viewer (`GET /` and `GET /planets/{id}`): one HTML page and one JavaScript bundle, built
//! from `web/` (three.js and 3d-tiles-renderer bundled by esbuild, see `web/package.json`) and
//! embedded in the binary, so the server needs no files and the page no CDN.
//!
//! The page names the bundle `/assets/viewer.js?v={hash}` (the first 16 hex characters of its
//! SHA-256): asked for with the current hash, the bundle is immutable for a year; without it (or
//! with another) it must be revalidated.

use super::error::ApiError;
use axum::extract::{Path, Query};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use sha2::{Digest, Sha256};
use std::collections::HashMap;
use std::sync::LazyLock;

/// The page, with `{{VIEWER_JS}}` where the bundle's URL goes.
const PAGE: &str = include_str!("../../web/index.html");
/// The bundle (`npm run build` in `web/`).
pub const VIEWER_JS: &[u8] = include_bytes!("../../web/dist/viewer.js");

/// The first 16 hex characters of the bundle's SHA-256.
pub static VIEWER_JS_HASH: LazyLock<String> =
    LazyLock::new(|| Sha256::digest(VIEWER_JS).iter().take(8).map(|b| format!("{b:02x}")).collect());

static PAGE_HTML: LazyLock<String> =
    LazyLock::new(|| PAGE.replace("{{VIEWER_JS}}", &format!("/assets/viewer.js?v={}", *VIEWER_JS_HASH)));

fn page() -> Response {
    let mut res = PAGE_HTML.as_str().into_response();
    let h = res.headers_mut();
    h.insert(header::CONTENT_TYPE, HeaderValue::from_static("text/html; charset=utf-8"));
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-cache"));
    h.insert(header::X_CONTENT_TYPE_OPTIONS, HeaderValue::from_static("nosniff"));
    res
}

/// `GET /`: the viewer, opening the built-in planet.
pub async fn index() -> Response {
    page()
}

/// `GET /planets/{id}`: the viewer, opening planet `id` (which the page polls until ready).
pub async fn planet(Path(id): Path<String>) -> Result<Response, ApiError> {
    if !super::valid_id(&id) {
        return Err(ApiError::not_found(&format!("planet {id:?}")));
    }
    Ok(page())
}

/// `GET /assets/viewer.js[?v=HASH]`.
pub async fn script(Query(query): Query<HashMap<String, String>>, headers: HeaderMap) -> Response {
    let etag = format!("\"{}\"", *VIEWER_JS_HASH);
    let versioned = query.get("v").is_some_and(|v| *v == *VIEWER_JS_HASH);
    let cache = if versioned { "public, max-age=31536000, immutable" } else { "no-cache" };
    let matches = headers
        .get(header::IF_NONE_MATCH)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.split(',').any(|t| t.trim() == etag || t.trim() == "*"));
    let mut res = if matches { StatusCode::NOT_MODIFIED.into_response() } else { VIEWER_JS.into_response() };
    let h = res.headers_mut();
    if !matches {
        h.insert(header::CONTENT_TYPE, HeaderValue::from_static("application/javascript; charset=utf-8"));
    }
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static(cache));
    h.insert(header::ETAG, HeaderValue::from_str(&etag).expect("hex etag"));
    h.insert(header::X_CONTENT_TYPE_OPTIONS, HeaderValue::from_static("nosniff"));
    res
}
