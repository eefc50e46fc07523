// The riverworld web viewer: streams a planet's 3D Tiles (`/v1/planets/{id}/tileset.json`) with
// three.js and 3d-tiles-renderer, uploads maps as new planets and asks the server for a
// render.png of the current camera.
import {
  AmbientLight,
  Color,
  DirectionalLight,
  FrontSide,
  Matrix4,
  Mesh,
  PerspectiveCamera,
  Scene,
  ShaderMaterial,
  SphereGeometry,
  Vector3,
  WebGLRenderer,
} from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { MeshoptDecoder } from 'three/examples/jsm/libs/meshopt_decoder.module.js';
import { GlobeControls, TilesRenderer } from '3d-tiles-renderer/three';

const $ = (id) => document.getElementById(id);
const stats = { tilesLoaded: 0, tileRequests: 0, pending: 0, frames: 0, planet: null, errors: 0 };
window.viewerStats = stats;

const canvas = $('view');
// A logarithmic depth buffer: from 1 km to 100,000 km a linear one resolves only kilometres at
// planet distance, and the water surface, which on a coarse tile's river faces runs a few metres
// to kilometres under the ground, would show through the land.
const renderer = new WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true, logarithmicDepthBuffer: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
renderer.setClearColor(new Color(0x05070d));

const scene = new Scene();
const camera = new PerspectiveCamera(60, 1, 1000, 1e8);
scene.add(new AmbientLight(0xffffff, 0.6));
const sun = new DirectionalLight(0xffffff, 2.2);
sun.position.set(1, 1, 2);
camera.add(sun);
scene.add(camera);

// The atmosphere as render.png draws it (`shaders/render.wgsl`): a shell 60 km above the sea
// whose fragments add the sky's colour by the length of the view ray inside the air, 1 -
// exp(-path / 700 km) over the ground (haze) and 1 - exp(-path / 40 km) against space (the
// limb's glow), lit by the sun at the ray's point nearest the planet. Computed in the planet
// frame (the tiles group's), drawn after the tiles without a depth test: from outside, the
// shell's front lies before anything it covers.
const ATMOSPHERE_M = 60000;
const atmosphere = new ShaderMaterial({
  uniforms: {
    eye: { value: new Vector3() },
    sunDir: { value: new Vector3(0, 0, 1) },
    radii: { value: new Vector3(1, 1 + ATMOSPHERE_M, 0) },
  },
  vertexShader: `
    varying vec3 vLocal;
    void main() {
      vLocal = position;
      gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
    }`,
  fragmentShader: `
    uniform vec3 eye;
    uniform vec3 sunDir;
    uniform vec3 radii;
    varying vec3 vLocal;
    const vec3 SKY = vec3(0.32, 0.55, 0.95);
    void main() {
      vec3 dir = normalize(vLocal - eye);
      float b = dot(dir, -eye);
      float h = dot(eye, eye) - b * b;
      float ra = radii.y;
      float s = sqrt(max(ra * ra - h, 0.0));
      float t0 = max(b - s, 0.0);
      float t1 = b + s;
      float rg = radii.x;
      bool ground = rg * rg - h > 0.0 && b - sqrt(rg * rg - h) > 0.0;
      float tEnd = ground ? b - sqrt(rg * rg - h) : t1;
      float path = max(tEnd - t0, 0.0);
      float amount = 1.0 - exp(-path / (ground ? 700000.0 : 40000.0));
      vec3 closest = normalize(eye + dir * max(ground ? tEnd : b, 0.0));
      float daylight = smoothstep(-0.15, 0.25, dot(closest, sunDir));
      gl_FragColor = vec4(SKY * daylight, amount);
      #include <colorspace_fragment>
    }`,
  transparent: true,
  depthTest: false,
  depthWrite: false,
  side: FrontSide,
});
let shell = null;
const sunWorld = new Vector3();
const sunTarget = new Vector3();

const controls = new GlobeControls(scene, camera, canvas);
controls.enableDamping = true;

let tiles = null;
let planetId = null;

function status(text) {
  $('status').textContent = text;
}

function resize() {
  const w = canvas.clientWidth;
  const h = canvas.clientHeight;
  if (canvas.width !== Math.floor(w * renderer.getPixelRatio()) || canvas.height !== Math.floor(h * renderer.getPixelRatio())) {
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }
}

/// Streams the tileset of planet `id` (which must be ready).
function open(id) {
  if (tiles) {
    scene.remove(tiles.group);
    tiles.dispose();
  }
  planetId = id;
  stats.planet = id;
  stats.tilesLoaded = 0;
  stats.tileRequests = 0;
  tiles = new TilesRenderer(`/v1/planets/${id}/tileset.json`);
  // Tile contents are quantized (KHR_mesh_quantization) and meshopt-compressed
  // (EXT_meshopt_compression): their glTF loader gets three.js's meshopt decoder.
  const gltf = new GLTFLoader(tiles.manager);
  gltf.setMeshoptDecoder(MeshoptDecoder);
  tiles.manager.addHandler(/\.(gltf|glb)$/g, gltf);
  // The tileset's frame is the planet frame (planet-centred metres, +Z north); the scene keeps
  // it as its world frame, so camera positions read directly as planet coordinates.
  tiles.errorTarget = 6;
  tiles.setCamera(camera);
  tiles.setResolutionFromRenderer(camera, renderer);
  tiles.addEventListener('load-root-tileset', () => {
    const r = tiles.ellipsoid.radius.x;
    if (shell) shell.removeFromParent();
    atmosphere.uniforms.radii.value.set(r, r + ATMOSPHERE_M, 0);
    shell = new Mesh(new SphereGeometry(r + ATMOSPHERE_M, 128, 64), atmosphere);
    shell.renderOrder = 1;
    shell.frustumCulled = false;
    tiles.group.add(shell);
    camera.position.set(2.2 * r, 0.9 * r, 1.5 * r);
    camera.up.set(0, 0, 1);
    camera.lookAt(0, 0, 0);
    camera.updateMatrixWorld();
    controls.setEllipsoid(tiles.ellipsoid, tiles.group);
  });
  tiles.addEventListener('load-model', () => {
    stats.tilesLoaded++;
  });
  tiles.addEventListener('load-error', (e) => {
    stats.errors++;
    status(`tile load failed: ${e.error && e.error.message}`);
  });
  scene.add(tiles.group);
  history.replaceState(null, '', `/planets/${id}`);
  $('planet-id').textContent = id;
  $('render').disabled = false;
}

// Counts the tile contents asked for (the glb requests), for the page's own statistics.
const fetchOriginal = window.fetch.bind(window);
window.fetch = (input, init) => {
  const url = typeof input === 'string' ? input : input.url;
  if (url.includes('/tiles/') && url.endsWith('.glb')) stats.tileRequests++;
  return fetchOriginal(input, init);
};

function frame() {
  resize();
  controls.update();
  camera.updateMatrixWorld();
  if (tiles) {
    tiles.setResolutionFromRenderer(camera, renderer);
    tiles.update();
    // The atmosphere's eye and sun in the planet frame.
    const toPlanet = new Matrix4().copy(tiles.group.matrixWorld).invert();
    atmosphere.uniforms.eye.value.copy(camera.position).applyMatrix4(toPlanet);
    // Towards the sun: from the light's target to the light.
    sun.getWorldPosition(sunWorld);
    sun.target.getWorldPosition(sunTarget);
    atmosphere.uniforms.sunDir.value.copy(sunWorld.sub(sunTarget)).transformDirection(toPlanet);
    const t = tiles.stats;
    stats.pending = t.queued + t.downloading + t.parsing;
  }
  renderer.render(scene, camera);
  stats.frames++;
  requestAnimationFrame(frame);
}

async function json(res) {
  const body = await res.json().catch(() => ({}));
  if (!res.ok) {
    const err = body.error || {};
    throw new Error(`${res.status} ${err.code || ''}: ${err.message || res.statusText}`);
  }
  return body;
}

function showRecord(record) {
  $('record').textContent = JSON.stringify(record, null, 2);
}

/// Polls the planet's record until it is ready (or failed), then opens it.
async function waitAndOpen(id) {
  for (;;) {
    const record = await json(await fetch(`/v1/planets/${id}`));
    showRecord(record);
    if (record.status === 'ready') {
      status(`planet ${id} ready`);
      open(id);
      return;
    }
    if (record.status === 'failed') {
      status(`planet ${id} failed: ${record.error}`);
      return;
    }
    const pct = Math.round((record.progress || 0) * 100);
    status(`planet ${id}: ${record.status} ${pct}%`);
    $('progress').value = record.progress || 0;
    await new Promise((r) => setTimeout(r, 1000));
  }
}

async function upload(event) {
  event.preventDefault();
  const file = $('map').files[0];
  if (!file) {
    status('choose a map file first');
    return;
  }
  const form = new FormData();
  form.append('map', file);
  form.append('map_kind', $('map-kind').value);
  const headers = {};
  const token = $('token').value.trim();
  if (token) headers.Authorization = `Bearer ${token}`;
  status('uploading...');
  try {
    const record = await json(await fetch('/v1/planets', { method: 'POST', body: form, headers }));
    showRecord(record);
    await waitAndOpen(record.id);
  } catch (e) {
    status(`upload failed: ${e.message}`);
  }
}

/// The camera as a render query: planet-centred metres (+Z north), vertical fov in degrees.
function cameraQuery(maxWidth = 1280) {
  const toPlanet = new Matrix4().copy(tiles ? tiles.group.matrixWorld : new Matrix4()).invert();
  const eye = camera.position.clone().applyMatrix4(toPlanet);
  const forward = new Vector3(0, 0, -1).transformDirection(camera.matrixWorld).transformDirection(toPlanet);
  const up = new Vector3(0, 1, 0).transformDirection(camera.matrixWorld).transformDirection(toPlanet);
  const target = eye.clone().addScaledVector(forward, Math.max(eye.length(), 1));
  let width = Math.max(16, Math.round(canvas.clientWidth));
  let height = Math.max(16, Math.round(canvas.clientHeight));
  if (width > maxWidth) {
    height = Math.round((height * maxWidth) / width);
    width = maxWidth;
  }
  const v = (p) => [p.x, p.y, p.z].map((c) => +c.toFixed(3)).join(',');
  const u = (p) => [p.x, p.y, p.z].map((c) => +c.toFixed(6)).join(',');
  return `eye=${v(eye)}&target=${v(target)}&up=${u(up)}&fov=${+camera.fov.toFixed(4)}&width=${width}&height=${height}`;
}

async function renderSnapshot() {
  if (!planetId) return;
  const url = `/v1/planets/${planetId}/render.png?${cameraQuery()}`;
  $('render').disabled = true;
  status('rendering on the server...');
  try {
    const res = await fetch(url);
    if (!res.ok) await json(res);
    const blob = await res.blob();
    const img = $('snapshot');
    if (img.src.startsWith('blob:')) URL.revokeObjectURL(img.src);
    img.src = URL.createObjectURL(blob);
    $('snapshot-box').hidden = false;
    status('render ready');
  } catch (e) {
    status(`render failed: ${e.message}`);
  } finally {
    $('render').disabled = false;
  }
}

async function listPlanets() {
  try {
    const { planets } = await json(await fetch('/v1/planets'));
    const select = $('planets');
    select.replaceChildren();
    for (const p of planets) {
      const o = document.createElement('option');
      o.value = p.id;
      o.textContent = `${p.id} (${p.status})`;
      select.append(o);
    }
    if (planetId) select.value = planetId;
  } catch (e) {
    status(`cannot list planets: ${e.message}`);
  }
}

window.viewer = { cameraQuery, open, waitAndOpen, get tiles() { return tiles; } };

$('upload').addEventListener('submit', upload);
$('render').addEventListener('click', renderSnapshot);
$('open').addEventListener('click', () => {
  const id = $('planets').value;
  if (id) waitAndOpen(id).catch((e) => status(e.message));
});
$('refresh').addEventListener('click', listPlanets);
$('close-snapshot').addEventListener('click', () => {
  $('snapshot-box').hidden = true;
});

const fromPath = location.pathname.match(/^\/planets\/([^/]+)$/);
const first = fromPath ? decodeURIComponent(fromPath[1]) : 'earth';
waitAndOpen(first).catch((e) => status(e.message));
listPlanets();
requestAnimationFrame(frame);
