//! The `riverworld` command line.

use clap::{Parser, Subcommand};
mod cli;

use cli::files::{self, WriteError};
use riverworld::input::{self, InputError, MapSource};
use riverworld::maps::{GeoBounds, MapKind, MapLimits};
use riverworld::params::PlanetRequest;
use riverworld::server::defaults;
use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;

/// Largest face budget anywhere ([`riverworld::adapt::MAX_MESH_FACES`]).
const MAX_MESH_FACES: u64 = riverworld::adapt::MAX_MESH_FACES as u64;

/// [`riverworld::adapt::face_budget`], its refusal naming `--max-faces`.
fn budget(base: &riverworld::mesh::Mesh, asked: Option<usize>, default: usize) -> Result<usize, String> {
    riverworld::adapt::face_budget(base, asked, default).map_err(|e| format!("--max-faces: {e}"))
}

#[derive(Parser)]
#[command(
    name = "riverworld",
    version,
    about = "Procedural planets with realistic river networks (Derzapf et al. 2011)",
    after_help = "Exit status: 0 done; 2 input refused, named on stderr (flags, maps, cameras, \
                  budgets; nothing written); 1 a failure while running (writing the output, the \
                  GPU or graphics adapter, the network)."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// Options that define a planet, shared by the commands that build one.
#[derive(clap::Args, Clone, Debug)]
struct PlanetArgs {
    /// Planet seed (overrides the seed in --params).
    #[arg(long)]
    seed: Option<u64>,
    /// A map: 8-bit PNG continent bitmap (white = land), 8/16-bit PNG elevation (with
    /// --map-range) or GeoTIFF elevation in metres. Equirectangular, row 0 = north edge.
    #[arg(long)]
    map: Option<PathBuf>,
    /// How to read --map [default: elevation for GeoTIFF or when --map-range is given, else continents].
    #[arg(long, value_parser = parse_kind)]
    map_kind: Option<MapKind>,
    /// Metres of the darkest and brightest PNG elevation values, "MIN_M,MAX_M".
    #[arg(long, value_parser = parse_range, allow_hyphen_values = true)]
    map_range: Option<(f64, f64)>,
    /// Bounds of a regional PNG map in degrees, "WEST,SOUTH,EAST,NORTH" [default: the whole globe;
    /// GeoTIFFs carry their own]. Beyond a regional map the planet is sea (an elevation map gets a
    /// shore outside its bounds).
    #[arg(long, value_parser = parse_bounds, allow_hyphen_values = true)]
    map_bounds: Option<GeoBounds>,
    /// Mean annual precipitation in place of the climate model's (rivers' discharge, lakes,
    /// ground colours): single-band GeoTIFF in mm per year, or 8/16-bit PNG with
    /// --precipitation-range. Equirectangular, row 0 = north edge; nodata keeps the model's.
    #[arg(long)]
    precipitation: Option<PathBuf>,
    /// Millimetres per year of the darkest and brightest PNG precipitation values, "MIN_MM,MAX_MM".
    #[arg(long, value_parser = parse_range, allow_hyphen_values = true)]
    precipitation_range: Option<(f64, f64)>,
    /// Bounds of a regional PNG precipitation map, "WEST,SOUTH,EAST,NORTH" [default: the whole
    /// globe; GeoTIFFs carry their own]. Outside them the model's precipitation.
    #[arg(long, value_parser = parse_bounds, allow_hyphen_values = true)]
    precipitation_bounds: Option<GeoBounds>,
    /// JSON file {"seed": N, "params": {...}} with the planet parameters (paper Table 2).
    #[arg(long)]
    params: Option<PathBuf>,
    /// Faces of the base shape (overrides params.base_faces). A map adds detail inside its bounds,
    /// and the mountain vertices between rivers add more: stats.json gives the base mesh's faces.
    #[arg(long)]
    faces: Option<u32>,
}

#[derive(Subcommand)]
enum Command {
    /// Build a planet and write planet.glb, rivers.geojson, landmask.png, elevation.tif,
    /// preview.png and stats.json.
    Generate {
        #[command(flatten)]
        planet: PlanetArgs,
        /// Output directory.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Width of the equirectangular rasters (height is half).
        #[arg(long, default_value_t = 1024, value_parser = clap::value_parser!(u32).range(2..=16384))]
        raster_width: u32,
    },
    /// Adapt the planet to one or more cameras (visited in order) and write the last view as
    /// a .glb: terrain relative to a local origin (node translation) plus the water surface.
    View {
        #[command(flatten)]
        planet: PlanetArgs,
        /// Camera query: eye=X,Y,Z&target=X,Y,Z[&up=X,Y,Z][&fov=DEG][&width=PX][&height=PX]
        /// [&land_px=PX][&water_px=PX]; metres, planet-centred (+Z north, longitude 0 on +X).
        /// Defaults: up the local vertical, fov 60 (vertical), 1920x1080, land_px 8, water_px 40.
        /// Repeatable: the cameras are visited in order and the last one is written.
        #[arg(long = "camera", required = true, allow_hyphen_values = true)]
        cameras: Vec<String>,
        /// Face budget: coarser targets until the view fits (`lod_scale` in --stats says by how
        /// much). At least the base mesh's faces, the coarsest view of the planet; at most 2^30.
        /// [default: 20,000,000 (~1.5 GB of mesh, so that a mistaken camera such as land_px=0.5
        /// at the ground cannot fill the memory), or the base mesh's faces where more]
        #[arg(long, value_parser = clap::value_parser!(u64).range(1..=MAX_MESH_FACES))]
        max_faces: Option<u64>,
        /// Output file.
        #[arg(long, default_value = "view.glb")]
        out: PathBuf,
        /// Print adaption statistics as JSON.
        #[arg(long)]
        stats: bool,
        /// meshopt (quantized attributes, KHR_mesh_quantization, in EXT_meshopt_compression
        /// streams; about a quarter of the bytes) or none (f32 attributes, no extension).
        #[arg(long, default_value = "meshopt", value_parser = parse_compression)]
        compression: riverworld::export::glb::Compression,
        /// Where adaption runs: cpu (rayon), gpu (wgpu compute: every stage, the mesh kept on
        /// the device) or auto (the GPU when the adapter is a real GPU with f64 in shaders whose
        /// meshes are the CPU's bit for bit, checked on a small planet; else the CPU). The choice
        /// is printed on stderr.
        #[arg(long, default_value = "auto", value_parser = parse_backend)]
        backend: riverworld::adapt::gpu::Backend,
    },
    /// Adapt the planet to a camera and draw it with wgpu: climate-coloured terrain, water,
    /// sun light, haze and sky. The image size is the camera's width and height.
    Render {
        #[command(flatten)]
        planet: PlanetArgs,
        /// Camera query as for `view`, plus [&sun=X,Y,Z] (direction towards the sun, planet frame;
        /// default: over the viewer's shoulder).
        #[arg(long, allow_hyphen_values = true)]
        camera: String,
        /// Face budget of the adapted mesh; at least the base mesh's faces, at most 2^30
        /// [default: 1,000,000, or the base mesh's faces where more].
        #[arg(long, value_parser = clap::value_parser!(u64).range(1..=MAX_MESH_FACES))]
        max_faces: Option<u64>,
        /// Image format [default: from the --out extension, else png].
        #[arg(long, value_parser = parse_format)]
        format: Option<riverworld::render::ImageFormat>,
        /// Output file.
        #[arg(long, default_value = "render.png")]
        out: PathBuf,
        /// Where adaption runs: cpu, gpu or auto, as for `view`.
        #[arg(long, default_value = "auto", value_parser = parse_backend)]
        backend: riverworld::adapt::gpu::Backend,
    },
    /// Serve planets over HTTP (see openapi.yaml); without options, the built-in planet `earth`
    /// on 127.0.0.1:8080 with inputs stored under ./data.
    Serve(ServeArgs),
    /// Write the planet as a static tile set, the same bytes as `serve` answers: 3D Tiles 1.1
    /// (tileset.json, tiles/{key}.glb, tiles/{key}.json), Cesium quantized-mesh terrain
    /// (layer.json, {z}/{x}/{y}.terrain with normals, water mask and metadata), MapLibre
    /// elevation tiles (tilejson.json, {z}/{x}/{y}.png) or rivers and lakes as vector tiles
    /// (tilejson.json, {z}/{x}/{y}.mvt). The last level written has no children.
    Tiles {
        #[command(flatten)]
        planet: PlanetArgs,
        /// Output directory.
        #[arg(long, default_value = "tiles")]
        out: PathBuf,
        /// Levels to write. 3D Tiles: level 0 has 8 tiles; quantized-mesh: 2; terrarium, mapbox
        /// and mvt: 1; each further level four times as many.
        #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u8).range(1..=9))]
        levels: u8,
        /// 3dtiles, quantized-mesh, terrarium, mapbox (Terrain-RGB elevation tiles) or mvt.
        #[arg(long, default_value = "3dtiles", value_parser = ["3dtiles", "quantized-mesh", "terrarium", "mapbox", "mvt"])]
        format: String,
        /// 3D Tiles contents: meshopt (quantized, EXT_meshopt_compression) or none (f32, no
        /// extension; the server's `?compression=none`).
        #[arg(long, default_value = "meshopt", value_parser = parse_compression)]
        compression: riverworld::export::glb::Compression,
    },
    /// Write a DEM of a region as a Cloud-Optimized GeoTIFF (float32, EPSG:4326): band 1 the
    /// ground and band 2 the water surface (NaN where dry), metres relative to sea level, at
    /// the cell centres of the bbox grid, from the planet refined to the grid's resolution with
    /// the split rule of views and tiles. Prints the grid and timing as JSON.
    Dem {
        #[command(flatten)]
        planet: PlanetArgs,
        /// Region: W,S,E,N in degrees (inside -180..180, -90..90).
        #[arg(long, allow_hyphen_values = true)]
        bbox: String,
        /// Cells across (1..=8192).
        #[arg(long)]
        width: u32,
        /// Cells down (1..=8192) [default: square cells in degrees].
        #[arg(long)]
        height: Option<u32>,
        /// Output file.
        #[arg(long, default_value = "dem.tif")]
        out: PathBuf,
    },
    /// Time planet builds, view adaption and snapshots, and print Markdown tables.
    Bench {
        /// Directory with the Earth maps.
        #[arg(long, default_value = "maps")]
        maps: PathBuf,
        /// Runs per case (the median is reported).
        #[arg(long, default_value_t = 5)]
        runs: usize,
        /// Only the small cases.
        #[arg(long)]
        quick: bool,
        /// Print only these tables (repeatable) [default: all].
        #[arg(long, value_enum)]
        only: Vec<cli::bench::Table>,
    },
}

/// Options of `riverworld serve`.
#[derive(clap::Args, Clone, Debug)]
struct ServeArgs {
    /// Address to listen on.
    #[arg(long, default_value = defaults::ADDR)]
    addr: std::net::SocketAddr,
    /// Directory that stores the planets' inputs (request.json and map.bin per planet).
    #[arg(long, default_value = defaults::DATA_DIR)]
    data: PathBuf,
    /// Store URL instead of --data: file:///DIR, or s3://BUCKET/PREFIX in a build with
    /// `--features s3` (credentials and region from the AWS_* environment variables).
    #[arg(long)]
    store: Option<String>,
    /// Build jobs that may wait for a worker; more answer 429.
    #[arg(long, default_value_t = defaults::MAX_QUEUE)]
    max_queue: usize,
    /// Build worker threads.
    #[arg(long, default_value_t = defaults::WORKERS, value_parser = clap::value_parser!(u32).range(1..=256))]
    workers: u32,
    /// Builds of planets one client address may have queued or running; more answer 429
    /// client_queue_full (0: no limit).
    #[arg(long, default_value_t = defaults::MAX_BUILDS_PER_CLIENT)]
    max_builds_per_client: usize,
    /// Take the client's address for --max-builds-per-client from the last X-Forwarded-For
    /// entry: only behind a proxy that sets it (HAProxy `option forwardfor`).
    #[arg(long)]
    trust_forwarded_for: bool,
    /// In-memory cache of built planets and rendered files, MiB.
    #[arg(long, default_value_t = defaults::CACHE_MB)]
    cache_mb: usize,
    /// Largest request body (a map upload), MiB.
    #[arg(long, default_value_t = defaults::BODY_LIMIT_MB, value_parser = clap::value_parser!(u32).range(1..=4096))]
    body_limit_mb: u32,
    /// Allowed CORS origins: * or a comma-separated list.
    #[arg(long, default_value = defaults::CORS_ORIGIN)]
    cors_origin: String,
    /// Largest max_faces a view.glb request may ask for (at most 2^30).
    #[arg(long, default_value_t = defaults::MAX_FACES_CAP, value_parser = clap::value_parser!(u64).range(1..=MAX_MESH_FACES))]
    max_faces_cap: u64,
    /// Most faces the base mesh of a planet created by POST may have, estimated from its
    /// base_faces and its map's size before it is accepted (kept within --max-faces-cap).
    #[arg(long, default_value_t = riverworld::server::DEFAULT_MAX_PLANET_FACES as u64,
          value_parser = clap::value_parser!(u64).range(8..=MAX_MESH_FACES))]
    max_planet_faces: u64,
    /// Seconds before a request is answered 503 timeout.
    #[arg(long, default_value_t = defaults::TIMEOUT_S, value_parser = clap::value_parser!(u64).range(1..))]
    timeout_s: u64,
    /// Do not serve the built-in planet earth.
    #[arg(long)]
    no_default_planet: bool,
    /// Require `Authorization: Bearer TOKEN` on POST and DELETE (reads stay public). Also read
    /// from the environment variable RIVERWORLD_API_TOKEN, which is safer: command lines are
    /// visible to other local users. Without a token the server warns that it is open.
    #[arg(long, value_name = "TOKEN", hide_default_value = true)]
    api_token: Option<String>,
    /// Renders of uncached answers (views, rasters) running at once [default: one per CPU core,
    /// at least 2].
    #[arg(long, default_value_t = 0, hide_default_value = true)]
    render_permits: usize,
    /// Working memory, MiB, that the heavy work running at once (renders, map decodes, planet
    /// builds) may take together; each draws what its faces and pixels need before it starts
    /// (work above the whole budget runs alone).
    #[arg(long, default_value_t = riverworld::server::DEFAULT_RENDER_MEMORY_MIB,
          value_parser = clap::value_parser!(u32).range(1..))]
    render_memory_mb: u32,
    /// Renders that may wait for a permit; more answer 429 busy.
    #[arg(long, default_value_t = defaults::RENDER_QUEUE)]
    render_queue: usize,
    /// Widest raster (landmask.png, preview.png, elevation.tif) a request may ask for.
    #[arg(long, default_value_t = riverworld::server::resources::MAX_RASTER_WIDTH,
          value_parser = clap::value_parser!(u32).range(2..=16384))]
    max_raster_width: u32,
    /// Most pixels an uploaded map may declare, in units of 2^20 pixels (checked before decoding).
    #[arg(long, default_value_t = defaults::MAX_MAP_MPIXELS, value_parser = clap::value_parser!(u64).range(1..=1024))]
    max_map_mpixels: u64,
    /// Most pixels (width x height) a render.png or render.jpg may ask for.
    #[arg(long, default_value_t = riverworld::server::DEFAULT_MAX_RENDER_PIXELS,
          value_parser = clap::value_parser!(u64).range(1..=(8192 * 8192)))]
    max_render_pixels: u64,
    /// Most cells (width x height) a dem.tif may ask for.
    #[arg(long, default_value_t = riverworld::export::dem::DEFAULT_MAX_DEM_PIXELS,
          value_parser = clap::value_parser!(u64).range(1..=(8192 * 8192)))]
    max_dem_pixels: u64,
    /// Where adaption runs for views and snapshots: cpu (rayon), gpu (wgpu compute; refuses to
    /// start without a suitable adapter) or auto (the GPU when the adapter is a real GPU with
    /// f64 in shaders whose meshes are the CPU's bit for bit, checked on a small planet; else
    /// the CPU). The choice is logged at start.
    #[arg(long, default_value = "auto", value_parser = parse_backend)]
    backend: riverworld::adapt::gpu::Backend,
}

/// Why a command failed, and its exit code: 2 for input it refuses (flags, files, cameras,
/// budgets; nothing is written), 1 for a failure while running (writing the output, the GPU or
/// graphics adapter, the network).
#[derive(Debug)]
enum CliError {
    Input(String),
    Run(String),
}

impl CliError {
    fn code(&self) -> ExitCode {
        match self {
            CliError::Input(_) => ExitCode::from(2),
            CliError::Run(_) => ExitCode::FAILURE,
        }
    }
}

impl std::fmt::Display for CliError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CliError::Input(m) | CliError::Run(m) => f.write_str(m),
        }
    }
}

impl From<InputError> for CliError {
    fn from(e: InputError) -> Self {
        CliError::Input(e.to_string())
    }
}

impl From<WriteError> for CliError {
    fn from(e: WriteError) -> Self {
        CliError::Run(e.to_string())
    }
}

/// Bad input, named.
fn input(e: impl std::fmt::Display) -> CliError {
    CliError::Input(e.to_string())
}

/// A failure while running, named.
fn failed(e: impl std::fmt::Display) -> CliError {
    CliError::Run(e.to_string())
}

/// The adaption backend `--backend` asks for, or why it is not here (a failure of this machine,
/// with the way out).
fn select_backend(
    backend: riverworld::adapt::gpu::Backend,
) -> Result<(Option<std::sync::Arc<riverworld::adapt::gpu::GpuAdaption>>, String), CliError> {
    riverworld::adapt::gpu::select(backend)
        .map_err(|e| failed(format!("--backend gpu: {e}; --backend cpu (or auto) adapts on the CPU, the same bytes")))
}

/// The server's configuration from `serve`'s flags (and RIVERWORLD_API_TOKEN).
fn serve_config(args: &ServeArgs) -> Result<riverworld::server::Config, CliError> {
    use riverworld::server;
    Ok(server::Config {
        data_dir: args.data.clone(),
        store_url: args.store.clone(),
        max_queue: args.max_queue,
        workers: args.workers as usize,
        max_builds_per_client: args.max_builds_per_client,
        trust_forwarded_for: args.trust_forwarded_for,
        cache_bytes: args.cache_mb.saturating_mul(1 << 20),
        body_limit: args.body_limit_mb as usize * (1 << 20),
        cors_origin: args.cors_origin.clone(),
        max_faces_cap: args.max_faces_cap as usize,
        max_planet_faces: args.max_planet_faces as usize,
        request_timeout: std::time::Duration::from_secs(args.timeout_s),
        default_planet: !args.no_default_planet,
        build_delay: std::time::Duration::ZERO,
        api_token: match args.api_token.clone().or_else(|| std::env::var("RIVERWORLD_API_TOKEN").ok()) {
            Some(token) => Some(server::auth::ApiToken::new(&token).map_err(input)?),
            None => None,
        },
        render_permits: args.render_permits,
        render_memory_mib: args.render_memory_mb,
        render_queue: args.render_queue,
        max_raster_width: args.max_raster_width,
        max_map_pixels: args.max_map_mpixels << 20,
        max_render_pixels: args.max_render_pixels,
        max_dem_pixels: args.max_dem_pixels,
        render_delay: std::time::Duration::ZERO,
        adapt_backend: args.backend,
    })
}

fn run_serve(args: ServeArgs) -> Result<(), CliError> {
    use riverworld::server;
    tracing_subscriber::fmt()
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_default_env()
                .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new("info")),
        )
        .with_writer(std::io::stderr)
        .with_ansi(std::io::stderr().is_terminal())
        .init();
    let config = serve_config(&args)?;
    let runtime = tokio::runtime::Runtime::new().map_err(|e| failed(format!("cannot start the runtime: {e}")))?;
    runtime.block_on(async move {
        let listener = tokio::net::TcpListener::bind(args.addr)
            .await
            .map_err(|e| failed(format!("cannot listen on {}: {e}", args.addr)))?;
        let server = server::serve(config, listener).await.map_err(failed)?;
        eprintln!("riverworld: serving on http://{}", server.local_addr());
        let _ = tokio::signal::ctrl_c().await;
        eprintln!("riverworld: shutting down");
        server.shutdown().await.map_err(failed)
    })
}

fn parse_compression(s: &str) -> Result<riverworld::export::glb::Compression, String> {
    riverworld::export::glb::Compression::parse(s).ok_or_else(|| format!("{s:?}: expected meshopt or none"))
}

fn parse_backend(s: &str) -> Result<riverworld::adapt::gpu::Backend, String> {
    s.parse()
}

fn parse_format(s: &str) -> Result<riverworld::render::ImageFormat, String> {
    s.parse()
}
fn parse_kind(s: &str) -> Result<MapKind, String> {
    s.parse().map_err(|e: riverworld::maps::MapError| e.to_string())
}
fn parse_range(s: &str) -> Result<(f64, f64), String> {
    input::parse_range(s).map_err(|e| e.to_string())
}
fn parse_bounds(s: &str) -> Result<GeoBounds, String> {
    GeoBounds::parse(s).map_err(|e| e.to_string())
}

impl PlanetArgs {
    fn spec(&self) -> Result<riverworld::planet::PlanetSpec, InputError> {
        let mut req = match &self.params {
            Some(path) => input::load_request(path)?,
            None => PlanetRequest::default(),
        };
        if let Some(seed) = self.seed {
            req.seed = seed;
        }
        if let Some(faces) = self.faces {
            req.params.base_faces = faces;
        }
        req.params.validate()?;
        let map = match &self.map {
            Some(path) => {
                let src = MapSource {
                    path: path.clone(),
                    kind: self.map_kind,
                    range_m: self.map_range,
                    bounds: self.map_bounds,
                };
                Some(input::load_map(&src, &MapLimits::default())?)
            }
            None => None,
        };
        let precipitation = match &self.precipitation {
            Some(path) => {
                let src = MapSource {
                    path: path.clone(),
                    kind: None,
                    range_m: self.precipitation_range,
                    bounds: self.precipitation_bounds,
                };
                Some(input::load_precipitation(&src, &MapLimits::default())?)
            }
            None => None,
        };
        Ok(input::spec(req, map, precipitation))
    }
}

fn progress_bar() -> Option<indicatif::ProgressBar> {
    if !std::io::stderr().is_terminal() {
        return None;
    }
    let bar = indicatif::ProgressBar::new(1000);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{spinner} {msg:12} [{bar:40}] {percent:>3}% {elapsed}")
            .expect("valid template")
            .progress_chars("=> "),
    );
    Some(bar)
}

fn run_generate(planet: &PlanetArgs, out: &std::path::Path, raster_width: u32) -> Result<(), CliError> {
    let spec = planet.spec()?;
    let bar = progress_bar();
    let mut report = |stage: &str, f: f32| {
        if let Some(b) = &bar {
            b.set_message(stage.to_string());
            b.set_position((f * 1000.0) as u64);
        }
    };
    let built = riverworld::planet::build_planet(&spec, &mut report).map_err(input)?;
    report("writing", 0.95);
    let files = files::outputs(&built, &spec, raster_width).map_err(input)?;
    files::write_outputs(out, &files)?;
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    println!("{}", serde_json::to_string_pretty(&built.stats).expect("stats serialise"));
    Ok(())
}

fn run_view(
    planet: &PlanetArgs,
    cameras: &[String],
    max_faces: Option<usize>,
    out: &std::path::Path,
    stats: bool,
    compression: riverworld::export::glb::Compression,
    backend: riverworld::adapt::gpu::Backend,
) -> Result<(), CliError> {
    let file_name = out_file_name(out)?;
    let spec = planet.spec()?;
    let radius = spec.params.radius_m;
    let cams = cameras
        .iter()
        .map(|q| {
            let (cam, rest) = riverworld::adapt::Camera::parse_query(q, radius).map_err(input)?;
            refuse_other_keys(&rest).map(|()| cam)
        })
        .collect::<Result<Vec<_>, CliError>>()?;
    let built = riverworld::planet::build_planet(&spec, &mut |_, _| {}).map_err(input)?;
    let max_faces = budget(&built.mesh, max_faces, riverworld::adapt::VIEW_FACES).map_err(input)?;
    let (gpu, choice) = select_backend(backend)?;
    eprintln!("riverworld: {choice}");
    let on_gpu = gpu.is_some();
    let mut adapter = riverworld::adapt::Adapter::new(built.mesh, spec.params.clone()).with_gpu(gpu);
    let mut last = None;
    for cam in &cams {
        last = Some(adapter.adapt(cam, Some(max_faces)));
    }
    if on_gpu && !adapter.on_gpu() {
        eprintln!("riverworld: the GPU failed during adaption; it finished on the CPU");
    }
    let cam = cams.last().expect("at least one camera");
    let origin = riverworld::export::view::local_origin(cam.eye, radius);
    let glb = riverworld::export::view::view_glb(adapter.mesh(), &spec.params, cam, origin, compression)
        .map_err(|e| input(format!("--max-faces: {e}: ask for fewer faces")))?;
    files::write_outputs(out.parent().unwrap_or(std::path::Path::new(".")), &[(file_name, glb)])?;
    if stats {
        println!("{}", serde_json::to_string_pretty(&last).expect("stats serialise"));
    }
    Ok(())
}

/// Refuses the keys of a `--camera` query that the camera did not take: the budget is a flag
/// on the command line (`max_faces` joins the query only over HTTP), anything else unknown.
fn refuse_other_keys(rest: &[(String, String)]) -> Result<(), CliError> {
    match rest.first() {
        Some((k, _)) if k == "max_faces" => Err(input("max_faces is not a camera parameter here: use --max-faces")),
        Some((k, _)) => Err(input(format!("unknown camera parameter {k:?}"))),
        None => Ok(()),
    }
}

fn run_render(
    planet: &PlanetArgs,
    camera: &str,
    max_faces: Option<usize>,
    format: Option<riverworld::render::ImageFormat>,
    out: &std::path::Path,
    backend: riverworld::adapt::gpu::Backend,
) -> Result<(), CliError> {
    use riverworld::render::{self, ImageFormat, Shot};
    let file_name = out_file_name(out)?;
    let spec = planet.spec()?;
    let (shot, rest) = Shot::parse_query(camera, spec.params.radius_m).map_err(input)?;
    refuse_other_keys(&rest)?;
    let format = format.unwrap_or_else(|| match out.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("jpg") || e.eq_ignore_ascii_case("jpeg") => ImageFormat::Jpeg,
        _ => ImageFormat::Png,
    });
    let renderer = render::shared().map_err(failed)?;
    let built = riverworld::planet::build_planet(&spec, &mut |_, _| {}).map_err(input)?;
    let max_faces = budget(&built.mesh, max_faces, riverworld::adapt::RENDER_FACES).map_err(input)?;
    let (gpu, choice) = select_backend(backend)?;
    eprintln!("riverworld: {choice}");
    let pixels = render::snapshot(renderer, &built.mesh, &spec.params, &shot, max_faces, gpu).map_err(failed)?;
    let bytes = render::encode(&pixels, shot.camera.width, shot.camera.height, format);
    Ok(files::write_outputs(out.parent().unwrap_or(std::path::Path::new(".")), &[(file_name, bytes)])?)
}

/// The file name that `--out` ends in (refused where it names none: `..`, `/`).
fn out_file_name(out: &std::path::Path) -> Result<&str, CliError> {
    match out.file_name() {
        Some(n) => n.to_str().ok_or_else(|| input(format!("--out {}: the file name is not UTF-8", out.display()))),
        None => Err(input(format!("--out {}: names no file", out.display()))),
    }
}

fn run_tiles(
    planet: &PlanetArgs,
    out: &std::path::Path,
    levels: u8,
    format: &str,
    compression: riverworld::export::glb::Compression,
) -> Result<(), CliError> {
    use riverworld::export::{terrain_rgb::Encoding, tile_sets};
    let spec = planet.spec()?;
    let built = riverworld::planet::build_planet(&spec, &mut |_, _| {}).map_err(input)?;
    let tiles =
        riverworld::export::tiles::PlanetTiles::new(std::sync::Arc::new(built), spec.params.clone()).map_err(failed)?;
    let name = format!("seed {}", spec.seed);
    std::fs::create_dir_all(out).map_err(|e| failed(format!("cannot write to {}: {e}", out.display())))?;
    let stats = match format {
        "quantized-mesh" => tile_sets::write_quantized_mesh(&tiles, out, levels, &name),
        "terrarium" => tile_sets::write_terrarium(&tiles, out, levels, &name, Encoding::Terrarium),
        "mapbox" => tile_sets::write_terrarium(&tiles, out, levels, &name, Encoding::Mapbox),
        "mvt" => tile_sets::write_mvt(&tiles, out, levels, &name),
        _ => tiles.write_files(out, levels, compression),
    }
    .map_err(|e| failed(format!("cannot write to {}: {e}", out.display())))?;
    println!("{}", serde_json::to_string_pretty(&stats).expect("stats serialise"));
    Ok(())
}

/// `riverworld dem`.
fn run_dem(
    planet: &PlanetArgs,
    bbox: &str,
    width: u32,
    height: Option<u32>,
    out: &std::path::Path,
) -> Result<(), CliError> {
    use riverworld::export::dem::{dem_tiff, DemRequest, DEFAULT_MAX_DEM_PIXELS};
    let req = DemRequest::new(bbox, width, height, DEFAULT_MAX_DEM_PIXELS).map_err(|e| input(format!("--{e}")))?;
    let spec = planet.spec()?;
    let built = riverworld::planet::build_planet(&spec, &mut |_, _| {}).map_err(input)?;
    let tiles =
        riverworld::export::tiles::PlanetTiles::new(std::sync::Arc::new(built), spec.params.clone()).map_err(failed)?;
    // The tiling's face index is made once per planet (kept, like the planet and its tree, by
    // the server): timed apart from the DEM.
    let t0 = std::time::Instant::now();
    tiles.index_faces();
    let index_ms = t0.elapsed().as_secs_f64() * 1e3;
    let t0 = std::time::Instant::now();
    let dem = riverworld::export::dem::sample_dem(&tiles, &req);
    let sampled_ms = t0.elapsed().as_secs_f64() * 1e3;
    let bytes = dem_tiff(&dem);
    let total_ms = t0.elapsed().as_secs_f64() * 1e3;
    std::fs::write(out, &bytes).map_err(|e| failed(format!("cannot write {}: {e}", out.display())))?;
    let stats = serde_json::json!({
        "out": out.display().to_string(), "query": req.to_query(), "width": req.width, "height": req.height,
        "splits": dem.splits, "bytes": bytes.len(), "index_ms": index_ms.round(), "sample_ms": sampled_ms.round(), "total_ms": total_ms.round(),
    });
    println!("{}", serde_json::to_string_pretty(&stats).expect("stats serialise"));
    Ok(())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let done = match cli.command {
        Command::Generate { planet, out, raster_width } => run_generate(&planet, &out, raster_width),
        Command::Render { planet, camera, max_faces, format, out, backend } => {
            run_render(&planet, &camera, max_faces.map(|n| n as usize), format, &out, backend)
        }
        Command::View { planet, cameras, max_faces, out, stats, compression, backend } => {
            run_view(&planet, &cameras, max_faces.map(|n| n as usize), &out, stats, compression, backend)
        }
        Command::Tiles { planet, out, levels, format, compression } => {
            run_tiles(&planet, &out, levels, &format, compression)
        }
        Command::Dem { planet, bbox, width, height, out } => run_dem(&planet, &bbox, width, height, &out),
        Command::Serve(args) => run_serve(args),
        Command::Bench { maps, runs, quick, only } => {
            cli::bench::run(&maps, runs.max(1), quick, &only);
            Ok(())
        }
    };
    match done {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            e.code()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `serve` without options runs with `Config::default()`: the defaults are written once.
    #[test]
    fn serve_without_options_is_the_default_config() {
        let Command::Serve(args) = Cli::try_parse_from(["riverworld", "serve"]).unwrap().command else {
            panic!("serve parses as serve");
        };
        if std::env::var_os("RIVERWORLD_API_TOKEN").is_none() {
            let config = serve_config(&args).unwrap();
            assert_eq!(format!("{config:?}"), format!("{:?}", riverworld::server::Config::default()));
        }
        assert_eq!(args.addr.to_string(), defaults::ADDR);
    }

    /// The face budgets `--help` states are the ones `view` and `render` use.
    #[test]
    fn help_states_the_face_budget_defaults() {
        use clap::CommandFactory;
        let grouped = |n: usize| {
            let digits = n.to_string();
            let mut out = String::new();
            for (i, c) in digits.chars().enumerate() {
                if i > 0 && (digits.len() - i).is_multiple_of(3) {
                    out.push(',');
                }
                out.push(c);
            }
            out
        };
        let mut cli = Cli::command();
        for (name, faces) in [("view", riverworld::adapt::VIEW_FACES), ("render", riverworld::adapt::RENDER_FACES)] {
            let help = cli.find_subcommand_mut(name).unwrap().render_long_help().to_string();
            assert!(help.contains(&format!("[default: {}", grouped(faces))), "{name}: {help}");
        }
    }
}
