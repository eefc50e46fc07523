//! How a `.glb`'s vertex and index data are stored ([`Compression`]): plain `f32` attributes,
//! or quantized attributes (`KHR_mesh_quantization`) in meshoptimizer's streams
//! (`EXT_meshopt_compression`), about a quarter of the bytes.
//!
//! **Quantization.** Positions become `i16` steps from the centre of their box (the node's
//! translation and uniform scale give them back), but only where a step is at most
//! 1/[`POSITION_STEPS_PER_EDGE`] of the mesh's shortest edge, so no triangle changes shape
//! visibly, and at most [`MAX_POSITION_STEP_M`], so that a water surface standing a river's
//! depth above the ground stays on its side of it (coarser steps scatter blue blotches over the
//! land where the surface of a coarse face's river slopes down into the ground). So 3D Tiles
//! contents are quantized from cells of about 40 km (level 8 on Earth), coarser ones and a
//! view (near triangles metres across on a planet-wide mesh) keep `f32`. Normals become `i8`
//! (error under 0.5°); colours and indices are kept as they are.
//!
//! **Order.** Before encoding, triangles are reordered for the vertex cache and vertices in
//! order of first use (meshoptimizer's `optimizeVertexCache` and `optimizeVertexFetch`), which
//! makes both streams smaller; the triangles and their winding are unchanged.
//!
//! **Streams.** Each buffer view is encoded by meshoptimizer (the `meshopt` crate): attributes
//! with the vertex codec, version 0 (the only one `EXT_meshopt_compression` admits), indices
//! with the index codec (`TRIANGLES` mode). The extension is required: the views point into a
//! fallback buffer that holds no bytes (clients without a meshopt decoder ask for
//! `compression=none`).

/// Vertex and index data of a `.glb`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Compression {
    /// `f32` positions and normals in plain buffer views: any glTF 2.0 client.
    None,
    /// `KHR_mesh_quantization` and `EXT_meshopt_compression` (required).
    #[default]
    Meshopt,
}

impl Compression {
    /// The query value naming it (`compression=none|meshopt`).
    pub fn as_str(self) -> &'static str {
        match self {
            Compression::None => "none",
            Compression::Meshopt => "meshopt",
        }
    }

    /// From its query value.
    pub fn parse(s: &str) -> Option<Compression> {
        match s {
            "none" => Some(Compression::None),
            "meshopt" => Some(Compression::Meshopt),
            _ => None,
        }
    }
}

/// Least number of position steps along the mesh's shortest edge for positions to be
/// quantized.
pub const POSITION_STEPS_PER_EDGE: f64 = 64.0;

/// Largest position step (metres) of quantized positions.
pub const MAX_POSITION_STEP_M: f64 = 1.0;

/// Positions as `i16` steps: `p = centre + step * q` (glTF axes, metres).
#[derive(Clone, Debug, PartialEq)]
pub struct QuantizedPositions {
    /// x, y, z and a zero pad (vertex attributes are 4-byte aligned).
    pub values: Vec<[i16; 4]>,
    pub centre: [f64; 3],
    pub step: f64,
}

/// Positions of a triangle list as `i16` steps when a step is at most
/// 1/[`POSITION_STEPS_PER_EDGE`] of the shortest edge and [`MAX_POSITION_STEP_M`], else `None`.
pub fn quantize_positions(positions: &[[f32; 3]], indices: &[u32]) -> Option<QuantizedPositions> {
    let edges = indices.chunks_exact(3).flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])]);
    quantize_with_edges(positions, edges)
}

/// [`quantize_positions`] of a list of line segments (index pairs).
pub fn quantize_line_positions(positions: &[[f32; 3]], indices: &[u32]) -> Option<QuantizedPositions> {
    quantize_with_edges(positions, indices.chunks_exact(2).map(|s| (s[0], s[1])))
}

fn quantize_with_edges(positions: &[[f32; 3]], edges: impl Iterator<Item = (u32, u32)>) -> Option<QuantizedPositions> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in positions {
        for k in 0..3 {
            lo[k] = lo[k].min(f64::from(p[k]));
            hi[k] = hi[k].max(f64::from(p[k]));
        }
    }
    let centre: [f64; 3] = std::array::from_fn(|k| (lo[k] + hi[k]) / 2.0);
    let half = (0..3).map(|k| (hi[k] - lo[k]) / 2.0).fold(0.0, f64::max);
    if !half.is_finite() || half <= 0.0 {
        return None;
    }
    let step = half / f64::from(i16::MAX);
    let at = |i: u32| positions[i as usize].map(f64::from);
    let shortest = edges
        .map(|(a, b)| {
            let (a, b) = (at(a), at(b));
            (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt()
        })
        .fold(f64::INFINITY, f64::min);
    if step * POSITION_STEPS_PER_EDGE > shortest || step > MAX_POSITION_STEP_M {
        return None;
    }
    let values = positions
        .iter()
        .map(|p| {
            let q = |k: usize| ((f64::from(p[k]) - centre[k]) / step).round().clamp(-32767.0, 32767.0) as i16;
            [q(0), q(1), q(2), 0]
        })
        .collect();
    Some(QuantizedPositions { values, centre, step })
}

/// Unit normals as normalized `i8` (x, y, z and a zero pad).
pub fn quantize_normals(normals: &[[f32; 3]]) -> Vec<[i8; 4]> {
    let q = |x: f32| (x * 127.0).round().clamp(-127.0, 127.0) as i8;
    normals.iter().map(|n| [q(n[0]), q(n[1]), q(n[2]), 0]).collect()
}

/// What a buffer view holds, for its meshopt stream.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StreamKind {
    /// Vertex attributes, `stride` bytes a vertex (a multiple of 4).
    Attributes { stride: usize },
    /// A triangle list of `u16` (`stride` 2) or `u32` (4) indices below `vertices`.
    Triangles { stride: usize, vertices: usize },
    /// Any other index list (line segments), as for `Triangles`.
    Indices { stride: usize, vertices: usize },
}

impl StreamKind {
    /// The extension's `mode`.
    pub fn mode(self) -> &'static str {
        match self {
            StreamKind::Attributes { .. } => "ATTRIBUTES",
            StreamKind::Triangles { .. } => "TRIANGLES",
            StreamKind::Indices { .. } => "INDICES",
        }
    }

    pub fn stride(self) -> usize {
        match self {
            StreamKind::Attributes { stride }
            | StreamKind::Triangles { stride, .. }
            | StreamKind::Indices { stride, .. } => stride,
        }
    }
}

/// The meshopt stream of a buffer view's little-endian `bytes` (whole elements of `kind`).
pub fn meshopt_stream(bytes: &[u8], kind: StreamKind) -> Vec<u8> {
    fn vertices<const N: usize>(bytes: &[u8]) -> Vec<u8> {
        let items: Vec<[u8; N]> = bytes.chunks_exact(N).map(|c| c.try_into().expect("N bytes")).collect();
        // Version 0: the one EXT_meshopt_compression admits (the library defaults to 1).
        meshopt::encode_vertex_buffer_level(&items, 2, Some(0)).expect("meshopt encodes vertices")
    }
    match kind {
        StreamKind::Attributes { stride: 4 } => vertices::<4>(bytes),
        StreamKind::Attributes { stride: 8 } => vertices::<8>(bytes),
        StreamKind::Attributes { stride: 12 } => vertices::<12>(bytes),
        StreamKind::Attributes { stride } => panic!("no meshopt stream for {stride}-byte vertices"),
        StreamKind::Triangles { stride, vertices } | StreamKind::Indices { stride, vertices } => {
            let indices: Vec<u32> = match stride {
                2 => bytes.chunks_exact(2).map(|c| u32::from(u16::from_le_bytes([c[0], c[1]]))).collect(),
                4 => bytes.chunks_exact(4).map(|c| u32::from_le_bytes(c.try_into().expect("4 bytes"))).collect(),
                _ => panic!("indices are 2 or 4 bytes"),
            };
            if matches!(kind, StreamKind::Triangles { .. }) {
                meshopt::encode_index_buffer(&indices, vertices).expect("meshopt encodes indices")
            } else {
                meshopt::encode_index_sequence(&indices, vertices).expect("meshopt encodes indices")
            }
        }
    }
}

#[cfg(test)]
#[path = "glb_pack_tests.rs"]
mod tests;
