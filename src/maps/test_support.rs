//! Helpers shared by the map tests: sample files and synthetic PNG/TIFF encoders.

use std::io::Cursor;

use image::codecs::png::PngEncoder;
use image::{ExtendedColorType, ImageEncoder};
use tiff::encoder::{colortype, TiffEncoder, TiffValue};
use tiff::tags::Tag;

use super::GeoBounds;

/// A sample map shipped in the repository's `maps/` folder.
pub(super) fn shared(name: &str) -> Option<Vec<u8>> {
    let path = format!(concat!(env!("CARGO_MANIFEST_DIR"), "/maps/{}"), name);
    Some(std::fs::read(&path).unwrap_or_else(|e| panic!("sample map {path}: {e}")))
}

pub(super) fn encode_png(w: u32, h: u32, color: ExtendedColorType, data: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    PngEncoder::new(&mut out).write_image(data, w, h, color).expect("encode test PNG");
    out
}

pub(super) fn png_l16(w: u32, h: u32, v: &[u16]) -> Vec<u8> {
    let data: Vec<u8> = v.iter().flat_map(|x| x.to_ne_bytes()).collect();
    encode_png(w, h, ExtendedColorType::L16, &data)
}

/// Georeference for a test TIFF: pixel scale and tiepoint (NW corner of pixel 0,0).
pub(super) fn georef(b: GeoBounds, w: u32, h: u32) -> ([f64; 3], [f64; 6]) {
    let sx = (b.east - b.west) / f64::from(w);
    let sy = (b.north - b.south) / f64::from(h);
    ([sx, sy, 0.0], [0.0, 0.0, 0.0, b.west, b.north, 0.0])
}

pub(super) fn encode_tiff<C: colortype::ColorType>(
    w: u32,
    h: u32,
    data: &[C::Inner],
    geo: Option<([f64; 3], [f64; 6])>,
    extra: &[(Tag, Vec<u16>)],
    nodata: Option<&str>,
) -> Vec<u8>
where
    [C::Inner]: TiffValue,
{
    let mut buf = Cursor::new(Vec::new());
    let mut enc = TiffEncoder::new(&mut buf).expect("tiff encoder");
    let mut img = enc.new_image::<C>(w, h).expect("tiff image");
    if let Some((scale, tie)) = geo {
        let e = img.encoder();
        e.write_tag(Tag::ModelPixelScaleTag, &scale[..]).expect("tag");
        e.write_tag(Tag::ModelTiepointTag, &tie[..]).expect("tag");
    }
    for (tag, v) in extra {
        img.encoder().write_tag(*tag, &v[..]).expect("tag");
    }
    if let Some(nd) = nodata {
        img.encoder().write_tag(Tag::GdalNodata, nd).expect("tag");
    }
    img.write_data(data).expect("tiff data");
    buf.into_inner()
}

/// Deterministic pseudo-random numbers in [0, 1) (splitmix64).
pub(super) struct Rng(pub u64);
impl Rng {
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}
