'use strict';
// The page's state and controls (manual/web.md). The state is the window state of the
// desktop (session/state/window_state.h) as JSON; core owns it: every change goes through
// Session.setState, which checks it with the session reader, and the page reads it back.
// Views (flow_view.js, basis_view.js, comparison_view.js, analysis_view.js, slices_view.js) draw the state on one
// 2D canvas; the world view (world_view.js) draws with vtk.js on its own WebGL canvas over it.

const app = {
  module: null,    // the WebAssembly module of core (createOflabModule)
  session: null,   // its Session (web/web_session.h)
  state: null,     // the state object, as core last accepted it
  views: {},       // name -> {title, draw(ctx, width, height, style)}
  playing: false,
  lastStep: 0,     // time of the last played frame, ms
  dirty: true,     // the canvas needs drawing
  schema: [],      // the state's field table (Session.stateSchemaJson)
  lessons: [],     // lessons as web_session.h lessons_json gives them
  lesson: null,    // the lesson shown, and its step (0: the narrative)
  lessonStep: 0,
};

function $(id) { return document.getElementById(id); }

// Sets an element's HTML only when it changed, so a view redrawn every frame does not make
// the browser lay the page out again for the same table.
function setHtml(element, html) {
  if (element.dataset.html !== html) {
    element.innerHTML = html;
    element.dataset.html = html;
  }
}

// Shows `text` in the message bar (and keeps the page working); empty text hides it.
function showMessage(text) {
  const bar = $('message');
  bar.textContent = text || '';
  bar.hidden = !text;
}

// Reads `object` over the default state through core's session reader. On refusal the
// previous state stays and the reader's message (file, field, limit) is shown.
function applyState(object, origin) {
  const problem = app.session.setState(JSON.stringify(object), origin || 'page');
  if (problem) {
    showMessage(problem);
    return false;
  }
  app.state = JSON.parse(app.session.stateJson());
  syncControls();
  app.dirty = true;
  return true;
}

// A copy of the state with `change(copy)` applied, then applied.
function editState(change, origin) {
  const next = JSON.parse(JSON.stringify(app.state));
  change(next);
  if (applyState(next, origin)) showMessage('');
}

function seek(frame) {
  app.session.seek(frame);
  app.state.frame = app.session.frame();
  app.dirty = true;
  syncFrame();
}

function setPlaying(playing) {
  app.playing = playing;
  $('play').innerHTML = playing ? '&#10074;&#10074; Pause' : '&#9654; Play';
  app.lastStep = performance.now();
}

function syncFrame() {
  const frames = app.session.frameCount();
  $('scrub').max = String(frames - 1);
  $('scrub').value = String(app.state.frame);
  $('frame-label').textContent = `frame ${app.state.frame} / ${frames - 1}`;
}

function syncControls() {
  const s = app.state;
  document.body.dataset.view = shownView();
  document.body.classList.toggle('presentation', s.presentation);
  $('presentation').classList.toggle('active', s.presentation);
  for (const b of document.querySelectorAll('#views button')) {
    b.classList.toggle('active', b.dataset.view === s.view);
  }
  $('script').value = s.script;
  syncSourcePickers(s);
  $('basis-kind').value = s.basis.kind;
  if (app.views.flow) app.views.flow.syncControls(s);
  if (app.explorer) app.explorer.syncControls(s);
  if (app.views.analysis) app.views.analysis.syncControls(s);
  if (app.views.animation) app.views.animation.syncControls(s);
  syncPoseControls(s);
  syncFrame();
}

// The fields of the state, from the one field table of the teaching layer
// (session/state/state_fields.h, Session.stateSchemaJson): name, type, range, default, doc.
function stateField(name) {
  return app.schema.find((f) => f.name === name);
}

// The names a field of type "name" allows: its range, "one of a, b, c".
function fieldNames(name) {
  return stateField(name).range.replace(/^one of /, '').split(', ');
}

// The pose and motion of the plane (the state's "plane" object), edited field by field:
// every [x, y, z] field of plane.pose and plane.motion, labelled by its name and unit.
function poseFields() {
  return app.schema.filter((f) => f.type === '[x, y, z]' && /^plane\.(pose|motion)\./.test(f.name))
    .map((f) => {
      const [, group, key] = f.name.split('.');
      const unit = /\d\s+(\S+)$/.exec(f.range);
      return [key[0].toUpperCase() + key.slice(1) + (unit ? ` ${unit[1]}` : ''), group, key];
    });
}

function buildPoseControls() {
  const grid = $('pose-controls');
  for (const [label, group, key] of poseFields()) {
    const name = document.createElement('span');
    name.textContent = label;
    grid.appendChild(name);
    for (let i = 0; i < 3; ++i) {
      const input = document.createElement('input');
      input.type = 'number';
      input.step = '0.05';
      input.id = `pose-${key}-${i}`;
      input.addEventListener('change', () => editState((s) => {
        s.plane[group][key][i] = Number(input.value);
      }, 'pose and motion'));
      grid.appendChild(input);
    }
  }
  const model = document.createElement('span');
  model.textContent = 'Motion model';
  const select = document.createElement('select');
  select.id = 'pose-model';
  for (const m of fieldNames('plane.motion.model')) select.add(new Option(m, m));
  select.addEventListener('change', () => editState((s) => { s.plane.motion.model = select.value; }));
  grid.append(model, select);
}

function syncPoseControls(s) {
  for (const [, group, key] of poseFields()) {
    for (let i = 0; i < 3; ++i) $(`pose-${key}-${i}`).value = String(+s.plane[group][key][i].toFixed(4));
  }
  $('pose-model').value = s.plane.motion.model;
  $('pose-motion').title = s.script ? 'The script moves the plane; these are the plane\'s own pose and motion' : '';
}

// A file the user opened: a motion script, a lesson or a session, read by core's readers; anything
// else, or a file they refuse, gives a message naming the file.
function openFile(file) {
  file.text().then((text) => {
    let format = '';
    try { format = JSON.parse(text).format || ''; } catch (e) { format = ''; }
    if (format === 'oflab-lesson') {
      const lesson = JSON.parse(Module.Session.lessonFileJson(text, file.name));
      if (lesson.error) { showMessage(lesson.error); return; }
      app.lessons = app.lessons.filter((l) => l.name !== lesson.name).concat([lesson]);
      fillLessonPicker();
      startLesson(lesson.name);
      return;
    }
    if (format === 'oflab-session') {
      openSessionText(text, file.name);
      return;
    }
    // Scripts, and whatever is not a lesson or a session: the script reader names the problem.
    const added = JSON.parse(app.session.addScript(text, file.name));
    if (added.error) { showMessage(added.error); return; }
    const name = added.path;
    if (![...$('script').options].some((o) => o.value === name)) $('script').add(new Option(file.name, name));
    editState((s) => { s.script = name; s.frame = 0; }, file.name);
  }, (error) => showMessage(`${file.name}: cannot read the file (${error})`));
}

function bindControls() {
  for (const b of document.querySelectorAll('#views button')) {
    b.addEventListener('click', () => editState((s) => { s.view = b.dataset.view; }));
  }
  $('presentation').addEventListener('click', () => editState((s) => { s.presentation = !s.presentation; }));
  $('play').addEventListener('click', () => setPlaying(!app.playing));
  $('step').addEventListener('click', () => seek(app.state.frame + 1));
  $('step-back').addEventListener('click', () => seek(app.state.frame - 1));
  $('scrub').addEventListener('input', () => seek(Number($('scrub').value)));
  $('script').addEventListener('change', () => editState((s) => {
    s.script = $('script').value;
    s.animation.source = { kind: 'plane', name: '', viewer: '' };
    s.frame = 0;
  }));
  $('basis-kind').addEventListener('change', () => editState((s) => { s.basis.kind = $('basis-kind').value; }));
  $('lesson').addEventListener('change', () => startLesson($('lesson').value));
  $('lesson-next').addEventListener('click', () => showLessonStep(app.lessonStep + 1));
  $('lesson-prev').addEventListener('click', () => showLessonStep(app.lessonStep - 1));
  $('open-file').addEventListener('change', (e) => {
    if (e.target.files.length) openFile(e.target.files[0]);
    e.target.value = '';
  });
  document.addEventListener('keydown', onKey);
  window.addEventListener('resize', () => { app.dirty = true; });
}

// Space plays and pauses; the arrows step (Up and Down by ten frames); Home and End go to
// the first and the last frame; Page Down and Page Up step through a lesson; 1-6 pick a view,
// P the presentation mode.
function onKey(e) {
  // The study panel takes its own keys (study_view.js), but Page Down and Page Up still step
  // a lesson (a lesson's step may have opened the panel).
  const lessonKey = app.lesson && (e.key === 'PageDown' || e.key === 'PageUp');
  if (studyOpen() && !lessonKey) return;
  if (e.target.tagName === 'INPUT' && e.target.type !== 'range') return;
  if (e.target.tagName === 'SELECT') return;
  const frame = app.state.frame;
  const keys = {
    ' ': () => setPlaying(!app.playing),
    ArrowRight: () => seek(frame + 1),
    ArrowLeft: () => seek(frame - 1),
    ArrowUp: () => seek(frame + 10),
    ArrowDown: () => seek(frame - 10),
    Home: () => seek(0),
    End: () => seek(app.session.frameCount() - 1),
    PageDown: () => app.lesson && showLessonStep(app.lessonStep + 1),
    PageUp: () => app.lesson && showLessonStep(app.lessonStep - 1),
    1: () => editState((s) => { s.view = 'flow'; }),
    2: () => editState((s) => { s.view = 'basis'; }),
    3: () => editState((s) => { s.view = 'animation'; }),
    4: () => editState((s) => { s.view = 'analysis'; }),
    5: () => editState((s) => { s.view = 'world'; }),
    6: () => editState((s) => { s.view = 'slices'; }),
    p: () => editState((s) => { s.presentation = !s.presentation; }),
  };
  const action = keys[e.key];
  if (action) {
    e.preventDefault();
    action();
  }
}

// Drawing style: line widths and text sizes, doubled in presentation mode.
function drawStyle() {
  const k = app.state.presentation ? 2 : 1;
  return { line: k, font: (px) => `${Math.round(px * k)}px system-ui, sans-serif`, scale: k };
}

function draw() {
  const canvas = $('canvas');
  const w = Math.max(1, Math.floor(canvas.clientWidth));
  const h = Math.max(1, Math.floor(canvas.clientHeight));
  if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
  // Opaque: the browser composites the canvas without blending it over the page.
  const ctx = canvas.getContext('2d', { alpha: false });
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = '#111315';
  ctx.fillRect(0, 0, w, h);
  const view = app.views[shownView()];
  try {
    view.draw(ctx, w, h, drawStyle());
    if (!(app.state.view in app.views)) {
      // A state (a lesson's) may name a view of the desktop window that the page lacks.
      ctx.fillStyle = '#e6c35a';
      ctx.font = drawStyle().font(14);
      ctx.fillText(`The ${app.state.view} view is in the desktop window only; this is the ${view.title} view.`, 12, h - 10);
    }
  } catch (error) {
    showMessage(`The ${app.state.view} view could not draw: ${error.message || error}`);
  }
  // Frames drawn so far: the tests wait for the first before taking a screenshot.
  document.body.dataset.drawn = String(Number(document.body.dataset.drawn || 0) + 1);
}

// The page's view for the state's: a view of the desktop window the page lacks shows as the
// flow view (draw says so on the picture).
function shownView() {
  const view = app.state.view;
  if (view in app.views) return view;
  return 'flow';
}

// One frame of the page: plays at the state's play rate, draws when something changed.
function tick(now) {
  if (app.playing && now - app.lastStep >= 1000 / app.state.play_rate - 1) {
    app.lastStep = now;
    seek(app.state.frame + 1);
  }
  if (app.dirty) {
    app.dirty = false;
    draw();
  }
  requestAnimationFrame(tick);
}

function fillScriptPicker() {
  for (const name of JSON.parse(Module.Session.scriptNamesJson())) $('script').add(new Option(name, name));
}

// Options from the URL: view=flow|world|basis|animation|analysis|slices, script=NAME,
// source=KIND:NAME:VIEWER (the animation's source, e.g. scene:street:walk), frame=N,
// lesson=NAME, step=K, presentation, explorer (the basis view's explorer), display=NAME (the
// animation's display: comparison makes the analysis view chart the compared policies);
// applied over the default state (the screenshot tests use them). With a lesson, only
// presentation applies besides step: it is the teacher's look, which the lesson's steps keep
// (as `oflab --lesson NAME --presentation`).
function applyUrlOptions(params) {
  if (params.has('lesson')) {
    if (params.has('presentation')) editState((s) => { s.presentation = true; }, 'the page address');
    startLesson(params.get('lesson'));
    if (params.has('step')) showLessonStep(Number(params.get('step')));
    return;
  }
  editState((s) => {
    if (params.has('view')) s.view = params.get('view');
    if (params.has('script')) { s.script = params.get('script'); }
    if (params.has('source')) {
      const [kind, name = '', viewer = ''] = params.get('source').split(':');
      s.animation.source = { kind, name, viewer };
    }
    if (params.has('presentation')) s.presentation = true;
    if (params.has('explorer')) s.basis.explorer = true;
    if (params.has('display')) s.animation.display = params.get('display');
  }, 'the page address');
  if (params.has('frame')) seek(Number(params.get('frame')));
}

async function start() {
  try {
    app.module = await createOflabModule();
    window.Module = app.module;
    app.session = new Module.Session();
    app.moduleMs = performance.now();
  } catch (error) {
    showMessage(`oflab could not start its WebAssembly module: ${error.message || error}`);
    return;
  }
  const params = new URLSearchParams(location.search);
  app.defaultState = JSON.parse(app.session.stateJson());
  app.timings = { module_ms: Math.round(app.moduleMs), load_event_ms: Math.round(performance.getEntriesByType('navigation')[0]?.loadEventStart || 0) };
  app.state = JSON.parse(app.session.stateJson());
  app.schema = JSON.parse(Module.Session.stateSchemaJson());
  buildPoseControls();
  for (const view of Object.values(app.views)) if (view.build) view.build();
  bindControls();
  bindShareControls();
  bindStudyControls();
  fillScriptPicker();
  loadLessons();
  syncControls();
  applyUrlOptions(params);
  applyStudyUrlOptions(params);
  const fragment = location.hash.slice(1);
  document.body.classList.toggle('embed', fragment.split('&').includes('embed'));
  if (fragment) {
    const problem = await openLink(fragment);
    if (problem) showMessage(problem);
  }
  if (params.has('bench')) { runBench(params.get('bench')); return; }
  draw();
  app.dirty = false;
  app.interactiveMs = performance.now();
  document.body.dataset.interactive = String(Math.round(app.interactiveMs));
  requestAnimationFrame(tick);
  if (params.has('selftest')) runSelftest();
}

window.addEventListener('load', start);
window.addEventListener('hashchange', () => {
  document.body.classList.toggle('embed', location.hash.slice(1).split('&').includes('embed'));
  openLink(location.hash.slice(1)).then((problem) => { if (problem) showMessage(problem); });
  app.dirty = true;
});
