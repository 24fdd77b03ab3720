/**
 * The tracer view's two engines: the CPU's progressive renderer (on Web
 * Workers for large frames) and the GPU's whole frames (lib/p5/tracer/gpu-renderer.js).
 * A path-traced view goes to the GPU's path tracer (lib/p5/tracer/gpu-path-renderer.js)
 * and back, with its path options. Switching keeps the scene, the camera and the order; when the GPU cannot
 * take the picture (no WebGL2, a lost context, a shape it cannot draw, a
 * visual mode other than the shaded picture, set before or after) the view
 * stays on, or goes back to, the CPU, and a line under the picture says why.
 */
import { WorkerProgressiveRenderer } from '../../tracing/workers/worker-frames.js';
import { GpuRenderer } from './gpu-renderer.js';
import { GpuPathRenderer } from './gpu-path-renderer.js';
import { PathProgressiveRenderer } from '../../tracing/pathtrace/progressive.js';
import { element } from '../dom.js';
import { show } from '../../text/check.js';

const ENGINES = ['cpu', 'gpu'];

/** `engine` checked: 'cpu' or 'gpu'. */
export function checkEngine(engine) {
  if (!ENGINES.includes(engine)) throw new TypeError(`engine must be 'cpu' or 'gpu', got ${show(engine)}`);
  return engine;
}

/**
 * The renderer for `engine`, carrying on from `current` (the same renderer
 * when it is already that engine's), the engine it is, and why it is not
 * the one asked for (null when it is).
 */
export function engineRenderer(engine, current, { budgetMs, shader, shaded }) {
  const { scene, camera, order } = current;
  const onGpu = current.engine === 'gpu', path = current.pathTraced ? current.options : null;
  let why = onGpu ? current.lost : null; // the GPU cannot go on: its context lost, or a visual mode
  if (engine === 'gpu' && !why) {
    if (onGpu) return { renderer: current, engine, why: null };
    if (!path && !shaded) why = 'the GPU draws the shaded picture only';
    else {
      try {
        const renderer = path ? new GpuPathRenderer({ scene, camera, path, budgetMs }) : new GpuRenderer({ scene, camera, order });
        return { renderer, engine, why: null };
      } catch (error) {
        why = error.message;
      }
    }
  }
  if (!onGpu) return { renderer: current, engine: 'cpu', why };
  if (path) return { renderer: new PathProgressiveRenderer({ scene, camera, path, budgetMs }), engine: 'cpu', why };
  return { renderer: new WorkerProgressiveRenderer({ scene, camera, order, budgetMs, shader }), engine: 'cpu', why };
}

/** The canvas's data-engine, and the line saying why the GPU was not taken (hidden when nothing went wrong). */
export function showEngine(view, engine, why) {
  view.canvasElement.dataset.engine = engine;
  view.figure.dataset.engine = engine;
  if (!view.engineNote) {
    view.engineNote = element('p', { class: 'rt-note rt-view-note', 'data-message': 'view-engine', role: 'status', hidden: true });
    view.workerNote.before(view.engineNote);
  }
  view.engineNote.hidden = !why;
  view.engineNote.textContent = why ? `Traced on the CPU: ${why}.` : '';
}

/**
 * For the inspector: where the GPU's pixel differs from the record's colour
 * (inspectPixel's, float64, the CPU's), a line saying by how much; none on
 * the CPU engine or when they agree. The GPU traces in float32, so a pixel
 * may differ by a unit or two, and on a grazing edge by more.
 * @returns {HTMLElement[]}
 */
export function gpuDifference(view, record) {
  if (view.engine !== 'gpu' || view.pathState) return []; // a path-traced pixel is a mean of random paths, not the record's colour
  const i = (record.y * view.width + record.x) * 4, gpu = view.buffer;
  const delta = [0, 1, 2].map((c) => gpu[i + c] - record.color[c]);
  if (delta.every((d) => d === 0)) return [element('p', { class: 'rt-note', 'data-gpu-difference': '0' }, 'The GPU drew this pixel with the same bytes.')];
  const most = Math.max(...delta.map(Math.abs));
  return [element('p', { class: 'rt-note', 'data-gpu-difference': String(most) },
    `The GPU drew rgb(${[0, 1, 2].map((c) => gpu[i + c]).join(', ')}) here: ${delta.map((d) => (d > 0 ? `+${d}` : String(d))).join(', ')} from the record's colour (float32 on the GPU, float64 here).`)];
}
