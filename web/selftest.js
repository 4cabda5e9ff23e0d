'use strict';
// The page's self-test and benchmark (manual/web.md; tests/web/web_test.js reads both).
//
// ?selftest runs every shipped motion script through the engine with the default settings
// (as `oflab-cli animate --script NAME`) and writes one JSON object into #selftest:
//   {"passed": bool, "scripts": {NAME: {"levels": [...], "coefficients": {...}}},
//    "bad_files": {"script": message, "lesson": message}}
// "passed" says every script ran and both broken files were refused with a message; the
// test compares the levels and coefficients with the CLI's golden outputs.
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

function runSelftest() {
  const result = { passed: true, scripts: {}, bad_files: {} };
  for (const name of JSON.parse(Module.Session.scriptNamesJson())) {
    const run = JSON.parse(Module.Session.scriptRunJson(name));
    if (run.error) result.passed = false;
    result.scripts[name] = run;
  }
  // Broken files must be refused with the reader's message naming the file.
  const session = app.session;
  result.bad_files.script = session.addScript('{"format": "oflab-script", "version": 1, "camera": 3}', 'broken-script.json');
  const lesson = JSON.parse(Module.Session.lessonFileJson('{"format": "oflab-lesson", "version": 1, "name": "x"', 'broken-lesson.json'));
  result.bad_files.lesson = lesson.error || '';
  for (const [file, message] of [['broken-script.json', result.bad_files.script], ['broken-lesson.json', result.bad_files.lesson]]) {
    if (!message.includes(file)) result.passed = false;
  }
  finish('selftest', result);
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
