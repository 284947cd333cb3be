// Validates glTF files with the Khronos glTF-Validator (npm package gltf-validator) and prints
// one JSON report per file: {"file", "errors", "messages": [[code, severity, pointer, message]]}.
// Usage: node gltf_validate.mjs VALIDATOR_DIR FILE...
import { readFile } from "node:fs/promises";
import { createRequire } from "node:module";
import path from "node:path";

const [dir, ...files] = process.argv.slice(2);
const require = createRequire(path.join(path.resolve(dir), "noop.js"));
const validator = require("gltf-validator");
const out = [];
for (const file of files) {
  const data = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(data, { maxIssues: 200 });
  out.push({
    file,
    errors: report.issues.numErrors,
    messages: report.issues.messages.map((m) => [m.code, m.severity, m.pointer || "", m.message]),
  });
}
console.log(JSON.stringify(out));
