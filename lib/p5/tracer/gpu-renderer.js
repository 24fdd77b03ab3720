/**
 * The tracer view's GPU engine: the renderer the view drives (as it drives
 * lib/tracing/workers/worker-frames.js's), but each step is a whole frame traced by
 * the GPU engine (lib/gpu/engine.js) and drawn onto the view's canvas: no
 * progressive passes, a whole new frame on the animation frame after every
 * change (of camera or scene), and nothing while nothing changes (a page
 * left open costs the GPU nothing). A step allocates nothing. Its `buffer` is read
 * back from the GPU only when asked (a click's inspector, a saved PNG), so
 * the frame loop waits for nothing.
 */
import { GpuTracer } from '../../gpu/engine.js';
import { Scene } from '../../scene/scene.js';
import { Camera } from '../../math/camera.js';
import { show } from '../../text/check.js';
import { renderPixel } from '../../tracing/render.js';

export class GpuRenderer {
  /** The engine's canvas and context are made here: an Error saying why when there is no WebGL2 or the scene cannot go to the GPU. */
  constructor({ scene, camera, order = 'coarse' }) {
    this.tracer = new GpuTracer(undefined, { preserveDrawingBuffer: true });
    this.order = order;
    this.scene = null;
    this.camera = null;
    this.restart({ scene, camera });
    /** Frames drawn, and the time they took, for the frames per second. */
    this.frames = 0;
    this.current = null;
    this.problem = null;
    this.engine = 'gpu';
  }

  get width() { return this.camera.width; }
  get height() { return this.camera.height; }
  /** A GPU frame is whole once drawn. */
  get done() { return this.#drawn; }
  get progress() { return this.#drawn ? 1 : 0; }
  /** Primary rays per second, from the time between the change and its frame (every pixel's samples). */
  get raysPerSecond() { return this.#rays; }
  /** Why the GPU cannot go on (the view then goes back to the CPU), or null. */
  get lost() {
    if (this.tracer.lost) return 'the GPU context was lost';
    return this.#shaded ? null : 'the GPU draws the shaded picture only';
  }

  #drawn = false; #rays = 0; #buffer = null; #stale = true; #last = 0; #shaded = true;

  /** A new scene or camera (or both): checked, then uploaded (the scene) for the next frame; another visual mode's shader: `lost`. */
  /** @param {{ scene?: any, camera?: any, shader?: any }} [options] */
  restart({ scene = this.scene, camera = this.camera, shader } = {}) {
    if (shader !== undefined) this.#shaded = shader === renderPixel;
    if (!(scene instanceof Scene)) throw new TypeError(`scene must be a Scene (new Scene(…)), got ${show(scene)}`);
    if (!(camera instanceof Camera)) throw new TypeError(`camera must be a Camera (new Camera({ width, height })), got ${show(camera)}`);
    if (scene !== this.scene) this.tracer.setScene(scene);
    this.scene = scene;
    this.camera = camera;
    this.#drawn = false;
    this.#last = performance.now();
  }

  /** One whole frame on the GPU (whatever the budget): changed and done. */
  step() {
    this.tracer.draw(this.camera);
    this.#drawn = true;
    this.#stale = true;
    this.frames++;
    const now = performance.now(), ms = now - this.#last; // the GPU works apart from the page: time from the change to its frame
    this.#rays = ms > 0 ? (this.width * this.height * this.camera.samples * 1000) / ms : 0;
    this.#last = now;
    return STEP;
  }

  /** Draws the last frame onto a 2D context (the view's canvas): GPU to GPU, no copy through the page. */
  blitTo(ctx) {
    if (this.#drawn) ctx.drawImage(this.tracer.canvas, 0, 0);
  }

  /** The last frame's RGBA bytes, read back from the GPU when they changed since the last read. */
  get buffer() {
    const n = this.width * this.height * 4;
    if (this.#buffer?.length !== n) { this.#buffer = new Uint8ClampedArray(n); this.#stale = true; }
    if (this.#stale && this.#drawn) { this.tracer.read(this.#buffer, this.width, this.height); this.#stale = false; }
    return this.#buffer;
  }

  terminate() {
    this.tracer.dispose();
  }
}

const STEP = Object.freeze({ changed: true, done: true });
