// Validates .glb files with the Khronos glTF-Validator; exits non-zero on any error.
import { readFileSync } from "node:fs";
import validator from "gltf-validator";

let failed = false;
for (const path of process.argv.slice(2)) {
  const report = await validator.validateBytes(new Uint8Array(readFileSync(path)));
  const { numErrors, numWarnings } = report.issues;
  console.log(`${path}: ${numErrors} errors, ${numWarnings} warnings`);
  if (numErrors > 0) {
    failed = true;
    for (const m of report.issues.messages.filter((m) => m.severity === 0).slice(0, 10)) {
      console.log(`  ${m.code}: ${m.message} (${m.pointer ?? ""})`);
    }
  }
}
process.exit(failed ? 1 : 0);
