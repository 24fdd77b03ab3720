/**
 * The one-file build's entry (npm run build: dist/raytracing-sketchbook.js and
 * .mjs): the library and the p5 addon as one module. In the classic script
 * it is the global `RT`, and loading it registers the addon with the `p5`
 * that p5's own <script> defined, so a global-mode sketch calls
 * `createTracerView({ scene, camera })` bare and builds scenes with
 * `new RT.Scene()`, `new RT.Sphere(…)`, `RT.classScene()`.
 */
export * from './index.js';
export * from './p5/index.js';
