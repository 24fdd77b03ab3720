/**
 * The 3D scene view: the scene of a tracer view seen from outside, on its own
 * p5 WEBGL canvas (a second p5 instance, in instance mode, that draws only
 * when asked: it works whatever canvas the sketch itself has). It shows the
 * shapes, the lights, the eye, the image plane with the traced picture filling
 * in, the view frustum, and the selected pixel's rays (primary ray, normal,
 * shadow rays coloured as in the 2D diagrams, bounces). Drag to turn, wheel to
 * zoom, click a pixel of the image plane to select it (and the other way round).
 *
 *   const view = p.createTracerView({ scene, camera });
 *   p.createSceneView({ view });
 *
 * It draws on the next animation frame when something changed (it hears the
 * tracer view's 'select', 'restart' and 'progress'); while the picture is being
 * traced it redraws only now and then, so the trace keeps its pace.
 *
 * SceneView keeps the state and the frames; its parts, each given what it needs:
 * scene-view-mesh.js (shapes, lights, eye as triangles), -draw.js (image plane,
 * frustum, rays), -rays.js (a pixel's rays, the fans), -flight.js (Shoot), -labels.js
 * (words at scene points), -input.js (pointer, orbit maths), -keys.js, -controls.js, -words.js.
 */
import p5 from 'p5';
import { ballOf } from '../../shapes/index.js';
import { inspectPixel } from '../../lesson/inspect.js';
import { recordOf } from '../pixel/record.js';
import { Vec3 } from '../../math/vec3.js';
import { show, checkOptions } from '../../text/check.js';
import { pixelCenter, sceneBounds, orbitCamera, projectToScreen } from '../../lesson/rays3d.js';
import { useStyle, resolveParent } from '../dom.js';
import { nearestAhead } from './mesh.js';
import { RAY_COLORS, StillGeometry, PlaneTexture, wireSphere, line3, drawSegment, drawImagePlane, drawFrustum, drawLightOutlines } from './draw.js';
import { Flight, legSeconds, checkSpeed } from './flight.js';
import { pixelStory, shotStory, fanRays } from './rays.js';
import { constructionOf, placeLabels, drawLabels } from './labels.js';
import { listenForInput, pixelUnder, checkOrbit, clampPitch, zoomDistance } from './input.js';
import { createControls, createFigure, dressCanvas, SPEEDS } from './controls.js';

export { RAY_COLORS };
/** Vertical field of view of the 3D view's own camera, radians. */
export const FOVY = Math.PI / 3;
/** Where the view looks from at first and after Reset: a little to the right, a little above. */
export const HOME = { yaw: -35, pitch: 20 };
/** While tracing, redraw the picture at most once per this many times the last draw took. */
const TRACE_SHARE = 6;

const OPTIONS = ['view', 'width', 'height', 'parent', 'label', 'planeDistance', 'frustum', 'orbit', 'controls', 'raysPerSecond', 'construction'];

/**
 * Creates a 3D view of a tracer view's scene (call it from setup()).
 * @param {import('p5').default} p the sketch
 * @param {object} options
 * @param {import('../tracer/view.js').TracerView} options.view the tracer view it shows and selects in
 * @param {number} [options.width=480] canvas width, px
 * @param {number} [options.height=360] canvas height, px
 * @param {HTMLElement|string|{elt: HTMLElement}} [options.parent] where to put it; default next to the tracer view
 * @param {string} [options.label] a caption above it
 * @param {number|'auto'} [options.planeDistance='auto'] how far from the eye to show the image plane (the camera's own is at 1; rays through a pixel pass through the same pixel at any distance)
 * @param {boolean} [options.frustum=true] draw the view frustum
 * @param {{yaw?: number, pitch?: number, distance?: number}} [options.orbit] where to look from at first (degrees; distance in scene units)
 * @param {boolean} [options.controls=true] show the Reset button, the Shoot button and its speed slider
 * @param {import('../../shapes/sphere.js').Sphere} [options.construction] a sphere: draw the geometric route (L, tca, d, thc, with their values) of the selected ray for it
 * @param {number} [options.raysPerSecond=4] how fast Shoot sends rays (one of 1, 2, 4, 8, 15, 30, 60, 120)
 * @returns {SceneView}
 * @example
 * const view = p.createTracerView({ scene: classScene(), camera: new Camera({ width: 32, height: 24 }) });
 * p.createSceneView({ view, width: 480, height: 360 }); // drag to orbit; the selected pixel's ray in 3D
 */
export function createSceneView(p, options) {
  return new SceneView(p, options);
}

/**
 * The 3D view of a tracer view's scene, what `p.createSceneView({ view })` returns: eye, image plane, rays and spheres.
 * @example
 * const view3d = p.createSceneView({ view });
 * view3d.setOrbit({ yaw: 30, pitch: 20 }); // look from the side and above
 * view3d.reset();                          // back to where it started
 */
export class SceneView {
  #g = null; #view; #raf = 0; #destroyed = false; #unlisten = []; #ready;
  #orbit; #home; #bounds; #planeDistance; #planeOption; #frustum;
  #texture = null; #lastDrawMs = 0; #lastDrawAt = -Infinity;
  /** Following the trace: the progress last drawn (-1: none since the last restart). */
  #following = false; #seen = -1;
  #selected = null; #segments = [];
  #extra = []; #target; #still = new StillGeometry();
  /** The construction sphere, and the selected ray's route for it `{ rays, labels }` (scene-view-labels.js). */
  #constructionSphere = null; #construction = { rays: [], labels: [] };
  /** @type {HTMLButtonElement|null} the Stop button (none without controls) */
  stopButton = null;
  /** Shoot: its flight, whether it runs, the order and slow speed to go back to; the row / column fan ('h' / 'v'). */
  #flight = new Flight(); #shooting = false; #before = { order: 'coarse', slowRaysPerSecond: 0 }; #fan = null; #fanSegments = []; #labels = [];

  constructor(p, options = {}) {
    const { view, width = 480, height = 360, parent, label = 'The scene in 3D', planeDistance = 'auto', frustum = true, orbit = {}, controls = true, raysPerSecond = 4, construction = null } = checkOptions(options, OPTIONS, 'scene view');
    if (construction !== null && !(construction && ballOf(construction))) throw new TypeError(`construction must be a Sphere of the scene, got ${show(construction)}`);
    this.#constructionSphere = construction;
    if (!SPEEDS.includes(raysPerSecond)) throw new RangeError(`raysPerSecond must be one of ${SPEEDS.join(', ')}, got ${show(raysPerSecond)}`);
    this.raysPerSecond = raysPerSecond;
    if (!view || typeof view.on !== 'function' || !view.camera) throw new TypeError(`createSceneView needs { view }: a tracer view, got ${show(view)}`);
    for (const [name, v] of [['width', width], ['height', height]]) {
      if (!Number.isInteger(v) || v < 16 || v > 4096) throw new RangeError(`${name} must be a whole number of pixels from 16 to 4096, got ${show(v)}`);
    }
    if (planeDistance !== 'auto' && !(typeof planeDistance === 'number' && planeDistance > 0 && Number.isFinite(planeDistance))) {
      throw new RangeError(`planeDistance must be 'auto' or a distance greater than 0, got ${show(planeDistance)}`);
    }
    this.#view = view;
    this.#planeOption = planeDistance;
    this.#frustum = Boolean(frustum);
    this.width = width;
    this.height = height;

    useStyle();
    this.#buildDom(parent, label, controls);
    this.#sceneChanged();
    this.#orbit = { ...this.#home, ...checkOrbit(orbit) };
    this.#unlisten = [
      view.onSelect((s) => this.#selectionChanged(s)),
      view.on('restart', () => this.#restarted()),
      view.on('progress', (p) => this.#traced(p)),
    ];
    this.#selectionChanged(view.selected);
    this.#following = true;
    this.#traced({ progress: view.done ? 1 : view.progress, done: view.done, current: view.current });
  }

  /* ---------------- public API ---------------- */

  /** The tracer view it shows. */
  get view() { return this.#view; }
  /** The `<canvas data-view3d>` (null until its p5 instance has set up). */
  get canvas() { return this.#g?.canvas ?? null; }
  /** The p5 instance (WEBGL) that draws it. */
  get graphics() { return this.#g; }
  /** Resolves once the canvas is on the page (p5 sets a sketch up asynchronously). */
  get ready() { return this.#ready; }
  /** Where the view looks from: `{ yaw, pitch, distance }` (degrees, scene units). */
  get orbit() { return { yaw: this.#orbit.yaw, pitch: this.#orbit.pitch, distance: this.#orbit.distance }; }
  /** The selected pixel's segments (see lib/lesson/rays3d.js raySegments), [] when none. */
  get segments() { return this.#segments; }
  /** How long the last draw took, ms (for the benchmark). */
  get lastDrawMs() { return this.#lastDrawMs; }
  /** How far from the eye the image plane is shown. */
  get planeDistance() { return this.#planeDistance; }

  /**
   * Where the centre of pixel (x, y) of the image plane is on the 3D canvas,
   * `{ x, y }` in CSS px from its top-left, or null when behind the view.
   */
  screenPointOfPixel(x, y) {
    return projectToScreen(this.#eye(), pixelCenter(this.#view.camera, x, y, this.#planeDistance), this.width, this.height, FOVY);
  }

  /** Looks from `{ yaw, pitch, distance }` (any of them); redraws. */
  setOrbit(orbit) {
    Object.assign(this.#orbit, checkOrbit(orbit));
    this.#orbit.pitch = clampPitch(this.#orbit.pitch);
    return this.redraw();
  }

  /** Turns the view by `yaw` and `pitch` degrees (the arrow keys do this); redraws. */
  turn(yaw, pitch) {
    return this.setOrbit({ yaw: this.#orbit.yaw + yaw, pitch: this.#orbit.pitch + pitch });
  }

  /** Multiplies the view's distance by `factor` (< 1: nearer; + and − do this), within what the wheel allows. */
  zoom(factor) {
    return this.setOrbit({ distance: zoomDistance(this.#orbit.distance, factor, this.#bounds.radius) });
  }

  /** Back to the first point of view. */
  reset() {
    this.#orbit = { ...this.#home };
    return this.redraw();
  }

  /**
   * Extra rays to draw besides the selected pixel's, e.g. a row of primary
   * rays or sample photon paths: `[{ from, to, color, weight? }]`.
   */
  setExtraRays(rays) {
    if (!Array.isArray(rays)) throw new TypeError(`setExtraRays takes an array of { from, to, color }, got ${show(rays)}`);
    this.#extra = rays;
    return this.redraw();
  }

  /**
   * Text labels at scene points, drawn on a layer above the 3D picture:
   * `[{ at, text, color? }]` (e.g. L, tca, d, thc of the geometric route).
   */
  setLabels(labels) {
    if (!Array.isArray(labels)) throw new TypeError(`setLabels takes an array of { at, text }, got ${show(labels)}`);
    this.#labels = labels;
    return this.redraw();
  }

  /**
   * Shoot: traces the picture again in slow motion, scanline order, at
   * `raysPerSecond`, and shows each ray leave the eye through its pixel, fly
   * to its hit and send its shadow rays (and its bounces).
   */
  shoot(raysPerSecond = this.raysPerSecond) {
    this.raysPerSecond = checkSpeed(raysPerSecond);
    this.#flight = new Flight();
    if (!this.#shooting) this.#before = { order: this.#view.order, slowRaysPerSecond: this.#view.slowRaysPerSecond };
    this.#shooting = true;
    if (this.stopButton) this.stopButton.disabled = false;
    this.#view.slowRaysPerSecond = raysPerSecond;
    this.#view.setOrder('slow'); // the view's restart and progress events bring the rays
    return this;
  }

  /** Stops a Shoot: no more rays fly, and the picture finishes at full speed in the order it had before. */
  stop() {
    if (!this.#shooting) return this;
    this.#shootEnded();
    this.#flight.flying = [];
    this.#view.setOrder(this.#before.order === 'slow' ? 'coarse' : this.#before.order);
    return this.redraw();
  }

  /** Changes how fast Shoot sends rays, even while it runs. */
  setSpeed(raysPerSecond) {
    this.raysPerSecond = checkSpeed(raysPerSecond);
    if (this.#shooting) this.#view.slowRaysPerSecond = raysPerSecond;
    return this;
  }

  /**
   * Shows every primary ray of the selected pixel's row ('row', key h) or
   * column ('column', key v), or none (null). The same kind again hides it.
   */
  showFan(kind) {
    if (kind !== null && kind !== 'row' && kind !== 'column') throw new RangeError(`showFan takes 'row', 'column' or null, got ${show(kind)}`);
    this.#fan = kind;
    this.#fanSegments = fanRays(this.#view, this.#selected, kind, this.#bounds.radius);
    if (this.canvas) this.canvas.dataset.fan = kind ?? '';
    return this.redraw();
  }

  /** Rays sent by the last Shoot so far (one per traced pixel). */
  get shots() { return this.#flight.shots; }
  /** True while Shoot is under way. */
  get shooting() { return this.#shooting; }

  /** 'row', 'column' or null: the fan of rays shown. */
  get fan() { return this.#fan; }

  /** The scene or camera changed in place (the tracer view's restart() does this too): measure it again. */
  refresh() {
    this.#seen = -1;
    this.#sceneChanged();
    this.#selectionChanged(this.#view.selected, true); // changed in place: the view's record may be of the scene as it was
    return this;
  }

  /** Draws on the next animation frame (once, however often it is asked). */
  redraw() {
    if (!this.#raf && !this.#destroyed) this.#raf = requestAnimationFrame(this.#frame);
    const c = this.canvas;
    if (c) c.dataset.state = 'drawing';
    if (c && this.#orbit) { // p5 1.x sets the canvas up inside the constructor, before the orbit is known
      // where it looks from, for tests and tools: the arrow keys change these
      c.dataset.yaw = String(Math.round(this.#orbit.yaw * 100) / 100);
      c.dataset.pitch = String(Math.round(this.#orbit.pitch * 100) / 100);
      c.dataset.distance = String(Math.round(this.#orbit.distance * 100) / 100);
    }
    return this;
  }

  /** Removes the view from the page. */
  destroy() {
    if (this.#destroyed) return;
    this.#destroyed = true;
    cancelAnimationFrame(this.#raf);
    for (const unlisten of this.#unlisten) unlisten();
    this.figure.remove();
    this.#texture?.remove();
    this.#g?.remove();
  }

  /* ---------------- what changed ---------------- */

  #sceneChanged() {
    const { scene, camera } = this.#view;
    // far enough out to be seen, near enough to stay in front of everything the eye sees
    this.#planeDistance = this.#planeOption === 'auto' ? Math.max(1, nearestAhead(scene, camera) * 0.7) : this.#planeOption;
    this.#bounds = sceneBounds(scene, camera, this.#planeDistance);
    // look at a point between the middle of the scene and the eye: the eye, the image plane and the rays are the lesson
    const c = this.#bounds.center, e = camera.position;
    this.#target = new Vec3(c.x + (e.x - c.x) * 0.45, c.y + (e.y - c.y) * 0.45, c.z + (e.z - c.z) * 0.45);
    this.#home = { ...HOME, distance: this.#bounds.radius * 0.95 };
    if (!this.#orbit) return;
    this.#texture?.stale();
    this.#redrawUnlessRestarting();
  }

  /**
   * A restart (the picture just cleared) is followed by the view's progress,
   * which redraws at a pace the trace can afford; anything else redraws at once.
   */
  #redrawUnlessRestarting() {
    const v = this.#view;
    if (!v.done && v.progress === 0 && this.#following) return;
    this.redraw();
  }

  /** The tracer view traces again: the scene, camera or order may be new. */
  #restarted() {
    this.#seen = -1;
    this.#sceneChanged();
  }

  #selectionChanged(s, fresh = false) {
    this.#selected = s ? { x: s.x, y: s.y } : null;
    if (this.canvas) this.canvas.dataset.selected = s ? `${s.x},${s.y}` : '';
    const view = this.#view, r = this.#bounds.radius;
    this.#fanSegments = fanRays(view, this.#selected, this.#fan, r);
    const record = !s ? null : fresh ? inspectPixel(view.scene, view.camera, s.x, s.y) : recordOf(view, s);
    this.#construction = constructionOf(record, this.#constructionSphere);
    this.#segments = record ? pixelStory(view.scene, record, r) : [];
    this.#texture?.stale();
    this.#redrawUnlessRestarting();
  }

  /**
   * A frame of the trace (the tracer view's progress): while shooting, the
   * pixels traced since the last look start flying; the picture is redrawn
   * when it changed, at most once per TRACE_SHARE times the last draw took.
   */
  #traced({ progress, done, current }) {
    const v = this.#view;
    const storyOf = (x, y) => shotStory(v.scene, v.camera, x, y, this.#bounds.radius);
    if (this.#shooting && v.order === 'slow' && this.#flight.traced(current, v.width, storyOf)) {
      this.#texture?.stale();
      this.redraw();
    }
    if (this.#shooting && (done || v.order !== 'slow')) this.#shootEnded();
    if (progress === this.#seen) return;
    // keep the trace's pace: while it runs, redraw only when enough time has passed since the last draw
    if (done || performance.now() - this.#lastDrawAt > this.#lastDrawMs * TRACE_SHARE + 250) {
      this.#seen = progress;
      this.#texture?.stale();
      this.redraw();
    }
  }

  /** Shoot is over: its button goes, and the view's own slow motion keeps its speed. */
  #shootEnded() {
    this.#shooting = false;
    if (this.stopButton) this.stopButton.disabled = true;
    this.#view.slowRaysPerSecond = this.#before.slowRaysPerSecond;
  }

  /* ---------------- drawing ---------------- */

  #frame = () => {
    this.#raf = 0;
    if (this.#destroyed || !this.#g) return;
    this.#g.redraw();
    this.#lastDrawAt = performance.now();
    // "done" once it shows the finished picture and nothing more is waiting: tests and screenshots wait for it
    this.canvas.dataset.state = this.#view.done && !this.#raf ? 'done' : 'drawing';
  };

  /** The orbit camera as vectors (lib/lesson/rays3d.js orbitCamera). */
  #eye() {
    return orbitCamera({ target: this.#target, yaw: this.#orbit.yaw, pitch: this.#orbit.pitch, distance: this.#orbit.distance });
  }

  #draw() {
    const g = this.#g, { scene, camera } = this.#view, r = this.#bounds.radius;
    const o = this.#eye();
    g.push();
    g.background(246, 247, 249);
    // p5's WEBGL y axis points down: the scene is drawn with y negated (see scene-view-draw.js)
    g.perspective(FOVY, this.width / this.height, this.#orbit.distance * 0.02, this.#orbit.distance * 20);
    g.camera(o.eye.x, -o.eye.y, o.eye.z, o.target.x, -o.target.y, o.target.z, 0, 1, 0);
    g.noLights();
    g.noStroke();
    this.#still.drawSolid(g, { scene, camera, bounds: this.#bounds, constructionSphere: this.#constructionSphere });
    this.#texture.update(this.#view.canvas, this.#view.width, this.#view.height, this.#selected);
    drawImagePlane(g, camera, this.#planeDistance, this.#texture.graphics);
    if (this.#frustum) drawFrustum(g, camera, this.#planeDistance, this.#bounds);
    drawLightOutlines(g, scene);
    for (const s of this.#segments) drawSegment(g, s, r);
    for (const e of this.#extra) line3(g, e.from, e.to, e.color, e.weight ?? 1.5);
    this.canvas.dataset.extraRays = String(this.#extra.length); // for tests: how many extra segments it shows
    for (const f of this.#fanSegments) line3(g, f.from, f.to, RAY_COLORS.primary, 1);
    if (this.#constructionSphere) wireSphere(g, this.#constructionSphere);
    for (const c of this.#construction.rays) line3(g, c.from, c.to, c.color, c.weight);
    const flight = this.#flight.frame(performance.now(), legSeconds(this.raysPerSecond) * 1000);
    for (const s of flight.segments) drawSegment(g, s, r);
    this.#still.drawGlass(g);
    g.pop();
    const labels = this.#construction.labels.length ? [...this.#labels, ...this.#construction.labels] : this.#labels;
    drawLabels(this.labelLayer.getContext('2d'), placeLabels(labels, o, this.width, this.height, FOVY));
    if (flight.moving) this.redraw(); // the next frame of the flight
  }

  /* ---------------- DOM ---------------- */

  #buildDom(parent, label, controls) {
    const { figure, stage, labelLayer, bar } = createFigure({ width: this.width, height: this.height, label });
    this.figure = figure; this.labelLayer = labelLayer; this.bar = bar;
    if (controls) {
      const made = createControls({
        raysPerSecond: this.raysPerSecond, shoot: () => this.shoot(), stop: () => this.stop(),
        setSpeed: (v) => this.setSpeed(v), reset: () => this.reset(), orbitView: this,
      });
      this.stopButton = made.stopButton;
      bar.append(...made.controls);
    }
    const host = resolveParent(parent, null);
    if (host) host.append(figure); else this.#view.figure.after(figure);
    this.#ready = new Promise((resolve) => {
      new p5((q) => {
        q.setup = () => {
          q.createCanvas(this.width, this.height, q.WEBGL);
          q.pixelDensity(1);
          q.noLoop(); // drawn only when something changed (redraw())
          q.linePerspective(false); // rays as thick near as far
          this.#g = q;
          this.#texture = new PlaneTexture(q);
          this.#canvasReady(/** @type {any} */ (q).canvas, stage); // p5's types leave out the instance's canvas
          resolve(this);
        };
        q.draw = () => { const t = performance.now(); this.#draw(); this.#lastDrawMs = performance.now() - t; };
      }, stage);
    });
  }

  #canvasReady(c, stage) {
    dressCanvas(c, stage, this.#selected);
    listenForInput(c, {
      figure: this.figure, tracerCanvas: this.#view.canvas, view: this,
      radius: () => this.#bounds.radius, pick: (x, y) => this.#pick(x, y),
    });
    this.redraw();
  }

  /** A click on the image plane selects the pixel under it. */
  #pick(clientX, clientY) {
    const hit = pixelUnder(this.canvas.getBoundingClientRect(), clientX, clientY, {
      eye: this.#eye(), camera: this.#view.camera, planeDistance: this.#planeDistance, width: this.width, height: this.height, fovy: FOVY,
    });
    if (hit) this.#view.select(hit.x, hit.y);
  }
}
