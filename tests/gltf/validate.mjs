// Runs Khronos's glTF-Validator (npm gltf-validator) over each file named on the command line:
// node validate.mjs NODE_MODULES FILE... Prints every message of every file (code, severity,
// pointer, text) and a summary line per file; exit 1 when any file has an error or a warning
// (infos and hints are printed, not counted), 0 otherwise. Sidecar files (.bin, images) of a
// .gltf are read from beside it, as a loader would.
import { readFile } from 'node:fs/promises';
import { createRequire } from 'node:module';
import path from 'node:path';

const [modules, ...files] = process.argv.slice(2);
const validator = createRequire(path.join(modules, 'x.js'))('gltf-validator');
const severities = ['error', 'warning', 'info', 'hint'];
let failed = false;
for (const file of files) {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0,  // all of them
    externalResourceFunction: (uri) =>
      readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
  });
  const issues = report.issues;
  for (const m of issues.messages)
    console.log(`${file}: ${severities[m.severity]} ${m.code} ${m.pointer ?? (m.offset !== undefined ? 'offset ' + m.offset : '')}: ${m.message}`);
  const info = report.info ?? {};
  console.log(`${file}: glTF-Validator ${report.validatorVersion}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos, ${issues.numHints} hints (${info.drawCallCount ?? '?'} draw calls, ` +
              `${info.totalTriangleCount ?? '?'} triangles, ${(info.resources ?? []).length} resources, ` +
              `generator ${info.generator ?? '?'})`);
  if (issues.numErrors > 0 || issues.numWarnings > 0) failed = true;
}
process.exit(failed ? 1 : 0);
