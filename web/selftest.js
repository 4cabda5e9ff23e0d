'use strict';
// The page's self-test and benchmark (manual/web.md; tests/web/web_test.js reads both).
//
// ?selftest, once the page is interactive, runs every shipped motion script through the
// engine with the default settings (as `oflab-cli animate --script NAME`), plays every step
// of every lesson and each view, and writes one JSON object into #selftest:
//   {"passed": bool, "time_to_interactive_ms": ms from navigation to controls live,
//    "scripts": {NAME: {"levels": [...], "coefficients": {...}}},
//    "bad_files": {"script": message, "lesson": message},
//    "lessons": {NAME: [per part: {"frame", "state", "exact_frame_fnv1a", "claims"}]},
//    "views": {VIEW: {"paced_fps", "unpaced_fps", "median_work_ms"}}}
// "passed" says every script ran, both broken files were refused with a message, every
// lesson part showed and every engine claim held; the test compares the levels and
// coefficients with the CLI's golden outputs and the lessons with `oflab-cli lesson`.
//
// ?bench=flow|animation plays that view, stepping one frame and drawing it on every
// animation frame for kBenchFrames frames after kBenchWarmUp, and writes
// {"view", "frames", "fps", "median_ms", "p95_ms", "median_work_ms", "p95_work_ms", "width",
// "height"} into #bench: the frame times are those of requestAnimationFrame, so the figure
// is what the screen shows; the work is the time the page's own frame (core's step and the
// drawing calls) takes inside it, the headroom left within 16.7 ms.

const kBenchFrames = 300;
const kBenchWarmUp = 30;

function finish(id, object) {
  const out = $(id);
  out.textContent = JSON.stringify(object);
  out.hidden = false;
  out.dataset.done = 'true';
}

async function runSelftest() {
  const result = { passed: true, time_to_interactive_ms: Math.round(app.interactiveMs), startup: app.timings, scripts: {}, bad_files: {} };
  for (const name of JSON.parse(Module.Session.scriptNamesJson())) {
    const run = JSON.parse(Module.Session.scriptRunJson(name));
    if (run.error) result.passed = false;
    result.scripts[name] = run;
  }
  // Broken files must be refused with the reader's message naming the file.
  const session = app.session;
  result.bad_files.script = JSON.parse(session.addScript('{"format": "oflab-script", "version": 1, "camera": 3}', 'broken-script.json')).error || '';
  const lesson = JSON.parse(Module.Session.lessonFileJson('{"format": "oflab-lesson", "version": 1, "name": "x"', 'broken-lesson.json'));
  result.bad_files.lesson = lesson.error || '';
  for (const [file, message] of [['broken-script.json', result.bad_files.script], ['broken-lesson.json', result.bad_files.lesson]]) {
    if (!message.includes(file)) result.passed = false;
  }
  result.lessons = selftestLessons(result);
  result.views = await selftestViews();
  finish('selftest', result);
}

// Every step of every lesson as the page shows it: the state (a session's state object), its
// frame, a hash of the comparison's exact frame where the state plays an engine source
// (FNV-1a over the 160 x 120 panel's RGBA bytes; null when nothing plays) and the engine
// claims measured on the page ("line": as `oflab-cli lesson check` prints it).
function selftestLessons(result) {
  const lessons = {};
  for (const lesson of app.lessons) {
    const steps = [];
    for (let k = 0; k <= lesson.steps.length; ++k) {
      const problem = app.session.goToLessonStep(lesson.name, k);
      if (problem) { result.passed = false; steps.push({ error: problem }); continue; }
      const state = JSON.parse(app.session.stateJson());
      const claims = JSON.parse(app.session.checkClaimsJson()).filter((c) => c.source === 'engine');
      if (claims.some((c) => !c.holds)) result.passed = false;
      steps.push({ frame: state.frame, state, exact_frame_fnv1a: exactFrameHash(), claims: claims.map((c) => c.line) });
    }
    lessons[lesson.name] = steps;
  }
  return lessons;
}

function exactFrameHash() {
  if (app.session.comparisonProblem()) return null;
  JSON.parse(app.session.updateComparison(160, 120));
  const pixels = app.session.runPixels(app.session.runCount() - 1);
  let h = 0x811c9dc5;
  for (let i = 0; i < pixels.length; ++i) h = Math.imul(h ^ pixels[i], 0x01000193) >>> 0;
  return h.toString(16).padStart(8, '0');
}

// Per view (the world view in 3D; the gallery and the explorer; the charts and the comparison on the swing
// script; the comparison on the street scene; the scene-shifting view): frames a second
// of requestAnimationFrame over kViewFrames frames (after kViewWarmUp) stepping and drawing (paced by the
// display), and the frames a second the page's own work per frame allows (1000 / its
// median in ms: what an unpaced display could show).
const kViewFrames = 30;
const kViewWarmUp = 5;
async function selftestViews() {
  const views = {};
  const cases = [['flow', { view: 'flow' }], ['world', { view: 'world' }], ['basis', { view: 'basis' }],
    ['explorer', { view: 'basis', basis: { explorer: true } }],
    ['analysis', { view: 'analysis', script: 'swing' }],
    ['animation', { view: 'animation', script: 'swing' }],
    ['animation-street', { view: 'animation', animation: { source: { kind: 'scene', name: 'street', viewer: 'walk' } } }],
    ['slices', { view: 'slices' }]];
  for (const [name, state] of cases) {
    app.session.setState(JSON.stringify(state), 'selftest');
    app.state = JSON.parse(app.session.stateJson());
    syncControls();
    const times = [];
    const work = [];
    let last = 0;
    let frames = 0;
    await new Promise((done) => {
      function frame(now) {
        const start = performance.now();
        if (++frames > kViewWarmUp) times.push(now - last);
        last = now;
        seek(app.state.frame + 1);
        draw();
        if (frames > kViewWarmUp) work.push(performance.now() - start);
        if (times.length < kViewFrames) requestAnimationFrame(frame); else done();
      }
      requestAnimationFrame(frame);
    });
    const median = (a) => a.slice().sort((x, y) => x - y)[Math.floor(a.length / 2)];
    views[name] = { paced_fps: 1000 * times.length / times.reduce((a, b) => a + b, 0), unpaced_fps: 1000 / median(work), median_work_ms: median(work) };
  }
  return views;
}

function runBench(view) {
  if (!(view in app.views)) {
    finish('bench', { error: `no view '${view}' (views: ${Object.keys(app.views).join(', ')})` });
    return;
  }
  editState((s) => { s.view = view; });
  const times = [];
  const work = [];
  let last = 0;
  let frames = 0;
  function benchFrame(now) {
    const start = performance.now();
    if (frames > kBenchWarmUp) times.push(now - last);
    last = now;
    ++frames;
    seek(app.state.frame + 1);
    draw();
    if (frames > kBenchWarmUp + 1) work.push(performance.now() - start);
    if (frames <= kBenchWarmUp + kBenchFrames) {
      requestAnimationFrame(benchFrame);
      return;
    }
    const sorted = times.slice().sort((a, b) => a - b);
    const sortedWork = work.slice().sort((a, b) => a - b);
    const total = times.reduce((a, b) => a + b, 0);
    const canvas = $('canvas');
    finish('bench', {
      view,
      frames: times.length,
      fps: 1000 * times.length / total,
      median_ms: sorted[Math.floor(sorted.length / 2)],
      p95_ms: sorted[Math.floor(0.95 * (sorted.length - 1))],
      median_work_ms: sortedWork[Math.floor(sortedWork.length / 2)],
      p95_work_ms: sortedWork[Math.floor(0.95 * (sortedWork.length - 1))],
      width: window.innerWidth,
      height: window.innerHeight,
      canvas: [canvas.width, canvas.height],
    });
  }
  requestAnimationFrame(benchFrame);
}
