/**
 * Raytracing Sketchbook: the public API of the tracing library.
 * Pure ES modules, no p5; runs in Node, the browser and Web Workers.
 * (Everything else stays importable by its module path, for the kit's own code and tests.)
 */
// A scene: shapes with materials, lights, a background.
export { Scene } from './scene/scene.js';
export { Sphere, intersectQuadratic, intersectGeometric, EPSILON } from './shapes/sphere.js';
export { Plane } from './shapes/plane.js';
export { Box } from './shapes/box.js';
export { Cylinder } from './shapes/cylinder.js';
export { Cone } from './shapes/cone.js';
export { Triangle } from './shapes/triangle.js';
export { Mesh } from './shapes/mesh.js';
export { registerShape } from './shapes/index.js';
export { Material } from './shapes/material.js';
export { PointLight } from './lights/point-light.js';
export { AreaLight } from './lights/area-light.js';
export { SpotLight } from './lights/spot-light.js';
// Rays through pixels.
export { Ray } from './math/ray.js';
export { Camera } from './math/camera.js';
// Pictures, and the story of one pixel.
export { render } from './tracing/render.js';
export { renderGPU } from './gpu/render-gpu.js';
export { pathTraceGPU } from './gpu/path-trace-gpu.js';
export { inspectPixel } from './lesson/inspect.js';
export { ProgressiveRenderer } from './tracing/frames.js';
export { ParallelRenderer } from './tracing/workers/parallel.js';
// Light that bounces: pictures as the average of random paths, and the story of one path.
export { pathTrace } from './tracing/pathtrace/path-trace.js';
export { inspectPath } from './tracing/pathtrace/inspect-path.js';
// Colours as the lesson names them.
export { toColor, toHex, colorName } from './math/color.js';
// The class's example scene; scenes as JSON and as code.
export { classScene, classSceneAt } from './scene/examples.js';
export { sceneToJSON, sceneFromJSON, sceneToCode, sceneCodeLines } from './scene/json.js';
export { joinInSlices, nextTask } from './text/slices.js';
// The class activity and the homework self-checks.
export { pinkPixelVerdict, answerText, readAnswerLine } from './lesson/activity.js';
export { checkTrafficSignal, checkRearLights, solutionParameter } from './lesson/homework.js';
export { trafficSignalScene, trafficSignalCamera, rearLightsScene, rearLightsCamera } from './lesson/homework-scenes.js';
