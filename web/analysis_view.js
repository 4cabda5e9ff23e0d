'use strict';
// The analysis charts (the desktop's comparison charts, gui/views/analysis_charts.h): over
// the last kAnalysisFrames frames of the current pass of the lab's compared runs (or the
// source's own run when its kind has no reuse policy), one line per policy for the largest
// measured error per frame and for the work in the cost model, and one band per policy with
// its drawn layers per level, stacked in the levels' colours. The x axis moves only when the frame shown leaves it; a click on a
// chart goes to the frame under the pointer. The histories come from core
// (Session.analysisJson: session/player/policy_comparison.h's records).

const kAnalysisFrames = 80;
// The policies' line colours, in the compared order (Okabe and Ito's colour-blind-safe set,
// the palette of session/display/palette.h).
const kPolicyColours = ['rgb(86,180,233)', 'rgb(230,159,0)', 'rgb(0,158,115)', 'rgb(204,121,167)', 'rgb(213,94,0)'];

const analysisView = {
  title: 'Analysis',
  range: [0, kAnalysisFrames - 1],  // the frames the x axis shows
  charts: null,                      // {x, w} of the charts, for clicks

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
      if (shownView() !== 'analysis' || !this.charts) return;
      const rect = $('canvas').getBoundingClientRect();
      const { x, w } = this.charts;
      const t = (e.clientX - rect.left - x) / w;
      if (t < 0 || t > 1) return;
      seek(Math.round(this.range[0] + t * (this.range[1] - this.range[0])));
    });
  },

  draw(ctx, w, h, style) {
    const data = JSON.parse(app.session.analysisJson(kAnalysisFrames));
    if (data.problem) {
      drawCentredText(ctx, w, h, data.problem, style);
      return;
    }
    const [a, b] = this.xRange(data.last);
    const left = 60 * style.scale;
    const x = left;
    const cw = w - left - 20;
    this.charts = { x, w: cw };
    const fx = (frame) => x + (cw * (frame - a)) / Math.max(1, b - a);
    // Two line charts, then the level bands below them. (The desktop's frame-time chart is not
    // drawn: the page's wall times are the browser's, and vary from one run to the next.)
    const gap = 44 * style.scale;
    const top = 26 * style.scale;
    const lines = [
      ['largest measured error per frame, px', (f) => f.error_px, 1],
      ['work in the cost model (perspective-warp pixels), per policy', (f) => f.model_work, 1],
    ];
    const lineH = Math.round((h - top - lines.length * gap) * 0.3);
    this.drawn = [];
    lines.forEach(([title, value, quantile], k) => {
      const y = top + k * (lineH + gap);
      this.lineChart(ctx, data, { title, value, quantile }, { x, y, w: cw, h: lineH, a, b, fx }, style);
    });
    const bandsTop = top + lines.length * (lineH + gap) - 4 * style.scale;
    this.bands(ctx, data, x, bandsTop, cw, h - bandsTop - 20 * style.scale, fx, a, style);
    // The frame shown.
    ctx.strokeStyle = '#e6e6e6';
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(fx(data.last), top);
    ctx.lineTo(fx(data.last), h - 20 * style.scale);
    ctx.stroke();
    setHtml($('analysis-note'), `frames ${a} .. ${b}; click a chart to go to a frame (now ${data.last})`);
  },

  // One line per run of `chart.value(frame)` (null: a gap, never a zero) in the box `at`, its
  // scale's top the `chart.quantile` of the values shown (larger ones drawn at the top);
  // records the chart's title and top in this.drawn.
  lineChart(ctx, data, chart, at, style) {
    const { x, y, w, h, a, b, fx } = at;
    const values = [];
    for (const run of data.runs) for (const f of run.frames) if (f.frame >= a && chart.value(f) !== null) values.push(chart.value(f));
    values.sort((p, q) => p - q);
    const kept = values.length ? values[Math.min(values.length - 1, Math.floor(chart.quantile * (values.length - 1)))] : 0;
    const high = kept > 0 ? kept * 1.1 : 1;
    ctx.font = style.font(13);
    ctx.fillStyle = '#e6e6e6';
    ctx.fillText(chart.title, x, y - 8 * style.scale);
    this.axes(ctx, x, y, w, h, a, b, [0, high], style);
    const fy = (v) => y + h - (h * Math.min(v, high)) / high;
    data.runs.forEach((run, i) => {
      ctx.strokeStyle = kPolicyColours[i % kPolicyColours.length];
      ctx.lineWidth = 2 * style.line;
      ctx.beginPath();
      let open = false;
      for (const f of run.frames) {
        const v = chart.value(f);
        if (v === null || f.frame < a) { open = false; continue; }
        if (open) ctx.lineTo(fx(f.frame), fy(v)); else ctx.moveTo(fx(f.frame), fy(v));
        open = true;
      }
      ctx.stroke();
      ctx.fillStyle = ctx.strokeStyle;
      ctx.fillText(run.policy, x + w - 140 * style.scale, y + 16 * style.scale * (i + 1));
    });
    this.drawn.push({ title: chart.title, top: high });
  },

  // One band per run: its drawn layers per level at each frame, stacked from the cheapest.
  bands(ctx, data, x, y, w, h, fx, a, style) {
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
  },

  axes(ctx, x, y, w, h, a, b, [lo, hi], style) {
    ctx.strokeStyle = '#5a6068';
    ctx.lineWidth = 1;
    ctx.strokeRect(x, y, w, h);
    ctx.fillStyle = '#8a9099';
    ctx.font = style.font(11);
    for (let k = 0; k <= 4; ++k) {
      const v = lo + ((hi - lo) * k) / 4;
      const label = v >= 1e6 ? `${(v / 1e6).toPrecision(2)}M` : v >= 1e3 ? `${(v / 1e3).toPrecision(2)}k` : v.toPrecision(2);
      ctx.fillText(label, 4, y + h - (h * k) / 4 + 4);
    }
    for (let f = Math.ceil(a / 10) * 10; f <= b; f += 10) {
      const fxv = x + (w * (f - a)) / Math.max(1, b - a);
      ctx.fillText(String(f), fxv - 6, y + h + 14 * style.scale);
    }
  },
};
app.views.analysis = analysisView;
