'use strict';
// The world view, "World (the cause)": the eye, its frustum and image plane, the plane with
// its normal N and up U, V and Omega as arrows, the rays through the plane's corners and the
// path of its centre (for a scene source: the scene's polygons in their levels' colours and
// the viewer's path, the eye moving along it), in 3D with vtk.js (the bundle web/world/world_vtk.js, global
// OflabWorld). Every point and matrix comes from the teaching layer (Session.worldLoopJson,
// .worldFrameJson: session/display/world_geometry.h, the numbers the desktop's world view
// draws); this file only hands them to vtk.js and writes the labels and the caption.
//
// The loop's actors are made once per loop (a new state); a frame moves their points and
// matrices. Mouse: vtk.js's trackball camera (drag to orbit, Shift+drag to pan, wheel or
// right drag to zoom). With the state's cause_and_effect the world takes the left half of the
// stage and the flow view the right half, as the desktop's cause-and-effect layout.

const worldView = {
  title: 'World',
  world: null,      // OflabWorld's world, made on the first draw
  loopText: '',     // the loop JSON the actors were made for
  loop: null,
  problem: '',      // why the world cannot be drawn here ('' when it can)

  build() {
    $('world-reset').addEventListener('click', () => {
      this.placed = null;  // placed again even when the state already says "orbit"
      editState((s) => { s.world_camera = 'orbit'; });
    });
    $('world-eye').addEventListener('click', () => editState((s) => { s.world_camera = 'eye'; }));
    const stage = $('stage');
    this.box = document.createElement('div');
    this.box.id = 'world';
    this.labels = document.createElement('canvas');
    this.labels.id = 'world-labels';
    this.box.appendChild(this.labels);
    stage.appendChild(this.box);
  },

  // The world, made when first shown (WebGL only then).
  ensureWorld() {
    if (this.world || this.problem) return;
    if (!OflabWorld.webglAvailable()) {
      this.problem = 'The world view needs WebGL, which this browser does not give the page.';
      return;
    }
    this.world = OflabWorld.create(this.box);
    // A drag or a wheel turn moves the camera: the labels follow it.
    this.world.onCameraMoved(() => this.drawLabels());
  },

  // The 2D canvas: the flow view's half in the cause-and-effect layout, else only the note.
  draw(ctx, w, h, style) {
    const split = app.state.cause_and_effect;
    document.body.classList.toggle('cause-and-effect', split);
    if (split) {
      ctx.save();
      ctx.translate(Math.floor(w / 2), 0);
      flowView.draw(ctx, w - Math.floor(w / 2), h, style);
      ctx.restore();
    }
    this.ensureWorld();
    if (this.problem) {
      drawCentredText(ctx, split ? w / 2 : w, h, this.problem, style);
      return;
    }
    const loopText = app.session.worldLoopJson();
    const theme = this.theme(style);
    if (loopText !== this.loopText || theme.line !== this.line) {
      this.loop = JSON.parse(loopText);
      this.world.setLoop(this.loop, theme, app.session.worldTexture());
      this.loopText = loopText;
      this.line = theme.line;
      this.placed = null;
    }
    // The state's world camera: "orbit" frames the loop, "eye" looks through the eye.
    if (this.placed !== app.state.world_camera) {
      this.world.place(app.state.world_camera === 'eye');
      this.placed = app.state.world_camera;
    }
    this.frame = JSON.parse(app.session.worldFrameJson());
    this.world.setFrame(this.frame);
    // The image plane shows the frame, as the desktop's: the exact one for the plane, the
    // engine's for a scene.
    const picture = app.session.worldFrame();
    if (picture) this.world.setFrameImage(picture);
    this.world.render();
    this.drawLabels();
  },

  theme(style) {
    return { background: [17, 19, 21], text: [230, 230, 230], outline: [150, 156, 165], image: [150, 156, 165],
      muted: [110, 116, 125], line: style.line };
  },

  // The caption under the picture, then the labels next to the projection of the point they
  // name, on the canvas over vtk.js's. The labels are placed by the desktop's rule (Module.
  // placeLabels: session/display/label_layout.h): off each other and the caption, and off the
  // image plane and the textured plane where a place next to the point is free of them.
  drawLabels() {
    if (!this.world || !this.frame) return;
    const canvas = this.labels;
    const box = this.box.getBoundingClientRect();
    if (canvas.width !== Math.floor(box.width) || canvas.height !== Math.floor(box.height)) {
      canvas.width = Math.floor(box.width);
      canvas.height = Math.floor(box.height);
    }
    const ctx = canvas.getContext('2d');
    const style = drawStyle();
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    const band = this.drawCaption(ctx, canvas, style);
    ctx.font = style.font(14);
    ctx.textBaseline = 'middle';
    const colours = this.loop.colours;
    const colour = { velocity: colours.velocity, omega: colours.omega, normal: colours.normal, up: colours.up };
    // Through the eye, as the desktop: no eye and no Omega (both at the eye), and the image
    // plane's border is the camera's image.
    const fromEye = app.state.world_camera === 'eye';
    const shown = [];
    for (const label of this.frame.labels) {
      if (!label.text || (fromEye && (label.key === 'eye' || label.key === 'omega'))) continue;
      if (fromEye && label.key === 'image_plane') label.text = "the camera's image";
      const at = this.world.toPage(label.at);
      if (at) shown.push({ label, at, width: ctx.measureText(label.text).width + 6 });
    }
    const height = 18 * style.scale;
    const margin = 3;
    const answer = JSON.parse(Module.placeLabels(JSON.stringify({
      sizes: shown.map((s) => [s.width, height]), anchors: shown.map((s) => s.at),
      area: [margin, margin, canvas.width - 2 * margin, Math.max(height, band - 2 * margin)],
      taken: [], gap: 6, avoid: fromEye ? [] : this.pictureOutlines(),
    })));
    this.labelBoxes = [];
    if (answer.error) return;
    shown.forEach((s, k) => {
      const [x, y, w, h] = answer[k];
      const [r, g, b] = colour[s.label.key] || [230, 230, 230];
      ctx.fillStyle = 'rgba(17, 19, 21, 0.6)';
      ctx.fillRect(x, y, w, h);
      ctx.fillStyle = `rgb(${r},${g},${b})`;
      ctx.fillText(s.label.text, x + 3, y + h / 2);
      this.labelBoxes.push({ key: s.label.key, text: s.label.text, box: [x, y, w, h], at: s.at });
    });
  },

  // The caption in a dark band at the picture's foot; returns the band's top (page pixels).
  drawCaption(ctx, canvas, style) {
    ctx.font = style.font(13);
    ctx.textBaseline = 'alphabetic';
    const lines = [];
    for (const part of this.loop.caption.split('\n')) lines.push(...wrapLines(ctx, part, canvas.width - 24));
    const step = 17 * style.scale;
    const top = canvas.height - 16 - lines.length * step;
    // A dark band under the caption keeps it readable over the picture.
    ctx.fillStyle = 'rgba(17, 19, 21, 0.75)';
    ctx.fillRect(0, top, canvas.width, lines.length * step + 16);
    lines.forEach((line, i) => {
      ctx.fillStyle = '#e6e6e6';
      ctx.fillText(line, 12, canvas.height - 10 - (lines.length - 1 - i) * step);
    });
    return top;
  },

  // The pictures the labels keep off, as drawn (page pixels): the image plane (placed by the
  // frame's viewer matrix in a scene) and, for the plane, its textured quad.
  pictureOutlines() {
    const m = this.frame.viewer_matrix;
    const toWorld = (p) => (m ? [0, 1, 2].map((r) => m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3]) : p);
    const outlines = [this.loop.image_corners.map(toWorld)];
    if (this.frame.plane_corners) outlines.push(this.frame.plane_corners);
    return outlines.map((corners) => corners.map((c) => this.world.toPage(c))).filter((o) => o.every((p) => p));
  },

  // Paints the world as shown (vtk.js's picture and the labels) into the 2D canvas's context,
  // for the PNG download: rendered again first, as WebGL keeps its picture only until the
  // page is composited.
  paintInto(ctx) {
    if (!this.world) return;
    this.world.render();
    const gl = [...this.box.querySelectorAll('canvas')].find((c) => c !== this.labels);
    const box = this.box.getBoundingClientRect();
    ctx.drawImage(gl, 0, 0, box.width, box.height);
    ctx.drawImage(this.labels, 0, 0, box.width, box.height);
  },
};
app.views.world = worldView;
