/** A small room for the path tracer's tests: a floor, a red box, a mirror ball with fuzz, a glass ball, a lamp. */
import { Camera, Scene, Sphere, Plane, Box } from '../../lib/index.js';

export function room() {
  const scene = new Scene({ background: [0.2, 0.25, 0.35] })
    .add(new Plane([0, -2, 0], [0, 1, 0], { color: [0.75, 0.75, 0.7] }))
    .add(new Box([-4, -2, -14], [-1.5, 1, -11], { color: [0.8, 0.2, 0.2] }))
    .add(new Sphere([1.5, -1, -11], 1, { color: [0.9, 0.9, 0.9], reflection: 1, fuzz: 0.2 }))
    .add(new Sphere([3.5, -1, -12], 1, { transparency: 1, ior: 1.5 }))
    .add(new Sphere([0, 5, -12], 1.5, { color: [0, 0, 0], emission: [4, 4, 3.6] }));
  return { scene, camera: new Camera({ width: 24, height: 18, fov: 40, position: [0, 1, 0], pitch: -5 }) };
}
