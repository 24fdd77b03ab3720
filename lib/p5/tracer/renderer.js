/**
 * The renderer behind a tracer view, chosen from its options: a path tracer
 * whose samples grow (`path` given), or the Whitted tracer's progressive
 * frames, large shaded ones on Web Workers. The checks of the options that
 * choose it live here too, so a bad one is refused before anything changes.
 */
import { ORDERS } from '../../tracing/frames.js';
import { WorkerProgressiveRenderer } from '../../tracing/workers/worker-frames.js';
import { PathProgressiveRenderer } from '../../tracing/pathtrace/progressive.js';
import { modeShader } from '../../tracing/modes.js';
import { show } from '../../text/check.js';

/**
 * @param {{ scene: any, camera: any, mode: string, order?: string, renderMode?: string, path?: object, budgetMs: number, workers: any }} options
 *   as createTracerView's; the renderer checks the scene and camera, modeShader the visual mode
 * @returns {any} a PathProgressiveRenderer or a WorkerProgressiveRenderer
 */
export function viewRenderer({ scene, camera, mode, order, renderMode, path, budgetMs, workers }) {
  if (order !== undefined && renderMode !== undefined) throw new TypeError('createTracerView takes order or renderMode (its old name), not both');
  if (path !== undefined) {
    if (mode !== 'shaded' || order !== undefined || renderMode !== undefined) throw new TypeError('a path-traced view (path) shows the shaded picture, sample after sample: no mode or order');
    return new PathProgressiveRenderer({ scene, camera, path, budgetMs });
  }
  const checked = checkOrder(order ?? renderMode ?? 'coarse', renderMode === undefined ? 'order' : 'renderMode');
  return new WorkerProgressiveRenderer({ scene, camera, order: checked, budgetMs, shader: modeShader(mode), workers });
}

/** True when the view's renderer path traces, on the CPU or the GPU (setPath and pathState ask). */
export const pathTraced = (renderer) => renderer.pathTraced === true;

/** A render order ('coarse', 'scanline', 'slow'), checked before anything changes. */
export function checkOrder(order, field = 'order') {
  if (!ORDERS.includes(order)) throw new RangeError(`${field} must be one of ${ORDERS.map((m) => `'${m}'`).join(', ')}, got ${show(order)}`);
  return order;
}

/** The milliseconds of tracing a view may spend in one animation frame. */
export function checkBudget(ms) {
  if (typeof ms !== 'number' || !Number.isFinite(ms) || ms <= 0) {
    throw new RangeError(`budgetMs must be a number of milliseconds greater than 0, got ${show(ms)}`);
  }
  return ms;
}
