'use strict';
// The scene-shifting view, "Scene shifting" (the desktop's view id "slices";
// manual/scene-shifting.md): a top-down diagram of the slices for the train-window scene
// (depth against lateral position: the eye, the slice boundaries, the asymptote
// k|V|/epsilon, the scene's planes, depth ticks, a legend) beside the scene-shifting
// renderer's layered frame and core's exact projection of the same frame, with epsilon and
// the viewer's speed on sliders. Every number and pixel comes from the teaching layer
// (Module.Slices: session/player/slice_walk.h and session/display/slice_diagram.h, which
// the desktop's view draws too); this file only lays them out on the 2D canvas.

const kSliceBandA = 'rgba(90, 170, 120, 0.235)';
const kSliceBandB = 'rgba(90, 120, 170, 0.235)';
const kSliceAsymptote = 'rgb(213, 94, 0)';  // Okabe-Ito vermillion
const kSlicePlane = 'rgb(230, 159, 0)';     // Okabe-Ito orange
const kSliceText = '#e6e6e6';
const kSliceOutline = 'rgb(150, 156, 165)';

const slicesView = {
  title: 'Scene shifting',
  slices: null,  // Module.Slices, made when the view is first drawn
  info: null,    // the last update's JSON
  images: [],    // the two frames' ImageData, reused

  build() {
    for (const id of ['slices-epsilon', 'slices-speed']) {
      $(id).addEventListener('input', () => { this.syncLabels(); app.dirty = true; });
    }
    this.syncLabels();
  },

  // Epsilon in pixels per frame and |V| in world units per frame, from the sliders.
  epsilon() { return Number($('slices-epsilon').value); },
  speed() { return Number($('slices-speed').value); },
  syncLabels() {
    $('slices-epsilon-value').textContent = `${this.epsilon().toFixed(2)} px/frame`;
    $('slices-speed-value').textContent = `${this.speed().toFixed(2)} units/frame`;
  },

  // The walk at the window's frame (the play bar's, modulo the walk's length).
  update() {
    if (!this.slices) this.slices = new Module.Slices();
    this.info = JSON.parse(this.slices.update(this.epsilon(), this.speed(), app.state.frame));
    return this.info;
  },

  draw(ctx, w, h, style) {
    const info = this.update();
    if (info.problem) {
      drawCentredText(ctx, w, h, info.caption, style);
      return;
    }
    ctx.font = style.font(13);
    const step = 17 * style.scale;
    const captionLines = wrapLines(ctx, info.caption, w - 24);
    const bottom = h - 12 - captionLines.length * step;
    const half = Math.floor(w / 2);
    this.drawDiagram(ctx, { x: 0, y: 0, w: half, h: bottom }, info.diagram, style);
    const frameH = Math.floor(bottom / 2);
    this.drawFrame(ctx, 0, 'scene shifting (slices)', { x: half, y: 0, w: w - half, h: frameH }, info, style);
    this.drawFrame(ctx, 1, info.exact_problem || info.exact_title, { x: half, y: frameH, w: w - half, h: bottom - frameH },
      info, style);
    ctx.font = style.font(13);
    ctx.fillStyle = kSliceText;
    captionLines.forEach((line, i) => ctx.fillText(line, 12, h - 10 - (captionLines.length - 1 - i) * step));
  },

  // A camera frame fitted under its title in `box`; frame 0 is scene shifting's, 1 the exact one.
  drawFrame(ctx, index, title, box, info, style) {
    ctx.font = `bold ${style.font(13)}`;
    ctx.fillStyle = kSliceText;
    ctx.textAlign = 'center';
    ctx.fillText(title, box.x + box.w / 2, box.y + 16 * style.scale, box.w - 8);
    ctx.textAlign = 'left';
    const top = box.y + 22 * style.scale;
    if (!info.width || !info.height) return;
    const k = Math.min((box.w - 8) / info.width, (box.h - (top - box.y) - 4) / info.height);
    const pw = Math.max(1, Math.floor(k * info.width));
    const ph = Math.max(1, Math.floor(k * info.height));
    const pixels = this.slices.pixels(index === 1, pw, ph);
    if (!pixels.length) return;
    let image = this.images[index];
    if (!image || image.width !== pw || image.height !== ph) {
      image = new ImageData(pw, ph);
      this.images[index] = image;
    }
    image.data.set(pixels);
    const x = Math.round(box.x + (box.w - pw) / 2);
    const y = Math.round(top);
    ctx.putImageData(image, x, y);
    ctx.strokeStyle = 'rgb(110, 116, 125)';
    ctx.lineWidth = 1;
    ctx.strokeRect(x + 0.5, y + 0.5, pw - 1, ph - 1);
  },

  // The top-down diagram in `box`, as the desktop's (gui/views/slices_view.cpp
  // paint_slice_diagram): depth left to right on the teaching layer's square-root scale.
  drawDiagram(ctx, box, d, style) {
    ctx.save();
    ctx.translate(box.x, box.y);
    ctx.font = style.font(13);
    const line = 17 * style.scale;
    const left = 40 * style.scale;
    const right = box.w - 20;
    const bottom = box.h - 2.4 * line - 10;
    ctx.fillStyle = kSliceText;
    ctx.fillText(d.title, left, line);
    const labelRow = this.drawLegend(ctx, left, 1.3 * line, right - left, line, style);
    const top = labelRow + 1.2 * line + 4;
    const xOf = (z) => left + (right - left) * Math.sqrt(Math.min(Math.max(z, 0), d.max_depth) / d.max_depth);
    const yOf = (x) => top + (bottom - top) * (0.5 - x / (2 * d.half_width));
    d.slices.forEach((s, i) => {
      const far = s.far === null ? d.max_depth : s.far;
      ctx.fillStyle = i % 2 ? kSliceBandB : kSliceBandA;
      ctx.fillRect(xOf(s.near), top, xOf(far) - xOf(s.near), bottom - top);
      this.vertical(ctx, xOf(s.near), top, bottom, kSliceOutline, style.line, []);
    });
    if (d.asymptote !== null) {
      const x = xOf(d.asymptote);
      this.vertical(ctx, x, labelRow + line, bottom, kSliceAsymptote, 2 * style.line, [6, 4]);
      const width = ctx.measureText(d.asymptote_label).width;
      ctx.fillStyle = kSliceText;
      ctx.textBaseline = 'middle';
      ctx.fillText(d.asymptote_label, Math.min(Math.max(x - width / 2, left), Math.max(left, right - width)), labelRow + line / 2);
      ctx.textBaseline = 'alphabetic';
    }
    const clamp = (v) => Math.min(Math.max(v, -d.half_width), d.half_width);
    for (const p of d.planes) {
      if (p.depth > 0) this.segment(ctx, xOf(p.depth), yOf(clamp(p.left)), yOf(clamp(p.right)), kSlicePlane, 4 * style.line);
    }
    ctx.fillStyle = kSliceText;
    ctx.beginPath();
    ctx.arc(left, yOf(0), 5 * style.scale, 0, 2 * Math.PI);
    ctx.fill();
    ctx.fillText('eye', left - 30 * style.scale, yOf(0) - 8);
    this.drawAxis(ctx, xOf, left, right, bottom, d.ticks, line);
    ctx.restore();
  },

  vertical(ctx, x, y0, y1, colour, width, dash) {
    ctx.strokeStyle = colour;
    ctx.lineWidth = width;
    ctx.setLineDash(dash);
    ctx.beginPath();
    ctx.moveTo(x, y0);
    ctx.lineTo(x, y1);
    ctx.stroke();
    ctx.setLineDash([]);
  },

  segment(ctx, x, y0, y1, colour, width) { this.vertical(ctx, x, y0, y1, colour, width, []); },

  // The depth axis: a tick and label at each depth tick, the axis title at the right.
  drawAxis(ctx, xOf, left, right, bottom, ticks, line) {
    ctx.strokeStyle = kSliceText;
    ctx.fillStyle = kSliceText;
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(left, bottom);
    ctx.lineTo(right, bottom);
    ctx.stroke();
    let lastRight = -1e9;
    for (const z of ticks) {
      const x = xOf(z);
      ctx.beginPath();
      ctx.moveTo(x, bottom);
      ctx.lineTo(x, bottom + 5);
      ctx.stroke();
      const label = String(z);
      const width = ctx.measureText(label).width;
      if (x - width / 2 < lastRight + 6) continue;  // too close to the previous label
      ctx.fillText(label, x - width / 2, bottom + 5 + 0.8 * line);
      lastRight = x + width / 2;
    }
    const title = 'depth Z, world units (square-root scale)';
    ctx.fillText(title, right - ctx.measureText(title).width, bottom + 6 + 1.8 * line);
  },

  // The legend from (x0, y0): a swatch of each mark and its meaning, in as many rows as the
  // width needs. Returns the y below its last row.
  drawLegend(ctx, x0, y0, width, line, style) {
    const swatch = 1.6 * line;
    let x = x0;
    let y = y0;
    const entry = (name, mark) => {
      const w = swatch + 4 + ctx.measureText(name).width;
      if (x > x0 && x + w > x0 + width) { x = x0; y += 1.2 * line; }
      mark(x, y + 0.15 * line, swatch, 0.7 * line);
      ctx.fillStyle = kSliceText;
      ctx.fillText(name, x + swatch + 4, y + 0.8 * line);
      x += w + line;
    };
    entry('slices', (bx, by, bw, bh) => {
      ctx.fillStyle = kSliceBandA;
      ctx.fillRect(bx, by, bw / 2, bh);
      ctx.fillStyle = kSliceBandB;
      ctx.fillRect(bx + bw / 2, by, bw / 2, bh);
    });
    entry('slice boundary', (bx, by, bw, bh) => this.vertical(ctx, bx + bw / 2, by, by + bh, kSliceOutline, style.line, []));
    entry('asymptote k|V|/epsilon', (bx, by, bw, bh) => this.vertical(ctx, bx + bw / 2, by, by + bh, kSliceAsymptote, 2 * style.line, [4, 3]));
    entry('scene plane (seen from above)', (bx, by, bw, bh) => this.segment(ctx, bx + bw / 2, by, by + bh, kSlicePlane, 4 * style.line));
    return y + 1.2 * line;
  },
};
app.views.slices = slicesView;
