//! The GPU backend against the CPU backend on one device (lavapipe in CI): the same decisions
//! for every edge, and so the same adapted meshes, bit for bit.

use super::*;
use crate::adapt::cpu::state;
use crate::adapt::{Adapter, Camera, View};
use crate::mesh::Mesh;
use crate::params::Params;
use crate::planet::{build_planet, Planet, PlanetSpec};
use glam::DVec3;
use proptest::prelude::*;
use std::sync::OnceLock;

const R: f64 = 6_371_000.0;

fn planet() -> &'static Planet {
    static P: OnceLock<Planet> = OnceLock::new();
    P.get_or_init(|| {
        let spec = PlanetSpec {
            seed: 7,
            params: Params { base_faces: 4000, ..Params::paper() },
            map: None,
            precipitation: None,
        };
        build_planet(&spec, &mut |_, _| {}).unwrap()
    })
}

fn gpu() -> Arc<GpuAdaption> {
    static G: OnceLock<Arc<GpuAdaption>> = OnceLock::new();
    G.get_or_init(|| {
        let g = GpuAdaption::new().expect("a wgpu adapter with f64 (install mesa-vulkan-drivers for lavapipe)");
        eprintln!("GPU backend on {}", g.describe());
        Arc::new(g)
    })
    .clone()
}

fn view(cam: &Camera) -> View {
    let p = Params::paper();
    View::new(cam, p.radius_m, p.min_edge_length_m, crate::adapt::terrain_top(&p, &crate::mesh::Mesh::default()))
}

/// Asserts that the device decides every edge of `mesh` as the CPU does.
fn same_wants(mesh: &Mesh, cam: &Camera) {
    let v = view(cam);
    let cpu = state::edge_wants(mesh, &v);
    let dev = edge_wants(&gpu(), mesh, &v).expect("the state update runs on the device");
    assert_eq!(cpu.len(), dev.len());
    let differ: Vec<usize> = (0..cpu.len()).filter(|&e| cpu[e] != dev[e]).collect();
    assert!(
        differ.is_empty(),
        "{} of {} edges decided differently, e.g. {:?}",
        differ.len(),
        cpu.len(),
        &differ[..differ.len().min(8)]
    );
}

/// Asserts that two meshes are equal, naming the first entity that differs and how: bit for bit
/// on a CPU adapter (lavapipe rounds like the CPU) and wherever the shaders forbid fused
/// multiply-adds (SPIR-V on Vulkan); elsewhere (WGSL, whose compilers may fuse), the same
/// topology and kinds with positions within 1 µm and altitudes within 1 mm.
fn assert_same_mesh(cpu: &Mesh, dev: &Mesh, what: &str) {
    let exact = gpu().is_cpu() || gpu().exact_arithmetic();
    let sizes = |m: &Mesh| (m.vertices.len(), m.edges.len(), m.faces.len());
    assert_eq!(sizes(cpu), sizes(dev), "{what}: vertex, edge and face counts");
    let differ = |name: &str, n: usize, same: &dyn Fn(usize) -> bool, show: &dyn Fn(usize) -> String| {
        let bad: Vec<usize> = (0..n).filter(|&i| !same(i)).collect();
        assert!(bad.is_empty(), "{what}: {} of {n} {name} differ; first {}", bad.len(), show(bad[0]));
    };
    let close = |x: &crate::mesh::Vertex, y: &crate::mesh::Vertex| {
        x.p().distance(y.p()) <= 1e-6
            && (x.ground - y.ground).abs() <= 1e-3
            && (x.water - y.water).abs() <= 1e-3
            && (x.edge, x.seed, x.flags, x.tangent) == (y.edge, y.seed, y.flags, y.tangent)
    };
    differ(
        "vertices",
        cpu.vertices.len(),
        &|i| {
            let (x, y) = (&cpu.vertices[i], &dev.vertices[i]);
            bytemuck::bytes_of(x) == bytemuck::bytes_of(y) || (!exact && close(x, y))
        },
        &|i| format!("{i}: CPU {:?} GPU {:?}", cpu.vertices[i], dev.vertices[i]),
    );
    differ(
        "edges",
        cpu.edges.len(),
        &|i| {
            let (x, y) = (&cpu.edges[i], &dev.edges[i]);
            x == y || (!exact && (x.v, x.f, x.level, x.kind, x.land) == (y.v, y.f, y.level, y.kind, y.land))
        },
        &|i| format!("{i}: CPU {:?} GPU {:?}", cpu.edges[i], dev.edges[i]),
    );
    differ("faces", cpu.faces.len(), &|i| cpu.faces[i] == dev.faces[i], &|i| {
        format!("{i}: CPU {:?} GPU {:?}", cpu.faces[i], dev.faces[i])
    });
}

/// A camera `height` m above the ground at (lat, lon) looking `ahead` m along the ground to the north.
fn ground(lat: f64, lon: f64, height: f64, ahead: f64, px: f64) -> Camera {
    let sea = Params::paper().sea_level_m;
    let dir = crate::geo::direction(lat, lon);
    let north = (DVec3::Z - dir * dir.z).normalize_or(DVec3::X);
    let eye = dir * (R + sea + height);
    let target = (dir + north * (ahead / R)).normalize() * (R + sea);
    Camera::new(eye, target, None, 60.0, 640, 360, px, px * 5.0, R).unwrap()
}

#[test]
fn vulkan_runs_the_shaders_without_fused_multiply_adds() {
    let g = gpu();
    if g.info.backend == wgpu::Backend::Vulkan {
        assert!(g.exact_arithmetic(), "{}: shaders passed as WGSL, which lets the driver fuse", g.describe());
    }
}

#[test]
fn a_fly_through_adapts_to_the_same_meshes_on_both_backends() {
    let sea = Params::paper().sea_level_m;
    let cams = crate::adapt::flight::fly_through(R, sea, 12.0, 30.0, 20);
    let mut cpu = Adapter::new(planet().mesh.clone(), Params::paper());
    let mut dev = Adapter::new(planet().mesh.clone(), Params::paper()).with_gpu(Some(gpu()));
    for (i, cam) in cams.iter().enumerate() {
        // Decisions on the mesh of the previous camera, then the whole adaption.
        same_wants(cpu.mesh(), cam);
        let a = cpu.adapt(cam, Some(60_000));
        let b = dev.adapt(cam, Some(60_000));
        assert!(dev.on_gpu(), "camera {i}: the GPU backend fell back to the CPU");
        assert_eq!(
            (a.faces, a.splits, a.collapses, a.lod_scale),
            (b.faces, b.splits, b.collapses, b.lod_scale),
            "camera {i}"
        );
        assert_same_mesh(cpu.mesh(), dev.mesh(), &format!("camera {i}"));
    }
}

#[test]
fn metre_edges_by_the_eye_are_decided_alike_at_earth_radius() {
    // Two metres above the lowest land vertex (not inside a mountain), half-pixel targets:
    // edges in front of the eye come down to about a metre, where an f32 position at Earth
    // radius would be off by up to a quarter of a metre.
    let base = &planet().mesh;
    let land = base
        .edges
        .iter()
        .filter(|e| e.kind == crate::mesh::EdgeKind::Continent)
        .flat_map(|e| e.v)
        .min_by(|&x, &y| base.vertices[x as usize].ground.total_cmp(&base.vertices[y as usize].ground).then(x.cmp(&y)))
        .expect("the planet has land");
    let v = &base.vertices[land as usize];
    let dir = v.p().normalize();
    let north = (DVec3::Z - dir * dir.z).normalize();
    let ground = R + v.ground;
    let cam = Camera::new(
        dir * (ground + 2.0),
        (dir + north * (50.0 / R)).normalize() * ground,
        None,
        60.0,
        640,
        360,
        0.5,
        2.5,
        R,
    )
    .unwrap();
    let mut a = Adapter::new(planet().mesh.clone(), Params::paper());
    a.adapt(&cam, Some(400_000));
    let mesh = a.mesh();
    let shortest = (0..mesh.edges.len() as u32).map(|e| mesh.edge_length(e)).fold(f64::MAX, f64::min);
    assert!(shortest < 2.0, "the view did not refine to metre edges ({shortest} m)");
    same_wants(mesh, &cam);
    // And the adaption itself, from the base mesh, on the device.
    let mut dev = Adapter::new(planet().mesh.clone(), Params::paper()).with_gpu(Some(gpu()));
    dev.adapt(&cam, Some(400_000));
    assert!(dev.on_gpu(), "the GPU backend fell back to the CPU");
    assert_same_mesh(mesh, dev.mesh(), "metre edges");
}

#[test]
fn the_backend_names_parse() {
    assert_eq!("cpu".parse::<Backend>(), Ok(Backend::Cpu));
    assert_eq!("gpu".parse::<Backend>(), Ok(Backend::Gpu));
    assert_eq!("auto".parse::<Backend>(), Ok(Backend::Auto));
    assert!("cuda".parse::<Backend>().unwrap_err().contains("cpu, gpu or auto"));
    // The CPU backend opens nothing; auto on a CPU adapter stays on the CPU.
    assert!(select(Backend::Cpu).unwrap().0.is_none());
    if gpu().is_cpu() {
        let (chosen, line) = select(Backend::Auto).unwrap();
        assert!(chosen.is_none() && line.contains("is itself a CPU"), "{line}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    /// Random cameras, from the ground to far out, over a mesh adapted to another random camera.
    #[test]
    fn random_cameras_are_decided_alike(
        lat in -80.0f64..80.0, lon in -180.0f64..180.0, log_h in 0.0f64..7.5,
        lat2 in -80.0f64..80.0, lon2 in -180.0f64..180.0, px in 0.5f64..8.0,
    ) {
        let first = ground(lat2, lon2, 10f64.powf(5.0), 2e5, 4.0);
        let mut a = Adapter::new(planet().mesh.clone(), Params::paper());
        a.adapt(&first, Some(40_000));
        let h = 10f64.powf(log_h);
        same_wants(a.mesh(), &ground(lat, lon, h, h * 3.0 + 100.0, px));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 8, ..ProptestConfig::default() })]

    /// Random two-camera paths, from the ground to far out, adapted on both backends: the
    /// second camera's mesh grows from (and coarsens) the first's.
    #[test]
    fn random_camera_paths_adapt_alike(
        lat in -80.0f64..80.0, lon in -180.0f64..180.0, log_h in 0.0f64..7.0,
        lat2 in -80.0f64..80.0, lon2 in -180.0f64..180.0, px in 0.5f64..8.0,
    ) {
        let h = 10f64.powf(log_h);
        let cams = [ground(lat2, lon2, 1e5, 2e5, 4.0), ground(lat, lon, h, h * 3.0 + 100.0, px)];
        let mut cpu = Adapter::new(planet().mesh.clone(), Params::paper());
        let mut dev = Adapter::new(planet().mesh.clone(), Params::paper()).with_gpu(Some(gpu()));
        for (i, cam) in cams.iter().enumerate() {
            let a = cpu.adapt(cam, Some(40_000));
            let b = dev.adapt(cam, Some(40_000));
            prop_assert!(dev.on_gpu(), "camera {}: the GPU backend fell back to the CPU", i);
            prop_assert_eq!((a.splits, a.collapses, a.passes), (b.splits, b.collapses, b.passes));
            assert_same_mesh(cpu.mesh(), dev.mesh(), &format!("camera {i}"));
        }
    }
}

#[test]
fn a_jump_from_the_ground_to_orbit_coarsens_alike() {
    // Enough collapses in one run that the holes are squeezed out mid-run (more than
    // `N_ALLOC` dead faces), then decided again, on both backends.
    let cams = [ground(20.0, 10.0, 50.0, 500.0, 1.0), ground(-30.0, 120.0, 2e7, 3e7, 4.0)];
    let mut cpu = Adapter::new(planet().mesh.clone(), Params::paper());
    let mut dev = Adapter::new(planet().mesh.clone(), Params::paper()).with_gpu(Some(gpu()));
    for (i, cam) in cams.iter().enumerate() {
        let a = cpu.adapt(cam, Some(250_000));
        let b = dev.adapt(cam, Some(250_000));
        assert!(dev.on_gpu(), "camera {i}: the GPU backend fell back to the CPU");
        assert_eq!((a.splits, a.collapses, a.passes), (b.splits, b.collapses, b.passes), "camera {i}");
        if i == 1 {
            assert!(2 * a.collapses > crate::adapt::cpu::compact::N_ALLOC, "only {} collapses", a.collapses);
        }
        assert_same_mesh(cpu.mesh(), dev.mesh(), &format!("camera {i}"));
    }
}

/// A refined mesh with holes: every vertex a far camera lets collapse, collapsed once; and the
/// number of collapses.
fn mesh_with_holes() -> (Mesh, usize) {
    let mut a = Adapter::new(planet().mesh.clone(), Params::paper());
    a.adapt(&ground(10.0, 20.0, 2e3, 1e4, 2.0), Some(60_000));
    let mut mesh = a.mesh().clone();
    let far = view(&ground(-40.0, -100.0, 1e7, 2e7, 4.0));
    let wants = state::edge_wants(&mesh, &far);
    let sites = state::collapse_candidates(&mesh, &far, &crate::adapt::cpu::select::demanded(&mesh, &wants), None);
    assert!(sites.len() > 1000, "only {} collapses", sites.len());
    // SAFETY: the sites were found on this mesh, one per vertex.
    unsafe { mesh.collapse_vertices(&sites) };
    (mesh, sites.len())
}

#[test]
fn device_compaction_equals_host_compaction() {
    let (mut mesh, n) = mesh_with_holes();
    let (nv, ne, nf) = (mesh.vertices.len(), mesh.edges.len(), mesh.faces.len());

    let g = gpu();
    let dm = DeviceMesh::upload(&g, &mesh).unwrap();
    let mut sub = g.submission();
    let out = g.compact.encode(&g, &mut sub, &dm, (nv - n, ne - 3 * n, nf - 2 * n)).unwrap();
    sub.finish(&g, &out).unwrap();
    let dev = out.download(&g, mesh.radius).unwrap();
    mesh.compact();
    assert_eq!(mesh.faces.len(), nf - 2 * n);
    // Compaction moves entities and renumbers references; nothing is computed, so bit for bit
    // on every adapter.
    assert_eq!(bytemuck::cast_slice::<_, u8>(&mesh.vertices), bytemuck::cast_slice::<_, u8>(&dev.vertices));
    assert_eq!(mesh.edges, dev.edges);
    assert_eq!(mesh.faces, dev.faces);
}

#[test]
fn the_device_copy_follows_the_spatial_order_of_the_host() {
    // A mesh with holes renumbered by the order the host computes: the moves on the device
    // give the host's result bit for bit.
    let (mut mesh, _) = mesh_with_holes();
    let g = gpu();
    let dm = DeviceMesh::upload(&g, &mesh).unwrap();
    let order = mesh.compact_in_spatial_order();
    assert!(order.vertices.iter().enumerate().any(|(old, &new)| new != old as u32), "nothing moved");
    let mut sub = g.submission();
    let out = g.compact.encode_renumbering(&g, &mut sub, &dm, &order).unwrap();
    sub.finish(&g, &out).unwrap();
    let dev = out.download(&g, mesh.radius).unwrap();
    assert_eq!(bytemuck::cast_slice::<_, u8>(&mesh.vertices), bytemuck::cast_slice::<_, u8>(&dev.vertices));
    assert_eq!(mesh.edges, dev.edges);
    assert_eq!(mesh.faces, dev.faces);

    // Between cameras an adapter orders its mesh and keeps the device copy, which follows.
    let mut dev = Adapter::new(planet().mesh.clone(), Params::paper()).with_gpu(Some(g.clone()));
    dev.adapt(&ground(10.0, 20.0, 2e3, 1e4, 2.0), None);
    assert!(crate::adapt::cpu::compact::scattered(dev.mesh.faces.len(), dev.ordered_faces));
    dev.order();
    let device = dev.device.as_mut().expect("still on the device");
    assert_eq!(device.faces_ahead(), None);
    let kept = device.take_copy();
    let kept = kept.mesh.as_ref().expect("the device copy is kept through the ordering");
    let copy = kept.download(&g, dev.mesh.radius).unwrap();
    assert_same_mesh(&dev.mesh, &copy, "the ordered device copy");
}

/// A mesh larger than the device's largest buffer is read back buffer by buffer: the same mesh,
/// byte for byte. A mesh over the device's binding limit is refused with an error (the adapter
/// then goes on on the CPU) rather than a panic.
#[test]
fn large_meshes_read_back_or_are_refused() {
    let g = gpu();
    let mesh = planet().mesh.clone();
    let dm = DeviceMesh::upload(&g, &mesh).unwrap();
    let whole = dm.download(&g, mesh.radius).unwrap();
    let staged = dm.download_staged(&g, mesh.radius, 1024).unwrap();
    // The device holds the buffers; what the planet attaches to its mesh stays on the host.
    let buffers = Mesh { guide: None, channels: None, precipitation: None, ..mesh.clone() };
    assert!(whole == buffers && staged == buffers);
    let limit = g.device.limits().max_storage_buffer_binding_size;
    let too_many = (limit / crate::mesh::EDGE_BYTES as u64) as usize;
    match DeviceMesh::with_capacity(&g, 10, too_many, 10) {
        Err(GpuError::TooLarge { needed, limit: l }) => assert!(needed > l && l <= limit, "{needed} {l}"),
        other => panic!("expected TooLarge, got {other:?}"),
    }
}

/// Constants the shaders spell out themselves agree with the host's: workgroup sizes (the
/// host's dispatch grids count in them), the scan's block, the tangent code's range, and the
/// level-of-detail ball of a child edge (`child_lod` takes `LOD_RADIUS` as 1).
#[test]
fn shader_constants_match_the_host() {
    let sizes = |src: &str| -> Vec<u32> {
        src.split("@workgroup_size(").skip(1).map(|s| s[..s.find(')').unwrap()].trim().parse().unwrap()).collect()
    };
    let shaders: [(&str, &str, u32); 6] = [
        ("split", super::shaders::SPLIT, split::WORKGROUP),
        ("state", super::shaders::STATE, super::state::WORKGROUP),
        ("select", super::shaders::SELECT, WORKGROUP),
        ("scan", super::shaders::SCAN, WORKGROUP),
        ("collapse", super::shaders::COLLAPSE, WORKGROUP),
        ("compact", super::shaders::COMPACT, WORKGROUP),
    ];
    for (name, src, size) in shaders {
        let found = sizes(src);
        assert!(!found.is_empty() && found.iter().all(|&s| s == size), "{name}: {found:?} vs {size}");
    }
    assert!(super::shaders::SCAN.contains(&format!("const BLOCK: u32 = {BLOCK}u;")));
    let split_src = super::shaders::SPLIT;
    let scale = crate::mesh::Tangent::SCALE;
    assert_eq!(split_src.matches(&format!("f64(-{scale:.1}), f64({scale:.1})")).count(), 2);
    assert_eq!(crate::mesh::LOD_RADIUS, 1.0);
    let mesh_src = super::shaders::LAYOUT;
    use crate::mesh::VertexFlags as F;
    for (name, flag) in [("RIVER", F::RIVER), ("REFINED", F::REFINED), ("LAKE", F::LAKE)] {
        assert!(mesh_src.contains(&format!("const FLAG_{name}: u32 = {}u;", flag.0)), "FLAG_{name}");
    }
}

/// A planet whose parameters all differ from the defaults and from each other (the slopes
/// especially, which the default planet sets alike), on another radius: the device reads each
/// parameter where the CPU does.
#[test]
fn a_planet_with_other_parameters_adapts_alike() {
    let params = Params {
        radius_m: 3_000_000.0,
        base_faces: 3000,
        min_edge_length_m: 0.05,
        max_river_altitude_m: 9_000.0,
        max_mountain_altitude_m: 11_000.0,
        sea_level_m: 2_000.0,
        max_river_depth_m: 120.0,
        min_river_length_m: 90_000.0,
        min_river_slope_m_per_km: 2.5,
        min_riverbed_slope_m_per_km: 170.0,
        min_slope_near_river_m_per_km: 7.0,
        riverbed_edge_height_m: 4.0,
        max_ground_slope_m_per_km: 640.0,
        ..Params::paper()
    };
    params.validate().unwrap();
    let planet =
        build_planet(&PlanetSpec { seed: 11, params: params.clone(), map: None, precipitation: None }, &mut |_, _| {})
            .unwrap();
    let r = params.radius_m;
    let top = crate::adapt::terrain_top(&params, &planet.mesh);
    let mut cpu = Adapter::new(planet.mesh.clone(), params.clone());
    let mut dev = Adapter::new(planet.mesh.clone(), params.clone()).with_gpu(Some(gpu()));
    for (i, (lat, lon, height)) in [(10.0, 20.0, 3e6), (-30.0, 140.0, 2e4), (45.0, -60.0, 3e3)].into_iter().enumerate()
    {
        let dir = crate::geo::direction(lat, lon);
        let eye = dir * (r + params.sea_level_m + height);
        let cam = Camera::new(eye, dir * r + DVec3::Z * (height + 1e4), None, 50.0, 480, 270, 3.0, 15.0, r).unwrap();
        let v = View::new(&cam, r, params.min_edge_length_m, top);
        assert_eq!(state::edge_wants(cpu.mesh(), &v), edge_wants(&gpu(), cpu.mesh(), &v).unwrap(), "camera {i}");
        let (a, b) = (cpu.adapt(&cam, Some(80_000)), dev.adapt(&cam, Some(80_000)));
        assert!(dev.on_gpu(), "camera {i}: the GPU backend fell back to the CPU");
        assert_eq!((a.faces, a.splits, a.collapses), (b.faces, b.splits, b.collapses), "camera {i}");
        assert!(a.splits > 1000, "camera {i}: {a:?}");
        assert_same_mesh(cpu.mesh(), dev.mesh(), &format!("camera {i}"));
    }
}

/// The planet of the elevation map in the file at `path` (if it is there) with the default
/// parameters and `seed`, and an adapter on each backend.
fn from_map_file(path: &str, seed: u64) -> Option<(Planet, Params, Adapter, Adapter)> {
    let bytes = std::fs::read(path).ok()?;
    let limits = crate::maps::MapLimits::default();
    let map = crate::maps::Map::decode(&bytes, crate::maps::MapKind::Elevation, None, None, &limits).unwrap();
    let params = Params::default();
    let spec = PlanetSpec { seed, params: params.clone(), map: Some(Arc::new(map)), precipitation: None };
    let planet = build_planet(&spec, &mut |_, _| {}).unwrap();
    let cpu = Adapter::new(planet.mesh.clone(), params.clone());
    let dev = Adapter::new(planet.mesh.clone(), params.clone()).with_gpu(Some(gpu()));
    Some((planet, params, cpu, dev))
}

#[test]
fn a_planet_from_an_elevation_map_with_lakes_adapts_alike() {
    let Some((planet, params, mut cpu, mut dev)) = from_map_file("maps/earth_etopo5_1024x512.tif", 42) else { return };
    let guide = planet.mesh.guide.clone().expect("an elevation map guides the splits");
    let r = params.radius_m;
    // Over the Caspian (a terminal lake), the Great Lakes and the Himalaya (splits that take
    // the map's ground).
    // Over the Gulf of Mexico's shelf, sea splits below the map's pixel. Over the Gulf of
    // Genoa, a coast that follows the map below the base mesh's coast edges: sea splits above
    // sea level, land splits under the sea.
    let cameras = [(42.0, 50.5, 2e5), (45.0, -84.0, 3e4), (28.0, 86.0, 4e5), (28.5, -90.0, 3e4), (44.0, 9.0, 3e4)];
    for (i, (lat, lon, height)) in cameras.into_iter().enumerate() {
        let dir = crate::geo::direction(lat, lon);
        let north = (DVec3::Z - dir * dir.z).normalize();
        let target = (dir + north * 0.01).normalize() * r;
        let cam = Camera::new(dir * (r + height), target, None, 60.0, 640, 360, 3.0, 15.0, r).unwrap();
        let (a, b) = (cpu.adapt(&cam, Some(450_000)), dev.adapt(&cam, Some(450_000)));
        assert!(dev.on_gpu(), "camera {i}: the GPU backend fell back to the CPU");
        assert_eq!((a.faces, a.splits, a.collapses), (b.faces, b.splits, b.collapses), "camera {i}");
        let lake = crate::mesh::VertexFlags::LAKE;
        let refined_lake = cpu
            .mesh()
            .vertices
            .iter()
            .filter(|v| v.flags.contains(lake) && v.flags.contains(crate::mesh::VertexFlags::REFINED))
            .count();
        if i < 2 {
            assert!(refined_lake > 100, "camera {i}: {refined_lake} refined lake vertices");
        }
        // Refined dry vertices standing where the map puts them.
        let sea = params.sea_level_m;
        let mapped = cpu
            .mesh()
            .vertices
            .iter()
            .filter(|v| v.flags == crate::mesh::VertexFlags::REFINED | crate::mesh::VertexFlags::CONTINENT)
            .filter(|v| guide.at(v.p().normalize()).is_some_and(|m| (v.ground - sea - m).abs() < 1e-6))
            .count();
        assert!(mapped > 20, "camera {i}: {mapped} vertices on the map's ground");
        if i == 3 {
            let sea_floor = cpu
                .mesh()
                .vertices
                .iter()
                .filter(|v| v.flags == crate::mesh::VertexFlags::REFINED | crate::mesh::VertexFlags::SEA)
                .filter(|v| guide.at(v.p().normalize()).is_some_and(|m| (v.ground - sea - m).abs() > 1e-6))
                .count();
            assert!(sea_floor > 100, "camera {i}: {sea_floor} sea floor vertices below the map's pixel");
        }
        if i == 4 {
            let flags = |v: &crate::mesh::Vertex, kind: crate::mesh::VertexFlags| {
                v.flags == crate::mesh::VertexFlags::REFINED | kind
            };
            let vertices = &cpu.mesh().vertices;
            let dry_sea = vertices.iter().filter(|v| flags(v, crate::mesh::VertexFlags::SEA) && v.ground > sea).count();
            let flooded = vertices
                .iter()
                .filter(|v| flags(v, crate::mesh::VertexFlags::CONTINENT) && v.water == sea && v.ground < sea)
                .count();
            assert!(
                dry_sea > 20 && flooded > 20,
                "camera {i}: {dry_sea} dry sea splits, {flooded} flooded land splits"
            );
        }
        assert_same_mesh(cpu.mesh(), dev.mesh(), &format!("camera {i}"));
    }
}

/// The check `auto` makes of a real GPU before it adapts there: lavapipe rounds like the CPU,
/// so its canary meshes are the CPU's.
#[test]
fn the_device_reproduces_the_cpus_canary() {
    assert!(reproduces_cpu(&gpu()).unwrap());
}

/// A regional elevation map: splits inside it follow the map (its coast, in the shore outside
/// its bounds, too), splits beyond the data the guide holds take the rules without a map, and
/// both backends agree on all of them.
#[test]
fn a_regional_map_adapts_alike_at_its_edge() {
    let Some((planet, params, mut cpu, mut dev)) = from_map_file("maps/region_jacksboro_tn_403x344.tif", 5) else {
        return;
    };
    let guide = planet.mesh.guide.clone().expect("an elevation map guides the splits");
    let r = params.radius_m;
    // Inside the map near its eastern edge looking east across it, and beyond it looking back.
    for (i, (lat, lon, height, ahead)) in
        [(36.59, -84.13, 6e3, 0.01), (36.59, -84.03, 6e3, -0.01)].into_iter().enumerate()
    {
        let dir = crate::geo::direction(lat, lon);
        let east = DVec3::Z.cross(dir).normalize();
        let target = (dir + east * ahead).normalize() * r;
        let cam = Camera::new(dir * (r + height), target, None, 60.0, 320, 180, 3.0, 15.0, r).unwrap();
        // Room for the view without coarsening it (the backends count the splits of abandoned
        // trials apart).
        let budget = Some(planet.mesh.faces.len() + 40_000);
        let (a, b) = (cpu.adapt(&cam, budget), dev.adapt(&cam, budget));
        assert!(dev.on_gpu(), "camera {i}: the GPU backend fell back to the CPU");
        assert_eq!((a.faces, a.splits, a.collapses), (b.faces, b.splits, b.collapses), "camera {i}");
        let refined = cpu.mesh().vertices.iter().filter(|v| v.flags.contains(crate::mesh::VertexFlags::REFINED));
        let (on, off): (Vec<&crate::mesh::Vertex>, Vec<_>) =
            refined.partition(|v| guide.at(v.p().normalize()).is_some());
        assert!(
            on.len() > 100 && off.len() > 100,
            "camera {i}: {} splits on the map, {} off it ({a:?}, base {} faces)",
            on.len(),
            off.len(),
            planet.mesh.faces.len()
        );
        assert_same_mesh(cpu.mesh(), dev.mesh(), &format!("camera {i}"));
    }
}
