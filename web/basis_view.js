'use strict';
// The basis gallery: the twelve terms of one basis of the flow's Taylor expansion (planar,
// Taylor or Waxman-Ullman; session/basis/basis_catalog.h), each tile the flow of that term
// alone and its coefficient in the plane's current flow, greyed when negligible. Every
// number comes from Session.basisJson. With the state's basis.explorer on, the view is the
// basis explorer (explorer_view.js).

const kBasisRadiusPx = 100;  // tiles show [-100, 100]^2 centred pixels about the expansion point
const kBasisGrid = 4;        // 9 x 9 arrows a tile

const basisView = {
  title: 'Bases',

  // The explorer's controls (explorer_view.js) live in this view's side panel.
  build() { explorerView.build(); },

  draw(ctx, w, h, style) {
    if (app.state.basis.explorer) {
      explorerView.draw(ctx, w, h, style);
      setHtml($('basis-note'), '');
      return;
    }
    const basis = JSON.parse(app.session.basisJson(app.state.basis.kind, kBasisRadiusPx, kBasisGrid));
    const problem = app.session.sceneProblem();
    const columns = 6;
    const rows = 2;
    const pad = 8;
    const top = 34 * style.scale;
    const tile = Math.min((w - pad * (columns + 1)) / columns, (h - top - pad * (rows + 1)) / rows);
    ctx.fillStyle = '#e6e6e6';
    ctx.font = style.font(16);
    ctx.fillText(`${basis.title}: each term's flow alone, and its coefficient now (frame ${app.state.frame})`, pad, 22 * style.scale);
    let active = 0;
    basis.terms.forEach((term, index) => {
      // Row 1: the 2 translations and 4 first-order terms; row 2: the 6 second-order terms.
      const x = pad + (index % columns) * (tile + pad);
      const y = top + pad + Math.floor(index / columns) * (tile + pad);
      if (!term.negligible) ++active;
      this.drawTile(ctx, term, x, y, tile, style);
    });
    const note = problem
      ? `No flow now: ${problem}`
      : `${active} of 12 terms are active (non-zero within ${kBasisRadiusPx} px of the expansion point).`;
    setHtml($('basis-note'), escapeHtml(note));
  },

  drawTile(ctx, term, x, y, size, style) {
    ctx.fillStyle = term.negligible ? '#15171a' : '#1d2329';
    ctx.fillRect(x, y, size, size);
    ctx.strokeStyle = term.negligible ? '#2a2e34' : '#5aa9e6';
    ctx.lineWidth = style.line;
    ctx.strokeRect(x, y, size, size);
    const g = term.grid;
    let largest = 0;
    for (let i = 0; i < g.length; i += 4) largest = Math.max(largest, Math.hypot(g[i + 2], g[i + 3]));
    const cell = size * 0.6 / (2 * kBasisGrid);
    const k = size * 0.6 / (2 * kBasisRadiusPx);
    const s = largest > 0 ? 0.9 * cell / (k * largest) : 0;
    const cx = x + size / 2;
    const cy = y + size / 2 + 2 * style.scale;
    ctx.strokeStyle = term.negligible ? '#4a4f57' : '#e6c35a';
    ctx.beginPath();
    for (let i = 0; i < g.length; i += 4) {
      addArrow(ctx, cx + k * g[i], cy + k * g[i + 1], cx + k * (g[i] + s * g[i + 2]),
        cy + k * (g[i + 1] + s * g[i + 3]), 3 * style.line);
    }
    ctx.stroke();
    ctx.fillStyle = term.negligible ? '#6a7079' : '#e6e6e6';
    ctx.font = style.font(13);
    ctx.fillText(term.symbol, x + 6, y + 16 * style.scale);
    ctx.font = style.font(10);
    ctx.fillText(term.description, x + 6, y + 29 * style.scale, size - 12);
    ctx.font = style.font(12);
    ctx.fillText(`${formatNumber(term.coefficient)} ${term.unit}`, x + 6, y + size - 8);
  },
};
app.views.basis = basisView;
