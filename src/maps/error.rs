//! Errors from decoding and validating map inputs, each with a stable code and the request field
//! it belongs to, so that the HTTP layer can answer with a precise 4xx body.

/// Why a map input was refused. Every message names the problem in plain words.
#[derive(Debug, thiserror::Error)]
pub enum MapError {
    /// The upload is larger than [`super::MapLimits::max_bytes`].
    #[error("map is {bytes} bytes, over the limit of {max} bytes")]
    FileTooLarge { bytes: usize, max: usize },

    /// The bytes are not a PNG or TIFF image at all.
    #[error("map is not a PNG or TIFF image ({detail})")]
    NotAnImage { detail: String },

    /// A PNG or TIFF whose layout is valid but not accepted for this kind of map.
    #[error("{0}")]
    Unsupported(String),

    /// The header declares more pixels than [`super::MapLimits::max_pixels`].
    #[error("map is {width}x{height} = {pixels} pixels, over the limit of {max_pixels}")]
    ImageTooLarge { width: u32, height: u32, pixels: u64, max_pixels: u64 },

    /// The header declares zero columns or rows.
    #[error("map has zero width or height ({width}x{height})")]
    EmptyImage { width: u32, height: u32 },

    /// The sample bit depth or number format is not accepted for this kind of map.
    #[error("{expected} (got {got})")]
    WrongBitDepth { expected: &'static str, got: String },

    /// The colour model (RGB, palette, ...) is not accepted for this kind of map.
    #[error("{expected} (got {got})")]
    WrongColorType { expected: &'static str, got: String },

    /// A GeoTIFF with more than one band.
    #[error("elevation GeoTIFF must have a single band (got {bands} bands)")]
    WrongBandCount { bands: u16 },

    /// The file is damaged or cut short.
    #[error("{format} is truncated or corrupt: {detail}")]
    Corrupt { format: &'static str, detail: String },

    /// An elevation PNG came without `map_range`.
    #[error(
        "elevation PNG needs map_range MIN_M,MAX_M (the metres that the lowest and highest \
         pixel values stand for)"
    )]
    MissingMapRange,

    /// `map_range` is present but unusable.
    #[error("{0}")]
    InvalidMapRange(String),

    /// `map_bounds` (or bounds given in code) are unusable.
    #[error("map bounds W,S,E,N invalid: {0}")]
    InvalidBounds(String),

    /// The georeference tags inside a GeoTIFF are unusable.
    #[error("GeoTIFF georeference invalid: {0}")]
    InvalidGeoreference(String),

    /// `map_kind` is neither "continents" nor "elevation".
    #[error("map kind must be \"continents\" or \"elevation\" (got {0:?})")]
    UnknownKind(String),

    /// A value no map of its kind may hold (precipitation below 0 or above
    /// [`super::MAX_PRECIPITATION_MM`]), or no valid value at all.
    #[error("{0}")]
    OutOfRange(String),

    /// `map_kind` names a kind the file's format cannot hold (a GeoTIFF as continents).
    #[error("map kind {kind} does not fit the file: {hint}")]
    KindMismatch { kind: &'static str, hint: &'static str },
}

impl MapError {
    /// Stable snake_case code for API error bodies; never changes for a variant.
    pub fn code(&self) -> &'static str {
        match self {
            MapError::FileTooLarge { .. } => "file_too_large",
            MapError::NotAnImage { .. } | MapError::Unsupported(_) => "unsupported_format",
            MapError::ImageTooLarge { .. } => "image_too_large",
            MapError::EmptyImage { .. } => "empty_image",
            MapError::WrongBitDepth { .. } => "wrong_bit_depth",
            MapError::WrongColorType { .. } => "wrong_color_type",
            MapError::WrongBandCount { .. } => "wrong_band_count",
            MapError::Corrupt { .. } => "corrupt_image",
            MapError::MissingMapRange => "missing_map_range",
            MapError::InvalidMapRange(_) => "invalid_map_range",
            MapError::InvalidBounds(_) => "invalid_bounds",
            MapError::InvalidGeoreference(_) => "invalid_georeference",
            MapError::UnknownKind(_) => "invalid_map_kind",
            MapError::KindMismatch { .. } => "wrong_map_kind",
            MapError::OutOfRange(_) => "value_out_of_range",
        }
    }

    /// The request field the problem belongs to: "map", "map_range", "map_bounds" or "map_kind".
    pub fn field(&self) -> &'static str {
        match self {
            MapError::MissingMapRange | MapError::InvalidMapRange(_) => "map_range",
            MapError::InvalidBounds(_) => "map_bounds",
            MapError::UnknownKind(_) | MapError::KindMismatch { .. } => "map_kind",
            _ => "map",
        }
    }

    pub(crate) fn corrupt(format: &'static str, detail: impl std::fmt::Display) -> MapError {
        MapError::Corrupt { format, detail: detail.to_string() }
    }
}
