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
//! contents are quantized from cells of about 40 km (level 8 on Earth). Coarser ones and a view
//! (near triangles metres across on a planet-wide mesh) keep `f32` positions through the
//! `EXPONENTIAL` filter, with the fewest mantissa bits that keep them within half of that same
//! step (23 bits at planet scale: a sixth fewer position bytes than plain `f32`). Normals go
//! through the `OCTAHEDRAL` filter at 8 bits (within 1.25°); colours and indices are kept as
//! they are.
//!
//! **Order.** Before encoding, triangles are reordered for the vertex cache and vertices in
//! order of first use (meshoptimizer's `optimizeVertexCache` and `optimizeVertexFetch`), which
//! makes both streams smaller; the triangles and their winding are unchanged.
//!
//! **Streams.** Each buffer view is encoded by meshoptimizer (the `meshopt` crate): attributes
//! with the vertex codec, version 0 (the only one `EXT_meshopt_compression` admits), after
//! their filter where they have one, indices with the index codec (`TRIANGLES` mode). The
//! extension is required: the views point into a fallback buffer that holds no bytes (clients
//! without a meshopt decoder ask for `compression=none`).

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

/// The shortest edge (metres) of a triangle list, or of line segments (index pairs) with
/// `lines`; infinite without edges.
pub fn shortest_edge(positions: &[[f32; 3]], indices: &[u32], lines: bool) -> f64 {
    let at = |i: u32| positions[i as usize].map(f64::from);
    let length = |a: u32, b: u32| {
        let (a, b) = (at(a), at(b));
        (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt()
    };
    let shortest = |edges: &mut dyn Iterator<Item = f64>| edges.fold(f64::INFINITY, f64::min);
    if lines {
        shortest(&mut indices.chunks_exact(2).map(|s| length(s[0], s[1])))
    } else {
        shortest(
            &mut indices.chunks_exact(3).flat_map(|t| [length(t[0], t[1]), length(t[1], t[2]), length(t[2], t[0])]),
        )
    }
}

/// The largest step positions may be stored with, given the mesh's [`shortest_edge`]:
/// 1/[`POSITION_STEPS_PER_EDGE`] of it, and at most [`MAX_POSITION_STEP_M`].
pub fn position_step_limit(shortest_edge: f64) -> f64 {
    (shortest_edge / POSITION_STEPS_PER_EDGE).min(MAX_POSITION_STEP_M)
}

/// Positions as `i16` steps from the centre of their box when a step is at most `limit`
/// ([`position_step_limit`]), else `None`.
pub fn quantize_positions(positions: &[[f32; 3]], limit: f64) -> Option<QuantizedPositions> {
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
    if step > limit {
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

/// `f32` positions through the `EXPONENTIAL` filter: each component's mantissa cut to `bits`
/// bits under an exponent shared by that component across the view, so that the low bits are
/// zero and the vertex codec packs them.
#[derive(Clone, Debug, PartialEq)]
pub struct FilteredPositions {
    /// The filter's output, the view's stream before the vertex codec.
    pub values: Vec<[u32; 3]>,
    /// What a client decodes (the accessor's `min` and `max` come from these).
    pub decoded: Vec<[f32; 3]>,
    pub bits: u8,
}

/// [`FilteredPositions`] with the fewest mantissa bits (down to 12) that keep every component
/// within `limit / 2` of its value ([`position_step_limit`]: the error of a step of `limit`),
/// or `None` where even 24 bits do not.
pub fn filter_positions(positions: &[[f32; 3]], limit: f64) -> Option<FilteredPositions> {
    let filter = |bits: u8| {
        let values =
            meshopt::encode_filter_exp::<3>(positions, i32::from(bits), meshopt::EncodeExpMode::SharedComponent);
        let mut decoded = values.clone();
        meshopt::decode_filter_exp(&mut decoded);
        let decoded: Vec<[f32; 3]> = decoded.iter().map(|v| v.map(f32::from_bits)).collect();
        let within = decoded
            .iter()
            .zip(positions)
            .all(|(d, p)| (0..3).all(|k| (f64::from(d[k]) - f64::from(p[k])).abs() <= limit / 2.0));
        within.then_some(FilteredPositions { values, decoded, bits })
    };
    let mut best = filter(24)?;
    for bits in (12..24).rev() {
        match filter(bits) {
            Some(f) => best = f,
            None => break,
        }
    }
    Some(best)
}

/// Unit normals through the `OCTAHEDRAL` filter, 8 bits: x and y on the octahedron, then the
/// scale (127) and a zero pad; the direction within 1.25° (normalized `i8` components alone
/// would take a third more bytes).
pub fn octahedral_normals(normals: &[[f32; 3]]) -> Vec<[i8; 4]> {
    let padded: Vec<[f32; 4]> = normals.iter().map(|n| [n[0], n[1], n[2], 0.0]).collect();
    meshopt::encode_filter_oct::<i8>(&padded, 8)
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
