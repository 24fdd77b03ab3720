/**
 * The record of a selected pixel, for a tracer view's listeners: the view's
 * own `record` (lib/lesson/inspect.js inspectPixel, made once per selection and
 * scene however many panels follow the view), or, for a pixel the view has
 * not selected, one made here.
 */
import { inspectPixel } from '../../lesson/inspect.js';

/**
 * @param {{ scene: object, camera: object, selected?: { x: number, y: number }|null, record?: object|null }} view
 * @param {{ x: number, y: number }} pixel
 */
export function recordOf(view, pixel) {
  const s = view.selected;
  if (s && s.x === pixel.x && s.y === pixel.y && 'record' in view) return view.record;
  return inspectPixel(view.scene, view.camera, pixel.x, pixel.y);
}
