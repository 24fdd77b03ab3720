/**
 * The sketchbook as a p5 addon (2.x; on 1.x register.js puts it on
 * p5.prototype): every factory of the p5 adapter becomes a method of p5,
 * taking one options object, so a sketch writes
 *
 *   p.createTracerView({ scene, camera })   // instance mode
 *   createTracerView({ scene, camera })     // global mode (function setup() {…})
 *
 * Each factory module exports `createX(p, options)`; this table is the one
 * place they become methods. A new factory is one more line here.
 */
import { createTracerView } from './tracer/view.js';
import { createSceneView } from './scene-view/view.js';
import { createPhotonView } from './tracer/photon-view.js';
import { createInspector } from './pixel/inspector.js';
import { createAnswerForm } from './controls/answer-form.js';
import { createPixelMarks, createPixelHighlight } from './pixel/marks.js';
import { createSliderField } from './controls/slider-field.js';
import { createSwitches } from './controls/switches.js';
import { createExamplePicker } from './controls/example-picker.js';
import { createAnimation } from './controls/animation.js';
import { createSceneForm } from './controls/scene-form.js';
import { createHomeworkCheck } from './controls/homework-check.js';
import { createTaskList } from './controls/task-list.js';
import { createSampleRays } from './pixel/sample-rays.js';
import { createBvhView } from './pixel/bvh-view.js';
import { createPathPanel } from './pixel/path-panel.js';
import { drawSideView, drawTopView } from './diagrams/plane-views.js';
import { drawGeometricConstruction } from './diagrams/construction.js';
import { drawParabola } from './diagrams/parabola.js';
import { drawLegend } from './diagrams/legend.js';
import { show } from '../text/check.js';

/**
 * `name: (p, options) => part`: what each p5 method makes.
 * @type {Record<string, (p: import('p5').default, options: object) => any>}
 */
export const FACTORIES = {
  createTracerView,
  createSceneView,
  createPhotonView,
  createInspector,
  createAnswerForm,
  createPixelMarks,
  createPixelHighlight,
  createSliderField,
  createSwitches,
  createExamplePicker,
  createAnimation,
  createSceneForm,
  createHomeworkCheck,
  createTaskList,
  createSampleRays,
  createBvhView,
  createPathPanel,
  // Diagrams draw into the sketch's own canvas, inside the box { x, y, w, h }.
  drawSideView,
  drawTopView,
  drawGeometricConstruction,
  drawParabola,
  /**
   * A visual mode's legend drawn into the sketch's canvas: its title, colour bar and note.
   * @param {import('p5').default} p the sketch
   * @param {object} options
   * @param {object} options.legend what to draw, `{ title, stops, note }` (lib/tracing/modes.js's modeLegend makes one per visual mode)
   * @param {number} options.x the box it is drawn in: left
   * @param {number} options.y top
   * @param {number} options.w width
   * @param {number} options.h height
   * @example
   * p.drawLegend({ legend, x: 0, y: 0, w: 300, h: 90 }); // under the diagram it explains
   */
  drawLegend: (p, { legend, x, y, w, h }) => drawLegend(p, legend, { x, y, w, h }),
};

/** Every part with a `destroy()` made by each p5 instance, so `p.remove()` ends them too. */
const partsOf = new WeakMap();

/**
 * The addon (`p5.registerAddon(sketchbookAddon)` on 2.x; lib/p5/index.js does it, through register.js).
 * @param {typeof import('p5').default & { disableSketchChecker?: boolean }} p5Class
 * @param {object} fn p5's prototype
 * @param {object} lifecycles p5's lifecycle hooks
 * @example
 * import p5 from 'p5';
 * import { sketchbookAddon } from 'raytracing-sketchbook/p5'; // importing it already does this:
 * p5.registerAddon(sketchbookAddon);
 */
export function sketchbookAddon(p5Class, fn, lifecycles) {
  // p5's sketch checker fetches the page's last script and parses it before
  // setup(): in a production build that script is the whole bundle, a
  // one-second freeze in the middle of the first render. It looks for
  // global-mode name clashes, which the kit's own names never make.
  p5Class.disableSketchChecker = true;

  for (const [name, make] of Object.entries(FACTORIES)) {
    fn[name] = function (options = {}) {
      if (options === null || typeof options !== 'object' || Array.isArray(options)) {
        throw new TypeError(`${name} takes one options object, e.g. ${name}({ … }), got ${show(options)}`);
      }
      const part = make(this, options);
      if (typeof part?.destroy === 'function') partsOf.set(this, [...(partsOf.get(this) ?? []), part]);
      return part;
    };
  }

  lifecycles.remove = function () {
    for (const part of partsOf.get(this) ?? []) part.destroy();
    partsOf.delete(this);
  };
}
