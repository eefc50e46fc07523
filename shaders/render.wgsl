// Snapshot rendering of an adapted planet (paper §3.3): climate-textured terrain, a water
// surface coloured by depth with a specular sun, atmospheric haze and a sky / space background.
//
// Positions arrive relative to the eye (computed in f64 on the CPU), so f32 keeps millimetres
// near the camera; depth is reversed-Z with an infinite far plane (`src/render/scene.rs`).
// Colours are linear; the target is sRGB.

struct Frame {
    // Eye-relative position -> clip space (reversed-Z, infinite far plane).
    view_proj: mat4x4<f32>,
    // View basis for the background: forward, right * tan(fov_x / 2), up * tan(fov_y / 2).
    forward: vec4<f32>,
    right: vec4<f32>,
    up: vec4<f32>,
    // Planet centre relative to the eye (xyz), radius of the sea surface (w), metres.
    centre: vec4<f32>,
    // Unit direction towards the sun (xyz), radius of the top of the atmosphere (w).
    sun: vec4<f32>,
    // x: lowest altitude of the climate texture, y: its altitude span, z: haze length,
    // w: depth of the darkest water, metres.
    lookup: vec4<f32>,
    // x: haze length of the sky, metres; y: precipitation at the end of the climate texture's
    // z axis (which runs over its square root), mm/yr; z, w: the cosines of the slopes at which
    // land is all bare rock and at which it starts to be.
    sky: vec4<f32>,
    // Bare rock's colour, linear (xyz).
    rock: vec4<f32>,
}

@group(0) @binding(0) var<uniform> frame: Frame;
@group(0) @binding(1) var climate: texture_3d<f32>;
@group(0) @binding(2) var water_ramp: texture_2d<f32>;
@group(0) @binding(3) var ramp_sampler: sampler;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) ground: f32,
    @location(2) normal: vec3<f32>,
    @location(3) water: f32,
    @location(4) up: vec3<f32>,
    @location(5) latitude: f32,
    @location(6) precip: f32,
}

struct Surface {
    @builtin(position) clip: vec4<f32>,
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) up: vec3<f32>,
    // x: ground altitude, y: water depth, z: latitude in degrees, w: precipitation (mm/yr).
    @location(3) data: vec4<f32>,
}

const SPACE: vec3<f32> = vec3<f32>(0.0, 0.0, 0.004);
const SKY: vec3<f32> = vec3<f32>(0.32, 0.55, 0.95);
const AMBIENT: f32 = 0.06;

// Length of the part of the ray `t * dir` (t in [0, t_max]) inside the atmosphere.
fn atmosphere_path(dir: vec3<f32>, t_max: f32) -> f32 {
    let c = frame.centre.xyz;
    let ra = frame.sun.w;
    let b = dot(dir, c);
    let h = dot(c, c) - b * b;
    let disc = ra * ra - h;
    if disc <= 0.0 {
        return 0.0;
    }
    let s = sqrt(disc);
    let t0 = max(b - s, 0.0);
    let t1 = min(b + s, t_max);
    return max(t1 - t0, 0.0);
}

// Daylight at a point whose local up is `up`: soft terminator.
fn daylight(up: vec3<f32>) -> f32 {
    return smoothstep(-0.15, 0.25, dot(up, frame.sun.xyz));
}

fn haze(colour: vec3<f32>, position: vec3<f32>, up: vec3<f32>) -> vec3<f32> {
    let dist = length(position);
    let path = atmosphere_path(position / max(dist, 1e-6), dist);
    let amount = 1.0 - exp(-path / frame.lookup.z);
    return mix(colour, SKY * daylight(up), amount);
}

fn lit(albedo: vec3<f32>, normal: vec3<f32>, up: vec3<f32>) -> vec3<f32> {
    let diffuse = max(dot(normal, frame.sun.xyz), 0.0) * smoothstep(-0.1, 0.1, dot(up, frame.sun.xyz));
    return albedo * (AMBIENT + (1.0 - AMBIENT) * diffuse);
}

@vertex
fn terrain_vertex(v: VertexIn) -> Surface {
    var out: Surface;
    out.clip = frame.view_proj * vec4<f32>(v.position, 1.0);
    out.position = v.position;
    out.normal = v.normal;
    out.up = v.up;
    out.data = vec4<f32>(v.ground, v.water - v.ground, v.latitude, v.precip);
    return out;
}

@fragment
fn terrain_fragment(s: Surface) -> @location(0) vec4<f32> {
    let u = clamp((s.data.x - frame.lookup.x) / frame.lookup.y, 0.0, 1.0);
    let v = clamp((90.0 - abs(s.data.z)) / 90.0, 0.0, 1.0);
    let w = sqrt(clamp(s.data.w / frame.sky.y, 0.0, 1.0));
    let climate_albedo = textureSampleLevel(climate, ramp_sampler, vec3<f32>(u, v, w), 0.0).rgb;
    let n = normalize(s.normal);
    let up = normalize(s.up);
    // Steep land is bare rock (`climate::on_slope`); the sea floor keeps its colour.
    let bare = select(0.0, 1.0 - smoothstep(frame.sky.z, frame.sky.w, dot(n, up)), s.data.x > 0.0);
    let albedo = mix(climate_albedo, frame.rock.xyz, bare);
    let colour = lit(albedo, n, up);
    return vec4<f32>(haze(colour, s.position, up), 1.0);
}

// The water surface: flat at the level of the water body, the same vertices moved along their
// local up from the ground to that level (down, under the ground, at dry banks). The signed
// depth interpolates to zero where the surface meets the ground.
@vertex
fn water_vertex(v: VertexIn) -> Surface {
    var out: Surface;
    let lift = v.water - v.ground;
    let p = v.position + v.up * lift;
    out.clip = frame.view_proj * vec4<f32>(p, 1.0);
    out.position = p;
    out.normal = v.up;
    out.up = v.up;
    out.data = vec4<f32>(v.ground, lift, v.latitude, v.precip);
    return out;
}

@fragment
fn water_fragment(s: Surface) -> @location(0) vec4<f32> {
    let depth = s.data.y;
    if depth <= 0.01 {
        discard;
    }
    let ramp = sqrt(clamp(depth / frame.lookup.w, 0.0, 1.0));
    let albedo = textureSampleLevel(water_ramp, ramp_sampler, vec2<f32>(ramp, 0.5), 0.0).rgb;
    let n = normalize(s.normal);
    let up = normalize(s.up);
    let to_eye = -normalize(s.position);
    let half_way = normalize(to_eye + frame.sun.xyz);
    let sun_up = smoothstep(-0.05, 0.1, dot(up, frame.sun.xyz));
    let specular = pow(max(dot(n, half_way), 0.0), 180.0) * 0.8 * sun_up;
    let colour = lit(albedo, n, up) + vec3<f32>(specular);
    // Shallow water shows the bed; a few metres down it is opaque.
    let alpha = mix(0.55, 0.97, clamp(depth / 20.0, 0.0, 1.0));
    return vec4<f32>(haze(colour, s.position, up), alpha);
}

// Rivers narrower than a pixel: one-pixel lines along their water surface whose opacity is
// the share of the pixel the channel covers (`river_lines` in `src/render/scene.rs`), coloured
// as water of the channel's depth.
struct LineIn {
    @location(0) position: vec3<f32>,
    @location(1) coverage: f32,
    @location(2) up: vec3<f32>,
    @location(3) depth: f32,
}

struct Line {
    @builtin(position) clip: vec4<f32>,
    @location(0) position: vec3<f32>,
    @location(1) up: vec3<f32>,
    // x: coverage, y: channel depth.
    @location(2) data: vec2<f32>,
}

@vertex
fn river_vertex(v: LineIn) -> Line {
    var out: Line;
    out.clip = frame.view_proj * vec4<f32>(v.position, 1.0);
    out.position = v.position;
    out.up = v.up;
    out.data = vec2<f32>(v.coverage, v.depth);
    return out;
}

@fragment
fn river_fragment(l: Line) -> @location(0) vec4<f32> {
    let ramp = sqrt(clamp(l.data.y / frame.lookup.w, 0.0, 1.0));
    let albedo = textureSampleLevel(water_ramp, ramp_sampler, vec2<f32>(ramp, 0.5), 0.0).rgb;
    let up = normalize(l.up);
    return vec4<f32>(haze(lit(albedo, up, up), l.position, up), clamp(l.data.x, 0.0, 1.0));
}

struct Background {
    @builtin(position) clip: vec4<f32>,
    @location(0) ndc: vec2<f32>,
}

// One triangle covering the screen, behind everything (depth 0 with reversed-Z).
@vertex
fn sky_vertex(@builtin(vertex_index) i: u32) -> Background {
    let xy = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u)) * 2.0 - 1.0;
    var out: Background;
    out.clip = vec4<f32>(xy, 0.0, 1.0);
    out.ndc = xy;
    return out;
}

fn star(dir: vec3<f32>) -> f32 {
    let cell = vec3<i32>(floor(dir * 700.0));
    var h = u32(cell.x * 73856093) ^ u32(cell.y * 19349663) ^ u32(cell.z * 83492791);
    h = (h ^ (h >> 16u)) * 0x45d9f3bu;
    h = (h ^ (h >> 16u)) * 0x45d9f3bu;
    h = h ^ (h >> 16u);
    let r = f32(h & 0xffffu) / 65535.0;
    return select(0.0, (r - 0.9985) / 0.0015, r > 0.9985);
}

@fragment
fn sky_fragment(b: Background) -> @location(0) vec4<f32> {
    let dir = normalize(frame.forward.xyz + b.ndc.x * frame.right.xyz + b.ndc.y * frame.up.xyz);
    // The ray ends where it meets the sea sphere (terrain covers it there anyway).
    let c = frame.centre.xyz;
    let bb = dot(dir, c);
    let disc = frame.centre.w * frame.centre.w - (dot(c, c) - bb * bb);
    var t_max = 1e30;
    if disc > 0.0 && bb - sqrt(disc) > 0.0 {
        t_max = bb - sqrt(disc);
    }
    let path = atmosphere_path(dir, t_max);
    let amount = 1.0 - exp(-path / frame.sky.x);
    // Light of the sky at the point of the ray closest to the planet.
    let closest = normalize(dir * max(bb, 0.0) - c);
    let sky = SKY * daylight(closest);
    let stars = vec3<f32>(star(dir)) * (1.0 - amount);
    return vec4<f32>(mix(SPACE + stars, sky, amount), 1.0);
}
