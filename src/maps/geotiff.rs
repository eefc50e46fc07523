//! Elevation GeoTIFFs: one band of int16, uint16, int32, float32 or float64 metres, georeferenced
//! by ModelPixelScale + ModelTiepoint (or an unrotated ModelTransformation), with GDAL_NODATA.

use std::io::Cursor;

use tiff::decoder::{Decoder, DecodingResult, Limits};
use tiff::tags::Tag;
use tiff::TiffError;

use super::{check_dimensions, check_plausible, guard, GeoBounds, Map, MapError, MapKind, MapLimits};

/// GeoKey ids (GeoTIFF 1.0 §6.3.1).
const GT_MODEL_TYPE: u16 = 1024;
const GT_RASTER_TYPE: u16 = 1025;
const MODEL_TYPE_GEOGRAPHIC: u16 = 2;
const RASTER_PIXEL_IS_POINT: u16 = 2;
/// Edges this close to ±180/±90 are snapped onto them (float noise from scale * size).
const SNAP_DEG: f64 = 1e-7;

type Dec<'a> = Decoder<Cursor<&'a [u8]>>;

fn tiff_error(e: TiffError) -> MapError {
    match e {
        TiffError::UnsupportedError(u) => MapError::Unsupported(format!("TIFF feature not supported: {u}")),
        TiffError::LimitsExceeded => MapError::Unsupported("TIFF needs more decoder memory than allowed".to_string()),
        other => MapError::corrupt("TIFF", other),
    }
}

/// A tiff-crate call with its error mapped and any panic on malformed data caught.
fn call<T>(f: impl FnOnce() -> Result<T, TiffError>) -> Result<T, MapError> {
    guard("TIFF", || f().map_err(tiff_error))
}

/// Decode an elevation GeoTIFF. Bounds come from the georeference tags when present, otherwise
/// from `fallback` (the caller's `bounds` argument or GLOBE, already validated).
pub(super) fn decode(bytes: &[u8], kind: MapKind, fallback: GeoBounds, limits: &MapLimits) -> Result<Map, MapError> {
    if kind == MapKind::Continents {
        return Err(MapError::KindMismatch {
            kind: "continents",
            hint: "a GeoTIFF holds elevations in metres: send it as map_kind elevation (the default for a \
                   TIFF); continent bitmaps are 8-bit grayscale PNGs",
        });
    }
    let mut dec = call(|| Decoder::new(Cursor::new(bytes)))?;
    let (width, height) = call(|| dec.dimensions())?;
    let pixels = check_dimensions(width, height, limits)?;

    let bands = call(|| dec.find_tag_unsigned::<u16>(Tag::SamplesPerPixel))?.unwrap_or(1);
    if bands != 1 {
        return Err(MapError::WrongBandCount { bands });
    }
    let first = |v: Option<Vec<u16>>, default: u16| v.and_then(|v| v.first().copied()).unwrap_or(default);
    let bits = first(call(|| dec.find_tag_unsigned_vec(Tag::BitsPerSample))?, 1);
    let format = first(call(|| dec.find_tag_unsigned_vec(Tag::SampleFormat))?, 1);
    let (type_name, sample_bytes) = match (format, bits) {
        (2, 16) => ("int16", 2),
        (1, 16) => ("uint16", 2),
        (2, 32) => ("int32", 4),
        (3, 32) => ("float32", 4),
        (3, 64) => ("float64", 8),
        _ => {
            let kind = match format {
                1 => "uint",
                2 => "int",
                3 => "float",
                _ => "unknown-format ",
            };
            return Err(MapError::WrongBitDepth {
                expected: "elevation GeoTIFF samples must be int16, uint16, int32, float32 or float64",
                got: format!("{kind}{bits}"),
            });
        }
    };

    // Every strip or tile lies inside the file: a cut file is corrupt even where the decoder
    // would not read the missing bytes (the padding of a COG's last tile, say).
    for (offsets, counts) in [(Tag::StripOffsets, Tag::StripByteCounts), (Tag::TileOffsets, Tag::TileByteCounts)] {
        let at = call(|| dec.find_tag_unsigned_vec::<u64>(offsets))?.unwrap_or_default();
        let len = call(|| dec.find_tag_unsigned_vec::<u64>(counts))?.unwrap_or_default();
        if at.iter().zip(&len).any(|(&a, &n)| a.saturating_add(n) > bytes.len() as u64) {
            return Err(MapError::Corrupt {
                format: "TIFF",
                detail: "a strip or tile lies past the end of the file".into(),
            });
        }
    }
    let bounds = georeference(&mut dec, width, height)?.unwrap_or(fallback);
    let nodata = read_nodata(&mut dec)?;
    // LZW, the most expansive TIFF codec, turns a 12-bit code into at most 4096 bytes.
    let decoded: u64 = pixels.saturating_mul(sample_bytes);
    check_plausible("TIFF", width, height, decoded, bytes.len(), 2800)?;

    let mut tiff_limits = Limits::default();
    tiff_limits.decoding_buffer_size = usize::try_from(decoded).unwrap_or(usize::MAX).max(1 << 20);
    tiff_limits.intermediate_buffer_size = limits.max_bytes.max(1 << 20);
    let mut dec = dec.with_limits(tiff_limits);
    let data = call(|| dec.read_image())?;

    let values = match data {
        DecodingResult::I16(v) => convert(v, f64::from, nodata),
        DecodingResult::U16(v) => convert(v, f64::from, nodata),
        DecodingResult::I32(v) => convert(v, f64::from, nodata),
        // Compare float32 pixels with the nodata value rounded to float32, as GDAL does.
        DecodingResult::F32(v) => convert(v, f64::from, nodata.map(|n| f64::from(n as f32))),
        DecodingResult::F64(v) => convert(v, |x| x, nodata),
        _ => {
            return Err(MapError::corrupt(
                "TIFF",
                format!("tags say {type_name} but the decoder produced another sample type"),
            ))
        }
    };
    Map::from_values(MapKind::Elevation, width, height, bounds, values)
}

/// Elevation as f32, with nodata and non-finite samples turned into NaN.
fn convert<T: Copy>(data: Vec<T>, to_f64: impl Fn(T) -> f64, nodata: Option<f64>) -> Vec<f32> {
    data.into_iter()
        .map(|x| {
            let v = to_f64(x);
            if !v.is_finite() || nodata == Some(v) {
                f32::NAN
            } else {
                v as f32
            }
        })
        .collect()
}

fn read_nodata(dec: &mut Dec<'_>) -> Result<Option<f64>, MapError> {
    let Some(value) = call(|| dec.find_tag(Tag::GdalNodata))? else {
        return Ok(None);
    };
    let text = call(|| value.into_string())?;
    let text = text.trim_matches(|c: char| c == '\0' || c.is_whitespace());
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(Some(v)),
        Ok(_) => Ok(None), // NaN/inf nodata: non-finite samples already become NaN.
        Err(_) => Err(MapError::corrupt("TIFF", format!("GDAL_NODATA tag {text:?} is not a number"))),
    }
}

fn f64_tag(dec: &mut Dec<'_>, tag: Tag) -> Result<Option<Vec<f64>>, MapError> {
    match call(|| dec.find_tag(tag))? {
        Some(v) => Ok(Some(call(|| v.into_f64_vec())?)),
        None => Ok(None),
    }
}

/// Value of a GeoKey stored directly in the GeoKeyDirectory (location 0), if present.
fn geokey(dir: &[u16], key: u16) -> Option<u16> {
    let count = usize::from(*dir.get(3)?);
    dir.get(4..)?.chunks_exact(4).take(count).find(|e| e[0] == key && e[1] == 0).map(|e| e[3])
}

fn snap(v: f64, target: f64) -> f64 {
    if (v - target).abs() < SNAP_DEG {
        target
    } else {
        v
    }
}

/// Bounds from the GeoTIFF tags, or None when the file carries no georeference.
fn georeference(dec: &mut Dec<'_>, width: u32, height: u32) -> Result<Option<GeoBounds>, MapError> {
    let bad = |m: String| Err(MapError::InvalidGeoreference(m));
    let keys = match call(|| dec.find_tag(Tag::GeoKeyDirectoryTag))? {
        Some(v) => call(|| v.into_u16_vec())?,
        None => Vec::new(),
    };
    if let Some(model) = geokey(&keys, GT_MODEL_TYPE) {
        if model != MODEL_TYPE_GEOGRAPHIC {
            return bad(format!(
                "map must be in geographic longitude/latitude degrees such as EPSG:4326 \
                 (GTModelTypeGeoKey is {model}, not 2)"
            ));
        }
    }
    let scale = f64_tag(dec, Tag::ModelPixelScaleTag)?;
    let tie = f64_tag(dec, Tag::ModelTiepointTag)?;
    let transform = f64_tag(dec, Tag::ModelTransformationTag)?;
    let (mut west, mut north, sx, sy) = match (scale, tie, transform) {
        (Some(s), Some(t), _) => {
            if s.len() < 2 || t.len() < 6 {
                return bad("ModelPixelScale or ModelTiepoint has too few values".to_string());
            }
            (t[3] - t[0] * s[0], t[4] + t[1] * s[1], s[0], s[1])
        }
        (_, _, Some(m)) => {
            if m.len() < 16 {
                return bad("ModelTransformation must have 16 values".to_string());
            }
            if m[1] != 0.0 || m[4] != 0.0 {
                return bad("rotated or sheared rasters are not supported".to_string());
            }
            (m[3], m[7], m[0], -m[5])
        }
        _ => return Ok(None),
    };
    if !(sx.is_finite() && sy.is_finite() && sx > 0.0 && sy > 0.0) {
        return bad(format!("pixel size must be positive with north up (got {sx} x {sy} degrees)"));
    }
    if geokey(&keys, GT_RASTER_TYPE) == Some(RASTER_PIXEL_IS_POINT) {
        // Tiepoint names the centre of pixel (0,0); move to its north-west corner.
        west -= sx / 2.0;
        north += sy / 2.0;
    }
    let b = GeoBounds {
        west: snap(west, -180.0),
        south: snap(north - f64::from(height) * sy, -90.0),
        east: snap(west + f64::from(width) * sx, 180.0),
        north: snap(north, 90.0),
    };
    match b.validate() {
        Ok(()) => Ok(Some(b)),
        Err(MapError::InvalidBounds(why)) => {
            bad(format!("tags give bounds {},{},{},{}: {why}", b.west, b.south, b.east, b.north))
        }
        Err(e) => Err(e),
    }
}
