/**
 * An animation in a tracer view: each frame of `sceneAt(t)` traced whole,
 * either on the page's own thread (the view's renderer) or shared out over Web
 * Workers (ParallelRenderer: the page only copies the finished frame onto the
 * view's canvas), with a frame and FPS counter. On the workers the frames are
 * pipelined: while draw() shows frame n, the workers already trace frame n+1
 * (the moment of the next draw()), up to PIPELINE frames under way. While it
 * plays the page says `data-render="rendering"`; paused, once the last frame
 * is on screen, "done", and a click on a pixel explains that frame.
 *
 *   const movie = new SceneAnimation(view, { sceneAt, camera, stats: element });
 *   movie.start('main');                      // or 'workers'; movie.stop() hands the view back
 *   p.draw = () => movie.tick(p.deltaTime);
 *
 * The pure parts (framesPerSecond, FrameCounter, statsLine, readWorkerCount,
 * sameBytes) need no page.
 */
import { registerView } from '../page/page-state.js';
import { element } from '../dom.js';
import { ParallelRenderer } from '../../tracing/workers/parallel.js';
import { checkOptions } from '../../text/check.js';

/** Frames under way on the workers at most: one shown while the next ones are traced. */
export const PIPELINE = 2;

/** Frames per second from the times (ms) frames reached the screen: 0 with fewer than two. */
export function framesPerSecond(stamps) {
  const span = stamps.length > 1 ? stamps.at(-1) - stamps[0] : 0;
  return span > 0 ? ((stamps.length - 1) * 1000) / span : 0;
}

/** Counts frames, and keeps the last second of them for the FPS. */
export class FrameCounter {
  frames = 0;
  stamps = [];

  /** One more frame on screen at `now` (ms). */
  tick(now = performance.now()) {
    this.frames++;
    this.stamps = [...this.stamps.filter((s) => now - s < 1000), now];
  }

  get fps() {
    return framesPerSecond(this.stamps);
  }

  reset() {
    this.frames = 0;
    this.stamps = [];
  }
}

/** `frame 12 · 9.5 FPS · t = 1.25 s · 4 workers` (`workers` 0 or absent: "main thread"). */
export function statsLine({ frame, fps, time, workers = 0 }) {
  const by = workers > 0 ? `${workers} worker${workers > 1 ? 's' : ''}` : 'main thread';
  return `frame ${frame} · ${fps.toFixed(1)} FPS · t = ${time.toFixed(2)} s · ${by}`;
}

/** The worker count typed in a box, a whole number in min…max, else a RangeError saying so. */
export function readWorkerCount(typed, { min = 1, max = 8 } = {}) {
  const text = String(typed).trim(), n = Number(text);
  if (text === '' || !Number.isInteger(n) || n < min || n > max) {
    throw new RangeError(`workers must be a whole number from ${min} to ${max}, got ${text ? `"${text}"` : 'nothing'}`);
  }
  return n;
}

/** True when two pixel buffers hold the same bytes. */
export function sameBytes(a, b) {
  return a.length === b.length && a.every((byte, i) => byte === b[i]);
}

/** Copies an RGBA buffer of width × height onto a canvas. */
export function blit(canvas, buffer, width, height) {
  canvas.getContext('2d').putImageData(new ImageData(buffer, width, height), 0, 0);
}

/**
 * An animation shown in a tracer view: `p.createAnimation({ view, sceneAt, camera })`;
 * the other options as for the SceneAnimation class below.
 * @param {import('p5').default} p the sketch
 * @param {object} options
 * @param {import('../tracer/view.js').TracerView} options.view where the frames are shown
 * @returns {SceneAnimation}
 * @example
 * const view = p.createTracerView({ scene: classSceneAt(0), camera: new Camera({ width: 160, height: 120 }) });
 * const animation = p.createAnimation({ view, sceneAt: classSceneAt, camera: view.camera, workers: 2 });
 * animation.start('workers'); // or 'main': the frames traced on the page's own thread
 */
export function createAnimation(p, options) { // no options: checkOptions gives {}
  const { view, ...rest } = checkOptions(options, ['view', 'sceneAt', 'camera', 'workers', 'stats', 'onPlay', 'onPause', 'onError'], 'createAnimation');
  return new SceneAnimation(view, rest);
}

/**
 * An animation in a tracer view, what `p.createAnimation({ view, sceneAt, camera })` returns: the class's animated examples, with an FPS line.
 * @example
 * const animation = p.createAnimation({ view, sceneAt: (t) => classSceneAt(t), camera: view.camera });
 * animation.start('main');
 * animation.play(false); // pause: click a pixel of the frame on screen
 */
export class SceneAnimation {
  #page;
  #parallel = null;
  /** Frames posted to the workers and not yet back; the newest one back, `{ buffer, t }`, not yet shown. */
  #inFlight = 0;
  #arrived = null;
  /** The workers' frame on screen. */
  #workerFrame = null;
  /** Bumped by start() and stop(): frames of an earlier run are dropped. */
  #run = 0;

  /**
   * @param {import('../tracer/view.js').TracerView} view where the frames are shown
   * @param {object} options
   * @param {(t: number) => import('../../scene/scene.js').Scene} options.sceneAt the scene t seconds in
   * @param {import('../../math/camera.js').Camera} options.camera the camera of every frame
   * @param {number} [options.workers=4] how many workers share a frame on 'workers'
   * @param {{ elt?: HTMLElement }|HTMLElement} [options.stats] gets the stats line and data-frame, data-fps, data-time
   * @param {(playing: boolean) => void} [options.onPlay] after Play / Pause
   * @param {(info: { thread: string, same?: boolean }) => void} [options.onPause] paused with a frame on screen;
   *   on 'workers', `same` says whether one thread traces that frame byte for byte the same
   * @param {(error: Error) => void} [options.onError] the workers failed: the frames go on, traced on the
   *   page's own thread (the same bytes), and this says why; a frame that cannot be traced at all pauses the animation
   */
  constructor(view, { sceneAt, camera, workers = 4, stats, onPlay, onPause, onError } = /** @type {any} */ ({})) {
    this.view = view;
    this.sceneAt = sceneAt;
    this.camera = camera;
    this.workers = workers;
    this.onPlay = onPlay;
    this.onPause = onPause;
    this.onError = onError;
    /** @type {HTMLElement|null} where the stats line goes (a p5.Element's element, or the element) */
    this.stats = /** @type {any} */ (stats)?.elt ?? stats ?? null;
    this.thread = null;   // 'main', 'workers', or null when the view is the sketch's
    this.playing = false;
    this.time = 0;        // the animation clock, seconds
    this.shown = 0;       // the time of the frame on screen
    this.counter = new FrameCounter();
    this.#page = registerView(this);
    this.#page.done(); // not playing yet
  }

  /** Plays the animation, each frame traced on 'main' (this thread) or on 'workers'. */
  start(thread) {
    this.thread = thread;
    this.#reset();
    this.view.setCamera(this.camera);
    this.traceHere(this.time);
    this.play(true);
  }

  /** Stops the animation: the view is the sketch's again. */
  stop() {
    this.thread = null;
    this.#reset();
    this.play(false);
  }

  play(on) {
    this.playing = on;
    this.onPlay?.(on);
    if (on) this.#page.rendering();
    else if (this.#inFlight === 0) {
      if (this.#arrived) this.#showWorkerFrame();
      this.#paused();
    }
  }

  /**
   * Call from draw(): moves the clock on `ms` and shows the next frame. On
   * 'main' it is traced now; on 'workers' it is the newest frame back from
   * them, and the frame for the next draw() (`ms` on) is posted to them.
   */
  tick(ms) {
    if (!this.playing) return;
    this.time += ms / 1000;
    if (this.thread === 'main') {
      this.traceHere(this.time);
      this.#counted(this.time);
      return;
    }
    if (this.#arrived) this.#showWorkerFrame();
    if (this.#inFlight < PIPELINE) this.#traceOnWorkers(this.time + ms / 1000);
  }

  /** Traces the frame of time t whole, now, on this thread (the view's own renderer). */
  traceHere(t) {
    this.view.budgetMs = 60_000; // no slicing: the whole frame in one go
    this.view.setScene(this.sceneAt(t));
    this.view.draw();
    this.shown = t;
  }

  /** Posts the frame of time t to the workers; it is shown by the first draw() after it is back. */
  async #traceOnWorkers(t) {
    if (this.#parallel?.workers !== this.workers) {
      if (this.#inFlight > 0) return; // a new worker count waits for the frames under way
      this.#parallel?.terminate();
      // A worker that fails or stays silent: its frames go on, traced here, and the page says why.
      this.#parallel = new ParallelRenderer({ workers: this.workers, onProblem: (error) => this.onError?.(error) }).warm();
    }
    const run = this.#run;
    this.#inFlight++;
    try {
      const buffer = await this.#parallel.render(this.sceneAt(t), this.camera);
      if (run === this.#run && t >= (this.#arrived?.t ?? -Infinity)) this.#arrived = { buffer, t };
    } catch (error) {
      if (run === this.#run) {
        this.onError?.(error);
        this.play(false);
      }
    } finally {
      this.#inFlight--;
      if (!this.playing && this.#inFlight === 0) { // paused while frames were under way: the last one back stays
        if (this.#arrived) this.#showWorkerFrame();
        this.#paused();
      }
    }
  }

  #showWorkerFrame() {
    const { buffer, t } = this.#arrived;
    this.#arrived = null;
    this.#workerFrame = buffer;
    this.#blit(buffer);
    this.#counted(t);
  }

  /** The frame on screen is final: let the inspector explain it, and the page say "done". */
  #paused() {
    if (this.thread === 'workers' && this.#workerFrame) {
      this.traceHere(this.shown); // the same frame on one thread, so the inspector knows its scene…
      const same = sameBytes(this.#workerFrame, this.view.buffer);
      this.#blit(this.#workerFrame); // …but what stays on screen is the workers' picture
      this.onPause?.({ thread: 'workers', same });
    } else if (this.thread === 'main') {
      this.onPause?.({ thread: 'main' });
    }
    this.#showStats();
    this.#page.done();
  }

  #blit(buffer) {
    blit(this.view.canvas, buffer, this.camera.width, this.camera.height);
  }

  #reset() {
    this.counter.reset();
    this.#workerFrame = null;
    this.#arrived = null;
    this.#run++;
  }

  /** One more frame on screen, made for time t: count it for the FPS. */
  #counted(t) {
    this.shown = t;
    this.counter.tick();
    this.#showStats();
  }

  #showStats() {
    if (!this.stats) return;
    const { frames: frame, fps } = this.counter;
    this.stats.textContent = statsLine({ frame, fps, time: this.shown, workers: this.thread === 'workers' && this.#parallel?.usingWorkers !== false ? this.workers : 0 });
    Object.assign(this.stats.dataset, { frame, fps: fps.toFixed(1), time: this.shown });
  }
}

/**
 * A "workers (1–8)" number box for an animation, and a message for when what
 * is typed is not a worker count (the count then stays as it was).
 * @returns {{ label: HTMLElement, message: HTMLElement }} the labelled box, the message
 */
export function workerCountBox(animation, { min = 1, max = 8 } = {}) {
  const input = element('input', { type: 'number', min, max });
  input.value = String(animation.workers);
  const label = element('label', {}, `workers (${min}–${max}) `, input);
  const message = element('span', { class: 'error', role: 'alert', 'data-message': 'workers' });
  input.addEventListener('change', () => {
    try {
      animation.workers = readWorkerCount(input.value, { min, max });
      message.textContent = '';
    } catch (error) {
      message.textContent = `${error.message}; still using ${animation.workers}.`;
    }
  });
  return { label, message };
}
