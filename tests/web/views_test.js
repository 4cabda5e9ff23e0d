'use strict';
// The page's scene-shifting view and a scene's world view (manual/web.md), run by
// web_test.js with its browser and helpers ({ browser, open, evaluate, check, drawnMarker,
// cli }).
//
// - The scene-shifting view (Module.Slices: session/player/slice_walk.h): its slices and
//   asymptote are `oflab-cli slices`'s for the walk's focal length, nearest depth, epsilon and
//   speed, to 1e-12 relative, at two epsilons; the CLI's slices for another epsilon are not the
//   page's (negative control); the depth ticks are 1-2-5 steps up to the diagram's depth; the
//   walk follows the play bar's frame and says when it repeats; both frames are drawn.
// - A scene's world (session/display/world_geometry.h scene_world_loop and _frame): the
//   street's 13 polygons with the walk's path, the eye on its path at the frame shown, the
//   polygons in the levels' colours (culled ones pale), the scene's caption; the plane's
//   world is still the plane's (negative control).
// - The analysis charts: the error and cost-model work charts and the level bands
//   are drawn; each compared run's work per frame is `oflab-cli animate --script swing --mode
//   POLICY`'s model_work column (6 significant digits, as the CSV prints); the two policies'
//   works differ (negative control).
// - The world view's labels (Module.placeLabels: session/display/label_layout.h, the desktop's
//   rule), for the plane and the street: no two overlap, each lies inside the picture above the
//   caption band and next to its point; a request of the wrong form is refused naming the field
//   (negative control).
const fs = require('fs');
const path = require('path');
const { spawnSync } = require('child_process');

const root = path.resolve(__dirname, '..', '..');
const kRelative = 1e-12;
const close = (a, b) => a === b || Math.abs(a - b) <= kRelative * Math.max(Math.abs(a), Math.abs(b));

// `oflab-cli slices --json` for the diagram's focal length, nearest depth and `epsilon`, `speed`.
function cliSlices(cli, diagram, epsilon, speed) {
  const r = spawnSync(cli, ['slices', '--speed', String(speed), '--focal', String(diagram.focal_px),
    '--epsilon', String(epsilon), '--near', String(diagram.slices[0].near), '--json'], { encoding: 'utf8' });
  return r.status === 0 ? JSON.parse(r.stdout) : { error: r.stderr.trim() };
}

// Differences between the page's diagram and the CLI's slices, one line each.
function slicesProblems(diagram, cli) {
  if (cli.error) return [`oflab-cli: ${cli.error}`];
  const problems = [];
  if (diagram.slices.length !== cli.slices.length) problems.push(`${diagram.slices.length} slices, the CLI's ${cli.slices.length}`);
  diagram.slices.forEach((s, k) => {
    const c = cli.slices[k];
    if (!c || !close(s.near, c.near) || !(s.far === c.far || close(s.far, c.far))) problems.push(`slice ${k}: ${JSON.stringify(s)}, the CLI's ${JSON.stringify(c)}`);
  });
  if (!close(diagram.asymptote, cli.asymptote)) problems.push(`asymptote ${diagram.asymptote}, the CLI's ${cli.asymptote}`);
  return problems;
}

// 1, 2 and 5 times powers of ten up to `max` (computed here, not by the page).
function expectedTicks(max) {
  const ticks = [];
  for (let decade = 1; decade <= max; decade *= 10) for (const step of [1, 2, 5]) if (step * decade <= max) ticks.push(step * decade);
  return ticks;
}

async function testSlicesView({ browser, open, evaluate, check, drawnMarker, cli }) {
  await open(browser, '?view=slices&frame=10', drawnMarker);
  const read = async (epsilon, frame) => JSON.parse(await evaluate(browser, `(() => {
    if (${epsilon} > 0) { $('slices-epsilon').value = '${epsilon}'; $('slices-epsilon').dispatchEvent(new Event('input')); }
    if (${frame} >= 0) seek(${frame});
    draw();
    const pixels = [0, 1].map((k) => slicesView.images[k] ? slicesView.images[k].data.some((v, i) => i % 4 !== 3 && v > 40) : false);
    return JSON.stringify({ info: slicesView.info, view: document.body.dataset.view, pixels, message: $('message').textContent });
  })()`));
  const first = await read(0, -1);
  const d = first.info.diagram;
  const atOne = slicesProblems(d, cliSlices(cli, d, 1, 0.05));
  check('SlicesViewShowsTheCliSlicesAndAsymptote', first.view === 'slices' && d.epsilon_px === 1 && d.speed === 0.05 &&
    atOne.length === 0, `${d.slices.length} slices from ${d.slices[0].near.toFixed(3)}, asymptote ${d.asymptote}` +
    `${atOne.length ? `; ${atOne.slice(0, 3).join('; ')}` : ''}${first.message ? `; ${first.message}` : ''}`);
  check('SlicesViewDepthTicksAndRange', d.max_depth === Math.max(50, 1.25 * d.asymptote) &&
    JSON.stringify(d.ticks) === JSON.stringify(expectedTicks(d.max_depth)) && d.planes.length > 0, `${d.ticks} up to ${d.max_depth}`);
  check('SlicesViewFollowsTheFrameAndDrawsBothFrames', first.info.frame === 10 && first.pixels.every(Boolean) &&
    !/repeats/.test(first.info.caption), `${first.info.caption} (pixels drawn: ${first.pixels})`);
  const second = await read(2, first.info.frame_count + 10);
  const atTwo = slicesProblems(second.info.diagram, cliSlices(cli, second.info.diagram, 2, 0.05));
  check('SlicesViewRecutsForItsEpsilonAsTheCli', atTwo.length === 0 && second.info.diagram.epsilon_px === 2 &&
    second.info.frame === 10 && /walk repeats/.test(second.info.caption),
  `${second.info.diagram.slices.length} slices at epsilon 2; ${second.info.caption}${atTwo.length ? `; ${atTwo.slice(0, 3).join('; ')}` : ''}`);
  // Negative control: the CLI's slices for epsilon 1 are not the page's at epsilon 2.
  check('NegativeControl_SlicesOfAnotherEpsilonDiffer', slicesProblems(second.info.diagram, cliSlices(cli, d, 1, 0.05)).length > 0);
}

async function testSceneWorld({ browser, open, evaluate, check, drawnMarker }) {
  await open(browser, '?view=world&source=scene:street:walk&frame=20', drawnMarker);
  const got = JSON.parse(await evaluate(browser, `JSON.stringify({ loop: JSON.parse(app.session.worldLoopJson()),
    frame: JSON.parse(app.session.worldFrameJson()), caption: worldView.loop.caption, levels: Module.levelColours(),
    actors: worldView.world.renderer.getActors().length, message: $('message').textContent })`));
  const street = JSON.parse(fs.readFileSync(path.join(root, 'datasets/scenes/street.json'), 'utf8'));
  const { loop, frame } = got;
  const eyeOnPath = loop.path[frame.path_index].every((v, i) => Math.abs(v - frame.eye[i]) <= 1e-12 * Math.max(1, Math.abs(v)));
  // The eye at the viewer matrix's origin: its last column.
  const origin = [3, 7, 11].map((i) => frame.viewer_matrix[i]);
  const atOrigin = origin.every((v, i) => Math.abs(v - frame.eye[i]) <= 1e-9 * Math.max(1, Math.abs(v)));
  check('SceneWorldShowsTheScenesPolygonsAndTheViewersPath', loop.kind === 'scene' && loop.outlines.length === street.polygons.length &&
    loop.path.length > 1 && frame.frame === 20 && frame.path_index === 20 && eyeOnPath && atOrigin &&
    !/desktop window only/.test(got.caption) && /walks through the scene/.test(got.caption),
  `${loop.outlines.length} polygons (the file's ${street.polygons.length}), ${loop.path.length} path points, ${got.actors} actors` +
    `${got.message ? `; ${got.message}` : ''}`);
  const key = (c) => c.join(',');
  const levels = new Set(Object.values(got.levels).map(key));
  const colours = frame.polygon_colours.map(key);
  check('SceneWorldColoursThePolygonsByLevel', colours.length === street.polygons.length &&
    colours.some((c) => levels.has(c)) && colours.every((c) => levels.has(c) || ['215,215,215', '70,70,70', '0,0,0'].includes(c)),
  colours.join(' '));
  await open(browser, '?view=world&frame=20', drawnMarker);
  const plane = JSON.parse(await evaluate(browser, 'app.session.worldLoopJson()'));
  check('NegativeControl_ThePlanesWorldIsNoScene', plane.kind === 'plane' && !plane.outlines);
}

// The boxes the world view drew its labels in, the picture's size and the caption band's top.
async function worldLabels(evaluate, browser) {
  return JSON.parse(await evaluate(browser, `JSON.stringify({ boxes: worldView.labelBoxes,
    width: worldView.labels.width, height: worldView.labels.height,
    band: worldView.drawCaption(worldView.labels.getContext('2d'), worldView.labels, drawStyle()) })`));
}

// Problems of labels placed: overlaps, boxes outside the picture or in the caption band,
// boxes far from their points; one line each.
function labelProblems({ boxes, width, height, band }) {
  const problems = [];
  const overlap = (a, b) => Math.max(0, Math.min(a[0] + a[2], b[0] + b[2]) - Math.max(a[0], b[0])) *
    Math.max(0, Math.min(a[1] + a[3], b[1] + b[3]) - Math.max(a[1], b[1]));
  boxes.forEach((l, i) => {
    const [x, y, w, h] = l.box;
    if (x < 0 || y < 0 || x + w > width || y + h > Math.min(height, band)) problems.push(`${l.text} at ${l.box} leaves the picture (${width} x ${height}, caption from ${band})`);
    const dx = Math.max(x - l.at[0], 0, l.at[0] - (x + w)), dy = Math.max(y - l.at[1], 0, l.at[1] - (y + h));
    if (Math.hypot(dx, dy) > 20 * h) problems.push(`${l.text} at ${l.box} is far from its point ${l.at}`);
    for (const m of boxes.slice(i + 1)) if (overlap(l.box, m.box) > 0) problems.push(`${l.text} overlaps ${m.text}`);
  });
  return problems;
}

async function testWorldLabels({ browser, open, evaluate, check, drawnMarker }) {
  for (const [name, query] of [['Plane', '?view=world&frame=20'], ['Street', '?view=world&source=scene:street:walk&frame=20']]) {
    await open(browser, query, drawnMarker);
    const labels = await worldLabels(evaluate, browser);
    const problems = labelProblems(labels);
    check(`WorldLabelsOfThe${name}NeitherOverlapNorLeaveThePicture`, labels.boxes.length >= 3 && problems.length === 0,
      `${labels.boxes.length} labels: ${labels.boxes.map((l) => `${l.text} [${l.box.map(Math.round)}]`).join(', ')}${problems.length ? `; ${problems.join('; ')}` : ''}`);
  }
  const refused = JSON.parse(await evaluate(browser, `Module.placeLabels(JSON.stringify({ sizes: [[10, 10]], anchors: [[1, 2, 3]], area: [0, 0, 9, 9] }))`));
  check('NegativeControl_ALabelRequestOfTheWrongFormIsRefused', /anchors/.test(refused.error || ''), JSON.stringify(refused));
}

// `oflab-cli animate --script NAME --mode POLICY`'s model_work column, one number per frame.
// `oflab-cli animate --script SCRIPT --mode POLICY`'s frames.csv as {columns: {name: [per
// frame]}} (numbers, the level's name as text), or {error}.
function cliFrames(cli, script, policy) {
  const dir = fs.mkdtempSync(path.join(require('os').tmpdir(), 'oflab-web-work-'));
  try {
    const r = spawnSync(cli, ['animate', '--script', script, '--mode', policy, '--out', path.join(dir, 'run'),
      '--quiet', '--no-warm-up', '--repeat-timing', '1'], { encoding: 'utf8' });
    if (r.status !== 0) return { error: r.stderr.trim() };
    const rows = fs.readFileSync(path.join(dir, 'run', 'frames.csv'), 'utf8').trim().split('\n');
    const names = rows[0].split(',');
    const columns = {};
    names.forEach((name, c) => {
      columns[name] = rows.slice(1).map((row) => (name === 'level' ? row.split(',')[c] : Number(row.split(',')[c])));
    });
    return { columns };
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

function cliModelWork(cli, script, policy) {
  const r = cliFrames(cli, script, policy);
  return r.error ? r : { work: r.columns.model_work };
}

// The budget of level L (0 none .. 3 perspective) at frame k from the CLI's columns, computed
// apart from core's function: the books carried into frame k (the accumulated errors after
// frame k - 1, or after frame k with `after`, the negative control) plus frame k's flow,
// summed over the terms L .. higher that the level neglects.
function cliBudget(columns, k, level, after = false) {
  const terms = ['translate', 'affine', 'perspective', 'higher'];
  let sum = 0;
  for (let t = level; t < 4; ++t) sum += columns[`err_${terms[t]}`][after ? k : k - 1] + columns[`flow_${terms[t]}`][k];
  return sum;
}

// The engine's charts (the state's display not the comparison layout, as on the desktop):
// each level's budget per frame equals the CLI's books and flow summed apart, the percent
// approximated its level column; control: the books after the frame instead give other values.
async function testEngineCharts({ browser, open, evaluate, check, drawnMarker, cli }) {
  await open(browser, '?view=analysis&script=loop', drawnMarker);
  const got = JSON.parse(await evaluate(browser, `(() => { seek(60); draw();
    return JSON.stringify({ data: JSON.parse(app.session.analysisJson(80)), drawn: analysisView.drawn }); })()`));
  const titles = (got.drawn || []).map((d) => d.title).join(' | ');
  const run = got.data.runs && got.data.runs[0];
  check('TheAnalysisViewDrawsTheEnginesBudgetCharts', !got.data.comparing && run && run.policy === 'perspective' &&
    ['none', 'translate', 'affine', 'perspective'].every((l) => titles.includes(`${l}: error left`)) && /approximated/.test(titles), titles);
  const cliRun = cliFrames(cli, 'loop', 'perspective');
  if (cliRun.error || !run) { check('EachBudgetIsTheCliBooksPlusFlow', false, cliRun.error || 'no run'); return; }
  const problems = [];
  let compared = 0;
  let controlDiffers = false;
  for (const f of run.frames) {
    const k = f.frame;
    const rerender = cliRun.columns.level[k] === 'rerender';
    if (f.approximated_percent !== (rerender ? 0 : 100)) problems.push(`frame ${k}: approximated ${f.approximated_percent}, level ${cliRun.columns.level[k]}`);
    for (let level = 0; level < 4; ++level) {
      const value = f.budgets[level];
      if (k === 0) { if (value !== null) problems.push(`frame 0: budget ${value}, none expected`); continue; }
      const want = cliBudget(cliRun.columns, k, level);
      if (!(Math.abs(value - want) <= 1e-4 * Math.max(1, Math.abs(want)))) problems.push(`frame ${k} level ${level}: ${value}, the CLI's ${want}`);
      if (Math.abs(value - cliBudget(cliRun.columns, k, level, true)) > 1e-3) controlDiffers = true;
      ++compared;
    }
  }
  check('EachBudgetIsTheCliBooksPlusFlow', problems.length === 0 && compared >= 4 * 60, problems.slice(0, 4).join('; ') || `${compared} budgets`);
  check('NegativeControl_TheBooksAfterTheFrameDiffer', controlDiffers);
}

async function testAnalysisCharts({ browser, open, evaluate, check, drawnMarker, cli }) {
  await open(browser, '?view=analysis&script=swing&display=comparison', drawnMarker);
  const got = JSON.parse(await evaluate(browser, `(() => { seek(30); draw();
    return JSON.stringify({ data: JSON.parse(app.session.analysisJson(80)), drawn: analysisView.drawn }); })()`));
  const titles = (got.drawn || []).map((d) => d.title).join(' | ');
  check('TheAnalysisViewDrawsTheErrorTimeAndWorkCharts', got.data.comparing && /measured error/.test(titles) && /frame time/.test(titles) &&
    /cost model/.test(titles) && got.data.runs.length >= 2 && got.data.runs.every((r) => r.frames.every((f) => f.time_ms >= 0)), titles);
  const problems = [];
  for (const run of got.data.runs) {
    const cliRun = cliModelWork(cli, 'swing', run.policy);
    if (cliRun.error) { problems.push(`${run.policy}: ${cliRun.error}`); continue; }
    for (const f of run.frames) {
      const want = cliRun.work[f.frame];
      if (!(Math.abs(f.model_work - want) <= 1e-5 * Math.max(1, Math.abs(want)))) problems.push(`${run.policy} frame ${f.frame}: ${f.model_work}, the CLI's ${want}`);
    }
  }
  check('EachRunsWorkPerFrameIsAnimatesModelWork', problems.length === 0 && got.data.runs.every((r) => r.frames.length === 31),
    problems.slice(0, 4).join('; ') || `${got.data.runs.map((r) => `${r.policy} ${r.frames.length} frames`).join(', ')}`);
  const [p, q] = got.data.runs;
  check('NegativeControl_TwoPoliciesWorkDiffers', p && q && p.frames.some((f, k) => f.model_work !== q.frames[k].model_work));
}

// The animation view's four layouts (the state's display, the desktop's *Show* box): side by
// side shows the model's own engine (the state's mode, perspective) and the exact projection,
// its engine panel pixel for pixel the comparison's run of the same policy at the same panel
// size and its exact panel the comparison's; difference shows that run's heat map; blink shows
// the engine's panel, then the exact one kBlinkMs later, then the engine's again. Control: the
// comparison's affine run is another picture.
async function testDisplays({ browser, open, evaluate, check, drawnMarker }) {
  await open(browser, '?view=animation&script=loop&frame=20', drawnMarker);
  const r = JSON.parse(await evaluate(browser, `(async () => {
    const hash = (a) => { let h = 2166136261; for (let i = 0; i < a.length; ++i) h = Math.imul(h ^ a[i], 16777619); return h >>> 0; };
    const take = (display) => {
      editState((s) => { s.animation.display = display; });
      const info = JSON.parse(app.session.updateComparison(240, 180));
      return { policies: info.runs.map((run) => run.policy), pixels: info.runs.map((run, i) => hash(app.session.runPixels(i))),
        heat: info.runs.slice(0, -1).map((run, i) => hash(app.session.runHeat(i))), frame: info.frame };
    };
    const side = take('side-by-side');
    const diff = take('difference');
    const comp = take('comparison');
    editState((s) => { s.animation.display = 'blink'; });
    const canvas = $('canvas');
    const shot = () => { draw(); return [comparisonView.blinkPhase, hash(canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data)]; };
    const wait = () => new Promise((ok) => setTimeout(ok, kBlinkMs - (performance.now() % kBlinkMs) + 20));
    const blink = [shot()];
    await wait();
    blink.push(shot());
    await wait();
    blink.push(shot());
    return JSON.stringify({ side, diff, comp, blink, select: $('animation-display').value });
  })()`));
  const { side, diff, comp, blink } = r;
  check('SideBySideShowsTheModelsEngineAndTheExactProjection', side.frame === 20 && side.policies.join() === 'perspective,rerender' &&
    comp.policies.join() === 'affine,perspective,rerender' && side.pixels[0] === comp.pixels[1] && side.pixels[1] === comp.pixels[2],
    `side by side ${side.policies}, comparison ${comp.policies}; ${side.pixels} against ${comp.pixels}`);
  check('TheDifferenceLayoutShowsTheEnginesHeatMap', diff.policies.join() === 'perspective,rerender' && diff.heat[0] === comp.heat[1], `${diff.heat} against ${comp.heat}`);
  check('BlinkShowsTheEngineThenTheExactFrameInTurn', blink[0][0] !== blink[1][0] && blink[2][0] === blink[0][0] &&
    blink[0][1] !== blink[1][1] && blink[2][1] === blink[0][1] && r.select === 'blink', JSON.stringify(blink));
  check('NegativeControl_TheAffineRunIsAnotherPicture', comp.pixels[0] !== side.pixels[0]);
}

module.exports = { testSlicesView, testSceneWorld, testWorldLabels, testAnalysisCharts, testEngineCharts, testDisplays };
