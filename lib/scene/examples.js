/**
 * Ready-made scenes for sketches, tests and the benchmark.
 */
import { Scene } from './scene.js';
import { Sphere } from '../shapes/sphere.js';
import { finiteNumber } from '../text/check.js';

/**
 * The class's example scene, from the original JavaScript library: a huge
 * grey ground sphere, four coloured spheres (the big one is the PINK one of
 * the activity) and two emissive spheres as lights, on a white background.
 * Options: `full` adds the original's mirror and glass (reflection,
 * transparency) for the full-shading benchmark.
 * @example
 * const scene = classScene();                   // the spheres of the class's example
 * const shiny = classScene({ full: true });     // with its mirrors and glass
 */
export function classScene({ full = false } = {}) {
  const scene = new Scene({ background: [2, 2, 2] });
  scene.add(new Sphere([0, -10004, -20], 10000, { color: [0.2, 0.2, 0.2], name: 'ground' }));
  scene.add(new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36], ...(full && { reflection: 0.5, transparency: 0.5 }), name: 'pink' }));
  scene.add(new Sphere([5, -1, -15], 2, { color: [0.9, 0.76, 0.46], ...(full && { reflection: 0.5 }), name: 'yellow' }));
  scene.add(new Sphere([5, 0, -25], 3, { color: [0.65, 0.77, 0.97], ...(full && { reflection: 0.5 }), name: 'blue' }));
  scene.add(new Sphere([-5.5, 0, -15], 3, { color: [0.9, 0.9, 0.9], ...(full && { reflection: 0.5, specular: 0.5 }), name: 'white' }));
  scene.add(new Sphere([0, 20, -30], 3, { color: [0, 0, 0], emission: 1.2, name: 'light 1' }));
  scene.add(new Sphere([0, 10, 10], 3, { color: [0, 0, 0], emission: 1, name: 'light 2' }));
  return scene;
}

/**
 * The class scene `t` seconds into the original animated example: the yellow,
 * blue and white spheres circle the pink one (about its vertical axis), once
 * every `secondsPerTurn` seconds; the rest stays put.
 * @example
 * const frame = render(classSceneAt(1.5), new Camera({ width: 64, height: 48 })); // 1.5 s into the animation
 */
export function classSceneAt(t, secondsPerTurn = 12) {
  finiteNumber(t, 't');
  if (finiteNumber(secondsPerTurn, 'secondsPerTurn') <= 0) throw new RangeError(`secondsPerTurn must be greater than 0, got ${secondsPerTurn}`);
  const scene = classScene();
  const pink = scene.objects.find((o) => o.name === 'pink').center;
  const angle = (2 * Math.PI * t) / secondsPerTurn, turnX = Math.cos(angle), turnZ = Math.sin(angle);
  for (const name of ['yellow', 'blue', 'white']) {
    const c = scene.objects.find((o) => o.name === name).center;
    const x = c.x - pink.x, z = c.z - pink.z;
    c.x = pink.x + x * turnX - z * turnZ;
    c.z = pink.z + x * turnZ + z * turnX;
  }
  return scene;
}
