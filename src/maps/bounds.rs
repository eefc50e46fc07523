//! Geographic bounds of a map (plate carrée, degrees).

use serde::{Deserialize, Serialize};

use super::MapError;

/// Tolerance (degrees) for deciding that bounds span the whole globe.
const GLOBAL_EPS_DEG: f64 = 1e-9;

/// Bounds of an equirectangular map in degrees: west/east longitude, south/north latitude.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct GeoBounds {
    pub west: f64,
    pub south: f64,
    pub east: f64,
    pub north: f64,
}

impl GeoBounds {
    /// The whole sphere: 180°W..180°E, 90°S..90°N.
    pub const GLOBE: GeoBounds = GeoBounds { west: -180.0, south: -90.0, east: 180.0, north: 90.0 };

    /// Parse `"W,S,E,N"` (degrees, spaces allowed) and validate the result.
    pub fn parse(s: &str) -> Result<GeoBounds, MapError> {
        let parts: Vec<&str> = s.split(',').map(str::trim).collect();
        if parts.len() != 4 {
            return Err(MapError::InvalidBounds(format!(
                "expected 4 comma-separated numbers W,S,E,N, got {} ({s:?})",
                parts.len()
            )));
        }
        let mut v = [0.0f64; 4];
        for (slot, (part, name)) in v.iter_mut().zip(parts.iter().zip(["west", "south", "east", "north"])) {
            *slot =
                part.parse::<f64>().map_err(|_| MapError::InvalidBounds(format!("{name} {part:?} is not a number")))?;
        }
        let b = GeoBounds { west: v[0], south: v[1], east: v[2], north: v[3] };
        b.validate()?;
        Ok(b)
    }

    /// Latitude (degrees) of the centres of row `row` of `height` rows over the bounds.
    pub fn lat_of(&self, row: u32, height: u32) -> f64 {
        self.north - (row as f64 + 0.5) * (self.north - self.south) / height as f64
    }

    /// Longitude (degrees) of the centres of column `col` of `width` columns over the bounds.
    pub fn lon_of(&self, col: u32, width: u32) -> f64 {
        self.west + (col as f64 + 0.5) * (self.east - self.west) / width as f64
    }

    /// Check that all edges are finite, west < east, south < north and everything lies within
    /// ±180° longitude and ±90° latitude.
    pub fn validate(&self) -> Result<(), MapError> {
        let GeoBounds { west, south, east, north } = *self;
        let bad = |msg: String| Err(MapError::InvalidBounds(msg));
        if ![west, south, east, north].iter().all(|v| v.is_finite()) {
            return bad(format!("all four edges must be finite numbers (got {west},{south},{east},{north})"));
        }
        if west < -180.0 || east > 180.0 {
            return bad(format!("longitudes must lie within -180..180 (got west {west}, east {east})"));
        }
        if south < -90.0 || north > 90.0 {
            return bad(format!("latitudes must lie within -90..90 (got south {south}, north {north})"));
        }
        if west >= east {
            return bad(format!("west {west} must be below east {east}"));
        }
        if south >= north {
            return bad(format!("south {south} must be below north {north}"));
        }
        Ok(())
    }

    /// True when the bounds cover all longitudes (a full 360° span).
    pub fn spans_all_longitudes(&self) -> bool {
        self.east - self.west >= 360.0 - GLOBAL_EPS_DEG
    }

    /// True when the bounds cover the whole sphere.
    pub fn is_global(&self) -> bool {
        self.spans_all_longitudes() && self.south <= -90.0 + GLOBAL_EPS_DEG && self.north >= 90.0 - GLOBAL_EPS_DEG
    }

    /// Solid angle covered, in steradians (4π for the globe).
    pub fn area_steradians(&self) -> f64 {
        let dlon = (self.east - self.west).to_radians();
        dlon * (self.north.to_radians().sin() - self.south.to_radians().sin())
    }

    /// Map any longitude onto `[west, west + 360)`.
    pub(crate) fn unwrap_lon(&self, lon_deg: f64) -> f64 {
        let mut off = (lon_deg - self.west).rem_euclid(360.0);
        if off >= 360.0 {
            // rem_euclid can round up to the divisor for tiny negative inputs.
            off = 0.0;
        }
        self.west + off
    }

    /// Whether a point (longitude in any range) lies inside the bounds, edges included.
    pub fn contains(&self, lat_deg: f64, lon_deg: f64) -> bool {
        if !lat_deg.is_finite() || !lon_deg.is_finite() {
            return false;
        }
        if lat_deg < self.south || lat_deg > self.north {
            return false;
        }
        self.spans_all_longitudes() || self.unwrap_lon(lon_deg) <= self.east
    }
}
