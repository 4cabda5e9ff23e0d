'use strict';
// The animation view, in the desktop's four layouts (the state's animation.display, the
// *Show* box): the comparison (the state's compared reuse policies, affine and perspective by
// default, and the exact projection play the same frames of the source, side by side; each
// panel shows its frame with the shown layer's outline in the colour of the engine's level,
// and under each policy the difference from the exact frame as a heat map); side by side (the
// model's own engine, the state's mode, beside the exact projection); difference (the heat
// map of the engine's frame against the exact one); blink (the engine's frame and the exact
// one in turn, each for kBlinkMs). The frames, levels, errors and heat maps come from core
// (Session.updateComparison, .runPixels, .runHeat; web/shown_runs.h picks the runs by the
// same display).

// The levels' colours, from core's palette (session/display/palette.h level_colour), read once.
let levelColoursCache = null;
function levelColours() {
  if (!levelColoursCache) {
    levelColoursCache = {};
    for (const [level, [r, g, b]] of Object.entries(Module.levelColours())) levelColoursCache[level] = `rgb(${r},${g},${b})`;
  }
  return levelColoursCache;
}

// How long blink shows each of the two frames, as the desktop's (half a second).
const kBlinkMs = 500;

const comparisonView = {
  title: 'Animation',
  images: [],  // per panel: its ImageData, reused frame to frame

  // Copies core's pixels (a view into the module's memory, valid until the next call into
  // it) to the canvas at (x, y), pixel for pixel.
  put(ctx, index, pixels, width, height, x, y) {
    let image = this.images[index];
    if (!image || image.width !== width || image.height !== height) {
      image = new ImageData(width, height);
      this.images[index] = image;
    }
    image.data.set(pixels);
    ctx.putImageData(image, x, y);
  },

  draw(ctx, w, h, style) {
    const problem = app.session.comparisonProblem();
    if (problem) {
      drawCentredText(ctx, w, h, problem, style);
      setHtml($('runs'), '');
      return;
    }
    const display = app.state.animation.display;
    if (display === 'comparison') this.drawComparison(ctx, w, h, style);
    else this.drawModel(ctx, w, h, style, display);
  },

  build() {
    $('animation-display').addEventListener('change', () => editState((s) => {
      s.animation.display = $('animation-display').value;
    }));
  },

  syncControls(s) {
    $('animation-display').value = s.animation.display;
  },

  // The shown layers' outlines of `run` over its panel at (x, y), clipped to it: the panel
  // shows `info.shown` ([x0, y0, camera pixels per panel pixel]) at `info.panel` ([width,
  // height]; Session.updateComparison), and a layer may reach past what it shows.
  outlines(ctx, run, x, y, info, style) {
    const [x0, y0, pixel] = info.shown;
    ctx.save();
    ctx.beginPath();
    ctx.rect(x, y, info.panel[0], info.panel[1]);
    ctx.clip();
    for (const outline of run.outlines) {
      tracePolygon(ctx, outline.points.map(([px, py]) => [x + (px - x0) / pixel, y + (py - y0) / pixel]));
      ctx.strokeStyle = levelColours()[outline.level];
      ctx.lineWidth = 2 * style.line;
      ctx.stroke();
    }
    ctx.restore();
  },

  caption(run) {
    return `${run.policy}: ${run.level}, ${run.measured_error_px.toFixed(2)} px`;
  },

  drawComparison(ctx, w, h, style) {
    // Panels fitted side by side, frames above and heat maps below; core frames them as the
    // desktop does and samples them at the panels' size, so each is copied to the canvas
    // pixel for pixel.
    const n = app.session.runCount();
    const pad = 8;
    const label = 20 * style.scale;
    const panelW = (w - pad * (n + 1)) / n;
    const info = JSON.parse(app.session.updateComparison(Math.floor(panelW), Math.floor(h / 2 - label - pad * 2)));
    const [pw, ph] = info.panel;
    info.runs.forEach((run, i) => {
      const x = Math.round(pad + i * (panelW + pad) + (panelW - pw) / 2);
      const y = Math.round(pad + label);
      const exact = i === n - 1;
      this.put(ctx, 2 * i, app.session.runPixels(i), pw, ph, x, y);
      this.outlines(ctx, run, x, y, info, style);
      ctx.fillStyle = '#e6e6e6';
      ctx.font = style.font(14);
      ctx.fillText(exact ? 'exact projection' : this.caption(run), x, pad + 14 * style.scale, pw);
      if (exact) return;
      const hy = Math.round(y + ph + label + pad);
      this.put(ctx, 2 * i + 1, app.session.runHeat(i), pw, ph, x, hy);
      ctx.fillText(`difference from exact: largest ${run.heat_max} grey levels, PSNR ${run.psnr_db.toFixed(1)} dB`,
        x, hy - 6, pw);
    });
    this.drawLegend(ctx, pad + (n - 1) * (panelW + pad), pad * 2 + label + ph + label, panelW, info, style);
    this.fillTable(info);
  },

  // The model's own engine (run 0) and the exact projection (run 1): side by side, the
  // difference heat map, or blink; the legend below the panels.
  drawModel(ctx, w, h, style, display) {
    const pad = 8;
    const label = 20 * style.scale;
    const legend = 110 * style.scale;  // the levels' key below two panels
    const n = display === 'side-by-side' ? 2 : 1;
    const panelW = (w - pad * (n + 1)) / n;
    const info = JSON.parse(app.session.updateComparison(Math.floor(panelW), Math.floor(h - legend - label - pad * 2)));
    const [pw, ph] = info.panel;
    const [engine, exact] = info.runs;
    const y = Math.round(pad + label);
    const at = (i) => Math.round(pad + i * (panelW + pad) + (panelW - pw) / 2);
    ctx.fillStyle = '#e6e6e6';
    ctx.font = style.font(14);
    let title;
    if (display === 'side-by-side') {
      this.put(ctx, 0, app.session.runPixels(0), pw, ph, at(0), y);
      this.outlines(ctx, engine, at(0), y, info, style);
      this.put(ctx, 2, app.session.runPixels(1), pw, ph, at(1), y);
      ctx.fillText(this.caption(engine), at(0), pad + 14 * style.scale, pw);
      ctx.fillText('exact projection', at(1), pad + 14 * style.scale, pw);
      title = null;
    } else if (display === 'difference') {
      this.put(ctx, 1, app.session.runHeat(0), pw, ph, at(0), y);
      title = `${engine.policy} - exact: largest ${engine.heat_max} grey levels, PSNR ${engine.psnr_db.toFixed(1)} dB`;
    } else {
      // Blink: the phase by the clock, and a redraw at the next change of phase.
      const phase = Math.floor(performance.now() / kBlinkMs) % 2;
      if (phase === 0) {
        this.put(ctx, 0, app.session.runPixels(0), pw, ph, at(0), y);
        this.outlines(ctx, engine, at(0), y, info, style);
      } else {
        this.put(ctx, 2, app.session.runPixels(1), pw, ph, at(0), y);
      }
      title = phase === 0 ? `blink: ${this.caption(engine)}` : 'blink: exact projection';
      clearTimeout(this.blinkTimer);
      this.blinkTimer = setTimeout(() => { if (shownView() === 'animation') app.dirty = true; },
        kBlinkMs - (performance.now() % kBlinkMs) + 1);
      this.blinkPhase = phase;
    }
    if (title) ctx.fillText(title, at(0), pad + 14 * style.scale, pw);
    // The key of what is shown: the levels' colours of the outlines, or the heat map's bar;
    // right of a single panel where it fits, else below.
    const beside = n === 1 && w - (at(0) + pw) >= 180 * style.scale;
    const kx = beside ? at(0) + pw + 2 * pad : pad;
    const ky = beside ? y : y + ph + pad * 2;
    this.drawLegend(ctx, kx, ky, Math.min(w - kx - pad, 256), info, style,
      { levels: display !== 'difference', bar: display === 'difference' });
    this.fillTable({ ...info, runs: [engine, exact] });
  },

  // The levels' colours and the heat map's colour bar (0 .. full scale grey levels), or one of
  // them (`shown`).
  drawLegend(ctx, x, y, width, info, style, shown = { levels: true, bar: true }) {
    ctx.font = style.font(13);
    let ly = y + 10;
    for (const [level, colour] of shown.levels ? Object.entries(levelColours()) : []) {
      ctx.fillStyle = colour;
      ctx.fillRect(x, ly - 10, 14, 10);
      ctx.fillStyle = '#e6e6e6';
      ctx.fillText(level, x + 20, ly);
      ly += 18 * style.scale;
    }
    if (!shown.bar) return;
    ly += shown.levels ? 10 : 0;
    const barW = Math.min(width, 256);
    ctx.drawImage(this.colourBar(), x, ly, barW, 14);
    ctx.fillStyle = '#e6e6e6';
    ctx.fillText('0', x, ly + 30 * style.scale);
    ctx.fillText(`${info.heat_full_scale}+ grey levels`, x + barW - 110 * style.scale, ly + 30 * style.scale);
  },

  // The heat map's ramp from core, 256 x 1 pixels, made once.
  colourBar() {
    if (!this.bar) {
      this.bar = document.createElement('canvas');
      this.bar.width = 256;
      this.bar.height = 1;
      const bctx = this.bar.getContext('2d');
      for (let i = 0; i < 256; ++i) {
        const [r, g, b] = Module.heatColour(i / 255);
        bctx.fillStyle = `rgb(${r},${g},${b})`;
        bctx.fillRect(i, 0, 1, 1);
      }
    }
    return this.bar;
  },

  fillTable(info) {
    const levels = ['none', 'translate', 'affine', 'perspective', 'rerender'];
    const runs = info.runs.slice(0, -1);
    let html = `<tr><th>frame ${info.frame}</th>${runs.map((r) => `<th>${r.policy}</th>`).join('')}</tr>`;
    html += `<tr><td>level</td>${runs.map((r) => `<td>${r.level}</td>`).join('')}</tr>`;
    html += `<tr><td>error, px</td>${runs.map((r) => `<td>${r.measured_error_px.toFixed(3)}</td>`).join('')}</tr>`;
    html += `<tr><td>largest, px</td>${runs.map((r) => `<td>${r.max_error_px.toFixed(3)}</td>`).join('')}</tr>`;
    html += `<tr><td>pixels written</td>${runs.map((r) => `<td>${r.pixels_written}</td>`).join('')}</tr>`;
    // Under the visible-only warp, what the warps computed of them (as the desktop's captions).
    if (info.warp === 'visible') {
      html += `<tr><td>warped, what shows only</td>${runs.map((r) => `<td>${r.pixels_warped}</td>`).join('')}</tr>`;
    }
    html += `<tr><th colspan="${runs.length + 1}">share of frames 1 .. now</th></tr>`;
    for (const level of levels) {
      html += `<tr><td>${level}</td>${runs.map((r) => `<td>${(100 * r.level_shares[level]).toFixed(0)}%</td>`).join('')}</tr>`;
    }
    setHtml($('runs'), html);
  },
};
app.views.animation = comparisonView;
