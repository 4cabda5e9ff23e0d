'use strict';
// The page's per-frame CSV (manual/web.md, "Keep and share"), run by web_test.js with its
// browser and helpers ({ browser, open, evaluate, check, drawnMarker, cli }).
//
// The CSV the page's *CSV* control downloads is the teaching layer's per-frame CSV of the
// source played (RunPlayer::write_csv, as the desktop's export): for a motion script, the
// columns and rows of `oflab-cli animate --script NAME`'s frames.csv, equal in every column but
// the wall times. Negative control: another script's CSV differs. A source that cannot be
// played gives a message, not a file.
const fs = require('fs');
const os = require('os');
const path = require('path');
const { spawnSync } = require('child_process');

// The wall-time columns: measured, so they differ between any two runs.
const kTimeColumns = new Set(['time_ms', 'render_ms', 'warp_ms']);
// Measured against the exact re-render, which the CLI runs beside the engine and the page's (and
// the desktop's) per-frame CSV does not: "nan" there.
const kBaselineColumns = new Set(['psnr_db']);

// `oflab-cli animate --script NAME`'s frames.csv text, or { error }.
function cliFramesCsv(cli, script) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'oflab-web-csv-'));
  try {
    const r = spawnSync(cli, ['animate', '--script', script, '--out', path.join(dir, 'run'), '--quiet',
      '--no-warm-up', '--repeat-timing', '1'], { encoding: 'utf8' });
    if (r.status !== 0) return { error: r.stderr.trim() };
    return { csv: fs.readFileSync(path.join(dir, 'run', 'frames.csv'), 'utf8') };
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// The differences between two CSV texts outside the columns `skipped`, one line each (at most 5).
function csvDifferences(a, b, skipped = kTimeColumns) {
  const rowsA = a.trim().split('\n');
  const rowsB = b.trim().split('\n');
  const problems = [];
  if (rowsA[0] !== rowsB[0]) problems.push(`header: ${rowsA[0]} | ${rowsB[0]}`);
  if (rowsA.length !== rowsB.length) problems.push(`rows: ${rowsA.length} | ${rowsB.length}`);
  const header = rowsA[0].split(',');
  for (let r = 1; r < Math.min(rowsA.length, rowsB.length) && problems.length < 5; ++r) {
    const x = rowsA[r].split(','), y = rowsB[r].split(',');
    header.forEach((name, c) => {
      if (!skipped.has(name) && x[c] !== y[c]) problems.push(`row ${r} ${name}: ${x[c]} | ${y[c]}`);
    });
  }
  return problems.slice(0, 5);
}

async function testRunCsv({ browser, open, evaluate, check, drawnMarker, cli }) {
  await open(browser, '?view=animation&script=swing', drawnMarker);
  const page = JSON.parse(await evaluate(browser, 'app.session.runCsvJson()'));
  const swing = cliFramesCsv(cli, 'swing');
  const zoom = cliFramesCsv(cli, 'zoom');
  const skipped = new Set([...kTimeColumns, ...kBaselineColumns]);
  const same = page.csv && swing.csv ? csvDifferences(page.csv, swing.csv, skipped) : [page.error || swing.error];
  const rows = page.csv ? page.csv.trim().split('\n') : [];
  const psnrColumn = rows.length ? rows[0].split(',').indexOf('psnr_db') : -1;
  const psnrNotMeasured = psnrColumn >= 0 && rows.slice(1).every((r) => r.split(',')[psnrColumn] === 'nan');
  check('ThePagesCsvIsAnimatesFramesCsvButTheWallTimesAndPsnr', same.length === 0 && psnrNotMeasured,
    same.length ? same.join('; ') : `${rows.length - 1} frames, psnr_db not measured: ${psnrNotMeasured}`);
  const other = page.csv && zoom.csv ? csvDifferences(page.csv, zoom.csv, skipped) : [];
  check('AnotherScriptsCsvIsNotThePages', other.length > 0, other[0]);
  const downloaded = JSON.parse(await evaluate(browser, `(async () => {
    let saved = null;
    const keep = window.download;
    window.download = (blob, name) => { saved = { name, type: blob.type, blob }; };
    try { $('save-csv').click(); } finally { window.download = keep; }
    return JSON.stringify(saved && { name: saved.name, type: saved.type, text: await saved.blob.text() });
  })()`));
  const again = downloaded && page.csv ? csvDifferences(downloaded.text, page.csv) : ['nothing downloaded'];
  check('TheCsvControlDownloadsTheCsv', downloaded && /\.csv$/.test(downloaded.name) &&
    downloaded.type === 'text/csv' && again.length === 0, downloaded ? `${downloaded.name}: ${again.join('; ')}` : 'none');
}

module.exports = { testRunCsv };
