//! Uploaded maps: `Map::decode` on arbitrary bytes must answer Ok or a `MapError`, never crash,
//! hang or allocate beyond its limits. The first byte picks the map kind, a metre range and
//! regional bounds; the rest is the file.

#![no_main]

use libfuzzer_sys::fuzz_target;
use riverworld::maps::{GeoBounds, Map, MapKind, MapLimits};

fuzz_target!(
    init: {
        // Third-party decoders may panic on malformed data; `Map::decode` catches that and
        // answers a corrupt-image error, so such panics are not failures. A panic that escapes
        // `decode` still aborts the run.
        std::panic::set_hook(Box::new(|_| {}));
    },
    |data: &[u8]| {
        let Some((&selector, bytes)) = data.split_first() else { return };
        let kind = if selector & 1 == 0 { MapKind::Continents } else { MapKind::Elevation };
        let range = (selector & 2 != 0).then_some((-500.0, 4000.0));
        let bounds = (selector & 4 != 0).then_some(GeoBounds { west: -10.0, south: 30.0, east: 20.0, north: 60.0 });
        let limits = MapLimits { max_pixels: 1 << 22, max_bytes: 1 << 24 };
        if let Ok(map) = Map::decode(bytes, kind, range, bounds, &limits) {
            let pixels = u64::from(map.width) * u64::from(map.height);
            assert!(pixels > 0 && pixels <= limits.max_pixels);
            assert_eq!(map.values().len() as u64, pixels);
            let _ = map.sample(45.0, 5.0);
            let _ = map.land_fraction();
        }
    }
);
