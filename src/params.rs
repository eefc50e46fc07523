//! Planet parameters (paper Table 2) with the paper's defaults, their JSON shape and validation.
//!
//! One JSON shape everywhere: `{"seed": 42, "params": {...}}`. Names are snake_case and carry their
//! unit; unknown fields are errors. Altitudes are measured from the base sphere of radius
//! `radius_m`, as in the paper (sea level `sea_level_m` above it); exports convert to metres
//! relative to sea level.

use serde::{Deserialize, Serialize};

/// The colours of the 2D climate lookup texture (§3.3) used by previews and renders.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Climate {
    /// Earth-like: ice caps, tundra, forest, desert belts, rock and snow line.
    #[default]
    Temperate,
    /// Dry: deserts and steppe, little ice.
    Arid,
    /// Cold: wide ice caps, tundra and snow down to low altitude.
    Frozen,
}

/// Where the parameters not given take their values from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Preset {
    /// Earth-like altitudes and river gradients (the default): see [`Params::earth`].
    #[default]
    Earth,
    /// The paper's Table 2 exactly: see [`Params::paper`].
    Paper,
}

/// The parameters of a planet: the paper's Table 2 plus the preset they start from and the
/// climate of the colours. Given fields override the preset's values.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The preset the other fields' defaults come from.
    pub preset: Preset,
    /// r: radius of the base sphere.
    pub radius_m: f64,
    /// Number of continents grown when no map is given.
    pub continents: u32,
    /// Land area as a percentage of the planet's surface (random continents).
    pub land_percent: f64,
    /// Triangles of the base shape (the octahedron is refined to about this many).
    pub base_faces: u32,
    /// Minimum edge length for adaption.
    pub min_edge_length_m: f64,
    /// a_max_river: highest altitude of a river spring.
    pub max_river_altitude_m: f64,
    /// a_max_mountain: highest mountain altitude.
    pub max_mountain_altitude_m: f64,
    /// epsilon_sea: global water level above the base sphere.
    pub sea_level_m: f64,
    /// epsilon_river: river depth at the mouth.
    pub max_river_depth_m: f64,
    /// l_rmin: minimum river length; shorter edges are smoothed (eq. 8) and get no new arms.
    pub min_river_length_m: f64,
    /// s_r: minimum slope of a river's water surface.
    pub min_river_slope_m_per_km: f64,
    /// s_rb: minimum slope of a riverbed's banks.
    pub min_riverbed_slope_m_per_km: f64,
    /// s_p: minimum slope of the ground near a river.
    pub min_slope_near_river_m_per_km: f64,
    /// epsilon_rb: height of a riverbed's edge above the water.
    pub riverbed_edge_height_m: f64,
    /// s_g: maximum ground slope.
    pub max_ground_slope_m_per_km: f64,
    /// Planets without an elevation map: how much mountain belts lift the land (their ridges
    /// by this much, small rivers nearly as much, great rivers less, as they cut gorges); 0
    /// for none (the paper).
    pub mountain_belt_uplift_m: f64,
    /// The 2D climate lookup texture.
    pub climate: Climate,
}

impl Default for Params {
    /// The `earth` preset.
    fn default() -> Params {
        Params::earth()
    }
}

impl Params {
    /// The values of a preset.
    pub fn preset(preset: Preset) -> Params {
        match preset {
            Preset::Earth => Params::earth(),
            Preset::Paper => Params::paper(),
        }
    }

    /// Earth-like values: the paper's shape with Earth's land hypsometry and river gradients.
    /// Rivers spring at most 1.5 km above sea level, mountain belts lift ranges 3 km more and
    /// mountains reach 8.8 km, so that most land lies a few hundred metres up with 1-2 % above
    /// 4 km (the shipped continent bitmap, seed 42: median 579 m, 90th percentile 1,407 m, 99th
    /// 4,350 m, 1.4 % above 4 km; Earth: ~440 m, ~2 km, ~4.5 km, 1-2 %); water surfaces fall at
    /// least 1 cm per km (the lower Amazon falls 2-3 cm/km, the lower Mississippi ~4 cm/km); a
    /// great river's channel is some 20 m deep at its mouth; and riverbanks rise 5 m plus 0.1 m
    /// per km above the water, as a floodplain does. Land covers 29 % of a random planet, as on
    /// Earth.
    pub fn earth() -> Params {
        let sea = 3_000.0;
        Params {
            preset: Preset::Earth,
            land_percent: 29.0,
            max_river_altitude_m: sea + 1_500.0,
            max_mountain_altitude_m: sea + 8_800.0,
            max_river_depth_m: 20.0,
            min_river_slope_m_per_km: 0.01,
            min_slope_near_river_m_per_km: 0.1,
            riverbed_edge_height_m: 5.0,
            mountain_belt_uplift_m: 3_000.0,
            ..Params::paper()
        }
    }

    /// Table 2 of the paper.
    pub fn paper() -> Params {
        Params {
            preset: Preset::Paper,
            radius_m: 6_371_000.0,
            continents: 6,
            land_percent: 50.0,
            base_faces: 5000,
            min_edge_length_m: 0.01,
            max_river_altitude_m: 12_000.0,
            max_mountain_altitude_m: 13_000.0,
            sea_level_m: 3_000.0,
            max_river_depth_m: 300.0,
            min_river_length_m: 200_000.0,
            min_river_slope_m_per_km: 1.0,
            min_riverbed_slope_m_per_km: 300.0,
            min_slope_near_river_m_per_km: 1.0,
            riverbed_edge_height_m: 10.0,
            max_ground_slope_m_per_km: 1000.0,
            mountain_belt_uplift_m: 0.0,
            climate: Climate::Temperate,
        }
    }
}

/// The request body that defines a planet: a seed and the parameters.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct PlanetRequest {
    pub seed: u64,
    pub params: Params,
}

/// A parameter outside its allowed range.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{field}: {message}")]
pub struct ParamError {
    /// Dotted path of the field, e.g. `params.land_percent`.
    pub field: String,
    pub message: String,
}

/// Most faces a base mesh may have.
pub const MAX_BASE_FACES: u32 = 4_194_304;

impl Params {
    /// Checks every field against its allowed range; the error names the field and the range.
    pub fn validate(&self) -> Result<(), ParamError> {
        let sea = self.sea_level_m;
        let range = |name: &str, v: f64, lo: f64, hi: f64, open_lo: bool, unit: &str| {
            let ok = v.is_finite() && (if open_lo { v > lo } else { v >= lo }) && v <= hi;
            if ok {
                Ok(())
            } else {
                let l = if open_lo { "(" } else { "[" };
                Err(ParamError {
                    field: format!("params.{name}"),
                    message: format!(
                        "must be in {l}{lo}, {hi}]{}, got {v}",
                        if unit.is_empty() { String::new() } else { format!(" {unit}") }
                    ),
                })
            }
        };
        range("radius_m", self.radius_m, 1_000.0, 1.0e8, false, "m")?;
        range("continents", self.continents as f64, 1.0, 64.0, false, "")?;
        range("land_percent", self.land_percent, 0.0, 100.0, true, "%")?;
        if self.land_percent >= 100.0 {
            return Err(ParamError {
                field: "params.land_percent".into(),
                message: format!("must be in (0, 100) %, got {}", self.land_percent),
            });
        }
        range("base_faces", self.base_faces as f64, 8.0, MAX_BASE_FACES as f64, false, "")?;
        range("min_edge_length_m", self.min_edge_length_m, 0.001, 10_000.0, false, "m")?;
        range("sea_level_m", sea, 0.0, 100_000.0, true, "m")?;
        range("max_river_depth_m", self.max_river_depth_m, 0.0, sea, true, "m (below sea_level_m)")?;
        range("max_river_altitude_m", self.max_river_altitude_m, sea, 200_000.0, true, "m (above sea_level_m)")?;
        range(
            "max_mountain_altitude_m",
            self.max_mountain_altitude_m,
            self.max_river_altitude_m,
            200_000.0,
            false,
            "m (at least max_river_altitude_m)",
        )?;
        range(
            "mountain_belt_uplift_m",
            self.mountain_belt_uplift_m,
            0.0,
            self.max_mountain_altitude_m - self.max_river_altitude_m,
            false,
            "m (at most max_mountain_altitude_m - max_river_altitude_m)",
        )?;
        range("min_river_length_m", self.min_river_length_m, 0.0, 1.0e8, true, "m")?;
        range("min_river_slope_m_per_km", self.min_river_slope_m_per_km, 0.0, 1_000.0, true, "m/km")?;
        range("min_riverbed_slope_m_per_km", self.min_riverbed_slope_m_per_km, 0.0, 100_000.0, true, "m/km")?;
        range("min_slope_near_river_m_per_km", self.min_slope_near_river_m_per_km, 0.0, 100_000.0, false, "m/km")?;
        range("riverbed_edge_height_m", self.riverbed_edge_height_m, 0.0, 10_000.0, false, "m")?;
        range(
            "max_ground_slope_m_per_km",
            self.max_ground_slope_m_per_km,
            self.min_riverbed_slope_m_per_km.max(self.min_river_slope_m_per_km),
            1.0e6,
            false,
            "m/km (at least min_riverbed_slope_m_per_km)",
        )?;
        Ok(())
    }

    /// Slopes as plain ratios (m per m).
    pub fn river_slope(&self) -> f64 {
        self.min_river_slope_m_per_km / 1000.0
    }
    pub fn riverbed_slope(&self) -> f64 {
        self.min_riverbed_slope_m_per_km / 1000.0
    }
    pub fn near_river_slope(&self) -> f64 {
        self.min_slope_near_river_m_per_km / 1000.0
    }
    pub fn ground_slope(&self) -> f64 {
        self.max_ground_slope_m_per_km / 1000.0
    }
    /// Ground altitude of a river mouth: `epsilon_sea - epsilon_river`.
    pub fn mouth_ground(&self) -> f64 {
        self.sea_level_m - self.max_river_depth_m
    }
}

impl PlanetRequest {
    /// Parses and validates a JSON request; syntax errors and unknown fields name the place.
    pub fn from_json(text: &str) -> Result<PlanetRequest, ParamError> {
        let body = |message: String| ParamError { field: "body".into(), message };
        let value: serde_json::Value = serde_json::from_str(text).map_err(|e| {
            // A number out of range (1e999) stops the parse inside a field: name that field.
            let mut de = serde_json::Deserializer::from_str(text);
            let field = match serde_path_to_error::deserialize::<_, PlanetRequest>(&mut de) {
                _ if e.is_eof() => "body".to_string(),
                // Only a path into the object names a field; an array body or the root is the body.
                Err(pe)
                    if !matches!(pe.path().to_string().as_str(), "." | "")
                        && !pe.path().to_string().starts_with('[') =>
                {
                    pe.path().to_string()
                }
                _ => "body".to_string(),
            };
            ParamError { field, message: e.to_string() }
        })?;
        if !value.is_object() {
            return Err(body("expected a JSON object {\"seed\": N, \"params\": {...}}".into()));
        }
        if let Some(path) = duplicate_key(text) {
            // An empty key at the top has no path: the body names it.
            let field = if path.is_empty() { "body".to_string() } else { path };
            return Err(ParamError { field, message: "the key is given twice; give it once".into() });
        }
        let value = with_preset_defaults(value);
        let req: PlanetRequest = serde_path_to_error::deserialize(value).map_err(|e| {
            let path = e.path().to_string();
            let inner = e.into_inner();
            let field = if path == "." || path.is_empty() { "body".to_string() } else { path };
            ParamError { field, message: inner.to_string() }
        })?;
        req.params.validate()?;
        Ok(req)
    }
}

/// The dotted path of the first key that one JSON object of `text` (valid JSON) gives twice,
/// which a parse into a map would settle silently by keeping the last.
fn duplicate_key(text: &str) -> Option<String> {
    use serde::de::{DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
    struct Walk<'a>(&'a mut Option<String>, String);
    impl<'de> DeserializeSeed<'de> for Walk<'_> {
        type Value = ();
        fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
            d.deserialize_any(self)
        }
    }
    impl<'de> Visitor<'de> for Walk<'_> {
        type Value = ();
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("JSON")
        }
        fn visit_bool<E>(self, _: bool) -> Result<(), E> {
            Ok(())
        }
        fn visit_i64<E>(self, _: i64) -> Result<(), E> {
            Ok(())
        }
        fn visit_u64<E>(self, _: u64) -> Result<(), E> {
            Ok(())
        }
        fn visit_f64<E>(self, _: f64) -> Result<(), E> {
            Ok(())
        }
        fn visit_str<E>(self, _: &str) -> Result<(), E> {
            Ok(())
        }
        fn visit_unit<E>(self) -> Result<(), E> {
            Ok(())
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
            let Walk(found, path) = self;
            let mut i = 0;
            while seq.next_element_seed(Walk(&mut *found, format!("{path}[{i}]")))?.is_some() {
                i += 1;
            }
            Ok(())
        }
        fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
            let Walk(found, path) = self;
            let mut seen = std::collections::HashSet::new();
            while let Some(key) = map.next_key::<String>()? {
                let at = if path.is_empty() { key.clone() } else { format!("{path}.{key}") };
                if !seen.insert(key) && found.is_none() {
                    *found = Some(at.clone());
                }
                map.next_value_seed(Walk(&mut *found, at))?;
            }
            Ok(())
        }
    }
    let mut found = None;
    let mut de = serde_json::Deserializer::from_str(text);
    Walk(&mut found, String::new()).deserialize(&mut de).ok()?;
    found
}

/// Fills the fields a request's `params` leaves out from its `preset` (default `earth`). A
/// `preset` that names none is left for the deserializer to refuse by name.
fn with_preset_defaults(mut value: serde_json::Value) -> serde_json::Value {
    let Some(params) = value.get_mut("params").and_then(|p| p.as_object_mut()) else {
        return value;
    };
    let preset = match params.get("preset") {
        None => Preset::Earth,
        Some(p) => match serde_json::from_value::<Preset>(p.clone()) {
            Ok(p) => p,
            Err(_) => return value,
        },
    };
    let serde_json::Value::Object(mut full) = serde_json::to_value(Params::preset(preset)).expect("params serialise")
    else {
        unreachable!("params serialise as an object")
    };
    for (k, v) in std::mem::take(params) {
        full.insert(k, v);
    }
    *params = full;
    value
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_paper_preset_is_table_2_and_earth_is_the_default() {
        let p = Params::paper();
        assert_eq!(p.radius_m, 6_371_000.0);
        assert_eq!(p.base_faces, 5000);
        assert_eq!(p.sea_level_m, 3000.0);
        assert_eq!((p.max_river_altitude_m, p.max_mountain_altitude_m), (12_000.0, 13_000.0));
        assert_eq!((p.max_river_depth_m, p.min_river_slope_m_per_km), (300.0, 1.0));
        assert_eq!(p.max_ground_slope_m_per_km, 1000.0);
        p.validate().unwrap();
        let e = Params::default();
        assert_eq!(e, Params::earth());
        assert_eq!(e.preset, Preset::Earth);
        assert_eq!(e.min_river_slope_m_per_km, 0.01);
        e.validate().unwrap();
    }

    #[test]
    fn a_preset_fills_what_the_request_leaves_out() {
        let req = PlanetRequest::from_json(r#"{"params": {"preset": "paper", "continents": 3}}"#).unwrap();
        assert_eq!(req.params, Params { continents: 3, ..Params::paper() });
        let req = PlanetRequest::from_json(r#"{"params": {"max_river_depth_m": 50}}"#).unwrap();
        assert_eq!(req.params, Params { max_river_depth_m: 50.0, ..Params::earth() });
        // A stored request (every field given) reads back the same, whatever its preset.
        let text = serde_json::to_string(&PlanetRequest { seed: 1, params: Params::paper() }).unwrap();
        assert_eq!(PlanetRequest::from_json(&text).unwrap().params, Params::paper());
        let e = PlanetRequest::from_json(r#"{"params": {"preset": "mars"}}"#).unwrap_err();
        assert_eq!(e.field, "params.preset", "{e}");
    }

    #[test]
    fn json_round_trip_and_partial_bodies() {
        let req = PlanetRequest::from_json(r#"{"seed": 7, "params": {"continents": 3}}"#).unwrap();
        assert_eq!(req.seed, 7);
        assert_eq!(req.params.continents, 3);
        assert_eq!(req.params.land_percent, 29.0);
        let text = serde_json::to_string(&req).unwrap();
        assert_eq!(PlanetRequest::from_json(&text).unwrap(), req);
        assert_eq!(PlanetRequest::from_json("{}").unwrap().params, Params::default());
        // Digits past what an f64 holds parse to the nearest f64, so the shortest form printed
        // back parses to the same number (found by fuzzing: the default parser was one ulp off).
        let long = r#"{"params": {"radius_m": 3985029, "land_percent": 30.5555555555555484550}}"#;
        let req = PlanetRequest::from_json(long).unwrap();
        let text = serde_json::to_string(&req).unwrap();
        assert_eq!(PlanetRequest::from_json(&text).unwrap(), req);
    }

    #[test]
    fn unknown_fields_are_errors_naming_them() {
        let e = PlanetRequest::from_json(r#"{"params": {"radius": 5}}"#).unwrap_err();
        assert!(e.message.contains("radius"), "{e}");
        let e = PlanetRequest::from_json(r#"{"sede": 1}"#).unwrap_err();
        assert_eq!(e.field, "sede");
        let e = PlanetRequest::from_json(r#"{"params": {"climate": "tropical"}}"#).unwrap_err();
        assert!(e.message.contains("tropical"), "{e}");
    }

    #[test]
    fn out_of_range_values_name_the_field() {
        let bad = [
            (r#"{"params": {"land_percent": 0}}"#, "params.land_percent"),
            (r#"{"params": {"land_percent": 100}}"#, "params.land_percent"),
            (r#"{"params": {"radius_m": -1}}"#, "params.radius_m"),
            (r#"{"params": {"base_faces": 4}}"#, "params.base_faces"),
            (r#"{"seed": 1, "seed": 2}"#, "seed"),
            (r#"{"see": 3, "": 3, "": 3, "ams": {"radius_m": ""}}"#, "body"),
            (
                r#"{"seed": 1, "params": {"land_percent": 20, "sea_level_m": 0, "land_percent": 30}}"#,
                "params.land_percent",
            ),
            (r#"{"params": {"max_river_depth_m": 5000}}"#, "params.max_river_depth_m"),
            (r#"{"params": {"max_mountain_altitude_m": 100}}"#, "params.max_mountain_altitude_m"),
            (r#"{"params": {"continents": 0}}"#, "params.continents"),
            (r#"{"params": {"max_ground_slope_m_per_km": 10}}"#, "params.max_ground_slope_m_per_km"),
            (r#"{"params": {"continents": 2.5}}"#, "params.continents"),
        ];
        for (body, field) in bad {
            let e = PlanetRequest::from_json(body).unwrap_err();
            assert_eq!(e.field, field, "{body}: {e}");
        }
        for body in ["[1,2", "{\"seed\": ", "not json", "[1, {}]"] {
            assert_eq!(PlanetRequest::from_json(body).unwrap_err().field, "body", "{body}");
        }
    }

    #[test]
    fn non_finite_values_are_rejected() {
        let p = Params { sea_level_m: f64::NAN, ..Params::default() };
        assert_eq!(p.validate().unwrap_err().field, "params.sea_level_m");
        let p = Params { radius_m: f64::INFINITY, ..Params::default() };
        assert_eq!(p.validate().unwrap_err().field, "params.radius_m");
    }
}
