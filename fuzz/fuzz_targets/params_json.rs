//! The planet request body: `PlanetRequest::from_json` on any text answers a validated request
//! or an error naming a field; an accepted request survives a JSON round trip unchanged.

#![no_main]

use libfuzzer_sys::fuzz_target;
use riverworld::params::PlanetRequest;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    match PlanetRequest::from_json(text) {
        Ok(request) => {
            request.params.validate().expect("an accepted request is valid");
            let json = serde_json::to_string(&request).expect("serialises");
            let again = PlanetRequest::from_json(&json).expect("the round trip parses");
            assert_eq!(again, request);
        }
        Err(e) => assert!(!e.field.is_empty() && !e.message.is_empty()),
    }
});
