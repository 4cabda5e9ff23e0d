'use strict';
// The threshold study on the page (manual/study.md): the desktop window's loop in the module
// (web/web_study.h, `Module.Study`). Set-up (study, method, name, the screen's pixels per inch
// typed or matched to a credit card, seed); trials: the two clips of each request drawn one
// clip pixel to one screen pixel on requestAnimationFrame at 60 frames per second, half a
// second of grey between them, then 1 or 2; a presentation in which a frame was skipped is
// recorded late and shown again; a second of frames before the first trial, refused when any
// is late; results: the thresholds with their intervals, the psychometric plot, the CSV.

const kCardWidthMm = 85.60;  // a credit card's width (ISO/IEC 7810 ID-1)
const kClipRate = 60;        // frames per second (session/study/study_file.h kClipFrameRate)
const kGapMs = 500;

const study = {
  core: null,       // Module.Study
  shipped: [],      // Module.Study.shippedJson()
  fileName: '',     // a study opened from a file: its name and text
  fileText: '',
  phase: 'idle',    // idle, check, first, gap, second, answer
  frame: 0,
  start: 0,         // the phase's first frame time, ms
  late: false,      // a frame of this presentation was late
  lateFrames: 0,
  image: null,      // the canvas's ImageData
};

function studyOpen() { return !$('study-panel').hidden; }

function showStudyPage(name) {
  for (const page of ['setup', 'trial', 'results']) $(`study-${page}`).hidden = page !== name;
}

function fillStudyPicker() {
  study.shipped = JSON.parse(Module.Study.shippedJson());
  const picker = $('study-name');
  picker.innerHTML = '';
  for (const s of study.shipped) picker.add(new Option(s.title, s.name));
  studyChosen();
}

function studyChosen() {
  const s = study.shipped.find((x) => x.name === $('study-name').value);
  if (!s) return;
  study.fileName = '';
  study.fileText = '';
  $('study-description').textContent =
    `${s.description} (${s.conditions.length} conditions, ${s.trials} trials each)`;
  $('study-method').value = s.method;
}

function setPpi(ppi) {
  $('study-ppi').value = ppi.toFixed(1);
  $('study-card').value = String(Math.round(ppi * kCardWidthMm / 25.4));
  $('study-card-bar').style.width = `${Number($('study-card').value) / devicePixelRatio}px`;
}

// The clip canvas at one clip pixel to one screen pixel whatever the page's zoom.
function sizeStudyCanvas() {
  const canvas = $('study-canvas');
  canvas.style.width = `${canvas.width / devicePixelRatio}px`;
  canvas.style.height = `${canvas.height / devicePixelRatio}px`;
}

function drawStudyFrame(clip, frame) {
  const canvas = $('study-canvas');
  const ctx = canvas.getContext('2d');
  if (clip === 0) {
    ctx.fillStyle = 'rgb(128, 128, 128)';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    return;
  }
  if (!study.image) study.image = ctx.createImageData(canvas.width, canvas.height);
  study.image.data.set(study.core.clipFrame(clip, frame));
  ctx.putImageData(study.image, 0, 0);
}

// `core` becomes the study shown unless `problem` says why it cannot (then it is dropped, the
// study shown before stays and the set-up page says why). True when adopted.
function adoptStudyCore(core, problem) {
  if (problem) {
    core.delete();
    $('study-status').textContent = problem;
    return false;
  }
  if (study.core) study.core.delete();
  study.core = core;
  $('study-status').textContent = '';
  return true;
}

function startStudy() {
  const observer = $('study-observer').value.trim();
  if (!observer || /[,\n\r]/.test(observer)) {
    $('study-status').textContent = 'Your name or code: some text without commas.';
    return;
  }
  $('study-status').textContent = 'Measuring the errors the engine shows...';
  setTimeout(() => {  // lets the status show before the ladders run
    const core = new Module.Study();
    const name = study.fileName || $('study-name').value;
    const problem = core.open(name, study.fileText, $('study-method').value,
      Number($('study-seed').value || -1));
    if (!adoptStudyCore(core, problem)) return;
    showStudyPage('trial');
    sizeStudyCanvas();
    study.lateFrames = 0;
    $('study-trial-text').textContent =
      `Checking that this display shows ${kClipRate} frames per second...`;
    setAnswering(false);
    playPhase('check');
  }, 20);
}

function setAnswering(on) {
  $('study-first').disabled = !on;
  $('study-second').disabled = !on;
}

// The phase's clock starts at its first animation frame, which draws its frame 0.
function playPhase(phase) {
  study.phase = phase;
  study.frame = 0;
  study.start = -1;
  requestAnimationFrame(studyTick);
}

// The clock: the frame due is floor(elapsed * rate); one due more than one ahead of the last
// drawn was skipped, and makes the presentation late.
function studyTick(now) {
  if (!studyOpen() || !['check', 'first', 'gap', 'second'].includes(study.phase)) return;
  if (study.start < 0) {
    study.start = now;
    drawStudyFrame(study.phase === 'gap' ? 0 : study.phase === 'second' ? 2 : 1, 0);
    requestAnimationFrame(studyTick);
    return;
  }
  const elapsed = now - study.start;
  if (study.phase === 'gap') {
    if (elapsed >= kGapMs) playPhase('second');
    else requestAnimationFrame(studyTick);
    return;
  }
  const due = Math.floor(elapsed * kClipRate / 1000);
  if (due <= study.frame) { requestAnimationFrame(studyTick); return; }
  const length = study.core.clipLength();
  if (due > study.frame + 1) {  // frames skipped (those past the clip's end not counted)
    study.late = true;
    study.lateFrames += Math.min(due, length) - study.frame - 1;
  }
  study.frame = due;
  if (due >= length) { clipEnded(); return; }
  drawStudyFrame(study.phase === 'second' ? 2 : 1, study.phase === 'check' ? 0 : due);
  requestAnimationFrame(studyTick);
}

function clipEnded() {
  if (study.phase === 'check') {
    if (study.lateFrames > 0) {
      showStudyPage('setup');
      $('study-status').textContent = `This display drew ${study.lateFrames} of ` +
        `${study.core.clipLength()} frames late at ${kClipRate} frames per second; a trial must ` +
        'show every frame on time. Close other tabs and programs, and start again.';
      study.phase = 'idle';
      return;
    }
    nextTrial();
  } else if (study.phase === 'first') {
    playPhase('gap');
  } else {
    study.phase = 'answer';
    drawStudyFrame(0, 0);
    updateTrialText();
    setAnswering(true);
  }
}

function updateTrialText() {
  const r = JSON.parse(study.core.requestJson());
  const where = `Trial ${r.answered + 1} of ${r.total} (${r.condition})`;
  $('study-trial-text').textContent = study.phase === 'answer'
    ? `${where}: which clip was distorted? Press 1 or 2.` : `${where}: watch both clips.`;
}

function nextTrial() {
  if (study.core.finished()) { showStudyResults(); return; }
  study.late = false;
  setAnswering(false);
  study.phase = 'first';
  updateTrialText();
  playPhase('first');
}

function answerStudy(chosen) {
  if (study.phase !== 'answer') return;
  const problem = study.core.answer(chosen, study.late);
  if (problem) { $('study-trial-text').textContent = problem; return; }
  nextTrial();
}

function studyRowsText(r) {
  const f = (v) => (v === null ? '' : v.toFixed(2));
  const px = `${f(r.threshold_px)} (${f(r.ci95_px[0])}-${f(r.ci95_px[1])})`;
  const arcmin = r.threshold_arcmin === null ? ''
    : `${f(r.threshold_arcmin)} (${f(r.ci95_arcmin[0])}-${f(r.ci95_arcmin[1])})`;
  const who = r.observer === null ? '(class)' : r.observer;
  return `<tr><td>${who}</td><td>${r.condition}</td><td>${r.trials} (${r.late})</td><td>${px}` +
    `${r.at_bound ? ' at the fit\'s bound' : ''}</td><td>${arcmin}</td>` +
    `<td>${Math.round(r.proportion_correct * 100)} %</td></tr>`;
}

// The results page: the fits' table (a row per observer and condition, the class's rows
// last), and the plot of the class's rows when there are several observers, else the one's.
function showResultsOf(info, results, rows, heading) {
  study.phase = 'idle';
  showStudyPage('results');
  $('study-table').innerHTML = '<tr><th>observer</th><th>condition</th><th>trials (late)</th>' +
    '<th>threshold, 95 % interval (px)</th><th>the same in arcmin</th><th>correct</th></tr>' +
    results.map(studyRowsText).join('');
  $('study-results-text').textContent = `${heading} The threshold is the error seen three ` +
    'times in four; for reuse to go unseen, the engine\'s threshold should sit below it.';
  const pooled = results.some((r) => r.observer === null);
  drawPsychometricPlot(info, results.filter((r) => !pooled || r.observer === null), rows);
}

function showStudyResults() {
  const observer = $('study-observer').value.trim();
  const ppi = Number($('study-ppi').value);
  const info = JSON.parse(study.core.studyJson());
  const r = JSON.parse(study.core.requestJson());
  showResultsOf(info, JSON.parse(study.core.resultsJson(observer, ppi)),
    parseTrialCsv(study.core.csv(observer, ppi)),
    `${info.title}${r.late ? `: ${r.late} presentations were late and shown again.` : '.'}`);
}

// The class view: the students' CSV files analysed together by the module.
function openClassCsvs(files) {
  Promise.all(Array.from(files).map((f) => f.text().then((text) => ({ name: f.name, text }))))
    .then((list) => {
      if (!study.core) study.core = new Module.Study();
      const out = JSON.parse(study.core.classResultsJson(JSON.stringify(list)));
      if (out.problem) { $('study-status').textContent = out.problem; return; }
      const rows = list.flatMap((f) => parseTrialCsv(f.text));
      const observers = new Set(rows.map((row) => row.observer));
      showResultsOf(out.study, out.results, rows, `${list.length} files, ${observers.size} ` +
        `observers, ${rows.length} presentations of ${out.study.title}.`);
    });
}

function parseTrialCsv(text) {
  const [header, ...lines] = text.trim().split('\n');
  const names = header.split(',');
  return lines.map((line) => Object.fromEntries(line.split(',').map((v, i) => [names[i], v])));
}

// Proportion correct (0..1) against the shown error (log scale): the answers in eight bins of
// the error range (a dot's area by its count) and each condition's fitted function
// (Module.Study.curve, the module's psychometric function) with its threshold marked.
function drawPsychometricPlot(info, results, rows) {
  const canvas = $('study-plot');
  const ctx = canvas.getContext('2d');
  const style = getComputedStyle(document.body);
  const [w, h] = [canvas.width, canvas.height];
  const box = { x: 60, y: 14, w: w - 80, h: h - 64 };
  const span = Math.log(info.max_px / info.min_px);
  const at = (px, p) => [box.x + Math.min(1, Math.max(0, Math.log(px / info.min_px) / span)) * box.w,
    box.y + box.h - (0.03 + 0.94 * p) * box.h];
  ctx.fillStyle = style.getPropertyValue("--panel").trim() || "#181b1f";
  ctx.fillRect(0, 0, w, h);
  ctx.strokeStyle = ctx.fillStyle = style.color;
  ctx.font = '13px sans-serif';
  ctx.strokeRect(box.x, box.y, box.w, box.h);
  for (const v of [0, 0.5, 0.75, 1]) ctx.fillText(String(v), 20, at(info.min_px, v)[1] + 4);
  for (let px = info.min_px; px <= info.max_px * 1.0001; px *= 10) {
    ctx.fillText(String(+px.toPrecision(3)), at(px, 0)[0] - 8, box.y + box.h + 18);
  }
  ctx.fillText('error shown (px, log scale); proportion correct', box.x + box.w / 2 - 150, h - 8);
  info.conditions.forEach((name, c) => {
    const colour = `rgb(${Module.policyColour(c).join(',')})`;
    const count = new Array(8).fill(0);
    const right = new Array(8).fill(0);
    for (const row of rows) {
      if (row.condition !== name || row.late === '1') continue;
      const u = Math.log(Math.max(Number(row.measured_px), info.min_px) / info.min_px) / span;
      const b = Math.min(7, Math.max(0, Math.floor(u * 8)));
      ++count[b];
      right[b] += row.correct === '1' ? 1 : 0;
    }
    ctx.fillStyle = colour;
    const shift = (c - (info.conditions.length - 1) / 2) * 10;
    count.forEach((n, b) => {
      if (!n) return;
      const [x, y] = at(info.min_px * Math.exp((b + 0.5) / 8 * span), right[b] / n);
      ctx.beginPath();
      ctx.arc(x + shift, y, 3 + 2 * Math.sqrt(n), 0, 2 * Math.PI);
      ctx.fill();
    });
    const fit = results.find((r) => r.condition === name);
    if (!fit) return;
    const curve = study.core.curve(fit.threshold_px, 101);
    ctx.strokeStyle = colour;
    ctx.lineWidth = 2.5;
    ctx.beginPath();
    curve.forEach((p, i) => {
      const [x, y] = at(info.min_px * Math.exp(i / 100 * span), p);
      if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
    });
    ctx.stroke();
    ctx.lineWidth = 1;
    ctx.fillText(`${name}: threshold ${fit.threshold_px.toFixed(2)} px`, box.x + 8,
      at(info.min_px, 0.97 - 0.07 * c)[1]);
  });
}

function saveStudyCsv() {
  const observer = $('study-observer').value.trim();
  const text = study.core.csv(observer, Number($('study-ppi').value));
  const link = document.createElement('a');
  link.href = URL.createObjectURL(new Blob([text], { type: 'text/csv' }));
  link.download = `${observer}.csv`;
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 1000);
}

function openStudyFile(file) {
  file.text().then((text) => {
    const probe = new Module.Study();
    const problem = probe.open(file.name, text, '', -1);
    probe.delete();
    if (problem) { $('study-status').textContent = problem; return; }  // the choice stays
    study.fileName = file.name;
    study.fileText = text;
    $('study-description').textContent = `${file.name} (opened from a file)`;
    $('study-status').textContent = '';
  });
}

// ?study=NAME opens the study panel on a shipped study; with &study-simulate=PX a simulated
// observer of that threshold answers it at once and the results show (a class's slide of
// what the study gives, and the page's check that it runs).
function applyStudyUrlOptions(params) {
  if (!params.has('study')) return;
  $('study-panel').hidden = false;
  showStudyPage('setup');
  $('study-name').value = params.get('study');
  studyChosen();
  if (!params.has('study-simulate')) return;
  const core = new Module.Study();
  const problem = core.open(params.get('study'), '', '', -1) ||
    core.simulate(Number(params.get('study-simulate')));
  if (!adoptStudyCore(core, problem)) return;
  $('study-observer').value = 'simulated';
  showStudyResults();
}

function bindStudyControls() {
  fillStudyPicker();
  setPpi(96);
  $('study-open').addEventListener('click', () => {
    $('study-panel').hidden = false;
    showStudyPage('setup');
  });
  $('study-close').addEventListener('click', () => { $('study-panel').hidden = true; });
  $('study-name').addEventListener('change', studyChosen);
  $('study-card').addEventListener('input', () => {
    setPpi(Number($('study-card').value) / (kCardWidthMm / 25.4));
  });
  $('study-ppi').addEventListener('change', () => setPpi(Number($('study-ppi').value)));
  $('study-file').addEventListener('change', (e) => {
    if (e.target.files[0]) openStudyFile(e.target.files[0]);
    e.target.value = '';
  });
  $('study-start').addEventListener('click', startStudy);
  $('study-class').addEventListener('change', (e) => {
    if (e.target.files.length) openClassCsvs(e.target.files);
    e.target.value = '';
  });
  $('study-first').addEventListener('click', () => answerStudy(1));
  $('study-second').addEventListener('click', () => answerStudy(2));
  $('study-stop').addEventListener('click', showStudyResults);
  $('study-save').addEventListener('click', saveStudyCsv);
  $('study-again').addEventListener('click', () => showStudyPage('setup'));
  document.addEventListener('keydown', (e) => {
    if (!studyOpen()) return;
    if (e.key === '1') answerStudy(1);
    if (e.key === '2') answerStudy(2);
    if (e.key === 'Escape') $('study-panel').hidden = true;
  });
}
