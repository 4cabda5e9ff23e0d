'use strict';
// Links, checks and files of the page (manual/web.md): the state in the address's fragment
// (a permalink), #embed (one view without controls, for an iframe on a slide), the claims of
// a lesson's step measured by the teaching layer in the module, the view as PNG or as a video,
// the state as the desktop's session file, and the source pickers (scenes with viewer scripts).
//
// A permalink is #s=<the state's fields that differ from the page's opening state, as JSON,
// deflated (CompressionStream 'deflate-raw') and base64url-encoded>. Opening it reads those
// fields over the default state through the session reader (Session.setState), so the state
// restored is the one linked, frame included.

const kLinkPrefix = 's=';

// The fields of `state` that differ from `base`, objects compared field by field and
// everything else (numbers, names, lists) as a whole.
function stateDiff(state, base) {
  const diff = {};
  for (const [key, value] of Object.entries(state)) {
    const b = base ? base[key] : undefined;
    if (value && typeof value === 'object' && !Array.isArray(value) && b && typeof b === 'object') {
      const inner = stateDiff(value, b);
      if (Object.keys(inner).length) diff[key] = inner;
    } else if (JSON.stringify(value) !== JSON.stringify(b)) {
      diff[key] = value;
    }
  }
  return diff;
}

async function streamBytes(bytes, transform) {
  const stream = new Blob([bytes]).stream().pipeThrough(transform);
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

function toBase64Url(bytes) {
  let text = '';
  for (const b of bytes) text += String.fromCharCode(b);
  return btoa(text).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

function fromBase64Url(text) {
  const plain = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  return Uint8Array.from(plain, (c) => c.charCodeAt(0));
}

// The permalink's fragment of the state shown (without '#').
async function linkFragment(state) {
  const json = JSON.stringify(stateDiff(state || app.state, app.defaultState));
  const packed = await streamBytes(new TextEncoder().encode(json), new CompressionStream('deflate-raw'));
  return kLinkPrefix + toBase64Url(packed);
}

// The state object a fragment holds (the fields over the default state), or throws.
async function linkState(fragment) {
  const part = fragment.split('&').find((p) => p.startsWith(kLinkPrefix));
  if (!part) return null;
  const bytes = await streamBytes(fromBase64Url(part.slice(kLinkPrefix.length)), new DecompressionStream('deflate-raw'));
  return JSON.parse(new TextDecoder().decode(bytes));
}

// Shows the state a permalink holds: "" or why not (the page then stays as it was).
async function openLink(fragment) {
  let diff;
  try {
    diff = await linkState(fragment);
  } catch (error) {
    return `the link: its state cannot be read (${error.message || error})`;
  }
  if (!diff) return '';
  if (!applyState(diff, 'the link')) return $('message').textContent;
  showLessonOfState();
  return '';
}

// After a state was applied whole (a link, a session file): the lesson panel shows the
// lesson and step the state names, without playing it again.
function showLessonOfState() {
  app.lesson = app.lessons.find((l) => l.name === app.state.lesson) || null;
  $('lesson').value = app.lesson ? app.lesson.name : '';
  $('lesson-panel').hidden = !app.lesson;
  if (app.lesson) showLessonText(app.state.lesson_step);
}

async function copyLink() {
  const url = `${location.href.split('#')[0]}#${await linkFragment()}`;
  history.replaceState(null, '', url);
  try {
    await navigator.clipboard.writeText(url);
    showMessage('');
    $('copy-link').textContent = 'Link copied';
  } catch (error) {
    // file:// pages may not reach the clipboard: the address bar holds the link.
    $('copy-link').textContent = 'Link in the address bar';
  }
  setTimeout(() => { $('copy-link').textContent = 'Copy link'; }, 2000);
}

function download(blob, name) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

function fileStem() {
  return app.state.lesson ? `oflab-${app.state.lesson}-${app.state.lesson_step}` : `oflab-${app.state.view}-${app.state.frame}`;
}

function savePng() {
  draw();
  if (shownView() === 'world') worldView.paintInto($('canvas').getContext('2d', { alpha: false }));
  $('canvas').toBlob((blob) => download(blob, `${fileStem()}.png`), 'image/png');
}

// The desktop's video export (gui/app/exports.h) on the page: the view shown, played from
// frame `first` to `last`, each frame drawn and encoded by the browser's WebCodecs
// VideoEncoder (VP9, else VP8) with the timestamp k / kVideoFps s, and written into a WebM
// file by webm-muxer (web/video/webm_writer.js): one video frame per frame played, at the
// canvas's size, whatever the time each takes to draw. progress(k, n) after each frame.
// Resolves {blob}, or {error} (no encoder; 'cancelled' after cancelVideo): then
// nothing is kept. Play stops meanwhile; the frame shown before is shown again after.
const kVideoFps = 30;
let videoJob = null;  // {cancelled} while a video is recorded

async function videoConfig(width, height) {
  if (!window.VideoEncoder || !window.OflabWebm) return null;
  for (const [codec, webm] of [['vp09.00.10.08', 'V_VP9'], ['vp8', 'V_VP8']]) {
    const config = { codec, width, height, bitrate: 8e6, framerate: kVideoFps };
    if ((await VideoEncoder.isConfigSupported(config)).supported) return { config, webm };
  }
  return null;
}

async function recordVideo(first, last, progress = () => {}) {
  if (videoJob) return { error: 'a video is being recorded already' };
  const job = { cancelled: false };
  videoJob = job;
  const canvas = $('canvas');
  const chosen = await videoConfig(canvas.width, canvas.height);
  if (!chosen || job.cancelled) {
    videoJob = null;
    return { error: chosen ? 'cancelled' : 'this browser cannot encode WebM video (no WebCodecs VP9 or VP8 encoder)' };
  }
  const shown = app.state.frame;
  const wasPlaying = app.playing;
  setPlaying(false);
  const { Muxer, ArrayBufferTarget } = window.OflabWebm;
  const muxer = new Muxer({ target: new ArrayBufferTarget(),
    video: { codec: chosen.webm, width: canvas.width, height: canvas.height, frameRate: kVideoFps } });
  let failure = null;
  const encoder = new VideoEncoder({ output: (chunk, meta) => muxer.addVideoChunk(chunk, meta),
    error: (e) => { failure = e; } });
  try {
    encoder.configure(chosen.config);
    for (let frame = first; frame <= last && !job.cancelled && !failure; ++frame) {
      seek(frame);
      draw();
      if (shownView() === 'world') worldView.paintInto(canvas.getContext('2d', { alpha: false }));
      const k = frame - first;
      const picture = new VideoFrame(canvas, { timestamp: Math.round((k * 1e6) / kVideoFps), duration: Math.round(1e6 / kVideoFps) });
      encoder.encode(picture, { keyFrame: k % (2 * kVideoFps) === 0 });
      picture.close();
      progress(k + 1, last - first + 1);
      // Let the page breathe (the control stays live to cancel) and the encoder keep up.
      do await new Promise((r) => setTimeout(r, 0)); while (encoder.encodeQueueSize > 4 && !failure);
    }
    if (!job.cancelled && !failure) await encoder.flush();
  } catch (error) {
    failure = failure || error;
  } finally {
    if (encoder.state !== 'closed') encoder.close();
    videoJob = null;
    seek(shown);
    setPlaying(wasPlaying);
  }
  if (failure) return { error: `the encoder failed: ${failure.message || failure}` };
  if (job.cancelled) return { error: 'cancelled' };
  muxer.finalize();
  return { blob: new Blob([muxer.target.buffer], { type: 'video/webm' }) };
}

function cancelVideo() {
  if (videoJob) videoJob.cancelled = true;
}

// The *Video* control: the whole run of the view shown (frame 0 to the last) as a WebM file;
// pressed again while it records, it cancels.
async function saveVideo() {
  if (videoJob) { cancelVideo(); return; }
  const button = $('save-video');
  const r = await recordVideo(0, app.session.frameCount() - 1, (k, n) => {
    button.textContent = `Recording ${k} / ${n} (press to cancel)`;
  });
  button.textContent = 'Video';
  if (r.error) {
    if (r.error !== 'cancelled') showMessage(`Video: ${r.error}`);
    return;
  }
  download(r.blob, `${fileStem()}.webm`);
}

function saveSession() {
  download(new Blob([app.session.sessionFileText()], { type: 'application/json' }), `${fileStem()}.json`);
}

// The animation's per-frame CSV over its whole run (the desktop's per-frame CSV export, the
// columns of `oflab-cli animate`); a source that cannot be played is named in the message.
function saveCsv() {
  const r = JSON.parse(app.session.runCsvJson());
  if (r.error) {
    showMessage(`CSV: ${r.error}`);
    return;
  }
  download(new Blob([r.csv], { type: 'text/csv' }), `${fileStem()}.csv`);
}

// A session file the user opened, read by the desktop's reader: shown whole, or refused with
// the message naming the file and the field (nothing changes).
function openSessionText(text, name) {
  const problem = app.session.openSession(text, name);
  if (problem) {
    showMessage(problem);
    return false;
  }
  app.state = JSON.parse(app.session.stateJson());
  syncControls();
  showLessonOfState();
  app.dirty = true;
  showMessage('');
  return true;
}

// The claims of the lesson's part shown, measured now: says / measured / holds.
function checkClaims() {
  const claims = JSON.parse(app.session.checkClaimsJson());
  const rows = claims.map((c) => {
    const bounds = [c.at_least !== null ? `\u2265 ${c.at_least}` : '', c.at_most !== null ? `\u2264 ${c.at_most}` : ''].filter(Boolean).join(', ');
    if (c.holds === undefined) {
      return `<tr><td>${escapeHtml(c.says)}</td><td>${escapeHtml(c.kind)} ${bounds}</td><td colspan="2" class="unit">on the screen: oflab --check-lesson</td></tr>`;
    }
    const measured = c.measured === null ? 'n/a' : Number(c.measured.toPrecision(4)).toString();
    return `<tr class="${c.holds ? 'holds' : 'false'}"><td>${escapeHtml(c.says)}</td><td>${escapeHtml(c.kind)} ${bounds}</td>` +
      `<td>${measured}</td><td>${c.holds ? 'holds' : 'FALSE'}</td></tr>`;
  });
  $('lesson-checks').innerHTML = rows.length
    ? `<tr><th>says</th><th>claim</th><th>measured</th><th>holds</th></tr>${rows.join('')}`
    : '<tr><td>This part makes no claims.</td></tr>';
  $('lesson-checks').hidden = false;
  return claims;
}

// The source pickers: the plane (with the script picker) or a shipped scene, played by the
// scene animator or by scene shifting, walked through by a shipped viewer script.
function fillSourcePickers() {
  const names = JSON.parse(Module.Session.sceneNamesJson());
  const source = $('source');
  source.add(new Option('the plane', 'plane:'));
  for (const kind of ['scene', 'scene-shifting']) {
    for (const name of names.scenes) source.add(new Option(`${kind === 'scene' ? 'Scene' : 'Scene shifting'}: ${name}`, `${kind}:${name}`));
  }
  for (const name of names.viewers) $('viewer').add(new Option(name, name));
  source.addEventListener('change', () => editState((s) => {
    const [kind, name] = source.value.split(':');
    s.animation.source = { kind, name, viewer: kind === 'plane' ? '' : ($('viewer').value || names.viewers[0]) };
    if (kind !== 'plane') s.view = 'animation';
    s.frame = 0;
  }, 'the source'));
  $('viewer').addEventListener('change', () => editState((s) => {
    s.animation.source.viewer = $('viewer').value;
    s.frame = 0;
  }, 'the viewer script'));
}

function syncSourcePickers(s) {
  const src = s.animation.source;
  const value = `${src.kind}:${src.kind === 'plane' ? '' : src.name}`;
  if ([...$('source').options].some((o) => o.value === value)) $('source').value = value;
  $('viewer').value = src.viewer || '';
  $('viewer').disabled = src.kind === 'plane';
}

function bindShareControls() {
  $('copy-link').addEventListener('click', () => copyLink());
  $('save-png').addEventListener('click', savePng);
  $('save-session').addEventListener('click', saveSession);
  $('save-csv').addEventListener('click', saveCsv);
  $('save-video').addEventListener('click', saveVideo);
  $('lesson-check').addEventListener('click', checkClaims);
  fillSourcePickers();
}
