//! glTF 2.0 binary (`.glb`) export, the JSON built with `gltf-json`.
//!
//! **Axes.** glTF is Y-up; the planet frame is Z-up (+Z north pole, longitude 0 on +X, 90°E on
//! +Y). A planet-frame point `(x, y, z)` is written as glTF `(x, z, -y)`: north is glTF +Y,
//! longitude 0 is +X, 90°E is -Z. The map is a rotation by -90° about X (determinant +1), so
//! counter-clockwise faces stay counter-clockwise seen from outside, and it is the inverse of the
//! Y-up to Z-up rotation 3D Tiles applies to glTF content. Units stay metres, planet-centred.
//!
//! [`encode_glb`] writes any number of [`GlbMesh`]es (one mesh, one primitive and one node each,
//! all in the default scene), plain or quantized and meshopt-compressed ([`Compression`],
//! `glb_pack.rs`); [`planet_glb`] uses it for the base mesh.

use super::climate::surface_colour;
pub use super::glb_pack::Compression;
use super::glb_pack::{
    filter_positions, meshopt_stream, octahedral_normals, position_step_limit, quantize_positions, shortest_edge,
    StreamKind,
};
use super::surface_normals;
use crate::mesh::{Mesh, VertexFlags};
use crate::params::Params;
use gltf_json as json;
use json::accessor::{ComponentType, GenericComponentType, Type};
use json::validation::{Checked::Valid, USize64};
use std::collections::BTreeMap;

/// One triangle list for [`encode_glb`], in glTF axes (see [`to_gltf_axes`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GlbMesh {
    /// Vertex positions, metres, relative to `translation` when there is one.
    pub positions: Vec<[f32; 3]>,
    /// Unit normals, one per position, or empty to leave NORMAL out.
    pub normals: Vec<[f32; 3]>,
    /// Colours with alpha, one per position, or empty to leave COLOR_0 out: linear components,
    /// as glTF defines COLOR_0 ([`linear_rgba`] makes them from sRGB). Any alpha below 255 gives
    /// the primitive a blended material.
    pub colors: Vec<[u8; 4]>,
    /// Triangles, counter-clockwise seen from the front; or, with `lines`, line segments.
    pub indices: Vec<u32>,
    /// Whether `indices` are line segments (pairs) rather than triangles.
    pub lines: bool,
    /// Local origin of the positions (node translation), metres in glTF axes. Written with full
    /// `f64` precision, so positions can stay small `f32` offsets.
    pub translation: Option<[f64; 3]>,
}

/// A `.glb` too large for its container, whose lengths are `u32`: at most 4 GiB.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("the .glb would be {bytes} bytes, over the 4 GiB (4,294,967,295 bytes) a binary glTF can hold")]
pub struct GlbTooLarge {
    pub bytes: u64,
}

/// Length of a `.glb` whose JSON chunk (padded) and binary chunk data (padded; 0 for none)
/// take `json_len` and `bin_len` bytes, within the container's `u32` limit.
pub fn glb_len(json_len: usize, bin_len: usize) -> Result<u32, GlbTooLarge> {
    let bin_chunk = if bin_len == 0 { 0 } else { 8u64.saturating_add(bin_len as u64) };
    let total = (12 + 8 + json_len as u64).saturating_add(bin_chunk);
    u32::try_from(total).map_err(|_| GlbTooLarge { bytes: total })
}

/// Planet frame (Z-up) to glTF axes (Y-up): `(x, y, z) -> (x, z, -y)`.
#[inline]
pub fn to_gltf_axes(p: [f64; 3]) -> [f64; 3] {
    [p[0], p[2], -p[1]]
}

/// Colour of river vertices in the planet model (`planet.glb`, which has no water surface).
const RIVER_RGB: [u8; 3] = [40, 90, 185];

/// The planet's base mesh as a `.glb`: one mesh, one primitive, POSITION / NORMAL / COLOR_0 and
/// u32 indices, coloured by vertex type and altitude with the climate lookup, river vertices
/// blue (the model shows the network; views and tiles draw rivers as their water surface).
pub fn planet_glb(mesh: &Mesh, params: &Params) -> Result<Vec<u8>, GlbTooLarge> {
    encode_glb(&[planet_mesh(mesh, params)], Compression::None)
}

/// The base mesh as a [`GlbMesh`] (glTF axes, no translation).
pub fn planet_mesh(mesh: &Mesh, params: &Params) -> GlbMesh {
    let mut model = terrain_mesh(mesh, params, None);
    for (c, v) in model.colors.iter_mut().zip(&mesh.vertices) {
        if v.flags.contains(VertexFlags::RIVER) {
            *c = linear_rgba(RIVER_RGB, 255);
        }
    }
    model
}

/// The terrain of a mesh as a [`GlbMesh`] in glTF axes; with `origin` (planet frame), positions
/// are `f32` offsets from it computed in `f64`, and the origin becomes the node translation.
pub fn terrain_mesh(mesh: &Mesh, params: &Params, origin: Option<glam::DVec3>) -> GlbMesh {
    let triangles = mesh.triangles();
    terrain_mesh_with_normals(mesh, params, origin, &triangles, &surface_normals(mesh, &triangles))
}

/// [`terrain_mesh`] of the mesh's `triangles` ([`Mesh::triangles`]) with the given unit normals
/// (planet frame), one per vertex.
pub fn terrain_mesh_with_normals(
    mesh: &Mesh,
    params: &Params,
    origin: Option<glam::DVec3>,
    triangles: &[[u32; 3]],
    normals: &[glam::DVec3],
) -> GlbMesh {
    use rayon::prelude::*;
    assert_eq!(normals.len(), mesh.vertices.len(), "one normal per vertex");
    let o = origin.unwrap_or(glam::DVec3::ZERO);
    let vertices = &mesh.vertices;
    GlbMesh {
        positions: vertices.par_iter().map(|v| to_gltf_axes((v.p() - o).to_array()).map(|x| x as f32)).collect(),
        normals: normals
            .par_iter()
            .map(|n| {
                let n = to_gltf_axes(n.to_array()).map(|x| x as f32);
                let len = n.iter().map(|x| x * x).sum::<f32>().sqrt();
                if len > 0.0 {
                    n.map(|x| x / len)
                } else {
                    [0.0, 1.0, 0.0]
                }
            })
            .collect(),
        colors: (0..vertices.len())
            .into_par_iter()
            // A river vertex is coloured as its land: its water, as wide as its channel, is the
            // water surface's (a coarse face beside a river is not a river). Steep land is rock.
            .map(|v| linear_rgba(surface_colour(mesh, params, v, normals[v]), 255))
            .collect(),
        indices: triangles.par_iter().flat_map_iter(|t| *t).collect(),
        lines: false,
        translation: origin.map(|o| to_gltf_axes(o.to_array())),
    }
}

/// An sRGB colour as glTF's COLOR_0 holds it: linear components (the format's "linear
/// multiplier"; a client that shows sRGB bytes as linear draws everything washed out), 8 bits
/// each, and `alpha` as it is.
pub fn linear_rgba(rgb: [u8; 3], alpha: u8) -> [u8; 4] {
    static LINEAR: std::sync::OnceLock<[u8; 256]> = std::sync::OnceLock::new();
    let table = LINEAR.get_or_init(|| {
        std::array::from_fn(|i| (super::climate::srgb_to_linear(i as f64 / 255.0) * 255.0).round() as u8)
    });
    [table[rgb[0] as usize], table[rgb[1] as usize], table[rgb[2] as usize], alpha]
}

/// The data of one buffer view, written into the binary chunk once the JSON before it is known.
enum ViewData<'a> {
    Vec3(&'a [[f32; 3]]),
    Rgba(&'a [[u8; 4]]),
    /// Quantized positions (x, y, z, pad).
    Short4(Vec<[i16; 4]>),
    /// Positions through the `EXPONENTIAL` filter.
    Exponential(Vec<[u32; 3]>),
    /// Normals through the `OCTAHEDRAL` filter.
    Octahedral(Vec<[i8; 4]>),
    /// Triangle indices written as u16 (all below 65535), or as u32.
    U16(&'a [u32]),
    U32(&'a [u32]),
    /// Line segments' indices, likewise.
    Lines16(&'a [u32]),
    Lines32(&'a [u32]),
}

impl ViewData<'_> {
    fn byte_len(&self) -> usize {
        match self {
            ViewData::Vec3(v) => v.len() * 12,
            ViewData::Rgba(c) => c.len() * 4,
            ViewData::Short4(v) => v.len() * 8,
            ViewData::Exponential(v) => v.len() * 12,
            ViewData::Octahedral(v) => v.len() * 4,
            ViewData::U16(i) | ViewData::Lines16(i) => i.len() * 2,
            ViewData::U32(i) | ViewData::Lines32(i) => i.len() * 4,
        }
    }

    /// Its meshopt stream's kind; `vertices` is the count its indices stay below.
    fn stream_kind(&self, vertices: usize) -> StreamKind {
        match self {
            ViewData::Vec3(_) | ViewData::Exponential(_) => StreamKind::Attributes { stride: 12 },
            ViewData::Rgba(_) | ViewData::Octahedral(_) => StreamKind::Attributes { stride: 4 },
            ViewData::Short4(_) => StreamKind::Attributes { stride: 8 },
            ViewData::U16(_) => StreamKind::Triangles { stride: 2, vertices },
            ViewData::U32(_) => StreamKind::Triangles { stride: 4, vertices },
            ViewData::Lines16(_) => StreamKind::Indices { stride: 2, vertices },
            ViewData::Lines32(_) => StreamKind::Indices { stride: 4, vertices },
        }
    }

    /// The meshopt filter its stream went through, if any.
    fn filter(&self) -> Option<&'static str> {
        match self {
            ViewData::Exponential(_) => Some("EXPONENTIAL"),
            ViewData::Octahedral(_) => Some("OCTAHEDRAL"),
            _ => None,
        }
    }

    /// Appends the little-endian bytes (a filtered view's: the filter's output), then zeros up to a multiple of 4.
    fn write(&self, out: &mut Vec<u8>) {
        let little = cfg!(target_endian = "little");
        match self {
            ViewData::Vec3(v) if little => out.extend_from_slice(bytemuck::cast_slice(v)),
            ViewData::Vec3(v) => v.iter().flatten().for_each(|x| out.extend_from_slice(&x.to_le_bytes())),
            ViewData::Rgba(c) => out.extend_from_slice(bytemuck::cast_slice(c)),
            ViewData::Short4(v) => v.iter().flatten().for_each(|x| out.extend_from_slice(&x.to_le_bytes())),
            ViewData::Exponential(v) => v.iter().flatten().for_each(|x| out.extend_from_slice(&x.to_le_bytes())),
            ViewData::Octahedral(v) => out.extend(v.iter().flatten().map(|&x| x as u8)),
            ViewData::U16(i) | ViewData::Lines16(i) => {
                i.iter().for_each(|&i| out.extend_from_slice(&(i as u16).to_le_bytes()))
            }
            ViewData::U32(i) | ViewData::Lines32(i) if little => out.extend_from_slice(bytemuck::cast_slice(i)),
            ViewData::U32(i) | ViewData::Lines32(i) => i.iter().for_each(|i| out.extend_from_slice(&i.to_le_bytes())),
        }
        out.resize(out.len().next_multiple_of(4), 0);
    }
}

/// The buffer views of the binary chunk, in order, and its padded length.
#[derive(Default)]
struct Layout<'a> {
    views: Vec<ViewData<'a>>,
    kinds: Vec<StreamKind>,
    bin_len: usize,
}

impl<'a> Layout<'a> {
    /// Adds a buffer view for `data` (attributes or indices of a mesh of `vertices`) at the end
    /// of the binary chunk; with `stride`, the view declares its byte stride.
    fn push(
        &mut self,
        root: &mut json::Root,
        data: ViewData<'a>,
        vertices: usize,
        target: json::buffer::Target,
        stride: bool,
    ) -> json::Index<json::buffer::View> {
        let (offset, len) = (self.bin_len, data.byte_len());
        let kind = data.stream_kind(vertices);
        self.bin_len += len.next_multiple_of(4);
        self.views.push(data);
        self.kinds.push(kind);
        root.push(json::buffer::View {
            buffer: json::Index::new(0),
            byte_length: USize64::from(len),
            byte_offset: Some(USize64::from(offset)),
            byte_stride: stride.then_some(json::buffer::Stride(kind.stride())),
            target: Some(Valid(target)),
            extensions: None,
            extras: Default::default(),
        })
    }
}

/// Drops the values gltf-json writes although they are glTF's defaults (an opaque, one-sided,
/// unlit-by-emission material of white base colour: ~100 bytes a material) and writes the
/// roughness as the decimal it was set from rather than its `f32` (0.8999999761581421).
fn trim_materials(value: &mut serde_json::Value) {
    use serde_json::json;
    let Some(materials) = value.get_mut("materials").and_then(|m| m.as_array_mut()) else { return };
    for m in materials.iter_mut().filter_map(|m| m.as_object_mut()) {
        for (key, default) in
            [("emissiveFactor", json!([0.0, 0.0, 0.0])), ("doubleSided", json!(false)), ("alphaMode", json!("OPAQUE"))]
        {
            if m.get(key) == Some(&default) {
                m.remove(key);
            }
        }
        let Some(pbr) = m.get_mut("pbrMetallicRoughness").and_then(|p| p.as_object_mut()) else { continue };
        if pbr.get("baseColorFactor") == Some(&json!([1.0, 1.0, 1.0, 1.0])) {
            pbr.remove("baseColorFactor");
        }
        if let Some(r) = pbr.get("roughnessFactor").and_then(|r| r.as_f64()) {
            pbr.insert("roughnessFactor".into(), json!((r * 1e6).round() / 1e6));
        }
    }
}

fn accessor(
    view: json::Index<json::buffer::View>,
    count: usize,
    component: ComponentType,
    type_: Type,
    normalized: bool,
    bounds: Option<(serde_json::Value, serde_json::Value)>,
) -> json::Accessor {
    let (min, max) = bounds.map_or((None, None), |(a, b)| (Some(a), Some(b)));
    json::Accessor {
        buffer_view: Some(view),
        byte_offset: None,
        count: USize64::from(count),
        component_type: Valid(GenericComponentType(component)),
        extensions: None,
        extras: Default::default(),
        type_: Valid(type_),
        min,
        max,
        normalized,
        sparse: None,
    }
}

/// An opaque material, or a blended one for translucent surfaces (the water), which is
/// double-sided so that an eye under the sea sees the surface from below.
fn material(root: &mut json::Root, blend: bool) -> json::Index<json::Material> {
    use json::material::{AlphaMode, PbrMetallicRoughness, StrengthFactor};
    root.push(json::Material {
        alpha_mode: Valid(if blend { AlphaMode::Blend } else { AlphaMode::Opaque }),
        double_sided: blend,
        pbr_metallic_roughness: PbrMetallicRoughness {
            metallic_factor: StrengthFactor(0.0),
            roughness_factor: StrengthFactor(if blend { 0.2 } else { 0.9 }),
            ..Default::default()
        },
        ..Default::default()
    })
}

/// Encodes meshes as one `.glb`: one glTF mesh (one TRIANGLES primitive, or LINES for `lines`),
/// one node and one set of
/// accessors per [`GlbMesh`], in order, all in one binary buffer and one default scene, stored
/// as `compression` says (`glb_pack.rs`). Meshes without positions or indices are left out (no
/// meshes at all: no scene, no buffer). Panics if `normals` or `colors` is neither empty nor as
/// long as `positions`, or if an index is out of range; refuses meshes that would not fit the
/// container ([`GlbTooLarge`]) before writing.
pub fn encode_glb(meshes: &[GlbMesh], compression: Compression) -> Result<Vec<u8>, GlbTooLarge> {
    use json::buffer::Target::{ArrayBuffer, ElementArrayBuffer};
    let mut root = json::Root {
        asset: json::Asset {
            generator: Some("riverworld".to_string()),
            version: "2.0".to_string(),
            ..Default::default()
        },
        ..Default::default()
    };
    for m in meshes {
        let n = m.positions.len();
        assert!(m.normals.is_empty() || m.normals.len() == n, "normals must match positions");
        assert!(m.colors.is_empty() || m.colors.len() == n, "colors must match positions");
        assert!(m.indices.iter().all(|&i| (i as usize) < n), "index out of range");
    }
    let packed = compression == Compression::Meshopt;
    let reordered: Vec<GlbMesh>;
    let meshes = if packed {
        reordered = meshes
            .iter()
            .map(|m| {
                if m.indices.is_empty() {
                    GlbMesh::default()
                } else if m.lines {
                    m.clone()
                } else {
                    reorder(m)
                }
            })
            .collect();
        &reordered[..]
    } else {
        meshes
    };
    // The binary chunk is laid out first and written last, straight into the output.
    let mut layout = Layout::default();
    let mut materials: [Option<json::Index<json::Material>>; 2] = [None, None];
    let mut nodes = Vec::new();
    // Each node's translation (f64) and uniform scale (quantized positions).
    let mut transforms: Vec<(Option<[f64; 3]>, Option<f64>)> = Vec::new();
    let mut quantized_any = false;
    for m in meshes.iter().filter(|m| !m.positions.is_empty() && !m.indices.is_empty()) {
        let n = m.positions.len();
        let mut attributes = BTreeMap::new();
        let limit = if packed { position_step_limit(shortest_edge(&m.positions, &m.indices, m.lines)) } else { 0.0 };
        let quantized = if packed { quantize_positions(&m.positions, limit) } else { None };
        let filtered = if packed && quantized.is_none() { filter_positions(&m.positions, limit) } else { None };
        let (position, transform) = match (quantized, filtered) {
            (Some(q), _) => {
                let (lo, hi) = extent(q.values.iter().map(|v| [v[0], v[1], v[2]]), i16::MAX, i16::MIN);
                let bounds = (serde_json::json!(lo), serde_json::json!(hi));
                let base = m.translation.unwrap_or([0.0; 3]);
                let translation = std::array::from_fn(|k| base[k] + q.centre[k]);
                let view = layout.push(&mut root, ViewData::Short4(q.values), n, ArrayBuffer, true);
                quantized_any = true;
                let acc = accessor(view, n, ComponentType::I16, Type::Vec3, false, Some(bounds));
                (acc, (Some(translation), Some(q.step)))
            }
            (None, filtered) => {
                let decoded = filtered.as_ref().map_or(&m.positions[..], |f| &f.decoded[..]);
                let (lo, hi) = extent(decoded.iter().copied(), f32::INFINITY, f32::NEG_INFINITY);
                let bounds = (serde_json::json!(lo.map(f64::from)), serde_json::json!(hi.map(f64::from)));
                let data = filtered.map_or(ViewData::Vec3(&m.positions), |f| ViewData::Exponential(f.values));
                let view = layout.push(&mut root, data, n, ArrayBuffer, packed);
                (accessor(view, n, ComponentType::F32, Type::Vec3, false, Some(bounds)), (m.translation, None))
            }
        };
        attributes.insert(Valid(json::mesh::Semantic::Positions), root.push(position));
        if !m.normals.is_empty() {
            let acc = if packed {
                quantized_any = true;
                let view =
                    layout.push(&mut root, ViewData::Octahedral(octahedral_normals(&m.normals)), n, ArrayBuffer, true);
                accessor(view, n, ComponentType::I8, Type::Vec3, true, None)
            } else {
                let view = layout.push(&mut root, ViewData::Vec3(&m.normals), n, ArrayBuffer, false);
                accessor(view, n, ComponentType::F32, Type::Vec3, false, None)
            };
            attributes.insert(Valid(json::mesh::Semantic::Normals), root.push(acc));
        }
        if !m.colors.is_empty() {
            let view = layout.push(&mut root, ViewData::Rgba(&m.colors), n, ArrayBuffer, packed);
            let acc = root.push(accessor(view, n, ComponentType::U8, Type::Vec4, true, None));
            attributes.insert(Valid(json::mesh::Semantic::Colors(0)), acc);
        }
        // 16-bit indices where they fit (65535 itself is reserved for primitive restart).
        let (data, component) = match (n <= usize::from(u16::MAX), m.lines) {
            (true, false) => (ViewData::U16(&m.indices), ComponentType::U16),
            (false, false) => (ViewData::U32(&m.indices), ComponentType::U32),
            (true, true) => (ViewData::Lines16(&m.indices), ComponentType::U16),
            (false, true) => (ViewData::Lines32(&m.indices), ComponentType::U32),
        };
        let view = layout.push(&mut root, data, n, ElementArrayBuffer, false);
        let indices = root.push(accessor(view, m.indices.len(), component, Type::Scalar, false, None));
        let blend = m.colors.iter().any(|c| c[3] < 255);
        let mat = match materials[blend as usize] {
            Some(i) => i,
            None => *materials[blend as usize].insert(material(&mut root, blend)),
        };
        let primitive = json::mesh::Primitive {
            attributes,
            extensions: None,
            extras: Default::default(),
            indices: Some(indices),
            material: Some(mat),
            mode: Valid(if m.lines { json::mesh::Mode::Lines } else { json::mesh::Mode::Triangles }),
            targets: None,
        };
        let mesh = root.push(json::Mesh {
            extensions: None,
            extras: Default::default(),
            primitives: vec![primitive],
            weights: None,
        });
        nodes.push(root.push(json::Node {
            mesh: Some(mesh),
            translation: transform.0.map(|t| t.map(|x| x as f32)),
            scale: transform.1.map(|s| [s as f32; 3]),
            ..Default::default()
        }));
        transforms.push(transform);
    }
    // The binary chunk: the views' bytes (written last, straight into the output), or their
    // meshopt streams.
    let mut streams: Vec<(usize, usize)> = Vec::new();
    let mut packed_bin = Vec::new();
    if packed {
        let mut plain = Vec::new();
        for (data, kind) in layout.views.iter().zip(&layout.kinds) {
            plain.clear();
            data.write(&mut plain);
            let stream = meshopt_stream(&plain[..data.byte_len()], *kind);
            streams.push((packed_bin.len(), stream.len()));
            packed_bin.extend_from_slice(&stream);
            packed_bin.resize(packed_bin.len().next_multiple_of(4), 0);
        }
    }
    let bin_len = if packed { packed_bin.len() } else { layout.bin_len };
    if bin_len > 0 {
        root.push(json::Buffer {
            byte_length: USize64::from(bin_len),
            uri: None,
            extensions: None,
            extras: Default::default(),
        });
    }
    if packed && bin_len > 0 {
        // The views' uncompressed layout lives in a fallback buffer that holds no bytes.
        root.push(json::Buffer {
            byte_length: USize64::from(layout.bin_len),
            uri: None,
            extensions: None,
            extras: Default::default(),
        });
        root.extensions_used.push(MESHOPT.to_string());
        root.extensions_required.push(MESHOPT.to_string());
        if quantized_any {
            root.extensions_used.push(QUANTIZATION.to_string());
            root.extensions_required.push(QUANTIZATION.to_string());
        }
    }
    if !nodes.is_empty() {
        let scene = root.push(json::Scene { extensions: None, extras: Default::default(), nodes });
        root.scene = Some(scene);
    }

    let mut value = serde_json::to_value(&root).expect("glTF JSON serialises");
    // gltf-json holds translations and scales as f32 (~0.5 m at planet scale): write the f64
    // values.
    for (i, (t, s)) in transforms.iter().enumerate() {
        if let Some(t) = t {
            value["nodes"][i]["translation"] = serde_json::json!(t);
        }
        if let Some(s) = s {
            value["nodes"][i]["scale"] = serde_json::json!([s, s, s]);
        }
    }
    trim_materials(&mut value);
    if packed && bin_len > 0 {
        value["buffers"][1]["extensions"] = serde_json::json!({ MESHOPT: { "fallback": true } });
        for (i, (((offset, len), kind), data)) in streams.iter().zip(&layout.kinds).zip(&layout.views).enumerate() {
            let view = &mut value["bufferViews"][i];
            view["buffer"] = serde_json::json!(1);
            let count = view["byteLength"].as_u64().expect("a length") / kind.stride() as u64;
            let mut ext = serde_json::json!({
                "buffer": 0, "byteOffset": offset, "byteLength": len,
                "byteStride": kind.stride(), "count": count, "mode": kind.mode(),
            });
            if let Some(filter) = data.filter() {
                ext["filter"] = serde_json::json!(filter);
            }
            view["extensions"] = serde_json::json!({ MESHOPT: ext });
        }
    }
    let mut json_bytes = serde_json::to_vec(&value).expect("glTF JSON serialises");
    // GLB container: 12-byte header, JSON chunk padded with spaces, BIN chunk (when there is
    // data) padded with zeros.
    json_bytes.resize(json_bytes.len().next_multiple_of(4), b' ');
    let total = glb_len(json_bytes.len(), bin_len)?;
    let mut out = Vec::with_capacity(total as usize);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&total.to_le_bytes());
    out.extend_from_slice(&(json_bytes.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json_bytes);
    if bin_len > 0 {
        out.extend_from_slice(&(bin_len as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        if packed {
            out.extend_from_slice(&packed_bin);
        } else {
            layout.views.iter().for_each(|data| data.write(&mut out));
        }
    }
    debug_assert_eq!(out.len(), total as usize);
    Ok(out)
}

/// The mesh with its triangles in vertex-cache order and its vertices in order of first use
/// (unused ones dropped), for smaller meshopt streams.
pub fn reorder(m: &GlbMesh) -> GlbMesh {
    let n = m.positions.len();
    let indices = meshopt::optimize_vertex_cache(&m.indices, n);
    let remap = meshopt::optimize_vertex_fetch_remap(&indices, n);
    let kept = remap.iter().filter(|&&r| r != u32::MAX).count();
    fn apply<T: Copy + Default>(values: &[T], remap: &[u32], kept: usize) -> Vec<T> {
        if values.is_empty() {
            return Vec::new();
        }
        let mut out = vec![T::default(); kept];
        for (v, &to) in values.iter().zip(remap) {
            if to != u32::MAX {
                out[to as usize] = *v;
            }
        }
        out
    }
    GlbMesh {
        positions: apply(&m.positions, &remap, kept),
        normals: apply(&m.normals, &remap, kept),
        colors: apply(&m.colors, &remap, kept),
        indices: indices.iter().map(|&i| remap[i as usize]).collect(),
        lines: false,
        translation: m.translation,
    }
}

/// Least and greatest value per axis (`none` and `all` start them: the type's greatest and
/// least).
fn extent<T: Copy + PartialOrd>(points: impl Iterator<Item = [T; 3]>, none: T, all: T) -> ([T; 3], [T; 3]) {
    let (mut lo, mut hi) = ([none; 3], [all; 3]);
    for p in points {
        for k in 0..3 {
            if p[k] < lo[k] {
                lo[k] = p[k];
            }
            if p[k] > hi[k] {
                hi[k] = p[k];
            }
        }
    }
    (lo, hi)
}

/// The extensions a compressed `.glb` requires.
const MESHOPT: &str = "EXT_meshopt_compression";
const QUANTIZATION: &str = "KHR_mesh_quantization";

#[cfg(test)]
#[path = "glb_tests.rs"]
pub(crate) mod tests;
