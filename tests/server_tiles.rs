//! The 3D Tiles routes: `tileset.json`, tile contents and external tilesets answer as cached,
//! immutable files whose URIs resolve to one another, the same bytes the library writes; bad
//! tile names answer 422 or 404 as JSON errors.

mod server_common;

use riverworld::export::glb::Compression;
use riverworld::export::tiles::{PlanetTiles, TileKey};
use riverworld::params::Params;
use riverworld::planet::{build_planet, PlanetSpec};
use serde_json::Value;
use server_common::*;
use std::sync::Arc;

/// The URIs of a tileset file's tiles, in document order.
fn uris(tile: &Value, out: &mut Vec<String>) {
    if let Some(uri) = tile["content"]["uri"].as_str() {
        out.push(uri.to_string());
    }
    for child in tile["children"].as_array().into_iter().flatten() {
        uris(child, out);
    }
}

/// A server with one built planet of `seed` and `base_faces`, and the planet's id.
async fn server_with_planet(name: &str, seed: u64, base_faces: u32) -> (TestServer, String) {
    let s = start(config(&scratch(name))).await;
    let body = format!(r#"{{"seed": {seed}, "params": {{"base_faces": {base_faces}}}}}"#);
    let record: Value = s.post_json(&body).await.json().await.unwrap();
    let id = record["id"].as_str().unwrap().to_string();
    s.wait_ready(&id).await;
    (s, id)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn tilesets_and_tiles_are_served_and_resolve() {
    let (s, id) = server_with_planet("tiles", 31, 2000).await;
    let base = format!("/v1/planets/{id}");

    let res = s.get(&format!("{base}/tileset.json")).await;
    assert_eq!(res.status(), 200);
    assert_eq!(res.headers()["content-type"], "application/json");
    assert_eq!(res.headers()["cache-control"], "public, max-age=31536000, immutable");
    let tag = res.headers()["etag"].to_str().unwrap().to_string();
    let top: Value = res.json().await.unwrap();
    assert_eq!(top["asset"]["version"], "1.1");
    let again =
        s.client.get(s.url(&format!("{base}/tileset.json"))).header("if-none-match", &tag).send().await.unwrap();
    assert_eq!(again.status(), 304);

    // Every URI of the entry tileset resolves, and so does every URI of one external tileset.
    let mut top_uris = Vec::new();
    uris(&top["root"], &mut top_uris);
    assert_eq!(top_uris.len(), 8 + 32);
    for uri in &top_uris {
        let res = s.get(&format!("{base}/{uri}")).await;
        assert_eq!(res.status(), 200, "{uri}");
        let body = res.bytes().await.unwrap();
        if uri.ends_with(".glb") {
            assert_eq!(&body[..4], b"glTF", "{uri}");
        } else {
            let sub: Value = serde_json::from_slice(&body).unwrap();
            assert_eq!(sub["root"]["refine"], "REPLACE");
        }
    }
    let sub: Value = s.get(&format!("{base}/tiles/23.json")).await.json().await.unwrap();
    let mut sub_uris = Vec::new();
    uris(&sub["root"], &mut sub_uris);
    assert_eq!(sub_uris.len(), 1 + 4 + 16);
    for uri in &sub_uris {
        assert_eq!(s.get(&format!("{base}/tiles/{uri}")).await.status(), 200, "{uri}");
    }

    // The server's bytes are the library's for the same planet.
    let spec = PlanetSpec {
        seed: 31,
        params: Params { base_faces: 2000, ..Params::default() },
        map: None,
        precipitation: None,
    };
    let planet = Arc::new(build_planet(&spec, &mut |_, _| {}).unwrap());
    let tiles = PlanetTiles::new(planet, spec.params.clone()).unwrap();
    let key = TileKey::root(2).child(3).child(1);
    let served = s.get(&format!("{base}/tiles/231.glb")).await.bytes().await.unwrap();
    assert_eq!(served.as_ref(), tiles.content(key, Compression::Meshopt).glb.as_slice());

    // `compression=none`: plain contents, and tileset files whose URIs keep asking for them
    // (a client that also carries the tileset's query to them asks twice, alike: fine).
    let plain: Value = s.get(&format!("{base}/tileset.json?compression=none")).await.json().await.unwrap();
    let mut plain_uris = Vec::new();
    uris(&plain["root"], &mut plain_uris);
    assert_eq!(plain_uris.len(), top_uris.len());
    for (p, u) in plain_uris.iter().zip(&top_uris) {
        assert_eq!(p, &format!("{u}?compression=none"));
    }
    let sub: Value = s.get(&format!("{base}/tiles/23.json?compression=none")).await.json().await.unwrap();
    assert!(sub["root"]["content"]["uri"].as_str().unwrap().ends_with(".glb?compression=none"));
    for query in ["compression=none", "compression=none&compression=none"] {
        let res = s.get(&format!("{base}/tiles/231.glb?{query}")).await;
        assert_eq!(res.status(), 200);
        assert_ne!(res.headers()["etag"].to_str().unwrap(), tag, "another answer, another tag");
        assert_eq!(res.bytes().await.unwrap().as_ref(), tiles.content(key, Compression::None).glb.as_slice());
    }
    let explicit = s.get(&format!("{base}/tiles/231.glb?compression=meshopt")).await.bytes().await.unwrap();
    assert_eq!(explicit, served);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bad_tile_names_answer_json_errors() {
    let (s, id) = server_with_planet("tiles-errors", 32, 500).await;
    let base = format!("/v1/planets/{id}/tiles");
    for bad in ["8.glb", "0.png", "0a.glb", "..%2F0.glb", ".glb", "01.glb.json", "0%00.glb"] {
        let err = expect_error(s.get(&format!("{base}/{bad}")).await, 422, "invalid_tile").await;
        assert_eq!(err["field"], "tile", "{bad}");
    }
    // Deeper than level 21, a tileset below a tile that starts none, an unknown planet.
    expect_error(s.get(&format!("{base}/0{}.glb", "0".repeat(22))).await, 404, "not_found").await;
    expect_error(s.get(&format!("{base}/000.json")).await, 404, "not_found").await;
    expect_error(s.get(&format!("{base}/0.json")).await, 404, "not_found").await;
    expect_error(s.get("/v1/planets/ffffffffffffffff/tiles/0.glb").await, 404, "not_found").await;
    expect_error(s.get("/v1/planets/ffffffffffffffff/tileset.json").await, 404, "not_found").await;
    // The one query parameter, with a value it knows, once (or repeated alike).
    for (query, code, field) in [
        ("compression=draco", "invalid_parameter", "compression"),
        ("compression=none&compression=meshopt", "duplicate_parameter", "compression"),
        ("level=3", "unknown_parameter", "level"),
    ] {
        for path in [format!("{base}/0.glb?{query}"), format!("/v1/planets/{id}/tileset.json?{query}")] {
            let err = expect_error(s.get(&path).await, 422, code).await;
            assert_eq!(err["field"], field, "{path}");
        }
    }
    // Paths with more segments are no route.
    expect_error(s.get(&format!("{base}/0/1.glb")).await, 404, "not_found").await;
    s.stop().await;
}
