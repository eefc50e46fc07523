//! PNG maps: continent bitmaps (8-bit grayscale) and elevation maps (8/16-bit grayscale with a
//! user-given metre range).
//!
//! The IHDR chunk is parsed by hand first, so that size, bit depth and colour type are refused
//! with precise messages before any decoder runs or any pixel memory is allocated.

use std::io::Cursor;

use image::codecs::png::PngDecoder;
use image::{ColorType, ImageDecoder, ImageError};

use super::{check_dimensions, check_plausible, guard, validate_range, GeoBounds, Map, MapError, MapKind, MapLimits};

pub(super) const SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];

/// The fields of a PNG IHDR chunk that decide whether the map is acceptable.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct PngHeader {
    pub width: u32,
    pub height: u32,
    pub bit_depth: u8,
    pub color_type: u8,
}

/// Read the IHDR chunk that must follow the 8-byte signature.
pub(super) fn read_header(bytes: &[u8]) -> Result<PngHeader, MapError> {
    let corrupt = |d: &str| MapError::corrupt("PNG", d);
    if bytes.len() < 33 {
        return Err(corrupt("file ends inside the header"));
    }
    if bytes[..8] != SIGNATURE {
        return Err(corrupt("bad PNG signature"));
    }
    let be32 = |at: usize| u32::from_be_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]);
    if be32(8) != 13 || &bytes[12..16] != b"IHDR" {
        return Err(corrupt("first chunk is not a 13-byte IHDR"));
    }
    let header = PngHeader { width: be32(16), height: be32(20), bit_depth: bytes[24], color_type: bytes[25] };
    let depth_ok = match header.color_type {
        0 => matches!(header.bit_depth, 1 | 2 | 4 | 8 | 16),
        3 => matches!(header.bit_depth, 1 | 2 | 4 | 8),
        2 | 4 | 6 => matches!(header.bit_depth, 8 | 16),
        _ => return Err(corrupt(&format!("unknown colour type {}", header.color_type))),
    };
    if !depth_ok {
        return Err(corrupt(&format!(
            "bit depth {} is not allowed with colour type {}",
            header.bit_depth, header.color_type
        )));
    }
    Ok(header)
}

fn color_name(h: &PngHeader) -> String {
    let model = match h.color_type {
        0 => "grayscale",
        2 => "RGB",
        3 => "palette (indexed colour)",
        4 => "grayscale+alpha",
        _ => "RGBA",
    };
    format!("{}-bit {model}", h.bit_depth)
}

/// Refuse colour models and bit depths that the map kind does not accept.
fn check_pixel_format(h: &PngHeader, kind: MapKind) -> Result<(), MapError> {
    let gray = matches!(h.color_type, 0 | 4);
    match kind {
        MapKind::Continents => {
            const EXPECTED: &str = "continent bitmap must be 8-bit grayscale, white = land";
            if !gray {
                return Err(MapError::WrongColorType { expected: EXPECTED, got: color_name(h) });
            }
            if h.bit_depth > 8 {
                return Err(MapError::WrongBitDepth {
                    expected: "continent bitmap must be 8-bit grayscale",
                    got: format!("{}-bit", h.bit_depth),
                });
            }
        }
        MapKind::Elevation => {
            if !gray {
                return Err(MapError::WrongColorType {
                    expected: "elevation PNG must be 16-bit or 8-bit grayscale",
                    got: color_name(h),
                });
            }
        }
    }
    Ok(())
}

fn image_error(e: ImageError) -> MapError {
    match e {
        ImageError::Limits(l) => MapError::Unsupported(format!("PNG needs more decoder memory than allowed: {l}")),
        ImageError::Unsupported(u) => MapError::Unsupported(format!("PNG not supported: {u}")),
        other => MapError::corrupt("PNG", other),
    }
}

/// Decode a PNG map. `bounds` has already been validated (argument or GLOBE).
pub(super) fn decode(
    bytes: &[u8],
    kind: MapKind,
    range_m: Option<(f64, f64)>,
    bounds: GeoBounds,
    limits: &MapLimits,
) -> Result<Map, MapError> {
    let header = read_header(bytes)?;
    let pixels = check_dimensions(header.width, header.height, limits)?;
    check_pixel_format(&header, kind)?;
    let channels: u64 = match header.color_type {
        2 => 3,
        4 => 2,
        6 => 4,
        _ => 1,
    };
    let row_bytes = (u64::from(header.width) * channels * u64::from(header.bit_depth)).div_ceil(8);
    let filtered = u64::from(header.height) * (1 + row_bytes);
    // Deflate expands at most ~1032:1.
    check_plausible("PNG", header.width, header.height, filtered, bytes.len(), 1040)?;
    let range = match kind {
        MapKind::Elevation => Some(validate_range(range_m)?),
        MapKind::Continents => None,
    };

    // Budget for the decoder: the output buffer (at most 4 bytes per pixel for LA16) plus room
    // for row buffers, the inflate window and ancillary chunks.
    let mut img_limits = image::Limits::default();
    img_limits.max_image_width = Some(header.width);
    img_limits.max_image_height = Some(header.height);
    img_limits.max_alloc = Some(pixels.saturating_mul(4).saturating_add(16 << 20));

    let decoder = guard("PNG", || PngDecoder::with_limits(Cursor::new(bytes), img_limits).map_err(image_error))?;
    if decoder.dimensions() != (header.width, header.height) {
        return Err(MapError::corrupt("PNG", "decoder disagrees with IHDR size"));
    }
    let color = decoder.color_type();
    let (stride, wide) = match color {
        ColorType::L8 => (1, false),
        ColorType::La8 => (2, false),
        ColorType::L16 => (2, true),
        ColorType::La16 => (4, true),
        other => return Err(MapError::Unsupported(format!("PNG decodes to unexpected pixel layout {other:?}"))),
    };
    let total =
        usize::try_from(decoder.total_bytes()).map_err(|_| MapError::corrupt("PNG", "image does not fit in memory"))?;
    let mut buf = vec![0u8; total];
    guard("PNG", || decoder.read_image(&mut buf).map_err(image_error))?;

    // read_image hands 16-bit samples over in native byte order.
    let raw = buf.chunks_exact(stride).map(|px| {
        if wide {
            f64::from(u16::from_ne_bytes([px[0], px[1]])) / 65535.0
        } else {
            f64::from(px[0]) / 255.0
        }
    });
    let values: Vec<f32> = match range {
        Some((lo, hi)) => raw.map(|t| (lo + t * (hi - lo)) as f32).collect(),
        None => raw.map(|t| t as f32).collect(),
    };
    Map::from_values(kind, header.width, header.height, bounds, values)
}
