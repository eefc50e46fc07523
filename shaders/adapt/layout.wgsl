// Every layout the adaption shaders read, spelt out once on the device side and prepended to
// every stage (`src/adapt/gpu/shaders.rs`): the mesh buffers of `src/mesh/mod.rs` (`Vertex`,
// `Edge`, `Face`, paper Table 3) and the elevation map's `GuideFace`, and the parameter blocks
// of `src/adapt/gpu/layout.rs` (`View`, `SplitParams`, `Sweep`, `Grid`). A test of `layout.rs`
// checks each struct's size and member offsets against its Rust twin. Also the constants and
// arithmetic the stages share.
//
// Every f64 operation follows the CPU code (glam's `DVec3`, `src/rng.rs`) operation for
// operation and in the same order, so a device that rounds f64 arithmetic and `sqrt` correctly
// without fusing multiply-adds (lavapipe) computes the CPU's values bit for bit.

struct Vertex {
    pos: array<f64, 3>,
    ground: f64,
    water: f64,
    edge: u32,
    // `Lod`: length (bfloat16, low half), radius (bfloat16, high half)
    parent_lod: u32,
    seed: u32,
    // `Tangent` (24 bits, low), flags (u8, high)
    bits: u32,
}

struct Edge {
    v: array<u32, 2>,
    f: array<u32, 2>,
    // `Lod`: length (bfloat16, low half), radius (bfloat16, high half)
    lod: u32,
    // level (u16), kind (u8), land (u8: bit 0 when face f[0] is land, bit 1 for f[1])
    bits: u32,
}

// Corners are not stored: `e[i]` is the edge opposite corner `i`, and the stages that need a
// corner take it from the far end of one of these edges (`Mesh::corners`). The face's kind
// is kept by its edges (`Edge::land`).
struct Face {
    e: array<u32, 3>,
}

// A vertex-wise dispatch of the collapse stages (`Sweep`).
struct Sweep {
    vertices: u32,
    // Invocations per row of the dispatch grid (vertex = x + y * row).
    row: u32,
    // 1: look only at vertices marked `MARK_LOOK` (the apexes the last collapses restored).
    among: u32,
    _pad: u32,
}

// The view of the state update and of the collapses' restored edges (`GpuView`).
struct View {
    eye: array<f64, 3>,
    planes: array<array<f64, 3>, 5>,
    per_unit: array<f64, 5>,
    eye_dir: array<f64, 3>,
    horizon: f64,
    c_land: f64,
    c_water: f64,
    min_len: f64,
    c_lod: f64,
    edges: u32,
    row: u32,
}

// The terrain parameters and batch shape of the splits (`SplitParams`).
struct SplitParams {
    radius: f64,
    sea_level: f64,
    riverbed_edge_height: f64,
    max_river_depth: f64,
    min_river_length: f64,
    max_river_altitude: f64,
    max_mountain_altitude: f64,
    riverbed_slope: f64,
    near_river_slope: f64,
    ground_slope: f64,
    river_slope: f64,
    // `2 sqrt(3)` as the CPU computes it, and `MIN_SPLIT_QUALITY`.
    quality_scale: f64,
    min_quality: f64,
    // The constants of the terrain arithmetic, read at run time: compilers rewrite expressions
    // with literal constants (lavapipe folded `(1 - a) + b` into `(b - a) + 1` and a constant
    // factor into a neighbouring sum), which round differently; they cannot rewrite with values
    // they do not know. `SplitParams::new` gives the CPU's values.
    one: f64,
    half: f64,
    quarter: f64,
    three_quarters: f64,
    sea_roughness: f64,
    roughness: f64,
    roughness_length: f64,
    sea_roughness_length: f64,
    tangent_scale: f64,
    tangent_offset: f64,
    // `Guide::min_edge_m` (`src/mesh/guide.rs`): continent splits of edges at least this long
    // take the elevation map's ground.
    guide_min_edge: f64,
    // `src/mesh/split/landform.rs`: the landform's detail below the map's pixel.
    floor_slope: f64,
    floor_length: f64,
    relief: f64,
    altitude_gain: f64,
    hybrid: f64,
    relief_length: f64,
    smooth_length: f64,
    threshold: f64,
    map_relief: f64,
    ridge: f64,
    floor_fade: f64,
    altitude_length: f64,
    sea_detail: f64,
    // Slots where the new vertices, edges and faces start.
    vertices: u32,
    edges: u32,
    faces: u32,
    // Splits in the list, and invocations per row of the dispatch (split = x + y * row).
    count: u32,
    row: u32,
    // The guide's faces (0: the planet has no elevation map) and cells along their sides.
    guide_faces: u32,
    guide_side: u32,
    _pad: u32,
}

// `GuideFace` of `src/mesh/guide.rs`.
struct GuideFace {
    centre: vec3<f64>,
    x0: f64,
    east: vec3<f64>,
    y0: f64,
    north: vec3<f64>,
    step: f64,
}

// The shape of a block prefix sum (`ScanGrid`).
struct Grid {
    // Items to scan.
    items: u32,
    // Invocations per row of an item-wise dispatch (item = x + y * row).
    row: u32,
    // Blocks of `BLOCK` items, and workgroups per row of the block-wise dispatch.
    blocks: u32,
    block_row: u32,
}

const NONE: u32 = 0xffffffffu;
// An entity a collapse removed, until compaction (`mesh::split::DEAD`).
const DEAD: u32 = 0xfffffffeu;

const KIND_SEA: u32 = 0u;
const KIND_COAST: u32 = 1u;
const KIND_CONTINENT: u32 = 2u;
const KIND_RIVER: u32 = 3u;

const FLAG_RIVER: u32 = 8u;
const FLAG_REFINED: u32 = 64u;
const FLAG_LAKE: u32 = 128u;

// Per-vertex marks of the collapse stage: an apex a collapse restored (looked at next), and a
// collapse candidate.
const MARK_LOOK: u32 = 1u;
const MARK_COLLAPSE: u32 = 2u;

const F64_MAX: f64 = 1.7976931348623157e308lf;

fn edge_kind(e: Edge) -> u32 {
    return (e.bits >> 16u) & 0xffu;
}

// Bit 0: face f[0] is land; bit 1: face f[1] is.
fn edge_land(e: Edge) -> u32 {
    return e.bits >> 24u;
}

fn edge_level(e: Edge) -> u32 {
    return e.bits & 0xffffu;
}

fn vertex_flags(v: Vertex) -> u32 {
    return v.bits >> 24u;
}

// A bfloat16 is the upper half of an f32.
fn lod_len(lod: u32) -> f32 {
    return bitcast<f32>(lod << 16u);
}

fn lod_radius(lod: u32) -> f32 {
    return bitcast<f32>(lod & 0xffff0000u);
}

fn triple(a: array<f64, 3>) -> vec3<f64> {
    return vec3<f64>(a[0], a[1], a[2]);
}

// `(a.x * b.x + a.y * b.y) + a.z * b.z`, in that order (glam's dot).
fn dot3(a: vec3<f64>, b: vec3<f64>) -> f64 {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

fn length3(a: vec3<f64>) -> f64 {
    return sqrt(dot3(a, a));
}

fn distance3(a: vec3<f64>, b: vec3<f64>) -> f64 {
    return length3(a - b);
}

// glam's `normalize`: times the reciprocal of the length.
fn normalize3(a: vec3<f64>) -> vec3<f64> {
    return a * (f64(1.0) / length3(a));
}

fn cross3(a: vec3<f64>, b: vec3<f64>) -> vec3<f64> {
    return vec3<f64>(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y);
}

// `mix32` of `src/rng.rs` (lowbias32).
fn mix32(seed: u32) -> u32 {
    var x = seed;
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// `unit` of `src/rng.rs`: uniform in [0, 1) for a seed and a salt.
fn unit(seed: u32, salt: u32) -> f64 {
    let h = mix32(seed ^ mix32(salt * 0x9e3779b9u + 0x632be5abu));
    return f64(h) / f64(4294967296.0);
}

fn uniform_in(seed: u32, salt: u32, lo: f64, hi: f64) -> f64 {
    return lo + (hi - lo) * unit(seed, salt);
}
