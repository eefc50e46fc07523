//! Planet generation (paper §4): base shape, continents and initial river networks.

pub mod basins;
pub mod belts;
pub mod climate;
pub mod continents;
pub mod downhill;
pub mod fidelity;
pub mod lakes;
pub mod network;
pub mod relief;
pub mod rivers;
pub mod shape;

use crate::maps::{Map, MapKind};
use crate::mesh::guide::Guide;
use crate::mesh::{FaceKind, Mesh, VertexFlags};
use crate::params::{ParamError, Params, MAX_BASE_FACES};
use serde::{Deserialize, Serialize};
use std::sync::Arc;
use std::time::Instant;

pub use network::RiverGraph;

/// Everything a planet is made from: seed, parameters and an optional map.
#[derive(Clone, Debug)]
pub struct PlanetSpec {
    pub seed: u64,
    pub params: Params,
    pub map: Option<Arc<Map>>,
    /// Mean annual precipitation (mm/yr, [`crate::maps::decode_precipitation`]) in place of the
    /// climate model's where the map covers the planet.
    pub precipitation: Option<Arc<Map>>,
}

/// A built base mesh with its river network and statistics.
#[derive(Clone, Debug)]
pub struct Planet {
    pub mesh: Mesh,
    pub rivers: RiverGraph,
    pub stats: Stats,
    /// Elevation maps: the lakes, and the lake each base-mesh vertex lies under (`NONE` off
    /// lakes; empty without a map).
    pub lakes: Vec<lakes::Lake>,
    pub lake_of: Vec<u32>,
    /// Runoff and open water's net evaporation per base-mesh vertex, from the planet's climate
    /// ([`climate`]): what the rivers' discharge sums and loses.
    pub water: network::WaterBudget,
}

/// `stats.json`: the numbers that describe a built planet.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Stats {
    pub faces: usize,
    pub vertices: usize,
    pub edges: usize,
    /// Share of the sphere's area covered by land faces.
    pub land_fraction: f64,
    pub continents: usize,
    pub river_edges: usize,
    pub river_mouths: usize,
    /// Share of the land area whose water reaches the sea through the network.
    pub drained_fraction: f64,
    pub monotone_violations: usize,
    pub bytes_per_vertex: f64,
    /// Wall-clock time of the build (ms). Left out of the service's planet records (`None`):
    /// it measures the replica that built the planet, not the planet, and every replica must
    /// answer the same bytes.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub build_ms: Option<f64>,
    /// Elevation maps: lakes (the depressions of the map kept as lakes and the terminal lakes
    /// of closed basins), depressions breached as artefacts, and closed (endorheic) basins.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lakes: Option<usize>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub endorheic_basins: Option<usize>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub breached_depressions: Option<usize>,
    /// Elevation maps: the planet's ground against the map (see [`fidelity`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub map_fidelity: Option<fidelity::MapFidelity>,
}

/// Why a planet could not be built from its inputs.
#[derive(Debug, thiserror::Error)]
pub enum BuildError {
    #[error(transparent)]
    Params(#[from] ParamError),
    #[error(
        "the map leaves the planet no sea: every face is land (an elevation map's sea is ground \
         below 0 m joined to the ocean, or the outside of a regional map's bounds)"
    )]
    NoSea,
    #[error(
        "the map leaves the planet no land: every face is sea (an elevation map's land is ground \
         above 0 m, or below it and cut off from the ocean)"
    )]
    NoLand,
}

impl BuildError {
    pub fn field(&self) -> &str {
        match self {
            BuildError::Params(e) => &e.field,
            BuildError::NoSea | BuildError::NoLand => "map",
        }
    }
}

/// Refinement edge length a map needs, in map pixels: nine for a continent bitmap (a coast
/// needs no finer), two for an elevation map, whose heights the mesh must keep. (At four, a
/// 512-pixel Earth map got 313 km edges where the face budget allows 165 km, and its rivers,
/// valleys and banks departed from the map at its own pixels twice as much as the real relief
/// does: docs/realism.md, "2026-12-06 (night)".)
const PIXELS_PER_EDGE: f64 = 9.0;
const ELEVATION_PIXELS_PER_EDGE: f64 = 2.0;
/// Refinement edges inside a map's bounds are no shorter than what gives the bounds about this
/// many faces before mountains are inserted (which about quadruples them): a global map finer
/// than 2048 pixels across gets the mesh of one at 2048 (~170 km refinement edges), not one
/// that grows with the map's size.
const MAP_FACES: f64 = 75_000.0;
/// Width of the shore around a regional elevation map, in refinement edges: enough that the
/// coast's faces, and the ground they pull towards sea level, stay outside the map's bounds.
const SHORE_EDGES: f64 = 3.0;

/// Target edge length (m) to honour a map's detail: a few pixels per edge, within the bounds'
/// share of [`MAP_FACES`].
pub fn map_edge_length(map: &Map, radius: f64) -> f64 {
    let (_, dlat) = map.pixel_size_deg();
    let per_edge = if map.kind == MapKind::Elevation { ELEVATION_PIXELS_PER_EDGE } else { PIXELS_PER_EDGE };
    let b = map.bounds;
    let area =
        (b.east - b.west).to_radians() * (b.north.to_radians().sin() - b.south.to_radians().sin()) * radius * radius;
    // A face under its refinement edge L covers about L²/4.
    let floor = (4.0 * area / MAP_FACES).sqrt();
    (per_edge * dlat.to_radians() * radius).max(floor)
}

/// An upper estimate of the faces of a planet's base mesh, known before it is built (the
/// server admits planets by it). The base shape's faces outside a map's bounds, and inside them
/// the finer of the base shape and the refinement the map asks for ([`map_edge_length`]), each
/// grown by the rivers' and mountains' vertices that land adds. Measured against builds of the
/// shipped maps and random planets (test `the_face_estimate_bounds_the_build`), it is 1.2-2.2x
/// the faces a build gives.
pub fn estimated_faces(p: &Params, map: Option<&Map>) -> usize {
    // Faces of a shape refined to edge L over area A: about 4 A / L² (triangles of L²/4);
    // refinement leaves edges between L/2 and L, so up to 16 A / L².
    const REFINED_PER_AREA: f64 = 16.0;
    // Growth of the faces by rivers and mountains: up to x4.65 over land (paper §4.3), x1.15
    // over sea (coasts).
    const SEA_GROWTH: f64 = 1.15;
    const LAND_GROWTH: f64 = 3.5;
    let base = f64::from(p.base_faces);
    let random_growth = SEA_GROWTH + LAND_GROWTH * p.land_percent / 100.0;
    let Some(map) = map else { return (base * random_growth).ceil() as usize };
    let r = p.radius_m;
    let target = map_edge_length(map, r);
    let b = map.bounds;
    // A regional elevation map is widened by its shore (see `build_planet`).
    let pad =
        if map.kind == MapKind::Elevation && !b.is_global() { (SHORE_EDGES * target / r).to_degrees() } else { 0.0 };
    let (south, north) = ((b.south - pad).max(-90.0), (b.north + pad).min(90.0));
    let span = (b.east - b.west + 2.0 * pad).min(360.0).to_radians();
    let area = span * (north.to_radians().sin() - south.to_radians().sin()) * r * r;
    let share = (area / (4.0 * std::f64::consts::PI * r * r)).min(1.0);
    let inside = (base * share).max(REFINED_PER_AREA * area / (target * target));
    let growth = SEA_GROWTH + LAND_GROWTH * map.land_fraction();
    // Outside the bounds the planet is sea.
    (base * (1.0 - share) * SEA_GROWTH + inside * growth).ceil() as usize
}

/// Builds the base mesh of a planet (§4). `progress` receives a stage name and a fraction.
pub fn build_planet(spec: &PlanetSpec, progress: &mut dyn FnMut(&str, f32)) -> Result<Planet, BuildError> {
    let start = Instant::now();
    let p = &spec.params;
    p.validate()?;
    progress("base shape", 0.0);
    let mut mesh = shape::octahedron(p.radius_m, spec.seed);
    shape::refine_to(&mut mesh, p.base_faces as usize, spec.seed);
    // A regional elevation map's coast lies outside its bounds (see `maps::margin`): the mesh,
    // rivers and guide see the map widened by a shore of SHORE_EDGES refinement edges.
    let target = spec.map.as_deref().map(|m| map_edge_length(m, p.radius_m));
    let edge_px =
        spec.map.as_deref().zip(target).map_or(0.0, |(m, t)| t / (m.pixel_size_deg().1.to_radians() * p.radius_m));
    let shore_px = (SHORE_EDGES * edge_px).ceil();
    let widened = spec.map.as_deref().and_then(|m| m.with_shore(shore_px as u32));
    let map_in = widened.as_ref().or(spec.map.as_deref());
    if let (Some(map), Some(target)) = (map_in, target) {
        let bounds = map.bounds;
        shape::refine_where(&mut mesh, MAX_BASE_FACES as usize, |m, f| {
            let face = &m.faces[f as usize];
            m.edge_length(face.e[0]) > target && face_touches(m, f, &bounds)
        });
    }
    progress("continents", 0.3);
    match map_in {
        Some(map) => {
            continents::from_map(&mut mesh, map);
            let land = (0..mesh.faces.len() as u32).filter(|&f| mesh.face_kind(f) == FaceKind::Land).count();
            if land == 0 {
                return Err(BuildError::NoLand);
            }
            if land == mesh.faces.len() {
                return Err(BuildError::NoSea);
            }
        }
        None => {
            continents::grow_random(&mut mesh, p.continents, p.land_percent, spec.seed);
        }
    }
    progress("rivers", 0.4);
    // Vertices sample the map averaged over about their spacing (a third of the refinement edge).
    let relief = spec.map.as_deref().filter(|m| m.kind == MapKind::Elevation).map(|m| {
        let filtered = m.box_filtered((edge_px / 3.0) as u32);
        let k = f64::from(m.width / filtered.width);
        filtered.with_shore((shore_px / k).ceil() as u32).unwrap_or(filtered)
    });
    // A precipitation map on the climate's grid, once for both water balances.
    let rain = spec.precipitation.as_deref().map(climate::precipitation_grid);
    let mut report = rivers::build_rivers(&mut mesh, p, relief.as_ref(), rain.as_deref(), spec.seed);
    progress("finishing", 0.9);
    rivers::finish(&mut mesh);
    // Splits below the base mesh follow an elevation map where it resolves them.
    mesh.guide = map_in.and_then(|m| Guide::from_map(m, p.radius_m)).map(std::sync::Arc::new);
    let graph = RiverGraph::from_mesh(&mesh);
    let (water, precipitation) = water_budget(&mesh, p.sea_level_m, rain.as_deref());
    mesh.precipitation = precipitation.map(std::sync::Arc::new);
    // Channel widths for the water surface, from the discharge of the climate's runoff.
    mesh.channels = network::channels(&mesh, &graph, &graph.discharge(&mesh, &water)).map(std::sync::Arc::new);
    let map_fidelity = spec.map.as_deref().and_then(|m| fidelity::map_fidelity(&mesh, m, p.sea_level_m));
    let stats = Stats {
        faces: mesh.faces.len(),
        vertices: mesh.vertices.len(),
        edges: mesh.edges.len(),
        land_fraction: continents::land_fraction(&mesh),
        continents: continents::count_continents(&mesh),
        river_edges: mesh.edges.iter().filter(|e| e.kind == crate::mesh::EdgeKind::River).count(),
        river_mouths: graph.mouths.len(),
        drained_fraction: graph.drained_fraction(&mesh),
        monotone_violations: graph.monotone_violations,
        bytes_per_vertex: mesh.bytes_per_vertex(),
        build_ms: Some(start.elapsed().as_secs_f64() * 1000.0),
        lakes: relief.as_ref().map(|_| report.lakes),
        endorheic_basins: relief.as_ref().map(|_| report.endorheic),
        breached_depressions: relief.as_ref().map(|_| report.breached),
        map_fidelity,
    };
    let lake_of = std::mem::take(&mut report.lake_of);
    let lakes = lakes::lakes(&mesh, &lake_of, &report.lake_levels);
    progress("done", 1.0);
    Ok(Planet { mesh, rivers: graph, stats, lakes, lake_of, water })
}

/// Runoff (mm/yr) of each land vertex and what a river's floodplain loses there, in the
/// climate of the built mesh, and the climate's precipitation for the colours.
fn water_budget(
    mesh: &Mesh,
    sea: f64,
    rain: Option<&[f32]>,
) -> (network::WaterBudget, Option<crate::mesh::precipitation::Precipitation>) {
    let land = |v: usize| mesh.vertices[v].flags.is_inland() || mesh.vertices[v].flags.contains(VertexFlags::COAST);
    let altitude = |v: usize| mesh.vertices[v].ground - sea;
    let c = climate::Climate::of_mesh(mesh, land, altitude).with_precipitation(rain);
    let at = c.at_vertices(mesh, altitude);
    let runoff_mm = at
        .iter()
        .enumerate()
        .map(|(v, &(p, e0))| if land(v) { climate::runoff_mm(p, e0) as f32 } else { 0.0 })
        .collect();
    let channel_loss_mm = at.iter().map(|&(p, e0)| climate::channel_loss_mm(p, e0) as f32).collect();
    let precipitation = crate::mesh::precipitation::Precipitation::new(c.width, c.height, c.precip_mm);
    (network::WaterBudget { runoff_mm, channel_loss_mm }, precipitation)
}

/// Whether face `f` may overlap the map bounds (its vertices' bounding box, widened by the
/// face's size so faces straddling the edge count).
fn face_touches(mesh: &Mesh, f: u32, bounds: &crate::maps::GeoBounds) -> bool {
    if bounds.is_global() {
        return true;
    }
    let face = &mesh.faces[f as usize];
    let pad = (mesh.edge_length(face.e[0]) / mesh.radius).to_degrees();
    let ll: Vec<(f64, f64)> = mesh.corners(f).iter().map(|&v| crate::geo::lat_lon(mesh.pos(v))).collect();
    let (lat_lo, lat_hi) = ll.iter().fold((90.0f64, -90.0f64), |(lo, hi), &(la, _)| (lo.min(la), hi.max(la)));
    if lat_hi + pad < bounds.south || lat_lo - pad > bounds.north {
        return false;
    }
    let (lon_lo, lon_hi) = ll.iter().fold((180.0f64, -180.0f64), |(lo, hi), &(_, lo2)| (lo.min(lo2), hi.max(lo2)));
    if lon_hi - lon_lo > 180.0 || lat_hi > 89.0 || lat_lo < -89.0 {
        return true; // wraps the antimeridian or touches a pole: keep it simple and refine
    }
    let cos = lat_lo.abs().max(lat_hi.abs()).min(89.0).to_radians().cos();
    let lon_pad = pad / cos;
    !(lon_hi + lon_pad < bounds.west || lon_lo - lon_pad > bounds.east)
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_climate;
#[cfg(test)]
pub(crate) mod tests_relief;
