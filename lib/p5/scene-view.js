/**
 * The 3D scene view: the scene of a tracer view seen from outside, on its own
 * p5 WEBGL canvas (a second p5 instance, in instance mode, that draws only
 * when asked: it works whatever canvas the sketch itself has). It shows the shapes in their colours, the lights,
 * the eye, the image plane at its place with the pixel grid and the traced
 * picture filling in, the view frustum, and the selected pixel's rays:
 * primary ray, normal, shadow rays (lit / blocked, coloured as in the 2D
 * diagrams), mirror and glass bounces. Drag to turn, wheel to zoom, click a
 * pixel of the image plane to select it (the tracer view follows, and the
 * other way round).
 *
 *   const view = p.createTracerView({ scene, camera });
 *   p.createSceneView({ view });
 *
 * It draws only when something changed (selection, orbit, new traced pixels),
 * on the next animation frame; while the picture is being traced it redraws
 * the picture only now and then, so the trace keeps its pace.
 */
import p5 from 'p5';
import { clamp } from '../numbers.js';
import { intersectGeometric } from '../shapes/sphere.js';
import { ballOf } from '../shapes/index.js';
import { inspectPixel } from '../explain.js';
import { Vec3, sub, dot, normalize, cross } from '../vec3.js';
import { show, checkOptions } from '../check.js';
import {
  imagePlane, pixelCenter, pickImagePlane, geometricConstruction, raySegments, sceneBounds, orbitCamera, screenRay, projectToScreen, HUGE_RADIUS,
} from '../rays3d.js';
import { listenForOrbitKeys, createOrbitButtons } from './scene-view-keys.js';
import { useStyle, element, resolveParent } from './dom.js';
import { INK, MUTED, RAY, NORMAL, LIT, SHADOW, CONSTRUCT, FONT } from './diagrams/style.js';

/** Vertical field of view of the 3D view's own camera, radians. */
export const FOVY = Math.PI / 3;
/** Where the view looks from at first and after Reset: a little to the right, a little above. */
export const HOME = { yaw: -35, pitch: 20 };
/** Colours of the kinds of ray (shadow rays as in the 2D diagrams). */
export const RAY_COLORS = { primary: RAY, normal: NORMAL, lit: LIT, shadow: SHADOW, away: MUTED, reflection: CONSTRUCT, refraction: '#0f8b8d', photon: '#e07b00' };
/** Texels per traced pixel on the image plane's texture, at most. */
const MAX_TEXTURE = 512;
/** While tracing, redraw the picture at most once per this many times the last draw took. */
const TRACE_SHARE = 6;
/** Mouse travel (px) under which a press and release is a click, not a turn. */
const CLICK_SLOP = 4;

const OPTIONS = ['view', 'width', 'height', 'parent', 'label', 'planeDistance', 'frustum', 'orbit', 'controls', 'raysPerSecond', 'construction'];
/** Speeds the shoot slider offers, rays per second. */
const SPEEDS = [1, 2, 4, 8, 15, 30, 60, 120];

/**
 * Creates a 3D view of a tracer view's scene (call it from setup()).
 * @param {import('p5').default} p the sketch
 * @param {object} options
 * @param {import('./tracer-view.js').TracerView} options.view the tracer view it shows and selects in
 * @param {number} [options.width=480] canvas width, px
 * @param {number} [options.height=360] canvas height, px
 * @param {HTMLElement|string|{elt: HTMLElement}} [options.parent] where to put it; default next to the tracer view
 * @param {string} [options.label] a caption above it
 * @param {number|'auto'} [options.planeDistance='auto'] how far from the eye to show the image plane (the camera's own is at 1; rays through a pixel pass through the same pixel at any distance)
 * @param {boolean} [options.frustum=true] draw the view frustum
 * @param {{yaw?: number, pitch?: number, distance?: number}} [options.orbit] where to look from at first (degrees; distance in scene units)
 * @param {boolean} [options.controls=true] show the Reset button, the Shoot button and its speed slider
 * @param {import('../shapes/sphere.js').Sphere} [options.construction] a sphere: draw the geometric route (L, tca, d, thc, with their values) of the selected ray for it
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
  #g = null; #view; #raf = 0; #destroyed = false; #unlisten;
  #orbit; #home; #bounds; #planeDistance; #planeOption; #frustum;
  #picture; #pictureCtx; #pictureKey = ''; #lastDrawMs = 0; #lastDrawAt = -Infinity;
  #selected = null; #segments = []; #record = null;
  #extra = []; #drag = null; #target; #geometry = null; #glass = null; #geometryKey = '';
  /** Shoot: rays in flight `{ segments, t0 }`, the pixel traced last, the row / column fan ('h' / 'v'). */
  #constructionSphere = null; #construction = []; #constructionLabels = [];
  /** @type {HTMLButtonElement|null} the Stop button (none without controls) */
  stopButton = null;
  #flying = []; #shots = 0; #shooting = false; #lastShot = null; #fan = null; #fanSegments = []; #watching = 0; #labels = [];

  constructor(p, options = {}) {
    const { view, width = 480, height = 360, parent, label = 'The scene in 3D', planeDistance = 'auto', frustum = true, orbit = {}, controls = true, raysPerSecond = 4, construction = null } = checkOptions(options, OPTIONS, 'scene view');
    if (construction !== null && !(construction && ballOf(construction))) throw new TypeError(`construction must be a Sphere of the scene, got ${show(construction)}`);
    this.#constructionSphere = construction;
    if (!SPEEDS.includes(raysPerSecond)) throw new RangeError(`raysPerSecond must be one of ${SPEEDS.join(', ')}, got ${show(raysPerSecond)}`);
    this.raysPerSecond = raysPerSecond;
    if (!view || typeof view.onSelect !== 'function' || !view.camera) throw new TypeError(`createSceneView needs { view }: a tracer view, got ${show(view)}`);
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
    this.#unlisten = view.onSelect((s) => this.#selectionChanged(s));
    this.#selectionChanged(view.selected);
    this.#watchTrace();
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
  /** The selected pixel's segments (see lib/rays3d.js raySegments), [] when none. */
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
    this.#orbit.pitch = clamp(this.#orbit.pitch, -89, 89);
    return this.redraw();
  }

  /** Turns the view by `yaw` and `pitch` degrees (the arrow keys do this); redraws. */
  turn(yaw, pitch) {
    return this.setOrbit({ yaw: this.#orbit.yaw + yaw, pitch: this.#orbit.pitch + pitch });
  }

  /** Multiplies the view's distance by `factor` (< 1: nearer; + and − do this), within what the wheel allows. */
  zoom(factor) {
    const r = this.#bounds.radius;
    return this.setOrbit({ distance: clamp(this.#orbit.distance * factor, r * 0.3, r * 8) });
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
    if (!(typeof raysPerSecond === 'number' && raysPerSecond > 0 && Number.isFinite(raysPerSecond))) throw new RangeError(`raysPerSecond must be a number greater than 0, got ${show(raysPerSecond)}`);
    this.raysPerSecond = raysPerSecond;
    this.#flying = [];
    this.#lastShot = null;
    this.#shots = 0;
    if (!this.#shooting) this.#modeBeforeShoot = this.#view.renderMode;
    this.#shooting = true;
    if (this.stopButton) this.stopButton.disabled = false;
    this.#view.renderer.slowRaysPerSecond = raysPerSecond;
    this.#view.setRenderMode('slow');
    this.#watchTrace();
    return this;
  }

  /** Stops a Shoot: no more rays fly, and the picture finishes at full speed in the order it had before. */
  stop() {
    if (!this.#shooting) return this;
    this.#shooting = false;
    this.#flying = [];
    if (this.stopButton) this.stopButton.disabled = true;
    this.#view.setRenderMode(this.#modeBeforeShoot === 'slow' ? 'coarse' : this.#modeBeforeShoot);
    return this.redraw();
  }

  #modeBeforeShoot = 'coarse';

  /** Changes how fast Shoot sends rays, even while it runs. */
  setSpeed(raysPerSecond) {
    if (!(typeof raysPerSecond === 'number' && raysPerSecond > 0 && Number.isFinite(raysPerSecond))) throw new RangeError(`raysPerSecond must be a number greater than 0, got ${show(raysPerSecond)}`);
    this.raysPerSecond = raysPerSecond;
    if (this.#shooting) this.#view.renderer.slowRaysPerSecond = raysPerSecond;
    return this;
  }

  /**
   * Shows every primary ray of the selected pixel's row ('row', key h) or
   * column ('column', key v), or none (null). The same kind again hides it.
   */
  showFan(kind) {
    if (kind !== null && kind !== 'row' && kind !== 'column') throw new RangeError(`showFan takes 'row', 'column' or null, got ${show(kind)}`);
    this.#fan = kind;
    this.#fanSegments = this.#fanFor(kind);
    if (this.canvas) this.canvas.dataset.fan = kind ?? '';
    return this.redraw();
  }

  /** Rays sent by the last Shoot so far (one per traced pixel). */
  get shots() { return this.#shots; }
  /** True while Shoot is under way. */
  get shooting() { return this.#shooting; }

  /** 'row', 'column' or null: the fan of rays shown. */
  get fan() { return this.#fan; }

  /** The scene or camera changed in place (the tracer view's restart() does this too): measure it again. */
  refresh() {
    this.#sceneChanged();
    this.#selectionChanged(this.#view.selected);
    this.#watchTrace();
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
    cancelAnimationFrame(this.#watching);
    this.#unlisten();
    this.#observer?.disconnect();
    this.figure.remove();
    this.#picture?.remove(); // p5's remove() leaves a p5.Graphics' hidden canvas on the page
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
    this.#pictureKey = '';
    this.#redrawUnlessRestarting();
  }

  /**
   * A restart (the picture just cleared) is followed by the trace watch, which
   * redraws at a pace the trace can afford; anything else redraws at once.
   */
  #redrawUnlessRestarting() {
    const v = this.#view;
    if (!v.done && v.progress === 0 && this.#observer) return this.#watchTrace();
    this.redraw();
  }

  #selectionChanged(s) {
    this.#selected = s ? { x: s.x, y: s.y } : null;
    if (this.canvas) this.canvas.dataset.selected = s ? `${s.x},${s.y}` : '';
    const view = this.#view;
    this.#record = s ? inspectPixel(view.scene, view.camera, s.x, s.y) : null;
    this.#fanSegments = this.#fanFor(this.#fan);
    this.#buildConstruction();
    this.#segments = this.#record ? raySegments(view.scene, this.#record, { missLength: this.#bounds.radius * 2.5, normalLength: this.#bounds.radius * 0.08 }) : [];
    this.#pictureKey = '';
    this.#redrawUnlessRestarting();
  }

  #observer = null;

  /**
   * Follows the tracer view's picture as it fills in: polls on animation
   * frames only while it is tracing (the view marks its figure with
   * data-state), and wakes up when it starts again.
   */
  #watchTrace() {
    if (!this.#observer) {
      this.#observer = new MutationObserver(() => {
        if (this.#view.figure.dataset.state === 'rendering') this.#sceneChanged(); // traced again: the scene may be new
        this.#watchTrace();
      });
      this.#observer.observe(this.#view.figure, { attributes: true, attributeFilter: ['data-state'] });
    }
    if (this.#watching || this.#destroyed) return;
    let seen = -1;
    const poll = () => {
      this.#watching = 0;
      const v = this.#view, progress = v.done ? 1 : v.progress;
      if (progress < seen) this.#sceneChanged(); // a restart
      const c = v.renderer.current;
      if (this.#shooting && v.renderMode === 'slow' && c && (c.x !== this.#lastShot?.x || c.y !== this.#lastShot?.y)) {
        // every pixel traced since the last look, in scanline order; only the last few fly (the rest would overlap)
        const W = v.width, from = this.#lastShot ? this.#lastShot.y * W + this.#lastShot.x + 1 : 0, to = c.y * W + c.x;
        for (let i = Math.max(from, to - 7); i <= to; i++) this.#shot(i % W, Math.floor(i / W));
        this.#shots += to - from + 1;
        this.#lastShot = { ...c };
        this.#pictureKey = '';
        this.redraw();
      }
      if (this.#shooting && (v.done || v.renderMode !== 'slow')) {
        this.#shooting = false;
        if (this.stopButton) this.stopButton.disabled = true;
      }
      if (progress !== seen) {
        const now = performance.now();
        // keep the trace's pace: while it runs, redraw only when enough time has passed since the last draw
        if (v.done || now - this.#lastDrawAt > this.#lastDrawMs * TRACE_SHARE + 250) {
          seen = progress;
          this.#pictureKey = '';
          this.redraw();
        }
      }
      if (!v.done || seen !== 1) this.#watching = requestAnimationFrame(poll);
    };
    poll();
  }

  /** The geometric route for the selected ray and the construction sphere: L, tca, d, thc as lines with their values. */
  #buildConstruction() {
    const sphere = this.#constructionSphere, record = this.#record;
    this.#construction = [];
    this.#constructionLabels = [];
    if (!sphere || !record) return;
    const g = intersectGeometric(record.ray, sphere);
    const parts = geometricConstruction(record.ray, sphere, g);
    // labels part-way along, so that L and tca (both from the eye) do not sit on each other
    const along = ([a, b], k) => new Vec3(a.x + (b.x - a.x) * k, a.y + (b.y - a.y) * k, a.z + (b.z - a.z) * k);
    const add = (seg, color, text, k, dy) => {
      if (!seg) return;
      this.#construction.push({ from: seg[0], to: seg[1], color, weight: 3 });
      this.#constructionLabels.push({ at: along(seg, k), text, color, dy });
    };
    add(parts.L, CONSTRUCT, 'L', 0.7, -14);
    add(parts.tca, CONSTRUCT, `tca = ${g.tca.toFixed(2)}`, 0.4, 14);
    add(parts.d, INK, `d = ${Math.sqrt(Math.max(0, g.d2)).toFixed(2)}`, 0.5, 0);
    add(parts.thc, NORMAL, `thc = ${g.thc?.toFixed(2)}`, 0.5, 16);
  }

  /** The primary rays of the selected pixel's row or column, each to its hit (or out to the background). */
  #fanFor(kind) {
    const s = this.#selected, view = this.#view;
    if (!kind || !s) return [];
    const out = [];
    const n = kind === 'row' ? view.width : view.height;
    for (let i = 0; i < n; i++) {
      const x = kind === 'row' ? i : s.x, y = kind === 'row' ? s.y : i;
      if (x === s.x && y === s.y) continue; // the selected pixel's own ray is drawn in full
      const record = inspectPixel(view.scene, view.camera, x, y);
      out.push(raySegments(view.scene, record, { missLength: this.#bounds.radius * 2.5 })[0]);
    }
    return out;
  }

  /** Shoot: a new pixel was traced: its ray starts flying. */
  #shot(x, y) {
    const view = this.#view;
    const record = inspectPixel(view.scene, view.camera, x, y);
    const segments = raySegments(view.scene, record, { missLength: this.#bounds.radius * 2.5, normalLength: this.#bounds.radius * 0.06 });
    this.#flying.push({ segments, t0: performance.now() });
    if (this.#flying.length > 60) this.#flying.shift();
  }

  /** Seconds a ray takes for one leg of its flight (eye → hit, hit → light, …). */
  #legSeconds() {
    return clamp(1.6 / this.raysPerSecond, 0.06, 0.8);
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

  /** The orbit camera as vectors (lib/rays3d.js orbitCamera). */
  #eye() {
    return orbitCamera({ target: this.#target, yaw: this.#orbit.yaw, pitch: this.#orbit.pitch, distance: this.#orbit.distance });
  }

  #draw() {
    const g = this.#g, view = this.#view, camera = view.camera;
    const o = this.#eye();
    g.push();
    g.background(246, 247, 249);
    // p5's WEBGL y axis points down: the scene is drawn with y negated (see P below)
    g.perspective(FOVY, this.width / this.height, this.#orbit.distance * 0.02, this.#orbit.distance * 20);
    g.camera(o.eye.x, -o.eye.y, o.eye.z, o.target.x, -o.target.y, o.target.z, 0, 1, 0);
    g.noLights();
    g.noStroke();
    g.model(this.#staticGeometry(g));
    this.#drawImagePlane(g, camera);
    if (this.#frustum) this.#drawFrustum(g, camera);
    for (const s of this.#segments) this.#drawSegment(g, s);
    for (const r of this.#extra) line3(g, r.from, r.to, r.color, r.weight ?? 1.5);
    for (const f of this.#fanSegments) line3(g, f.from, f.to, RAY_COLORS.primary, 1);
    if (this.#constructionSphere) wireSphere(g, this.#constructionSphere);
    for (const c of this.#construction) line3(g, c.from, c.to, c.color, c.weight);
    const flying = this.#drawFlying(g);
    this.#drawGlass(g);
    g.pop();
    this.#drawLabels(o);
    if (flying) this.redraw(); // the next frame of the flight
  }

  /**
   * The rays in flight: each segment grows from its start in turn (the
   * primary ray, then at its hit the normal and shadow rays and the bounce,
   * and so on); a ray fades once it has arrived. True while any still moves.
   */
  #drawFlying(g) {
    const now = performance.now(), leg = this.#legSeconds() * 1000;
    let moving = false;
    this.#flying = this.#flying.filter((f, i) => {
      const phase = (now - f.t0) / leg;
      const last = i === this.#flying.length - 1;
      const end = Math.max(...f.segments.map((s) => startOf(s) + 1));
      if (phase > end + 2 && !last) return false; // arrived a while ago: gone
      if (phase < end) moving = true;
      for (const s of f.segments) {
        const k = clamp(phase - startOf(s), 0, 1);
        if (k <= 0) continue;
        const to = new Vec3(s.from.x + (s.to.x - s.from.x) * k, s.from.y + (s.to.y - s.from.y) * k, s.from.z + (s.to.z - s.from.z) * k);
        this.#drawSegment(g, { ...s, to, blockedAt: k === 1 ? s.blockedAt : null, hit: s.hit && k === 1 });
      }
      return true;
    });
    if (this.#flying.length > 1) moving = true; // old ones still to clear away
    return moving;
  }

  /** The meshes a shape draws itself with (its drawIn3D): a ball (a huge one as a patch of ground), a ground patch, a box. */
  #meshKit() {
    return {
      ball: (into, center, radius, rgb, lit) => (radius > HUGE_RADIUS
        ? this.#groundPatch(into, center, sub(new Vec3(), this.#bounds.center, center), radius, rgb)
        : sphereMesh(into, center, radius, rgb, lit)),
      ground: (into, point, normal, radius, rgb) => this.#groundPatch(into, point, normal, radius, rgb),
      box: boxMesh,
    };
  }

  /**
   * Everything that does not move (shapes, lights, the eye) as one p5.Geometry,
   * built when the scene changes: each vertex carries its colour with the light
   * already worked out (a fixed light from above right), so each frame draws it
   * without p5's lights. Software WebGL lights every pixel in its shader, and
   * that alone took a frame from 30 ms to 500 ms. Glass (a material with
   * transparency) goes into a second geometry, `#glass`, drawn last and see-through.
   */
  #staticGeometry(g) {
    const key = this.#shapesKey();
    if (this.#geometry && this.#geometryKey === key) return this.#geometry;
    for (const old of [this.#geometry, this.#glass]) if (old) g.freeGeometry(old);
    const { scene, camera } = this.#view;
    const r = this.#bounds.radius;
    const mesh = { positions: [], colors: [], alpha: 1 }, glass = { positions: [], colors: [], alpha: 1 };
    for (const object of scene.objects) {
      const m = object.material;
      const rgb = m.isEmissive ? GLOW : m.color.map((c) => Math.min(1, c));
      if (object === this.#constructionSphere) continue; // drawn as a wire ball: the construction is inside it
      const into = m.transparency > 0 && !m.isEmissive ? glass : mesh;
      into.alpha = into === glass ? glassAlpha(m.transparency) : 1;
      object.drawIn3D?.(this.#meshKit(), into, rgb); // the shape says which of the view's meshes it is
    }
    for (const light of scene.lights) if (!light.object) sphereMesh(mesh, light.position, r * 0.025, GLOW, false, 8, 12);
    sphereMesh(mesh, camera.position, r * 0.02, [0.11, 0.14, 0.2], true, 8, 12);
    this.#geometry = toGeometry(g, mesh);
    this.#glass = glass.positions.length > 0 ? toGeometry(g, glass) : null;
    this.#geometryKey = key;
    return this.#geometry;
  }

  /**
   * The glass, after everything else: see-through, so the rays it bends show
   * inside it. It is tested against what is nearer but hides nothing behind
   * it (no depth writes), so its far side and what lies beyond show too.
   */
  #drawGlass(g) {
    if (!this.#glass) return;
    const gl = g.drawingContext;
    gl.depthMask(false);
    g.model(this.#glass);
    gl.depthMask(true);
  }

  /** What the static geometry depends on: the shapes, their colours, the lights, the eye and the framing. */
  #shapesKey() {
    const { scene, camera } = this.#view;
    const parts = [camera.position.x, camera.position.y, camera.position.z, this.#bounds.radius, this.#constructionSphere ? 1 : 0];
    for (const o of scene.objects) {
      const m = o.material;
      parts.push(o.center?.x, o.center?.y, o.center?.z, o.radius, o.point?.x, o.point?.y, o.point?.z, o.normal?.x, o.normal?.y, o.normal?.z,
        o.min?.x, o.min?.y, o.min?.z, o.max?.x, o.max?.y, o.max?.z, ...m.color, m.isEmissive ? 1 : 0, m.transparency);
    }
    for (const l of scene.lights) parts.push(l.position.x, l.position.y, l.position.z);
    return parts.join(',');
  }

  /** A huge sphere or a plane: a square patch of it under the scene, big enough to stand on. */
  #groundPatch(g, origin, towardScene, radius, rgb) {
    const n = normalize(new Vec3(), towardScene);
    const c = this.#bounds.center;
    // the patch's middle: on the surface, under the middle of the scene
    const base = radius > 0 ? new Vec3(origin.x + n.x * radius, origin.y + n.y * radius, origin.z + n.z * radius) : origin;
    const k = dot(sub(new Vec3(), c, base), n);
    const mid = new Vec3(c.x - n.x * k, c.y - n.y * k, c.z - n.z * k);
    const u = normalize(new Vec3(), cross(new Vec3(), n, Math.abs(n.x) < 0.9 ? new Vec3(1, 0, 0) : new Vec3(0, 0, 1)));
    const v = cross(new Vec3(), n, u);
    const h = this.#bounds.radius * 1.1;
    const corner = (a, b) => new Vec3(mid.x + (u.x * a + v.x * b) * h, mid.y + (u.y * a + v.y * b) * h, mid.z + (u.z * a + v.z * b) * h);
    const [p, q, s, t] = [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)];
    const col = shade(rgb, n);
    for (const x of [p, q, s, p, s, t]) coloredVertex(g, x, col);
  }

  /** The image plane, textured with the traced picture, its grid and the selected pixel. */
  #drawImagePlane(g, camera) {
    this.#updatePicture();
    const [tl, tr, br, bl] = imagePlane(camera, this.#planeDistance).corners;
    g.push();
    g.noLights();
    g.textureMode(g.NORMAL);
    g.texture(this.#picture);
    g.beginShape(g.TRIANGLES);
    vertexUV(g, tl, 0, 0); vertexUV(g, tr, 1, 0); vertexUV(g, br, 1, 1);
    vertexUV(g, tl, 0, 0); vertexUV(g, br, 1, 1); vertexUV(g, bl, 0, 1);
    g.endShape();
    g.pop();
    outline(g, [tl, tr, br, bl], INK, 1.5);
  }

  #drawFrustum(g, camera) {
    const far = Math.max(this.#planeDistance * 2, dot(sub(new Vec3(), this.#bounds.center, camera.position), camera.forward) + this.#bounds.radius * 0.5);
    const corners = imagePlane(camera, far).corners;
    for (const c of corners) line3(g, camera.position, c, MUTED, 1);
    outline(g, corners, MUTED, 1);
  }

  #drawSegment(g, s) {
    if (s.kind === 'shadow') {
      if (!s.facing) return line3(g, s.from, s.to, RAY_COLORS.away, 1);
      if (s.lit) return line3(g, s.from, s.to, RAY_COLORS.lit, 2.5);
      const stop = s.blockedAt ?? s.to;
      line3(g, s.from, stop, RAY_COLORS.shadow, 2.5);
      if (s.blockedAt) { line3(g, stop, s.to, RAY_COLORS.shadow, 0.75); dot3(g, stop, RAY_COLORS.shadow, this.#bounds.radius * 0.012); }
      return;
    }
    const color = RAY_COLORS[s.kind];
    line3(g, s.from, s.to, color, s.kind === 'normal' ? 2.5 : s.depth === 0 ? 3 : 2);
    if (s.hit) dot3(g, s.to, color, this.#bounds.radius * 0.012);
  }

  /**
   * The picture for the image plane: the traced pixels as blocks of k × k
   * texels, the grid between them and the selected pixel outlined. Built only
   * when the picture or the selection changed.
   */
  #updatePicture() {
    const view = this.#view, W = view.width, H = view.height;
    const key = `${W}x${H}:${this.#selected?.x},${this.#selected?.y}`;
    if (this.#pictureKey === key) return;
    this.#pictureKey = key;
    const k = Math.max(1, Math.floor(MAX_TEXTURE / Math.max(W, H)));
    const pic = this.#picture;
    if (pic.width !== W * k || pic.height !== H * k) { pic.resizeCanvas(W * k, H * k); this.#pictureCtx = pic.drawingContext; }
    const c = pic.elt, ctx = this.#pictureCtx;
    ctx.fillStyle = '#e4e7ec'; // not traced yet
    ctx.fillRect(0, 0, c.width, c.height);
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(view.canvas, 0, 0, c.width, c.height);
    if (k >= 4) {
      ctx.beginPath();
      for (let x = 1; x < W; x++) { ctx.moveTo(x * k + 0.5, 0); ctx.lineTo(x * k + 0.5, c.height); }
      for (let y = 1; y < H; y++) { ctx.moveTo(0, y * k + 0.5); ctx.lineTo(c.width, y * k + 0.5); }
      ctx.strokeStyle = 'rgba(0, 0, 0, 0.25)';
      ctx.lineWidth = 1;
      ctx.stroke();
    }
    const s = this.#selected;
    if (s) {
      const w = Math.max(2, Math.round(k / 5));
      ctx.lineWidth = w + 2; ctx.strokeStyle = 'rgba(0, 0, 0, 0.85)';
      ctx.strokeRect(s.x * k - w / 2, s.y * k - w / 2, k + w, k + w);
      ctx.lineWidth = w; ctx.strokeStyle = '#ffffff';
      ctx.strokeRect(s.x * k - w / 2, s.y * k - w / 2, k + w, k + w);
    }
  }

  #drawLabels(o) {
    const c = this.labelLayer, ctx = c.getContext('2d');
    ctx.clearRect(0, 0, c.width, c.height);
    const labels = this.#constructionLabels.length ? [...this.#labels, ...this.#constructionLabels] : this.#labels;
    if (!labels.length) return;
    ctx.font = `bold 14px ${FONT}`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    for (const l of labels) {
      const at = projectToScreen(o, l.at, this.width, this.height, FOVY);
      if (!at) continue;
      ctx.lineWidth = 4; ctx.strokeStyle = 'rgba(255, 255, 255, 0.9)';
      const y = at.y + (l.dy ?? 0);
      ctx.strokeText(l.text, at.x, y);
      ctx.fillStyle = l.color ?? INK;
      ctx.fillText(l.text, at.x, y);
    }
  }

  /* ---------------- DOM and input ---------------- */

  #buildDom(parent, label, controls) {
    this.labelLayer = element('canvas', { class: 'rt-view3d-labels', 'aria-hidden': 'true', width: this.width, height: this.height });
    Object.assign(this.labelLayer.style, { position: 'absolute', left: '0', top: '0', width: `${this.width}px`, height: `${this.height}px`, pointerEvents: 'none' });
    const stage = element('div', { class: 'rt-stage rt-view3d-stage' }, this.labelLayer);
    stage.style.position = 'relative';
    stage.style.width = `${this.width}px`;
    stage.style.height = `${this.height}px`;
    this.figure = element('figure', { class: 'rt-view rt-view3d', 'data-scene-view': '' });
    if (label) this.figure.append(element('figcaption', { class: 'rt-label' }, label));
    this.figure.append(stage);
    this.bar = element('div', { class: 'rt-bar rt-view3d-bar' });
    if (controls) {
      const reset = element('button', { type: 'button', class: 'rt-button', 'data-view3d-reset': '', title: 'Look from the first point of view again' }, 'Reset view');
      reset.addEventListener('click', () => this.reset());
      const shoot = element('button', { type: 'button', class: 'rt-button', 'data-view3d-shoot': '', title: 'Trace the picture again, one ray at a time, and watch each ray fly' }, 'Shoot rays');
      shoot.addEventListener('click', () => this.shoot());
      this.stopButton = element('button', { type: 'button', class: 'rt-button', 'data-view3d-stop': '', title: 'Stop shooting rays (Esc)', disabled: '' }, 'Stop');
      this.stopButton.addEventListener('click', () => this.stop());
      const speedText = element('span', { class: 'rt-view3d-speed-text' }, `${this.raysPerSecond} rays/s`);
      const speed = element('input', {
        type: 'range', min: '0', max: String(SPEEDS.length - 1), step: '1', value: String(SPEEDS.indexOf(this.raysPerSecond)),
        'data-view3d-speed': '', 'aria-label': 'Rays per second',
      });
      speed.addEventListener('input', () => {
        const v = SPEEDS[Number(speed.value)];
        speedText.textContent = `${v} rays/s`;
        this.setSpeed(v);
      });
      const speedLabel = element('label', { class: 'rt-view3d-speed' }, 'Speed ', speed, speedText);
      speedLabel.style.display = 'inline-flex';
      speedLabel.style.alignItems = 'center';
      speedLabel.style.gap = '0.4rem';
      this.bar.append(shoot, this.stopButton, speedLabel, reset, createOrbitButtons(this));
    }
    this.figure.append(this.bar);
    const host = resolveParent(parent, null);
    if (host) host.append(this.figure); else this.#view.figure.after(this.figure);
    this.#ready = new Promise((resolve) => {
      new p5((q) => {
        q.setup = () => {
          q.createCanvas(this.width, this.height, q.WEBGL);
          q.pixelDensity(1);
          q.noLoop(); // drawn only when something changed (redraw())
          q.linePerspective(false); // rays as thick near as far
          this.#g = q;
          // the image plane's texture: a 2D p5.Graphics drawn through its own context
          this.#picture = q.createGraphics(16, 16);
          this.#picture.pixelDensity(1);
          this.#pictureCtx = this.#picture.drawingContext;
          this.#canvasReady(/** @type {any} */ (q).canvas, stage); // p5's types leave out the instance's canvas
          resolve(this);
        };
        q.draw = () => { const t = performance.now(); this.#draw(); this.#lastDrawMs = performance.now() - t; };
      }, stage);
    });
  }

  #ready;

  #canvasReady(c, stage) {
    stage.prepend(c);
    c.style.display = 'block';
    c.style.touchAction = 'none';
    c.style.cursor = 'grab';
    c.setAttribute('data-view3d', '');
    c.setAttribute('tabindex', '0');
    c.setAttribute('role', 'img');
    c.setAttribute('aria-label', 'The scene in 3D: the arrow keys or dragging turn it, + and − or the wheel zoom it, Esc stops shooting rays; click a pixel of the image plane to select it');
    c.classList.add('rt-view3d-canvas');
    const s = this.#selected;
    c.setAttribute('data-selected', s ? `${s.x},${s.y}` : '');
    this.#listen(c);
    this.redraw();
  }

  #listen(c) {
    // h / v: all rays of the selected pixel's row / column, from either view (as in RayTeaching)
    const keys = (e) => {
      if (e.ctrlKey || e.metaKey || e.altKey) return;
      const kind = { h: 'row', v: 'column' }[e.key.toLowerCase()];
      if (!kind) return;
      this.showFan(this.#fan === kind ? null : kind);
    };
    c.addEventListener('keydown', keys);
    this.#view.canvas.addEventListener('keydown', keys);
    listenForOrbitKeys(c, this.figure, this);
    c.addEventListener('pointerdown', (e) => {
      if (e.button !== 0) return;
      c.setPointerCapture?.(e.pointerId);
      this.#drag = { x: e.clientX, y: e.clientY, yaw: this.#orbit.yaw, pitch: this.#orbit.pitch, moved: false };
      c.style.cursor = 'grabbing';
    });
    c.addEventListener('pointermove', (e) => {
      const d = this.#drag;
      if (!d || !(e.buttons & 1)) return;
      const dx = e.clientX - d.x, dy = e.clientY - d.y;
      if (!d.moved && Math.hypot(dx, dy) < CLICK_SLOP) return;
      d.moved = true;
      this.setOrbit({ yaw: d.yaw - dx * 0.4, pitch: d.pitch + dy * 0.4 });
    });
    const release = (e) => {
      const d = this.#drag;
      this.#drag = null;
      c.style.cursor = 'grab';
      if (d && !d.moved && e.type === 'pointerup') this.#pick(e);
    };
    c.addEventListener('pointerup', release);
    c.addEventListener('pointercancel', release);
    c.addEventListener('wheel', (e) => {
      e.preventDefault(); // zoom the view, not scroll the page
      const r = this.#bounds.radius;
      this.setOrbit({ distance: clamp(this.#orbit.distance * Math.exp(e.deltaY * 0.0015), r * 0.3, r * 8) });
    }, { passive: false });
  }

  /** A click on the image plane selects the pixel under it. */
  #pick(e) {
    const box = this.canvas.getBoundingClientRect();
    const px = ((e.clientX - box.left) / box.width) * this.width, py = ((e.clientY - box.top) / box.height) * this.height;
    const { origin, direction } = screenRay(this.#eye(), px, py, this.width, this.height, FOVY);
    const hit = pickImagePlane(this.#view.camera, this.#planeDistance, origin, direction);
    if (hit) this.#view.select(hit.x, hit.y);
  }
}

/* ---------------- helpers ---------------- */

/** Emissive shapes and point lights: a warm glow. */
const GLOW = [1, 0.84, 0.3];
/** The fixed light the shapes are shaded by (from above, right, front) and how much light reaches everything. */
const SUN = normalize(new Vec3(), new Vec3(0.35, 0.85, 0.4));
const AMBIENT = 0.45;

/** A colour [0–1] as lit by SUN on a surface with normal n: 0–255 bytes. */
function shade(rgb, n, lit = true) {
  const k = lit ? AMBIENT + (1 - AMBIENT) * Math.max(0, dot(n, SUN)) : 1;
  return [Math.round(255 * rgb[0] * k), Math.round(255 * rgb[1] * k), Math.round(255 * rgb[2] * k)];
}

/** How opaque glass of this transparency is drawn: clear glass stays faintly visible. */
function glassAlpha(transparency) {
  return 1 - 0.75 * transparency;
}

function coloredVertex(mesh, p, col) {
  mesh.positions.push(p.x, -p.y, p.z);
  mesh.colors.push(col[0] / 255, col[1] / 255, col[2] / 255, mesh.alpha ?? 1);
}

/**
 * A p5.Geometry from flat triangle lists (x, −y, z per vertex; r, g, b, a),
 * filled in directly: building it through fill() and vertex() parses a colour
 * per vertex, a second for the class scene's 20,000 vertices.
 */
function toGeometry(g, { positions, colors }) {
  // p5's types know neither this constructor's renderer argument nor vertexColors, which p5 2.3 has.
  const Geometry = /** @type {any} */ (p5.Geometry);
  return new Geometry(1, 1, /** @this {any} the geometry being built */ function () {
    const n = positions.length / 3;
    for (let i = 0; i < n; i++) {
      this.vertices.push(g.createVector(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]));
      this.vertexNormals.push(g.createVector(0, 0, 1));
    }
    for (let i = 0; i < n; i += 3) this.faces.push([i, i + 1, i + 2]);
    this.vertexColors = colors;
  }, g._renderer);
}

/** A sphere as latitude/longitude triangles, each vertex coloured by its normal (flat glow when not lit). */
function sphereMesh(g, c, r, rgb, lit = true, rings = 16, segments = 28) {
  const at = (i, j) => {
    const theta = (Math.PI * i) / rings, phi = (2 * Math.PI * j) / segments;
    const n = new Vec3(Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi));
    return { p: new Vec3(c.x + r * n.x, c.y + r * n.y, c.z + r * n.z), col: shade(rgb, n, lit) };
  };
  for (let i = 0; i < rings; i++) {
    for (let j = 0; j < segments; j++) {
      const a = at(i, j), b = at(i + 1, j), d = at(i, j + 1), e = at(i + 1, j + 1);
      for (const v of [a, b, e, a, e, d]) coloredVertex(g, v.p, v.col);
    }
  }
}

/** A sphere as a few circles (three great circles and two latitudes), so what is inside it shows. */
function wireSphere(g, sphere) {
  const c = sphere.center, r = sphere.radius, m = sphere.material.color, n = 48;
  g.push();
  g.noFill();
  g.stroke(Math.round(255 * Math.min(1, m[0])), Math.round(255 * Math.min(1, m[1])), Math.round(255 * Math.min(1, m[2])));
  g.strokeWeight(1.5);
  g.beginShape(g.LINES);
  const circle = (point) => {
    for (let i = 0; i < n; i++) {
      const a = point((2 * Math.PI * i) / n), b = point((2 * Math.PI * (i + 1)) / n);
      g.vertex(c.x + a[0] * r, -(c.y + a[1] * r), c.z + a[2] * r);
      g.vertex(c.x + b[0] * r, -(c.y + b[1] * r), c.z + b[2] * r);
    }
  };
  circle((t) => [Math.cos(t), Math.sin(t), 0]);
  circle((t) => [Math.cos(t), 0, Math.sin(t)]);
  circle((t) => [0, Math.cos(t), Math.sin(t)]);
  for (const y of [-0.6, 0.6]) { const k = Math.sqrt(1 - y * y); circle((t) => [k * Math.cos(t), y, k * Math.sin(t)]); }
  g.endShape();
  g.pop();
}

/** A box: two triangles a face, each face shaded by its normal. */
function boxMesh(g, min, max, rgb) {
  const P = (x, y, z) => new Vec3(x ? max.x : min.x, y ? max.y : min.y, z ? max.z : min.z);
  /** @type {Array<[import('../vec3.js').Vec3, import('../vec3.js').Vec3[]]>} a face: its normal and its four corners */
  const faces = [
    [new Vec3(1, 0, 0), [P(1, 0, 0), P(1, 1, 0), P(1, 1, 1), P(1, 0, 1)]], [new Vec3(-1, 0, 0), [P(0, 0, 0), P(0, 0, 1), P(0, 1, 1), P(0, 1, 0)]],
    [new Vec3(0, 1, 0), [P(0, 1, 0), P(0, 1, 1), P(1, 1, 1), P(1, 1, 0)]], [new Vec3(0, -1, 0), [P(0, 0, 0), P(1, 0, 0), P(1, 0, 1), P(0, 0, 1)]],
    [new Vec3(0, 0, 1), [P(0, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1)]], [new Vec3(0, 0, -1), [P(0, 0, 0), P(0, 1, 0), P(1, 1, 0), P(1, 0, 0)]],
  ];
  for (const [n, [a, b, c, d]] of faces) {
    const col = shade(rgb, n);
    for (const v of [a, b, c, a, c, d]) coloredVertex(g, v, col);
  }
}

/** p5 coordinates of a scene point: y negated (p5's WEBGL y points down). */
function vertexUV(g, p, u, v) { g.vertex(p.x, -p.y, p.z, u, v); }

function line3(g, a, b, color, weight) {
  g.push();
  g.stroke(color);
  g.strokeWeight(weight);
  g.line(a.x, -a.y, a.z, b.x, -b.y, b.z);
  g.pop();
}

function outline(g, pts, color, weight) {
  for (let i = 0; i < pts.length; i++) line3(g, pts[i], pts[(i + 1) % pts.length], color, weight);
}

function dot3(g, at, color, r) {
  g.push();
  g.noStroke();
  g.noLights();
  g.fill(color);
  g.translate(at.x, -at.y, at.z);
  g.sphere(r, 10, 6);
  g.pop();
}

/** The distance along the view direction to the nearest shape in front of the eye (for the image plane to stay clear of it). */
function nearestAhead(scene, camera) {
  let nearest = Infinity;
  for (const o of scene.objects) {
    const ball = ballOf(o);
    if (!ball || ball.radius > HUGE_RADIUS) continue;
    const along = dot(sub(new Vec3(), ball.center, camera.position), camera.forward) - ball.radius;
    if (along > 0) nearest = Math.min(nearest, along);
  }
  return Number.isFinite(nearest) ? nearest : 10;
}

function checkOrbit(orbit) {
  const own = checkOptions(orbit, ['yaw', 'pitch', 'distance'], 'orbit');
  const out = {};
  for (const key of Object.keys(own)) {
    const v = orbit[key];
    if (typeof v !== 'number' || !Number.isFinite(v) || (key === 'distance' && v <= 0)) throw new RangeError(`orbit.${key} must be a ${key === 'distance' ? 'distance greater than 0' : 'number of degrees'}, got ${show(v)}`);
    out[key] = v;
  }
  return out;
}

/** When a segment starts to grow, in legs of the flight: a ray of depth d after d legs, the normal and shadow rays at its end. */
function startOf(s) {
  return s.kind === 'normal' || s.kind === 'shadow' ? s.depth + 1 : s.depth;
}
