/**
 * Raytracing Sketchbook: the public API of the tracing library.
 * Pure ES modules; runs in Node, the browser and Web Workers.
 */
export { Ray } from './ray.js';
export { Camera, angles } from './camera.js';
export { Scene } from './scene.js';
export { Material } from './material.js';
export { PointLight } from './lights.js';
export { Sphere, intersectQuadratic, intersectGeometric, EPSILON } from './shapes/sphere.js';
export { Plane } from './shapes/plane.js';
export { Box } from './shapes/box.js';
export { trace, nearestHit } from './trace.js';
export { render, renderPixel, writePixel } from './render.js';
export { inspectPixel } from './explain.js';
export { toColor, toHex, colorToHex, colorName } from './color.js';
export { classScene, classSceneAt } from './scenes.js';
export * as vec3 from './vec3.js';
export { ProgressiveRenderer } from './progressive.js';
export { sceneToJSON, sceneFromJSON, cameraToJSON, cameraFromJSON, sceneToCode } from './serialize.js';
export { MODES, modeShader, modeLegend, discriminantColor, angleColor } from './modes.js';
export { ParallelRenderer } from './workers/parallel.js';
export { checkTrafficSignal, checkRearLights } from './homework.js';
export { pinkPixelVerdict, answerText, readAnswerLine } from './activity.js';
