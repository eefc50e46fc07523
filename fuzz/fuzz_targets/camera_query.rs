//! The camera query of `view.glb`: `Camera::parse_query` on any text answers a camera or an
//! error naming a field; an accepted camera's normal form (the cache key and ETag input)
//! parses back to the same normal form.

#![no_main]

use libfuzzer_sys::fuzz_target;
use riverworld::adapt::Camera;

const RADIUS: f64 = 6_371_000.0;

fuzz_target!(|data: &[u8]| {
    let Ok(query) = std::str::from_utf8(data) else { return };
    match Camera::parse_query(query, RADIUS) {
        Ok((camera, _rest)) => {
            let norm = camera.to_query();
            let (again, rest) = Camera::parse_query(&norm, RADIUS).expect("the normal form parses");
            assert!(rest.is_empty(), "{norm}");
            assert_eq!(again.to_query(), norm);
        }
        Err(e) => assert!(!e.field.is_empty()),
    }
});
