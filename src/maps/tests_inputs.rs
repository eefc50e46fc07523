//! Bad inputs: each must be refused with the right code, quickly and without panicking.

use std::time::{Duration, Instant};

use image::ExtendedColorType;
use proptest::prelude::*;
use tiff::encoder::colortype;

use super::test_support::{encode_png, encode_tiff, georef, png_l16, shared, Rng};
use super::*;

fn lim() -> MapLimits {
    MapLimits::default()
}

fn err(bytes: &[u8], kind: MapKind, range: Option<(f64, f64)>) -> MapError {
    match Map::decode(bytes, kind, range, None, &lim()) {
        Ok(m) => panic!("expected an error, decoded {m:?}"),
        Err(e) => e,
    }
}

fn crc32(data: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in data {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 { (crc >> 1) ^ 0xEDB8_8320 } else { crc >> 1 };
        }
    }
    !crc
}

fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    out.extend_from_slice(&(data.len() as u32).to_be_bytes());
    let start = out.len();
    out.extend_from_slice(kind);
    out.extend_from_slice(data);
    let crc = crc32(&out[start..]);
    out.extend_from_slice(&crc.to_be_bytes());
}

/// A hand-made PNG: IHDR with any size/colour, one tiny IDAT (an empty stored zlib stream).
fn crafted_png(width: u32, height: u32, bit_depth: u8, color_type: u8) -> Vec<u8> {
    let mut out = super::png::SIGNATURE.to_vec();
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&width.to_be_bytes());
    ihdr.extend_from_slice(&height.to_be_bytes());
    ihdr.extend_from_slice(&[bit_depth, color_type, 0, 0, 0]);
    chunk(&mut out, b"IHDR", &ihdr);
    if color_type == 3 {
        chunk(&mut out, b"PLTE", &[0, 0, 0, 255, 255, 255]);
    }
    chunk(&mut out, b"IDAT", &[0x78, 0x01, 0x01, 0x00, 0x00, 0xff, 0xff, 0, 0, 0, 1]);
    chunk(&mut out, b"IEND", &[]);
    out
}

/// A 64x64 8-bit PNG of noise (so that it compresses badly and truncation bites).
fn noise_png() -> Vec<u8> {
    let mut rng = Rng(99);
    let data: Vec<u8> = (0..64 * 64).map(|_| (rng.next() * 256.0) as u8).collect();
    encode_png(64, 64, ExtendedColorType::L8, &data)
}

fn assert_code(e: &MapError, code: &str, field: &str, words: &str) {
    assert_eq!((e.code(), e.field()), (code, field), "{e}");
    assert!(e.to_string().contains(words), "message {e:?} lacks {words:?}");
}

#[test]
fn not_an_image() {
    assert_code(&err(b"", MapKind::Continents, None), "unsupported_format", "map", "empty");
    let e = err(b"<html><body>404</body></html>", MapKind::Elevation, None);
    assert_code(&e, "unsupported_format", "map", "starts with bytes 3c 68 74 6d");
    assert_eq!(e.to_string(), "map is not a PNG or TIFF image (starts with bytes 3c 68 74 6d)");
    assert_code(&err(b"GIF8", MapKind::Continents, None), "unsupported_format", "map", "47 49");
}

#[test]
fn truncated_pngs_are_corrupt() {
    let mut files = vec![noise_png()];
    files.extend(shared("earth_landmask_ne10m_1024x512.png"));
    for png in files {
        assert!(Map::decode(&png, MapKind::Continents, None, None, &lim()).is_ok());
        for cut in [100, png.len() / 2, 20] {
            let e = err(&png[..cut], MapKind::Continents, None);
            assert_code(&e, "corrupt_image", "map", "PNG is truncated or corrupt");
        }
    }
}

#[test]
fn wrong_pixel_formats() {
    let png16 = png_l16(2, 2, &[0, 1, 2, 65535]);
    let e = err(&png16, MapKind::Continents, None);
    assert_code(&e, "wrong_bit_depth", "map", "16-bit");
    assert!(e.to_string().starts_with("continent bitmap must be 8-bit grayscale"));
    let rgb = encode_png(2, 1, ExtendedColorType::Rgb8, &[255, 0, 0, 0, 255, 0]);
    assert_code(&err(&rgb, MapKind::Continents, None), "wrong_color_type", "map", "RGB");
    assert_code(&err(&rgb, MapKind::Elevation, Some((0.0, 1.0))), "wrong_color_type", "map", "RGB");
    let rgba = encode_png(1, 1, ExtendedColorType::Rgba8, &[1, 2, 3, 4]);
    assert_code(&err(&rgba, MapKind::Continents, None), "wrong_color_type", "map", "RGBA");
    let palette = crafted_png(4, 4, 8, 3);
    assert_code(&err(&palette, MapKind::Continents, None), "wrong_color_type", "map", "palette");
    // 16-bit is fine for elevation.
    assert!(Map::decode(&png16, MapKind::Elevation, Some((0.0, 1.0)), None, &lim()).is_ok());
}

#[test]
fn map_range_problems() {
    let png = encode_png(2, 1, ExtendedColorType::L8, &[0, 255]);
    let e = err(&png, MapKind::Elevation, None);
    assert_code(&e, "missing_map_range", "map_range", "elevation PNG needs map_range MIN_M,MAX_M");
    for bad in [(5.0, 5.0), (6.0, 5.0)] {
        let e = err(&png, MapKind::Elevation, Some(bad));
        assert_code(&e, "invalid_map_range", "map_range", "map_range min must be below max");
    }
    for bad in [(f64::NAN, 1.0), (0.0, f64::INFINITY)] {
        assert_code(&err(&png, MapKind::Elevation, Some(bad)), "invalid_map_range", "map_range", "finite");
    }
    // 8-bit elevation: v = 255 maps to the top of the range; continents ignore the range.
    let m = Map::decode(&png, MapKind::Elevation, Some((-10.0, 10.0)), None, &lim()).expect("8-bit");
    assert_eq!(m.values(), &[-10.0, 10.0]);
    let m = Map::decode(&png, MapKind::Continents, Some((5.0, 5.0)), None, &lim()).expect("mask");
    assert_eq!(m.values(), &[0.0, 1.0]);
}

#[test]
fn huge_header_is_refused_quickly() {
    let png = crafted_png(100_000, 100_000, 8, 0);
    let start = Instant::now();
    let e = err(&png, MapKind::Continents, None);
    assert!(start.elapsed() < Duration::from_secs(1), "took {:?}", start.elapsed());
    assert_code(&e, "image_too_large", "map", "over the limit of 67108864");
    assert_eq!(e.to_string(), "map is 100000x100000 = 10000000000 pixels, over the limit of 67108864");
    // Within the pixel limit but far more pixels than 70 bytes can hold: refused, not allocated.
    let e = err(&crafted_png(8192, 8192, 16, 0), MapKind::Elevation, Some((0.0, 1.0)));
    assert_code(&e, "corrupt_image", "map", "cannot hold 8192x8192 pixels");
    // Even with no pixel limit at all.
    let open = MapLimits { max_pixels: u64::MAX, max_bytes: usize::MAX };
    let r = Map::decode(&png, MapKind::Continents, None, None, &open);
    assert_eq!(r.map(|_| ()).map_err(|e| e.code()), Err("corrupt_image"));
}

#[test]
fn size_limits() {
    let png = noise_png();
    let small = MapLimits { max_pixels: 100, max_bytes: 1 << 20 };
    let e = Map::decode(&png, MapKind::Continents, None, None, &small).expect_err("pixels");
    assert_eq!(e.to_string(), "map is 64x64 = 4096 pixels, over the limit of 100");
    let tiny = MapLimits { max_pixels: 1 << 20, max_bytes: 100 };
    let e = Map::decode(&png, MapKind::Continents, None, None, &tiny).expect_err("bytes");
    assert_code(&e, "file_too_large", "map", "over the limit of 100 bytes");
    for (w, h) in [(0, 10), (10, 0)] {
        let e = err(&crafted_png(w, h, 8, 0), MapKind::Continents, None);
        assert_code(&e, "empty_image", "map", "zero width or height");
    }
}

#[test]
fn bad_tiffs() {
    let rgb = vec![1.0f32; 4 * 3];
    let tif = encode_tiff::<colortype::RGB32Float>(2, 2, &rgb, None, &[], None);
    let e = err(&tif, MapKind::Elevation, None);
    assert_code(&e, "wrong_band_count", "map", "single band (got 3 bands)");
    let u8s = encode_tiff::<colortype::Gray8>(2, 2, &[1u8, 2, 3, 4], None, &[], None);
    assert_code(&err(&u8s, MapKind::Elevation, None), "wrong_bit_depth", "map", "uint8");
    let ok = encode_tiff::<colortype::GrayI16>(2, 2, &[1i16, 2, 3, 4], None, &[], None);
    let e = err(&ok, MapKind::Continents, None);
    assert_code(&e, "wrong_map_kind", "map_kind", "a GeoTIFF holds elevations");
    assert_code(&err(&ok[..ok.len() - 4], MapKind::Elevation, None), "corrupt_image", "map", "TIFF");
    assert_code(&err(&ok[..6], MapKind::Elevation, None), "corrupt_image", "map", "TIFF");
    let off = GeoBounds { west: 100.0, south: 0.0, east: 300.0, north: 10.0 };
    let geo = georef(off, 2, 2);
    let tif = encode_tiff::<colortype::GrayI16>(2, 2, &[1i16, 2, 3, 4], Some(geo), &[], None);
    let e = err(&tif, MapKind::Elevation, None);
    assert_code(&e, "invalid_georeference", "map", "-180..180");
}

#[test]
fn bad_bounds() {
    for s in ["1,2,3", "10,0,5,5", "nan,0,1,1", "0,0,200,10", "0,-91,1,1", "a,b,c,d", "0,5,1,5"] {
        let e = GeoBounds::parse(s).expect_err(s);
        assert_code(&e, "invalid_bounds", "map_bounds", "map bounds W,S,E,N invalid: ");
    }
    let png = noise_png();
    let b = GeoBounds { west: 5.0, south: 0.0, east: 5.0, north: 1.0 };
    let e = Map::decode(&png, MapKind::Continents, None, Some(b), &lim()).expect_err("bounds");
    assert_code(&e, "invalid_bounds", "map_bounds", "west 5 must be below east 5");
}

fn valid_samples() -> Vec<Vec<u8>> {
    let geo = georef(GeoBounds::GLOBE, 8, 4);
    let v: Vec<i16> = (0..32).collect();
    vec![
        noise_png(),
        png_l16(8, 4, &[7u16; 32]),
        encode_tiff::<colortype::GrayI16>(8, 4, &v, Some(geo), &[], Some("3")),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn decode_never_panics_on_noise(bytes in proptest::collection::vec(any::<u8>(), 0..4096),
                                    magic in 0usize..4) {
        let mut input = [&b"\x89PNG\r\n\x1a\n"[..], b"II*\0", b"MM\0*", b""][magic].to_vec();
        input.extend_from_slice(&bytes);
        for kind in [MapKind::Continents, MapKind::Elevation] {
            let _ = Map::decode(&input, kind, Some((0.0, 1.0)), None, &lim());
        }
    }

    #[test]
    fn decode_never_panics_on_mutated_files(which in 0usize..3, cut in 0.0f64..=1.0,
        flips in proptest::collection::vec((0.0f64..1.0, any::<u8>()), 0..8)) {
        let mut input = valid_samples().swap_remove(which);
        input.truncate(((input.len() as f64) * cut) as usize);
        let n = input.len();
        for (at, byte) in flips {
            if n > 0 {
                input[((n as f64 * at) as usize).min(n - 1)] = byte;
            }
        }
        for kind in [MapKind::Continents, MapKind::Elevation] {
            let _ = Map::decode(&input, kind, Some((0.0, 1.0)), None, &lim());
        }
    }
}
