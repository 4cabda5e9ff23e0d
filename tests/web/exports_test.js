'use strict';
// The page's per-frame CSV (manual/web.md, "Keep and share"), run by web_test.js with its
// browser and helpers ({ browser, open, evaluate, check, drawnMarker, cli }).
//
// The CSV the page's *CSV* control downloads is the teaching layer's per-frame CSV of the
// source played (RunPlayer::write_csv, as the desktop's export): for a motion script, the
// columns and rows of `oflab-cli animate --script NAME`'s frames.csv, equal in every column but
// the wall times. Negative control: another script's CSV differs. A source that cannot be
// played gives a message, not a file.
//
// The page's video (*Video*, share.js recordVideo): a WebM file whose frames, counted by
// reading its EBML structure here (apart from the browser), are the frames played, at the
// canvas's size and 30 frames a second (its last block's time); its first frame, decoded by
// the browser, is the view's frame 0 as drawn (within the codec's loss), not its last (the
// control); a cancelled recording gives no file.
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

// The EBML elements of a WebM file (Matroska): per element its ID and where its data lies;
// master elements (Segment, Cluster, BlockGroup, Tracks, TrackEntry, Video) are entered, their
// size known or not (a live recording's Segment and Clusters have the unknown size).
const kMasters = new Set([0x18538067, 0x1F43B675, 0xA0, 0x1654AE6B, 0xAE, 0xE0]);
function ebmlElements(bytes) {
  const vint = (at, keepMarker) => {
    const first = bytes[at];
    let length = 1;
    while (length <= 8 && !(first & (0x80 >> (length - 1)))) ++length;
    let value = keepMarker ? first : first & (0xFF >> length);
    for (let k = 1; k < length; ++k) value = value * 256 + bytes[at + k];
    const unknown = !keepMarker && value === 2 ** (7 * length) - 1;
    return { value, length, unknown };
  };
  const elements = [];
  let at = 0;
  while (at < bytes.length) {
    const id = vint(at, true);
    const size = vint(at + id.length, false);
    const start = at + id.length + size.length;
    elements.push({ id: id.value, start, size: size.unknown ? null : size.value });
    at = kMasters.has(id.value) || size.unknown ? start : start + size.value;
  }
  return elements;
}

function readUint(bytes, element) {
  let value = 0;
  for (let k = 0; k < element.size; ++k) value = value * 256 + bytes[element.start + k];
  return value;
}

// The frames (SimpleBlocks and Blocks) and the frame size a WebM file holds.
function webmFacts(bytes) {
  const elements = ebmlElements(bytes);
  const one = (id) => elements.find((e) => e.id === id);
  // A block's time: its cluster's timecode (0xE7) plus its own 16-bit offset after the track
  // number (in the file's timecode scale, 1 ms unless Info says otherwise).
  let cluster = 0;
  const times = [];
  for (const e of elements) {
    if (e.id === 0xE7) cluster = readUint(bytes, e);
    if (e.id === 0xA3 || e.id === 0xA1) {
      const offset = e.start + 1;  // a one-byte track number (track 1)
      times.push(cluster + ((bytes[offset] << 8 | bytes[offset + 1]) << 16 >> 16));
    }
  }
  return {
    ebml: bytes[0] === 0x1A && bytes[1] === 0x45 && bytes[2] === 0xDF && bytes[3] === 0xA3,
    frames: times.length,
    lastMs: times.length ? times[times.length - 1] : null,
    width: one(0xB0) ? readUint(bytes, one(0xB0)) : null,
    height: one(0xBA) ? readUint(bytes, one(0xBA)) : null,
  };
}

async function testVideo({ browser, open, evaluate, check, drawnMarker }) {
  await open(browser, '?view=animation&script=swing', drawnMarker);
  const r = JSON.parse(await evaluate(browser, `(async () => {
    const canvas = $('canvas');
    const pixels = (frame) => { seek(frame); draw(); return canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data; };
    const first = pixels(0), last = pixels(14);
    seek(7);
    const made = await recordVideo(0, 14);
    if (made.error) return JSON.stringify({ error: made.error });
    const bytes = new Uint8Array(await made.blob.arrayBuffer());
    // The first frame as the browser decodes it, against frames 0 and 14 as drawn.
    const video = document.createElement('video');
    video.muted = true;
    video.src = URL.createObjectURL(made.blob);
    await new Promise((ok, fail) => { video.onloadeddata = ok; video.onerror = () => fail(new Error('no decode')); });
    // The first frame presented (before that the element may hold no picture yet).
    await new Promise((ok) => { video.requestVideoFrameCallback(ok); video.play(); });
    video.pause();
    const c = document.createElement('canvas');
    c.width = canvas.width; c.height = canvas.height;
    c.getContext('2d').drawImage(video, 0, 0);
    const decoded = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const psnr = (a, b) => { let s = 0, n = 0; for (let k = 0; k < a.length; k += 4) for (let q = 0; q < 3; ++q) { const d = a[k + q] - b[k + q]; s += d * d; ++n; } return 10 * Math.log10(255 * 255 * n / Math.max(s, 1e-9)); };
    // Cancelled: no file.
    const cancelled = recordVideo(0, 14);
    cancelVideo();
    const gone = await cancelled;
    let text = '';
    for (let k = 0; k < bytes.length; k += 8192) text += String.fromCharCode(...bytes.subarray(k, k + 8192));
    return JSON.stringify({ type: made.blob.type, base64: btoa(text), size: [canvas.width, canvas.height],
      first: psnr(decoded, first), last: psnr(decoded, last), frameAfter: app.session.frame(), cancelled: gone.error || 'kept' });
  })()`));
  if (r.error) { check('TheVideoHoldsEveryFramePlayed', false, r.error); return; }
  const facts = webmFacts(new Uint8Array(Buffer.from(r.base64, 'base64')));
  check('TheVideoHoldsEveryFramePlayed', /^video\/webm/.test(r.type) && facts.ebml && facts.frames === 15 &&
    facts.width === r.size[0] && facts.height === r.size[1] && Math.abs(facts.lastMs - (14 * 1000) / 30) <= 1 && r.frameAfter === 7,
    `${r.type}: ${facts.frames} frames of ${facts.width} x ${facts.height} (canvas ${r.size}), the last at ${facts.lastMs} ms, frame shown after ${r.frameAfter}`);
  check('TheVideosFirstFrameIsTheViewsFrameZero', r.first >= 30 && r.first > r.last + 3,
    `PSNR ${r.first.toFixed(1)} dB against frame 0, ${r.last.toFixed(1)} dB against frame 14 (the control)`);
  check('ACancelledVideoGivesNoFile', r.cancelled === 'cancelled', r.cancelled);
}

module.exports = { testRunCsv, testVideo };
