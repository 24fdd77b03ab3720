// Sketch 16's Cornell box (sketches/16-light-that-bounces.js builds the same
// scene in its own words, for the class to read), for the path tracers'
// tests and benchmarks (bench/paths.js, bench/browser/paths.js): white floor, ceiling, back and front walls, a red wall
// left, a green one right, a lamp under the ceiling, a tall block and a
// fuzzy mirror ball; the eye inside, at [0, 5, 3.7], looking down −z.
import { Scene, Plane, Box, Sphere, Camera } from '../../lib/index.js';

const WHITE = [0.73, 0.73, 0.73], RED = [0.65, 0.05, 0.05], GREEN = [0.12, 0.45, 0.15];

/** The box, its lamp giving off `lamp` (8: the path-traced picture's). */
export function cornellBox(lamp = 8) {
  const scene = new Scene({ background: [0, 0, 0], ambient: 0.05 });
  scene.add(new Plane([0, 0, 0], [0, 1, 0], { color: WHITE, name: 'floor' }));
  scene.add(new Plane([0, 10, 0], [0, -1, 0], { color: WHITE, name: 'ceiling' }));
  scene.add(new Plane([0, 0, -20], [0, 0, 1], { color: WHITE, name: 'back wall' }));
  scene.add(new Plane([0, 0, 5], [0, 0, -1], { color: WHITE, name: 'front wall' })); // behind the eye
  scene.add(new Plane([-5, 0, 0], [1, 0, 0], { color: RED, name: 'red wall' }));
  scene.add(new Plane([5, 0, 0], [-1, 0, 0], { color: GREEN, name: 'green wall' }));
  scene.add(new Box([-2.5, 9.8, -17], [2.5, 9.99, -12], { color: [0, 0, 0], emission: [lamp, lamp, 0.9 * lamp], name: 'lamp' }));
  scene.add(new Box([-3.6, 0, -18], [-0.8, 6, -15], { color: WHITE, name: 'tall block' }));
  scene.add(new Sphere([2.2, 1.8, -13], 1.8, { color: [0.9, 0.9, 0.9], reflection: 1, fuzz: 0.05, name: 'mirror ball' }));
  return scene;
}

/** Sketch 16's camera, at any size. */
export function cornellCamera(width = 64, height = 64) {
  return new Camera({ width, height, fov: 40, position: [0, 5, 3.7] });
}
