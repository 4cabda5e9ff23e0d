'use strict';
// The comparison: the state's compared reuse policies (affine and perspective by default)
// and the exact projection play the same frames of the source, side by side; each panel
// shows its frame with the shown layer's outline in the colour of the engine's level, and
// under each policy the difference from the exact frame as a heat map. The frames, levels,
// errors and heat maps come from core (Session.runPixels, .runHeat, .comparisonJson).

const kLevelColours = {
  none: '#9aa0a6', translate: '#5aa9e6', affine: '#6cc070', perspective: '#e6c35a', rerender: '#e0645a',
};

const comparisonView = {
  title: 'Comparison',
  surfaces: [],  // per run: an offscreen canvas and its ImageData, reused frame to frame

  surface(index, width, height) {
    let s = this.surfaces[index];
    if (!s || s.canvas.width !== width || s.canvas.height !== height) {
      const canvas = document.createElement('canvas');
      canvas.width = width;
      canvas.height = height;
      s = { canvas, ctx: canvas.getContext('2d'), image: new ImageData(width, height) };
      this.surfaces[index] = s;
    }
    return s;
  },

  // Copies core's pixels (a view into the module's memory) into surface `index`.
  blit(index, pixels, width, height) {
    const s = this.surface(index, width, height);
    s.image.data.set(pixels);
    s.ctx.putImageData(s.image, 0, 0);
    return s.canvas;
  },

  draw(ctx, w, h, style) {
    const info = JSON.parse(app.session.comparisonJson());
    if (info.problem) {
      drawCentredText(ctx, w, h, info.problem, style);
      $('runs').innerHTML = '';
      return;
    }
    const n = info.runs.length;
    const pad = 8;
    const label = 20 * style.scale;
    const panelW = (w - pad * (n + 1)) / n;
    const k = Math.min(panelW / info.width, (h / 2 - label - pad * 2) / info.height);
    const pw = k * info.width;
    const ph = k * info.height;
    info.runs.forEach((run, i) => {
      const x = pad + i * (panelW + pad) + (panelW - pw) / 2;
      const y = pad + label;
      const exact = i === n - 1;
      ctx.drawImage(this.blit(2 * i, app.session.runPixels(i), info.width, info.height), x, y, pw, ph);
      for (const outline of run.outlines) {
        tracePolygon(ctx, outline.points.map(([px, py]) => [x + k * px, y + k * py]));
        ctx.strokeStyle = kLevelColours[outline.level];
        ctx.lineWidth = 2 * style.line;
        ctx.stroke();
      }
      ctx.fillStyle = '#e6e6e6';
      ctx.font = style.font(14);
      ctx.fillText(exact ? 'exact projection' : `${run.policy}: ${run.level}, ${run.measured_error_px.toFixed(2)} px`,
        x, pad + 14 * style.scale, pw);
      if (exact) return;
      const hy = y + ph + label + pad;
      ctx.drawImage(this.blit(2 * i + 1, app.session.runHeat(i), info.width, info.height), x, hy, pw, ph);
      ctx.fillText(`difference from exact: largest ${run.heat_max} grey levels, PSNR ${run.psnr_db.toFixed(1)} dB`,
        x, hy - 6, pw);
    });
    this.drawLegend(ctx, pad + (n - 1) * (panelW + pad), pad * 2 + label + ph + label, panelW, info, style);
    this.fillTable(info);
  },

  // The levels' colours and the heat map's colour bar (0 .. full scale grey levels).
  drawLegend(ctx, x, y, width, info, style) {
    ctx.font = style.font(13);
    let ly = y + 10;
    for (const [level, colour] of Object.entries(kLevelColours)) {
      ctx.fillStyle = colour;
      ctx.fillRect(x, ly - 10, 14, 10);
      ctx.fillStyle = '#e6e6e6';
      ctx.fillText(level, x + 20, ly);
      ly += 18 * style.scale;
    }
    ly += 10;
    const barW = Math.min(width, 256);
    for (let i = 0; i < barW; ++i) {
      const [r, g, b] = Module.heatColour(i / (barW - 1));
      ctx.fillStyle = `rgb(${r},${g},${b})`;
      ctx.fillRect(x + i, ly, 1, 14);
    }
    ctx.fillStyle = '#e6e6e6';
    ctx.fillText('0', x, ly + 30 * style.scale);
    ctx.fillText(`${info.heat_full_scale}+ grey levels`, x + barW - 110 * style.scale, ly + 30 * style.scale);
  },

  fillTable(info) {
    const levels = ['none', 'translate', 'affine', 'perspective', 'rerender'];
    const runs = info.runs.slice(0, -1);
    let html = `<tr><th>frame ${info.frame}</th>${runs.map((r) => `<th>${r.policy}</th>`).join('')}</tr>`;
    html += `<tr><td>level</td>${runs.map((r) => `<td>${r.level}</td>`).join('')}</tr>`;
    html += `<tr><td>error, px</td>${runs.map((r) => `<td>${r.measured_error_px.toFixed(3)}</td>`).join('')}</tr>`;
    html += `<tr><td>largest, px</td>${runs.map((r) => `<td>${r.max_error_px.toFixed(3)}</td>`).join('')}</tr>`;
    html += `<tr><th colspan="${runs.length + 1}">share of frames 1 .. now</th></tr>`;
    for (const level of levels) {
      html += `<tr><td>${level}</td>${runs.map((r) => `<td>${(100 * r.level_shares[level]).toFixed(0)}%</td>`).join('')}</tr>`;
    }
    $('runs').innerHTML = html;
  },
};
app.views.animation = comparisonView;
