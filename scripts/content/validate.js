#!/usr/bin/env node
// Runs the Khronos glTF-Validator (npm package gltf-validator) on glTF files and prints one line per
// file: "<path> errors=E warnings=W infos=I hints=H", then every error and warning message.
// Exit status: 0 when every file has 0 errors and 0 warnings, 1 otherwise, 2 when the validator is
// not installed (scripts/deps installs it into build/tools/node_modules).
// Usage: node scripts/content/validate.js [--json] FILE...
'use strict';
const fs = require('fs');
const path = require('path');

function loadValidator() {
  const root = path.resolve(__dirname, '..', '..');
  const places = [process.env.GLTF_VALIDATOR_DIR, path.join(root, 'build', 'tools', 'node_modules', 'gltf-validator'),
                  'gltf-validator'].filter(Boolean);
  for (const p of places) {
    try { return require(p); } catch (e) { /* try the next place */ }
  }
  return null;
}

async function main() {
  const args = process.argv.slice(2);
  const json = args.includes('--json');
  const files = args.filter((a) => a !== '--json');
  const validator = loadValidator();
  if (!validator) {
    console.error('validate.js: gltf-validator is not installed (run scripts/deps: it installs it into build/tools)');
    process.exit(2);
  }
  let bad = 0;
  const reports = [];
  for (const f of files) {
    const bytes = new Uint8Array(fs.readFileSync(f));
    const report = await validator.validateBytes(bytes, {
      uri: path.basename(f),
      maxIssues: 0,
      externalResourceFunction: (uri) => new Promise((resolve, reject) => {
        fs.readFile(path.join(path.dirname(f), decodeURIComponent(uri)), (err, data) => err ? reject(err) : resolve(new Uint8Array(data)));
      }),
    });
    const i = report.issues;
    reports.push({file: f, validatorVersion: report.validatorVersion, issues: i});
    if (!json) {
      console.log(`${f} errors=${i.numErrors} warnings=${i.numWarnings} infos=${i.numInfos} hints=${i.numHints}`);
      for (const m of i.messages)
        if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} ${m.pointer || ''}: ${m.message}`);
    }
    if (i.numErrors > 0 || i.numWarnings > 0) bad++;
  }
  if (json) console.log(JSON.stringify(reports, null, 1));
  process.exit(bad ? 1 : 0);
}
main().catch((e) => { console.error('validate.js: ' + (e && e.stack || e)); process.exit(3); });
