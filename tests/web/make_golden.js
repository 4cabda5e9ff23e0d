#!/usr/bin/env node
'use strict';
// Records the CLI's outputs that the browser page's self-test must reproduce
// (tests/web/golden/scripts.json): for every shipped motion script, the level of every
// frame of `oflab-cli animate --script NAME` (the default policy and settings; frames.csv's
// "level" column) and the planar coefficients of its frame 0 from `oflab-cli flow` with the
// script's camera, plane and first segment. Run after a change of behaviour on purpose:
//   node tests/web/make_golden.js build/analysis/oflab-cli
// With --check it writes nothing and fails (exit 1) when the CLI's outputs today differ from
// the recorded file, so the page's test always compares with what the CLI prints:
//   node tests/web/make_golden.js --check build/analysis/oflab-cli
const { execFileSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const root = path.resolve(__dirname, '..', '..');
const checkOnly = process.argv.includes('--check');
const cliArg = process.argv.slice(2).find((a) => a !== '--check');
const cli = path.resolve(cliArg || path.join(root, 'build/analysis/oflab-cli'));
const scriptsDir = path.join(root, 'datasets/scripts');
const out = path.join(__dirname, 'golden/scripts.json');

function levelsOf(name) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'oflab-web-golden-'));
  try {
    execFileSync(cli, ['animate', '--script', name, '--out', path.join(dir, 'run'), '--quiet',
      '--no-warm-up', '--repeat-timing', '1']);
    const rows = fs.readFileSync(path.join(dir, 'run/frames.csv'), 'utf8').trim().split('\n');
    const column = rows[0].split(',').indexOf('level');
    return rows.slice(1).map((row) => row.split(',')[column]);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

function coefficientsOf(file) {
  const s = JSON.parse(fs.readFileSync(file, 'utf8'));
  if (!s.plane || !s.segments) throw new Error(`${file}: the generator reads plane + segments scripts only`);
  const v = (a) => a.map(String);
  const args = ['flow', '--focal', String(s.camera.focal_px), '--image', ...v(s.camera.image),
    '--plane-point', ...v(s.plane.point), '--plane-normal', ...v(s.plane.normal),
    '--plane-up', ...v(s.plane.up), '--plane-size', ...v(s.plane.size),
    '--velocity', ...v(s.segments[0].velocity), '--omega', ...v(s.segments[0].omega),
    '--motion', s.motion_model || 'screw', '--json'];
  return JSON.parse(execFileSync(cli, args, { encoding: 'utf8' })).coefficients;
}

const golden = {};
for (const file of fs.readdirSync(scriptsDir).filter((f) => f.endsWith('.json')).sort()) {
  const name = path.basename(file, '.json');
  golden[name] = { levels: levelsOf(name), coefficients: coefficientsOf(path.join(scriptsDir, file)) };
}
const text = `${JSON.stringify(golden, null, 1)}\n`;
if (checkOnly) {
  const same = fs.existsSync(out) && fs.readFileSync(out, 'utf8') === text;
  console.log(`${same ? 'ok  ' : 'FAIL'} GoldenOutputsAreTheCliOutputsToday: ${out}`);
  process.exit(same ? 0 : 1);
}
fs.writeFileSync(`${out}.tmp`, text);
fs.renameSync(`${out}.tmp`, out);
console.log(`wrote ${out}: ${Object.keys(golden).length} scripts`);
