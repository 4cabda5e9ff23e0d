#!/usr/bin/env node
'use strict';
// The browser page's tests (manual/web.md), in headless Chromium driven over its DevTools
// protocol (no packages: Node's own WebSocket, zlib and child_process).
//
//   node tests/web/web_test.js [--page build-web/oflab-web.html] [--out DIR]
//        [--update-baselines] [--bench]
//
// - The self-test (oflab-web.html?selftest): every shipped script's levels equal the CLI's
//   golden outputs (tests/web/golden/scripts.json, tests/web/make_golden.js) and its frame-0
//   coefficients agree to 1e-12 relative; a changed level or coefficient is caught (negative
//   controls); broken script and lesson files are refused with a message naming the file.
// - Screenshots at 1280 x 720 of each view, the comparison, a lesson and a refused file:
//   each is not blank (>= 5 % of its pixels differ from the background, >= 64 colours) and
//   within 30 dB PSNR of its baseline (tests/web/baselines/); the flow view's screenshot is
//   not within 30 dB of the gallery's baseline, and a blank image is found blank (negative
//   controls). A failing screenshot is written to --out.
// - The world view (vtk.js): its numbers are the teaching layer's as the flow view sees them
//   (a moved corner is caught), playing keeps its actors, a drag turns it, and the world
//   lesson shows it beside the flow view. A scene's world and the scene-shifting view:
//   tests/web/views_test.js. The flow view's texture is the CLI's exact frame:
//   tests/web/flow_texture_test.js.
// - The basis explorer's planes and motions are `oflab-cli explain`'s for its coefficients.
// - Every step of every shipped lesson shows the state and frame `oflab-cli lesson state`
//   gives (--cli, default build/analysis/oflab-cli); a changed frame is caught.
// - The threshold study: the page's loop with a simulated observer writes the CSV of
//   `oflab-cli study session` (same study, method, seed), another seed does not, a broken
//   study file is refused naming the file and the field.
// - --bench: the flow view, the world view and the comparison played frame by frame for 300 frames, paced
//   at 60 Hz and unpaced; prints the frames per second of requestAnimationFrame (speed is
//   reported, not tested).
if (typeof WebSocket === 'undefined') {
  if (process.execArgv.includes('--experimental-websocket')) {
    console.error(`web_test.js needs Node 20.10 or later (a WebSocket client); this is ${process.version}`);
    process.exit(2);
  }
  // Node 20 has its WebSocket client behind a flag: run again with it.
  const { spawnSync } = require('child_process');
  const r = spawnSync(process.execPath, ['--experimental-websocket', '--no-warnings', __filename, ...process.argv.slice(2)], { stdio: 'inherit' });
  process.exit(r.status === null ? 1 : r.status);
}
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { decodePng } = require('./png');
const { testSlicesView, testSceneWorld, testWorldLabels, testAnalysisCharts, testEngineCharts, testDisplays } = require('./views_test');
const { testRunCsv, testVideo } = require('./exports_test');
const { testFlowTexture, testWorldFrame, testPanelFraming } = require('./flow_texture_test');

const root = path.resolve(__dirname, '..', '..');
const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const page = path.resolve(option('--page', path.join(root, 'build-web/oflab-web.html')));
const outDir = path.resolve(option('--out', path.join(os.tmpdir(), 'oflab-web-test')));
const baselines = path.join(__dirname, 'baselines');
const kWidth = 1280;
const kHeight = 720;
const kMinPsnrDb = 30;
const kRelativeTolerance = 1e-12;

let failures = 0;
function check(name, ok, detail) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}${detail ? `: ${detail}` : ''}`);
  if (!ok) ++failures;
}

// --- Chromium over the DevTools protocol -------------------------------------------------
// extraFlags: more Chromium switches (the unpaced speed measurement's).
async function launchChromium(extraFlags = []) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'oflab-web-chromium-'));
  const child = spawn(option('--chromium', '/usr/bin/chromium'), ['--headless=new', '--no-sandbox',
    // WebGL (the world view's vtk.js) on SwiftShader's software GL, which Chromium gives a
    // page without a GPU only when asked.
    '--disable-gpu', '--enable-unsafe-swiftshader', '--no-first-run', '--remote-debugging-port=0', `--user-data-dir=${profile}`,
    `--window-size=${kWidth},${kHeight}`, ...extraFlags, 'about:blank'], { stdio: ['ignore', 'ignore', 'pipe'] });
  const url = await new Promise((resolve, reject) => {
    let text = '';
    const timer = setTimeout(() => reject(new Error(`chromium did not start: ${text}`)), 30000);
    child.stderr.on('data', (d) => {
      text += d;
      const m = /DevTools listening on (ws:\/\/\S+)/.exec(text);
      if (m) { clearTimeout(timer); resolve(m[1]); }
    });
    child.on('exit', (code) => reject(new Error(`chromium exited (${code}): ${text}`)));
  });
  const socket = new WebSocket(url);
  await new Promise((resolve, reject) => { socket.onopen = resolve; socket.onerror = reject; });
  let next = 1;
  const pending = new Map();
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    const waiter = pending.get(message.id);
    if (!waiter) return;
    pending.delete(message.id);
    if (message.error) waiter.reject(new Error(JSON.stringify(message.error))); else waiter.resolve(message.result);
  };
  const send = (method, params = {}, sessionId) => new Promise((resolve, reject) => {
    const id = next++;
    pending.set(id, { resolve, reject });
    socket.send(JSON.stringify({ id, method, params, sessionId }));
  });
  const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
  const { sessionId } = await send('Target.attachToTarget', { targetId, flatten: true });
  const tab = (method, params) => send(method, params, sessionId);
  await tab('Emulation.setDeviceMetricsOverride', { width: kWidth, height: kHeight, deviceScaleFactor: 1, mobile: false });
  return {
    tab,
    async close() {
      socket.close();
      const exited = new Promise((resolve) => child.on('exit', resolve));
      child.kill();
      await exited;
      // Chromium's helper processes may still write into the profile after the browser
      // has exited: retry, and leave a profile that will not go rather than fail the run.
      try {
        fs.rmSync(profile, { recursive: true, force: true, maxRetries: 20, retryDelay: 250 });
      } catch (error) {
        console.log(`note: the Chromium profile ${profile} was left behind (${error.code})`);
      }
    },
  };
}

async function evaluate(browser, expression) {
  const r = await browser.tab('Runtime.evaluate', { expression, returnByValue: true, awaitPromise: true });
  return r.result.value;
}

// Opens the page with `query` and waits until `ready` (a JS expression) is true.
async function open(browser, query, ready, seconds = 180) {
  await browser.tab('Page.navigate', { url: `file://${page}${query}` });
  const end = Date.now() + seconds * 1000;
  while (Date.now() < end) {
    try {
      if (await evaluate(browser, ready)) return;
    } catch (e) { /* the page is still loading */ }
    await new Promise((r) => setTimeout(r, 200));
  }
  throw new Error(`${query}: not ready after ${seconds} s (${ready}); message: ${await evaluate(browser, "document.getElementById('message')?.textContent")}`);
}

const doneMarker = (id) => `document.getElementById('${id}')?.dataset.done === 'true'`;

// --- The self-test ---------------------------------------------------------------------
// Differences between the page's self-test and the golden outputs, one line each.
function compareWithGolden(result, golden) {
  const problems = [];
  for (const [name, expected] of Object.entries(golden)) {
    const got = result.scripts[name];
    if (!got || got.error) { problems.push(`${name}: ${got ? got.error : 'missing'}`); continue; }
    if (got.levels.length !== expected.levels.length) {
      problems.push(`${name}: ${got.levels.length} frames, the CLI ${expected.levels.length}`);
    }
    const first = expected.levels.findIndex((level, k) => got.levels[k] !== level);
    if (first >= 0) problems.push(`${name}: frame ${first} is ${got.levels[first]}, the CLI's ${expected.levels[first]}`);
    for (const [key, value] of Object.entries(expected.coefficients)) {
      const v = got.coefficients[key];
      const scale = Math.max(Math.abs(value), Math.abs(v), 1e-300);
      if (!(Math.abs(v - value) <= kRelativeTolerance * scale || v === value)) {
        problems.push(`${name}: ${key} = ${v}, the CLI's ${value}`);
      }
    }
  }
  for (const name of Object.keys(result.scripts)) if (!(name in golden)) problems.push(`${name}: no golden output`);
  return problems;
}

let selftestResult = null;  // the self-test's JSON, for the claims' test
async function testSelftest(browser) {
  await open(browser, '?selftest', doneMarker('selftest'));
  const result = JSON.parse(await evaluate(browser, "document.getElementById('selftest').textContent"));
  selftestResult = result;
  const golden = JSON.parse(fs.readFileSync(path.join(__dirname, 'golden/scripts.json'), 'utf8'));
  check('SelftestReportsPassed', result.passed === true, JSON.stringify(result.bad_files));
  const problems = compareWithGolden(result, golden);
  check('SelftestLevelsAndCoefficientsEqualTheCliGoldenOutputs', problems.length === 0,
    `${Object.keys(golden).length} scripts, ${Object.values(golden).reduce((n, g) => n + g.levels.length, 0)} frames${problems.length ? `; ${problems.slice(0, 5).join('; ')}` : ''}`);
  // Negative controls: one changed level and one coefficient changed by 1e-10 are caught.
  const changed = JSON.parse(JSON.stringify(result));
  const name = Object.keys(changed.scripts)[0];
  changed.scripts[name].levels[1] = changed.scripts[name].levels[1] === 'none' ? 'affine' : 'none';
  check('ComparisonCatchesAChangedLevel', compareWithGolden(changed, golden).length === 1);
  const nudged = JSON.parse(JSON.stringify(result));
  const c = nudged.scripts[name].coefficients;
  const key = Object.keys(c).find((k) => c[k] !== 0);
  c[key] *= 1 + 1e-10;
  check('ComparisonCatchesACoefficientOff1e-10', compareWithGolden(nudged, golden).length === 1, key);
  check('BrokenScriptIsRefusedNamingTheFileAndField', /broken-script\.json.*camera/.test(result.bad_files.script), result.bad_files.script);
  check('BrokenLessonIsRefusedNamingTheFile', /broken-lesson\.json/.test(result.bad_files.lesson), result.bad_files.lesson);
  // The lessons, views and time to interactive a check outside the project reads.
  const lessonDiffer = [];
  let parts = 0;
  for (const [name, steps] of Object.entries(result.lessons || {})) {
    steps.forEach((part, k) => {
      const expected = cliLessonState(name, k);
      if (JSON.stringify(part.state) !== JSON.stringify(expected) || part.frame !== expected.frame) lessonDiffer.push(`${name} ${k}`);
      // Its source plays on the page (scenes too): the exact frame was made.
      if (!/^[0-9a-f]{8}$/.test(part.exact_frame_fnv1a)) lessonDiffer.push(`${name} ${k}: no exact frame`);
      ++parts;
    });
  }
  check('SelftestLessonsEqualTheCliStates', Object.keys(result.lessons || {}).length === 19 && parts >= 53 && lessonDiffer.length === 0,
    `${parts} parts${lessonDiffer.length ? `; differ: ${lessonDiffer.slice(0, 5).join(', ')}` : ''}`);
  const views = Object.entries(result.views || {});
  check('SelftestReportsViewsAndTimeToInteractive', views.length === 8 && 'world' in result.views && 'slices' in result.views && views.every(([, v]) => v.paced_fps > 0 && v.unpaced_fps > 0) &&
    result.time_to_interactive_ms > 0, `interactive after ${result.time_to_interactive_ms} ms; ` +
    views.map(([n, v]) => `${n} ${v.paced_fps.toFixed(1)} paced, ${v.unpaced_fps.toFixed(0)} unpaced fps`).join(', '));
}

// `oflab-cli lesson state NAME --step K`'s state object (--cli, default build/analysis/oflab-cli).
const cliStates = new Map();
function cliLessonState(name, k) {
  const key = `${name} ${k}`;
  if (!cliStates.has(key)) {
    const { spawnSync } = require('child_process');
    const cli = path.resolve(option('--cli', path.join(root, 'build/analysis/oflab-cli')));
    const r = spawnSync(cli, ['lesson', 'state', name, '--step', String(k)], { encoding: 'utf8' });
    cliStates.set(key, r.status === 0 ? JSON.parse(r.stdout).state : { error: r.stderr.trim() });
  }
  return cliStates.get(key);
}

// --- The threshold study ---------------------------------------------------------------------
// The page's study loop (Module.Study, web/web_study.h) answered by a simulated observer gives
// the CSV of `oflab-cli study session` byte for byte for the same study, method, seed, name and
// ppi (and the desktop window's, tests/gui/views/study_window_test.cpp); another seed does not
// (negative control); a broken study file is refused naming the file and the field.
async function testStudy(browser) {
  const file = path.join(__dirname, 'fixtures/short-study.json');
  const text = fs.readFileSync(file, 'utf8');
  const pageCsv = async (seed) => evaluate(browser, `(() => {
    const s = new Module.Study();
    const problem = s.open('short-study.json', ${JSON.stringify(text)}, 'staircase', ${seed})
      || s.simulate(0.8);
    const out = problem || s.csv('ann', 110);
    s.delete();
    return out;
  })()`);
  const { spawnSync } = require('child_process');
  const cli = path.resolve(option('--cli', path.join(root, 'build/analysis/oflab-cli')));
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'oflab-web-study-'));
  try {
    const csv = path.join(dir, 'ann.csv');
    const r = spawnSync(cli, ['study', 'session', '--study', file, '--observer-threshold', '0.8',
      '--seed', '5', '--method', 'staircase', '--observer', 'ann', '--ppi', '110', '--csv', csv],
    { encoding: 'utf8' });
    const expected = r.status === 0 ? fs.readFileSync(csv, 'utf8') : `oflab-cli: ${r.stderr}`;
    await open(browser, '', "document.body.dataset.interactive !== undefined");
    const same = await pageCsv(5);
    check('StudyOnThePageIsTheCommandLinesSession', same === expected,
      same === expected ? `${expected.trim().split('\n').length - 1} trials` : `page: ${same.slice(0, 200)}`);
    const other = await pageCsv(6);
    check('StudyWithAnotherSeedDiffers (negative control)', other !== expected && other.includes('short-study'));
    const refused = await evaluate(browser, `(() => {
      const s = new Module.Study();
      const out = s.open('short-study.json', ${JSON.stringify(text.replace('"trials": 5', '"trials": 4'))}, '', -1);
      s.delete();
      return out;
    })()`);
    check('StudyFileRefusedNamingTheFileAndField', /^short-study\.json: .*trials/.test(refused), refused);
    // The class view: two observers' CSVs fitted on the page as `oflab-cli study analyse`.
    const bob = path.join(dir, 'bob.csv');
    spawnSync(cli, ['study', 'session', '--study', file, '--observer-threshold', '2', '--seed', '8',
      '--method', 'staircase', '--observer', 'bob', '--csv', bob]);
    const files = [csv, bob].map((f) => ({ name: path.basename(f), text: fs.readFileSync(f, 'utf8') }));
    const analysed = spawnSync(cli, ['study', 'analyse', csv, bob, '--json'], { encoding: 'utf8' });
    const want = analysed.status === 0 ? JSON.parse(analysed.stdout).results : [];
    const got = JSON.parse(await evaluate(browser, `(() => {
      const s = new Module.Study();
      const out = s.classResultsJson(${JSON.stringify(JSON.stringify(files))});
      s.delete();
      return out;
    })()`));
    const close = (a, b) => Math.abs(a - b) <= 1e-9 * Math.max(1, Math.abs(b));
    const fitsAgree = got.results && got.results.length === want.length && want.length === 3 &&
      want.every((w, i) => got.results[i].observer === w.observer &&
        close(got.results[i].threshold_px, w.threshold_px) &&
        close(got.results[i].ci95_px[0], w.ci95_px[0]) && close(got.results[i].ci95_px[1], w.ci95_px[1]));
    check('StudyClassViewFitsAsTheCommandLine', fitsAgree,
      `${(got.results || []).map((r) => `${r.observer}: ${r.threshold_px}`).join(', ')} against ` +
      `${want.map((r) => `${r.observer}: ${r.threshold_px}`).join(', ')}`);
    const broken = await evaluate(browser, `(() => {
      const s = new Module.Study();
      const out = s.classResultsJson(JSON.stringify([{ name: 'broken.csv', text: 'study,observer\\nx,y\\n' }]));
      s.delete();
      return out;
    })()`);
    check('StudyClassViewRefusesABrokenFileNamingIt', /broken\.csv/.test(JSON.parse(broken).problem || ''), broken);
    // "Use X px": the comparison's four thresholds become the smallest threshold the results
    // show (the lesson's study answered by a simulated observer of 1 px).
    await open(browser, '?study=lesson&study-simulate=1', "document.getElementById('study-results').hidden === false");
    const used = JSON.parse(await evaluate(browser, `(() => {
      const shown = JSON.parse(study.core.resultsJson($('study-observer').value.trim(), Number($('study-ppi').value)));
      const before = app.state.animation.thresholds;
      $('study-use').click();
      return JSON.stringify({ shown: shown.map((r) => r.threshold_px), before, thresholds: app.state.animation.thresholds,
        hidden: $('study-use').hidden, text: $('study-use').textContent });
    })()`));
    const smallest = Math.min(...used.shown);
    check('StudyUseSetsTheComparisonsThresholds', !used.hidden && used.shown.length > 0 &&
      used.thresholds.length === 4 && used.thresholds.every((t) => t === smallest) &&
      used.before.some((t) => t !== smallest) && used.text.includes(`${smallest.toFixed(2)} px`), JSON.stringify(used));
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// A person's run on the page: Start plays the rate check and the first trial's clips on
// requestAnimationFrame, then asks; the key 2 answers (the session counts it, or records it
// late and shows it again). On a display that drew a frame of the check late the study must
// refuse to start, saying so. Either way within 60 s; anything else fails.
async function testStudyTrial(browser) {
  await open(browser, '?study=class', "document.body.dataset.interactive !== undefined");
  await evaluate(browser, 'startStudy()');
  const end = Date.now() + 60000;
  let state = {};
  while (Date.now() < end) {
    state = await evaluate(browser, `({ phase: study.phase, status: $('study-status').textContent,
      text: $('study-trial-text').textContent })`);
    if (state.phase === 'answer' || state.status.includes('late')) break;
    await new Promise((r) => setTimeout(r, 200));
  }
  if (state.phase !== 'answer') {
    check('StudyTrialRefusedWhenTheDisplayIsLate', state.status.includes('late'), state.status || state.phase);
    return;
  }
  await press(browser, '2');
  const after = await evaluate(browser, 'JSON.parse(study.core.requestJson())');
  check('StudyTrialPlaysBothClipsAndTakesTheAnswer',
    /Press 1 or 2/.test(state.text) && (after.answered === 1 || after.late === 1),
    `${state.text} -> ${JSON.stringify(after)}`);
}

// --- Screenshots -------------------------------------------------------------------------
const drawnMarker = "Number(document.body.dataset.drawn || 0) > 0";
const shots = [
  ['flow', '?view=flow&frame=20'],
  // The world view in 3D (vtk.js on WebGL), and the world lesson's cause beside its effect.
  ['world', '?view=world&frame=20'],
  ['world-1366', '?view=world&frame=20', [1366, 768]],
  ['world-lesson', '?lesson=where-the-flow-comes-from'],
  // A scene's world: the street's polygons in their levels' colours and the viewer's path.
  ['world-scene', '?view=world&source=scene:street:walk&frame=20'],
  ['world-scene-1366', '?view=world&source=scene:street:walk&frame=20', [1366, 768]],
  // The scene-shifting view: the train window's slices beside its layered and exact frames.
  ['slices', '?view=slices&frame=30'],
  ['slices-1366', '?view=slices&frame=30', [1366, 768]],
  ['flow-presentation', '?view=flow&frame=60&presentation'],
  ['basis', '?view=basis&frame=20'],
  ['comparison', '?view=animation&script=swing&frame=40&display=comparison'],
  // The animation view's other layouts: the engine beside the exact frame, its difference.
  ['side-by-side', '?view=animation&script=loop&frame=20'],
  ['difference', '?view=animation&script=loop&frame=20&display=difference'],
  ['lesson', '?lesson=affine-vs-perspective'],
  // Streamlines of the first-order part (the flow-of-a-plane lesson's first step).
  ['lesson-step', '?lesson=flow-of-a-plane&step=1'],
  // A lesson on a scene, played by the scene animator: its engine beside the exact frame
  // (the lesson's display is the default, side by side).
  ['lesson-on-a-scene', '?lesson=occlusion&step=1'],
  // The street walked through (when-reuse-pays), the scene with the most polygons.
  ['street', '?lesson=when-reuse-pays'],
  // The analysis charts of the errors-accumulate lesson's first step.
  ['analysis', '?lesson=why-errors-accumulate&step=1'],
  // A laptop's 1366 x 768: the comparison, the street and the charts.
  ['comparison-1366', '?view=animation&script=swing&frame=40&display=comparison', [1366, 768]],
  ['analysis-1366', '?lesson=why-errors-accumulate&step=1', [1366, 768]],
  ['flow-1366', '?view=flow&frame=20', [1366, 768]],
  ['basis-1366', '?view=basis&frame=20', [1366, 768]],
  // The basis explorer: the default eight terms, both ways.
  ['explorer', '?view=basis&explorer'],
  ['explorer-1366', '?view=basis&explorer', [1366, 768]],
  ['explorer-presentation', '?view=basis&explorer&presentation'],
];

// The PSNR of a against b over the pixels outside the rectangles `left_out` ({x, y, w, h},
// page pixels): the charts of times measured in the page, which differ from run to run.
function psnr(a, b, leftOut = []) {
  if (a.width !== b.width || a.height !== b.height) return -Infinity;
  const outside = (x, y) => !leftOut.some((r) => x >= r.x && x < r.x + r.w && y >= r.y && y < r.y + r.h);
  let sum = 0;
  let pixels = 0;
  for (let y = 0; y < a.height; ++y) {
    for (let x = 0; x < a.width; ++x) {
      if (!outside(x, y)) continue;
      const i = 4 * (y * a.width + x);
      for (let c = 0; c < 3; ++c) sum += (a.data[i + c] - b.data[i + c]) ** 2;
      ++pixels;
    }
  }
  const mse = sum / (3 * Math.max(1, pixels));
  return mse === 0 ? 99 : 10 * Math.log10(255 * 255 / mse);
}

// "Not blank": at least 5 % of the pixels differ from the top-left pixel and at least 64
// distinct colours.
function notBlank(image) {
  const d = image.data;
  const colours = new Set();
  let differing = 0;
  for (let i = 0; i < d.length; i += 4) {
    if (d[i] !== d[0] || d[i + 1] !== d[1] || d[i + 2] !== d[2]) ++differing;
    if (colours.size < 64) colours.add((d[i] << 16) | (d[i + 1] << 8) | d[i + 2]);
  }
  return differing >= 0.05 * image.width * image.height && colours.size >= 64;
}

async function screenshot(browser, query, [width, height] = [kWidth, kHeight]) {
  await browser.tab('Emulation.setDeviceMetricsOverride', { width, height, deviceScaleFactor: 1, mobile: false });
  try {
    await open(browser, query, drawnMarker);
    const { data } = await browser.tab('Page.captureScreenshot', { format: 'png' });
    // The measured charts' rectangles in page pixels (none but in the analysis view).
    const measured = JSON.parse(await evaluate(browser, `(() => { const r = document.getElementById('canvas').getBoundingClientRect();
      return JSON.stringify(shownView() !== 'analysis' ? [] : analysisView.measured.map((m) => ({ x: Math.floor(r.left + m.x), y: Math.floor(r.top + m.y), w: Math.ceil(m.w) + 1, h: Math.ceil(m.h) + 1 }))); })()`));
    return { png: Buffer.from(data, 'base64'), measured };
  } finally {
    await browser.tab('Emulation.setDeviceMetricsOverride', { width: kWidth, height: kHeight, deviceScaleFactor: 1, mobile: false });
  }
}

async function testScreenshots(browser) {
  fs.mkdirSync(outDir, { recursive: true });
  const images = {};
  for (const [name, query, size = [kWidth, kHeight]] of shots) {
    const { png, measured } = await screenshot(browser, query, size);
    const image = decodePng(png, name);
    images[name] = image;
    const baseline = path.join(baselines, `${name}.png`);
    if (args.includes('--update-baselines')) {
      fs.writeFileSync(`${baseline}.tmp`, png);
      fs.renameSync(`${baseline}.tmp`, baseline);
    }
    const blankOk = notBlank(image) && image.width === size[0] && image.height === size[1];
    check(`Screenshot_${name}_IsNotBlank`, blankOk, `${image.width} x ${image.height}`);
    if (!fs.existsSync(baseline)) {
      check(`Screenshot_${name}_MatchesBaseline`, false, `missing baseline ${baseline} (this run's is in ${outDir})`);
      fs.writeFileSync(path.join(outDir, `${name}.png`), png);
      continue;
    }
    // A chart of times measured in this run is left out, and only such a chart (at most a
    // tenth of the page).
    const leftOut = measured.reduce((n, r) => n + r.w * r.h, 0) / (size[0] * size[1]);
    const db = psnr(image, decodePng(fs.readFileSync(baseline), baseline), measured);
    const without = measured.length ? `, ${measured.length} measured chart(s) left out (${(100 * leftOut).toFixed(1)} % of the page)` : '';
    check(`Screenshot_${name}_MatchesBaseline`, db >= kMinPsnrDb && leftOut <= 0.1, `${db.toFixed(1)} dB (>= ${kMinPsnrDb})${without}`);
    if (db < kMinPsnrDb || !blankOk) fs.writeFileSync(path.join(outDir, `${name}.png`), png);
  }
  const basis = path.join(baselines, 'basis.png');
  if (fs.existsSync(basis)) {
    const db = psnr(images.flow, decodePng(fs.readFileSync(basis), basis));
    check('NegativeControl_FlowScreenshotDoesNotMatchTheGalleryBaseline', db < kMinPsnrDb, `${db.toFixed(1)} dB`);
  }
  const flow = path.join(baselines, 'flow.png');
  if (fs.existsSync(flow)) {
    const db = psnr(images.world, decodePng(fs.readFileSync(flow), flow));
    check('NegativeControl_WorldScreenshotDoesNotMatchTheFlowBaseline', db < kMinPsnrDb, `${db.toFixed(1)} dB`);
  }
  if (fs.existsSync(basis)) {
    const db = psnr(images.explorer, decodePng(fs.readFileSync(basis), basis));
    check('NegativeControl_ExplorerScreenshotDoesNotMatchTheGalleryBaseline', db < kMinPsnrDb, `${db.toFixed(1)} dB`);
  }
  const blank = { width: kWidth, height: kHeight, data: new Uint8Array(kWidth * kHeight * 4).fill(17) };
  check('NegativeControl_ABlankImageIsFoundBlank', !notBlank(blank));
  // A refused file leaves a message on the page, not a blank page.
  await open(browser, '?script=no-such-script', "document.getElementById('message').hidden === false && " + drawnMarker);
  const message = await evaluate(browser, "document.getElementById('message').textContent");
  check('AnUnknownScriptGivesAMessageOnThePage', /no-such-script/.test(message), message);
}

// --- The world view ----------------------------------------------------------------------
// Problems of the page's world numbers against the flow view's (both from the teaching
// layer; computed independently here): each plane corner seen through the camera lands on the
// flow view's outline, each ray image lies on the image plane and on its corner's ray, each
// arrow's matrix takes the unit arrow's tip to origin + length along the direction.
function worldProblems(loop, frame, flow) {
  const problems = [];
  const c = loop.camera;
  const near = (a, b, tol) => Math.abs(a - b) <= tol * Math.max(1, Math.abs(a), Math.abs(b));
  frame.plane_corners.forEach(([x, y, z], k) => {
    const [px, py] = [c.focal_px * x / z + c.cx, c.focal_px * y / z + c.cy];
    if (!near(px, flow.outline[k][0], 1e-9) || !near(py, flow.outline[k][1], 1e-9)) problems.push(`corner ${k} at ${px}, ${py}, the flow's ${flow.outline[k]}`);
    const r = frame.ray_images[k];
    if (!near(r[2], loop.depth, 1e-12) || !near(r[0] * z, x * r[2], 1e-9) || !near(r[1] * z, y * r[2], 1e-9)) problems.push(`ray image ${k} ${r}`);
  });
  for (const [name, a] of Object.entries(frame.arrows)) {
    const m = a.matrix;
    const norm = Math.hypot(...a.direction);
    for (let i = 0; i < 3; ++i) {
      const tip = m[4 * i] + m[4 * i + 3];
      const expected = a.origin[i] + (norm > 0 ? a.length * a.direction[i] / norm : 0);
      if (!near(tip, expected, 1e-9)) { problems.push(`${name} tip ${i}: ${tip}, expected ${expected}`); break; }
    }
  }
  return problems;
}

async function testWorld(browser) {
  await open(browser, '?view=world&frame=20', drawnMarker);
  const got = JSON.parse(await evaluate(browser, `JSON.stringify({ loop: JSON.parse(app.session.worldLoopJson()),
    frame: JSON.parse(app.session.worldFrameJson()), flow: JSON.parse(app.session.flowJson()), state: app.state,
    view: document.body.dataset.view, actors: worldView.world.renderer.getActors().length })`));
  const problems = worldProblems(got.loop, got.frame, got.flow);
  check('WorldNumbersAreTheTeachingLayersAsTheFlowViewSeesThem', problems.length === 0 && got.frame.frame === 20 && got.view === 'world',
    `${got.actors} actors, depth ${got.loop.depth.toFixed(3)}, ${got.loop.path.length} path points${problems.length ? `; ${problems.slice(0, 3).join('; ')}` : ''}`);
  // Negative control: a corner moved by 1e-6 of a unit is caught.
  const moved = JSON.parse(JSON.stringify(got.frame));
  moved.plane_corners[2][0] += 1e-6;
  check('NegativeControl_AMovedWorldCornerIsCaught', worldProblems(got.loop, moved, got.flow).length > 0);
  // The plane's own motion at frame 20 is the state's (screw: V is the state's velocity).
  const same = (a, b) => a.every((v, i) => Math.abs(v - b[i]) <= 1e-12);
  check('WorldVAndOmegaAreTheStatesMotion', same(got.frame.velocity, got.state.plane.motion.velocity) && same(got.frame.omega, got.state.plane.motion.omega),
    `V ${got.frame.velocity}, Omega ${got.frame.omega}`);
  // Playing moves the actors' points and matrices, never makes an actor anew; a drag turns
  // the camera (vtk.js's trackball).
  const played = JSON.parse(await evaluate(browser, `(async () => {
    const before = worldView.world.renderer.getActors().slice();
    const corner = JSON.stringify(worldView.frame.plane_corners);
    for (let k = 0; k < 10; ++k) { seek(app.state.frame + 1); draw(); }
    const after = worldView.world.renderer.getActors();
    return JSON.stringify({ same: after.length === before.length && after.every((a, i) => a === before[i]),
      moved: JSON.stringify(worldView.frame.plane_corners) !== corner, renders: worldView.world.renders,
      camera: worldView.world.renderer.getActiveCamera().getPosition() });
  })()`));
  const box = JSON.parse(await evaluate(browser, "JSON.stringify(document.getElementById('world').getBoundingClientRect())"));
  const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
  await browser.tab('Input.dispatchMouseEvent', { type: 'mousePressed', x, y, button: 'left', buttons: 1, clickCount: 1 });
  for (let k = 1; k <= 5; ++k) await browser.tab('Input.dispatchMouseEvent', { type: 'mouseMoved', x: x + 20 * k, y: y + 8 * k, button: 'left', buttons: 1 });
  await browser.tab('Input.dispatchMouseEvent', { type: 'mouseReleased', x: x + 100, y: y + 40, button: 'left', buttons: 0, clickCount: 1 });
  const turned = JSON.parse(await evaluate(browser, 'JSON.stringify(worldView.world.renderer.getActiveCamera().getPosition())'));
  const dragged = Math.hypot(...turned.map((v, i) => v - played.camera[i]));
  check('WorldPlaysWithTheSameActorsAndTheMouseTurnsIt', played.same && played.moved && dragged > 1e-3,
    `actors kept ${played.same}, plane moved ${played.moved}, camera moved ${dragged.toFixed(3)} by a drag`);
  // The world lesson shows the world view (beside the flow), without the line of a view the
  // page lacks.
  await open(browser, '?lesson=where-the-flow-comes-from', drawnMarker);
  const lesson = JSON.parse(await evaluate(browser, `JSON.stringify({ view: document.body.dataset.view,
    split: document.body.classList.contains('cause-and-effect'), width: document.getElementById('world').getBoundingClientRect().width,
    stage: document.getElementById('stage').getBoundingClientRect().width })`));
  check('TheWorldLessonShowsTheWorldViewBesideTheFlow', lesson.view === 'world' && lesson.split && Math.abs(lesson.width - lesson.stage / 2) < 2,
    JSON.stringify(lesson));
}

// --- Controls ----------------------------------------------------------------------------
const kKeys = {
  ' ': ['Space', 32], ArrowRight: ['ArrowRight', 39], ArrowLeft: ['ArrowLeft', 37], ArrowUp: ['ArrowUp', 38],
  Home: ['Home', 36], End: ['End', 35], PageDown: ['PageDown', 34], PageUp: ['PageUp', 33], p: ['KeyP', 80], 2: ['Digit2', 50], 4: ['Digit4', 52],
};

async function press(browser, key) {
  const [code, keyCode] = kKeys[key];
  for (const type of ['keyDown', 'keyUp']) {
    await browser.tab('Input.dispatchKeyEvent', { type, key, code, windowsVirtualKeyCode: keyCode, text: type === 'keyDown' && key.length === 1 ? key : undefined });
  }
}

async function testControls(browser) {
  await open(browser, '?view=animation&script=swing', drawnMarker);
  const frame = () => evaluate(browser, 'app.state.frame');
  const steps = [];
  for (const [key, expect] of [['End', 119], ['Home', 0], ['ArrowRight', 1], ['ArrowUp', 11], ['ArrowLeft', 10]]) {
    await press(browser, key);
    steps.push(`${key} -> ${await frame()} (expected ${expect})`);
    if (await frame() !== expect) { check('KeysStepAndJump', false, steps.join(', ')); return; }
  }
  check('KeysStepAndJump', true, steps.join(', '));
  await press(browser, ' ');
  const playing = await evaluate(browser, 'app.playing');
  await new Promise((r) => setTimeout(r, 1500));
  const played = await frame();
  await press(browser, ' ');
  check('SpacePlaysAndPauses', playing && played > 10 && !(await evaluate(browser, 'app.playing')), `frame 10 -> ${played} in 1.5 s`);
  await press(browser, 'p');
  const presentation = await evaluate(browser, "app.state.presentation && document.body.classList.contains('presentation')");
  await press(browser, '2');
  check('KeysSetPresentationAndView', presentation && (await evaluate(browser, 'app.state.view')) === 'basis');
  // Pose and motion: an accepted edit moves the plane; a refused one (a zero normal) leaves
  // the state as it was and says why on the page.
  await open(browser, '?view=flow', drawnMarker);
  const edit = (id, value) => evaluate(browser, `(() => { const e = document.getElementById('${id}');
    e.value = '${value}'; e.dispatchEvent(new Event('change')); return app.state.plane; })()`);
  const moved = await edit('pose-point-2', '3');
  const zero = ['0', '1', '2'].map((i) => `pose-normal-${i}`);
  await edit(zero[0], '0');
  await edit(zero[1], '0');
  const refused = await edit(zero[2], '0');
  const message = await evaluate(browser, "document.getElementById('message').textContent");
  check('PoseEditsApplyAndBadOnesAreRefusedWithAMessage', moved.pose.point[2] === 3 &&
    refused.pose.normal[2] !== 0 && /normal/.test(message), message);
  // A lesson's step applies its state: the basis-deformations lesson's second step shows
  // Waxman-Ullman's basis, and Page Down goes no further than the last step.
  await open(browser, '?lesson=basis-deformations&step=1', drawnMarker);
  await press(browser, 'PageDown');
  await press(browser, 'PageDown');
  const lesson = await evaluate(browser, "[app.lessonStep, app.state.basis.kind, document.getElementById('lesson-caption').textContent]");
  check('LessonStepsApplyTheirState', lesson[0] === 2 && lesson[1] === 'waxman-ullman', lesson.join(' | '));
  // A step whose state names a study (study.open) opens the study panel on its set-up page with
  // that study chosen; going back to the narrative (study.open empty) closes it.
  await open(browser, '?lesson=how-much-error-can-you-see&step=1', drawnMarker);
  const opened = await evaluate(browser, "[document.getElementById('study-panel').hidden, document.getElementById('study-setup').hidden, document.getElementById('study-name').value]");
  await press(browser, 'PageUp');
  const closed = await evaluate(browser, "[app.lessonStep, document.getElementById('study-panel').hidden]");
  check('ALessonStepOpensTheStudyPanelOnItsStudy', opened[0] === false && opened[1] === false && opened[2] === 'lesson' &&
    closed[0] === 0 && closed[1] === true, `${opened.join(' | ')} then ${closed.join(' | ')}`);
  // The source pickers: scene shifting of the train window seen from the train plays beside
  // the scene's exact projection; scene shifting of the street (planes not facing the
  // viewer) is refused with the reason, and the state stays.
  await open(browser, '?view=flow', drawnMarker);
  const picked = JSON.parse(await evaluate(browser, `(() => {
    const pick = (value, viewer) => { $('viewer').value = viewer; $('source').value = value; $('source').dispatchEvent(new Event('change')); };
    pick('scene-shifting:train-window', 'train-sideways');
    seek(30);
    const played = { source: app.state.animation.source, view: app.state.view, problem: app.session.comparisonProblem(),
      runs: JSON.parse(app.session.updateComparison(160, 120)).runs.map((r) => r.policy) };
    const before = app.session.stateJson();
    pick('scene-shifting:street', 'walk');
    return JSON.stringify({ played, message: $('message').textContent, unchanged: app.session.stateJson() === before });
  })()`));
  check('TheSourcePickerPlaysSceneShifting', picked.played.source.kind === 'scene-shifting' && picked.played.source.viewer === 'train-sideways' &&
    picked.played.view === 'animation' && !picked.played.problem && picked.played.runs.join() === 'scene-shifting,rerender', JSON.stringify(picked.played));
  check('ASourceThatCannotPlayIsRefusedAndTheStateStays', picked.unchanged && /not parallel to the image plane/.test(picked.message), picked.message);
  // A click on any analysis chart goes to the frame under the pointer, through that chart's
  // own rectangle (the engine's charts in two columns): chart i is clicked where its x axis of
  // frames 0 .. 79 shows frame 10 + 7 i (the key 4 shows the charts).
  await open(browser, '?script=swing&frame=60', drawnMarker);
  await press(browser, '4');
  const charts = JSON.parse(await evaluate(browser, `(() => { draw(); const r = document.getElementById('canvas').getBoundingClientRect();
    return JSON.stringify({ boxes: analysisView.charts.map((c) => ({ x: r.left + c.x, y: r.top + c.y, w: c.w, h: c.h })), view: app.state.view, range: analysisView.range }); })()`));
  const misses = [];
  for (const [i, c] of charts.boxes.entries()) {
    const frame = 10 + 7 * i;
    const x = c.x + (c.w * frame) / 79;
    const y = c.y + c.h / 2;
    await browser.tab('Input.dispatchMouseEvent', { type: 'mousePressed', x, y, button: 'left', clickCount: 1 });
    await browser.tab('Input.dispatchMouseEvent', { type: 'mouseReleased', x, y, button: 'left', clickCount: 1 });
    const jumped = await evaluate(browser, 'app.session.frame()');
    if (jumped !== frame) misses.push(`chart ${i}: frame ${jumped}, expected ${frame}`);
  }
  check('AClickOnEveryAnalysisChartGoesToThatFrame', charts.view === 'analysis' && charts.range[0] === 0 && charts.boxes.length === 7 && misses.length === 0,
    `view ${charts.view}, axis ${charts.range}, ${charts.boxes.length} charts; ${misses.join('; ')}`);
}

// --- The basis explorer ------------------------------------------------------------------
// The page's explorer (Session.explorerJson) gives for its eight terms the planes and
// motions `oflab-cli explain` gives for the same coefficients (another command, another
// reader: to 1e-9); a dialled term goes through the state (and its limit is kept, with a
// message naming the field); "All zero" gives the no-motion case.
async function testExplorer(browser) {
  const { spawnSync } = require('child_process');
  const cli = path.resolve(option('--cli', path.join(root, 'build/analysis/oflab-cli')));
  await open(browser, '?view=basis&explorer', drawnMarker);
  const r = JSON.parse(await evaluate(browser, 'JSON.stringify(app.explorer.result())'));
  const c = r.coefficients;
  const out = spawnSync(cli, ['explain', '--coefficients', ...['tx', 'ty', 'j11', 'j12', 'j21', 'j22', 'px', 'py'].map((k) => String(c[k])),
    '--focal', String(r.camera.focal_px), '--json'], { encoding: 'utf8' });
  const explained = out.status === 0 ? JSON.parse(out.stdout).solutions : [];
  const close = (a, b) => a.every((v, i) => Math.abs(v - b[i]) <= 1e-9 * Math.max(1, Math.abs(v)));
  const same = (p, q) => close(p.normal, q.normal) && close(p.v_over_d, q.v_over_d) && close(p.omega, q.omega) &&
    close([p.depth_over_d], [q.depth_over_d]);
  const matched = r.solutions.length === explained.length && r.solutions.every((p) => explained.some((q) => same(p, q)));
  check('TheExplorersSolutionsAreTheCliExplainsOfItsCoefficients', matched && r.solutions.length === 2,
    `${r.solutions.length} solutions on the page, ${explained.length} from oflab-cli explain (${out.stderr || 'ok'})`);
  // Negative control: another solution's normal is not a match.
  const other = JSON.parse(JSON.stringify(r.solutions[0]));
  other.normal[0] += 1e-6;
  check('NegativeControl_ANudgedNormalIsNotTheCliSolution', !explained.some((q) => same(other, q)));
  check('TheExplorersFuturesPartAsTheDesktopSays', r.futures.played && r.futures.frames === 30 && r.futures.first_frame_apart === 13,
    `played ${r.futures.played}, ${r.futures.frames} frames, over 1 px first at frame ${r.futures.first_frame_apart} (the desktop's default: 13)`);
  const dialled = JSON.parse(await evaluate(browser, `(() => {
    const box = $('explorer-tx'); box.value = '120'; box.dispatchEvent(new Event('change'));
    const accepted = [app.state.basis.terms.tx, app.explorer.result().terms[0].value, app.explorer.result().coefficients.tx];
    box.value = '1e6'; box.dispatchEvent(new Event('change'));
    const refused = [app.state.basis.terms.tx, $('message').textContent];
    $('explorer-zero').click();
    return JSON.stringify({ accepted, refused, zero: app.explorer.result().case });
  })()`));
  check('ADialledTermGoesThroughTheStateAndItsLimitIsKept', dialled.accepted.every((v) => v === 120) &&
    dialled.refused[0] === 120 && /basis\.terms\b.*\btx\b/.test(dialled.refused[1]), JSON.stringify(dialled));
  check('AllZeroIsTheNoMotionCase', /^No motion/.test(dialled.zero), dialled.zero);
  // "From the scene" dials the flow of the frame shown now, not of the frame the explorer was
  // last drawn at: at frame 60 of swing its coefficients are the flow view's there (another
  // computation: the flow's own coefficients), and differ from frame 40's.
  await open(browser, '?view=basis&explorer&script=swing&frame=40', drawnMarker);
  const scene = JSON.parse(await evaluate(browser, `(() => {
    draw();
    const at40 = JSON.parse(app.session.flowJson()).coefficients;
    seek(60);
    $('explorer-scene').click();
    return JSON.stringify({ at40, flow: JSON.parse(app.session.flowJson()).coefficients,
      explorer: app.explorer.result().coefficients, frame: app.state.frame });
  })()`));
  const keys = ['tx', 'ty', 'j11', 'j12', 'j21', 'j22', 'px', 'py'];
  const near = (a, b) => keys.every((k) => Math.abs(a[k] - b[k]) <= 1e-9 * Math.max(1, Math.abs(b[k])));
  check('FromTheSceneDialsTheFlowOfTheFrameShown', scene.frame === 60 && near(scene.explorer, scene.flow) &&
    !near(scene.at40, scene.flow), JSON.stringify(scene));
}

// --- The same lesson everywhere ----------------------------------------------------------
// Every step of every shipped lesson shows in the page (Session.goToLessonStep, the one
// lesson player) the state and frame that `oflab-cli lesson state` gives; the desktop
// window is held to the CLI's states by tests/gui/app/lesson_player_test.cpp.
async function testLessonStates(browser) {
  const { spawnSync } = require('child_process');
  const cli = path.resolve(option('--cli', path.join(root, 'build/analysis/oflab-cli')));
  await open(browser, '?view=flow', drawnMarker);
  const lessons = await evaluate(browser, 'JSON.stringify(app.lessons.map((l) => [l.name, l.steps.length]))');
  let parts = 0;
  const differ = [];
  for (const [name, steps] of JSON.parse(lessons)) {
    for (let k = 0; k <= steps; ++k) {
      const expected = cliLessonState(name, k);
      if (expected.error) { differ.push(`${name} ${k}: oflab-cli: ${expected.error}`); continue; }
      const shown = JSON.parse(await evaluate(browser,
        `(() => { const p = app.session.goToLessonStep(${JSON.stringify(name)}, ${k}); return p || app.session.stateJson(); })()`));
      if (JSON.stringify(shown) !== JSON.stringify(expected)) {
        differ.push(`${name} step ${k}: page frame ${shown.frame}, CLI frame ${expected.frame}`);
      }
      ++parts;
    }
  }
  check('EveryLessonStepShowsTheCliStateAndFrame', differ.length === 0 && parts >= 44,
    differ.length ? differ.slice(0, 5).join('; ') : `${parts} parts of ${JSON.parse(lessons).length} lessons`);
  // Negative control: a changed frame is a difference.
  const nudged = JSON.parse(spawnSync(cli, ['lesson', 'state', 'flow-of-a-plane'], { encoding: 'utf8' }).stdout).state;
  const page = JSON.parse(await evaluate(browser, "(() => { app.session.goToLessonStep('flow-of-a-plane', 0); return app.session.stateJson(); })()"));
  nudged.frame += 1;
  check('NegativeControl_AnotherFrameIsADifference', JSON.stringify(page) !== JSON.stringify(nudged));
  // A lesson opened in presentation mode from the address keeps the teacher's look through
  // its steps (as `oflab --lesson NAME --presentation`); without it the look is the normal one.
  const look = async (query) => {
    await open(browser, query, drawnMarker);
    return JSON.parse(await evaluate(browser, `(() => { const first = app.state.presentation && document.body.classList.contains('presentation');
      showLessonStep(1); return JSON.stringify([first, app.state.presentation, app.lessonStep]); })()`));
  };
  const presenting = await look('?lesson=occlusion&presentation');
  const plain = await look('?lesson=occlusion');
  check('ALessonOpenedInPresentationModeKeepsItThroughItsSteps', presenting[0] === true && presenting[1] === true &&
    presenting[2] === 1 && plain[0] === false && plain[1] === false, `${presenting} against ${plain}`);
}

// --- Claims ------------------------------------------------------------------------------
// Every engine claim of every part of every lesson, measured on the page's lab after the
// page went to that part (Session.checkClaimsJson, the check control; the self-test's
// "claims"), gives the line `oflab-cli lesson check all` prints for it, word for word, and
// holds.
async function testClaims(browser) {
  const { spawnSync } = require('child_process');
  const cli = path.resolve(option('--cli', path.join(root, 'build/analysis/oflab-cli')));
  const r = spawnSync(cli, ['lesson', 'check', 'all'], { encoding: 'utf8' });
  const expected = r.stdout.split('\n').filter((l) => l && !l.startsWith('oflab-cli lesson check:'));
  const lines = [];
  for (const parts of Object.values((selftestResult && selftestResult.lessons) || {})) {
    for (const part of parts) lines.push(...(part.error ? [part.error] : part.claims));
  }
  const differ = lines.map((l, i) => (l === expected[i] ? '' : `page: ${l} | CLI: ${expected[i]}`)).filter(Boolean);
  check('EveryEngineClaimIsMeasuredOnThePageAsTheCli', r.status === 0 && lines.length === expected.length && differ.length === 0,
    `${lines.length} claims on the page, ${expected.length} from oflab-cli${differ.length ? `; ${differ.slice(0, 3).join('; ')}` : ''}`);
  check('EveryEngineClaimHoldsOnThePage', lines.length > 0 && lines.every((l) => / holds$/.test(l)),
    lines.filter((l) => !/ holds$/.test(l)).slice(0, 3).join('; '));
  // The check control lists says / measured / holds for the part shown.
  await open(browser, '?lesson=occlusion&step=1', drawnMarker);
  const control = JSON.parse(await evaluate(browser, "JSON.stringify(JSON.parse(app.session.checkClaimsJson()).filter((c) => c.source === 'engine').map((c) => c.line))"));
  check('TheCheckControlMeasuresAsTheCli', control.length > 0 && control.every((l) => expected.includes(l)), control.join('; '));
  await evaluate(browser, "document.getElementById('lesson-check').click()");
  const table = await evaluate(browser, "document.getElementById('lesson-checks').textContent");
  check('TheCheckControlListsSaysMeasuredHolds', /says.*measured.*holds/.test(table) && /holds/.test(table.replace(/^.*?holds/, '')), table.slice(0, 160));
  // Negative control: the same claims measured on another frame are not the CLI's lines.
  const moved = JSON.parse(await evaluate(browser, `(() => { app.session.goToLessonStep('why-errors-accumulate', 1); app.session.seek(3);
    return JSON.stringify(JSON.parse(app.session.checkClaimsJson()).filter((c) => c.source === 'engine').map((c) => c.line)); })()`));
  check('NegativeControl_ClaimsOnAnotherFrameDiffer', moved.some((l) => !expected.includes(l)), moved.slice(0, 1).join(''));
  // The visible-only warp's pixels in the comparison's table, as the desktop's captions give
  // them (fewer than the pixels written); a lesson under the whole warp has no such row.
  await open(browser, '?lesson=warping-what-shows', drawnMarker);
  const rows = JSON.parse(await evaluate(browser, "JSON.stringify([...document.querySelectorAll('#runs tr')].map((tr) => [...tr.children].map((c) => c.textContent)))"));
  const written = rows.find((r) => r[0] === 'pixels written');
  const warped = rows.find((r) => r[0] === 'warped, what shows only');
  check('TheVisibleWarpShowsItsPixelsWarped', Boolean(written && warped) && Number(warped[1]) > 0 && Number(warped[1]) < Number(written[1]),
    JSON.stringify([written, warped]));
  await open(browser, '?lesson=occlusion&step=1', drawnMarker);
  const whole = await evaluate(browser, "document.getElementById('runs').textContent");
  check('NegativeControl_TheWholeWarpHasNoWarpedRow', /pixels written/.test(whole) && !/what shows only/.test(whole), whole.slice(0, 160));
}

// --- Links and files ------------------------------------------------------------------------
// Every lesson part and every session file the project keeps (fuzz/seeds/session: no session
// ships in datasets/) as a permalink: at most 2 KB, and opening it on a fresh page's state
// restores the state exactly. A session saved by the page reads back to the same state; a
// refused session file names the file and the field and changes nothing.
async function testLinks(browser) {
  await open(browser, '?view=flow', drawnMarker);
  const sessions = fs.readdirSync(path.join(root, 'fuzz/seeds/session')).filter((f) => f.endsWith('.json'))
    .map((f) => [f, fs.readFileSync(path.join(root, 'fuzz/seeds/session', f), 'utf8')]);
  const result = JSON.parse(await evaluate(browser, `(async () => {
    const parts = [];
    for (const lesson of app.lessons) {
      for (let k = 0; k <= lesson.steps.length; ++k) parts.push(['lesson', lesson.name, k]);
    }
    for (const [name, text] of ${JSON.stringify(sessions)}) parts.push(['session', name, text]);
    const out = { count: 0, longest: 0, differ: [], refused: [] };
    for (const [kind, name, arg] of parts) {
      const problem = kind === 'lesson' ? app.session.goToLessonStep(name, arg) : app.session.openSession(arg, name);
      // A session naming a file this machine does not have is refused, naming the field.
      if (problem && kind === 'session' && /: (texture|script): .*cannot/.test(problem)) { out.refused.push(problem); continue; }
      if (problem) { out.differ.push(name + ': ' + problem); continue; }
      const original = app.session.stateJson();
      const fragment = await linkFragment(JSON.parse(original));
      out.longest = Math.max(out.longest, fragment.length + 1);
      if (fragment.length + 1 > 2048) out.differ.push(name + ' ' + arg + ': link of ' + (fragment.length + 1) + ' bytes');
      app.session.setState('{}', 'reset');
      const opened = await openLink(fragment);
      const restored = app.session.stateJson();
      if (opened || restored !== original) out.differ.push(name + ' ' + (kind === 'lesson' ? arg : '') + ': ' + (opened || 'restored state differs'));
      ++out.count;
    }
    return JSON.stringify(out);
  })()`));
  check('EveryLessonPartAndSessionRoundTripsThroughAPermalinkOfAtMost2KB', result.differ.length === 0 && result.count >= 48,
    `${result.count} states, longest link ${result.longest} bytes; refused (a file missing): ${result.refused.join('; ') || 'none'}${result.differ.length ? `; ${result.differ.slice(0, 3).join('; ')}` : ''}`);
  // Negative control: a link of another state does not restore this one.
  const other = await evaluate(browser, `(async () => { app.session.goToLessonStep('holes', 1); const a = app.session.stateJson();
    const f = await linkFragment(JSON.parse(a)); app.session.goToLessonStep('holes', 0); const g = await linkFragment(JSON.parse(app.session.stateJson()));
    await openLink(g); return app.session.stateJson() !== a && f !== g; })()`);
  check('NegativeControl_AnotherLinkRestoresAnotherState', other === true);
  // Opening the page at a permalink shows that state; #embed hides the controls.
  const fragment = await evaluate(browser, "(async () => { app.session.goToLessonStep('occlusion', 1); return linkFragment(JSON.parse(app.session.stateJson())); })()");
  const expected = await evaluate(browser, 'app.session.stateJson()');
  await open(browser, `#embed&${fragment}`, drawnMarker);
  await open(browser, `?view=basis#embed&${fragment}`, `Number(document.body.dataset.interactive || 0) > 0`);
  const shown = await evaluate(browser, "[app.session.stateJson(), getComputedStyle(document.getElementById('bar')).display, getComputedStyle(document.getElementById('canvas')).width]");
  check('APermalinkOpensItsStateAndEmbedHidesTheControls', shown[0] === expected && shown[1] === 'none', `bar ${shown[1]}, canvas ${shown[2]}`);
  // The PNG and session controls download the view as a PNG of the canvas's size and the
  // state as a session file (the downloads are caught where the page hands them over).
  const saved = JSON.parse(await evaluate(browser, `new Promise((done) => {
    const got = [];
    download = (blob, name) => {
      const read = blob.type === 'image/png' ? blob.arrayBuffer().then((b) => { const v = new DataView(b); return [v.getUint32(16), v.getUint32(20)]; }) : blob.text();
      read.then((content) => { got.push({ name, type: blob.type, content }); if (got.length === 2) done(JSON.stringify({ got, canvas: [$('canvas').width, $('canvas').height], state: app.session.stateJson() })); });
    };
    $('save-png').click();
    $('save-session').click();
  })`));
  const png = saved.got.find((g) => g.type === 'image/png');
  const session = saved.got.find((g) => g.type === 'application/json');
  check('PngAndSessionDownloads', png && JSON.stringify(png.content) === JSON.stringify(saved.canvas) && /\.png$/.test(png.name) &&
    session && JSON.parse(session.content).format === 'oflab-session' && /\.json$/.test(session.name),
    `${png && png.name} ${png && png.content}, canvas ${saved.canvas}; ${session && session.name}`);
  // A saved session reads back to the same state; a refused one names the file and the field.
  const files = JSON.parse(await evaluate(browser, `(() => {
    app.session.goToLessonStep('timewarp-rotation', 1);
    const before = app.session.stateJson();
    const text = app.session.sessionFileText();
    app.session.setState('{}', 'reset');
    const back = openSessionText(text, 'saved.json') && app.session.stateJson() === before;
    const bad = text.replace('"cadence": 2', '"cadence": -4');
    const refused = !openSessionText(bad, 'broken-session.json');
    return JSON.stringify({ back, refused, message: document.getElementById('message').textContent,
      unchanged: app.session.stateJson() === before, format: JSON.parse(text).format });
  })()`));
  check('ASavedSessionReadsBackToTheSameState', files.back && files.format === 'oflab-session', files.format);
  check('ARefusedSessionNamesTheFileAndFieldAndChangesNothing', files.refused && files.unchanged && /broken-session\.json.*cadence/.test(files.message), files.message);
}

// --- Speed -------------------------------------------------------------------------------
// Each view twice: paced, as a 60 Hz display shows it (requestAnimationFrame at most 60 a
// second, so 60 is the most this can show), and unpaced (Chromium's frame-rate limit and
// vsync off), which shows how many frames a second the page can make.
const kUnpacedFlags = ['--disable-gpu-vsync', '--disable-frame-rate-limit'];
// The views benchmarked: [name as printed, the page's query].
const kBenchViews = [['flow', '?bench=flow'], ['world', '?bench=world'],
  ['animation', '?bench=animation&script=swing&display=comparison'],
  // The street comparison: the lesson when-reuse-pays's state (perspective beside re-rendering).
  ['animation-street', '?lesson=when-reuse-pays&bench=animation']];
async function benchViews(browser, pace) {
  for (const [view, query] of kBenchViews) {
    await open(browser, query, doneMarker('bench'), 300);
    const r = JSON.parse(await evaluate(browser, "document.getElementById('bench').textContent"));
    console.log(`bench ${view} (${pace}): ${r.fps.toFixed(1)} fps over ${r.frames} frames (frame time median ${r.median_ms.toFixed(1)} ms, ` +
      `95th percentile ${r.p95_ms.toFixed(1)} ms; the page's work median ${r.median_work_ms.toFixed(1)} ms, ` +
      `95th percentile ${r.p95_work_ms.toFixed(1)} ms) at ${r.width} x ${r.height}, load average ${os.loadavg()[0].toFixed(1)}`);
  }
}

// Time to interactive: the page opened in a Chromium started afresh (a new profile, so no
// code cached from an earlier visit), then opened again in the same browser, `rounds` times;
// each line gives the page's own figures (ms from the navigation's start): its load event,
// its module ready, its first frame drawn with the controls live.
async function benchStartup(rounds = 5) {
  const figures = { first: [], again: [] };
  for (let round = 0; round < rounds; ++round) {
    const fresh = await launchChromium();
    try {
      for (const visit of ['first', 'again']) {
        if (visit === 'again') await fresh.tab('Page.navigate', { url: 'about:blank' });
        await open(fresh, '', "document.body.dataset.interactive !== undefined");
        const t = JSON.parse(await evaluate(fresh,
          'JSON.stringify({ interactive: app.interactiveMs, module: app.timings.module_ms, load: app.timings.load_event_ms })'));
        figures[visit].push(t.interactive);
        console.log(`bench startup round ${round + 1}, ${visit} visit: interactive ${t.interactive.toFixed(0)} ms ` +
          `(load event ${t.load} ms, module ready ${t.module} ms), load average ${os.loadavg()[0].toFixed(1)}`);
      }
    } finally {
      await fresh.close();
    }
  }
  const median = (xs) => xs.slice().sort((a, b) => a - b)[Math.floor(xs.length / 2)];
  console.log(`bench startup: time to interactive median ${median(figures.first).toFixed(0)} ms on a first visit ` +
    `(largest ${Math.max(...figures.first).toFixed(0)}), ${median(figures.again).toFixed(0)} ms on a second ` +
    `(largest ${Math.max(...figures.again).toFixed(0)}), ${rounds} rounds`);
}

async function bench(browser) {
  await benchStartup();
  await benchViews(browser, 'paced at 60 Hz');
  const unpaced = await launchChromium(kUnpacedFlags);
  try {
    await benchViews(unpaced, 'unpaced');
  } finally {
    await unpaced.close();
  }
}

(async () => {
  if (!fs.existsSync(page)) {
    console.error(`${page}: missing; build it with tools/build-web.sh`);
    process.exit(2);
  }
  const size = fs.statSync(page).size;
  check('PageIsAtMost6MB', size <= 6 * 1024 * 1024, `${size} bytes`);
  const browser = await launchChromium();
  try {
    if (args.includes('--bench')) {
      await bench(browser);
    } else {
      await testSelftest(browser);
      await testScreenshots(browser);
      await testWorld(browser);
      const helpers = { browser, open, evaluate, check, drawnMarker, cli: path.resolve(option('--cli', path.join(root, 'build/analysis/oflab-cli'))) };
      await testSlicesView(helpers);
      await testSceneWorld(helpers);
      await testWorldLabels(helpers);
      await testAnalysisCharts(helpers);
      await testEngineCharts(helpers);
      await testDisplays(helpers);
      await testRunCsv(helpers);
      await testVideo(helpers);
      await testFlowTexture(helpers);
      await testWorldFrame(helpers);
      await testPanelFraming(helpers);
      await testControls(browser);
      await testExplorer(browser);
      await testLessonStates(browser);
      await testClaims(browser);
      await testLinks(browser);
      await testStudy(browser);
      await testStudyTrial(browser);
    }
  } catch (error) {
    check('TheTestsRan', false, error.message);
  } finally {
    await browser.close();
  }
  console.log(failures ? `${failures} failed` : 'all passed');
  process.exit(failures ? 1 : 0);
})();
