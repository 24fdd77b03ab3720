/**
 * Diagrams a sketch places next to its tracer view, each drawn into a p5
 * sketch `p` inside a box { x, y, w, h }, big and labelled for a projector:
 *
 *   drawSideView / drawTopView     the eye, the image plane, the spheres, the
 *                                  selected ray, its normal and shadow rays
 *   drawGeometricConstruction     L, tca, d, thc, r and t0, t1 for one sphere
 *   drawParabola                  f(t) = At² + Bt + C and its roots
 *   drawLegend, createLegendElement   the key of a visual mode
 *   focusTest                      which sphere a pixel's diagrams explain
 *   formatLabel                    a number as the diagrams print it (fmt: its old name)
 *
 * `record` is `inspectPixel(scene, camera, x, y)`'s result; without one the
 * diagrams draw the scene and ask for a click. Nothing here throws on a miss,
 * a tangent ray, a ray starting inside a sphere or a huge ground sphere.
 *
 * The code lives beside this file: plane-views.js and plane-marks.js (side and
 * top views), construction.js, parabola.js, legend.js, and the shared
 * style.js, draw.js, labels.js and focus.js; numbers are printed by lib/text/format.js.
 */
export { drawSideView, drawTopView } from './plane-views.js';
export { drawGeometricConstruction } from './construction.js';
export { drawParabola } from './parabola.js';
export { drawLegend, createLegendElement } from './legend.js';
export { focusTest } from './focus.js';
export { formatLabel, fmt } from '../../text/format.js';
