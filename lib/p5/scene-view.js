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
import { Sphere } from '../shapes/sphere.js';
import { Plane } from '../shapes/plane.js';
import { Box } from '../shapes/box.js';
import { inspectPixel } from '../explain.js';
import { vec3, sub, dot, normalize, cross } from '../vec3.js';
import { show, checkOptions } from '../check.js';
import {
  imagePlane, pixelCenter, pickImagePlane, raySegments, sceneBounds, orbitCamera, screenRay, projectToScreen, HUGE_RADIUS,
} from '../rays3d.js';
import { useStyle, element } from './dom.js';
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

const OPTIONS = ['view', 'width', 'height', 'parent', 'label', 'planeDistance', 'frustum', 'orbit', 'controls'];

/**
 * Creates a 3D view of a tracer view's scene (call it from setup()).
 * @param {p5} p the sketch
 * @param {object} options
 * @param {import('./tracer-view.js').TracerView} options.view the tracer view it shows and selects in
 * @param {number} [options.width=480] canvas width, px
 * @param {number} [options.height=360] canvas height, px
 * @param {HTMLElement|string|{elt: HTMLElement}} [options.parent] where to put it; default next to the tracer view
 * @param {string} [options.label] a caption above it
 * @param {number|'auto'} [options.planeDistance='auto'] how far from the eye to show the image plane (the camera's own is at 1; rays through a pixel pass through the same pixel at any distance)
 * @param {boolean} [options.frustum=true] draw the view frustum
 * @param {{yaw?: number, pitch?: number, distance?: number}} [options.orbit] where to look from at first (degrees; distance in scene units)
 * @param {boolean} [options.controls=true] show the Reset button
 * @returns {SceneView}
 */
export function createSceneView(p, options = {}) {
  return new SceneView(p, options);
}

export class SceneView {
  #p; #g = null; #view; #raf = 0; #destroyed = false; #unlisten;
  #orbit; #home; #bounds; #planeDistance; #planeOption; #frustum;
  #picture; #pictureCtx; #k = 1; #pictureKey = ''; #lastDrawMs = 0; #lastDrawAt = -Infinity;
  #selected = null; #segments = []; #record = null;
  #extra = []; #drag = null; #target; #watching = 0; #labels = [];

  constructor(p, options = {}) {
    checkOptions(options, OPTIONS, 'scene view');
    const { view, width = 480, height = 360, parent, label = 'The scene in 3D', planeDistance = 'auto', frustum = true, orbit = {}, controls = true } = options;
    if (!view || typeof view.onSelect !== 'function' || !view.camera) throw new TypeError(`createSceneView needs { view }: a tracer view, got ${show(view)}`);
    for (const [name, v] of [['width', width], ['height', height]]) {
      if (!Number.isInteger(v) || v < 16 || v > 4096) throw new RangeError(`${name} must be a whole number of pixels from 16 to 4096, got ${show(v)}`);
    }
    if (planeDistance !== 'auto' && !(typeof planeDistance === 'number' && planeDistance > 0 && Number.isFinite(planeDistance))) {
      throw new RangeError(`planeDistance must be 'auto' or a distance greater than 0, got ${show(planeDistance)}`);
    }
    this.#p = p;
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
    if (this.canvas) this.canvas.dataset.state = 'drawing';
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
    this.#target = vec3(c.x + (e.x - c.x) * 0.45, c.y + (e.y - c.y) * 0.45, c.z + (e.z - c.z) * 0.45);
    this.#home = { ...HOME, distance: this.#bounds.radius * 0.95 };
    if (!this.#orbit) return;
    this.#pictureKey = '';
    this.redraw();
  }

  #selectionChanged(s) {
    this.#selected = s ? { x: s.x, y: s.y } : null;
    if (this.canvas) this.canvas.dataset.selected = s ? `${s.x},${s.y}` : '';
    const view = this.#view;
    this.#record = s ? inspectPixel(view.scene, view.camera, s.x, s.y) : null;
    this.#segments = this.#record ? raySegments(view.scene, this.#record, { missLength: this.#bounds.radius * 2.5, normalLength: this.#bounds.radius * 0.08 }) : [];
    this.#pictureKey = '';
    this.redraw();
  }

  #observer = null;

  /**
   * Follows the tracer view's picture as it fills in: polls on animation
   * frames only while it is tracing (the view marks its figure with
   * data-state), and wakes up when it starts again.
   */
  #watchTrace() {
    if (!this.#observer) {
      this.#observer = new MutationObserver(() => this.#watchTrace());
      this.#observer.observe(this.#view.figure, { attributes: true, attributeFilter: ['data-state'] });
    }
    if (this.#watching || this.#destroyed) return;
    let seen = -1;
    const poll = () => {
      this.#watching = 0;
      const v = this.#view, progress = v.done ? 1 : v.progress;
      if (progress < seen) this.#sceneChanged(); // a restart
      if (progress !== seen) {
        const now = performance.now();
        // keep the trace's pace: while it runs, redraw only when enough time has passed since the last draw
        if (v.done || now - this.#lastDrawAt > this.#lastDrawMs * TRACE_SHARE + 100) {
          seen = progress;
          this.#pictureKey = '';
          this.redraw();
        }
      }
      if (!v.done || seen !== 1) this.#watching = requestAnimationFrame(poll);
    };
    poll();
  }

  /* ---------------- drawing ---------------- */

  #frame = () => {
    this.#raf = 0;
    if (this.#destroyed || !this.#g) return;
    const start = performance.now();
    this.#g.redraw();
    this.#lastDrawAt = performance.now();
    this.#lastDrawMs = this.#lastDrawAt - start;
    // "done" once it shows the finished picture and nothing more is waiting: tests and screenshots wait for it
    this.canvas.dataset.state = this.#view.done && !this.#raf ? 'done' : 'drawing';
  };

  /** The orbit camera as vectors (lib/rays3d.js orbitCamera). */
  #eye() {
    return orbitCamera({ target: this.#target, yaw: this.#orbit.yaw, pitch: this.#orbit.pitch, distance: this.#orbit.distance });
  }

  #draw() {
    const g = this.#g, view = this.#view, scene = view.scene, camera = view.camera;
    const o = this.#eye();
    g.push();
    g.background(246, 247, 249);
    // p5's WEBGL y axis points down: the scene is drawn with y negated (see P below)
    g.perspective(FOVY, this.width / this.height, this.#orbit.distance * 0.02, this.#orbit.distance * 20);
    g.camera(o.eye.x, -o.eye.y, o.eye.z, o.target.x, -o.target.y, o.target.z, 0, 1, 0);
    g.ambientLight(120);
    g.directionalLight(150, 150, 150, 0.3, 0.8, -0.5);
    g.directionalLight(60, 60, 60, -0.4, -0.2, 0.8);
    g.noStroke();

    for (const object of scene.objects) this.#drawShape(g, object);
    for (const light of scene.lights) if (!light.object) this.#drawPointLight(g, light.position);
    this.#drawEye(g, camera);
    this.#drawImagePlane(g, camera);
    if (this.#frustum) this.#drawFrustum(g, camera);
    for (const s of this.#segments) this.#drawSegment(g, s);
    for (const r of this.#extra) line3(g, r.from, r.to, r.color, r.weight ?? 1.5);
    g.pop();
    this.#drawLabels(o);
  }

  #drawShape(g, object) {
    const m = object.material;
    g.push();
    const glow = m.isEmissive;
    const rgb = glow ? [255, 214, 80] : m.color.map((c) => Math.round(255 * Math.min(1, c)));
    if (glow) { g.emissiveMaterial(255, 200, 60); g.fill(255, 214, 80); } else g.fill(rgb[0], rgb[1], rgb[2], m.transparency > 0 ? 255 * (1 - 0.6 * m.transparency) : 255);
    if (m.reflection > 0) { g.specularMaterial(200); g.shininess(40); }
    if (object instanceof Sphere) {
      if (object.radius > HUGE_RADIUS) this.#drawGroundPatch(g, object.center, sub(vec3(), this.#bounds.center, object.center), object.radius);
      else { g.translate(object.center.x, -object.center.y, object.center.z); g.sphere(object.radius, 28, 18); }
    } else if (object instanceof Plane) {
      this.#drawGroundPatch(g, object.point, object.normal, 0);
    } else if (object instanceof Box) {
      const a = object.min, b = object.max;
      g.translate((a.x + b.x) / 2, -(a.y + b.y) / 2, (a.z + b.z) / 2);
      g.box(b.x - a.x, b.y - a.y, b.z - a.z);
    }
    g.pop();
  }

  /** A huge sphere or a plane: a square patch of it under the scene, big enough to stand on. */
  #drawGroundPatch(g, origin, towardScene, radius) {
    const n = normalize(vec3(), towardScene);
    const c = this.#bounds.center;
    // the patch's middle: on the surface, under the middle of the scene
    const base = radius > 0 ? vec3(origin.x + n.x * radius, origin.y + n.y * radius, origin.z + n.z * radius) : origin;
    const k = dot(sub(vec3(), c, base), n);
    const mid = vec3(c.x - n.x * k, c.y - n.y * k, c.z - n.z * k);
    g.translate(mid.x, -mid.y, mid.z);
    // turn p5's plane (in its x-y plane, facing +z) to face n (y negated)
    const np = normalize(vec3(), vec3(n.x, -n.y, n.z)), z = vec3(0, 0, 1);
    const axis = cross(vec3(), z, np), angle = Math.acos(clamp(dot(z, np), -1, 1));
    if (Math.hypot(axis.x, axis.y, axis.z) > 1e-9) g.rotate(angle, [axis.x, axis.y, axis.z]);
    const size = this.#bounds.radius * 2.2;
    g.plane(size, size);
  }

  #drawPointLight(g, at) {
    g.push();
    g.emissiveMaterial(255, 200, 60);
    g.fill(255, 214, 80);
    g.translate(at.x, -at.y, at.z);
    g.sphere(this.#bounds.radius * 0.025, 12, 8);
    g.pop();
  }

  #drawEye(g, camera) {
    const e = camera.position;
    g.push();
    g.fill(29, 36, 51);
    g.translate(e.x, -e.y, e.z);
    g.sphere(this.#bounds.radius * 0.02, 14, 10);
    g.pop();
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
    const far = Math.max(this.#planeDistance * 2, dot(sub(vec3(), this.#bounds.center, camera.position), camera.forward) + this.#bounds.radius * 0.5);
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
    const view = this.#view, W = view.width, H = view.height, r = view.renderer;
    const key = `${W}x${H}:${this.#selected?.x},${this.#selected?.y}`;
    if (this.#pictureKey === key) return;
    this.#pictureKey = key;
    const k = this.#k = Math.max(1, Math.floor(MAX_TEXTURE / Math.max(W, H)));
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
    if (!this.#labels.length) return;
    ctx.font = `bold 14px ${FONT}`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    for (const l of this.#labels) {
      const at = projectToScreen(o, l.at, this.width, this.height, FOVY);
      if (!at) continue;
      ctx.lineWidth = 4; ctx.strokeStyle = 'rgba(255, 255, 255, 0.9)';
      ctx.strokeText(l.text, at.x, at.y);
      ctx.fillStyle = l.color ?? INK;
      ctx.fillText(l.text, at.x, at.y);
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
      this.bar.append(reset);
    }
    this.figure.append(this.bar);
    const host = resolveParent(parent);
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
          this.#canvasReady(q.canvas, stage);
          resolve(this);
        };
        q.draw = () => this.#draw();
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
    c.setAttribute('aria-label', 'The scene in 3D: drag to turn it, the wheel to zoom, click a pixel of the image plane to select it');
    c.classList.add('rt-view3d-canvas');
    const s = this.#selected;
    c.setAttribute('data-selected', s ? `${s.x},${s.y}` : '');
    this.#listen(c);
    this.redraw();
  }

  #listen(c) {
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
    if (!(o instanceof Sphere) || o.radius > HUGE_RADIUS) continue;
    const along = dot(sub(vec3(), o.center, camera.position), camera.forward) - o.radius;
    if (along > 0) nearest = Math.min(nearest, along);
  }
  return Number.isFinite(nearest) ? nearest : 10;
}

function checkOrbit(orbit) {
  checkOptions(orbit, ['yaw', 'pitch', 'distance'], 'orbit');
  const out = {};
  for (const key of Object.keys(orbit)) {
    const v = orbit[key];
    if (typeof v !== 'number' || !Number.isFinite(v) || (key === 'distance' && v <= 0)) throw new RangeError(`orbit.${key} must be a ${key === 'distance' ? 'distance greater than 0' : 'number of degrees'}, got ${show(v)}`);
    out[key] = v;
  }
  return out;
}

function clamp(v, lo, hi) {
  return v < lo ? lo : v > hi ? hi : v;
}

function resolveParent(parent) {
  if (parent == null) return null;
  if (typeof parent === 'string') {
    const found = document.getElementById(parent) ?? document.querySelector(parent);
    if (!found) throw new TypeError(`parent: no element with id or selector ${show(parent)}`);
    return found;
  }
  if (parent.elt instanceof HTMLElement) return parent.elt;
  if (parent instanceof HTMLElement) return parent;
  throw new TypeError(`parent must be an element, its id or a p5.Element, got ${show(parent)}`);
}
