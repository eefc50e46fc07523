//! Map inputs (paper §4.1, Figure 8 mode): decode, validate and sample continent bitmaps and elevation maps.
//!
//! A user may steer the planet with a *continent bitmap* (8-bit grayscale PNG, white = land) or an
//! *elevation map* (8/16-bit grayscale PNG plus a metre range, or a single-band GeoTIFF in metres).
//! Maps are equirectangular (plate carrée), north up, with pixel-is-area registration: pixel
//! `(col, row)` covers `west + col*dx .. west + (col+1)*dx` and `north - (row+1)*dy .. north - row*dy`.
//!
//! Untrusted bytes are handled defensively: the format is sniffed from magic bytes, header
//! dimensions are checked against [`MapLimits`] before any pixel memory is allocated, decoders run
//! with their own allocation limits, headers that promise more pixels than the file could hold are
//! refused, and a panic inside a third-party decoder is reported as a corrupt image.

mod bounds;
mod error;
mod geotiff;
mod margin;
mod png;
mod precipitation;
mod sharpen;
#[cfg(test)]
mod test_support;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_inputs;

use std::fmt;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::str::FromStr;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

pub use bounds::GeoBounds;
pub use error::MapError;
pub use margin::SHORE_RIM_M;
pub use precipitation::{decode_precipitation, MAX_PRECIPITATION_MM};

/// Water below sea level that reaches this deep is sea even where the map lost its strait to
/// the ocean (the Black Sea's Bosporus at 20 km pixels). No land depression is as deep: the
/// lowest continental floor, Lake Baikal's, lies 1,186 m below sea level, the Caspian's 1,025 m.
pub const OCEAN_DEPTH_M: f32 = -1500.0;

/// What a map describes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum MapKind {
    /// Land/sea bitmap; values are land fractions 0..1 (white = land).
    Continents,
    /// Elevation in metres relative to sea level.
    Elevation,
}

impl MapKind {
    /// The lowercase name used in requests and JSON.
    pub fn as_str(&self) -> &'static str {
        match self {
            MapKind::Continents => "continents",
            MapKind::Elevation => "elevation",
        }
    }
}

impl fmt::Display for MapKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for MapKind {
    type Err = MapError;
    fn from_str(s: &str) -> Result<MapKind, MapError> {
        match s.trim().to_ascii_lowercase().as_str() {
            "continents" => Ok(MapKind::Continents),
            "elevation" => Ok(MapKind::Elevation),
            _ => Err(MapError::UnknownKind(s.to_string())),
        }
    }
}

/// Default most pixels a map may declare (`MapLimits::default`, `serve --max-map-mpixels`).
pub const DEFAULT_MAX_MAP_PIXELS: u64 = 64 << 20;

/// Resource limits for decoding one map.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MapLimits {
    /// Largest accepted width*height.
    pub max_pixels: u64,
    /// Largest accepted upload in bytes.
    pub max_bytes: usize,
}

impl Default for MapLimits {
    /// 64 Mpixel (e.g. 16384x4096) and 64 MiB.
    fn default() -> MapLimits {
        MapLimits { max_pixels: DEFAULT_MAX_MAP_PIXELS, max_bytes: 64 << 20 }
    }
}

/// One decoded map. Row 0 is the north edge, column 0 the west edge.
#[derive(Clone, PartialEq)]
pub struct Map {
    pub kind: MapKind,
    pub width: u32,
    pub height: u32,
    pub bounds: GeoBounds,
    /// Row-major; Continents: land fraction 0..1; Elevation: metres; NaN = nodata.
    values: Vec<f32>,
}

impl fmt::Debug for Map {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Map")
            .field("kind", &self.kind)
            .field("width", &self.width)
            .field("height", &self.height)
            .field("bounds", &self.bounds)
            .field("value_range", &self.value_range())
            .finish_non_exhaustive()
    }
}

/// Refuse zero-sized and oversized rasters; returns the pixel count.
pub(crate) fn check_dimensions(width: u32, height: u32, limits: &MapLimits) -> Result<u64, MapError> {
    if width == 0 || height == 0 {
        return Err(MapError::EmptyImage { width, height });
    }
    let pixels = u64::from(width) * u64::from(height);
    if pixels > limits.max_pixels {
        return Err(MapError::ImageTooLarge { width, height, pixels, max_pixels: limits.max_pixels });
    }
    Ok(pixels)
}

/// Check an elevation PNG's `map_range` (metres for the lowest and highest pixel value).
pub(crate) fn validate_range(range_m: Option<(f64, f64)>) -> Result<(f64, f64), MapError> {
    let (lo, hi) = range_m.ok_or(MapError::MissingMapRange)?;
    if !lo.is_finite() || !hi.is_finite() {
        return Err(MapError::InvalidMapRange(format!(
            "map_range must be two finite numbers of metres (got {lo},{hi})"
        )));
    }
    if lo >= hi {
        return Err(MapError::InvalidMapRange(format!("map_range min must be below max (got {lo},{hi})")));
    }
    Ok((lo, hi))
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    Png,
    Tiff,
}

/// Decide the format from magic bytes only.
fn sniff(bytes: &[u8]) -> Result<Format, MapError> {
    if bytes.is_empty() {
        return Err(MapError::NotAnImage { detail: "the upload is empty".to_string() });
    }
    if bytes.starts_with(b"\x89PNG") {
        return Ok(Format::Png);
    }
    const TIFF_MAGIC: [&[u8]; 4] = [b"II*\0", b"MM\0*", b"II+\0", b"MM\0+"];
    if TIFF_MAGIC.iter().any(|m| bytes.starts_with(m)) {
        return Ok(Format::Tiff);
    }
    let head: Vec<String> = bytes.iter().take(4).map(|b| format!("{b:02x}")).collect();
    Err(MapError::NotAnImage { detail: format!("starts with bytes {}", head.join(" ")) })
}

/// Refuse headers that promise more decoded bytes than the file could possibly expand to
/// (`max_ratio` = the codec's worst-case expansion), before the output buffer is allocated.
pub(crate) fn check_plausible(
    format: &'static str,
    width: u32,
    height: u32,
    decoded_bytes: u64,
    file_bytes: usize,
    max_ratio: u64,
) -> Result<(), MapError> {
    let capacity = (file_bytes as u64).saturating_mul(max_ratio).saturating_add(4096);
    if decoded_bytes > capacity {
        return Err(MapError::corrupt(format, format!("{file_bytes} bytes cannot hold {width}x{height} pixels")));
    }
    Ok(())
}

/// Run a third-party decoder call, turning a panic on malformed input into a corrupt-image error.
/// Only decoder calls are wrapped, so a panic in this module's own code still shows in tests.
pub(crate) fn guard<T>(format: &'static str, f: impl FnOnce() -> Result<T, MapError>) -> Result<T, MapError> {
    catch_unwind(AssertUnwindSafe(f))
        .unwrap_or_else(|_| Err(MapError::corrupt(format, "the decoder gave up on malformed data")))
}

impl Map {
    /// Decode and validate an uploaded map.
    ///
    /// * `range_m`: metres for pixel values 0 and max; required for elevation PNGs, ignored
    ///   otherwise (GeoTIFFs hold real metres, continent bitmaps are land fractions).
    /// * `bounds`: where the map lies; for PNGs it defaults to the globe, for GeoTIFFs the
    ///   georeference tags win and `bounds` (else the globe) is used only when they are absent.
    pub fn decode(
        bytes: &[u8],
        kind: MapKind,
        range_m: Option<(f64, f64)>,
        bounds: Option<GeoBounds>,
        limits: &MapLimits,
    ) -> Result<Map, MapError> {
        if bytes.len() > limits.max_bytes {
            return Err(MapError::FileTooLarge { bytes: bytes.len(), max: limits.max_bytes });
        }
        let format = sniff(bytes)?;
        if let Some(b) = &bounds {
            b.validate()?;
        }
        let bounds = bounds.unwrap_or(GeoBounds::GLOBE);
        match format {
            Format::Png => png::decode(bytes, kind, range_m, bounds, limits),
            Format::Tiff => geotiff::decode(bytes, kind, bounds, limits),
        }
    }

    /// Build a map from row-major values (row 0 north). Checks bounds and the value count.
    pub fn from_values(
        kind: MapKind,
        width: u32,
        height: u32,
        bounds: GeoBounds,
        values: Vec<f32>,
    ) -> Result<Map, MapError> {
        bounds.validate()?;
        if width == 0 || height == 0 {
            return Err(MapError::EmptyImage { width, height });
        }
        let expected = u64::from(width) * u64::from(height);
        if values.len() as u64 != expected {
            return Err(MapError::corrupt("raster", format!("{} values for {width}x{height} pixels", values.len())));
        }
        Ok(Map { kind, width, height, bounds, values })
    }

    /// All values, row-major with row 0 the north edge; NaN = nodata.
    pub fn values(&self) -> &[f32] {
        &self.values
    }

    /// The value of one pixel (NaN = nodata), or None outside the raster.
    pub fn value_at(&self, col: u32, row: u32) -> Option<f32> {
        if col >= self.width || row >= self.height {
            return None;
        }
        self.values.get(row as usize * self.width as usize + col as usize).copied()
    }

    /// Smallest and largest valid value, or None when every pixel is nodata.
    pub fn value_range(&self) -> Option<(f32, f32)> {
        self.values.iter().filter(|v| !v.is_nan()).fold(None, |acc, &v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
    }

    /// Whether a (valid) value counts as land: Continents >= 0.5, Elevation >= 0 m.
    pub fn is_land_value(&self, v: f32) -> bool {
        match self.kind {
            MapKind::Continents => v >= 0.5,
            MapKind::Elevation => v >= 0.0,
        }
    }

    /// Pixel size in degrees as (longitude step, latitude step).
    pub fn pixel_size_deg(&self) -> (f64, f64) {
        let b = &self.bounds;
        ((b.east - b.west) / f64::from(self.width), (b.north - b.south) / f64::from(self.height))
    }

    /// Bilinear sample between the four nearest pixel centres (pixel-is-area registration).
    ///
    /// Latitude is clamped between the outermost pixel centres and the map's north/south edges;
    /// longitude (any range) wraps when the map spans 360°, otherwise it is clamped the same way.
    /// Returns None outside the bounds, for non-finite input, or when the pixel containing the
    /// point is nodata; nodata neighbours are left out of the interpolation.
    pub fn sample(&self, lat_deg: f64, lon_deg: f64) -> Option<f32> {
        let b = &self.bounds;
        if !b.contains(lat_deg, lon_deg) {
            return None;
        }
        let lon = b.unwrap_lon(lon_deg);
        let (dx, dy) = self.pixel_size_deg();
        let (w, h) = (self.width as usize, self.height as usize);
        // Continuous coordinates in units of pixels, integer = pixel centre.
        let fx = (lon - b.west) / dx - 0.5;
        let fy = (b.north - lat_deg) / dy - 0.5;

        let nearest = |f: f64, n: usize| ((f + 0.5).floor().max(0.0) as usize).min(n - 1);
        let own = self.values[nearest(fy, h) * w + nearest(fx, w)];
        if own.is_nan() {
            return None;
        }

        let clamped = |f: f64, n: usize| {
            let f = f.clamp(0.0, (n - 1) as f64);
            let i0 = f.floor() as usize;
            (i0, (i0 + 1).min(n - 1), f - i0 as f64)
        };
        let (r0, r1, ty) = clamped(fy, h);
        let (c0, c1, tx) = if b.spans_all_longitudes() {
            let fl = fx.floor();
            let c0 = (fl as i64).rem_euclid(w as i64) as usize;
            (c0, (c0 + 1) % w, fx - fl)
        } else {
            clamped(fx, w)
        };

        let taps = [
            (r0, c0, (1.0 - ty) * (1.0 - tx)),
            (r0, c1, (1.0 - ty) * tx),
            (r1, c0, ty * (1.0 - tx)),
            (r1, c1, ty * tx),
        ];
        let (mut sum, mut wsum) = (0.0f64, 0.0f64);
        for (r, c, wt) in taps {
            let v = self.values[r * w + c];
            if wt > 0.0 && !v.is_nan() {
                sum += wt * f64::from(v);
                wsum += wt;
            }
        }
        if wsum > 0.0 {
            Some((sum / wsum) as f32)
        } else {
            Some(own)
        }
    }

    /// Indices into [`Map::values`] of the pixels within `radius` pixels (a square window,
    /// wrapping in longitude on a global map) of the pixel holding a point; none where
    /// [`Map::sample`] has no value.
    pub fn window(&self, lat_deg: f64, lon_deg: f64, radius: u32) -> impl Iterator<Item = usize> + '_ {
        let b = &self.bounds;
        let (dx, dy) = self.pixel_size_deg();
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        let valid = self.sample(lat_deg, lon_deg).is_some();
        let col = ((b.unwrap_lon(lon_deg) - b.west) / dx).floor() as i64;
        let row = ((b.north - lat_deg) / dy).floor() as i64;
        let r = if valid { i64::from(radius) } else { -1 };
        let wraps = b.spans_all_longitudes();
        ((row - r).max(0)..=(row + r).min(h - 1)).flat_map(move |rr| {
            (col - r..=col + r).filter_map(move |cc| {
                let cc = if wraps { cc.rem_euclid(w) } else { cc };
                (0..w).contains(&cc).then_some((rr * w + cc) as usize)
            })
        })
    }

    /// The lowest valid value within `radius` pixels of the pixel holding a point (see
    /// [`Map::window`]), or None where [`Map::sample`] has none. A vertex standing for ground
    /// several pixels wide drains through the lowest ground around it: a gorge narrower than
    /// the vertices' spacing still carries its river.
    pub fn sample_min(&self, lat_deg: f64, lon_deg: f64, radius: u32) -> Option<f32> {
        let low = self.window(lat_deg, lon_deg, radius).map(|i| self.values[i]).fold(f32::INFINITY, f32::min);
        low.is_finite().then_some(low)
    }

    /// Per pixel of an elevation map: below sea level and joined to the ocean through pixels
    /// below sea level (8-connected, across the antimeridian on a global map). The ocean is the
    /// largest such body of a global map, any body touching a regional map's edge (the planet
    /// is sea outside it), and any body reaching [`OCEAN_DEPTH_M`], however its strait was lost
    /// to the map's resolution. The Caspian or the Qattara Depression are no ocean; the Persian Gulf and the
    /// Baltic, whose straits the mesh may not resolve, are.
    pub fn ocean_pixels(&self) -> Vec<bool> {
        let (w, h) = (self.width as usize, self.height as usize);
        let wet = |i: usize| self.values[i] < 0.0;
        let mut body = vec![u32::MAX; w * h];
        let mut bodies: Vec<(usize, bool)> = Vec::new(); // (pixels, ocean)
        let wraps = self.bounds.spans_all_longitudes();
        let mut stack = Vec::new();
        for start in 0..w * h {
            if !wet(start) || body[start] != u32::MAX {
                continue;
            }
            let id = bodies.len() as u32;
            let (mut count, mut ocean) = (0usize, false);
            body[start] = id;
            stack.push(start);
            while let Some(i) = stack.pop() {
                count += 1;
                let (r, c) = ((i / w) as i64, (i % w) as i64);
                ocean |= self.values[i] <= OCEAN_DEPTH_M
                    || (!self.bounds.is_global() && (r == 0 || r == h as i64 - 1 || c == 0 || c == w as i64 - 1));
                for (dr, dc) in [(-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1)] {
                    let (rr, mut cc) = (r + dr, c + dc);
                    if wraps {
                        cc = cc.rem_euclid(w as i64);
                    }
                    if rr < 0 || rr >= h as i64 || cc < 0 || cc >= w as i64 {
                        continue;
                    }
                    let j = rr as usize * w + cc as usize;
                    if wet(j) && body[j] == u32::MAX {
                        body[j] = id;
                        stack.push(j);
                    }
                }
            }
            bodies.push((count, ocean));
        }
        if let Some(largest) = (0..bodies.len()).max_by_key(|&b| bodies[b].0).filter(|_| self.bounds.is_global()) {
            bodies[largest].1 = true;
        }
        body.iter().map(|&b| b != u32::MAX && bodies[b as usize].1).collect()
    }

    /// The map box-averaged over blocks of `k` x `k` pixels (nodata left out of each block; a
    /// block of nodata stays nodata), over the same bounds, with `k` the largest divisor of both
    /// sides up to `max_k` (1 gives a copy). Vertices spaced several pixels apart sample this
    /// instead of single pixels, so they stand for the ground around them rather than alias the
    /// map's finest detail.
    pub fn box_filtered(&self, max_k: u32) -> Map {
        let k = (1..=max_k.max(1))
            .rev()
            .find(|&k| self.width.is_multiple_of(k) && self.height.is_multiple_of(k))
            .unwrap_or(1);
        if k == 1 {
            return self.clone();
        }
        let (w, h) = (self.width / k, self.height / k);
        let values: Vec<f32> = (0..h)
            .into_par_iter()
            .flat_map_iter(|r| (0..w).map(move |c| self.block_mean(c, r, k, k).map_or(f32::NAN, |m| m as f32)))
            .collect();
        Map { kind: self.kind, width: w, height: h, bounds: self.bounds, values }
    }

    /// Mean of the valid pixels of block `(col, row)` of `kx` x `ky` pixels (pixels
    /// `col * kx .. (col + 1) * kx` across, likewise down, clipped to the map), or None when
    /// none is valid.
    pub fn block_mean(&self, col: u32, row: u32, kx: u32, ky: u32) -> Option<f64> {
        let (mut sum, mut count) = (0.0f64, 0u32);
        for r in row * ky..((row + 1) * ky).min(self.height) {
            for c in col * kx..((col + 1) * kx).min(self.width) {
                let v = self.values[r as usize * self.width as usize + c as usize];
                if !v.is_nan() {
                    sum += f64::from(v);
                    count += 1;
                }
            }
        }
        (count > 0).then(|| sum / f64::from(count))
    }

    /// Area-weighted share of valid pixels that are land (see [`Map::is_land_value`]);
    /// 0 when no pixel is valid. Rows are weighted by their exact area on the sphere.
    pub fn land_fraction(&self) -> f64 {
        let (_, dy) = self.pixel_size_deg();
        let north = self.bounds.north;
        let (land, valid) = self
            .values
            .par_chunks(self.width as usize)
            .enumerate()
            .map(|(row, px)| {
                let top = north - row as f64 * dy;
                let area = top.to_radians().sin() - (top - dy).to_radians().sin();
                let (l, v) = px
                    .iter()
                    .filter(|v| !v.is_nan())
                    .fold((0u64, 0u64), |(l, n), &x| (l + u64::from(self.is_land_value(x)), n + 1));
                (area * l as f64, area * v as f64)
            })
            .reduce(|| (0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
        if valid > 0.0 {
            land / valid
        } else {
            0.0
        }
    }
}
