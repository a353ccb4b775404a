// The Khronos glTF-Validator on each file named: prints one JSON line per
// file ({"file", "numErrors", "numWarnings", "numInfos", "numHints", "messages"})
// and exits 1 if any file has an error or a warning.  A .gltf's buffers are
// read from beside it.  Used by tests/model/test_gltf_validator.py.
"use strict";
const fs = require("fs");
const path = require("path");
const validator = require("gltf-validator");

async function check(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0,
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (err, data) =>
          err ? reject(err.toString()) : resolve(new Uint8Array(data)),
        );
      }),
  });
  const issues = report.issues;
  console.log(JSON.stringify({ file, ...issues, validatorVersion: report.validatorVersion }));
  return issues.numErrors + issues.numWarnings;
}

(async () => {
  let bad = 0;
  for (const file of process.argv.slice(2)) bad += await check(file);
  process.exit(bad ? 1 : 0);
})().catch((err) => {
  console.error(String(err));
  process.exit(2);
});
