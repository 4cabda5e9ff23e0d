'use strict';
// The basis explorer (the basis view with "Explore" on; the state's basis.explorer): the
// eight planar terms dialled by hand (basis.terms), the deformation they make in one
// second, the planes and motions that make exactly this flow (both solutions, sketched from
// above and behind the eye), and the two solutions played forward for one second. Every
// number and point comes from Session.explorerJson (web/web_explorer.h: the code of the
// desktop's explorer, session/basis/basis_explorer.h); this file only draws.

const kOkabeVermillion = '#d55e00';  // V/d, as the desktop draws it
const kOkabeBlue = '#0072b2';        // Omega

const explorerView = {
  title: 'Basis explorer',
  data: null,        // the last Session.explorerJson, parsed
  dataKey: '',       // the terms and camera it was computed for
  futureFrame: -1,   // the futures' frame shown; -1: the last one played
  playTimer: 0,

  build() {
    const dials = $('explorer-dials');
    for (const term of JSON.parse(app.session.explorerJson()).terms) {
      const row = document.createElement('div');
      row.className = 'dial';
      // The term and its unit under it; the slider and the number box beside them.
      const name = document.createElement('span');
      name.className = 'term';
      name.textContent = term.key;
      name.title = term.description;
      const unit = document.createElement('small');
      unit.textContent = term.unit;
      name.append(document.createElement('br'), unit);
      const slider = document.createElement('input');
      slider.type = 'range';
      slider.id = `explorer-slider-${term.key}`;
      slider.min = String(-term.span);
      slider.max = String(term.span);
      slider.step = String(term.span / 100);
      slider.setAttribute('aria-label', term.description);
      const box = document.createElement('input');
      box.type = 'number';
      box.id = `explorer-${term.key}`;
      box.step = String(term.span / 100);
      box.title = `${term.description}, ${term.unit} (${term.minimum}..${term.maximum})`;
      const set = (value) => editState((s) => { s.basis.terms[term.key] = Number(value); }, 'the explorer');
      slider.addEventListener('input', () => set(slider.value));
      box.addEventListener('change', () => set(box.value));
      row.append(name, slider, box);
      dials.appendChild(row);
    }
    $('basis-explorer').addEventListener('change', () => editState((s) => { s.basis.explorer = $('basis-explorer').checked; }));
    $('explorer-zero').addEventListener('click', () => this.setTerms(null));
    // The flow of the scene at the frame shown now (the cached result may be of another frame).
    $('explorer-scene').addEventListener('click', () => this.setTerms(JSON.parse(app.session.explorerJson()).from_scene));
    $('explorer-play').addEventListener('click', () => this.playFutures());
  },

  // Dials all eight terms at once: `values` in the gallery's order, or null for all zero.
  setTerms(values) {
    const terms = this.result().terms;
    editState((s) => {
      terms.forEach((term, k) => { s.basis.terms[term.key] = values ? values[k] : 0; });
    }, 'the explorer');
  },

  // The explorer of the state now (recomputed only when its terms, or the plane or script
  // that give its camera, changed).
  result() {
    const key = JSON.stringify([app.state.basis.terms, app.state.plane, app.state.script]);
    if (key !== this.dataKey || !this.data) {
      this.data = JSON.parse(app.session.explorerJson());
      this.dataKey = key;
    }
    return this.data;
  },

  syncControls(s) {
    $('basis-explorer').checked = s.basis.explorer;
    for (const el of document.querySelectorAll('.for-explorer')) el.hidden = !s.basis.explorer;
    $('basis-kind').disabled = s.basis.explorer;
    for (const term of this.result().terms) {
      const value = s.basis.terms[term.key];
      $(`explorer-slider-${term.key}`).value = String(value);
      const box = $(`explorer-${term.key}`);
      if (document.activeElement !== box) box.value = String(+value.toFixed(term.decimals));
    }
  },

  // Plays the two futures frame by frame at their own rate (1/30 s a frame), once.
  playFutures() {
    clearInterval(this.playTimer);
    const f = this.result().futures;
    if (!f.played) return;
    this.futureFrame = 0;
    this.playTimer = setInterval(() => {
      this.futureFrame += 1;
      if (this.futureFrame >= f.frames) { this.futureFrame = -1; clearInterval(this.playTimer); }
      app.dirty = true;
    }, 1000 * f.frame_seconds);
    app.dirty = true;
  },

  draw(ctx, w, h, style) {
    const r = this.result();
    this.fillSolutionsTable(r);
    const pad = 8;
    const left = Math.floor(w * 0.5);
    this.drawDeformation(ctx, r, { x: pad, y: pad, w: left - 1.5 * pad, h: h - 2 * pad }, style);
    const right = { x: left + pad / 2, w: w - left - 1.5 * pad };
    const top = Math.floor((h - 3 * pad) * 0.42);
    this.drawSolutions(ctx, r, { x: right.x, y: pad, w: right.w, h: top }, style);
    this.drawFutures(ctx, r, { x: right.x, y: 2 * pad + top, w: right.w, h: h - 3 * pad - top }, style);
  },

  fillSolutionsTable(r) {
    const vector = (v) => `(${v.map((x) => (Math.abs(x) < 0.005 ? 0 : x).toFixed(2)).join(', ')})`;
    const names = ['Solution A', 'Solution B'];
    let html = `<p><b>${escapeHtml(r.case)}</b></p>`;
    if (r.solutions.length) {
      const row = (label, cell) => `<tr><td>${label}</td>${r.solutions.map((s) => `<td>${escapeHtml(cell(s))}</td>`).join('')}</tr>`;
      html += `<table class="numbers explorer-solutions"><tr><th></th>${r.solutions.map((s, i) => `<th style="color:${this.colour(i)}">${names[i]}</th>`).join('')}</tr>`
        + row('normal N', (s) => (s.normal_known ? vector(s.normal) : 'unknown'))
        + row('facing', (s) => s.facing)
        + row('V/d, 1/s', (s) => vector(s.v_over_d))
        + row('Omega, rad/s', (s) => vector(s.omega))
        + '</table>';
    }
    if (r.dropped_behind) html += `<p>Left out, behind the eye: ${r.dropped_behind} mirror image(s). d, the plane's distance, is never known: only V/d.</p>`;
    setHtml($('explorer-solutions'), html);
  },

  colour(index) {
    const [red, green, blue] = Module.policyColour(index);
    return `rgb(${red}, ${green}, ${blue})`;
  },

  // The camera image, the texture rectangle (dashed) and where one second of the flow carries
  // it, with an 8 x 8 grid, framed so that both fill the picture.
  drawDeformation(ctx, r, box, style) {
    const d = r.deformation;
    const title = textBlock(ctx, `After ${d.seconds} s of this flow (dashed: the start)`, box.w, 15, style);
    title.draw(box.x, box.y, '#e6e6e6');
    const c = d.change;
    const numbers = textBlock(ctx, `The centre moved ${c.shift_px.toFixed(1)} px; area x${c.area.toFixed(3)}; turned ${c.turn_deg.toFixed(1)}\u00b0; keystone ${(100 * c.keystone).toFixed(1)} %.`,
      box.w, 13, style);
    numbers.draw(box.x, box.y + box.h - numbers.height, '#c8ccd2');
    const area = { x: box.x, y: box.y + title.height + 4, w: box.w, h: box.h - title.height - numbers.height - 8 };
    const points = d.rect.concat(d.quad);
    const fit = fitBox(points, area, 0.03);
    const { width, height } = r.camera;
    const frame = [[-width / 2, -height / 2], [width / 2, -height / 2], [width / 2, height / 2], [-width / 2, height / 2]];
    ctx.save();
    ctx.beginPath();
    ctx.rect(area.x, area.y, area.w, area.h);
    ctx.clip();
    ctx.fillStyle = '#6e737a';
    tracePolygon(ctx, frame.map(fit));
    ctx.fill();
    if (d.behind_eye) {
      ctx.restore();
      drawNote(ctx, area, 'In one second a corner of the rectangle passes behind the eye: no picture.', style);
      return;
    }
    ctx.fillStyle = '#101214';
    tracePolygon(ctx, d.quad.map(fit));
    ctx.fill();
    ctx.strokeStyle = '#2fbf9f';
    ctx.lineWidth = 1.5 * style.line;
    ctx.beginPath();
    for (const [x0, y0, x1, y1] of d.grid) {
      const a = fit([x0, y0]);
      const b = fit([x1, y1]);
      ctx.moveTo(a[0], a[1]);
      ctx.lineTo(b[0], b[1]);
    }
    ctx.stroke();
    ctx.setLineDash([6 * style.line, 5 * style.line]);
    ctx.strokeStyle = '#c8ccd2';
    ctx.lineWidth = style.line;
    tracePolygon(ctx, d.rect.map(fit));
    ctx.stroke();
    ctx.restore();
  },

  // Each solution in its own half: the eye, its line of sight, the plane, N, V/d and Omega.
  drawSolutions(ctx, r, box, style) {
    ctx.fillStyle = '#181b1f';
    ctx.fillRect(box.x, box.y, box.w, box.h);
    const title = 22 * style.scale;
    const items = [['dot: the eye', '#e6e6e6'], ['N normal', '#e6e6e6'], ['V/d velocity', kOkabeVermillion], ['Omega spin', kOkabeBlue]];
    const legend = legendRows(ctx, items, box.w - 12, 13, style);
    const count = Math.max(1, r.solutions.length);
    const cellW = box.w / count;
    const sketches = r.solutions.filter((s) => s.sketch).map((s) => s.sketch);
    const all = [[0, 0]];
    for (const k of sketches) all.push(...k.corners, k.centre, k.normal_tip, k.velocity_tip, k.spin_tip);
    const names = ['Solution A', 'Solution B'];
    for (let i = 0; i < count; ++i) {
      const cell = { x: box.x + i * cellW, y: box.y + title, w: cellW, h: box.h - title - legend.height };
      const s = r.solutions[i];
      ctx.fillStyle = s ? this.colour(i) : '#e6e6e6';
      ctx.font = `bold ${style.font(14)}`;
      ctx.fillText(r.solutions.length ? names[i] : 'No motion', cell.x + 6, box.y + 16 * style.scale);
      if (!s || !s.sketch) {
        drawNote(ctx, cell, s && s.omega.every((v) => v === 0) ? 'No motion: any plane, at rest'
          : 'Any plane: a pure rotation says nothing about it', style);
        continue;
      }
      this.drawSketch(ctx, s.sketch, fitBox(all, { x: cell.x + 6, y: cell.y, w: cell.w - 12, h: cell.h }, 0.05), i, style);
    }
    legend.draw(box.x + 6, box.y + box.h - legend.height);
  },

  drawSketch(ctx, k, fit, index, style) {
    const eye = fit([0, 0]);
    const at = (p) => fit(p);
    ctx.setLineDash([4, 4]);
    ctx.strokeStyle = '#8a9099';
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(eye[0], eye[1]);
    ctx.lineTo(...at(k.centre));
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.fillStyle = this.colour(index).replace('rgb', 'rgba').replace(')', ', 0.35)');
    ctx.strokeStyle = this.colour(index);
    ctx.lineWidth = 1.5 * style.line;
    tracePolygon(ctx, k.corners.map(at));
    ctx.fill();
    ctx.stroke();
    const head = 10 * style.scale;
    const arrow = (from, to, colour, width) => {
      ctx.strokeStyle = colour;
      ctx.lineWidth = width;
      ctx.beginPath();
      addArrow(ctx, from[0], from[1], to[0], to[1], head);
      ctx.stroke();
    };
    arrow(at(k.centre), at(k.normal_tip), '#e6e6e6', 1.5 * style.line);
    arrow(at(k.centre), at(k.velocity_tip), kOkabeVermillion, 2.5 * style.line);
    arrow(eye, at(k.spin_tip), kOkabeBlue, 2.5 * style.line);
    ctx.fillStyle = '#e6e6e6';
    ctx.beginPath();
    ctx.arc(eye[0], eye[1], 4 * style.scale, 0, 2 * Math.PI);
    ctx.fill();
  },

  // The two futures at the frame shown: each solution's image of the rectangle's corners
  // (the other's dashed), and the largest corner distance per frame.
  drawFutures(ctx, r, box, style) {
    const f = r.futures;
    ctx.fillStyle = '#181b1f';
    ctx.fillRect(box.x, box.y, box.w, box.h);
    if (!f.played) {
      drawNote(ctx, box, `Nothing played forward: ${f.note}.`, style);
      return;
    }
    const frame = this.futureFrame < 0 ? f.frames : Math.min(this.futureFrame, f.frames);
    const first = f.first_frame_apart;
    const after1 = f.distance_px.length > 1 ? f.distance_px[1] : 0;
    const sentence = textBlock(ctx, `Frame ${frame} of ${f.frames}: the images are ${f.distance_px[frame].toFixed(3)} px apart. After one frame ${after1.toFixed(3)} px; ${first >= 0 ? `over ${f.threshold_px} px first at frame ${first}` : `never over ${f.threshold_px} px`}.`,
      box.w - 8, 13, style);
    const title = 20 * style.scale;
    const line = sentence.height + 4;
    // The chart keeps at least 90 px (180 in presentation mode); the pictures take the rest,
    // and are left out when that is too small to show a quadrilateral.
    const chartH = Math.max(90 * style.scale, (box.h - line) * 0.5);
    const pictureH = box.h - line - chartH >= title + 30 * style.scale ? box.h - line - chartH : 0;
    const { width, height } = r.camera;
    const frameCorners = [[-width / 2, -height / 2], [width / 2, -height / 2], [width / 2, height / 2], [-width / 2, height / 2]];
    for (let i = 0; i < 2 && pictureH > 0; ++i) {
      const cell = { x: box.x + i * box.w / 2 + 4, y: box.y + title, w: box.w / 2 - 8, h: pictureH - title };
      ctx.fillStyle = this.colour(i);
      ctx.font = `bold ${style.font(13)}`;
      ctx.fillText(`${i ? 'B' : 'A'}, frame ${frame}`, cell.x, box.y + 15 * style.scale);
      const fit = fitBox(frameCorners, cell, 0);
      ctx.fillStyle = '#6e737a';
      tracePolygon(ctx, frameCorners.map(fit));
      ctx.fill();
      ctx.lineWidth = 1.5 * style.line;
      ctx.setLineDash([5, 4]);
      ctx.strokeStyle = this.colour(1 - i);
      tracePolygon(ctx, f.corners[frame][1 - i].map(fit));
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.strokeStyle = this.colour(i);
      ctx.fillStyle = '#101214';
      tracePolygon(ctx, f.corners[frame][i].map(fit));
      ctx.fill();
      ctx.stroke();
    }
    this.drawDistanceChart(ctx, f, frame, { x: box.x + 4, y: box.y + pictureH + 4, w: box.w - 8, h: box.h - pictureH - line - 8 }, style);
    sentence.draw(box.x + 4, box.y + box.h - sentence.height, '#e6e6e6');
  },

  drawDistanceChart(ctx, f, frame, box, style) {
    const largest = Math.max(f.threshold_px * 1.5, ...f.distance_px);
    const label = 40 * style.scale;
    const plot = { x: box.x + label, y: box.y + 18 * style.scale, w: box.w - label - 6, h: box.h - 36 * style.scale };
    const X = (k) => plot.x + (plot.w * k) / Math.max(1, f.frames);
    const Y = (v) => plot.y + plot.h * (1 - v / largest);
    ctx.strokeStyle = '#3a3f47';
    ctx.lineWidth = 1;
    ctx.strokeRect(plot.x, plot.y, plot.w, plot.h);
    ctx.fillStyle = '#c8ccd2';
    ctx.font = style.font(12);
    ctx.fillText('px apart, per frame', plot.x, box.y + 13 * style.scale);
    ctx.fillText(largest.toFixed(1), box.x, plot.y + 10 * style.scale);
    ctx.fillText('0', box.x, plot.y + plot.h);
    ctx.fillText(`frame ${f.frames}`, plot.x + plot.w - ctx.measureText(`frame ${f.frames}`).width, plot.y + plot.h + 15 * style.scale);
    ctx.setLineDash([5, 4]);
    ctx.strokeStyle = '#e6e6e6';
    ctx.beginPath();
    ctx.moveTo(plot.x, Y(f.threshold_px));
    ctx.lineTo(plot.x + plot.w, Y(f.threshold_px));
    if (f.first_frame_apart >= 0) {
      ctx.moveTo(X(f.first_frame_apart), plot.y);
      ctx.lineTo(X(f.first_frame_apart), plot.y + plot.h);
    }
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.strokeStyle = kOkabeVermillion;
    ctx.lineWidth = 2 * style.line;
    ctx.beginPath();
    f.distance_px.forEach((v, k) => (k ? ctx.lineTo(X(k), Y(v)) : ctx.moveTo(X(k), Y(v))));
    ctx.stroke();
    ctx.fillStyle = '#e6e6e6';
    ctx.beginPath();
    ctx.arc(X(frame), Y(f.distance_px[frame]), 4 * style.scale, 0, 2 * Math.PI);
    ctx.fill();
  },
};

// A uniform map of `points` ([x, y], Y down) onto `box`, centred, grown by `margin` of their
// extent on every side: returns the function from a point to canvas [x, y].
function fitBox(points, box, margin) {
  const xs = points.map((p) => p[0]);
  const ys = points.map((p) => p[1]);
  const x0 = Math.min(...xs);
  const x1 = Math.max(...xs);
  const y0 = Math.min(...ys);
  const y1 = Math.max(...ys);
  const spanX = Math.max(x1 - x0, 1e-9) * (1 + 2 * margin);
  const spanY = Math.max(y1 - y0, 1e-9) * (1 + 2 * margin);
  const k = Math.min(box.w / spanX, box.h / spanY);
  const cx = (x0 + x1) / 2;
  const cy = (y0 + y1) / 2;
  return (p) => [box.x + box.w / 2 + k * (p[0] - cx), box.y + box.h / 2 + k * (p[1] - cy)];
}

// `text` in a font of `px` (doubled in presentation mode) wrapped to `width` pixels: its
// height, and draw(x, top, colour) to draw it with its first line's top at `top`.
function textBlock(ctx, text, width, px, style) {
  ctx.font = style.font(px);
  const lines = wrapLines(ctx, text, width);
  const step = 1.3 * px * style.scale;
  return {
    height: lines.length * step,
    draw(x, top, colour) {
      ctx.font = style.font(px);
      ctx.fillStyle = colour;
      lines.forEach((l, i) => ctx.fillText(l, x, top + (i + 0.8) * step));
    },
  };
}

// A legend of [text, colour] items laid out in rows at most `width` pixels wide: its height,
// and draw(x, top).
function legendRows(ctx, items, width, px, style) {
  ctx.font = style.font(px);
  const gap = 14 * style.scale;
  const step = 1.3 * px * style.scale;
  const placed = [];
  let x = 0;
  let row = 0;
  for (const [text, colour] of items) {
    const w = ctx.measureText(text).width;
    if (x > 0 && x + w > width) { x = 0; ++row; }
    placed.push({ text, colour, x, row });
    x += w + gap;
  }
  return {
    height: (row + 1) * step,
    draw(left, top) {
      ctx.font = style.font(px);
      for (const p of placed) {
        ctx.fillStyle = p.colour;
        ctx.fillText(p.text, left + p.x, top + (p.row + 0.8) * step);
      }
    },
  };
}

// `text` in the middle of `box`, wrapped to its width.
function drawNote(ctx, box, text, style) {
  const block = textBlock(ctx, text, box.w - 12, 14, style);
  block.draw(box.x + 6, box.y + (box.h - block.height) / 2, '#e6e6e6');
}

app.explorer = explorerView;
