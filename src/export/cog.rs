//! Cloud-Optimized GeoTIFF writer for float32 rasters (`elevation.tif`, `dem.tif`).
//!
//! **Layout** (as GDAL's COG driver writes it, so that a reader fetching byte ranges needs one
//! request for the header and IFDs and one per tile): the 8-byte classic TIFF header, then the
//! IFD of the full-resolution image at byte 8 followed by its overviews' IFDs (each IFD's
//! out-of-line values right after it), then the tile data — the smallest overview's tiles first
//! and the full resolution's last, each image's tiles row by row.
//!
//! **Encoding**: tiles of [`TILE`] x [`TILE`] pixels, pixel-interleaved bands, DEFLATE (zlib)
//! with the floating-point predictor (TIFF Technical Note 3, predictor 3: each row's values are
//! split into byte planes, most significant first, and byte-differenced across the row with the
//! band count as stride). Tiles past the image's right and bottom edges repeat the last column
//! and row. Overviews halve the image (rounding up) until it fits one tile; each overview pixel
//! is the mean of the up to four pixels it covers, NaN (no data) ones left out.
//!
//! **Georeferencing**: GeoTIFF keys for EPSG:4326 with `RasterPixelIsArea`,
//! `ModelPixelScale` and `ModelTiepoint` at the north-west corner; `GDAL_NODATA` when the
//! raster has a no-data value (NaN); band names in `GDAL_METADATA`.
//!
//! Written by hand: no maintained Rust crate writes COGs without linking GDAL. Tests decode the
//! output with the `tiff` crate; CI validates it with GDAL (rasterio) and rio-cogeo.

use rayon::prelude::*;
use std::io::Write;

/// GeoKeyDirectory for EPSG:4326 (GeoTIFF 1.0): header, then (key, location, count, value).
pub const GEO_KEYS_EPSG_4326: [u16; 20] = [
    1, 1, 0, 4, //
    1024, 0, 1, 2, // GTModelTypeGeoKey = ModelTypeGeographic
    1025, 0, 1, 1, // GTRasterTypeGeoKey = RasterPixelIsArea
    2048, 0, 1, 4326, // GeographicTypeGeoKey = EPSG:4326 (WGS 84)
    2054, 0, 1, 9102, // GeogAngularUnitsGeoKey = degree
];

/// Tile width and height in pixels.
pub const TILE: usize = 512;

/// A float32 raster with one or more bands over a latitude/longitude grid.
pub struct CogRaster<'a> {
    pub width: usize,
    pub height: usize,
    /// Bands, each `width * height` values row-major from the north-west corner.
    pub bands: Vec<&'a [f32]>,
    /// A name per band (written to `GDAL_METADATA` as the band's description).
    pub names: Vec<&'a str>,
    /// West and north edges (degrees) and pixel size (degrees of longitude, latitude).
    pub west: f64,
    pub north: f64,
    pub pixel: [f64; 2],
    /// Whether NaN marks pixels without data (written as `GDAL_NODATA` "nan").
    pub nodata_nan: bool,
}

/// One image of the pyramid: its size and interleaved values.
struct Level {
    width: usize,
    height: usize,
    /// `width * height * bands` values, pixel-interleaved.
    values: Vec<f32>,
}

/// The COG's bytes.
pub fn write_cog(r: &CogRaster) -> Vec<u8> {
    assert!(r.width > 0 && r.height > 0 && !r.bands.is_empty());
    assert!(r.bands.iter().all(|b| b.len() == r.width * r.height));
    let spp = r.bands.len();
    let mut values = vec![0f32; r.width * r.height * spp];
    values.par_chunks_mut(spp).enumerate().for_each(|(i, px)| {
        for (s, band) in px.iter_mut().zip(&r.bands) {
            *s = band[i];
        }
    });
    let mut levels = vec![Level { width: r.width, height: r.height, values }];
    while levels.last().is_some_and(|l| l.width > TILE || l.height > TILE) {
        let next = halve(levels.last().unwrap(), spp);
        levels.push(next);
    }
    // Compressed tiles of every level, in parallel.
    let tiles: Vec<Vec<Vec<u8>>> = levels.iter().map(|l| encode_tiles(l, spp)).collect();
    let ifds: Vec<Ifd> = levels.iter().enumerate().map(|(i, l)| ifd(r, l, i, tiles[i].len())).collect();
    // Offsets: IFDs from byte 8, then the data, smallest level first.
    let mut at = 8u64;
    let mut ifd_at = Vec::new();
    for ifd in &ifds {
        ifd_at.push(at);
        at += ifd.size() as u64;
    }
    let mut data_at = vec![Vec::new(); levels.len()];
    for i in (0..levels.len()).rev() {
        for t in &tiles[i] {
            data_at[i].push(at);
            at += t.len() as u64;
        }
    }
    assert!(at <= u64::from(u32::MAX), "COG over 4 GiB needs BigTIFF");
    let mut out = Vec::with_capacity(at as usize);
    out.extend_from_slice(b"II");
    out.extend_from_slice(&42u16.to_le_bytes());
    out.extend_from_slice(&8u32.to_le_bytes());
    for (i, ifd) in ifds.into_iter().enumerate() {
        let next = ifd_at.get(i + 1).copied().unwrap_or(0) as u32;
        let offsets: Vec<u32> = data_at[i].iter().map(|&o| o as u32).collect();
        let counts: Vec<u32> = tiles[i].iter().map(|t| t.len() as u32).collect();
        ifd.write(&mut out, ifd_at[i] as u32, next, &offsets, &counts);
    }
    for level_tiles in tiles.iter().rev() {
        for t in level_tiles {
            out.extend_from_slice(t);
        }
    }
    debug_assert_eq!(out.len() as u64, at);
    out
}

/// The next overview: half the size (rounding up), each pixel the mean of the non-NaN pixels
/// it covers (NaN if none).
fn halve(l: &Level, spp: usize) -> Level {
    let (w, h) = (l.width.div_ceil(2), l.height.div_ceil(2));
    let mut values = vec![0f32; w * h * spp];
    values.par_chunks_mut(w * spp).enumerate().for_each(|(y, row)| {
        for x in 0..w {
            for s in 0..spp {
                let (mut sum, mut n) = (0f64, 0u32);
                for (dy, dx) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                    let (sy, sx) = (2 * y + dy, 2 * x + dx);
                    if sy < l.height && sx < l.width {
                        let v = l.values[(sy * l.width + sx) * spp + s];
                        if !v.is_nan() {
                            sum += f64::from(v);
                            n += 1;
                        }
                    }
                }
                row[x * spp + s] = if n > 0 { (sum / f64::from(n)) as f32 } else { f32::NAN };
            }
        }
    });
    Level { width: w, height: h, values }
}

/// The level's tiles, row by row: predictor 3 then zlib.
fn encode_tiles(l: &Level, spp: usize) -> Vec<Vec<u8>> {
    let (across, down) = (l.width.div_ceil(TILE), l.height.div_ceil(TILE));
    (0..across * down)
        .into_par_iter()
        .map(|t| {
            let (tx, ty) = (t % across, t / across);
            let wc = TILE * spp; // values per tile row
            let mut raw = Vec::with_capacity(TILE * wc * 4);
            let mut row = vec![0u8; wc * 4];
            for y in 0..TILE {
                let sy = (ty * TILE + y).min(l.height - 1);
                for x in 0..TILE {
                    let sx = (tx * TILE + x).min(l.width - 1);
                    for s in 0..spp {
                        let bytes = l.values[(sy * l.width + sx) * spp + s].to_be_bytes();
                        let i = x * spp + s;
                        for (b, byte) in bytes.into_iter().enumerate() {
                            row[b * wc + i] = byte;
                        }
                    }
                }
                for i in (spp..row.len()).rev() {
                    row[i] = row[i].wrapping_sub(row[i - spp]);
                }
                raw.extend_from_slice(&row);
            }
            let mut z = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::new(1));
            z.write_all(&raw).expect("compresses into memory");
            z.finish().expect("compresses into memory")
        })
        .collect()
}

/// TIFF field types.
const SHORT: u16 = 3;
const LONG: u16 = 4;
const ASCII: u16 = 2;
const DOUBLE: u16 = 12;

/// A tag's value: its type, count and little-endian bytes (`None` for the tile offsets and
/// byte counts, filled in when written).
struct Entry {
    tag: u16,
    kind: u16,
    count: u32,
    bytes: Option<Vec<u8>>,
}

struct Ifd {
    entries: Vec<Entry>,
}

fn shorts(tag: u16, v: &[u16]) -> Entry {
    Entry { tag, kind: SHORT, count: v.len() as u32, bytes: Some(v.iter().flat_map(|x| x.to_le_bytes()).collect()) }
}

fn long(tag: u16, v: u32) -> Entry {
    Entry { tag, kind: LONG, count: 1, bytes: Some(v.to_le_bytes().to_vec()) }
}

fn doubles(tag: u16, v: &[f64]) -> Entry {
    Entry { tag, kind: DOUBLE, count: v.len() as u32, bytes: Some(v.iter().flat_map(|x| x.to_le_bytes()).collect()) }
}

fn ascii(tag: u16, s: &str) -> Entry {
    let mut bytes = s.as_bytes().to_vec();
    bytes.push(0);
    Entry { tag, kind: ASCII, count: bytes.len() as u32, bytes: Some(bytes) }
}

/// The IFD of pyramid level `index` (0 = full resolution) with `tiles` tiles.
fn ifd(r: &CogRaster, l: &Level, index: usize, tiles: usize) -> Ifd {
    let spp = r.bands.len();
    let mut e = vec![
        long(254, u32::from(index > 0)), // NewSubfileType: reduced-resolution image
        long(256, l.width as u32),
        long(257, l.height as u32),
        shorts(258, &vec![32; spp]),                                      // BitsPerSample
        shorts(259, &[8]),                                                // Compression: Deflate (zlib)
        shorts(262, &[1]),                                                // Photometric: BlackIsZero
        shorts(277, &[spp as u16]),                                       // SamplesPerPixel
        shorts(284, &[1]),                                                // PlanarConfiguration: pixel-interleaved
        shorts(317, &[3]),                                                // Predictor: floating point
        shorts(322, &[TILE as u16]),                                      // TileWidth
        shorts(323, &[TILE as u16]),                                      // TileLength
        Entry { tag: 324, kind: LONG, count: tiles as u32, bytes: None }, // TileOffsets
        Entry { tag: 325, kind: LONG, count: tiles as u32, bytes: None }, // TileByteCounts
    ];
    if spp > 1 {
        e.push(shorts(338, &vec![0; spp - 1])); // ExtraSamples: unspecified
    }
    e.push(shorts(339, &vec![3; spp])); // SampleFormat: IEEE float
    if index == 0 {
        let [dx, dy] = r.pixel;
        e.push(doubles(33550, &[dx, dy, 0.0])); // ModelPixelScale
        e.push(doubles(33922, &[0.0, 0.0, 0.0, r.west, r.north, 0.0])); // ModelTiepoint
        e.push(shorts(34735, &GEO_KEYS_EPSG_4326)); // GeoKeyDirectory
        let items: String = r
            .names
            .iter()
            .enumerate()
            .map(|(i, n)| format!("<Item name=\"DESCRIPTION\" sample=\"{i}\" role=\"description\">{n}</Item>"))
            .collect();
        e.push(ascii(42112, &format!("<GDALMetadata>{items}</GDALMetadata>")));
    }
    if r.nodata_nan {
        e.push(ascii(42113, "nan")); // GDAL_NODATA
    }
    Ifd { entries: e }
}

impl Entry {
    fn len(&self) -> usize {
        self.count as usize
            * if self.kind == DOUBLE {
                8
            } else if self.kind == SHORT {
                2
            } else if self.kind == LONG {
                4
            } else {
                1
            }
    }
}

/// Out-of-line values are padded to even offsets.
fn padded(n: usize) -> usize {
    n + (n & 1)
}

impl Ifd {
    /// Bytes of the directory and its out-of-line values.
    fn size(&self) -> usize {
        let out: usize = self.entries.iter().filter(|e| e.len() > 4).map(|e| padded(e.len())).sum();
        2 + 12 * self.entries.len() + 4 + out
    }

    /// Appends the IFD at `at` (== `out.len()`), linking to `next`.
    fn write(self, out: &mut Vec<u8>, at: u32, next: u32, offsets: &[u32], counts: &[u32]) {
        debug_assert_eq!(out.len(), at as usize);
        let mut extra = Vec::new();
        let mut extra_at = at as usize + 2 + 12 * self.entries.len() + 4;
        out.extend_from_slice(&(self.entries.len() as u16).to_le_bytes());
        for e in &self.entries {
            let bytes = e.bytes.clone().unwrap_or_else(|| {
                let v = if e.tag == 324 { offsets } else { counts };
                v.iter().flat_map(|x| x.to_le_bytes()).collect()
            });
            out.extend_from_slice(&e.tag.to_le_bytes());
            out.extend_from_slice(&e.kind.to_le_bytes());
            out.extend_from_slice(&e.count.to_le_bytes());
            if bytes.len() <= 4 {
                let mut inline = [0u8; 4];
                inline[..bytes.len()].copy_from_slice(&bytes);
                out.extend_from_slice(&inline);
            } else {
                out.extend_from_slice(&(extra_at as u32).to_le_bytes());
                extra_at += padded(bytes.len());
                extra.extend_from_slice(&bytes);
                if bytes.len() & 1 == 1 {
                    extra.push(0);
                }
            }
        }
        out.extend_from_slice(&next.to_le_bytes());
        out.extend_from_slice(&extra);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tiff::decoder::{Decoder, DecodingResult};

    fn raster<'a>(w: usize, h: usize, bands: Vec<&'a [f32]>, nodata: bool) -> CogRaster<'a> {
        let names = vec!["a"; bands.len()];
        CogRaster {
            width: w,
            height: h,
            bands,
            names,
            west: 10.0,
            north: 50.0,
            pixel: [0.01, 0.01],
            nodata_nan: nodata,
        }
    }

    /// Decodes every image of the file with the `tiff` crate: (width, height, values).
    fn decode(bytes: &[u8]) -> Vec<(u32, u32, Vec<f32>)> {
        let mut d = Decoder::new(std::io::Cursor::new(bytes)).unwrap();
        let mut out = Vec::new();
        loop {
            let (w, h) = d.dimensions().unwrap();
            match d.read_image().unwrap() {
                DecodingResult::F32(v) => out.push((w, h, v)),
                _ => panic!("not float32"),
            }
            if !d.more_images() {
                break;
            }
            d.next_image().unwrap();
        }
        out
    }

    #[test]
    fn decodes_to_the_values_written_with_overviews() {
        // 1100 x 700: three tiles across, two down, partial at the edges; overviews 550x350
        // and 275x175.
        let (w, h) = (1100, 700);
        let a: Vec<f32> = (0..w * h)
            .map(|i| if i % 97 == 0 { f32::NAN } else { ((i % w) as f32 * 0.37).sin() * 900.0 + (i / w) as f32 })
            .collect();
        let bytes = write_cog(&raster(w, h, vec![&a], true));
        let images = decode(&bytes);
        assert_eq!(images.len(), 3, "full resolution and two overviews");
        let (iw, ih, v) = &images[0];
        assert_eq!((*iw as usize, *ih as usize), (w, h));
        for i in 0..w * h {
            assert_eq!(v[i].to_bits(), a[i].to_bits(), "pixel {i}");
        }
        let (ow, oh, o) = &images[1];
        assert_eq!((*ow, *oh), (550, 350));
        // Overview pixel (1, 1): mean of the four full-resolution pixels it covers; pixel (0,
        // 0) leaves out the NaN at (0, 0).
        let mean = (a[2 * w + 2] + a[2 * w + 3] + a[3 * w + 2] + a[3 * w + 3]) / 4.0;
        assert!((o[550 + 1] - mean).abs() < 1e-3, "{} vs {mean}", o[551]);
        let mean0 = (a[1] + a[w] + a[w + 1]) / 3.0;
        assert!((o[0] - mean0).abs() < 1e-3, "{} vs {mean0}", o[0]);
    }

    #[test]
    fn interleaves_bands() {
        // Two bands: the tiff crate does not decode them, so check the layout of one tile by
        // hand: undo zlib and the predictor (byte differences with the band count as stride,
        // then byte planes) and compare the first row.
        let (w, h) = (600, 3);
        let a: Vec<f32> = (0..w * h).map(|i| i as f32 * 1.5 - 200.0).collect();
        let b: Vec<f32> = (0..w * h).map(|i| if i % 3 == 0 { f32::NAN } else { -(i as f32) }).collect();
        let bytes = write_cog(&raster(w, h, vec![&a, &b], true));
        let u32_at = |o: usize| u32::from_le_bytes(bytes[o..o + 4].try_into().unwrap()) as usize;
        let n = u32_at(8 - 4 + 4) & 0xffff;
        let tag = |t: u16| (0..n).map(|k| 10 + 12 * k).find(|&o| bytes[o..o + 2] == t.to_le_bytes()).unwrap();
        let (offsets, counts) = (u32_at(u32_at(tag(324) + 8)), u32_at(u32_at(tag(325) + 8)));
        let mut raw = Vec::new();
        std::io::Read::read_to_end(&mut flate2::read::ZlibDecoder::new(&bytes[offsets..offsets + counts]), &mut raw)
            .unwrap();
        let wc = TILE * 2;
        let mut row = raw[..wc * 4].to_vec();
        for i in 2..row.len() {
            row[i] = row[i].wrapping_add(row[i - 2]);
        }
        for x in 0..TILE {
            for (s, band) in [&a, &b].iter().enumerate() {
                let i = x * 2 + s;
                let v = f32::from_be_bytes([row[i], row[wc + i], row[2 * wc + i], row[3 * wc + i]]);
                assert_eq!(v.to_bits(), band[x].to_bits(), "band {s} pixel {x}");
            }
        }
    }

    #[test]
    fn layout_is_cloud_optimized() {
        let (w, h) = (1500, 1200);
        let a: Vec<f32> = (0..w * h).map(|i| (i % 9000) as f32).collect();
        let bytes = write_cog(&raster(w, h, vec![&a], false));
        let u32_at = |o: usize| u32::from_le_bytes(bytes[o..o + 4].try_into().unwrap()) as usize;
        let u16_at = |o: usize| u16::from_le_bytes(bytes[o..o + 2].try_into().unwrap()) as usize;
        assert_eq!(&bytes[..4], b"II*\0");
        // IFDs first, each after the previous, all before any tile; the main image at byte 8.
        let mut ifd = u32_at(4);
        assert_eq!(ifd, 8);
        let mut first_tiles = Vec::new();
        let mut sizes = Vec::new();
        while ifd != 0 {
            let n = u16_at(ifd);
            let tag = |t: u16| (0..n).map(|k| ifd + 2 + 12 * k).find(|&o| u16_at(o) == t as usize);
            let get = |t: u16| u32_at(tag(t).unwrap() + 8);
            sizes.push((get(256), get(257)));
            let offsets = tag(324).unwrap();
            let count = u32_at(offsets + 4);
            let first = if count == 1 { u32_at(offsets + 8) } else { u32_at(u32_at(offsets + 8)) };
            first_tiles.push(first);
            // Tags in ascending order.
            let tags: Vec<usize> = (0..n).map(|k| u16_at(ifd + 2 + 12 * k)).collect();
            assert!(tags.windows(2).all(|p| p[0] < p[1]), "{tags:?}");
            let next = u32_at(ifd + 2 + 12 * n);
            assert!(next == 0 || next > ifd);
            ifd = next;
        }
        assert_eq!(sizes, vec![(1500, 1200), (750, 600), (375, 300)]);
        // Tile data after all IFDs, the smallest overview's first.
        assert!(first_tiles.windows(2).all(|p| p[0] > p[1]), "{first_tiles:?}");
        let images = decode(&bytes);
        assert_eq!(images[0].2, a);
    }
}
