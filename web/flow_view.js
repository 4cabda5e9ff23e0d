'use strict';
// The flow view: the plane's outline and faded texture (core's exact image of the plane,
// Session.flowTexture, as the desktop's), and the chosen part of its flow (gui/adapters/
// flow_parts.h) as arrows, streamlines and a colour wheel, with the coefficient table in the
// planar basis and its units. Every vector comes from core (Session.arrows, .streamlines,
// .flowJson); this file only maps them to the canvas.

const flowView = {
  title: 'Flow',

  build() {
    const draw = $('flow-draw');
    const options = [['arrows', 'Arrows'], ['streamlines', 'Streamlines'], ['colour_wheel', 'Colour wheel'],
      ['texture', 'Texture'], ['zoom_to_plane', 'Zoom to plane'], ['common_scale', 'Common scale']];
    for (const [key, label] of options) {
      const box = document.createElement('input');
      box.type = 'checkbox';
      box.id = `flow-${key}`;
      box.addEventListener('change', () => editState((s) => { s.flow[key] = box.checked; }));
      const row = document.createElement('label');
      row.append(box, ` ${label}`);
      draw.appendChild(row);
    }
    $('flow-part').addEventListener('change', () => editState((s) => { s.flow.part = $('flow-part').value; }));
    for (const part of JSON.parse(app.session.flowJson()).parts) $('flow-part').add(new Option(part.title, part.key));
  },

  syncControls(s) {
    $('flow-part').value = s.flow.part;
    for (const key of ['arrows', 'streamlines', 'colour_wheel', 'texture', 'zoom_to_plane', 'common_scale']) {
      $(`flow-${key}`).checked = s.flow[key];
    }
  },

  // Image pixels -> canvas: the image (or the plane's image) fitted into the area, Y down.
  fit(flow, area) {
    let [x0, y0, x1, y1] = [0, 0, flow.camera.width, flow.camera.height];
    if (app.state.flow.zoom_to_plane && flow.outline) {
      const xs = flow.outline.map((p) => p[0]).concat([flow.camera.cx]);
      const ys = flow.outline.map((p) => p[1]).concat([flow.camera.cy]);
      [x0, y0, x1, y1] = [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
      const pad = 0.08 * Math.max(x1 - x0, y1 - y0);
      [x0, y0, x1, y1] = [x0 - pad, y0 - pad, x1 + pad, y1 + pad];
    }
    const k = Math.min(area.w / (x1 - x0), area.h / (y1 - y0));
    const ox = area.x + (area.w - k * (x1 - x0)) / 2 - k * x0;
    const oy = area.y + (area.h - k * (y1 - y0)) / 2 - k * y0;
    return { k, map: (x, y) => [ox + k * x, oy + k * y] };
  },

  spacing(flow) {
    if (app.state.flow.spacing_px > 0) return app.state.flow.spacing_px;
    // About 14 arrows across the plane's image, 6 to 48 pixels apart (as the desktop).
    const xs = flow.outline.map((p) => p[0]);
    return Math.min(48, Math.max(6, (Math.max(...xs) - Math.min(...xs)) / 14));
  },

  draw(ctx, w, h, style) {
    const flow = JSON.parse(app.session.flowJson());
    if (flow.problem) {
      drawCentredText(ctx, w, h, `No flow to draw: ${flow.problem}`, style);
      return;
    }
    const area = { x: 10, y: 10, w: w - 20, h: h - 40 };
    const fit = this.fit(flow, area);
    const part = app.state.flow.part;
    const spacing = this.spacing(flow);
    // The texture (not under the colour wheel, which is opaque over the plane, as the desktop).
    const textured = app.state.flow.texture && !app.state.flow.colour_wheel;
    this.drawnTexture = textured ? this.drawTexture(ctx, fit, area, flow) : null;
    // The image frame and the plane's outline, tinted when it has no texture.
    ctx.lineWidth = style.line;
    ctx.strokeStyle = '#3a3f47';
    const [ix0, iy0] = fit.map(0, 0);
    ctx.strokeRect(ix0, iy0, fit.k * flow.camera.width, fit.k * flow.camera.height);
    tracePolygon(ctx, flow.outline.map((p) => fit.map(p[0], p[1])));
    ctx.fillStyle = 'rgba(90, 169, 230, 0.10)';
    if (!this.drawnTexture) ctx.fill();
    ctx.strokeStyle = '#5aa9e6';
    ctx.stroke();
    if (app.state.flow.colour_wheel) this.drawWheel(ctx, fit, part, Math.max(2, spacing / 4));
    const arrows = app.session.arrows(part, spacing);
    if (app.state.flow.arrows) this.drawArrows(ctx, fit, arrows, flow, spacing, style);
    if (app.state.flow.streamlines) this.drawStreamlines(ctx, fit, part, spacing, style);
    // The principal point, where the coefficients are expanded.
    const [cx, cy] = fit.map(flow.camera.cx, flow.camera.cy);
    ctx.strokeStyle = '#e6e6e6';
    ctx.beginPath();
    ctx.moveTo(cx - 6, cy); ctx.lineTo(cx + 6, cy); ctx.moveTo(cx, cy - 6); ctx.lineTo(cx, cy + 6);
    ctx.stroke();
    ctx.fillStyle = '#e6e6e6';
    ctx.font = style.font(13);
    const title = flow.parts.find((p) => p.key === part).title;
    ctx.fillText(`${title}, px/s (frame ${flow.frame}; motion model ${flow.motion_model})`, 12, h - 12);
    this.fillTable(flow);
  },

  // The plane's exact image (Session.flowTexture) faded towards the background as the
  // desktop's (0.45, 0.6 in presentation mode), sampled at the canvas pixels of the plane's
  // outline box inside the image frame and `area`; the canvas is the page's background there
  // (nothing is drawn before), so the pixels are put, not blended. Returns what was drawn
  // ({x, y, width, height} canvas pixels), or null.
  drawTexture(ctx, fit, area, flow) {
    const [ox, oy] = fit.map(0, 0);
    const cx = flow.outline.map((p) => fit.map(p[0], p[1])[0]);
    const cy = flow.outline.map((p) => fit.map(p[0], p[1])[1]);
    const left = Math.max(area.x, ox, Math.min(...cx));
    const top = Math.max(area.y, oy, Math.min(...cy));
    const right = Math.min(area.x + area.w, ox + fit.k * flow.camera.width, Math.max(...cx));
    const bottom = Math.min(area.y + area.h, oy + fit.k * flow.camera.height, Math.max(...cy));
    const [x, y] = [Math.floor(left), Math.floor(top)];
    const [width, height] = [Math.ceil(right) - x, Math.ceil(bottom) - y];
    if (!(width >= 1 && height >= 1)) return null;
    const opacity = app.state.presentation ? 0.6 : 0.45;
    const t = app.session.flowTexture((x - ox) / fit.k, (y - oy) / fit.k, 1 / fit.k, width, height, opacity);
    if (!t) return null;
    // putImageData ignores the context's transform: add its shift (the world view's layout
    // draws this view translated into the canvas's right half).
    const m = ctx.getTransform();
    // The image data is a view of the module's pixels, put at once (no copy).
    const data = new Uint8ClampedArray(t.pixels.buffer, t.pixels.byteOffset, t.pixels.length);
    ctx.putImageData(new ImageData(data, t.width, t.height), x + m.e, y + m.f);
    return { x, y, width, height };
  },

  // Arrow length: the largest flow of the drawn part (or of the full flow, with a common
  // scale) spans 0.9 grid spacings; colour is the magnitude.
  drawArrows(ctx, fit, a, flow, spacing, style) {
    let largest = 0;
    const scaleOf = app.state.flow.common_scale ? app.session.arrows('full', spacing) : a;
    for (let i = 0; i < scaleOf.length; i += 4) largest = Math.max(largest, Math.hypot(scaleOf[i + 2], scaleOf[i + 3]));
    if (!(largest > 0)) return;
    const s = 0.9 * spacing / largest;
    ctx.lineWidth = 1.2 * style.line;
    // One path per colour: the magnitude in kArrowColours steps.
    const kArrowColours = 12;
    const paths = Array.from({ length: kArrowColours }, () => new Path2D());
    for (let i = 0; i < a.length; i += 4) {
      const m = Math.min(1, Math.hypot(a[i + 2], a[i + 3]) / largest);
      const [x0, y0] = fit.map(a[i], a[i + 1]);
      const [x1, y1] = fit.map(a[i] + s * a[i + 2], a[i + 1] + s * a[i + 3]);
      addArrow(paths[Math.min(kArrowColours - 1, Math.floor(m * kArrowColours))], x0, y0, x1, y1, 4 * style.line);
    }
    paths.forEach((path, c) => {
      // The one magnitude ramp of every front-end (session/display/palette.h), from its
      // blue on: its darkest purple would vanish on the page's dark background.
      const [r, g, b] = Module.heatColour(0.25 + 0.75 * (c + 0.5) / kArrowColours);
      ctx.strokeStyle = `rgb(${r},${g},${b})`;
      ctx.stroke(path);
    });
  },

  drawStreamlines(ctx, fit, part, spacing, style) {
    const p = app.session.streamlines(part, 2 * spacing, 0.5, 24);
    ctx.strokeStyle = 'rgba(230, 230, 230, 0.75)';
    ctx.lineWidth = style.line;
    ctx.beginPath();
    let pen = false;
    for (let i = 0; i < p.length; i += 2) {
      if (Number.isNaN(p[i])) { pen = false; continue; }
      const [x, y] = fit.map(p[i], p[i + 1]);
      if (pen) ctx.lineTo(x, y); else ctx.moveTo(x, y);
      pen = true;
    }
    ctx.stroke();
  },

  // Hue is the direction of the flow, saturation its magnitude over the largest; a legend
  // wheel in the corner says which hue is which direction.
  drawWheel(ctx, fit, part, step) {
    const a = app.session.arrows(part, step);
    let largest = 0;
    for (let i = 0; i < a.length; i += 4) largest = Math.max(largest, Math.hypot(a[i + 2], a[i + 3]));
    const cell = fit.k * step + 0.5;
    for (let i = 0; i < a.length; i += 4) {
      const [x, y] = fit.map(a[i] - step / 2, a[i + 1] - step / 2);
      ctx.fillStyle = wheelColour(a[i + 2], a[i + 3], largest);
      ctx.fillRect(x, y, cell, cell);
    }
    const r = 34;
    const [lx, ly] = [ctx.canvas.width - r - 14, r + 14];
    for (let j = -r; j <= r; j += 2) {
      for (let i = -r; i <= r; i += 2) {
        if (i * i + j * j > r * r) continue;
        ctx.fillStyle = wheelColour(i, j, r);
        ctx.fillRect(lx + i, ly + j, 2, 2);
      }
    }
  },

  fillTable(flow) {
    const b = flow.planar_basis;
    const c = flow.coefficients;
    const rows = [['Planar basis', '', ''],
      ['tx', b.tx, 'px/s'], ['ty', b.ty, 'px/s'], ['scale', b.scale, '1/s'], ['squash', b.squash, '1/s'],
      ['shear', b.shear, '1/s'], ['rotation', b.rotation, '1/s'], ['px', b.px, '1/(px s)'], ['py', b.py, '1/(px s)'],
      ['Coefficients', '', '']];
    for (const key of ['j11', 'j12', 'j21', 'j22']) rows.push([key, c[key], flow.units[key]]);
    setHtml($('coefficients'), rows.map(([name, value, unit]) => (unit === ''
      ? `<tr><th colspan="3">${name}</th></tr>`
      : `<tr><td>${name}</td><td class="${Math.abs(value) < 1e-12 ? 'zero' : ''}">${formatNumber(value)}</td>` +
        `<td class="unit">${unit}</td></tr>`)).join(''));
  },
};
app.views.flow = flowView;

// The flow colour wheel of core's palette (session/display/palette.h flow_wheel_colour), as
// the desktop draws it: sampled once at every degree and 64 magnitudes, then looked up.
const kWheelAngles = 360;
const kWheelLevels = 64;
let wheelTableCache = null;
function wheelColour(vx, vy, largest) {
  if (!wheelTableCache) wheelTableCache = Uint8Array.from(Module.wheelTable(kWheelAngles, kWheelLevels));
  const a = Math.round(((Math.atan2(vy, vx) * 180 / Math.PI) + 360) % 360) % kWheelAngles;
  const m = largest > 0 ? Math.min(1, Math.hypot(vx, vy) / largest) : 0;
  const i = 3 * (a * kWheelLevels + Math.round(m * (kWheelLevels - 1)));
  return `rgb(${wheelTableCache[i]},${wheelTableCache[i + 1]},${wheelTableCache[i + 2]})`;
}

function formatNumber(v) {
  if (v === 0 || Math.abs(v) < 1e-12) return '0';
  const a = Math.abs(v);
  return a >= 1e4 || a < 1e-3 ? v.toExponential(3) : v.toPrecision(4);
}

function tracePolygon(ctx, points) {
  ctx.beginPath();
  points.forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
  ctx.closePath();
}

// An arrow from (x0, y0) to (x1, y1) with a head of `head` pixels (at most 0.4 of its
// length) added to `path` (a Path2D or the context's current path).
function addArrow(path, x0, y0, x1, y1, head) {
  const len = Math.hypot(x1 - x0, y1 - y0);
  path.moveTo(x0, y0);
  path.lineTo(x1, y1);
  if (len > 2) {
    const ux = (x1 - x0) / len;
    const uy = (y1 - y0) / len;
    const hl = Math.min(head, 0.4 * len);
    path.moveTo(x1 - hl * (ux - 0.5 * uy), y1 - hl * (uy + 0.5 * ux));
    path.lineTo(x1, y1);
    path.lineTo(x1 - hl * (ux + 0.5 * uy), y1 - hl * (uy - 0.5 * ux));
  }
}

// `text` broken at spaces into lines at most `width` pixels wide in the context's font (a
// word longer than that gets a line of its own).
function wrapLines(ctx, text, width) {
  const lines = [];
  let line = '';
  for (const word of text.split(' ')) {
    const longer = line ? `${line} ${word}` : word;
    if (line && ctx.measureText(longer).width > width) {
      lines.push(line);
      line = word;
    } else {
      line = longer;
    }
  }
  lines.push(line);
  return lines;
}

// `text` centred in the canvas, wrapped into lines at most 80 % of its width.
function drawCentredText(ctx, w, h, text, style) {
  ctx.fillStyle = '#e6e6e6';
  ctx.font = style.font(16);
  ctx.textAlign = 'center';
  const lines = wrapLines(ctx, text, 0.8 * w);
  const step = 22 * style.scale;
  lines.forEach((l, i) => ctx.fillText(l, w / 2, h / 2 + (i - (lines.length - 1) / 2) * step));
  ctx.textAlign = 'start';
}
