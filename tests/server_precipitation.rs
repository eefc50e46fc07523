//! A precipitation map as a planet's third input: stored with it, named in its id and record,
//! driving its rivers' discharge; a bad one refused naming its own fields.

mod server_common;

use serde_json::Value;
use server_common::*;

/// An 8-bit grayscale PNG of one value everywhere.
fn flat_png(w: u32, h: u32, value: u8) -> Vec<u8> {
    let img = image::GrayImage::from_pixel(w, h, image::Luma([value]));
    let mut out = std::io::Cursor::new(Vec::new());
    img.write_to(&mut out, image::ImageFormat::Png).unwrap();
    out.into_inner()
}

/// POSTs the small continent map, with a precipitation map and text parts.
async fn post(s: &TestServer, rain: Option<Vec<u8>>, parts: &[(&str, &str)]) -> reqwest::Response {
    let part = |b: Vec<u8>, name: &str| reqwest::multipart::Part::bytes(b).file_name(name.to_string());
    let mut form = reqwest::multipart::Form::new().part("map", part(small_map(), "map.png"));
    if let Some(bytes) = rain {
        form = form.part("precipitation", part(bytes, "rain.png"));
    }
    for (k, v) in [("params", FAST), ("seed", "1"), ("map_kind", "continents")].iter().chain(parts) {
        form = form.text(k.to_string(), v.to_string());
    }
    s.client.post(s.url("/v1/planets")).multipart(form).send().await.unwrap()
}

/// Total discharge over the reaches of a planet's rivers, and how many are perennial.
async fn rivers(s: &TestServer, id: &str) -> (f64, usize, usize) {
    let res = s.get(&format!("/v1/planets/{id}/rivers.geojson")).await;
    assert_eq!(res.status().as_u16(), 200);
    let json: Value = res.json().await.unwrap();
    let reaches: Vec<&Value> = json["features"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["properties"]["discharge_m3s"].is_number())
        .map(|f| &f["properties"])
        .collect();
    let total = reaches.iter().map(|p| p["discharge_m3s"].as_f64().unwrap()).sum();
    let perennial = reaches.iter().filter(|p| p["perennial"] == true).count();
    (total, perennial, reaches.len())
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_precipitation_map_drives_the_rivers_and_is_stored_with_the_planet() {
    let s = start(config(&scratch("precipitation"))).await;
    let model = post(&s, None, &[]).await;
    assert_eq!(model.status().as_u16(), 202);
    let model: Value = model.json().await.unwrap();
    let model = model["id"].as_str().unwrap().to_string();
    // 4,000 mm a year everywhere, and none anywhere: the same map and seed, other planets.
    let mut ids = Vec::new();
    for value in [255u8, 0] {
        let res = post(&s, Some(flat_png(36, 18, value)), &[("precipitation_range", "0,4000")]).await;
        assert_eq!(res.status().as_u16(), 202);
        let rec: Value = res.json().await.unwrap();
        assert_eq!(rec["precipitation"]["width"], 36, "{rec}");
        assert_eq!(rec["precipitation"]["range_mm"], serde_json::json!([0.0, 4000.0]));
        ids.push(rec["id"].as_str().unwrap().to_string());
    }
    assert!(ids[0] != model && ids[1] != model && ids[0] != ids[1], "{ids:?} {model}");
    let (wet, dry) = (&ids[0], &ids[1]);
    for id in [&model, wet, dry] {
        s.wait_ready(id).await;
    }
    assert!(s.dir.join(format!("planets/{wet}/precipitation.bin")).is_file());
    assert!(!s.dir.join(format!("planets/{model}/precipitation.bin")).exists());
    let (q_model, _, n) = rivers(&s, &model).await;
    let (q_wet, perennial_wet, _) = rivers(&s, wet).await;
    let (q_dry, perennial_dry, _) = rivers(&s, dry).await;
    assert!(n > 20, "{n} reaches");
    // Earth's land gets ~800 mm a year and loses about 60 % of it to evaporation.
    assert!(q_wet > 2.0 * q_model, "wet {q_wet} m³/s, model {q_model}");
    assert!(q_dry == 0.0 && perennial_dry == 0 && perennial_wet > 0, "dry {q_dry} m³/s, {perennial_dry} perennial");
    // The same inputs again: the same planet.
    let again = post(&s, Some(flat_png(36, 18, 255)), &[("precipitation_range", "0,4000")]).await;
    assert_eq!(again.status().as_u16(), 200);
    assert_eq!(again.json::<Value>().await.unwrap()["id"], wet.as_str());
    // Deleting a planet removes its precipitation map too.
    let res = s.client.delete(s.url(&format!("/v1/planets/{dry}"))).send().await.unwrap();
    assert!(res.status().is_success(), "{}", res.status());
    assert!(!s.dir.join(format!("planets/{dry}")).exists());
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_bad_precipitation_map_is_refused_naming_its_field() {
    let s = start(config(&scratch("precipitation-errors"))).await;
    let rain = || Some(flat_png(8, 4, 100));
    type Case<'a> = (Option<Vec<u8>>, &'a [(&'a str, &'a str)], u16, &'a str, &'a str);
    let cases: [Case; 6] = [
        (rain(), &[], 422, "invalid_map_range", "precipitation_range"),
        (rain(), &[("precipitation_range", "-4000,-100")], 422, "value_out_of_range", "precipitation"),
        (rain(), &[("precipitation_range", "4000")], 422, "invalid_map_range", "precipitation_range"),
        (
            rain(),
            &[("precipitation_range", "0,10"), ("precipitation_bounds", "10,0,5,1")],
            422,
            "invalid_bounds",
            "precipitation_bounds",
        ),
        (
            Some(b"not an image".to_vec()),
            &[("precipitation_range", "0,10")],
            415,
            "unsupported_format",
            "precipitation",
        ),
        (None, &[("precipitation_range", "0,4000")], 422, "missing_precipitation", "precipitation"),
    ];
    for (bytes, parts, status, code, field) in cases {
        let err = expect_error(post(&s, bytes, parts).await, status, code).await;
        assert_eq!(err["field"], field, "{err}");
    }
    // Nothing was stored.
    let list: Value = s.get("/v1/planets").await.json().await.unwrap();
    assert_eq!(list["planets"].as_array().unwrap().len(), 0, "{list}");
    s.stop().await;
}
