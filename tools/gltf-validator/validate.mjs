// Validates glTF 2.0 files (.gltf, .glb) with the Khronos glTF Validator and prints one
// summary line per file ("FILE: 0 errors, 1 warnings, 0 infos, 0 hints") followed by
// every reported message. Exit status: 0 when no file has errors, 1 when one has, 2 when
// a file cannot be read or the validator fails. Run through scripts/gltf-validator,
// which installs the validator package next to this file first.
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import process from 'node:process';
import validator from 'gltf-validator';

const severityNames = ['error', 'warning', 'info', 'hint'];

// Resources referenced by URI are read relative to the validated file.
function resourceReader(file) {
  const folder = path.dirname(path.resolve(file));
  return async (uri) => new Uint8Array(await readFile(path.resolve(folder, decodeURIComponent(uri))));
}

async function validateFile(file) {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0, // report everything
    externalResourceFunction: resourceReader(file),
  });
  const issues = report.issues;
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos, ${issues.numHints} hints`);
  for (const message of issues.messages) {
    const where = message.pointer ? ` at ${message.pointer}` : '';
    console.log(`  ${severityNames[message.severity] ?? 'issue'} ${message.code}${where}: ${message.message}`);
  }
  return issues.numErrors;
}

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: scripts/gltf-validator FILE.gltf|FILE.glb ...');
  process.exit(2);
}
let failed = false;
for (const file of files) {
  try {
    if (await validateFile(file) > 0)
      failed = true;
  } catch (error) {
    console.error(`${file}: cannot validate: ${error?.message ?? error}`);
    process.exit(2);
  }
}
process.exit(failed ? 1 : 0);
