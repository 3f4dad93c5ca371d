// Validate glTF 2.0 files (.glb or .gltf) with the Khronos glTF-Validator, all in one process.
//   node tools/js/validate_gltf.js FILE...
// Prints one JSON object: {"reports": [{"file", "errors", "warnings", "infos", "hints", "messages"}]}.
// External resources of a .gltf (buffers, images) are read relative to the file.
// Exit code: 0 when every file has no error and no warning, 1 otherwise, 2 on a usage error.
"use strict";

const fs = require("fs");
const path = require("path");
const validator = require("gltf-validator");

function readBeside(file) {
  return (uri) =>
    new Promise((resolve, reject) => {
      const target = path.resolve(path.dirname(file), decodeURIComponent(uri));
      fs.readFile(target, (error, data) => (error ? reject(error.toString()) : resolve(new Uint8Array(data))));
    });
}

async function validate(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0,
    externalResourceFunction: readBeside(file),
  });
  const issues = report.issues;
  return {
    file,
    errors: issues.numErrors,
    warnings: issues.numWarnings,
    infos: issues.numInfos,
    hints: issues.numHints,
    messages: issues.messages,
  };
}

async function main(files) {
  if (files.length === 0) {
    process.stderr.write("usage: node validate_gltf.js FILE...\n");
    return 2;
  }
  const reports = [];
  for (const file of files) {
    reports.push(await validate(file));
  }
  process.stdout.write(JSON.stringify({ validator: validator.version(), reports }) + "\n");
  return reports.every((r) => r.errors === 0 && r.warnings === 0) ? 0 : 1;
}

// exitCode, not exit(): a piped stdout is written asynchronously and exit() would cut it short
main(process.argv.slice(2)).then(
  (code) => {
    process.exitCode = code;
  },
  (error) => {
    process.stderr.write(String(error) + "\n");
    process.exitCode = 2;
  },
);
