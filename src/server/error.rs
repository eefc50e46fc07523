//! The one error shape of the HTTP API: `{"error": {"code", "message", "field"?}}`, always sent
//! with `Cache-Control: no-store`, plus a middleware that gives the same shape to the plain
//! answers of the routing and limit layers (404, 405, 413, timeouts).

use axum::body::Body;
use axum::http::{header, HeaderValue, Request, StatusCode};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use serde::Serialize;

/// An error answer: status, stable snake_case code, message and the request field at fault.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ApiError {
    #[serde(skip)]
    pub status: StatusCode,
    pub code: String,
    pub message: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub field: Option<String>,
    /// Seconds for `Retry-After`.
    #[serde(skip)]
    pub retry_after: Option<u32>,
}

impl ApiError {
    pub fn new(status: StatusCode, code: &str, message: impl Into<String>) -> ApiError {
        ApiError { status, code: code.to_string(), message: message.into(), field: None, retry_after: None }
    }

    /// The same error, naming the request field at fault.
    pub fn field(mut self, field: impl Into<String>) -> ApiError {
        self.field = Some(field.into());
        self
    }

    /// The same error, asking the client to retry after `secs` seconds.
    pub fn retry_after(mut self, secs: u32) -> ApiError {
        self.retry_after = Some(secs);
        self
    }

    pub fn not_found(what: &str) -> ApiError {
        ApiError::new(StatusCode::NOT_FOUND, "not_found", format!("{what} not found"))
    }

    pub fn unprocessable(code: &str, field: impl Into<String>, message: impl Into<String>) -> ApiError {
        ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, code, message).field(field)
    }

    pub fn internal(message: impl Into<String>) -> ApiError {
        ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, "internal", message)
    }

    /// A map the decoder refused: 415 for bytes that are no accepted image format, 413 for an
    /// upload over the map size limit, 422 otherwise; code and field come from the map error.
    pub fn from_map(e: &crate::maps::MapError) -> ApiError {
        let status = match e.code() {
            "unsupported_format" => StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "file_too_large" => StatusCode::PAYLOAD_TOO_LARGE,
            _ => StatusCode::UNPROCESSABLE_ENTITY,
        };
        ApiError::new(status, e.code(), e.to_string()).field(e.field())
    }

    /// A parameter outside its range or a body that does not parse.
    pub fn from_params(e: &crate::params::ParamError) -> ApiError {
        ApiError::unprocessable("invalid_params", e.field.clone(), e.message.clone())
    }

    /// The JSON body of this error; the message and field are cut to [`MAX_MESSAGE_CHARS`] and
    /// 200 characters, so that no input comes back whole, whatever its size.
    pub fn body(&self) -> serde_json::Value {
        let cut = ApiError {
            message: crate::query::cut_to(&self.message, MAX_MESSAGE_CHARS),
            field: self.field.as_deref().map(crate::query::cut),
            ..self.clone()
        };
        serde_json::json!({ "error": cut })
    }
}

impl std::fmt::Display for ApiError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} {}: {}", self.status.as_u16(), self.code, self.message)
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        let body = serde_json::to_vec(&self.body()).expect("error serialises");
        let mut res = (self.status, body).into_response();
        let h = res.headers_mut();
        h.insert(header::CONTENT_TYPE, HeaderValue::from_static("application/json"));
        h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
        if let Some(secs) = self.retry_after {
            h.insert(header::RETRY_AFTER, HeaderValue::from(secs));
        }
        res
    }
}

/// Longest error message sent, in characters (an echoed input is cut to fit).
pub const MAX_MESSAGE_CHARS: usize = 600;

/// Longest request target (path and query) the server reads, bytes; hyper itself refuses
/// targets from 64 KiB with an empty 414.
pub const MAX_TARGET_BYTES: usize = 8192;
/// Most header fields, and most bytes of header names and values together, a request may
/// carry; hyper itself refuses more than 100 fields or about 400 KiB with an empty 431.
pub const MAX_HEADERS: usize = 64;
pub const MAX_HEADER_BYTES: usize = 16384;

/// Refuses, in the API's error shape, request heads over the server's own limits, which lie
/// below the HTTP layer's (whose refusals have no body): 414 `uri_too_long`, 431
/// `headers_too_large`.
pub async fn head_limits(req: Request<Body>, next: Next) -> Response {
    let target = req.uri().path_and_query().map_or(0, |p| p.as_str().len());
    if target > MAX_TARGET_BYTES {
        let message = format!("the request target is {target} bytes; this server reads at most {MAX_TARGET_BYTES}");
        return ApiError::new(StatusCode::URI_TOO_LONG, "uri_too_long", message).into_response();
    }
    let fields = req.headers().len();
    let bytes: usize = req.headers().iter().map(|(k, v)| k.as_str().len() + v.len()).sum();
    if fields > MAX_HEADERS || bytes > MAX_HEADER_BYTES {
        let message = format!(
            "{fields} header fields of {bytes} bytes; this server reads at most {MAX_HEADERS} fields of \
             {MAX_HEADER_BYTES} bytes"
        );
        return ApiError::new(StatusCode::REQUEST_HEADER_FIELDS_TOO_LARGE, "headers_too_large", message)
            .into_response();
    }
    next.run(req).await
}

/// Code and message for an error status that reached the client without a JSON body.
fn plain_status(status: StatusCode) -> (&'static str, &'static str) {
    match status {
        StatusCode::NOT_FOUND => ("not_found", "no such resource"),
        StatusCode::METHOD_NOT_ALLOWED => ("method_not_allowed", "method not allowed on this resource"),
        StatusCode::PAYLOAD_TOO_LARGE => ("body_too_large", "the request body is over the size limit"),
        StatusCode::UNSUPPORTED_MEDIA_TYPE => ("unsupported_media_type", "unsupported content type"),
        StatusCode::REQUEST_TIMEOUT | StatusCode::SERVICE_UNAVAILABLE => {
            ("timeout", "the request took longer than the server allows")
        }
        s if s.is_client_error() => ("bad_request", "the request could not be read"),
        _ => ("internal", "internal server error"),
    }
}

/// Rewrites error answers that are not JSON (from routing, extractors and tower layers) into the
/// API's error shape, keeping their status and headers such as `Allow`.
pub async fn json_errors(req: Request<Body>, next: Next) -> Response {
    let res = next.run(req).await;
    let status = res.status();
    if !(status.is_client_error() || status.is_server_error()) {
        return res;
    }
    let is_json = res
        .headers()
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.starts_with("application/json"));
    if is_json {
        return res;
    }
    let (mut parts, body) = res.into_parts();
    // Keep a short plain-text message from the layer that answered, when there is one.
    let text = axum::body::to_bytes(body, 4096).await.ok().and_then(|b| String::from_utf8(b.to_vec()).ok());
    let (code, default) = plain_status(status);
    let message = text.filter(|t| !t.trim().is_empty()).unwrap_or_else(|| default.to_string());
    let err = ApiError::new(status, code, message.trim().to_string());
    let fresh = err.into_response();
    parts.headers.remove(header::CONTENT_LENGTH);
    for name in [header::CONTENT_TYPE, header::CACHE_CONTROL] {
        if let Some(v) = fresh.headers().get(&name) {
            parts.headers.insert(name, v.clone());
        }
    }
    Response::from_parts(parts, fresh.into_body())
}
