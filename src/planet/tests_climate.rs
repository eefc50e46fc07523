//! The planet's climate against the real one: precipitation at stations of every climate
//! (climate normals, WMO 1991-2020 where published, rounded), and the ground's colours at
//! places of known Köppen class, on the shipped Earth DEM.

use crate::maps::{Map, MapKind, MapLimits};
use crate::planet::climate::{Climate, HEIGHT, WIDTH};

/// The shipped Earth DEM, if the file is there.
fn earth_map() -> Option<Map> {
    let bytes = std::fs::read("maps/earth_etopo5_1024x512.tif").ok()?;
    Some(Map::decode(&bytes, MapKind::Elevation, None, None, &MapLimits::default()).unwrap())
}

/// The climate of the DEM's land and altitudes on the climate's grid.
fn earth_climate(map: &Map) -> Climate {
    let cells: Vec<(bool, f64)> = (0..WIDTH * HEIGHT)
        .map(|i| {
            let (lat, lon) = (89.5 - (i / WIDTH) as f64, -179.5 + (i % WIDTH) as f64);
            let h = f64::from(map.sample(lat, lon).unwrap_or(0.0));
            (h > 0.0, h.max(0.0))
        })
        .collect();
    Climate::new(&cells)
}

/// Mean annual precipitation (mm) at stations of every climate, from their climate normals.
const STATIONS: [(&str, f64, f64, f64); 37] = [
    ("Manaus", -3.1, -60.0, 2300.0),
    ("Kinshasa", -4.3, 15.3, 1400.0),
    ("Mbandaka", 0.05, 18.26, 1700.0),
    ("Cairo", 30.0, 31.2, 25.0),
    ("Khartoum", 15.6, 32.5, 120.0),
    ("Timbuktu", 16.8, -3.0, 200.0),
    ("N'Djamena", 12.1, 15.0, 550.0),
    ("Riyadh", 24.7, 46.7, 100.0),
    ("Chicago", 41.9, -87.6, 950.0),
    ("Thunder Bay", 48.4, -89.2, 710.0),
    ("Toronto", 43.7, -79.4, 830.0),
    ("Montreal", 45.5, -73.6, 1000.0),
    ("Las Vegas", 36.2, -115.1, 110.0),
    ("Salt Lake City", 40.8, -111.9, 400.0),
    ("Seattle", 47.6, -122.3, 950.0),
    ("Denver", 39.7, -105.0, 400.0),
    ("Atlanta", 33.7, -84.4, 1250.0),
    ("London", 51.5, 0.0, 600.0),
    ("Moscow", 55.7, 37.6, 700.0),
    ("Astrakhan", 46.3, 48.0, 230.0),
    ("Aralsk", 45.0, 60.0, 130.0),
    ("Tashkent", 41.3, 69.3, 440.0),
    ("Lop Nur", 40.2, 90.3, 20.0),
    ("Ulaanbaatar", 47.9, 106.9, 250.0),
    ("Chengdu", 30.7, 104.1, 900.0),
    ("Chongqing", 29.6, 106.5, 1100.0),
    ("Beijing", 40.0, 116.4, 570.0),
    ("Delhi", 28.6, 77.2, 800.0),
    ("Guwahati", 26.1, 91.7, 1700.0),
    ("Manila", 14.6, 121.0, 2000.0),
    ("Yakutsk", 62.0, 129.7, 240.0),
    ("Alice Springs", -23.7, 133.9, 280.0),
    ("Sydney", -33.9, 151.2, 1200.0),
    ("Buenos Aires", -34.6, -58.4, 1200.0),
    ("Kampala", 0.3, 32.6, 1300.0),
    ("Kigoma", -4.9, 29.6, 950.0),
    ("Tehran", 35.7, 51.4, 230.0),
];

/// More stations: the monsoon plains and the humid subtropics that a latitude belt would call
/// desert, the subtropical deserts (hyper-arid normals count as 25 mm below), coasts beside cold
/// currents, the continents' interiors.
const MORE_STATIONS: [(&str, f64, f64, f64); 60] = [
    ("Patna", 25.6, 85.1, 1100.0),
    ("Lucknow", 26.8, 80.9, 1000.0),
    ("Dhaka", 23.8, 90.4, 2100.0),
    ("Guangzhou", 23.1, 113.3, 1800.0),
    ("Changsha", 28.2, 112.9, 1400.0),
    ("Hanoi", 21.0, 105.8, 1680.0),
    ("Houston", 29.8, -95.4, 1260.0),
    ("Tallahassee", 30.4, -84.3, 1500.0),
    ("Brisbane", -27.5, 152.8, 1150.0),
    ("Sao Paulo", -23.5, -46.6, 1450.0),
    ("Asuncion", -25.3, -57.6, 1400.0),
    ("Pietermaritzburg", -29.6, 30.4, 980.0),
    ("Kunming", 25.0, 102.7, 1000.0),
    ("Yangon", 16.8, 96.2, 2700.0),
    ("In Salah", 27.2, 2.5, 17.0),
    ("Faya", 18.0, 19.2, 16.0),
    ("Tamanrasset", 22.8, 5.5, 45.0),
    ("Jaisalmer", 26.9, 70.9, 210.0),
    ("Hotan", 37.1, 79.9, 40.0),
    ("Ejin", 41.95, 101.07, 35.0),
    ("Nukus", 42.5, 59.6, 100.0),
    ("Calama", -22.5, -68.9, 5.0),
    ("Gobabeb", -23.6, 15.0, 25.0),
    ("Barstow", 34.9, -117.0, 110.0),
    ("Yuma", 32.7, -114.6, 85.0),
    ("Zahedan", 29.5, 60.9, 85.0),
    ("Baghdad", 33.3, 44.4, 150.0),
    ("Windhoek", -22.6, 17.1, 360.0),
    ("Niamey", 13.5, 2.1, 560.0),
    ("Phoenix", 33.4, -112.0, 200.0),
    ("Lima", -12.0, -76.8, 15.0),
    ("Karachi", 24.9, 67.0, 170.0),
    ("Muscat", 23.6, 58.4, 100.0),
    ("Perth", -31.9, 115.9, 730.0),
    ("Kalgoorlie", -30.7, 121.5, 270.0),
    ("Santiago", -33.4, -70.7, 330.0),
    ("Johannesburg", -26.2, 28.0, 710.0),
    ("Mumbai", 19.1, 72.9, 2200.0),
    ("Nairobi", -1.3, 36.8, 900.0),
    ("Addis Ababa", 9.0, 38.7, 1100.0),
    ("Mexico City", 19.4, -99.1, 820.0),
    ("Monterrey", 25.7, -100.3, 650.0),
    ("Dallas", 32.8, -96.8, 950.0),
    ("Kansas City", 39.1, -94.6, 1000.0),
    ("Novosibirsk", 55.0, 82.9, 430.0),
    ("Omsk", 55.0, 73.4, 400.0),
    ("Irkutsk", 52.3, 104.3, 480.0),
    ("Urumqi", 43.8, 87.6, 290.0),
    ("Kabul", 34.5, 69.2, 330.0),
    ("Ankara", 39.9, 32.9, 400.0),
    ("Madrid", 40.4, -3.7, 420.0),
    ("Kolkata", 22.6, 88.4, 1600.0),
    ("Nagpur", 21.1, 79.1, 1100.0),
    ("Wuhan", 30.6, 114.3, 1300.0),
    ("Brasilia", -15.8, -47.9, 1500.0),
    ("Cuiaba", -15.6, -56.1, 1400.0),
    ("Darwin", -12.4, 130.9, 1700.0),
    ("Tindouf", 27.7, -8.1, 50.0),
    ("Agadez", 17.0, 8.0, 160.0),
    ("Aswan", 24.1, 32.9, 1.0),
];

#[test]
fn precipitation_is_within_a_factor_of_two_at_most_stations() {
    let Some(map) = earth_map() else { return };
    let c = earth_climate(&map);
    let ratios: Vec<(&str, f64)> = STATIONS.iter().map(|s| (s.0, c.precip_at(s.1, s.2) / s.3)).collect();
    let within = ratios.iter().filter(|r| (0.5..=2.0).contains(&r.1)).count();
    // Measured 23 of 37 (docs/realism.md; 22 before the monsoon's reach and the wet land's
    // gain); deserts come out too wet, the humid subtropics too dry.
    assert!(within >= 21, "{ratios:?}");
    // Wet tropics far above deserts.
    assert!(c.precip_at(0.05, 18.26) > 3.0 * c.precip_at(16.8, -3.0));
    // Over all 97 stations, the mean factor off (hyper-arid places counted at 25 mm): measured
    // e^0.663 = 1.94 (e^0.743 before the monsoon's reach and the wet land's gain; e^0.823
    // before the cold coasts, the subtropics' drier floor and the smoothing).
    let all: Vec<_> = STATIONS.iter().chain(MORE_STATIONS.iter()).collect();
    let logs: Vec<(f64, &str)> =
        all.iter().map(|s| ((c.precip_at(s.1, s.2).max(25.0) / s.3.max(25.0)).ln(), s.0)).collect();
    let mean = logs.iter().map(|l| l.0.abs()).sum::<f64>() / logs.len() as f64;
    eprintln!(
        "STATIONS mean {mean:.3} close {} of 97, 37: {within}",
        logs.iter().filter(|l| l.0.abs() <= 2f64.ln()).count()
    );
    assert!(mean <= 0.70, "mean |ln(model / real)| {mean:.3}: {logs:?}");
    // Within a factor of two at 57 of the 97 (52 before).
    let close = logs.iter().filter(|l| l.0.abs() <= 2f64.ln()).count();
    assert!(close >= 54, "{close} of 97 within a factor of 2: {logs:?}");
}

/// Places of known Köppen class: humid (A, C or D) ones the ground's colour must show green,
/// arid (BW) ones desert. Many sit at 20-35°, where a colour by latitude alone is desert.
const HUMID: [&str; 26] = [
    "Patna",
    "Lucknow",
    "Dhaka",
    "Guangzhou",
    "Changsha",
    "Chongqing",
    "Hanoi",
    "Houston",
    "Tallahassee",
    "Brisbane",
    "Sao Paulo",
    "Asuncion",
    "Pietermaritzburg",
    "Kunming",
    "Atlanta",
    "Yangon",
    "Kolkata",
    "Wuhan",
    "Dallas",
    "Kansas City",
    "Johannesburg",
    "Nagpur",
    "Brasilia",
    "Chicago",
    "Moscow",
    "Irkutsk",
];
const ARID: [&str; 25] = [
    "In Salah",
    "Faya",
    "Tamanrasset",
    "Riyadh",
    "Jaisalmer",
    "Hotan",
    "Ejin",
    "Nukus",
    "Calama",
    "Gobabeb",
    "Alice Springs",
    "Barstow",
    "Yuma",
    "Zahedan",
    "Baghdad",
    "Lima",
    "Karachi",
    "Muscat",
    "Aswan",
    "Cairo",
    "Lop Nur",
    "Las Vegas",
    "Tindouf",
    "Agadez",
    "Khartoum",
];

#[test]
fn the_grounds_colour_follows_the_climate() {
    use crate::export::climate::{climate_colour, Palette};
    use crate::params::{Climate as Colours, Preset};
    let Some(map) = earth_map() else { return };
    let c = earth_climate(&map);
    let palette = Palette { climate: Colours::Temperate, preset: Preset::Earth };
    // Green minus red of the ground's colour at a place: forest about +60, steppe +15, desert -25.
    let greenness = |name: &&str| {
        let s = STATIONS.iter().chain(MORE_STATIONS.iter()).find(|s| s.0 == *name).expect("a station");
        let alt = f64::from(map.sample(s.1, s.2).unwrap_or(0.0)).max(0.0);
        let [r, g, _] = climate_colour(palette, s.1, alt, c.precip_at(s.1, s.2));
        i32::from(g) - i32::from(r)
    };
    let not_green: Vec<&str> = HUMID.iter().filter(|n| greenness(n) < 35).copied().collect();
    let not_desert: Vec<&str> = ARID.iter().filter(|n| greenness(n) > -10).copied().collect();
    // Measured: 18 of 26 green, 18 of 25 desert (the rest are the climate's errors: Yuma,
    // Barstow, Khartoum get 4-6x their rain, Chongqing and Asuncion a third; before the
    // monsoon's reach and the wet land's gain 17 and 13). By latitude alone: 3 of 26 and 17 of 25.
    assert!(not_green.len() <= 9, "humid places not green: {not_green:?}");
    assert!(not_desert.len() <= 9, "arid places not desert: {not_desert:?}");
    // The Sahara and the Ganges plain lie at the same latitude.
    assert!(greenness(&"Patna") > 35 && greenness(&"In Salah") < -20);
}
