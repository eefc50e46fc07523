// The GIS clients against a real server, in headless Chromium (software WebGL): starts
// `riverworld serve` (the built-in planet `earth`) and a static server for the pinned client
// libraries, then
//  - MapLibre GL JS: a `raster-dem` source from dem/tilejson.json as 3D terrain and hillshade, and
//    the `rivers` and `lakes` layers of rivers/tilejson.json over it;
//  - CesiumJS: `CesiumTerrainProvider.fromUrl(terrain/layer.json)` asking for vertex normals and
//    the water mask;
//  - CesiumJS: `Cesium3DTileset.fromUrl(tileset.json)`, whose contents are quantized and
//    meshopt-compressed glTF, from a camera low enough for tiles of level 8 (quantized
//    positions).
// Each must request tiles of its kinds from the server, draw a canvas that is not blank, and log
// no errors; nothing may be fetched from outside the two local servers.
//
//   node .ci/clients/clients.mjs [path/to/riverworld] [--chromium /usr/bin/chromium] [--shots DIR]
import { spawn } from 'node:child_process';
import { createServer } from 'node:http';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const opt = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args.splice(i, 2)[1] : fallback;
};
const browserPath = opt('--chromium', process.env.CHROMIUM || '/usr/bin/chromium');
const shots = opt('--shots', null); // a folder for the two canvases as PNG
const binary = args[0] || 'target/debug/riverworld';
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const fail = (message) => {
  throw new Error(message);
};

async function waitFor(what, seconds, probe) {
  const end = Date.now() + seconds * 1000;
  for (;;) {
    const value = await probe();
    if (value) return value;
    if (Date.now() > end) fail(`timed out after ${seconds} s waiting for ${what}`);
    await sleep(250);
  }
}

const port = 18300 + Math.floor(Math.random() * 500);
const api = `http://127.0.0.1:${port}`;
const planet = `${api}/v1/planets/earth`;

// Options of both Cesium viewers: no widgets, no sky, a canvas that can be read back.
const cesiumQuiet = `geocoder: false, animation: false, timeline: false, homeButton: false,
  sceneModePicker: false, navigationHelpButton: false, fullscreenButton: false, infoBox: false,
  selectionIndicator: false, skyBox: false, skyAtmosphere: false, requestRenderMode: false,
  contextOptions: { webgl: { preserveDrawingBuffer: true } }`;

// The start of both Cesium pages: the library, a 800 x 600 container, an error list.
const cesiumHead = `<!doctype html><html><head><meta charset="utf-8">
<script>window.CESIUM_BASE_URL = '/node_modules/cesium/Build/Cesium/';</script>
<link rel="stylesheet" href="/node_modules/cesium/Build/Cesium/Widgets/widgets.css">
<style>html,body,#c{margin:0;width:800px;height:600px}</style></head><body><div id="c"></div>
<script src="/node_modules/cesium/Build/Cesium/Cesium.js"></script><script>
window.errors = [];
`;

const pages = {
  '/maplibre.html': `<!doctype html><html><head><meta charset="utf-8">
<link rel="stylesheet" href="/node_modules/maplibre-gl/dist/maplibre-gl.css">
<style>html,body,#map{margin:0;width:800px;height:600px}</style></head><body><div id="map"></div>
<script src="/node_modules/maplibre-gl/dist/maplibre-gl.js"></script><script>
window.errors = [];
const map = new maplibregl.Map({
  container: 'map', center: [86.9, 27.9], zoom: 6, pitch: 60, bearing: 20,
  canvasContextAttributes: { preserveDrawingBuffer: true }, attributionControl: false,
  style: { version: 8,
    sources: {
      dem: { type: 'raster-dem', url: '${planet}/dem/tilejson.json' },
      rivers: { type: 'vector', url: '${planet}/rivers/tilejson.json' } },
    layers: [
      { id: 'bg', type: 'background', paint: { 'background-color': '#d8d0b8' } },
      { id: 'hills', type: 'hillshade', source: 'dem' },
      { id: 'lakes', type: 'fill', source: 'rivers', 'source-layer': 'lakes', paint: { 'fill-color': '#2a6fdb' } },
      { id: 'rivers', type: 'line', source: 'rivers', 'source-layer': 'rivers',
        paint: { 'line-color': '#2a6fdb', 'line-width': 2 } } ],
    terrain: { source: 'dem', exaggeration: 1.5 } } });
map.on('error', (e) => window.errors.push(String(e.error && e.error.message || e)));
map.on('idle', () => { window.idle = true; });
</script></body></html>`,
  '/cesium.html': `${cesiumHead}(async () => {
  try {
    const terrainProvider = await Cesium.CesiumTerrainProvider.fromUrl('${planet}/terrain',
      { requestVertexNormals: true, requestWaterMask: true });
    terrainProvider.errorEvent.addEventListener((e) => window.errors.push('terrain: ' + e.message));
    const viewer = new Cesium.Viewer('c', { terrainProvider, baseLayer: false, baseLayerPicker: false,
      ${cesiumQuiet} });
    viewer.scene.globe.baseColor = Cesium.Color.fromCssColorString('#b8a888');
    // Morning over the Himalaya (the sun 24° high in the east), so that the normals' shading shows
    // the relief: a midday sun lights the slopes almost alike.
    viewer.clock.shouldAnimate = false;
    viewer.clock.currentTime = Cesium.JulianDate.fromIso8601('2026-03-20T02:00:00Z');
    viewer.scene.globe.enableLighting = true;
    viewer.scene.globe.showWaterEffect = true;
    viewer.camera.setView({ destination: Cesium.Cartesian3.fromDegrees(86.9, 25.5, 250000),
      orientation: { heading: 0, pitch: Cesium.Math.toRadians(-30), roll: 0 } });
    window.viewer = viewer;
    window.hasNormals = () => terrainProvider.hasVertexNormals;
    window.hasWaterMask = () => terrainProvider.hasWaterMask;
  } catch (e) {
    window.errors.push(String(e && e.message || e));
  }
})();
</script></body></html>`,
  '/tiles3d.html': `${cesiumHead}window.loads = 0;
(async () => {
  try {
    const viewer = new Cesium.Viewer('c', { globe: false, baseLayer: false, baseLayerPicker: false,
      ${cesiumQuiet} });
    viewer.clock.shouldAnimate = false;
    viewer.clock.currentTime = Cesium.JulianDate.fromIso8601('2026-03-20T06:00:00Z');
    const tileset = await Cesium.Cesium3DTileset.fromUrl('${planet}/tileset.json');
    tileset.tileFailed.addEventListener((e) => window.errors.push('tile: ' + e.url + ': ' + e.message));
    tileset.tileLoad.addEventListener(() => { window.loads += 1; });
    viewer.scene.primitives.add(tileset);
    // 20 km over the Ligurian coast at Genoa, looking south-east along it over the sea and the
    // Apennines to the horizon: level 8 and finer near the camera.
    viewer.camera.setView({ destination: Cesium.Cartesian3.fromDegrees(8.6, 44.6, 20000),
      orientation: { heading: Cesium.Math.toRadians(120), pitch: Cesium.Math.toRadians(-20), roll: 0 } });
    window.viewer = viewer;
    window.tileset = tileset;
  } catch (e) {
    window.errors.push(String(e && e.message || e));
  }
})();
</script></body></html>`,
};

const types = { '.js': 'text/javascript', '.css': 'text/css', '.json': 'application/json', '.wasm': 'application/wasm',
  '.png': 'image/png', '.jpg': 'image/jpeg', '.svg': 'image/svg+xml', '.glsl': 'text/plain', '.xml': 'text/xml' };
const files = createServer((req, res) => {
  const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
  if (path === '/favicon.ico') {
    res.writeHead(204);
    return res.end();
  }
  if (pages[path]) {
    res.writeHead(200, { 'content-type': 'text/html' });
    return res.end(pages[path]);
  }
  const file = normalize(join(here, path));
  if (!file.startsWith(join(here, 'node_modules'))) {
    res.writeHead(404);
    return res.end();
  }
  try {
    const body = readFileSync(file);
    res.writeHead(200, { 'content-type': types[extname(file)] || 'application/octet-stream' });
    res.end(body);
  } catch {
    res.writeHead(404);
    res.end();
  }
});
await new Promise((r) => files.listen(0, '127.0.0.1', r));
const site = `http://127.0.0.1:${files.address().port}`;

const data = mkdtempSync(join(tmpdir(), 'riverworld-clients-'));
const server = spawn(binary, ['serve', '--addr', `127.0.0.1:${port}`, '--data', data], {
  env: { ...process.env, RUST_LOG: 'warn' }, stdio: ['ignore', 'pipe', 'pipe'] });
let log = '';
server.stdout.on('data', (d) => (log += d));
server.stderr.on('data', (d) => (log += d));
let exited = null;
server.on('exit', (code, signal) => (exited = `${code ?? signal}`));

const started = Date.now();
const seconds = () => ((Date.now() - started) / 1000).toFixed(1);
let browser;
try {
  await waitFor('/readyz', 300, async () => {
    if (exited !== null) fail(`server exited (${exited}):\n${log}`);
    try {
      return (await fetch(`${api}/readyz`)).status === 200;
    } catch {
      return false;
    }
  });
  console.log(`server ready after ${seconds()} s`);
  browser = await chromium.launch({ executablePath: browserPath, headless: true,
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist', '--no-sandbox'] });

  // One page: its problems, the server's answers by route kind, and the canvas's spread.
  async function open(name, kinds) {
    const page = await browser.newPage({ viewport: { width: 800, height: 600 } });
    const problems = [];
    const seen = Object.fromEntries(kinds.map((k) => [k, 0]));
    page.on('console', (m) => m.type() === 'error' && problems.push(`console error: ${m.text()}`));
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
    page.on('request', (r) => {
      const u = r.url();
      if (!u.startsWith(api) && !u.startsWith(site) && !/^(blob|data):/.test(u)) problems.push(`outside request: ${u}`);
    });
    page.on('response', (r) => {
      if (r.status() >= 400) problems.push(`${r.status()} for ${r.url()}`);
      if (!r.url().startsWith(api)) return;
      for (const k of kinds) if (r.url().includes(k) && r.status() === 200) seen[k] += 1;
    });
    await page.goto(`${site}/${name}.html`);
    const check = async () => {
      if (!problems.length) return;
      await sleep(1000); // let the events that explain the first problem arrive
      fail(`${name}: ${problems.join('\n')}`);
    };
    const spread = () =>
      page.evaluate(() => {
        const gl = document.querySelector('canvas');
        const c = document.createElement('canvas');
        c.width = gl.width;
        c.height = gl.height;
        const ctx = c.getContext('2d');
        ctx.drawImage(gl, 0, 0);
        const px = ctx.getImageData(0, 0, c.width, c.height).data;
        const colours = new Set();
        let sum = 0;
        for (let i = 0; i < px.length; i += 4 * 97) {
          colours.add((px[i] >> 3) * 1024 + (px[i + 1] >> 3) * 32 + (px[i + 2] >> 3));
          sum += px[i] + px[i + 1] + px[i + 2];
        }
        return { colours: colours.size, mean: sum / (3 * (px.length / (4 * 97))) };
      });
    return { page, problems, seen, check, spread };
  }

  // MapLibre GL JS: terrain, hillshade and the rivers over it.
  const ml = await open('maplibre', ['/dem/tilejson.json', '/rivers/tilejson.json', '.png', '.mvt']);
  await waitFor('MapLibre to request its tiles and settle', 240, async () => {
    await ml.check();
    const errors = await ml.page.evaluate(() => window.errors);
    if (errors.length) fail(`maplibre: ${errors.join('\n')}`);
    return ml.seen['.png'] > 0 && ml.seen['.mvt'] > 0 && (await ml.page.evaluate(() => window.idle === true));
  });
  const mlSpread = await ml.spread();
  if (shots) await ml.page.screenshot({ path: join(shots, 'maplibre.png') });
  await ml.check();
  if (mlSpread.colours < 20) fail(`maplibre: the canvas is nearly blank ${JSON.stringify(mlSpread)}`);
  console.log(`maplibre after ${seconds()} s: ${JSON.stringify(ml.seen)}, canvas ${JSON.stringify(mlSpread)}`);
  await ml.page.close();

  // CesiumJS: quantized-mesh terrain with normals and the water mask.
  const cs = await open('cesium', ['/terrain/layer.json', '.terrain']);
  await waitFor('Cesium to request terrain tiles and load them', 300, async () => {
    await cs.check();
    const state = await cs.page.evaluate(() => ({
      errors: window.errors,
      loaded: !!window.viewer && window.viewer.scene.globe.tilesLoaded,
    }));
    if (state.errors.length) fail(`cesium: ${state.errors.join('\n')}`);
    return cs.seen['.terrain'] >= 4 && state.loaded;
  });
  const ext = await cs.page.evaluate(() => [window.hasNormals(), window.hasWaterMask()]);
  if (!ext[0] || !ext[1]) fail(`cesium: normals ${ext[0]}, water mask ${ext[1]}`);
  const csSpread = await cs.spread();
  if (shots) await cs.page.screenshot({ path: join(shots, 'cesium.png') });
  await cs.check();
  if (csSpread.colours < 20) fail(`cesium: the canvas is nearly blank ${JSON.stringify(csSpread)}`);
  console.log(`cesium after ${seconds()} s: ${JSON.stringify(cs.seen)}, canvas ${JSON.stringify(csSpread)}`);
  await cs.page.close();

  // CesiumJS: the 3D Tiles, down to tiles whose positions are quantized.
  const t3 = await open('tiles3d', ['/tileset.json', '.glb']);
  let deepest = 0;
  t3.page.on('response', (r) => {
    const m = /\/tiles\/([0-7][0-3]*)\.glb$/.exec(new URL(r.url()).pathname);
    if (m && r.status() === 200) deepest = Math.max(deepest, m[1].length - 1);
  });
  await waitFor('Cesium to load 3D Tiles down to level 8', 300, async () => {
    await t3.check();
    const state = await t3.page.evaluate(() => ({
      errors: window.errors,
      loaded: !!window.tileset && window.tileset.tilesLoaded,
    }));
    if (state.errors.length) fail(`cesium 3D Tiles: ${state.errors.join('\n')}`);
    return deepest >= 8 && state.loaded;
  });
  const loads = await t3.page.evaluate(() => window.loads);
  const t3Spread = await t3.spread();
  if (shots) await t3.page.screenshot({ path: join(shots, 'cesium-3dtiles.png') });
  await t3.check();
  if (loads < t3.seen['.glb']) fail(`cesium 3D Tiles: ${t3.seen['.glb']} contents fetched, ${loads} loaded`);
  if (t3Spread.colours < 20) fail(`cesium 3D Tiles: the canvas is nearly blank ${JSON.stringify(t3Spread)}`);
  console.log(`cesium 3D Tiles after ${seconds()} s: ${JSON.stringify(t3.seen)}, deepest level ${deepest}, ` +
    `canvas ${JSON.stringify(t3Spread)}`);
  console.log(`GIS clients passed in ${seconds()} s`);
} finally {
  if (browser) await browser.close();
  server.kill('SIGTERM');
  files.close();
  rmSync(data, { recursive: true, force: true });
}
