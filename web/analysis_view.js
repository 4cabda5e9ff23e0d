'use strict';
// The analysis charts, by the desktop's rule (gui/views/analysis_charts.h): while the state's
// animation display is the comparison layout, the compared runs' charts: one line per policy
// for the largest measured error, the frame time and the work in the cost model, and one band
// per policy with its drawn layers per level, stacked in the levels' colours. Otherwise the
// model's one engine (the state's mode): its frame time and the percent of drawn layers
// approximated (not re-rendered), its layers per level, and for each cheaper level the error
// it would leave (its budget: the carried books plus the frame's flow over the terms it
// neglects, the sum the engine tests) against its dashed threshold, with the measured error
// dotted. Over the last kAnalysisFrames frames of the current pass; the x axis moves only when
// the frame shown leaves it; a click on a chart goes to the frame under the pointer, through
// that chart's own rectangle. The histories come from core (Session.analysisJson:
// session/player/policy_comparison.h's records, session/player/run_player.h's budgets).

const kAnalysisFrames = 80;
// The policies' line colours, in the compared order (Okabe and Ito's colour-blind-safe set,
// the palette of session/display/palette.h).
const kPolicyColours = ['rgb(86,180,233)', 'rgb(230,159,0)', 'rgb(0,158,115)', 'rgb(204,121,167)', 'rgb(213,94,0)'];
// The budget charts' levels, in the engine's order (none .. perspective).
const kBudgetLevels = ['none', 'translate', 'affine', 'perspective'];

const analysisView = {
  title: 'Analysis',
  range: [0, kAnalysisFrames - 1],  // the frames the x axis shows
  charts: [],                        // each chart's {x, y, w, h}, for clicks
  // The rectangles (canvas pixels) of the charts of times measured in this page, with their
  // values' labels: they differ from run to run, so a screenshot's comparison leaves them out.
  measured: [],

  // The x range holding `frame`: kept while the frame is in it, else moved to end at it.
  xRange(frame) {
    const [a, b] = this.range;
    if (frame < a || frame > b) {
      const first = Math.max(0, frame - kAnalysisFrames + 1);
      this.range = [first, first + kAnalysisFrames - 1];
    }
    return this.range;
  },

  build() {
    $('canvas').addEventListener('click', (e) => {
      if (shownView() !== 'analysis') return;
      const rect = $('canvas').getBoundingClientRect();
      const [px, py] = [e.clientX - rect.left, e.clientY - rect.top];
      const chart = this.charts.find((c) => px >= c.x && px <= c.x + c.w && py >= c.y - 4 && py <= c.y + c.h + 4);
      if (!chart) return;
      seek(Math.round(this.range[0] + ((px - chart.x) / chart.w) * (this.range[1] - this.range[0])));
    });
    // Charts of the compared policies exactly while the display is the comparison layout.
    $('analysis-of').addEventListener('change', () => editState((s) => {
      const comparison = $('analysis-of').value === 'comparison';
      if (comparison) s.animation.display = 'comparison';
      else if (s.animation.display === 'comparison') s.animation.display = 'side-by-side';
    }));
  },

  syncControls(s) {
    $('analysis-of').value = s.animation.display === 'comparison' ? 'comparison' : 'engine';
  },

  draw(ctx, w, h, style) {
    const data = JSON.parse(app.session.analysisJson(kAnalysisFrames));
    if (data.problem) {
      drawCentredText(ctx, w, h, data.problem, style);
      return;
    }
    const [a, b] = this.xRange(data.last);
    const x = 60 * style.scale;
    const cw = w - x - 20;
    const fx = (cx, cwidth) => (frame) => cx + (cwidth * (frame - a)) / Math.max(1, b - a);
    const at = (cx, y, cwidth, ch) => ({ x: cx, y, w: cwidth, h: ch, a, b, fx: fx(cx, cwidth) });
    const top = 26 * style.scale;
    const gap = 44 * style.scale;
    this.drawn = [];
    this.charts = [];
    this.measured = [];
    if (data.comparing) this.drawComparison(ctx, data, at, x, top, cw, h, gap, style);
    else this.drawEngine(ctx, data, at, x, top, cw, h, gap, style);
    // The frame shown, on every chart.
    ctx.strokeStyle = '#e6e6e6';
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (const c of this.charts) {
      const fxv = fx(c.x, c.w)(data.last);
      ctx.moveTo(fxv, c.y);
      ctx.lineTo(fxv, c.y + c.h);
    }
    ctx.stroke();
    const of = data.comparing ? 'the compared policies' : `the ${data.runs[0].policy} engine`;
    setHtml($('analysis-note'), `${of}: frames ${a} .. ${b}; click a chart to go to a frame (now ${data.last})`);
  },

  // The compared runs: three line charts (error, frame time, work), then the level bands.
  drawComparison(ctx, data, at, x, top, cw, h, gap, style) {
    const lines = [
      ['largest measured error per frame, px', (f) => f.error_px, 1],
      ['frame time of each engine in this page, ms', (f) => f.time_ms, 1, true],
      ['work in the cost model (perspective-warp pixels), per policy', (f) => f.model_work, 1],
    ];
    const lineH = Math.round((h - top - lines.length * gap) * 0.22);
    lines.forEach(([title, value, quantile, measured], k) => {
      const box = at(x, top + k * (lineH + gap), cw, lineH);
      this.lineChart(ctx, data, { title, value, quantile, measured }, box, style);
    });
    const bandsTop = top + lines.length * (lineH + gap) - 4 * style.scale;
    this.bands(ctx, data, at(x, bandsTop, cw, h - bandsTop - 20 * style.scale), style);
  },

  // The model's one engine: frame time and percent approximated side by side, its levels,
  // then the four budget charts two by two.
  drawEngine(ctx, data, at, x, top, cw, h, gap, style) {
    const half = (cw - x) / 2;
    const rowH = Math.round((h - top - 3 * gap) * 0.16);
    this.lineChart(ctx, data, { title: 'frame time of the engine in this page, ms', value: (f) => f.time_ms, quantile: 1, measured: true },
      at(x, top, half, rowH), style);
    this.lineChart(ctx, data, { title: 'approximated (not re-rendered), %', value: (f) => f.approximated_percent, quantile: 1, top: 100 },
      at(2 * x + half, top, half, rowH), style);
    const bandY = top + rowH + gap;
    this.bands(ctx, data, at(x, bandY, cw, rowH + 14 * style.scale), style);
    const gridY = bandY + rowH + gap + 14 * style.scale;
    const gridH = (h - gridY - gap - 20 * style.scale) / 2;
    kBudgetLevels.forEach((level, k) => {
      const box = at(k % 2 ? 2 * x + half : x, gridY + Math.floor(k / 2) * (gridH + gap), half, gridH);
      this.budgetChart(ctx, data, k, level, box, style);
    });
  },

  // Level k's budget chart: the error it would leave (its colour), the threshold (dashed)
  // and the measured error (dotted), on one scale.
  budgetChart(ctx, data, k, level, box, style) {
    const threshold = data.thresholds[k];
    const values = [threshold];
    for (const f of data.runs[0].frames) {
      if (f.frame < box.a) continue;
      if (f.budgets[k] !== null) values.push(f.budgets[k]);
      if (f.error_px !== null) values.push(f.error_px);
    }
    const high = Math.max(...values) * 1.1 || 1;
    const title = `${level}: error left, px`;
    ctx.font = style.font(13);
    ctx.fillStyle = '#e6e6e6';
    ctx.fillText(title, box.x, box.y - 8 * style.scale);
    this.axes(ctx, box, [0, high], style);
    const fy = (v) => box.y + box.h - (box.h * Math.min(v, high)) / high;
    ctx.setLineDash([6, 4]);
    ctx.strokeStyle = '#e6e6e6';
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(box.x, fy(threshold));
    ctx.lineTo(box.x + box.w, fy(threshold));
    ctx.stroke();
    ctx.setLineDash([2, 4]);
    this.series(ctx, data.runs[0].frames, (f) => f.error_px, box, fy, '#e6e6e6', 2 * style.line);
    ctx.setLineDash([]);
    this.series(ctx, data.runs[0].frames, (f) => f.budgets[k], box, fy, levelColours()[level], 2 * style.line);
    this.drawn.push({ title, top: high, threshold });
    this.charts.push(box);
  },

  // The line of `value(frame)` (null: a gap, never a zero) in `box`.
  series(ctx, frames, value, box, fy, colour, width) {
    ctx.strokeStyle = colour;
    ctx.lineWidth = width;
    ctx.beginPath();
    let open = false;
    for (const f of frames) {
      const v = value(f);
      if (v === null || f.frame < box.a) { open = false; continue; }
      if (open) ctx.lineTo(box.fx(f.frame), fy(v)); else ctx.moveTo(box.fx(f.frame), fy(v));
      open = true;
    }
    ctx.stroke();
  },

  // One line per run of `chart.value(frame)` (null: a gap, never a zero) in the box `at`, its
  // scale's top the `chart.quantile` of the values shown (larger ones drawn at the top);
  // records the chart's title and top in this.drawn, and its rectangle with its values'
  // labels in this.measured when `chart.measured` (times measured in this page).
  lineChart(ctx, data, chart, at, style) {
    const { x, y, w, a } = at;
    const values = [];
    for (const run of data.runs) for (const f of run.frames) if (f.frame >= a && chart.value(f) !== null) values.push(chart.value(f));
    values.sort((p, q) => p - q);
    const kept = values.length ? values[Math.min(values.length - 1, Math.floor(chart.quantile * (values.length - 1)))] : 0;
    const high = chart.top || (kept > 0 ? kept * 1.1 : 1);
    ctx.font = style.font(13);
    ctx.fillStyle = '#e6e6e6';
    ctx.fillText(chart.title, x, y - 8 * style.scale);
    this.axes(ctx, at, [0, high], style);
    const fy = (v) => y + at.h - (at.h * Math.min(v, high)) / high;
    data.runs.forEach((run, i) => {
      const colour = kPolicyColours[i % kPolicyColours.length];
      this.series(ctx, run.frames, chart.value, at, fy, colour, 2 * style.line);
      if (data.runs.length < 2) return;  // one engine: its name is in the note
      ctx.fillStyle = colour;
      ctx.fillText(run.policy, x + w - 140 * style.scale, y + 16 * style.scale * (i + 1));
    });
    this.drawn.push({ title: chart.title, top: high });
    this.charts.push(at);
    if (chart.measured) {
      const left = x - 58 * style.scale;  // the values' labels (axes) start 56 px left of the box,
      // the lowest one's descent ends below it
      this.measured.push({ x: left, y: y - 10 * style.scale, w: x + w + 3 - left, h: at.h + 20 * style.scale });
    }
  },

  // One band per run: its drawn layers per level at each frame, stacked from the cheapest.
  bands(ctx, data, box, style) {
    const { x, y, w, h, fx, a } = box;
    const colours = levelColours();
    const levels = Object.keys(colours);
    const title = 18 * style.scale;  // each band's title above it
    const bandH = Math.max(8, (h - title * data.runs.length) / data.runs.length);
    const barW = Math.max(1, w / kAnalysisFrames - 1);
    data.runs.forEach((run, i) => {
      const by = y + title + i * (bandH + title);
      ctx.fillStyle = '#e6e6e6';
      ctx.font = style.font(12);
      ctx.fillText(`${run.policy}: layers per level`, x, by - 4);
      for (const f of run.frames) {
        if (f.frame < a) continue;
        const drawn = f.levels.reduce((s, n) => s + n, 0);
        if (!drawn) continue;
        let base = by + bandH;
        f.levels.forEach((n, l) => {
          const hh = (bandH * n) / drawn;
          ctx.fillStyle = colours[levels[l]];
          ctx.fillRect(fx(f.frame) - barW / 2, base - hh, barW, hh);
          base -= hh;
        });
      }
    });
    this.charts.push(box);
  },

  // The box of a chart with its values' labels left of it and frame numbers under it.
  axes(ctx, { x, y, w, h, a, b }, [lo, hi], style) {
    ctx.strokeStyle = '#5a6068';
    ctx.lineWidth = 1;
    ctx.strokeRect(x, y, w, h);
    ctx.fillStyle = '#8a9099';
    ctx.font = style.font(11);
    for (let k = 0; k <= 4; ++k) {
      const v = lo + ((hi - lo) * k) / 4;
      const label = v >= 1e6 ? `${(v / 1e6).toPrecision(2)}M` : v >= 1e3 ? `${(v / 1e3).toPrecision(2)}k` : v.toPrecision(2);
      ctx.fillText(label, x - 56 * style.scale, y + h - (h * k) / 4 + 4);
    }
    for (let f = Math.ceil(a / 10) * 10; f <= b; f += 10) {
      const fxv = x + (w * (f - a)) / Math.max(1, b - a);
      ctx.fillText(String(f), fxv - 6, y + h + 14 * style.scale);
    }
  },
};
app.views.analysis = analysisView;
