// Validates .glb files with the Khronos glTF-Validator; exits non-zero on any error.
//
// The validator reads KHR_mesh_quantization but not EXT_meshopt_compression: a file whose views
// are meshopt streams is validated as it is (its JSON), then once more with every stream
// decoded by meshoptimizer's reference decoder (a plain-JavaScript implementation written from
// the format's description, independent of the library the server encodes with) into the
// views' own layout, the extension removed, so that the accessors' data is checked too
// (bounds, index ranges, normalized normals).
import { readFileSync } from "node:fs";
import validator from "gltf-validator";

// The package does not export the reference decoder: import its file.
const { MeshoptDecoder } = await import(
  new URL("./node_modules/meshoptimizer/meshopt_decoder_reference.js", import.meta.url).href
);

const MESHOPT = "EXT_meshopt_compression";

function chunks(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength)));
  const at = 20 + jsonLength;
  const bin = at < bytes.length ? bytes.subarray(at + 8, at + 8 + view.getUint32(at, true)) : new Uint8Array();
  return { json, bin };
}

function glb(json, bin) {
  const pad = (n) => (4 - (n % 4)) % 4;
  let text = new TextEncoder().encode(JSON.stringify(json));
  text = Uint8Array.from([...text, ...new Array(pad(text.length)).fill(0x20)]);
  const total = 12 + 8 + text.length + 8 + bin.length + pad(bin.length);
  const out = new Uint8Array(total);
  const view = new DataView(out.buffer);
  out.set(new TextEncoder().encode("glTF"), 0);
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, text.length, true);
  out.set(new TextEncoder().encode("JSON"), 16);
  out.set(text, 20);
  const at = 20 + text.length;
  view.setUint32(at, bin.length + pad(bin.length), true);
  out.set(new TextEncoder().encode("BIN\0"), at + 4);
  out.set(bin, at + 8);
  return out;
}

// The file with its meshopt streams decoded into the fallback buffer, which becomes the only one.
function decoded(bytes) {
  const { json, bin } = chunks(bytes);
  const fallback = json.buffers.findIndex((b) => b.extensions?.[MESHOPT]?.fallback);
  if (fallback < 0) throw new Error("no fallback buffer");
  const plain = new Uint8Array(json.buffers[fallback].byteLength);
  for (const view of json.bufferViews) {
    const ext = view.extensions[MESHOPT];
    if (view.buffer !== fallback || ext.buffer === fallback) throw new Error("a view outside the fallback buffer");
    const source = bin.subarray(ext.byteOffset ?? 0, (ext.byteOffset ?? 0) + ext.byteLength);
    const target = new Uint8Array(ext.count * ext.byteStride);
    MeshoptDecoder.decodeGltfBuffer(target, ext.count, ext.byteStride, source, ext.mode, ext.filter);
    if (target.length !== view.byteLength) throw new Error("a stream decodes to another length");
    plain.set(target, view.byteOffset ?? 0);
    delete view.extensions;
    view.buffer = 0;
  }
  json.buffers = [{ byteLength: plain.length }];
  json.extensionsUsed = json.extensionsUsed.filter((e) => e !== MESHOPT);
  json.extensionsRequired = json.extensionsRequired.filter((e) => e !== MESHOPT);
  for (const key of ["extensionsUsed", "extensionsRequired"]) if (!json[key].length) delete json[key];
  return glb(json, plain);
}

async function check(name, bytes) {
  const report = await validator.validateBytes(bytes);
  const { numErrors, numWarnings } = report.issues;
  console.log(`${name}: ${numErrors} errors, ${numWarnings} warnings`);
  for (const m of report.issues.messages.filter((m) => m.severity === 0).slice(0, 10)) {
    console.log(`  ${m.code}: ${m.message} (${m.pointer ?? ""})`);
  }
  return numErrors === 0;
}

let failed = false;
for (const path of process.argv.slice(2)) {
  const bytes = new Uint8Array(readFileSync(path));
  failed |= !(await check(path, bytes));
  if (chunks(bytes).json.extensionsUsed?.includes(MESHOPT)) {
    failed |= !(await check(`${path} (meshopt streams decoded)`, decoded(bytes)));
  }
}
process.exit(failed ? 1 : 0);
