/**
 * Raytracing Sketchbook: the public API of the tracing library.
 * Pure ES modules, no p5; runs in Node, the browser and Web Workers.
 * (Everything else stays importable by its module path, for the kit's own code and tests.)
 */
// A scene: shapes with materials, lights, a background.
export { Scene } from './scene.js';
export { Sphere, intersectQuadratic, intersectGeometric, EPSILON } from './shapes/sphere.js';
export { Plane } from './shapes/plane.js';
export { Box } from './shapes/box.js';
export { Cylinder } from './shapes/cylinder.js';
export { Cone } from './shapes/cone.js';
export { Triangle } from './shapes/triangle.js';
export { Mesh } from './shapes/mesh.js';
export { registerShape } from './shapes/index.js';
export { Material } from './material.js';
export { PointLight } from './lights.js';
export { AreaLight } from './area-light.js';
export { SpotLight } from './spot-light.js';
// Rays through pixels.
export { Ray } from './ray.js';
export { Camera } from './camera.js';
// Pictures, and the story of one pixel.
export { render } from './render.js';
export { renderGPU } from './gpu/render-gpu.js';
export { inspectPixel } from './explain.js';
export { ProgressiveRenderer } from './progressive.js';
export { ParallelRenderer } from './workers/parallel.js';
// Light that bounces: pictures as the average of random paths, and the story of one path.
export { pathTrace } from './pathtrace/path-trace.js';
export { inspectPath } from './pathtrace/inspect-path.js';
// Colours as the lesson names them.
export { toColor, toHex, colorName } from './color.js';
// The class's example scene; scenes as JSON and as code.
export { classScene, classSceneAt } from './scenes.js';
export { sceneToJSON, sceneFromJSON, sceneToCode, sceneCodeLines } from './serialize.js';
export { joinInSlices, nextTask } from './slices.js';
// The class activity and the homework self-checks.
export { pinkPixelVerdict, answerText, readAnswerLine } from './activity.js';
export { checkTrafficSignal, checkRearLights, solutionParameter } from './homework.js';
export { trafficSignalScene, trafficSignalCamera, rearLightsScene, rearLightsCamera } from './homework-scenes.js';
