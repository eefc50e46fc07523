//! The library's input layer for files: maps (by format and kind) and planet requests
//! (`{"seed", "params"}`) read from disk, assembled into a [`PlanetSpec`]. The server reads the
//! same inputs from requests (`server/input.rs`) with the same checks.

use crate::maps::{GeoBounds, Map, MapError, MapKind, MapLimits};
use crate::params::{ParamError, PlanetRequest};
use crate::planet::PlanetSpec;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Where a planet's map comes from and how to read it.
#[derive(Clone, Debug, Default)]
pub struct MapSource {
    pub path: PathBuf,
    /// `None`: elevation for TIFF files or when a range is given, else continents.
    pub kind: Option<MapKind>,
    pub range_m: Option<(f64, f64)>,
    pub bounds: Option<GeoBounds>,
}

/// Why the inputs cannot be read: all are the caller's input problems.
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    #[error("cannot read {path}: {source}")]
    Read { path: PathBuf, source: std::io::Error },
    #[error("{0}")]
    Params(#[from] ParamError),
    #[error("map: {0}")]
    Map(#[from] MapError),
    #[error("precipitation: {0}")]
    Precipitation(MapError),
}

/// Parses `MIN_M,MAX_M`.
pub fn parse_range(s: &str) -> Result<(f64, f64), MapError> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let bad = || MapError::InvalidMapRange(format!("expected MIN_M,MAX_M, got {s:?}"));
    if parts.len() != 2 {
        return Err(bad());
    }
    let lo: f64 = parts[0].parse().map_err(|_| bad())?;
    let hi: f64 = parts[1].parse().map_err(|_| bad())?;
    Ok((lo, hi))
}

/// Reads and decodes a map file.
pub fn load_map(src: &MapSource, limits: &MapLimits) -> Result<Map, InputError> {
    let bytes = std::fs::read(&src.path).map_err(|source| InputError::Read { path: src.path.clone(), source })?;
    let is_tiff = bytes.starts_with(b"II*\0") || bytes.starts_with(b"MM\0*");
    let kind =
        src.kind.unwrap_or(if is_tiff || src.range_m.is_some() { MapKind::Elevation } else { MapKind::Continents });
    Ok(Map::decode(&bytes, kind, src.range_m, src.bounds, limits)?)
}

/// Reads and checks a precipitation map file ([`crate::maps::decode_precipitation`]; the
/// source's range is in mm per year, its kind unused).
pub fn load_precipitation(src: &MapSource, limits: &MapLimits) -> Result<Map, InputError> {
    let bytes = std::fs::read(&src.path).map_err(|source| InputError::Read { path: src.path.clone(), source })?;
    crate::maps::decode_precipitation(&bytes, src.range_m, src.bounds, limits).map_err(InputError::Precipitation)
}

/// Reads a `{"seed", "params"}` file.
pub fn load_request(path: &Path) -> Result<PlanetRequest, InputError> {
    let text = std::fs::read_to_string(path).map_err(|source| InputError::Read { path: path.to_path_buf(), source })?;
    Ok(PlanetRequest::from_json(&text)?)
}

/// Assembles the spec from a request, an optional map and an optional precipitation map.
pub fn spec(req: PlanetRequest, map: Option<Map>, precipitation: Option<Map>) -> PlanetSpec {
    PlanetSpec {
        seed: req.seed,
        params: req.params,
        map: map.map(Arc::new),
        precipitation: precipitation.map(Arc::new),
    }
}
