//! Access control: when the server has an API token, requests that change state (`POST` and
//! `DELETE`) must carry `Authorization: Bearer <token>`; reads stay public.
//!
//! Only the token's SHA-256 digest is kept, and a presented token is compared by digest in
//! constant time, so neither the comparison's duration nor its length tells anything about the
//! token. The token itself is never logged or printed (its `Debug` is redacted).

use super::error::ApiError;
use super::state::AppState;
use axum::body::Body;
use axum::extract::State;
use axum::http::{header, HeaderMap, HeaderValue, Method, Request, StatusCode};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use sha2::{Digest, Sha256};
use std::sync::Arc;

/// The challenge sent with every 401.
pub const CHALLENGE: &str = "Bearer realm=\"riverworld\"";

/// A configured API token, held as its SHA-256 digest.
#[derive(Clone, PartialEq, Eq)]
pub struct ApiToken {
    digest: [u8; 32],
}

impl std::fmt::Debug for ApiToken {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("ApiToken(<redacted>)")
    }
}

fn digest(bytes: &[u8]) -> [u8; 32] {
    Sha256::digest(bytes).into()
}

/// Whether two digests are equal, looking at every byte whatever the first difference.
fn same_digest(a: &[u8; 32], b: &[u8; 32]) -> bool {
    let diff = a.iter().zip(b).fold(0u8, |acc, (x, y)| acc | (x ^ y));
    std::hint::black_box(diff) == 0
}

impl ApiToken {
    /// A token of visible ASCII characters (no spaces), as `Authorization: Bearer` can carry it.
    pub fn new(token: &str) -> Result<ApiToken, String> {
        if token.is_empty() {
            return Err("the API token is empty".into());
        }
        if !token.bytes().all(|b| b.is_ascii_graphic()) {
            return Err("the API token must be visible ASCII characters without spaces".into());
        }
        Ok(ApiToken { digest: digest(token.as_bytes()) })
    }

    /// Whether `presented` is the token (constant time over the digests).
    pub fn accepts(&self, presented: &[u8]) -> bool {
        same_digest(&self.digest, &digest(presented))
    }
}

/// The token of `Authorization: Bearer <token>`; None when the header is missing, repeated or
/// not of that form.
fn bearer(headers: &HeaderMap) -> Option<&[u8]> {
    let mut values = headers.get_all(header::AUTHORIZATION).iter();
    let value = values.next()?;
    if values.next().is_some() {
        return None;
    }
    let v = value.as_bytes();
    let (scheme, rest) = v.split_at(v.iter().position(|&b| b == b' ')?);
    if !scheme.eq_ignore_ascii_case(b"bearer") {
        return None;
    }
    let token = rest.trim_ascii();
    (!token.is_empty() && token.iter().all(u8::is_ascii_graphic)).then_some(token)
}

/// Middleware: `POST` and `DELETE` need the token when one is configured; 401 with
/// `WWW-Authenticate: Bearer` without a usable `Authorization` header, 403 for a wrong token.
pub async fn require_token(State(state): State<Arc<AppState>>, req: Request<Body>, next: Next) -> Response {
    let Some(token) = &state.config.api_token else {
        return next.run(req).await;
    };
    if !matches!(*req.method(), Method::POST | Method::DELETE) {
        return next.run(req).await;
    }
    match bearer(req.headers()) {
        Some(presented) if token.accepts(presented) => next.run(req).await,
        Some(_) => {
            ApiError::new(StatusCode::FORBIDDEN, "forbidden", "the bearer token is not accepted").into_response()
        }
        None => {
            let err = ApiError::new(
                StatusCode::UNAUTHORIZED,
                "unauthorized",
                "this request needs an Authorization: Bearer <token> header",
            );
            let mut res = err.field("Authorization").into_response();
            res.headers_mut().insert(header::WWW_AUTHENTICATE, HeaderValue::from_static(CHALLENGE));
            res
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn headers(values: &[&str]) -> HeaderMap {
        let mut h = HeaderMap::new();
        for v in values {
            h.append(header::AUTHORIZATION, HeaderValue::from_str(v).unwrap());
        }
        h
    }

    #[test]
    fn accepts_only_the_token() {
        let t = ApiToken::new("s3cret-token").unwrap();
        assert!(t.accepts(b"s3cret-token"));
        for wrong in [&b"s3cret-toke"[..], b"s3cret-tokenn", b"S3cret-token", b""] {
            assert!(!t.accepts(wrong), "{wrong:?}");
        }
        assert!(ApiToken::new("").is_err());
        assert!(ApiToken::new("two words").is_err());
        assert_eq!(format!("{t:?}"), "ApiToken(<redacted>)");
    }

    #[test]
    fn reads_bearer_headers() {
        assert_eq!(bearer(&headers(&["Bearer abc"])), Some(&b"abc"[..]));
        assert_eq!(bearer(&headers(&["bearer   abc "])), Some(&b"abc"[..]));
        for bad in
            [&["Basic abc"][..], &["Bearer"], &["Bearer "], &["Bearerabc"], &["Bearer a b"], &["Bearer a", "Bearer a"]]
        {
            assert_eq!(bearer(&headers(bad)), None, "{bad:?}");
        }
        assert_eq!(bearer(&HeaderMap::new()), None);
    }
}
