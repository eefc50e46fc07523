// Parallel edge splits (paper §5.3, Algorithm 2 steps 3-6): one invocation per ready edge of the
// split list. The twin of `split_vertex` (`src/mesh/altitude.rs`, `src/mesh/terrain.rs`: new
// vertex positions by eq. 2 / eq. 7-9, altitudes by step 6 and eq. 10-12) and of
// `Buffers::split` (`src/mesh/batch.rs`: the topology), operation for operation.
//
// Race-free as the paper argues: a ready edge is the refinement edge of both its faces, so a
// split owns its edge, its two faces and its new slots; what two splits can share is an outer
// edge, of which each rewrites only the face slot holding its own face, and a corner vertex,
// whose edge link only the split owning the linked edge moves. Both are single-word writes to
// words no other invocation writes, and the fields the splits read of their neighbours
// (positions, altitudes, seeds, tangents, flags) are not written by any split.
//
// Layouts: `layout.wgsl` (prepended).

@group(0) @binding(0) var<storage, read_write> vertices: array<Vertex>;
@group(0) @binding(1) var<storage, read_write> edges: array<Edge>;
@group(0) @binding(2) var<storage, read_write> faces: array<Face>;
@group(0) @binding(3) var<storage, read> list: array<u32>;
@group(0) @binding(4) var<uniform> p: SplitParams;
@group(0) @binding(5) var<storage, read> guide_faces: array<GuideFace>;
@group(0) @binding(6) var<storage, read> guide_values: array<f32>;

const SALT_XI: u32 = 1u;
const SALT_ETA: u32 = 2u;
const SALT_ALTITUDE: u32 = 3u;
const SALT_RIVER: u32 = 4u;
const SALT_DETAIL: u32 = 7u;
const F64_MIN_POSITIVE: f64 = 2.2250738585072014e-308lf;
const F64_MIN: f64 = -1.7976931348623157e308lf;

struct Site {
    edge: u32,
    a: u32,
    b: u32,
    t: u32,
    d: u32,
    f1: u32,
    f2: u32,
}

// A new vertex and the kinds of `[e1, e2, e3, e4]`.
struct Made {
    v: Vertex,
    kinds: array<u32, 4>,
}

fn pos(v: u32) -> vec3<f64> {
    return triple(vertices[v].pos);
}

fn sign1(x: f64) -> f64 {
    if x < f64(0.0) {
        return f64(-1.0);
    }
    return f64(1.0);
}

// Rust's `f64::round`: halves away from zero.
fn round_away(x: f64) -> f64 {
    let a = abs(x);
    var r = floor(a);
    if a - r >= f64(0.5) {
        r += f64(1.0);
    }
    if x < f64(0.0) {
        return -r;
    }
    return r;
}

// `Tangent::get` (`src/mesh/packed.rs`): octahedral code to unit vector.
fn tangent_get(code: u32) -> vec3<f64> {
    if code == 0u {
        return vec3<f64>(f64(0.0), f64(0.0), f64(0.0));
    }
    var x = (f64(code & 0xfffu) - p.tangent_offset) / p.tangent_scale;
    var y = (f64(code >> 12u) - p.tangent_offset) / p.tangent_scale;
    let z = p.one - abs(x) - abs(y);
    if z < f64(0.0) {
        let x0 = x;
        x = (p.one - abs(y)) * sign1(x0);
        y = (p.one - abs(x0)) * sign1(y);
    }
    return normalize3(vec3<f64>(x, y, z));
}

// `Tangent::new`: unit vector to octahedral code (0: no direction).
fn tangent_code(t: vec3<f64>) -> u32 {
    let l1 = abs(t.x) + abs(t.y) + abs(t.z);
    if !(l1 > f64(0.0) && l1 <= F64_MAX) {
        return 0u;
    }
    var x = t.x / l1;
    var y = t.y / l1;
    if t.z < f64(0.0) {
        let x0 = x;
        x = (p.one - abs(y)) * sign1(x0);
        y = (p.one - abs(x0)) * sign1(y);
    }
    let cx = u32(p.tangent_offset + clamp(round_away(x * p.tangent_scale), f64(-2047.0), f64(2047.0)));
    let cy = u32(p.tangent_offset + clamp(round_away(y * p.tangent_scale), f64(-2047.0), f64(2047.0)));
    return cx | (cy << 12u);
}

// `f32::next_down`.
fn next_down(f: f32) -> f32 {
    let bits = bitcast<u32>(f);
    if (bits & 0x7fffffffu) == 0u {
        return bitcast<f32>(0x80000001u);
    }
    if f > 0.0 {
        return bitcast<f32>(bits - 1u);
    }
    return bitcast<f32>(bits + 1u);
}

// `bf16_down`: the largest bfloat16 not above `x`, as its bits.
fn bf16_down(x: f64) -> u32 {
    var f = f32(x);
    if f64(f) > x {
        f = next_down(f);
    }
    let bits = bitcast<u32>(f);
    let high = bits >> 16u;
    if f < 0.0 && (bits & 0xffffu) != 0u {
        return high + 1u;
    }
    return high;
}

fn lod_new(len: f64, radius: f64) -> u32 {
    return bf16_down(len) | (bf16_down(radius) << 16u);
}

// Eq. 1.
fn lift(q: vec3<f64>, altitude: f64) -> vec3<f64> {
    return normalize3(q) * (p.radius + altitude);
}

fn tangent_towards(src: vec3<f64>, dst: vec3<f64>) -> vec3<f64> {
    return tangent_along(src, dst - src);
}

fn tangent_along(at: vec3<f64>, d: vec3<f64>) -> vec3<f64> {
    let up = normalize3(at);
    let t = d - up * dot3(d, up);
    // glam's `normalize_or_zero`.
    let rcp = f64(1.0) / length3(t);
    if rcp <= F64_MAX && rcp > f64(0.0) {
        return t * rcp;
    }
    return vec3<f64>(f64(0.0), f64(0.0), f64(0.0));
}

fn land_roughness(edge_len: f64) -> f64 {
    return p.roughness * edge_len / (p.one + edge_len / p.roughness_length);
}

fn sea_roughness(edge_len: f64) -> f64 {
    return p.sea_roughness * edge_len / (p.one + edge_len / p.sea_roughness_length);
}

// `Guide::at` (`src/mesh/guide.rs`): the elevation map's metres at unit direction `d`, if any.
struct Guided {
    found: bool,
    metres: f64,
}

fn guide_dot(a: vec3<f64>, b: vec3<f64>) -> f64 {
    return (a.x * b.x + a.y * b.y) + a.z * b.z;
}

// `Guide::face_of`: the guide face whose centre `d` is nearest.
fn guide_face(d: vec3<f64>) -> u32 {
    var best = 0u;
    var best_k = -F64_MAX;
    for (var i = 0u; i < p.guide_faces; i++) {
        let k = guide_dot(guide_faces[i].centre, d);
        if k > best_k {
            best_k = k;
            best = i;
        }
    }
    return best;
}

// The cell of the guide's grid under unit direction `d` (`Guide::cell`): the index of the
// lower corner of the four cells `guide_at` interpolates between, and the fractions.
struct GuideCell {
    found: bool,
    at: u32,
    fx: f64,
    fy: f64,
}

fn guide_cell(d: vec3<f64>) -> GuideCell {
    let best = guide_face(d);
    if p.guide_faces == 0u {
        return GuideCell(false, 0u, 0.0lf, 0.0lf);
    }
    let at_grid = guide_grid(best, d);
    if at_grid.z < p.half {
        return GuideCell(false, 0u, 0.0lf, 0.0lf);
    }
    let side = f64(p.guide_side);
    let gx = min(max(at_grid.x, 0.0lf), side - p.one);
    let gy = min(max(at_grid.y, 0.0lf), side - p.one);
    let ix = min(floor(gx), side - 2.0lf);
    let iy = min(floor(gy), side - 2.0lf);
    let at = best * p.guide_side * p.guide_side + u32(iy) * p.guide_side + u32(ix);
    return GuideCell(true, at, gx - ix, gy - iy);
}

// `Guide::patch`: the four cells around `d` and the fractions, found when the map has data in
// all four.
struct GuidePatch {
    found: bool,
    v00: f64,
    v10: f64,
    v01: f64,
    v11: f64,
    fx: f64,
    fy: f64,
}

fn guide_patch(d: vec3<f64>) -> GuidePatch {
    let c = guide_cell(d);
    if !c.found {
        return GuidePatch(false, 0.0lf, 0.0lf, 0.0lf, 0.0lf, 0.0lf, 0.0lf);
    }
    let v00 = f64(guide_values[c.at]);
    let v10 = f64(guide_values[c.at + 1u]);
    let v01 = f64(guide_values[c.at + p.guide_side]);
    let v11 = f64(guide_values[c.at + p.guide_side + 1u]);
    let missing = min(min(v00, v10), min(v01, v11)) < -1.0e29lf;
    return GuidePatch(!missing, v00, v10, v01, v11, c.fx, c.fy);
}

fn guide_at(d: vec3<f64>) -> Guided {
    let q = guide_patch(d);
    if !q.found {
        return Guided(false, 0.0lf);
    }
    let a = q.v00 + (q.v10 - q.v00) * q.fx;
    let b = q.v01 + (q.v11 - q.v01) * q.fx;
    return Guided(true, a + (b - a) * q.fy);
}

// `Guide::relief_at`: the twist of the map's bilinear patch under `d` (0 without data).
fn guide_twist(d: vec3<f64>) -> f64 {
    let q = guide_patch(d);
    if !q.found {
        return 0.0lf;
    }
    return abs((q.v00 + q.v11) - (q.v10 + q.v01));
}

// `catmull_rom` (`src/mesh/guide.rs`): the Catmull-Rom cubic through `p1` (at 0) and `p2` (at 1).
fn catmull_rom(p0: f64, p1: f64, p2: f64, p3: f64, t: f64) -> f64 {
    let a = p2 - p0;
    let b = (((p0 + p0) - (((p1 + p1) + (p1 + p1)) + p1)) + ((p2 + p2) + (p2 + p2))) - p3;
    let c = (((p1 - p2) + (p1 - p2)) + (p1 - p2)) + (p3 - p0);
    return p1 + (t * (a + t * (b + t * c))) * p.half;
}

// Grid coordinates of unit direction `q` on guide face `f` (`z` 0 behind it).
fn guide_grid(f: u32, q: vec3<f64>) -> vec3<f64> {
    let face = guide_faces[f];
    let k = guide_dot(face.centre, q);
    if !(k > 0.0lf) {
        return vec3<f64>(0.0lf, 0.0lf, 0.0lf);
    }
    let gx = (guide_dot(face.east, q) / k - face.x0) / face.step - p.half;
    let gy = (guide_dot(face.north, q) / k - face.y0) / face.step - p.half;
    return vec3<f64>(gx, gy, p.one);
}

// The bicubic through the 4 x 4 taps at grid fractions `(u, v)` from the taps' second cell.
fn guide_bicubic(taps: array<f64, 16>, u: f64, v: f64) -> f64 {
    let r0 = catmull_rom(taps[0], taps[1], taps[2], taps[3], u);
    let r1 = catmull_rom(taps[4], taps[5], taps[6], taps[7], u);
    let r2 = catmull_rom(taps[8], taps[9], taps[10], taps[11], u);
    let r3 = catmull_rom(taps[12], taps[13], taps[14], taps[15], u);
    return catmull_rom(r0, r1, r2, r3, v);
}

// `Guide::bend`: the bicubic through the map's cells at `d` less its mean at the diamond's
// corners `[a, t, b, d]`, all read from the cubic piece of `d`'s cell (0 without data).
fn guide_bend(d: vec3<f64>, ca: vec3<f64>, ct: vec3<f64>, cb: vec3<f64>, cd: vec3<f64>, edge_len: f64) -> f64 {
    // `BEND_REACH` (16): none for edges that much shorter than the map's pixel.
    if edge_len * 16.0lf < p.guide_min_edge {
        return 0.0lf;
    }
    let best = guide_face(d);
    let g = guide_grid(best, d);
    let ga = guide_grid(best, ca);
    let gt = guide_grid(best, ct);
    let gb = guide_grid(best, cb);
    let gd = guide_grid(best, cd);
    if min(min(g.z, ga.z), min(min(gt.z, gb.z), gd.z)) < p.half {
        return 0.0lf;
    }
    let side = f64(p.guide_side);
    let ix = min(floor(min(max(g.x, 0.0lf), side - p.one)), side - 2.0lf);
    let iy = min(floor(min(max(g.y, 0.0lf), side - p.one)), side - 2.0lf);
    let face = best * p.guide_side * p.guide_side;
    var taps: array<f64, 16>;
    for (var j = 0u; j < 4u; j++) {
        let y = u32(min(max(iy + f64(j) - p.one, 0.0lf), side - p.one));
        for (var i = 0u; i < 4u; i++) {
            let x = u32(min(max(ix + f64(i) - p.one, 0.0lf), side - p.one));
            let v = f64(guide_values[face + y * p.guide_side + x]);
            if v < -1.0e29lf {
                return 0.0lf;
            }
            taps[j * 4u + i] = v;
        }
    }
    let centre = guide_bicubic(taps, g.x - ix, g.y - iy);
    let va = guide_bicubic(taps, ga.x - ix, ga.y - iy);
    let vt = guide_bicubic(taps, gt.x - ix, gt.y - iy);
    let vb = guide_bicubic(taps, gb.x - ix, gb.y - iy);
    let vd = guide_bicubic(taps, gd.x - ix, gd.y - iy);
    return centre - ((va + vb) * p.half + (vt + vd) * p.half) * p.half;
}

fn edge_centre(s: Site) -> vec3<f64> {
    return (pos(s.a) + pos(s.b)) * p.half;
}

// Eq. 2.
fn weighted_position(s: Site, seed: u32) -> vec3<f64> {
    let xi = uniform_in(seed, SALT_XI, p.quarter, p.three_quarters);
    let eta = uniform_in(seed, SALT_ETA, p.quarter, p.three_quarters);
    let a = pos(s.a);
    let b = pos(s.b);
    let t = pos(s.t);
    let d = pos(s.d);
    return (p.one - eta) * (xi * a + (p.one - xi) * t) + eta * (xi * d + (p.one - xi) * b);
}

// Eq. 7-9.
fn river_position(s: Site, seed: u32) -> vec3<f64> {
    let xi0 = uniform_in(seed, SALT_XI, p.quarter, p.three_quarters);
    let a = pos(s.a);
    let b = pos(s.b);
    let t = pos(s.t);
    let d = pos(s.d);
    let ab = distance3(a, b);
    if ab >= p.min_river_length {
        return (p.one - xi0) * t + xi0 * d;
    }
    let a_up = vertices[s.a].water >= vertices[s.b].water;
    let up = select(s.b, s.a, a_up);
    let down = select(s.a, s.b, a_up);
    let tu = tangent_get(vertices[up].bits & 0xffffffu);
    let td = tangent_get(vertices[down].bits & 0xffffffu);
    // Times the run-time one: left as a sum, lavapipe folded the `- d` below into it.
    let vs = ((a + b) * p.half + ab * (tu - td) * p.quarter) * p.one;
    let td_line = t - d;
    let denom = dot3(td_line, td_line);
    let sx = select(p.half, p.one - dot3(vs - d, td_line) / denom, denom > f64(0.0));
    let xi = clamp(sx + p.quarter * (xi0 - p.half), f64(0.25), f64(0.75));
    return (p.one - xi) * t + xi * d;
}

fn face_quality(x: vec3<f64>, y: vec3<f64>, z: vec3<f64>) -> f64 {
    let twice_area = dot3(cross3(x, y), z);
    let sides = dot3(x - y, x - y) + dot3(y - z, y - z) + dot3(z - x, z - x);
    return p.quality_scale * twice_area / sides;
}

// `well_shaped`: the randomised point, or pulled towards the edge centre.
fn well_shaped(s: Site, q: vec3<f64>) -> vec3<f64> {
    let a = normalize3(pos(s.a));
    let b = normalize3(pos(s.b));
    let t = normalize3(pos(s.t));
    let d = normalize3(pos(s.d));
    let c = edge_centre(s);
    var scale = f64(1.0);
    for (var i = 0u; i < 3u; i++) {
        var x = q;
        if i > 0u {
            x = c + (q - c) * scale;
        }
        let m = normalize3(x);
        let worst = min(min(min(face_quality(m, t, a), face_quality(m, b, t)), face_quality(m, a, d)), face_quality(m, d, b));
        if worst >= p.min_quality {
            return x;
        }
        scale *= p.half;
    }
    return c;
}

fn split_position(s: Site, seed: u32, kind: u32) -> vec3<f64> {
    if kind == KIND_SEA {
        return edge_centre(s);
    }
    if kind == KIND_RIVER {
        return well_shaped(s, river_position(s, seed));
    }
    return well_shaped(s, weighted_position(s, seed));
}

fn new_vertex(at: vec3<f64>, seed: u32, ground: f64, water: f64, flags: u32, tangent: u32) -> Vertex {
    let q = lift(at, ground);
    return Vertex(array<f64, 3>(q.x, q.y, q.z), ground, water, NONE, 0u, seed, tangent | (flags << 24u));
}

// `guided_sea_floor`: the sea floor under an elevation map reading `metres` at `dir`: the
// map's where it resolves the split edge; on a shore (`straddles`) the map's plus the
// landform's offset; below its pixel the landform's detail at `sea_detail` of the land's.
fn guided_sea_floor(s: Site, seed: u32, dir: vec3<f64>, len: f64, metres: f64) -> f64 {
    let sea = p.sea_level;
    let corners = array<f64, 4>(vertices[s.a].ground, vertices[s.t].ground, vertices[s.b].ground, vertices[s.d].ground);
    if len >= p.guide_min_edge {
        return sea + metres;
    }
    let parts = landform_parts(corners, len, seed, guide_twist(dir), p.guide_min_edge);
    if straddles(s) {
        return (sea + metres) + shore_offset(p.sea_detail * parts.offset, metres);
    }
    // The corners' directions only where the bend is made (`Guide::bends`).
    var bend = 0.0lf;
    if len * 16.0lf >= p.guide_min_edge {
        bend = guide_bend(dir, normalize3(pos(s.a)), normalize3(pos(s.t)), normalize3(pos(s.b)), normalize3(pos(s.d)), len);
    }
    return (parts.mean + p.sea_detail * (parts.ridge + parts.offset)) + bend;
}

// `wet_vertex`: sea floor, shore, or river interpolated.
fn wet_vertex(s: Site, seed: u32, at: vec3<f64>, kind: u32) -> Vertex {
    let va = vertices[s.a];
    let vb = vertices[s.b];
    let xi = unit(seed, SALT_ALTITUDE);
    let sea = p.sea_level;
    let mid_ground = (va.ground + vb.ground) * p.half;
    let len = distance3(pos(s.a), pos(s.b));
    if kind == KIND_SEA || kind == KIND_COAST {
        // As on the CPU: under an elevation map, the sea floor's rule for sea and shore
        // splits, on the side of sea level the map has at the new vertex (the coast follows
        // the map's zero contour); the map's sea floor where it resolves the split edge, below
        // its pixel the landform's detail at `sea_detail` of the land's (`guided_sea_floor`).
        let dir = normalize3(at);
        var mapped = Guided(false, 0.0lf);
        if p.guide_faces > 0u {
            mapped = guide_at(dir);
        }
        if mapped.found {
            var g = guided_sea_floor(s, seed, dir, len, mapped.metres);
            if mapped.metres < 0.0lf {
                g = min(g, sea - p.one);
            } else {
                g = max(g, sea + p.one);
            }
            return new_vertex(at, seed, g, sea, FLAG_REFINED, 0u);
        }
        if kind == KIND_SEA {
            // Off the map, the paper's rule.
            let g = mid_ground + (xi - p.half) * sea_roughness(len);
            return new_vertex(at, seed, min(g, sea - p.one), sea, FLAG_REFINED, 0u);
        }
        let rough = min(p.riverbed_edge_height, land_roughness(len));
        let g = clamp(mid_ground + (xi - p.half) * rough, sea - p.max_river_depth, sea + p.riverbed_edge_height);
        return new_vertex(at, seed, g, sea, FLAG_REFINED, 0u);
    }
    let w = (va.water + vb.water) * p.half;
    var up = va;
    var down = vb;
    if !(va.water >= vb.water) {
        up = vb;
        down = va;
    }
    // Between two vertices under a lake, the river runs under it too (`wet_vertex`).
    let lake = vertex_flags(va) & vertex_flags(vb) & FLAG_LAKE;
    var v = new_vertex(at, seed, min(mid_ground, w), w, FLAG_RIVER | FLAG_REFINED | lake, 0u);
    v.bits |= tangent_code(tangent_along(triple(v.pos), triple(down.pos) - triple(up.pos)));
    return v;
}

// `straddles`: the diamond's corners on both sides of sea level.
fn straddles(s: Site) -> bool {
    let g = array<f64, 4>(vertices[s.a].ground, vertices[s.t].ground, vertices[s.b].ground, vertices[s.d].ground);
    var above = false;
    var below = false;
    for (var i = 0u; i < 4u; i++) {
        above = above || g[i] > p.sea_level;
        below = below || g[i] <= p.sea_level;
    }
    return above && below;
}

// `shore_offset`: the landform's offset at a shore split, within half the map's height.
fn shore_offset(offset: f64, m: f64) -> f64 {
    let reach = 0.5lf * abs(m);
    return clamp(offset, -reach, reach);
}

// `at_sea`: in the sea or on its shore, at its level, and no river's or lake's.
fn at_sea(v: Vertex) -> bool {
    return (vertex_flags(v) & (FLAG_RIVER | FLAG_LAKE)) == 0u && v.water == p.sea_level && v.ground <= p.sea_level;
}

fn is_wet(v: Vertex) -> bool {
    return (vertex_flags(v) & FLAG_RIVER) != 0u || v.water > v.ground;
}

// Eq. 11.
fn riverbank_floor(v: Vertex, le: f64) -> f64 {
    return min(v.ground + le * p.riverbed_slope, v.water + p.riverbed_edge_height + le * p.near_river_slope);
}

// `bank_gives_way`: a river's bank (not a lake's or the sea's) gives way where the elevation
// map at the new vertex shows the ground below eq. 11's floor.
fn bank_gives_way(v: Vertex, le: f64, at_map: Guided) -> bool {
    return (vertex_flags(v) & FLAG_RIVER) != 0u && (vertex_flags(v) & FLAG_LAKE) == 0u && at_map.found
        && p.sea_level + at_map.metres < riverbank_floor(v, le);
}

// `least_steep`: the altitude whose steepest slope to the neighbours is least.
fn least_steep(g: array<f64, 4>, l: array<f64, 4>) -> f64 {
    var best_k = -F64_MAX;
    var best = g[0];
    for (var i = 0u; i < 4u; i++) {
        for (var j = 0u; j < 4u; j++) {
            if g[i] > g[j] {
                let k = (g[i] - g[j]) / max(l[i] + l[j], F64_MIN_POSITIVE);
                if k > best_k {
                    best_k = k;
                    best = g[i] - k * l[i];
                }
            }
        }
    }
    return best;
}

// `landform_ground` (`src/mesh/split/landform.rs`).
fn landform_ground(g: array<f64, 4>, edge_len: f64, seed: u32, map_relief: f64, map_pixel: f64) -> f64 {
    let parts = landform_parts(g, edge_len, seed, map_relief, map_pixel);
    return (parts.mean + parts.ridge) + parts.offset;
}

struct LandformParts {
    mean: f64,
    ridge: f64,
    offset: f64,
}

// `landform_range` and `landform_parts` (`src/mesh/split/landform.rs`): the diamond's mean,
// its ridge term and the landform's random offset; `g` is the ground at `[a, t, b, d]`.
fn landform_parts(g: array<f64, 4>, edge_len: f64, seed: u32, map_relief: f64, map_pixel: f64) -> LandformParts {
    let a = g[0];
    let t = g[1];
    let b = g[2];
    let d = g[3];
    let mean = ((a + b) * p.half + (t + d) * p.half) * p.half;
    let lo = min(min(a, t), min(b, d));
    let hi = max(max(a, t), max(b, d));
    let slope = (hi - lo) / edge_len;
    var height = p.half;
    if hi > lo {
        height = (mean - lo) / (hi - lo);
    }
    var floor = p.floor_slope * edge_len / (p.one + edge_len / p.floor_length) / (p.one + edge_len / p.floor_fade);
    let up = max(mean - p.sea_level, 0.0lf);
    let high = up / p.altitude_length;
    let relief = edge_len * (p.relief * slope + p.altitude_gain * up * (p.one + high * high)) * (p.hybrid + height);
    let threshold = max(p.one - slope / (p.threshold * p.ground_slope), 0.0lf);
    var mapped = 0.0lf;
    if map_pixel > 0.0lf {
        mapped = p.map_relief * map_relief * sqrt(edge_len / map_pixel);
        // As on the CPU: the floor no larger than twice what the map's roughness gives.
        floor = min(floor, mapped + mapped);
    }
    let fade = edge_len / (edge_len + p.smooth_length);
    let range = (floor + relief + mapped) * threshold / (p.one + edge_len / p.relief_length) * fade;
    let ridge = (a + b) * p.half - (t + d) * p.half;
    let n = unit(seed, SALT_ALTITUDE) + unit(seed, SALT_DETAIL) - p.one;
    return LandformParts(mean, p.ridge * threshold * ridge, range * p.half * n);
}

// `continent_vertex`: midpoint displacement within eq. 11-12 (the landform's detail), or a new
// river arm (eq. 10).
fn continent_vertex(s: Site, seed: u32, at: vec3<f64>, kinds_in: array<u32, 4>) -> Made {
    var kinds = kinds_in;
    let ends = array<u32, 4>(s.a, s.t, s.b, s.d);
    var around: array<Vertex, 4>;
    var lens: array<f64, 4>;
    var grounds: array<f64, 4>;
    var dirs: array<vec3<f64>, 4>;
    let at_unit = normalize3(at);
    for (var i = 0u; i < 4u; i++) {
        around[i] = vertices[ends[i]];
        dirs[i] = normalize3(triple(around[i].pos));
        lens[i] = distance3(at_unit, dirs[i]) * p.radius;
        grounds[i] = around[i].ground;
    }
    // As on the CPU: under an elevation map, a river's bank gives way where the map shows the
    // ground below it.
    var at_map = Guided(false, 0.0lf);
    if p.guide_faces > 0u {
        at_map = guide_at(at_unit);
    }
    // As on the CPU: under a map, the sea is no riverbank, and a split the map puts under
    // the sea beside the sea floods.
    let sea = p.sea_level;
    var by_sea = false;
    if at_map.found {
        for (var i = 0u; i < 4u; i++) {
            by_sea = by_sea || at_sea(around[i]);
        }
    }
    let floods = by_sea && at_map.metres < 0.0lf;
    // `covers`: wet neighbours whose water covers the vertex below it (the sea too); `holds`:
    // those whose banks bound it (not the sea's, under a map).
    var covers: array<bool, 4>;
    var holds: array<bool, 4>;
    for (var i = 0u; i < 4u; i++) {
        covers[i] = is_wet(around[i]) && !bank_gives_way(around[i], lens[i], at_map);
        holds[i] = covers[i] && !(by_sea && at_sea(around[i]));
    }
    var bank_lo = sea + p.one;
    var slope_lo = -F64_MAX;
    var any_lo = -F64_MAX;
    var hi = F64_MAX;
    for (var i = 0u; i < 4u; i++) {
        let v = around[i];
        let le = lens[i];
        let below = v.ground - le * p.ground_slope;
        if holds[i] {
            bank_lo = max(bank_lo, riverbank_floor(v, le));
        } else {
            slope_lo = max(slope_lo, below);
        }
        any_lo = max(any_lo, below);
        hi = min(hi, v.ground + le * p.ground_slope);
    }
    // A lake's bed (`continent_vertex`): between two vertices under a lake, under it too.
    if (vertex_flags(around[0]) & FLAG_LAKE) != 0u && (vertex_flags(around[2]) & FLAG_LAKE) != 0u {
        let surface = max(around[0].water, around[2].water);
        let g = min((around[0].ground + around[2].ground) * p.half, surface);
        return Made(new_vertex(at, seed, g, surface, FLAG_LAKE | FLAG_REFINED, 0u), kinds);
    }
    let edge_len = distance3(pos(s.a), pos(s.b));

    // As on the CPU: a flooded split is a sea split, without the land's slope bounds.
    if floods {
        let g = min(guided_sea_floor(s, seed, at_unit, edge_len, at_map.metres), sea - p.one);
        return Made(new_vertex(at, seed, g, sea, FLAG_REFINED, 0u), kinds);
    }

    if edge_len >= p.min_river_length {
        var cap = F64_MAX;
        for (var i = 0u; i < 4u; i++) {
            let v = around[i];
            if !is_wet(v) {
                let le = lens[i];
                cap = min(cap, v.ground - min(le * p.riverbed_slope, p.riverbed_edge_height + le * p.near_river_slope));
            }
        }
        var best = 4u;
        var best_floor = f64(0.0);
        for (var i = 0u; i < 4u; i++) {
            if (vertex_flags(around[i]) & FLAG_RIVER) != 0u && lens[i] >= p.min_river_length {
                let lowest = around[i].water + lens[i] * p.river_slope;
                if lowest < cap && lowest < p.max_river_altitude && (best == 4u || lowest < best_floor) {
                    best = i;
                    best_floor = lowest;
                }
            }
        }
        if best < 4u {
            let top = min(cap, p.max_river_altitude);
            let g = best_floor + (top - best_floor) * unit(seed, SALT_RIVER) * p.half;
            kinds[best] = KIND_RIVER;
            var v = new_vertex(at, seed, g, g, FLAG_RIVER | FLAG_REFINED, 0u);
            v.bits |= tangent_code(tangent_towards(triple(v.pos), triple(around[best].pos)));
            return Made(v, kinds);
        }
    }

    // As on the CPU: the elevation map's ground where it resolves the split edge.
    var wanted: f64;
    if edge_len >= p.guide_min_edge && at_map.found {
        wanted = p.sea_level + at_map.metres;
    } else if at_map.found && by_sea && straddles(s) {
        // As on the CPU: on a shore, the map's ground plus the landform's offset.
        let parts = landform_parts(grounds, edge_len, seed, guide_twist(at_unit), p.guide_min_edge);
        wanted = (p.sea_level + at_map.metres) + shore_offset(parts.offset, at_map.metres);
    } else {
        var map_relief = 0.0lf;
        var map_pixel = 0.0lf;
        if p.guide_faces > 0u {
            map_relief = guide_twist(at_unit);
            map_pixel = p.guide_min_edge;
        }
        wanted = landform_ground(grounds, edge_len, seed, map_relief, map_pixel);
        if p.guide_faces > 0u {
            // As on the CPU: the map's smooth surface bends the diamond's mean (`Guide::bend`).
            wanted = wanted + guide_bend(at_unit, dirs[0], dirs[1], dirs[2], dirs[3], edge_len);
        }
    }
    let lo = max(bank_lo, slope_lo);
    var g: f64;
    if any_lo > hi {
        g = least_steep(grounds, lens);
    } else if lo <= hi {
        g = clamp(wanted, lo, min(hi, max(p.max_mountain_altitude, lo)));
    } else {
        g = hi;
    }
    var surface = F64_MIN;
    for (var i = 0u; i < 4u; i++) {
        if covers[i] {
            surface = max(surface, around[i].water);
        }
    }
    var water = g;
    if g < surface {
        water = surface;
    }
    return Made(new_vertex(at, seed, g, water, FLAG_REFINED, 0u), kinds);
}

// The kind of an edge inside a face: continent in a land face (`land` 1), else sea.
fn inner_kind(land: u32) -> u32 {
    return select(KIND_SEA, KIND_CONTINENT, land == 1u);
}

// `Lod` of a half or inner edge from `q` to `r`: inside its parent's bounds.
fn child_lod(parent: u32, q: vec3<f64>, r: vec3<f64>, parent_mid: vec3<f64>) -> u32 {
    let own = distance3(q, r);
    let offset = distance3((q + r) * p.half, parent_mid);
    let len = f64(lod_len(parent));
    let radius = f64(lod_radius(parent));
    return lod_new(min(own, len), min(own, radius - offset));
}

// In edge `e`, the face slot holding `old` now holds `new_face`.
fn relink(e: u32, old: u32, new_face: u32) {
    if edges[e].f[0] == old {
        edges[e].f[0] = new_face;
    } else {
        edges[e].f[1] = new_face;
    }
}

@compute @workgroup_size(64)
fn split_edges(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x + id.y * p.row;
    if i >= p.count {
        return;
    }
    let e1 = list[i];
    let parent = edges[e1];
    let old1 = faces[parent.f[0]];
    let old2 = faces[parent.f[1]];
    // The apexes: f1 = (t, a, b) holds (b, t) in slot 1, f2 = (d, b, a) holds (d, b) in slot 2.
    let t = far_end(old1.e[1], parent.v[1]);
    let d = far_end(old2.e[2], parent.v[1]);
    let s = Site(e1, parent.v[0], parent.v[1], t, d, parent.f[0], parent.f[1]);
    let seed = vertices[s.a].seed + vertices[s.b].seed;
    let kind = edge_kind(parent);
    let at = split_position(s, seed, kind);
    var made: Made;
    // Whether f1 (and so f3) and f2 (and f4) are land.
    let land = edge_land(parent);
    let land1 = land & 1u;
    let land2 = land >> 1u;
    let kinds = array<u32, 4>(kind, inner_kind(land1), kind, inner_kind(land2));
    if kind == KIND_CONTINENT {
        made = continent_vertex(s, seed, at, kinds);
    } else {
        made = Made(wet_vertex(s, seed, at, kind), kinds);
    }

    let m = p.vertices + i;
    let e2 = p.edges + 3u * i;
    let e3 = e2 + 1u;
    let e4 = e2 + 2u;
    let f3 = p.faces + 2u * i;
    let f4 = f3 + 1u;
    let level = edge_level(parent) + 1u;
    let pa = pos(s.a);
    let pb = pos(s.b);
    let pm = triple(made.v.pos);
    let parent_mid = (pa + pb) * p.half;
    let a = s.a;
    let b = s.b;
    let f1 = s.f1;
    let f2 = s.f2;

    // f1 = (m, t, a), f2 = (m, a, d), f3 = (m, b, t), f4 = (m, d, b).
    faces[f1] = Face(array<u32, 3>(old1.e[2], e1, e2));
    faces[f2] = Face(array<u32, 3>(old2.e[1], e4, e1));
    faces[f3] = Face(array<u32, 3>(old1.e[1], e2, e3));
    faces[f4] = Face(array<u32, 3>(old2.e[2], e3, e4));
    let k = made.kinds;
    let sides = land << 24u;
    let inner1 = (land1 * 3u) << 24u;
    let inner2 = (land2 * 3u) << 24u;
    edges[e1] = Edge(array<u32, 2>(a, m), array<u32, 2>(f1, f2), child_lod(parent.lod, pa, pm, parent_mid), level | (k[0] << 16u) | sides);
    edges[e2] = Edge(array<u32, 2>(m, t), array<u32, 2>(f1, f3), child_lod(parent.lod, pm, pos(t), parent_mid), level | (k[1] << 16u) | inner1);
    edges[e3] = Edge(array<u32, 2>(m, b), array<u32, 2>(f3, f4), child_lod(parent.lod, pm, pb, parent_mid), level | (k[2] << 16u) | sides);
    edges[e4] = Edge(array<u32, 2>(m, d), array<u32, 2>(f4, f2), child_lod(parent.lod, pm, pos(d), parent_mid), level | (k[3] << 16u) | inner2);
    var v = made.v;
    v.edge = e1;
    v.parent_lod = parent.lod;
    let flags = (1u << k[0]) | (1u << k[1]) | (1u << k[2]) | (1u << k[3]);
    v.bits |= flags << 24u;
    vertices[m] = v;
    relink(old1.e[1], f1, f3);
    relink(old2.e[2], f2, f4);
    if vertices[b].edge == e1 {
        vertices[b].edge = e3;
    }
}
