'use strict';
// The flow view's texture (manual/web.md, "Flow"), run by web_test.js with its browser and
// helpers ({ browser, open, evaluate, check, drawnMarker, cli }).
//
// - The page's texture (Session.flowTexture: core's exact image of the plane at the frame
//   shown) sampled at the frame's own size and not faded is the exact frame
//   `oflab-cli animate --mode rerender --frames-png` writes for the same script and frame,
//   flattened over the page's background: equal bytes where the CLI's pixel is opaque or
//   empty, within 2 grey levels on the plane's edge (the PNG's straight alpha is rounded
//   there). The CLI's frame 0 is not the page's frame 20 (negative control).
// - The view draws it (the canvas under the drawn rectangle changes) with flow.texture true
//   and draws none with it false (negative control: nothing drawn, the canvas is the tinted
//   outline only).
// - The world view's image plane (Session.worldFrame, as the desktop's image plane) shows the
//   same exact frame, sampled at the nearest pixel down to at most 512 pixels across and
//   flattened over the world's image grey: against the CLI's frame sampled by that rule, equal
//   bytes where the CLI's pixel is opaque or empty, within 2 levels on the plane's edge; the
//   world view's texture holds those bytes; the CLI's frame 0 differs (negative control).
// - The animation view's panels are framed as the desktop frames them
//   (session/display/panel_framing.h): the lesson Occlusion's framing of what is drawn around
//   the frame shown. The exact panel is the CLI's exact frame of the scene sampled over the
//   part the page says it shows (Session.updateComparison's "shown": the camera pixel under
//   x0 + (x + 0.5) pixel), and what it draws (pixels not the background) fills at least a
//   quarter of it: the lesson's screen claim, measured on the page. Controls: the loop's
//   framing fills less, the zoom enlarges the picture, and the CLI's frame sampled whole is
//   another picture.
const fs = require('fs');
const os = require('os');
const path = require('path');
const { spawnSync } = require('child_process');
const { decodePng } = require('./png');

const kBackground = [0x11, 0x13, 0x15];  // the page's canvas background, #111315

// `oflab-cli animate --mode rerender`'s frames 0 .. last of `script` (or of the source the
// arguments `source` name) as decoded PNGs, or { error }.
function cliExactFrames(cli, script, last, source = ['--script', script]) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'oflab-web-flowtex-'));
  try {
    const r = spawnSync(cli, ['animate', '--mode', 'rerender', ...source, '--out', path.join(dir, 'run'),
      '--frames-png', '--frames', String(last + 1), '--quiet', '--no-warm-up', '--repeat-timing', '1'], { encoding: 'utf8' });
    if (r.status !== 0) return { error: r.stderr.trim() };
    const read = (k) => {
      const name = `frame_${String(k).padStart(5, '0')}.png`;
      return decodePng(fs.readFileSync(path.join(dir, 'run', name)), name);
    };
    return { first: read(0), last: read(last) };
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// The CLI's straight-alpha frame over the background (premultiplied, rounded as core rounds)
// against the page's opaque bytes: how many pixels differ, and by how much at most, apart for
// opaque-or-empty pixels and partly covered ones.
function compareOverBackground(png, page, background = kBackground) {
  const out = { solidDiffering: 0, edgeLargest: 0, largest: 0 };
  if (page.length !== png.data.length) return { sizeMismatch: `${page.length} bytes, the CLI's ${png.data.length}` };
  for (let i = 0; i < png.data.length; i += 4) {
    const a = png.data[i + 3];
    for (let c = 0; c < 3; ++c) {
      const premultiplied = Math.round((png.data[i + c] * a) / 255);
      const expected = premultiplied + Math.floor((background[c] * (255 - a) + 127) / 255);
      const d = Math.abs(expected - page[i + c]);
      out.largest = Math.max(out.largest, d);
      if (a === 0 || a === 255) out.solidDiffering += d > 0 ? 1 : 0;
      else out.edgeLargest = Math.max(out.edgeLargest, d);
    }
  }
  return out;
}

async function testFlowTexture({ browser, open, evaluate, check, drawnMarker, cli }) {
  await open(browser, '?view=flow&script=swing&frame=20', drawnMarker);
  const frame = await evaluate(browser, 'app.session.frame()');
  const b64 = await evaluate(browser, `(() => {
    const t = app.session.flowTexture(0, 0, 1, app.session.frameWidth(), app.session.frameHeight(), 1);
    if (!t) return '';
    let s = '';
    for (let i = 0; i < t.pixels.length; i += 8192) s += String.fromCharCode(...t.pixels.subarray(i, i + 8192));
    return btoa(s);
  })()`);
  const page = Buffer.from(b64, 'base64');
  const frames = cliExactFrames(cli, 'swing', frame);
  if (frames.error || !page.length) {
    check('TheFlowTextureIsTheCliExactFrame', false, frames.error || 'the page drew no texture');
    return;
  }
  const same = compareOverBackground(frames.last, page);
  check('TheFlowTextureIsTheCliExactFrame', frame === 20 && !same.sizeMismatch && same.solidDiffering === 0 &&
    same.edgeLargest <= 2, `frame ${frame}: ${JSON.stringify(same)}`);
  const other = compareOverBackground(frames.first, page);
  check('TheCliFrame0IsNotTheFlowTextureOfFrame20', other.solidDiffering > 1000, JSON.stringify(other));

  // The view draws it with flow.texture, and not without.
  const drawn = JSON.parse(await evaluate(browser, `(() => {
    const read = (texture) => {
      editState((s) => { s.flow.texture = texture; s.flow.colour_wheel = false; });
      draw();
      const r = app.views.flow.drawnTexture;
      const box = r || { x: 0, y: 0, width: 1, height: 1 };
      return { r, pixels: $('canvas').getContext('2d').getImageData(box.x, box.y, box.width, box.height).data };
    };
    const on = read(true);
    const off = read(false);
    const box = on.r ? on.r : null;
    let differing = 0;
    if (box) {
      const again = $('canvas').getContext('2d').getImageData(box.x, box.y, box.width, box.height).data;
      for (let i = 0; i < again.length; i += 4) differing += again[i] !== on.pixels[i] || again[i + 1] !== on.pixels[i + 1] ? 1 : 0;
    }
    return JSON.stringify({ on: on.r, off: off.r, differing, state: app.state.flow.texture });
  })()`));
  check('TheFlowViewDrawsTheTexture', drawn.on && drawn.differing > 1000, JSON.stringify(drawn));
  check('WithoutFlowTextureTheViewDrawsNone', drawn.on && drawn.off === null && drawn.state === false, JSON.stringify(drawn));
}

// `png` sampled at the nearest pixel to `width` x `height` (web/frame_pixels.h
// display_sampling: display pixel i shows frame pixel floor((i + 0.5) * size / out)).
function nearestSampled(png, width, height) {
  const data = Buffer.alloc(width * height * 4);
  for (let y = 0; y < height; ++y) {
    const row = Math.min(png.height - 1, Math.floor(((y + 0.5) * png.height) / height));
    for (let x = 0; x < width; ++x) {
      const column = Math.min(png.width - 1, Math.floor(((x + 0.5) * png.width) / width));
      for (let c = 0; c < 4; ++c) data[(y * width + x) * 4 + c] = png.data[(row * png.width + column) * 4 + c];
    }
  }
  return { width, height, data };
}

async function testWorldFrame({ browser, open, evaluate, check, drawnMarker, cli }) {
  await open(browser, '?view=world&script=swing&frame=20', drawnMarker);
  const got = JSON.parse(await evaluate(browser, `(() => {
    const t = app.session.worldFrame();
    if (!t) return '{}';
    const image = worldView.world.frameImage;
    const shown = Array.from(image.getPointData().getScalars().getData());
    const same = shown.length === t.pixels.length && shown.every((v, i) => v === t.pixels[i]);
    let s = '';
    for (let i = 0; i < t.pixels.length; i += 8192) s += String.fromCharCode(...t.pixels.subarray(i, i + 8192));
    return JSON.stringify({ width: t.width, height: t.height, b64: btoa(s), shownIsIt: same, dims: image.getDimensions(), frame: app.session.frame() });
  })()`));
  const frames = cliExactFrames(cli, 'swing', 20);
  if (frames.error || !got.b64) {
    check('TheWorldImagePlaneIsTheCliExactFrame', false, frames.error || 'no frame on the image plane');
    return;
  }
  const page = Buffer.from(got.b64, 'base64');
  const grey = [150, 156, 165];
  const same = compareOverBackground(nearestSampled(frames.last, got.width, got.height), page, grey);
  check('TheWorldImagePlaneIsTheCliExactFrame', got.frame === 20 && got.shownIsIt && Math.max(got.width, got.height) <= 512 &&
    !same.sizeMismatch && same.solidDiffering === 0 && same.edgeLargest <= 2,
  `${got.width} x ${got.height} of ${frames.last.width} x ${frames.last.height}, texture holds it: ${got.shownIsIt}; ${JSON.stringify(same)}`);
  const other = compareOverBackground(nearestSampled(frames.first, got.width, got.height), page, grey);
  check('NegativeControl_TheCliFrame0IsNotTheImagePlanesFrame20', other.solidDiffering > 1000, JSON.stringify(other));
}

// The CLI's frame `png` sampled as the page's panel shows it: display pixel (x, y) shows the
// frame pixel under (x0 + (x + 0.5) pixel, y0 + (y + 0.5) pixel), nothing (alpha 0) outside
// the frame (frame_pixels.h region_sampling).
function regionSampled(png, [width, height], [x0, y0, pixel]) {
  const data = Buffer.alloc(width * height * 4);
  for (let y = 0; y < height; ++y) {
    const row = Math.floor(y0 + (y + 0.5) * pixel);
    for (let x = 0; x < width; ++x) {
      const column = Math.floor(x0 + (x + 0.5) * pixel);
      if (row < 0 || row >= png.height || column < 0 || column >= png.width) continue;
      for (let c = 0; c < 4; ++c) data[(y * width + x) * 4 + c] = png.data[(row * png.width + column) * 4 + c];
    }
  }
  return { width, height, data };
}

async function testPanelFraming({ browser, open, evaluate, check, drawnMarker, cli }) {
  await open(browser, '?view=animation', drawnMarker);
  const got = JSON.parse(await evaluate(browser, `(() => {
    const take = (framing, zoom) => {
      editState((s) => {
        s.animation.source = { kind: 'scene', name: 'five-semi-occluded', viewer: 'translate' };
        s.animation.framing = framing;
        s.animation.zoom = zoom;
        s.playing = false;
        s.frame = 10;
      });
      const info = JSON.parse(app.session.updateComparison(480, 360));
      const px = app.session.runPixels(info.runs.length - 1);
      let drawn = 0;
      for (let i = 0; i < px.length; i += 4) drawn += px[i] !== 24 || px[i + 1] !== 27 || px[i + 2] !== 31 ? 1 : 0;
      let s = '';
      for (let i = 0; i < px.length; i += 8192) s += String.fromCharCode(...px.subarray(i, i + 8192));
      return { frame: info.frame, panel: info.panel, shown: info.shown, fill: drawn / (px.length / 4), b64: btoa(s) };
    };
    return JSON.stringify({ content: take('content', 1), loop: take('loop', 1), zoomed: take('content', 2) });
  })()`));
  const frames = cliExactFrames(cli, null, 10, ['--scene', 'five-semi-occluded', '--script', 'translate']);
  if (frames.error) {
    check('TheFramedExactPanelIsTheCliFrameOverTheShownPart', false, frames.error);
    return;
  }
  const panelBackground = [24, 27, 31];
  const { content, loop, zoomed } = got;
  const page = Buffer.from(content.b64, 'base64');
  const same = compareOverBackground(regionSampled(frames.last, content.panel, content.shown), page, panelBackground);
  check('TheFramedExactPanelIsTheCliFrameOverTheShownPart', content.frame === 10 && !same.sizeMismatch &&
    same.solidDiffering === 0 && same.edgeLargest <= 2,
  `panel ${content.panel}, shown from (${content.shown[0].toFixed(1)}, ${content.shown[1].toFixed(1)}) at ${content.shown[2].toFixed(3)} camera pixels each; ${JSON.stringify(same)}`);
  check('OcclusionsPanelsFillAQuarterFramedOnWhatIsDrawn', content.fill >= 0.25 && loop.fill < content.fill &&
    zoomed.shown[2] < content.shown[2],
  `drawn ${(100 * content.fill).toFixed(1)} % of the panel framed on content, ${(100 * loop.fill).toFixed(1)} % on the loop; ` +
    `zoom 2: ${zoomed.shown[2].toFixed(3)} camera pixels a panel pixel against ${content.shown[2].toFixed(3)}`);
  const whole = compareOverBackground(nearestSampled(frames.last, content.panel[0], content.panel[1]), page, panelBackground);
  check('NegativeControl_TheWholeFrameSampledIsAnotherPicture', whole.solidDiffering > 1000, JSON.stringify(whole));
  // The lesson's own claim, measured by the page's Check on the panels as drawn (the exact
  // outlines' share of the exact panel, as the desktop measures it); with the flow view in
  // front it is left to the desktop (control).
  await open(browser, '?lesson=occlusion', drawnMarker);
  const claims = JSON.parse(await evaluate(browser, `(() => {
    const fill = () => JSON.parse(app.session.checkClaimsJson()).find((c) => c.kind === 'panel_fill');
    const animation = fill();
    editState((s) => { s.view = 'flow'; });
    return JSON.stringify({ animation, flow: fill() });
  })()`));
  const a = claims.animation || {};
  check('ThePageMeasuresOcclusionsPanelFillClaim', a.holds === true && a.measured >= 25 && claims.flow && claims.flow.holds === undefined,
    `${a.measured && a.measured.toFixed(1)} % (at least ${a.at_least}); ${a.line}; flow view in front: ${JSON.stringify(claims.flow)}`);
}

module.exports = { testFlowTexture, testWorldFrame, testPanelFraming };
