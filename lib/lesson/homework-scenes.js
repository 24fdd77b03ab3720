/**
 * The homework's scenes, everything but the lights the student adds (in
 * the library, so a page without Node, the p5 web editor's, has them too):
 *
 *   const scene = trafficSignalScene(); // Task 1: road, pole, housing, sun
 *   scene.add(new Sphere([0, 6.6, -16], 0.5, { color: [0, 0, 0], emission: [1, 0.1, 0.05] }));
 *   checkTrafficSignal(scene, trafficSignalCamera());
 *
 *   rearLightsScene(), rearLightsCamera() // Task 2: a car seen from behind
 */
import { Scene } from '../scene/scene.js';
import { Sphere } from '../shapes/sphere.js';
import { Box } from '../shapes/box.js';
import { Plane } from '../shapes/plane.js';
import { PointLight } from '../lights/point-light.js';
import { Camera } from '../math/camera.js';

const WIDTH = 160, HEIGHT = 120; // traced pixels of both tasks
const SKY = [0.62, 0.78, 0.95];
const ROAD = { color: [0.32, 0.33, 0.36], name: 'road' };

/**
 * Homework 1's street: a road, the signal's pole and its housing (x from
 * −0.8 to 0.8, y from 3.4 to 7.4, its front at z = −16.2), the sun; no lights:
 * the task is to add them.
 * @returns {Scene}
 * @example
 * const scene = trafficSignalScene(); // then three lights at x = 0, z = -16, red on top
 */
export function trafficSignalScene() {
  const scene = new Scene({ background: SKY, ambient: 0.2 });
  scene.add(new Plane([0, 0, 0], [0, 1, 0], ROAD));
  scene.add(new Box([-0.15, 0, -16.65], [0.15, 3.4, -16.35], { color: [0.35, 0.36, 0.38], name: 'pole' }));
  scene.add(new Box([-0.8, 3.4, -16.8], [0.8, 7.4, -16.2], { color: [0.15, 0.15, 0.16], name: 'housing' }));
  return scene.add(new PointLight([40, 200, 60], { intensity: 0.8, name: 'sun' }));
}

/**
 * Homework 1's camera: 160 × 120 pixels, at eye height, looking up at the signal.
 * @returns {Camera}
 * @example
 * checkTrafficSignal(trafficSignalScene(), trafficSignalCamera()).passed; // false: no lights yet
 */
export function trafficSignalCamera() {
  return new Camera({ width: WIDTH, height: HEIGHT, fov: 35, position: [0, 1.6, 0], pitch: 7 });
}

const PAINT = { color: [0.2, 0.42, 0.85], specular: 0.4 };
const TYRE = { color: [0.08, 0.08, 0.09] };

/**
 * Homework 2's road: a car seen from behind (body x from −1 to 1, y from 0.3
 * to 1, its back at z = −6.6; cabin, rear window, number plate, four wheels),
 * the sun; no rear lights: the task is to add them.
 * @returns {Scene}
 * @example
 * const scene = rearLightsScene(); // then two red lights at the same y, z = -6.5
 */
export function rearLightsScene() {
  const scene = new Scene({ background: SKY, ambient: 0.2 });
  scene.add(new Plane([0, 0, 0], [0, 1, 0], ROAD));
  scene.add(new Box([-1, 0.3, -10.6], [1, 1, -6.6], { ...PAINT, name: 'body' }));
  scene.add(new Box([-0.8, 1, -9.6], [0.8, 1.55, -7.3], { ...PAINT, name: 'cabin' }));
  scene.add(new Box([-0.65, 1.08, -7.32], [0.65, 1.48, -7.26], { color: [0.1, 0.12, 0.16], specular: 0.8, name: 'rear window' }));
  scene.add(new Box([-0.3, 0.42, -6.62], [0.3, 0.6, -6.56], { color: [0.95, 0.95, 0.9], name: 'number plate' }));
  for (const x of [-0.92, 0.92]) for (const z of [-7.3, -9.9]) scene.add(new Sphere([x, 0.33, z], 0.33, { ...TYRE, name: 'wheel' }));
  return scene.add(new PointLight([40, 120, 120], { intensity: 0.8, name: 'sun' }));
}

/**
 * Homework 2's camera: 160 × 120 pixels, behind the car, looking a little down.
 * @returns {Camera}
 * @example
 * const frame = render(rearLightsScene(), rearLightsCamera()); // 160 × 120 RGBA pixels
 */
export function rearLightsCamera() {
  return new Camera({ width: WIDTH, height: HEIGHT, position: [0, 1.4, 0], pitch: -5 });
}
