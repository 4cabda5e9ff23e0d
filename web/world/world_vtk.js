// The world view's 3D drawing with vtk.js (manual/web.md), bundled by esbuild into one
// minified script that defines the global `OflabWorld` (tools/build-web.sh installs the
// pinned packages of web/package.json; web/CMakeLists.txt bundles this file). Only the
// modules imported here are bundled: WebGL (no WebGPU), polygons, the arrow and sphere
// sources, the trackball interactor.
//
// It draws what the teaching layer computed (session/display/world_geometry.h through
// Session.worldLoopJson and .worldFrameJson): nothing here is geometry of the theory, only
// how vtk.js shows it. Every actor is made once by setLoop; setFrame changes points and
// matrices in place. Matrices arrive row-major (as vtkMatrix4x4::DeepCopy reads them);
// vtk.js's user matrix is column-major, so they are transposed here.
import '@kitware/vtk.js/Rendering/OpenGL/Profiles/Geometry';
import vtkOpenGLRenderWindow from '@kitware/vtk.js/Rendering/OpenGL/RenderWindow';
import vtkRenderWindow from '@kitware/vtk.js/Rendering/Core/RenderWindow';
import vtkRenderer from '@kitware/vtk.js/Rendering/Core/Renderer';
import vtkRenderWindowInteractor from '@kitware/vtk.js/Rendering/Core/RenderWindowInteractor';
import vtkInteractorStyleTrackballCamera from '@kitware/vtk.js/Interaction/Style/InteractorStyleTrackballCamera';
import vtkActor from '@kitware/vtk.js/Rendering/Core/Actor';
import vtkMapper from '@kitware/vtk.js/Rendering/Core/Mapper';
import vtkPolyData from '@kitware/vtk.js/Common/DataModel/PolyData';
import vtkArrowSource from '@kitware/vtk.js/Filters/Sources/ArrowSource';
import vtkSphereSource from '@kitware/vtk.js/Filters/Sources/SphereSource';
import vtkTexture from '@kitware/vtk.js/Rendering/Core/Texture';
import vtkImageData from '@kitware/vtk.js/Common/DataModel/ImageData';
import vtkDataArray from '@kitware/vtk.js/Common/Core/DataArray';

const rgb = (c) => c.map((v) => v / 255);

// A polydata actor in colour `c` (0..1), lines `width` pixels wide, added to `renderer`.
function polyActor(renderer, c, width = 1) {
  const data = vtkPolyData.newInstance();
  const mapper = vtkMapper.newInstance();
  mapper.setInputData(data);
  const actor = vtkActor.newInstance();
  actor.setMapper(mapper);
  actor.getProperty().setColor(...c);
  actor.getProperty().setLineWidth(width);
  actor.getProperty().setLighting(false);
  renderer.addActor(actor);
  return { actor, data };
}

// Points (x, y, z triples) and cells of `kind` ('lines' or 'polys') of polydata `data`:
// each cell a list of point indices.
function setCells(data, points, kind, cells) {
  data.getPoints().setData(Float32Array.from(points.flat()), 3);
  const cellArray = [];
  for (const cell of cells) cellArray.push(cell.length, ...cell);
  for (const other of ['lines', 'polys']) {
    data.getReferenceByName(other).setData(Uint32Array.from(other === kind ? cellArray : []));
  }
  data.modified();
}

const range = (n) => Array.from({ length: n }, (_, i) => i);
// Segments from[k] -> to[k].
function setSegments(data, from, to) {
  setCells(data, from.concat(to), 'lines', from.map((_, k) => [k, from.length + k]));
}
function setPolyline(data, points, closed) {
  const cell = range(points.length);
  if (closed && points.length > 2) cell.push(0);
  setCells(data, points, 'lines', points.length > 1 ? [cell] : []);
}

// The unit arrow from (0, 0, 0) to (1, 0, 0), as VTK's vtkArrowSource (vtk.js's is centred).
function unitArrow() {
  const source = vtkArrowSource.newInstance({ tipResolution: 16, shaftResolution: 16 });
  const data = source.getOutputData();
  const p = data.getPoints().getData();
  const shift = -data.getPoints().getBounds()[0];
  for (let i = 0; i < p.length; i += 3) p[i] += shift;
  data.getPoints().modified();
  return data;
}

// A texture of opaque RGBA rows, top row first (vtk.js's first row is v = 0).
function makeTexture({ width, height, pixels }) {
  const image = vtkImageData.newInstance();
  image.setDimensions(width, height, 1);
  image.getPointData().setScalars(vtkDataArray.newInstance({ numberOfComponents: 4, values: Uint8Array.from(pixels) }));
  const texture = vtkTexture.newInstance();
  texture.setInputData(image);
  texture.setInterpolate(true);
  return texture;
}

function transposed(m) {
  return Float64Array.from(range(16), (i) => m[4 * (i % 4) + Math.floor(i / 4)]);
}

// Row-major 4x4 `m` applied to point p (w = 1) or, with w = 0, to direction p.
function applied(m, p, w = 1) {
  return [0, 1, 2].map((r) => m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3] * w);
}

// Per-cell colours (opaque [r, g, b] bytes per cell) of polydata `data`, drawn as they are.
function setCellColours(data, colours) {
  const values = Uint8Array.from(colours.flatMap(([r, g, b]) => [r, g, b, 255]));
  data.getCellData().setScalars(vtkDataArray.newInstance({ name: 'colours', numberOfComponents: 4, values }));
  data.modified();
}

class World {
  constructor(container) {
    this.container = container;
    this.window = vtkRenderWindow.newInstance();
    this.renderer = vtkRenderer.newInstance();
    this.window.addRenderer(this.renderer);
    this.gl = vtkOpenGLRenderWindow.newInstance();
    this.window.addView(this.gl);
    this.gl.setContainer(container);
    this.interactor = vtkRenderWindowInteractor.newInstance();
    this.interactor.setView(this.gl);
    this.interactor.initialize();
    this.interactor.setInteractorStyle(vtkInteractorStyleTrackballCamera.newInstance());
    this.interactor.bindEvents(container);
    this.renders = 0;
  }

  // Makes every actor for `loop` (Session.worldLoopJson): the eye, the frustum and the image
  // plane, the plane with `texture` ({width, height, pixels}: opaque RGBA rows, top row
  // first, Session.worldTexture) and its outline, the rays, the arrows, the path. Called again
  // only when the source changes.
  setLoop(loop, theme, texture) {
    const r = this.renderer;
    r.removeAllViewProps();
    const c = loop.colours;
    r.setBackground(...rgb(theme.background));
    this.loop = loop;
    const sphere = vtkSphereSource.newInstance({ thetaResolution: 16, phiResolution: 8, radius: 0.5 });
    this.eye = polyActor(r, rgb(theme.text));
    this.eye.actor.getMapper().setInputConnection(sphere.getOutputPort());
    this.eye.actor.getProperty().setLighting(true);
    this.eye.actor.setScale(0.05 * loop.depth, 0.05 * loop.depth, 0.05 * loop.depth);
    this.frustum = polyActor(r, rgb(theme.outline), theme.line);
    // The image plane shows the frame (setFrameImage), white so the texture is not tinted.
    this.imagePlane = polyActor(r, [1, 1, 1]);
    this.frameImage = vtkImageData.newInstance();
    this.frameImage.setDimensions(1, 1, 1);
    this.frameImage.getPointData().setScalars(vtkDataArray.newInstance({ numberOfComponents: 4, values: Uint8Array.from(rgb(theme.image).map((v) => Math.round(255 * v)).concat([255])) }));
    const frameTexture = vtkTexture.newInstance();
    frameTexture.setInputData(this.frameImage);
    frameTexture.setInterpolate(true);
    this.imagePlane.actor.addTexture(frameTexture);
    this.plane = polyActor(r, [1, 1, 1]);
    this.plane.actor.addTexture(makeTexture(texture));
    // The image's top-left pixel at corner 0, as the desktop's (world_actors.h).
    this.plane.data.getPointData().setTCoords(vtkDataArray.newInstance({
      name: 'uv', numberOfComponents: 2, values: Float32Array.from([0, 0, 1, 0, 1, 1, 0, 1]) }));
    this.planeOutline = polyActor(r, rgb(theme.outline), theme.line);
    this.rays = polyActor(r, rgb(c.rays), theme.line);
    this.rayImages = polyActor(r, rgb(c.rays), 2.5 * theme.line);
    this.omegaAxis = polyActor(r, rgb(c.omega), theme.line);
    this.pathPast = polyActor(r, rgb(c.path_past), 2.5 * theme.line);
    this.pathFuture = polyActor(r, rgb(theme.muted), 1.5 * theme.line);
    const arrow = unitArrow();
    this.arrows = {};
    for (const name of ['velocity', 'omega', 'normal', 'up']) {
      const a = polyActor(r, rgb(c[name]));
      a.actor.getMapper().setInputData(arrow);
      a.actor.getProperty().setLighting(true);
      this.arrows[name] = a;
    }
    const corners = loop.image_corners;
    setCells(this.imagePlane.data, corners, 'polys', [[0, 1, 2, 3]]);
    // The frame's top-left pixel at corner 0, as the desktop's (world_scene.cpp).
    this.imagePlane.data.getPointData().setTCoords(vtkDataArray.newInstance({
      name: 'uv', numberOfComponents: 2, values: Float32Array.from([0, 0, 1, 0, 1, 1, 0, 1]) }));
    const from = [[0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0]].concat(corners);
    setSegments(this.frustum.data, from, corners.concat([1, 2, 3, 0].map((k) => corners[k])));
    this.scene = loop.kind === 'scene';
    if (this.scene) this.addScene(loop, theme);
    this.framed = false;
  }

  // A scene's polygons (their colours set per frame) with their edges; the plane's actors
  // stay empty and hidden.
  addScene(loop, theme) {
    this.polygons = polyActor(this.renderer, [1, 1, 1]);
    const mapper = this.polygons.actor.getMapper();
    mapper.setScalarModeToUseCellData();
    mapper.setColorModeToDirectScalars();
    mapper.setScalarVisibility(true);
    const points = [];
    const cells = [];
    for (const outline of loop.outlines) {
      cells.push(range(outline.length).map((i) => points.length + i));
      points.push(...outline);
    }
    setCells(this.polygons.data, points, 'polys', cells);
    setCellColours(this.polygons.data, loop.outlines.map(() => [150, 150, 150]));
    this.polygonEdges = polyActor(this.renderer, rgb(theme.outline), theme.line);
    setCells(this.polygonEdges.data, points, 'lines', cells.map((c) => c.concat([c[0]])));
    for (const p of [this.plane, this.planeOutline, this.rays, this.rayImages]) p.actor.setVisibility(false);
  }

  // Moves the actors to `frame` (Session.worldFrameJson): points and matrices only.
  setFrame(frame) {
    if (this.scene) {
      this.setSceneFrame(frame);
    } else {
      this.setPlaneFrame(frame);
    }
    setPolyline(this.omegaAxis.data, frame.omega_axis, false);
    const path = this.loop.path;
    const k = Math.min(Math.max(frame.path_index, 0), path.length - 1);
    setPolyline(this.pathPast.data, path.slice(0, k + 1), false);
    setPolyline(this.pathFuture.data, path.slice(k), false);
    for (const [name, a] of Object.entries(this.arrows)) {
      a.actor.setUserMatrix(transposed(frame.arrows[name].matrix));
    }
    this.frame = frame;
    if (this.fromEye && this.scene) this.viewFromEye(0.12);
  }

  // A scene's frame: the eye, its frustum and image plane moved to the viewer's pose, the
  // polygons in this frame's colours.
  setSceneFrame(frame) {
    const m = transposed(frame.viewer_matrix);
    for (const p of [this.eye, this.frustum, this.imagePlane]) p.actor.setUserMatrix(m);
    setCellColours(this.polygons.data, frame.polygon_colours);
  }

  // The frame the image plane shows ({width, height, pixels}: opaque RGBA rows, top row first,
  // Session.worldFrame); its storage reused while the size stays.
  setFrameImage({ width, height, pixels }) {
    const [w, h] = this.frameImage.getDimensions();
    const scalars = this.frameImage.getPointData().getScalars();
    if (w !== width || h !== height) {
      this.frameImage.setDimensions(width, height, 1);
      this.frameImage.getPointData().setScalars(vtkDataArray.newInstance({ numberOfComponents: 4, values: Uint8Array.from(pixels) }));
    } else {
      scalars.getData().set(pixels);
      scalars.modified();
    }
    this.frameImage.modified();
  }

  setPlaneFrame(frame) {
    const corners = frame.plane_corners;
    setCells(this.plane.data, corners, 'polys', [[0, 1, 2, 3]]);
    setPolyline(this.planeOutline.data, corners, true);
    setSegments(this.rays.data, corners.map(() => [0, 0, 0]), corners);
    setPolyline(this.rayImages.data, frame.ray_images, true);
  }

  // Shows or hides the parts ({frustum, image_plane, plane, velocity, omega, rays, path}:
  // false hides); `fromEye` hides what is at the eye (the eye, the image plane, the rays and
  // Omega) as the desktop does when it looks through the eye.
  setShown(shown, fromEye) {
    const on = (part) => shown[part] !== false && !(fromEye && ['image_plane', 'rays', 'omega'].includes(part));
    this.eye.actor.setVisibility(on('frustum') && !fromEye);
    this.frustum.actor.setVisibility(on('frustum'));
    this.imagePlane.actor.setVisibility(on('image_plane'));
    const plane = on('plane') && !this.scene;
    for (const p of [this.plane, this.planeOutline, this.arrows.normal, this.arrows.up]) p.actor.setVisibility(plane);
    if (this.scene) for (const p of [this.polygons, this.polygonEdges]) p.actor.setVisibility(on('scene'));
    this.arrows.velocity.actor.setVisibility(on('velocity'));
    this.arrows.omega.actor.setVisibility(on('omega'));
    this.omegaAxis.actor.setVisibility(on('omega'));
    this.rays.actor.setVisibility(on('rays') && !this.scene);
    this.rayImages.actor.setVisibility(on('rays') && !this.scene);
    this.pathPast.actor.setVisibility(on('path'));
    this.pathFuture.actor.setVisibility(on('path'));
  }

  // The camera framing the loop from behind the eye, to its left and above it (Y is down), so
  // the frustum opens towards the plane across the picture (the desktop's orbit vantage,
  // gui/views/world_camera.cpp), fitted to the bounds of the eye, the image plane and the
  // plane over the loop by vtk.js's resetCamera.
  resetCamera() {
    if (this.scene) {
      this.resetSceneCamera();
      return;
    }
    const cam = this.renderer.getActiveCamera();
    const centre = this.loop.world_centre;
    const focus = centre.map((v) => v / 2);
    const side = [-0.8, -0.8, -0.55];
    const distance = Math.max(1e-3, Math.hypot(...centre));
    cam.setFocalPoint(...focus);
    cam.setPosition(...focus.map((v, i) => v + side[i] * distance));
    cam.setViewUp(0, -1, 0);
    cam.setViewAngle(30);
    this.renderer.resetCamera(this.loop.bounds);
    cam.zoom(1.35);
    this.framed = true;
  }

  // A scene, as the desktop frames it (gui/views/world_camera.cpp): from the left of the
  // walk's first eye, a little behind and above it, looking at the middle of the eye and the
  // scene's centre; closer in a wide view.
  resetSceneCamera() {
    const m = this.loop.first_view;
    const eye = applied(m, [0, 0, 0]);
    const [forward, right, up] = [[0, 0, 1], [1, 0, 0], [0, -1, 0]].map((d) => applied(m, d, 0));
    const centre = this.loop.world_centre;
    const focus = eye.map((v, i) => 0.5 * (v + centre[i]));
    const distance = Math.max(1e-3, Math.hypot(...centre.map((v, i) => v - eye[i])));
    const side = [0, 1, 2].map((i) => -0.55 * forward[i] - 1.0 * right[i] + 0.45 * up[i]);
    const cam = this.renderer.getActiveCamera();
    cam.setFocalPoint(...focus);
    cam.setPosition(...focus.map((v, i) => v + distance * side[i]));
    cam.setViewUp(...up);
    cam.setViewAngle(30);
    this.renderer.resetCamera(this.loop.bounds);
    const box = this.container.getBoundingClientRect();
    const aspect = box.width / Math.max(1, box.height);
    cam.zoom(1.6 * Math.min(Math.max(aspect / 1.6, 0.6), 1.0));
    this.framed = true;
  }

  // The camera at the eye looking along +Z with the image's up (-Y), its vertical field of
  // view wide enough that the whole image and `margin` of it on each side fit the container's
  // shape (the desktop's "View from the camera"); the eye, the image plane, the rays and Omega
  // (all at the eye) are hidden by setShown while it looks from there.
  viewFromEye(margin) {
    const c = this.loop.camera;
    const box = this.container.getBoundingClientRect();
    const aspect = box.width / Math.max(1, box.height);
    const k = (1 + 2 * margin) / c.focal_px;
    const halfV = Math.max(c.cy, c.height - c.cy) * k;
    const halfH = Math.max(c.cx, c.width - c.cx) * k;
    const cam = this.renderer.getActiveCamera();
    // In a scene the eye is the viewer's at the frame shown (the frame's viewer matrix).
    const m = this.scene && this.frame ? this.frame.viewer_matrix : null;
    const at = (p) => (m ? applied(m, p) : p);
    cam.setPosition(...at([0, 0, 0]));
    cam.setFocalPoint(...at([0, 0, 1]));
    cam.setViewUp(...(m ? applied(m, [0, -1, 0], 0) : [0, -1, 0]));
    cam.setViewAngle(2 * Math.atan(Math.max(halfV, halfH / aspect)) * 180 / Math.PI);
    this.framed = true;
  }

  // Places the camera: through the eye (viewFromEye with the desktop's margin, 0.12) or
  // framing the loop (resetCamera), and shows the parts that placement shows.
  place(fromEye) {
    this.fromEye = fromEye;
    if (fromEye) this.viewFromEye(0.12); else this.resetCamera();
    this.setShown({}, fromEye);
  }

  // Calls `callback` whenever the camera moves (a drag, a wheel turn, a framing).
  onCameraMoved(callback) {
    this.renderer.getActiveCamera().onModified(callback);
  }

  // Renders at the container's size in CSS pixels times the device pixel ratio.
  render() {
    const box = this.container.getBoundingClientRect();
    const ratio = window.devicePixelRatio || 1;
    const size = [Math.max(1, Math.floor(box.width * ratio)), Math.max(1, Math.floor(box.height * ratio))];
    const now = this.gl.getSize();
    if (now[0] !== size[0] || now[1] !== size[1]) this.gl.setSize(...size);
    if (!this.framed) this.resetCamera();
    this.renderer.resetCameraClippingRange();
    this.window.render();
    ++this.renders;
  }

  // Where world point p lands on the container, CSS pixels from its top-left, or null when it
  // is behind the camera.
  toPage(p) {
    const box = this.container.getBoundingClientRect();
    const aspect = box.width / Math.max(1, box.height);
    const n = this.renderer.worldToNormalizedDisplay(p[0], p[1], p[2], aspect);
    if (!(n[2] >= 0 && n[2] <= 1)) return null;
    return [n[0] * box.width, (1 - n[1]) * box.height];
  }
}

window.OflabWorld = {
  create(container) { return new World(container); },
  // Whether this browser has WebGL at all (a canvas's 'webgl2' or 'webgl' context).
  webglAvailable() {
    const canvas = document.createElement('canvas');
    return !!(canvas.getContext('webgl2') || canvas.getContext('webgl'));
  },
};
