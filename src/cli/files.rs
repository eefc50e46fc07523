//! The files `riverworld generate` writes, and how every command writes its output: to a
//! temporary name beside it, then renamed into place.

use riverworld::export::glb::GlbTooLarge;
use riverworld::planet::{Planet, PlanetSpec};
use std::path::{Path, PathBuf};

/// An output file that could not be written.
#[derive(Debug, thiserror::Error)]
#[error("cannot write {path}: {source}")]
pub struct WriteError {
    pub path: PathBuf,
    pub source: std::io::Error,
}

/// The files `generate` writes, by name, in a fixed order.
pub fn outputs(
    planet: &Planet,
    spec: &PlanetSpec,
    raster_width: u32,
) -> Result<Vec<(&'static str, Vec<u8>)>, GlbTooLarge> {
    let (w, h) = (raster_width, (raster_width / 2).max(1));
    let p = &spec.params;
    let mut stats = serde_json::to_vec_pretty(&planet.stats).expect("stats serialise");
    stats.push(b'\n');
    Ok(vec![
        ("planet.glb", riverworld::export::glb::planet_glb(&planet.mesh, p)?),
        ("rivers.geojson", riverworld::export::geojson::rivers_geojson(planet, p).into_bytes()),
        ("landmask.png", riverworld::export::raster::landmask_png(&planet.mesh, w, h)),
        ("elevation.tif", riverworld::export::raster::elevation_tiff(&planet.mesh, p, w, h)),
        ("preview.png", riverworld::export::preview::preview_png(&planet.mesh, &planet.rivers, p, w, h)),
        ("stats.json", stats),
    ])
}

/// Writes each file atomically: to a temporary name in `dir`, then renamed into place.
pub fn write_outputs(dir: &Path, files: &[(&str, Vec<u8>)]) -> Result<(), WriteError> {
    let werr = |path: &Path| {
        let path = path.to_path_buf();
        move |source| WriteError { path, source }
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
