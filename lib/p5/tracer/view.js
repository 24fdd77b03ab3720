/**
 * The tracer view: a traced picture inside a p5 sketch, shown big with crisp
 * pixels so that "pixel 10,12" is something a class can point at.
 *
 *   new p5((p) => {
 *     p.setup = () => {
 *       p.noCanvas(); // the view brings its own canvas
 *       const view = p.createTracerView({ scene: classScene(), camera: new Camera({ width: 64, height: 48 }) });
 *       p.createInspector({ view });
 *     };
 *   });
 *
 * No draw() is needed: while there is work the view traces for `budgetMs` on
 * every animation frame, blits, and goes idle once the picture is done (so it
 * works the same whether the sketch has a draw(), animates, or calls noLoop()).
 * A sketch that animates just calls `view.setCamera(…)` from its draw().
 *
 * TracerView coordinates: it schedules the frames, builds its figure and
 * keeps the page's render state. Its parts live beside it: tracer-layout.js
 * (the size on screen), tracer-overlay.js (grid and marks over the picture),
 * tracer-input.js (press, drag, arrow keys), tracer-export.js (the PNG),
 * tracer-progress.js (the progress bar and the workers' note),
 * tracer-events.js (what it tells listeners: `view.on('select' | 'restart' | 'progress', fn)`).
 */
import { modeShader, modeLegend } from '../../tracing/modes.js';
import { pixelCoordinate, checkOptions } from '../../text/check.js';
import { inspectPixel } from '../../lesson/inspect.js';
import { sceneHolds } from '../page/scene-holds.js';
import { registerView } from '../page/page-state.js';
import { useStyle, element, resolveParent, sketchNode } from '../dom.js';
import { addProjectorSwitch } from '../page/projector.js';
import { createLegendElement } from '../diagrams/legend.js';
import { drawOverlay } from './overlay.js';
import { pixelAt, listenForPixels } from './input.js';
import { pngDataURL, pngFilename, download, createSaveButton } from './export.js';
import { checkScale, pictureScale, sizePicture, watchRoom } from './layout.js';
import { createPictureWords } from './picture-words.js';
import { reducedMotion } from '../page/announce.js';
import { createEvents } from './events.js';
import { createTracerProgress } from './progress.js';
import { engineRenderer, showEngine, checkEngine } from './engines.js';
import { listenForOrbit } from './gpu-orbit.js';
import { viewRenderer, pathTraced, checkOrder, checkBudget } from './renderer.js';

/**
 * Creates a tracer view inside a p5 sketch (call it from setup()).
 * @param {import('p5').default} p the sketch (instance mode), used for its parent node and its lifetime
 * @param {object} options
 * @param {import('../../scene/scene.js').Scene} options.scene
 * @param {import('../../math/camera.js').Camera} options.camera its width × height is the traced resolution
 * @param {'auto'|number} [options.scale='auto'] on-screen pixels per traced pixel with 16 px text (more, in whole steps, when the page's text is larger); 'auto' = the largest whole number that fits
 * @param {boolean} [options.grid=false] draw the pixel grid (on an overlay, never into the picture)
 * @param {string} [options.mode='shaded'] visual mode: 'shaded', 'discriminant', 'roots', 'h', 'v', 'normals', 'depth'
 * @param {'coarse'|'scanline'|'slow'} [options.order='coarse'] the render order: coarse blocks first, row by row, or row by row in slow motion
 * @param {'coarse'|'scanline'|'slow'} [options.renderMode] deprecated: the old name of `order` (it still works)
 * @param {number} [options.budgetMs=8] tracing time per animation frame
 * @param {'auto'|number|false} [options.workers='auto'] Web Workers for large shaded frames ('auto': one per core; false: none)
 * @param {HTMLElement|string|{elt: HTMLElement}} [options.parent] where to put it (element, id or p5.Element); default the sketch's node
 * @param {string} [options.label] a caption above the picture
 * @param {boolean} [options.legend=true] show the mode's legend under the picture (not for 'shaded')
 * @param {'cpu'|'gpu'} [options.engine='cpu'] 'gpu': a whole frame every animation frame by WebGL2 (lib/gpu/), with `path` its samples pass after pass; back to the CPU with a line on the page when WebGL2 is missing or lost
 * @param {object} [options.path] path trace the picture instead, sample after sample, with pathTrace's options
 *   (`{ samples, seed, maxBounces, sky, roulette }`); the progress line counts the samples ("Sample 37 of 256")
 * @returns {TracerView}
 * @example
 * new p5((p) => {
 *   p.setup = () => {
 *     p.noCanvas(); // the tracer view brings its own canvas
 *     const scene = new Scene().add(new Sphere([0, 0, -20], 4, { color: 'pink' })).add(new PointLight([-10, 20, 0]));
 *     const view = p.createTracerView({ scene, camera: new Camera({ width: 64, height: 48 }), grid: true });
 *     p.createInspector({ view });
 *   };
 * });
 * // global mode (one-file build): function setup() { noCanvas(); createTracerView({ scene, camera }); }
 */
export function createTracerView(p, options) { // no options: checkOptions gives {}
  return new TracerView(p, checkOptions(options, TRACER_VIEW_OPTIONS, 'createTracerView'));
}

/** The options createTracerView takes. */
const TRACER_VIEW_OPTIONS = ['scene', 'camera', 'scale', 'grid', 'mode', 'order', 'renderMode', 'budgetMs', 'workers', 'parent', 'label', 'legend', 'engine', 'path'];
/** What a tracer view tells its listeners (see `on`). */
const EVENTS = ['select', 'restart', 'progress'];

/**
 * The traced picture on the page, what `p.createTracerView({ … })` returns: progressive, clickable, restartable.
 * @example
 * const view = p.createTracerView({ scene: classScene(), camera: new Camera({ width: 64, height: 48 }) });
 * view.setMode('discriminant');          // the discriminant map; 'shaded' for the picture again
 * view.setScene(classSceneAt(2));        // re-traces without a reload
 * view.onSelect((pixel) => console.log(pixel)); // a click: { x, y } (null when the selection is cleared)
 * view.on('progress', ({ progress }) => console.log(`${Math.round(progress * 100)}%`));
 */
export class TracerView {
  /** @type {any} a WorkerProgressiveRenderer, or the GPU engine's (lib/p5/tracer/engines.js) */ #renderer; #page; #imageData = null; #raf = 0; #destroyed = false; #pictures = 0;
  #scale; #grid; #mode; #selected = null; #events = createEvents(EVENTS);
  /** The selected pixel's inspectPixel record (null: none selected; undefined: not made yet for this selection and scene). */
  #record;
  #shownCurrent = null; #ctx; #overlayCtx; #unwatchRoom; #words; #progress;

  /**
   * @param {import('p5').default} p
   * @param {Parameters<typeof createTracerView>[1]} options as for createTracerView
   */
  constructor(p, { scene, camera, scale = 'auto', grid = false, mode = 'shaded', order, renderMode, budgetMs = 8, workers = 'auto', parent, label, legend = true, engine = 'cpu', path } = /** @type {any} */ ({})) {
    checkEngine(engine);
    this.#scale = checkScale(scale);
    this.#grid = Boolean(grid);
    this.budgetMs = checkBudget(budgetMs);
    this.#mode = mode;
    this.#renderer = viewRenderer({ scene, camera, mode, order, renderMode, path, budgetMs: this.budgetMs, workers }); // the path tracer, or frames on Web Workers
    this.showLegend = legend;

    useStyle();
    addProjectorSwitch();
    this.#buildDom(resolveParent(parent, sketchNode(p)), label);
    listenForOrbit(this.canvasElement, this); // on the GPU: drag, arrows and +/− move the camera (first, to take the drag)
    listenForPixels(this.canvasElement, this); // press, drag, arrow keys: this.select(x, y)
    this.#page = registerView(this);
    this.#unwatchRoom = watchRoom(this.figure, () => this.#layout()); // the window, and the room the page's layout leaves
    this.setEngine(engine); // and the first frame starts
  }

  /* ---------------- public API ---------------- */

  /** The scene being traced. */
  get scene() { return this.#renderer.scene; }
  /** The camera (its width × height is the traced resolution). */
  get camera() { return this.#renderer.camera; }
  /** The visual mode ('shaded', 'discriminant', …): what a pixel shows. */
  get mode() { return this.#mode; }
  /** The render order: 'coarse' (blocks of 16, 8, … 1 px), 'scanline' (row by row) or 'slow' (row by row, a few rays at a time). */
  get order() { return this.#renderer.order; }
  /**
   * Deprecated: the old name of `order` (it still works).
   * @deprecated
   */
  get renderMode() { return this.order; }
  /** The traced image's width and height in pixels. */
  get width() { return this.#renderer.width; }
  get height() { return this.#renderer.height; }
  /** True once the whole picture is traced. */
  get done() { return this.#renderer.done; }
  /** Share of the picture traced, 0–1. */
  get progress() { return this.#renderer.progress; }
  /** Whole pictures shown since the view was made: on the GPU every frame it draws, on the CPU every picture traced to its end (frames per second: count them over a time). */
  get picturesDone() { return this.#pictures; }
  /** The selected pixel `{ x, y }` in traced-image coordinates, or null. */
  get selected() { return this.#selected && { ...this.#selected }; }
  /**
   * The selected pixel's whole record (lib/lesson/inspect.js inspectPixel), or null:
   * made when first asked after each selection or new scene, so every 'select'
   * listener (inspector, 3D view, tasks, sample rays) reads the same one.
   */
  get record() {
    if (this.#record === undefined) this.#record = this.#selected ? inspectPixel(this.scene, this.camera, this.#selected.x, this.#selected.y) : null;
    return this.#record;
  }
  /** The record of pixel (x, y): the selected one's `record`, shared with every listener; for another (a pixel pointed at), one made now. */
  recordAt(/** @type {number} */ x, /** @type {number} */ y) { return this.#selected?.x === x && this.#selected?.y === y ? this.record : inspectPixel(this.scene, this.camera, x, y); }
  /** On-screen pixels per traced pixel right now. */
  get scale() { return this.#screenScale(); }
  /** The `<canvas data-tracer>` holding the traced image (and nothing else). */
  get canvas() { return this.canvasElement; }
  /**
   * The pixel traced last `{ x, y }` in 'scanline' and 'slow' order (in slow
   * motion, the ray being shown), null in 'coarse' order or before the first.
   * It stays on the last pixel once the picture is done.
   */
  get current() { return this.#renderer.current && { ...this.#renderer.current }; }
  /** The traced picture's RGBA bytes, `width * height * 4` (read them; the view writes them). */
  get buffer() { return this.#renderer.buffer; }
  /** In 'slow' order: pixels traced per animation frame (a whole number ≥ 1), when `slowRaysPerSecond` is 0. */
  get slowRaysPerStep() { return this.#renderer.slowRaysPerStep; }
  set slowRaysPerStep(n) { this.#renderer.slowRaysPerStep = n; }
  /** In 'slow' order: rays per second by the clock (0: `slowRaysPerStep` a frame instead). Shoot in the 3D view sets it. */
  get slowRaysPerSecond() { return this.#renderer.slowRaysPerSecond; }
  set slowRaysPerSecond(n) { this.#renderer.slowRaysPerSecond = n; }
  get engine() { return this.#renderer.engine ?? 'cpu'; } // the engine tracing now, as the canvas's data-engine says

  /** 'gpu': a whole frame every animation frame; 'cpu': progressive. Where the GPU cannot, the CPU, and a line says why (lib/p5/tracer/engines.js). */
  setEngine(engine) {
    const { renderer, engine: now, why } = engineRenderer(checkEngine(engine), this.#renderer, { budgetMs: this.budgetMs, shader: modeShader(this.#mode), shaded: this.#mode === 'shaded' });
    if (renderer !== this.#renderer) { this.#renderer.terminate(); this.#renderer = renderer; }
    showEngine(this, now, why);
    this.#words.engine(now); // the picture's name says what its arrow keys do on this engine
    this.#started();
    return this;
  }

  /** The progressive renderer doing the work, for tools and benchmarks; sketches use the view's own API. */
  get renderer() { return this.#renderer; }

  /** The traced pixel `{ x, y }` under a point of the screen (a pointer event's clientX, clientY), or null. */
  pixelAt(clientX, clientY) {
    return pixelAt(this.canvasElement, clientX, clientY, this.width, this.height);
  }

  /** Traces a new scene, keeping camera, mode and selection. */
  setScene(scene) { return this.#change({ scene }); }
  /** Traces through a new camera (a new size changes the traced resolution). */
  setCamera(camera) { return this.#change({ camera }); }
  /** Shows another visual mode (see lib/tracing/modes.js). */
  setMode(mode) {
    const shader = modeShader(mode); // throws on an unknown mode, before anything changes
    this.#mode = mode;
    return this.#change({ shader });
  }
  /** Traces again in another render order: 'coarse', 'scanline' or 'slow'. */
  setOrder(order) { return this.#change({ order: checkOrder(order) }); }
  /**
   * Deprecated: the old name of `setOrder` (it still works).
   * @deprecated
   */
  setRenderMode(order) { return this.#change({ order: checkOrder(order, 'renderMode') }); }
  /** Sets the on-screen scale: 'auto' or a number of screen pixels per traced pixel. */
  setScale(scale) {
    this.#scale = checkScale(scale);
    this.#layout();
    return this;
  }
  /** Shows or hides the pixel grid. */
  setGrid(on) {
    this.#grid = Boolean(on);
    this.#drawOverlay();
    return this;
  }
  /** Traces the picture again from the start (after changing the scene in place, say). */
  restart() { return this.#change({}); }
  /**
   * A path-traced view (`path` given) traces again with these of pathTrace's options changed (the others kept).
   * @example
   * view.setPath({ maxBounces: 1 }); // direct light only
   */
  setPath(path) {
    if (!pathTraced(this.#renderer)) throw new TypeError('setPath: this view is not path traced (give createTracerView a path option)');
    return this.#change({ path });
  }
  /** A path-traced view's samples so far and in all, its path options and the noise left (each pixel's standard error, averaged; null when not measured), `{ sample, samples, options, noise }`; null for a view that is not path traced. */
  get pathState() {
    const r = this.#renderer;
    return pathTraced(r) ? { sample: r.sample, samples: r.samples, options: { ...r.options }, noise: r.noise ?? null } : null;
  }

  /**
   * Selects pixel (x, y) of the traced image (whole numbers in range, else a
   * RangeError); null clears the selection. Calls the onSelect listeners.
   * A scene broken since it was traced selects nothing: the mistake panel says why.
   */
  select(x, y) {
    if (x !== null && !sceneHolds(this.scene)) return this;
    if (x === null) {
      this.#selected = null;
    } else {
      pixelCoordinate(x, 'x', this.width);
      pixelCoordinate(y, 'y', this.height);
      this.#selected = { x, y };
    }
    this.#drawOverlay();
    this.#notify();
    return this;
  }

  /**
   * Calls `fn` whenever something happens to the view; returns a function that removes the listener.
   * - `'select'`: `fn({ x, y } | null, view)` when the selection changes, and again when the
   *   scene, camera or mode changes while a pixel is selected (its story changed); the pixel's
   *   inspectPixel record is `view.record`, made once for all the listeners;
   * - `'restart'`: `fn(view)` when the picture clears to be traced again (a new scene, camera,
   *   mode or order, or `restart()`);
   * - `'progress'`: `fn({ progress, done, current }, view)` after each frame of tracing
   *   (`progress` 0–1, `current` as the `current` property).
   * @param {'select'|'restart'|'progress'} event
   * @param {Function} fn
   * @returns {() => void}
   * @example
   * const stop = view.on('restart', () => console.log('tracing again'));
   * stop(); // no more calls
   */
  on(event, fn) { return this.#events.on(event, fn); }

  /**
   * Calls `fn({ x, y }, view)` whenever the selection changes (`null` when it is
   * cleared), as `on('select', fn)`. Returns a function that removes the listener.
   * @example
   * view.onSelect((pixel) => { if (pixel) console.log(`pixel ${pixel.x},${pixel.y}`); });
   */
  onSelect(fn) { return this.#events.on('select', fn); }

  /** The traced image (at traced resolution) as a PNG data URL. */
  toPNG() {
    return pngDataURL(this.canvasElement);
  }

  /** Downloads the traced image as a PNG file at traced resolution (named `trace-64x48-shaded.png` unless given a name). */
  downloadPNG(filename = pngFilename(this.width, this.height, this.#mode)) {
    download(this.toPNG(), filename);
  }

  /**
   * One frame of work: traces for `budgetMs`, blits what changed and updates
   * the progress bar. The view calls it by itself on each animation frame
   * while there is work; calling it by hand is harmless.
   */
  draw() {
    if (this.#destroyed) return;
    const r = this.#renderer;
    if (r.lost) { this.setEngine('cpu'); return; } // the GPU cannot go on (its context lost, a visual mode): engineRenderer says why
    const { changed, done } = r.step(this.budgetMs);
    if (changed && done) this.#pictures++;
    if (reducedMotion() ? done : changed) this.#blit(); // reduced motion: no passes, the picture once it is done
    this.#progress.show(r); // the bar, and the note when the workers failed
    if (this.#events.heard('progress')) this.#events.emit('progress', { progress: done ? 1 : r.progress, done, current: this.current }, this);
    const c = r.current;
    if (c && (c.x !== this.#shownCurrent?.x || c.y !== this.#shownCurrent?.y)) this.#drawOverlay();
    if (done) {
      if (this.#shownCurrent) this.#drawOverlay(); // the "now tracing" marker goes
      this.#page.done();
      this.#words.done();
      this.figure.dataset.state = 'done';
    }
  }

  /** Stops tracing and removes the view from the page. */
  destroy() {
    if (this.#destroyed) return;
    this.#destroyed = true;
    cancelAnimationFrame(this.#raf);
    this.#renderer.terminate();
    this.#words.destroy();
    this.#unwatchRoom();
    this.#page.unregister();
    this.figure.remove();
  }

  /* ---------------- rendering ---------------- */

  #change(changes) {
    if (!sceneHolds(changes.scene ?? this.scene)) return this;
    this.#renderer.restart(changes); // checks everything before changing anything
    const s = this.#selected;
    if (s && (s.x >= this.width || s.y >= this.height)) {
      this.#selected = { x: Math.min(s.x, this.width - 1), y: Math.min(s.y, this.height - 1) };
    }
    this.#started();
    if (this.#selected) this.#notify();
    return this;
  }

  /** A fresh render: resize if needed, clear, mark the page, start the frame loop. */
  #started() {
    this.#record = undefined;
    const c = this.canvasElement, w = this.width, h = this.height;
    if (c.width !== w || c.height !== h) {
      c.width = w; c.height = h; // also clears the canvas
      c.dataset.width = String(w);
      c.dataset.height = String(h);
      this.#layout();
    }
    this.#blit(); // the cleared buffer: the old picture must not pass for the new one
    this.#showLegend();
    this.#words.changed();
    this.figure.dataset.state = 'rendering';
    this.#page.rendering();
    this.#schedule();
    this.#events.emit('restart', this);
  }

  #schedule() {
    if (!this.#raf && !this.#destroyed) this.#raf = requestAnimationFrame(this.#frame);
  }

  #frame = () => {
    this.#raf = 0;
    this.draw();
    if (!this.#renderer.done) this.#schedule();
  };

  /** Copies the renderer's buffer into the canvas; no allocation unless the buffer itself changed. */
  #blit() {
    const r = this.#renderer;
    if (r.blitTo) { r.blitTo(this.#ctx); return; } // the GPU's frame, GPU to GPU
    if (this.#imageData?.data !== r.buffer) this.#imageData = new ImageData(r.buffer, r.width, r.height);
    this.#ctx.putImageData(this.#imageData, 0, 0);
  }

  /** The mode's key under the picture (none for the shaded picture itself). */
  #showLegend() {
    const host = this.legendHost;
    host.hidden = !this.showLegend || this.#mode === 'shaded';
    host.replaceChildren(...(host.hidden ? [] : [createLegendElement(modeLegend(this.#mode, this.scene, this.camera))]));
  }

  /* ---------------- size and overlay ---------------- */

  /** On-screen pixels per traced pixel for the scale option on this page (see tracer-layout.js). */
  #screenScale() {
    return pictureScale(this.#scale, this.width, this.height, this.figure);
  }

  /** Sizes the picture on screen and the overlay to match it. */
  #layout() {
    if (this.#destroyed) return;
    sizePicture({ canvas: this.canvasElement, overlay: this.overlay, figure: this.figure }, this.width, this.height, this.#screenScale());
    this.#drawOverlay();
  }

  /** Grid, the pixel being traced and the selected pixel's crosshair, on the overlay only (see tracer-overlay.js). */
  #drawOverlay() {
    const current = this.#renderer.done || reducedMotion() ? null : this.#renderer.current;
    this.#shownCurrent = current && { ...current };
    drawOverlay(this.#overlayCtx, { width: this.width, height: this.height, grid: this.#grid, current, selected: this.#selected });
  }

  /* ---------------- DOM ---------------- */

  #buildDom(parent, label) {
    this.figure = element('figure', { class: 'rt-view', 'data-tracer-view': '' });
    if (label) this.figure.append(element('figcaption', { class: 'rt-label' }, label));

    const c = this.canvasElement = element('canvas', {
      class: 'rt-canvas', 'data-tracer': '', tabindex: '0',
      'aria-label': 'Traced picture: click a pixel, or use the arrow keys, to inspect it',
    });
    this.#words = createPictureWords(c, this); // role="img", described by what the scene shows
    c.style.imageRendering = 'pixelated'; // inline too: crisp pixels even before the stylesheet loads
    this.#ctx = c.getContext('2d');
    this.overlay = element('canvas', { class: 'rt-overlay', 'data-overlay': '', 'aria-hidden': 'true' });
    this.#overlayCtx = this.overlay.getContext('2d');
    const stage = element('div', { class: 'rt-stage' }, c, this.overlay);
    this.#words.stage(stage); // the application screen readers pass the keys to

    this.#progress = createTracerProgress();
    this.workerNote = this.#progress.note; // lib/p5/tracer/engines.js puts the engine's note before it
    this.legendHost = element('div', { class: 'rt-legend-host' });
    const save = createSaveButton(() => this.downloadPNG());

    this.figure.append(stage, element('div', { class: 'rt-bar' }, this.#progress.bar, save), this.workerNote, this.legendHost, this.#words.details, this.#words.description);
    parent.append(this.figure);
  }

  #notify() {
    this.#record = undefined; // a new selection, or the same pixel of a new scene: made again when asked
    this.#events.emit('select', this.selected, this);
  }
}
