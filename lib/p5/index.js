/**
 * The p5 adapter of the Raytracing Sketchbook: a tracer view for sketches,
 * the inspector panel that explains the selected pixel, and the page contract
 * (`document.body.dataset.render`). The only part of lib/ that imports p5.
 */
export { createTracerView, TracerView, pixelAt } from './tracer-view.js';
// The scene in 3D beside a tracer view: eye, image plane, frustum and the selected pixel's rays:
export { createSceneView, SceneView } from './scene-view.js';
export { createInspector, Inspector, answerLine, formatNumber, formatVector, formatAngle, pixelCSV, routesAgree } from './inspector.js';
export { registerView, pageRenderState } from './page-state.js';
// Diagrams (side/top view, geometric construction, parabola) and legends:
export { drawSideView, drawTopView, drawGeometricConstruction, drawParabola, drawLegend, createLegendElement, focusTest } from './diagrams.js';
// An animation in a tracer view (main thread or Web Workers) with an FPS counter:
export { Animation, FrameCounter, framesPerSecond, statsLine, readWorkerCount, sameBytes, blit, workerCountBox } from './animation.js';
// An activity's answer form (checked boxes, Check, ✔/✘, the answer line) and marks over chosen pixels:
export { createAnswerForm, readBoxes } from './answer-form.js';
export { createPixelMarks, createPixelHighlight, findPixels } from './pixel-marks.js';
// Controls a sketch builds its page from: slider fields, a panel of switches, a picker of examples:
export { createSliderField, fieldMessage } from './slider-field.js';
export { createSwitches } from './switches.js';
export { createExamplePicker, exampleInLink } from './example-picker.js';
import './live-coding.js'; // mistakes shown on the page (data-error); a save's reload keeps the page's place
