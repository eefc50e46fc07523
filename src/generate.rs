//! `riverworld generate`: loads the inputs, builds the planet (paper §4) and writes its files.

use crate::build::{build_planet, BuildError, Planet, PlanetSpec};
use crate::export;
use crate::maps::{GeoBounds, Map, MapError, MapKind, MapLimits};
use crate::params::{ParamError, PlanetRequest};
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

/// Anything that stops `generate`; all are the caller's input problems except `Io` on output.
#[derive(Debug, thiserror::Error)]
pub enum GenerateError {
    #[error("cannot read {path}: {source}")]
    Read { path: PathBuf, source: std::io::Error },
    #[error("{0}")]
    Params(#[from] ParamError),
    #[error("map: {0}")]
    Map(#[from] MapError),
    #[error("{0}")]
    Build(#[from] BuildError),
    #[error("cannot write {path}: {source}")]
    Write { path: PathBuf, source: std::io::Error },
    #[error("planet.glb: {0}")]
    Glb(#[from] export::glb::GlbTooLarge),
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
pub fn load_map(src: &MapSource, limits: &MapLimits) -> Result<Map, GenerateError> {
    let bytes = std::fs::read(&src.path).map_err(|source| GenerateError::Read { path: src.path.clone(), source })?;
    let is_tiff = bytes.starts_with(b"II*\0") || bytes.starts_with(b"MM\0*");
    let kind =
        src.kind.unwrap_or(if is_tiff || src.range_m.is_some() { MapKind::Elevation } else { MapKind::Continents });
    Ok(Map::decode(&bytes, kind, src.range_m, src.bounds, limits)?)
}

/// Reads a `{"seed", "params"}` file.
pub fn load_request(path: &Path) -> Result<PlanetRequest, GenerateError> {
    let text =
        std::fs::read_to_string(path).map_err(|source| GenerateError::Read { path: path.to_path_buf(), source })?;
    Ok(PlanetRequest::from_json(&text)?)
}

/// Builds the planet of `spec`.
pub fn build(spec: &PlanetSpec, progress: &mut dyn FnMut(&str, f32)) -> Result<Planet, GenerateError> {
    Ok(build_planet(spec, progress)?)
}

/// The files `generate` writes, by name, in a fixed order.
pub fn outputs(
    planet: &Planet,
    spec: &PlanetSpec,
    raster_width: u32,
) -> Result<Vec<(&'static str, Vec<u8>)>, GenerateError> {
    let (w, h) = (raster_width, (raster_width / 2).max(1));
    let p = &spec.params;
    let mut stats = serde_json::to_vec_pretty(&planet.stats).expect("stats serialise");
    stats.push(b'\n');
    Ok(vec![
        ("planet.glb", export::glb::planet_glb(&planet.mesh, p)?),
        ("rivers.geojson", export::geojson::rivers_geojson(planet, p).into_bytes()),
        ("landmask.png", export::raster::landmask_png(&planet.mesh, w, h)),
        ("elevation.tif", export::raster::elevation_tiff(&planet.mesh, p, w, h)),
        ("preview.png", export::preview::preview_png(&planet.mesh, &planet.rivers, p, w, h)),
        ("stats.json", stats),
    ])
}

/// Writes each file atomically: to a temporary name in `dir`, then renamed into place.
pub fn write_outputs(dir: &Path, files: &[(&str, Vec<u8>)]) -> Result<(), GenerateError> {
    let werr = |path: &Path| {
        let path = path.to_path_buf();
        move |source| GenerateError::Write { path, source }
    };
    std::fs::create_dir_all(dir).map_err(werr(dir))?;
    for (name, bytes) in files {
        let path = dir.join(name);
        let tmp = dir.join(format!(".{name}.tmp"));
        std::fs::write(&tmp, bytes).map_err(werr(&tmp))?;
        std::fs::rename(&tmp, &path).map_err(werr(&path))?;
    }
    Ok(())
}

/// Assembles the spec from a request and an optional map.
pub fn spec(req: PlanetRequest, map: Option<Map>) -> PlanetSpec {
    PlanetSpec { seed: req.seed, params: req.params, map: map.map(Arc::new) }
}
