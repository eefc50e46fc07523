//! `GET /v1/planets/{id}/render.png` and `render.jpg`: a snapshot of the planet adapted to a
//! camera, drawn by the process-wide wgpu renderer ([`crate::render::shared`]), cached and
//! immutable like the other derived files (`resources.rs`).
//!
//! Where no graphics adapter exists the service still runs and these routes answer 503
//! `no_renderer` with the reason; a device failure mid-frame answers 503 `render_failed`.
//! Requests queue safely on the one device (the renderer draws one frame at a time) behind the
//! heavy-work permits.

use super::error::ApiError;
use super::resources::{
    budget_query, cached, cost, unknown_key, view_budget, whole_number_in, Derived, BYTES_PER_PIXEL,
};
use super::state::AppState;
use crate::render::{self, ImageFormat, RenderError, Shot};
use axum::extract::{Path, RawQuery, State};
use axum::http::{HeaderMap, StatusCode};
use axum::response::Response;
use std::sync::Arc;

type Answer = Result<Response, ApiError>;

/// The query keys a snapshot accepts.
const KEYS: &str = "eye, target, up, fov, width, height, land_px, water_px, sun, max_faces";

fn unavailable(e: &RenderError) -> ApiError {
    let code = match e {
        RenderError::NoAdapter(_) => "no_renderer",
        RenderError::TooLarge(_) => return ApiError::unprocessable("too_large", "width", e.to_string()),
        RenderError::Device(_) => "render_failed",
    };
    ApiError::new(StatusCode::SERVICE_UNAVAILABLE, code, e.to_string())
}

async fn snapshot(
    format: ImageFormat,
    state: Arc<AppState>,
    id: String,
    query: Option<String>,
    h: HeaderMap,
) -> Answer {
    let entry = state.lookup(&id).await?.ok_or_else(|| ApiError::not_found(&format!("planet {id:?}")))?;
    let params = entry.input.params.clone();
    let (shot, rest) = Shot::parse_query(query.as_deref().unwrap_or(""), params.radius_m)
        .map_err(|e| ApiError::unprocessable("invalid_camera", e.field, e.message))?;
    let cap = state.config.max_faces_cap;
    let mut max_faces = None;
    for (k, v) in rest {
        if k != "max_faces" {
            return Err(unknown_key(&k, KEYS));
        }
        max_faces = Some(whole_number_in("max_faces", &v, 1, cap)?);
    }
    let pixels = shot.camera.width as u64 * shot.camera.height as u64;
    if pixels > state.config.max_render_pixels {
        return Err(ApiError::unprocessable(
            "too_large",
            "width",
            format!(
                "{}x{} is {pixels} pixels; this server renders at most {}",
                shot.camera.width, shot.camera.height, state.config.max_render_pixels
            ),
        ));
    }
    let renderer = tokio::task::spawn_blocking(render::shared)
        .await
        .map_err(|_| ApiError::internal("starting the renderer failed"))?
        .map_err(|e| unavailable(&e))?;
    let route = match format {
        ImageFormat::Png => "render.png",
        ImageFormat::Jpeg => "render.jpg",
    };
    let norm = budget_query(shot.to_query(), max_faces, cap);
    let derived = Derived {
        route: route.into(),
        norm,
        content_type: format.content_type(),
        cost: cost(pixels * BYTES_PER_PIXEL, Some((max_faces, cap)), false),
    };
    let gpu = state.adaption.clone();
    cached(state, entry, derived, h, move |planet| {
        let budget = view_budget(&planet, max_faces, cap)?;
        let cam = &shot.camera;
        let rgba =
            render::snapshot(renderer, &planet.mesh, &params, &shot, budget, gpu).map_err(|e| unavailable(&e))?;
        Ok(render::encode(&rgba, cam.width, cam.height, format))
    })
    .await
}

/// `GET /v1/planets/{id}/render.png`.
pub async fn png(s: State<Arc<AppState>>, p: Path<String>, q: RawQuery, h: HeaderMap) -> Answer {
    snapshot(ImageFormat::Png, s.0, p.0, q.0, h).await
}

/// `GET /v1/planets/{id}/render.jpg`.
pub async fn jpeg(s: State<Arc<AppState>>, p: Path<String>, q: RawQuery, h: HeaderMap) -> Answer {
    snapshot(ImageFormat::Jpeg, s.0, p.0, q.0, h).await
}

/// Opens the renderer off the runtime and logs what it found (called once at start).
pub async fn announce() {
    match tokio::task::spawn_blocking(render::shared).await {
        Ok(Ok(r)) => tracing::info!("rendering on {}", r.describe()),
        Ok(Err(e)) => tracing::warn!("{e}; render.png and render.jpg will answer 503"),
        Err(_) => tracing::warn!("the renderer could not be started; render.png and render.jpg will answer 503"),
    }
}
