//! `/v1/planets`: create (idempotent: the id names the inputs), list, read and delete planets.

use super::error::ApiError;
use super::input::{self, planet_id};
use super::state::{client_queue_full, queue_full, AppState, Entry, EARTH_ID};
use super::transport::ClientAddr;
use crate::maps::MapLimits;
use axum::body::Body;
use axum::extract::{ConnectInfo, Path, RawQuery, State};
use axum::http::{header, HeaderValue, Request, StatusCode};
use axum::response::{IntoResponse, Response};
use std::net::IpAddr;
use std::sync::Arc;

/// A JSON answer that clients must not cache (records change while a planet builds).
fn json(status: StatusCode, value: &impl serde::Serialize) -> Response {
    let body = serde_json::to_vec(value).expect("record serialises");
    let mut res = (status, body).into_response();
    let h = res.headers_mut();
    h.insert(header::CONTENT_TYPE, HeaderValue::from_static("application/json"));
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    res
}

fn with_location(mut res: Response, id: &str) -> Response {
    let loc = HeaderValue::from_str(&format!("/v1/planets/{id}")).expect("id is a valid header");
    res.headers_mut().insert(header::LOCATION, loc);
    res
}

/// `POST /v1/planets`: 202 with the new record, or 200/202 with the existing one.
pub async fn create(State(state): State<Arc<AppState>>, req: Request<Body>) -> Result<Response, ApiError> {
    let limits = MapLimits { max_bytes: state.config.body_limit, max_pixels: state.config.max_map_pixels };
    let client = client_address(&req, state.config.trust_forwarded_for);
    let new = input::read(req, limits, &state.renders).await?;
    let id = planet_id(&new.input, new.map.as_deref(), new.precipitation.as_deref());
    if let Some(entry) = state.lookup(&id).await? {
        return Ok(existing(&state, &entry));
    }
    admit_size(&new, state.config.max_planet_faces.min(state.config.max_faces_cap))?;
    let ticket = state.clients.take(client).ok_or_else(|| client_queue_full(state.clients.held(client)))?;
    let slot = state.pool.reserve().ok_or_else(queue_full)?;
    state.store.put(&id, &new.input, new.map, new.precipitation).await.map_err(|e| {
        tracing::error!(%id, error = %e, "cannot store planet inputs");
        ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, "storage_error", format!("cannot store the inputs: {e}"))
    })?;
    let entry = {
        let mut planets = state.planets.write().expect("planets lock");
        if let Some(entry) = planets.get(&id).cloned() {
            drop(planets);
            return Ok(existing(&state, &entry));
        }
        let entry = Arc::new(Entry::new(id.clone(), new.input, None));
        planets.insert(id.clone(), Arc::clone(&entry));
        entry
    };
    tracing::info!(%id, "planet accepted");
    state.start_build(&entry, slot, ticket);
    Ok(with_location(json(StatusCode::ACCEPTED, &state.record(&entry)), &id))
}

/// The client's address: the connection's peer, or with `trust_forwarded_for` the last
/// `X-Forwarded-For` entry (the one the proxy in front added) where it parses.
fn client_address(req: &Request<Body>, trust_forwarded_for: bool) -> IpAddr {
    let forwarded = || {
        let last = req.headers().get_all("x-forwarded-for").iter().next_back()?.to_str().ok()?;
        last.rsplit(',').next()?.trim().parse::<IpAddr>().ok()
    };
    let peer = || req.extensions().get::<ConnectInfo<ClientAddr>>().map(|c| c.0 .0.ip());
    trust_forwarded_for.then(forwarded).flatten().or_else(peer).unwrap_or(IpAddr::V6(std::net::Ipv6Addr::UNSPECIFIED))
}

/// 422 `too_large` for a planet whose base mesh would have more faces than `limit` (the
/// server's `--max-planet-faces`, within its `--max-faces-cap`: every view of a planet holds
/// at least its base mesh), naming `map` when the map's refinement is what makes it large.
fn admit_size(new: &input::NewPlanet, limit: usize) -> Result<(), ApiError> {
    if new.estimated_faces <= limit {
        return Ok(());
    }
    let without_map = crate::planet::estimated_faces(&new.input.params, None);
    let field = if new.map.is_some() && without_map <= limit { "map" } else { "params.base_faces" };
    Err(ApiError::unprocessable(
        "too_large",
        field,
        format!(
            "this planet's base mesh would have up to {} faces (estimated from base_faces and the map's size and \
             bounds); this server builds planets of at most {limit} faces: lower base_faces, or send a map with \
             coarser pixels or smaller bounds",
            new.estimated_faces
        ),
    ))
}

/// The answer to a POST of inputs that are known already: 200 when ready (or failed), else 202.
fn existing(state: &Arc<AppState>, entry: &Arc<Entry>) -> Response {
    let _ = state.ensure_build(entry);
    let record = state.record(entry);
    let status = if matches!(record.status, "ready" | "failed") { StatusCode::OK } else { StatusCode::ACCEPTED };
    with_location(json(status, &record), &entry.id)
}

/// `GET /v1/planets`: every planet's record, sorted by id, including planets that another
/// server sharing the store created.
pub async fn list(State(state): State<Arc<AppState>>) -> Result<Response, ApiError> {
    state.sync_with_store().await?;
    let entries: Vec<Arc<Entry>> = state.planets.read().expect("planets lock").values().cloned().collect();
    let records: Vec<_> = entries.iter().map(|e| state.record(e)).collect();
    Ok(json(StatusCode::OK, &serde_json::json!({ "planets": records })))
}

/// `GET /v1/planets/{id}`: the record; starts the build of a planet that is not built.
pub async fn read(
    State(state): State<Arc<AppState>>,
    Path(id): Path<String>,
    RawQuery(query): RawQuery,
) -> Result<Response, ApiError> {
    let entry = state.lookup_confirmed(&id).await?.ok_or_else(|| ApiError::not_found(&format!("planet {id:?}")))?;
    super::resources::no_query(query.as_deref())?;
    // A full queue only delays the build: the next read tries again.
    let _ = state.ensure_build(&entry);
    Ok(json(StatusCode::OK, &state.record(&entry)))
}

/// `DELETE /v1/planets/{id}`: 204; removes the inputs from the store and every cached answer.
pub async fn delete(State(state): State<Arc<AppState>>, Path(id): Path<String>) -> Result<Response, ApiError> {
    if id == EARTH_ID {
        return Err(ApiError::new(
            StatusCode::FORBIDDEN,
            "protected_planet",
            "the built-in planet earth cannot be deleted",
        ));
    }
    let entry = state.lookup(&id).await?.ok_or_else(|| ApiError::not_found(&format!("planet {id:?}")))?;
    state.store.delete(&id).await.map_err(|e| {
        ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, "storage_error", format!("cannot delete the inputs: {e}"))
    })?;
    state.forget(&entry);
    tracing::info!(%id, "planet deleted");
    Ok(StatusCode::NO_CONTENT.into_response())
}
