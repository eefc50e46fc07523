//! Precipitation maps: a planet's mean annual precipitation given by the user (like the humidity
//! map of Cortial et al. 2020), in place of the climate model's where the map covers the planet
//! (`planet::climate`). The same formats, limits and checks as elevation maps: a single-band
//! GeoTIFF in mm per year, or an 8/16-bit grayscale PNG with the millimetres of its darkest and
//! brightest values; equirectangular, the globe unless bounds are given (a GeoTIFF's own
//! georeference wins). Nodata pixels, and everything outside the bounds, keep the model's rain.

use super::{GeoBounds, Map, MapError, MapKind, MapLimits};

/// Most precipitation a pixel may hold, mm per year: above the wettest places measured
/// (Mawsynram and Cherrapunji, about 11,900 mm; Lloró, Colombia, about 13,300 mm).
pub const MAX_PRECIPITATION_MM: f32 = 30_000.0;

/// Decodes and checks a precipitation map: `range_mm` gives the millimetres of a PNG's lowest
/// and highest pixel values (required for PNGs, ignored for GeoTIFFs); every valid value must
/// lie in 0..=[`MAX_PRECIPITATION_MM`], and one at least must be valid.
pub fn decode_precipitation(
    bytes: &[u8],
    range_mm: Option<(f64, f64)>,
    bounds: Option<GeoBounds>,
    limits: &MapLimits,
) -> Result<Map, MapError> {
    if range_mm.is_none() && super::sniff(bytes).is_ok_and(|f| f == super::Format::Png) {
        return Err(MapError::InvalidMapRange(
            "a precipitation PNG needs a range MIN_MM,MAX_MM (the mm per year that the lowest and highest pixel \
             values stand for)"
                .into(),
        ));
    }
    let map = Map::decode(bytes, MapKind::Elevation, range_mm, bounds, limits)?;
    let Some((lo, hi)) = map.value_range() else {
        return Err(MapError::OutOfRange("the precipitation map has no valid pixel (all nodata)".into()));
    };
    if lo < 0.0 || hi > MAX_PRECIPITATION_MM {
        let bad = if lo < 0.0 { lo } else { hi };
        return Err(MapError::OutOfRange(format!(
            "precipitation must lie in 0..={MAX_PRECIPITATION_MM} mm per year (a pixel holds {bad})"
        )));
    }
    Ok(map)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maps::test_support::png_l16;

    #[test]
    fn precipitation_maps_are_checked_like_elevation_maps() {
        let limits = MapLimits::default();
        let png = png_l16(4, 2, &[0, 100, 200, 300, 400, 500, 600, 65535]);
        let map = decode_precipitation(&png, Some((0.0, 3000.0)), None, &limits).unwrap();
        assert_eq!((map.width, map.height), (4, 2));
        assert_eq!(map.value_range(), Some((0.0, 3000.0)));
        // A PNG needs its range; values must be rain.
        let e = decode_precipitation(&png, None, None, &limits).unwrap_err();
        assert_eq!((e.code(), e.field()), ("invalid_map_range", "map_range"), "{e}");
        let e = decode_precipitation(&png, Some((-10.0, 3000.0)), None, &limits).unwrap_err();
        assert_eq!(e.code(), "value_out_of_range", "{e}");
        let e = decode_precipitation(&png, Some((0.0, 40_000.0)), None, &limits).unwrap_err();
        assert!(e.to_string().contains("40000"), "{e}");
        // Not an image at all.
        let e = decode_precipitation(b"hello", Some((0.0, 1.0)), None, &limits).unwrap_err();
        assert_eq!(e.code(), "unsupported_format");
    }
}
