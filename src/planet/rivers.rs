//! Initial river networks (paper §4.2): mouths, network growth, river altitudes (eq. 3–4),
//! sea floor, and the mountain vertices that separate rivers (eq. 5).
//!
//! Growth is a best-first search from the coast. With a random planet the priorities are
//! pseudo-random, as in the paper; with an elevation map they are the map's altitudes, so the
//! network floods upwards from the coast and rivers settle in the map's valleys.

use crate::maps::Map;
use crate::mesh::split::altitude::{bank_gives_way, riverbank_floor};
use crate::mesh::split::position::{altitude_random, lift, split_position, split_seed, tangent_towards};
use crate::mesh::{split_kinds, Diamond, EdgeKind, Mesh, SplitSite, Tangent, Vertex, VertexFlags, NONE};
use crate::params::Params;
use crate::rng::{salt, unit, Sequence};
use std::cmp::Ordering;
use std::collections::BinaryHeap;

use crate::geo::lat_lon;

/// Radius of the window (in pixels of the sampled map) whose lowest ground routes a vertex.
const ROUTE_RADIUS_PX: u32 = 1;

/// Upstream length over which a river's lift in a mountain belt halves about 1.4 times (m).
const GORGE_LENGTH_M: f64 = 600_000.0;

/// Sea-floor slope away from the coast for planets without a relief map (m per m).
const SHELF_SLOPE: f64 = 0.01;

/// What the river phase produced.
#[derive(Clone, Debug, Default)]
pub struct RiverReport {
    pub mouths: usize,
    pub mountains: usize,
    /// Inland vertices that could only join the network through a third tributary.
    pub forced_merges: usize,
    /// Relief maps: depressions kept as lakes and depressions breached (see [`super::relief`]).
    pub lakes: usize,
    pub breached: usize,
    /// Relief maps: river vertices drained to a lower neighbour instead of the one the flood
    /// reached them from, which stood higher on the map (`super::downhill`).
    pub downhill: super::downhill::Drained,
    /// Relief maps: depressions with no outlet to the sea (see [`super::basins`]).
    pub endorheic: usize,
    /// Relief maps: lake per vertex (`NONE` off lakes) and each lake's level and outlet.
    pub lake_of: Vec<u32>,
    pub lake_levels: Vec<super::relief::LakeLevel>,
}

/// Water each vertex yields as runoff from land (m³/yr), loses as open water, evaporation
/// less precipitation (m³/yr), and a river's floodplain loses there (mm/yr,
/// [`super::climate::channel_loss_mm`]), in the planet's climate ([`super::climate`]); `height`
/// is its altitude (m relative to sea level); `rain` a precipitation map on the climate's grid
/// ([`super::climate::precipitation_grid`]) in place of the model's.
fn water_balance(
    mesh: &Mesh,
    (inland, coast): (&[bool], &[bool]),
    height: &[f64],
    area: &[f64],
    rain: Option<&[f32]>,
) -> [Vec<f64>; 3] {
    use super::climate::{channel_loss_mm, runoff_mm, Climate};
    let is_land = |v: usize| inland[v] || coast[v];
    let climate = Climate::of_mesh(mesh, is_land, |v| height[v]).with_precipitation(rain);
    let mut runoff = vec![0.0f64; area.len()];
    let mut loss = vec![0.0f64; area.len()];
    let mut channel = vec![0.0f64; area.len()];
    for (v, (p, e0)) in climate.at_vertices(mesh, |v| height[v]).into_iter().enumerate() {
        if is_land(v) {
            runoff[v] = runoff_mm(p, e0) * 1e-3 * area[v];
        }
        loss[v] = (e0 - p) * 1e-3 * area[v];
        channel[v] = channel_loss_mm(p, e0);
    }
    [runoff, loss, channel]
}

/// The area each vertex stands for: a third of each face around it.
fn vertex_areas(mesh: &Mesh) -> Vec<f64> {
    let mut area = vec![0.0f64; mesh.vertices.len()];
    for f in 0..mesh.faces.len() as u32 {
        let a = mesh.face_area_vector(f).length() / 3.0;
        for v in mesh.corners(f) {
            area[v as usize] += a;
        }
    }
    area
}

struct Candidate {
    key: f64,
    key2: f64,
    tie: u64,
    from: u32,
    to: u32,
    edge: u32,
}

impl PartialEq for Candidate {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Candidate {}
impl PartialOrd for Candidate {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Candidate {
    /// Reversed, so the max-heap pops the lowest key first.
    fn cmp(&self, other: &Self) -> Ordering {
        other.key.total_cmp(&self.key).then(other.key2.total_cmp(&self.key2)).then(other.tie.cmp(&self.tie))
    }
}

/// Map altitude (m above sea level) at a vertex, if the relief map covers it.
fn relief_at(relief: Option<&Map>, mesh: &Mesh, v: u32) -> Option<f64> {
    let (lat, lon) = lat_lon(mesh.pos(v));
    relief.and_then(|m| m.sample(lat, lon)).map(f64::from).filter(|x| x.is_finite())
}

/// Builds the river networks and assigns every altitude of the base mesh; `rain`, a
/// precipitation map on the climate's grid, replaces the model's where it covers the planet.
pub fn build_rivers(
    mesh: &mut Mesh,
    params: &Params,
    relief: Option<&Map>,
    rain: Option<&[f32]>,
    seed: u64,
) -> RiverReport {
    let adj = mesh.adjacency();
    let n = mesh.vertices.len();
    let inland: Vec<bool> = mesh.vertices.iter().map(|v| v.flags.is_inland()).collect();
    let coast: Vec<bool> = mesh.vertices.iter().map(|v| v.flags.contains(VertexFlags::COAST)).collect();
    let elevation: Vec<Option<f64>> = (0..n as u32).map(|v| relief_at(relief, mesh, v)).collect();
    let mut rng = Sequence::new(seed, 0x7177e5);
    let mut report = RiverReport::default();

    // --- Network growth ---
    let mut downstream = vec![NONE; n];
    let mut down_edge = vec![NONE; n];
    let mut joined = vec![false; n];
    let mut tributaries = vec![0u8; n];
    let mut order: Vec<u32> = Vec::new();
    // Water finds its way through the lowest ground around a vertex (the map's pixels within
    // one of the sampled map's pixels, about the vertices' spacing): a gorge narrower than the
    // mesh still carries its river (the Congo through the Crystal Mountains, not out through
    // Gabon; the Nile to the Mediterranean, not the Red Sea).
    let route: Vec<Option<f64>> = match relief {
        Some(map) => (0..n as u32)
            .map(|v| {
                let (lat, lon) = lat_lon(mesh.pos(v));
                map.sample_min(lat, lon, ROUTE_RADIUS_PX).map(f64::from)
            })
            .collect(),
        None => Vec::new(),
    };
    let key_of = |rng: &mut Sequence, from: u32, to: u32| match relief {
        Some(_) => (route[to as usize].unwrap_or(0.0), route[from as usize].unwrap_or(-1e9)),
        None => (rng.unit(), 0.0),
    };
    let mut heap = BinaryHeap::new();
    for c in (0..n as u32).filter(|&c| coast[c as usize]) {
        for (v, e) in adj.around(c) {
            if inland[v as usize] {
                let (key, key2) = key_of(&mut rng, c, v);
                heap.push(Candidate { key, key2, tie: rng.next_u64(), from: c, to: v, edge: e });
            }
        }
    }
    let has_room = |u: usize, tributaries: &[u8]| if coast[u] { tributaries[u] == 0 } else { tributaries[u] < 2 };
    while let Some(c) = heap.pop() {
        let v = c.to as usize;
        if joined[v] {
            continue;
        }
        let (mut u, mut e) = (c.from, c.edge);
        if !has_room(u as usize, &tributaries) {
            // Prefer another neighbour already in the network that still takes a tributary.
            let alt = adj
                .around(c.to)
                .filter(|&(w, _)| (joined[w as usize] || coast[w as usize]) && has_room(w as usize, &tributaries))
                .min_by(|x, y| {
                    let kx = elevation[x.0 as usize].unwrap_or(0.0);
                    let ky = elevation[y.0 as usize].unwrap_or(0.0);
                    kx.total_cmp(&ky).then(x.0.cmp(&y.0))
                });
            match alt {
                Some((w, we)) => (u, e) = (w, we),
                None => continue,
            }
        }
        join(v as u32, u, e, &mut downstream, &mut down_edge, &mut joined, &mut tributaries, &mut order);
        for (w, we) in adj.around(v as u32) {
            if inland[w as usize] && !joined[w as usize] {
                let (key, key2) = key_of(&mut rng, v as u32, w);
                heap.push(Candidate { key, key2, tie: rng.next_u64(), from: v as u32, to: w, edge: we });
            }
        }
    }
    // Vertices every route of which was full: join them anyway (unavoidable merges).
    loop {
        let mut changed = false;
        for v in 0..n as u32 {
            if !inland[v as usize] || joined[v as usize] {
                continue;
            }
            let best = adj
                .around(v)
                .filter(|&(w, _)| joined[w as usize] || coast[w as usize])
                .min_by_key(|&(w, _)| (tributaries[w as usize], w));
            if let Some((w, we)) = best {
                join(v, w, we, &mut downstream, &mut down_edge, &mut joined, &mut tributaries, &mut order);
                report.forced_merges += 1;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }

    // --- On a relief map: no river edge uphill where a lower way out exists ---
    if relief.is_some() {
        let h = |v: u32| if coast[v as usize] { 0.0 } else { elevation[v as usize].unwrap_or(0.0) };
        let tree = super::downhill::Tree {
            downstream: &mut downstream,
            down_edge: &mut down_edge,
            tributaries: &mut tributaries,
            order: &mut order,
        };
        report.downhill = super::downhill::drain_downhill(&adj, &coast, &h, tree);
    }
    // --- Levels on a relief map: depressions breached, kept as lakes or closed ---
    let p = params;
    let mut sinks: Vec<u32> = Vec::new();
    let relief_levels = relief.map(|map| {
        let route: Vec<f64> = (0..n).map(|v| if coast[v] { 0.0 } else { route[v].unwrap_or(0.0) }).collect();
        // A river vertex's water stands at the map (its valley, lakes filled, barriers breached
        // below): the mountain vertices between rivers follow the map too, as eq. 11's banks
        // give way to it (`base_split_vertex`).
        let height: Vec<f64> = (0..n).map(|v| if coast[v] { 0.0 } else { elevation[v].unwrap_or(0.0) }).collect();
        let area = vertex_areas(mesh);
        let (_, dlat) = map.pixel_size_deg();
        let pixel = dlat.to_radians() * mesh.radius;
        let edge_of = |down_edge: &[u32]| -> Vec<f64> {
            (0..n).map(|v| if down_edge[v] == NONE { 0.0 } else { mesh.edge_length(down_edge[v]) }).collect()
        };
        let lens = edge_of(&down_edge);
        // The terrain; the tree (order, links, lengths) changes when closed basins drain to their pits.
        let terrain = super::relief::Flood {
            order: &[],
            downstream: &[],
            edge_len: &[],
            route: &route,
            height: &height,
            area: &area,
            min_lake_area_m2: 2.0 * pixel * pixel,
            river_slope: p.river_slope(),
        };
        let flood = super::relief::Flood { order: &order, downstream: &downstream, edge_len: &lens, ..terrain };
        let mut dep = super::relief::depressions(&flood);
        let [runoff, net_loss, channel_loss] = water_balance(mesh, (&inland, &coast), &height, &area, rain);
        let terminal = super::basins::terminal_levels(&flood, &mut dep, &runoff, &net_loss, &channel_loss);
        let (outlets, new_order) =
            super::basins::drain_to_pits(&mut downstream, &mut down_edge, &order, &dep, &terminal);
        for o in outlets {
            tributaries[o as usize] = tributaries[o as usize].saturating_sub(1);
        }
        order = new_order;
        sinks = (0..dep.spill.len()).filter(|&c| terminal[c].is_some()).map(|c| dep.pit[c]).collect();
        let lens = edge_of(&down_edge);
        let flood = super::relief::Flood { order: &order, downstream: &downstream, edge_len: &lens, ..terrain };
        super::relief::levels(&flood, &dep, &terminal)
    });
    if let Some(l) = &relief_levels {
        report.lakes = l.lakes.len();
        report.breached = l.breached;
        report.endorheic = l.endorheic;
        report.lake_of = l.lake.clone();
        report.lake_levels = l.lakes.clone();
    }

    // --- Lengths along the network ---
    let edge_len: Vec<f64> = (0..mesh.edges.len() as u32).map(|e| mesh.edge_length(e)).collect();
    let len = |e: u32| edge_len[e as usize];
    let mut l_down = vec![0.0f64; n];
    for &v in &order {
        l_down[v as usize] = l_down[downstream[v as usize] as usize] + len(down_edge[v as usize]);
    }
    let mut l_up = vec![0.0f64; n];
    for &v in order.iter().rev() {
        let u = downstream[v as usize] as usize;
        l_up[u] = l_up[u].max(l_up[v as usize] + len(down_edge[v as usize]));
    }

    // --- Altitudes (eq. 3–4) ---
    let sea = p.sea_level_m;
    let mouth_ground = p.mouth_ground();
    let mut gradient = vec![0.0f64; n]; // e_a per river vertex, reused by eq. 5
    for c in (0..n).filter(|&c| coast[c]) {
        let vert = &mut mesh.vertices[c];
        vert.water = sea;
        if tributaries[c] > 0 {
            vert.ground = mouth_ground;
            vert.flags.insert(VertexFlags::MOUTH | VertexFlags::RIVER);
            report.mouths += 1;
            gradient[c] = (p.max_river_altitude_m - mouth_ground) / (l_up[c]).max(p.min_river_length_m);
        } else {
            vert.ground = sea + p.riverbed_edge_height_m * altitude_random(vert.seed);
        }
    }
    // A closed basin's pit: its terminal lake's floor, or a dry pan, where its rivers end.
    if let Some(l) = &relief_levels {
        for &s in &sinks {
            let si = s as usize;
            let vert = &mut mesh.vertices[si];
            vert.water = sea + l.water[si];
            vert.ground = sea + elevation[si].unwrap_or(0.0).min(l.water[si] - p.riverbed_edge_height_m);
            vert.flags.insert(VertexFlags::LAKE | VertexFlags::RIVER);
            gradient[si] = (p.max_river_altitude_m - vert.ground) / l_up[si].max(p.min_river_length_m);
        }
    }
    for &v in &order {
        let (vi, u) = (v as usize, downstream[v as usize] as usize);
        let le = len(down_edge[vi]);
        let river_length = (l_down[vi] + l_up[vi]).max(1.0);
        let depth = p.max_river_depth_m * l_up[vi] / river_length;
        let (au, wu) = (mesh.vertices[u].ground, mesh.vertices[u].water);
        // s_r, unless the river is so long that s_r alone would lift its spring above
        // a_max_river: then the slope shrinks to fit (documented deviation).
        let river_slope = p.river_slope().min(0.5 * (p.max_river_altitude_m - mouth_ground) / river_length);
        let min_water = wu + river_slope * le;
        let xi = unit(mesh.vertices[vi].seed, salt::RIVER);
        gradient[vi] = (p.max_river_altitude_m - mouth_ground) / river_length;
        let water = match &relief_levels {
            Some(l) => sea + l.water[vi],
            None => {
                // Eq. 3 with xi in [0, 1): the rise per metre is at most e_a, so a spring stays
                // below a_max_river; it is at least what keeps the water surface falling by s_r
                // while the riverbed deepens towards the mouth (eq. 4).
                let least = river_slope + p.max_river_depth_m / river_length;
                let rise = least + (gradient[vi] - least).max(0.0) * xi;
                (au + rise * le + depth).max(min_water)
            }
        };
        let ground = match &relief_levels {
            // A lake's floor is the map's; a river's bed lies its depth below the water.
            Some(l) if l.lake[vi] != NONE => {
                sea + elevation[vi].unwrap_or(0.0).min(l.water[vi] - depth.max(p.riverbed_edge_height_m))
            }
            _ => water - depth,
        };
        let vert = &mut mesh.vertices[vi];
        vert.water = water;
        vert.ground = ground;
        vert.flags.insert(VertexFlags::RIVER);
        if relief_levels.as_ref().is_some_and(|l| l.lake[vi] != NONE) {
            vert.flags.insert(VertexFlags::LAKE);
        }
        let ek = &mut mesh.edges[down_edge[vi] as usize];
        ek.kind = EdgeKind::River;
    }
    for &v in &order {
        let u = downstream[v as usize];
        mesh.vertices[v as usize].flags.insert(VertexFlags::RIVER);
        mesh.vertices[u as usize].flags.insert(VertexFlags::RIVER);
    }

    // --- Mountain belts (planets without a relief map): rivers lifted downstream first ---
    if relief.is_none() && p.mountain_belt_uplift_m > 0.0 {
        let mut lift = vec![0.0f64; n];
        for &v in &order {
            let (vi, u) = (v as usize, downstream[v as usize] as usize);
            // A great river cuts a gorge through the range instead of rising over it; the lift
            // never falls upstream, so every river still falls to the sea.
            let gorge = (-l_up[vi] / GORGE_LENGTH_M).exp();
            let want = p.mountain_belt_uplift_m * super::belts::belt(seed, mesh.pos(v)) * gorge;
            lift[vi] = want.max(lift[u]);
            let vert = &mut mesh.vertices[vi];
            vert.water += lift[vi];
            vert.ground += lift[vi];
        }
    }

    // --- Sea floor: deeper away from the coast, or the relief map's bathymetry ---
    sea_floor(mesh, &adj, params, &elevation);

    // --- Mountain vertices between rivers (eq. 5) ---
    if !report.lake_of.is_empty() {
        report.lake_of.resize(n, NONE);
    }
    // The mountain vertices read the map's pixels as means over their areas (as the guide does
    // for the splits below the base mesh): a bilinear reading of the pixels flattens the
    // ridges and valleys two to four pixels across, about the base mesh's spacing. Whether one
    // lies under a lake, the pixels say as they are (sharpened, the shallows beside a lake's
    // shore overshoot its surface: a third of the Caspian's middle came out dry).
    let means = relief.map(Map::mean_preserving);
    report.mountains =
        insert_mountains(mesh, params, relief.zip(means.as_ref()), seed, &mut gradient, &mut report.lake_of);
    report
}

#[allow(clippy::too_many_arguments)]
fn join(
    v: u32,
    u: u32,
    e: u32,
    downstream: &mut [u32],
    down_edge: &mut [u32],
    joined: &mut [bool],
    tributaries: &mut [u8],
    order: &mut Vec<u32>,
) {
    downstream[v as usize] = u;
    down_edge[v as usize] = e;
    joined[v as usize] = true;
    tributaries[u as usize] = tributaries[u as usize].saturating_add(1);
    order.push(v);
}

/// Sea vertices: multi-source shortest distance from the coast sets the depth.
fn sea_floor(mesh: &mut Mesh, adj: &crate::mesh::Adjacency, p: &Params, elevation: &[Option<f64>]) {
    let n = mesh.vertices.len();
    let mut dist = vec![f64::INFINITY; n];
    let mut heap = BinaryHeap::new();
    for (v, vert) in mesh.vertices.iter().enumerate() {
        if vert.flags.contains(VertexFlags::COAST) {
            dist[v] = 0.0;
            heap.push(std::cmp::Reverse((0u64, v as u32)));
        }
    }
    while let Some(std::cmp::Reverse((d, v))) = heap.pop() {
        let d = f64::from_bits(d);
        if d > dist[v as usize] {
            continue;
        }
        for (w, e) in adj.around(v) {
            if mesh.vertices[w as usize].flags.is_pure_sea() {
                let nd = d + mesh.edge_length(e);
                if nd < dist[w as usize] {
                    dist[w as usize] = nd;
                    heap.push(std::cmp::Reverse((nd.to_bits(), w)));
                }
            }
        }
    }
    let sea = p.sea_level_m;
    for (v, vert) in mesh.vertices.iter_mut().enumerate() {
        if !vert.flags.is_pure_sea() {
            continue;
        }
        let shelf = sea - p.max_river_depth_m;
        let d = if dist[v].is_finite() { dist[v] } else { 1.0e7 };
        let procedural = (shelf - d * SHELF_SLOPE * (0.5 + altitude_random(vert.seed))).max(0.0);
        let ground = match elevation[v] {
            Some(h) if h < 0.0 => (sea + h).min(sea - 1.0),
            _ => procedural.min(sea - 1.0),
        };
        vert.ground = ground;
        vert.water = sea;
    }
}

/// Inserts a continent vertex into every continent edge between river or coast vertices, and
/// into coast edges joining two river mouths; the bisection closure splits whatever edges
/// must go first, with the paper's split rules; `relief` is the elevation map, as it is and as
/// means (`Map::mean_preserving`). Returns the number of mountain vertices made.
fn insert_mountains(
    mesh: &mut Mesh,
    p: &Params,
    relief: Option<(&Map, &Map)>,
    seed: u64,
    gradient: &mut Vec<f64>,
    lake_of: &mut Vec<u32>,
) -> usize {
    let wet = VertexFlags(VertexFlags::RIVER.0 | VertexFlags::COAST.0);
    let targets: Vec<(u32, [u32; 2])> = (0..mesh.edges.len() as u32)
        .filter(|&e| {
            let edge = &mesh.edges[e as usize];
            let [a, b] = edge.v.map(|v| mesh.vertices[v as usize].flags);
            match edge.kind {
                EdgeKind::Continent => a.intersects(wet) && b.intersects(wet),
                EdgeKind::Coast => a.contains(VertexFlags::MOUTH) && b.contains(VertexFlags::MOUTH),
                _ => false,
            }
        })
        .map(|e| (e, mesh.edges[e as usize].v))
        .collect();
    let mut mountains = 0;
    let mut make = |m: &Mesh, site: &SplitSite| {
        let (v, kinds) = base_split_vertex(m, site, p, relief, seed, gradient, lake_of);
        if v.flags.contains(VertexFlags::MOUNTAIN) {
            mountains += 1;
        }
        (v, kinds)
    };
    for (e, ends) in targets {
        // Skip edges the closure already split (their slot now holds a half).
        if mesh.edges[e as usize].v == ends {
            mesh.refine_edge(e, &mut make);
        }
    }
    mountains
}

/// The new vertex of a base-mesh split: positions as in §5.3 step 5 (on the base sphere; the
/// build lifts every vertex to its altitude at the end), altitudes by step 6 for sea, coast and
/// river edges, and eq. 5 for continent edges, which become mountains; `relief` as for
/// [`insert_mountains`].
fn base_split_vertex(
    m: &Mesh,
    site: &SplitSite,
    p: &Params,
    relief: Option<(&Map, &Map)>,
    planet_seed: u64,
    gradient: &mut Vec<f64>,
    lake_of: &mut Vec<u32>,
) -> (Vertex, [EdgeKind; 4]) {
    let diamond = Diamond::new(m, site);
    let seed = split_seed(&diamond);
    let edge = &m.edges[site.edge as usize];
    let [f1, f2] = edge.face_kinds();
    let kinds = split_kinds(edge.kind, f1, f2);
    let [va, vb, vt, vd] = [site.a, site.b, site.t, site.d].map(|v| &m.vertices[v as usize]);
    let xi = altitude_random(seed);
    let sea = p.sea_level_m;
    let (pos, ground, water, grad, flags) = match edge.kind {
        EdgeKind::Sea => {
            let pos = split_position(&diamond, seed, edge.kind, p.min_river_length_m);
            let mid = (va.ground + vb.ground) * 0.5;
            let g = (mid + (xi - 0.5) * m.edge_length(site.edge) * SHELF_SLOPE * 0.5).min(sea - 1.0);
            (pos, g, sea, 0.0, VertexFlags::empty())
        }
        EdgeKind::Coast => {
            let pos = split_position(&diamond, seed, edge.kind, p.min_river_length_m);
            (pos, sea + p.riverbed_edge_height_m * xi, sea, 0.0, VertexFlags::empty())
        }
        EdgeKind::River => {
            let pos = split_position(&diamond, seed, edge.kind, p.min_river_length_m);
            let g = (va.ground + vb.ground) * 0.5;
            let w = (va.water + vb.water) * 0.5;
            let grad = (gradient[site.a as usize] + gradient[site.b as usize]) * 0.5;
            (pos, g, w, grad, VertexFlags::RIVER)
        }
        EdgeKind::Continent => {
            let pos = split_position(&diamond, seed, edge.kind, p.min_river_length_m);
            let around = [(site.a, va), (site.b, vb), (site.t, vt), (site.d, vd)];
            let wet = VertexFlags(VertexFlags::RIVER.0 | VertexFlags::COAST.0);
            let (r, vr) = around
                .iter()
                .filter(|(_, v)| v.flags.intersects(wet))
                .max_by(|x, y| x.1.ground.total_cmp(&y.1.ground).then(x.0.cmp(&y.0)))
                .copied()
                .unwrap_or(around[0]);
            let unit_pos = pos.normalize() * m.radius;
            let horizontal = |q: &Vertex| unit_pos.distance(q.p().normalize() * m.radius);
            let (lat, lon) = lat_lon(pos);
            let mapped = relief.and_then(|(_, means)| means.sample(lat, lon)).map(|h| sea + h as f64);
            // Eq. 10–11: above every riverbank next to it by the riverbed rules, except a
            // river's where the map shows lower ground (as for the splits below the base mesh,
            // `bank_gives_way`): every inland base vertex is a river vertex, and one between a
            // river on a plateau's rim and the foot of its escarpment, or across a divide, is
            // not on its bank (lifted onto it, the map's fronts were smeared over a base edge
            // and every interfluve raised: +53 m over the Earth DEM's land with rivers at the map).
            let mut lo = f64::MIN;
            let mut hi = p.max_mountain_altitude_m;
            for (_, v) in around {
                let le = horizontal(v);
                if bank_gives_way(v, le, mapped, p) {
                    continue;
                }
                if v.flags.intersects(wet) || v.submerged() {
                    lo = lo.max(riverbank_floor(v, le, p));
                } else {
                    // Eq. 12: no steeper than the maximum ground slope towards other land.
                    lo = lo.max(v.ground - le * p.ground_slope());
                    hi = hi.min(v.ground + le * p.ground_slope());
                }
            }
            let wanted = match mapped {
                Some(h) => h,
                // A mountain belt lifts the ridges between rivers by its full height.
                None => {
                    let belt = p.mountain_belt_uplift_m * super::belts::belt(planet_seed, pos);
                    vr.ground + gradient[r as usize] * horizontal(vr) * xi + belt
                }
            };
            // Between two shores of one lake, ground the map has below the lake's surface is
            // its bed, under water (no island the map does not have).
            let lake = lake_of.get(site.a as usize).copied().filter(|&l| l != NONE);
            let surface = va.water.max(vb.water);
            let under =
                || relief.and_then(|(map, _)| map.sample(lat, lon)).is_some_and(|h| sea + f64::from(h) < surface);
            match mapped {
                Some(h) if lake.is_some_and(|l| lake_of[site.b as usize] == l) && under() => (
                    pos,
                    h.min(surface - p.riverbed_edge_height_m),
                    surface,
                    0.0,
                    VertexFlags(VertexFlags::MOUNTAIN.0 | VertexFlags::LAKE.0),
                ),
                _ => {
                    let g = wanted.min(hi).max(lo);
                    (pos, g, g, 0.0, VertexFlags::MOUNTAIN)
                }
            }
        }
    };
    let mut v = Vertex::new(lift(pos, m.radius, 0.0), seed);
    v.ground = ground;
    v.water = water;
    v.flags = flags;
    gradient.push(grad);
    if !lake_of.is_empty() {
        let (la, lb) = (lake_of[site.a as usize], lake_of[site.b as usize]);
        let lake = if la == lb && water > ground { la } else { NONE };
        lake_of.push(lake);
        if lake != NONE {
            v.flags.insert(VertexFlags::LAKE);
        }
    }
    (v, kinds)
}

/// Lifts every vertex to its ground altitude (eq. 1), then refreshes the level-of-detail bounds
/// and the downstream tangents of river vertices.
pub fn finish(mesh: &mut Mesh) {
    let r = mesh.radius;
    for v in mesh.vertices.iter_mut() {
        v.pos = lift(v.p(), r, v.ground).to_array();
    }
    mesh.reset_lod_roots();
    let graph = super::network::RiverGraph::from_mesh(mesh);
    for v in 0..mesh.vertices.len() {
        let d = graph.downstream[v];
        let up = graph.upstream_of(v as u32).next();
        let t = if d != NONE {
            tangent_towards(mesh.pos(v as u32), mesh.pos(d))
        } else if let Some(u) = up {
            -tangent_towards(mesh.pos(v as u32), mesh.pos(u))
        } else {
            continue;
        };
        mesh.vertices[v].tangent = Tangent::new(t);
    }
}
