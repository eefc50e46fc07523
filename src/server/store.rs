//! Where planets' inputs live: an object store (a local directory by default, S3 with the `s3`
//! feature) holding `planets/{id}/map.bin`, `planets/{id}/precipitation.bin` and
//! `planets/{id}/request.json`.
//!
//! Only inputs are stored; meshes and rendered files are caches, rebuilt on demand because the
//! same inputs always give the same planet. Each object is written atomically; the map goes first
//! and `request.json` last, so a planet exists in the store exactly when its `request.json` does.

use crate::maps::{GeoBounds, MapKind};
use crate::params::Params;
use bytes::Bytes;
use object_store::local::LocalFileSystem;
use object_store::path::Path;
use object_store::{ObjectStore, ObjectStoreExt, PutPayload};
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// A stored map's description (its bytes are in `map.bin`); also the record's `map` field.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MapMeta {
    pub kind: MapKind,
    /// Size of the uploaded file.
    pub bytes: usize,
    pub width: u32,
    pub height: u32,
    /// Metres of the darkest and brightest pixel (elevation PNG).
    pub range_m: Option<(f64, f64)>,
    /// Bounds given with the upload; null = the globe (or a GeoTIFF's own georeference).
    pub bounds: Option<GeoBounds>,
}

/// A stored precipitation map's description (its bytes are in `precipitation.bin`); also the
/// record's `precipitation` field.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PrecipitationMeta {
    /// Size of the uploaded file.
    pub bytes: usize,
    pub width: u32,
    pub height: u32,
    /// Millimetres per year of the darkest and brightest pixel (PNG).
    pub range_mm: Option<(f64, f64)>,
    /// Bounds given with the upload; null = the globe (or a GeoTIFF's own georeference).
    pub bounds: Option<GeoBounds>,
}

/// `request.json`: everything that defines a planet besides the maps' bytes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StoredInput {
    pub seed: u64,
    pub params: Params,
    pub map: Option<MapMeta>,
    /// A precipitation map in place of the climate model's (absent in older records).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub precipitation: Option<PrecipitationMeta>,
}

/// The planet store.
#[derive(Clone, Debug)]
pub struct Store {
    inner: Arc<dyn ObjectStore>,
}

fn planet_path(id: &str, name: &str) -> Path {
    Path::from(format!("planets/{id}/{name}"))
}

impl Store {
    /// Opens `url` (`file:///dir`, a plain directory path or `s3://bucket/prefix`), or the
    /// directory `data` when no URL is given; a local directory is created when missing.
    pub fn open(url: Option<&str>, data: &std::path::Path) -> Result<Store, String> {
        let dir = match url {
            None => data.to_path_buf(),
            Some(u) if u.starts_with("s3://") => return open_s3(u),
            Some(u) => match u.strip_prefix("file://") {
                Some(p) => std::path::PathBuf::from(p),
                None if u.contains("://") => {
                    return Err(format!(
                        "unsupported store URL {u:?}: use a directory, file:///dir or s3://bucket/prefix"
                    ))
                }
                None => std::path::PathBuf::from(u),
            },
        };
        std::fs::create_dir_all(&dir).map_err(|e| format!("cannot create data directory {}: {e}", dir.display()))?;
        // Deleting a planet's last file removes its directory too.
        let fs = LocalFileSystem::new_with_prefix(&dir)
            .map_err(|e| format!("cannot open data directory {}: {e}", dir.display()))?
            .with_automatic_cleanup(true);
        Ok(Store { inner: Arc::new(fs) })
    }

    /// Writes a planet's inputs: the maps (if any) first, `request.json` last.
    pub async fn put(
        &self,
        id: &str,
        input: &StoredInput,
        map: Option<Bytes>,
        precipitation: Option<Bytes>,
    ) -> Result<(), object_store::Error> {
        if let Some(bytes) = map {
            self.inner.put(&planet_path(id, "map.bin"), PutPayload::from_bytes(bytes)).await?;
        }
        if let Some(bytes) = precipitation {
            self.inner.put(&planet_path(id, "precipitation.bin"), PutPayload::from_bytes(bytes)).await?;
        }
        let json = serde_json::to_vec_pretty(input).expect("input serialises");
        self.inner.put(&planet_path(id, "request.json"), PutPayload::from(json)).await?;
        Ok(())
    }

    /// The ids of the stored planets (folders under `planets/` with a valid id).
    pub async fn ids(&self) -> Result<Vec<String>, object_store::Error> {
        let listing = self.inner.list_with_delimiter(Some(&Path::from("planets"))).await?;
        let mut ids: Vec<String> = listing
            .common_prefixes
            .iter()
            .filter_map(|p| p.filename().map(str::to_string))
            .filter(|id| super::valid_hex_id(id))
            .collect();
        ids.sort();
        Ok(ids)
    }

    /// A planet's `request.json`; Ok(None) when it does not exist.
    pub async fn input(&self, id: &str) -> Result<Option<StoredInput>, String> {
        match self.inner.get(&planet_path(id, "request.json")).await {
            Ok(r) => {
                let bytes = r.bytes().await.map_err(|e| e.to_string())?;
                serde_json::from_slice(&bytes).map(Some).map_err(|e| format!("planets/{id}/request.json: {e}"))
            }
            Err(object_store::Error::NotFound { .. }) => Ok(None),
            Err(e) => Err(e.to_string()),
        }
    }

    /// A planet's map bytes.
    pub async fn map(&self, id: &str) -> Result<Bytes, object_store::Error> {
        self.inner.get(&planet_path(id, "map.bin")).await?.bytes().await
    }

    /// A planet's precipitation map bytes.
    pub async fn precipitation(&self, id: &str) -> Result<Bytes, object_store::Error> {
        self.inner.get(&planet_path(id, "precipitation.bin")).await?.bytes().await
    }

    /// Removes a planet: `request.json` first, so a half-finished delete leaves no planet.
    pub async fn delete(&self, id: &str) -> Result<(), object_store::Error> {
        for name in ["request.json", "map.bin", "precipitation.bin"] {
            match self.inner.delete(&planet_path(id, name)).await {
                Ok(()) | Err(object_store::Error::NotFound { .. }) => {}
                Err(e) => return Err(e),
            }
        }
        Ok(())
    }
}

#[cfg(feature = "s3")]
fn open_s3(url: &str) -> Result<Store, String> {
    use object_store::aws::AmazonS3Builder;
    use object_store::prefix::PrefixStore;
    let s3 = AmazonS3Builder::from_env().with_url(url).build().map_err(|e| format!("cannot open {url}: {e}"))?;
    let rest = url.trim_start_matches("s3://");
    let prefix = rest.split_once('/').map(|(_, p)| p.trim_matches('/')).unwrap_or("");
    if prefix.is_empty() {
        Ok(Store { inner: Arc::new(s3) })
    } else {
        Ok(Store { inner: Arc::new(PrefixStore::new(s3, prefix)) })
    }
}

#[cfg(not(feature = "s3"))]
fn open_s3(url: &str) -> Result<Store, String> {
    Err(format!("cannot open {url}: S3 support is not built in (rebuild with `--features s3`)"))
}
