// A floor, a ball over it and a disc of light above: the ball hides part of
// the disc from the floor round its shadow (the penumbra). The tests count the
// shadow rays that reach the disc themselves, with the sphere's own formula,
// to check what the record says.
import { Scene, Sphere, Plane, Camera, inspectPixel } from '../../lib/index.js';
import { AreaLight } from '../../lib/lights/area-light.js';

export const BALL = { center: [0, 0, -20], radius: 3 };

export function penumbraScene({ samples = 16 } = {}) {
  const lamp = new AreaLight([-6, 14, -14], 4, { samples, name: 'lamp' });
  const scene = new Scene({ background: [0.8, 0.9, 1], ambient: 0.1 })
    .add(new Plane([0, -4, 0], [0, 1, 0], { color: [0.9, 0.9, 0.9] }))
    .add(new Sphere(BALL.center, BALL.radius, { color: [1, 0.32, 0.36] }))
    .add(lamp);
  return { scene, lamp };
}

export const penumbraCamera = (samples = 1) => new Camera({ width: 48, height: 36, position: [0, 6, 8], pitch: -25, samples });

/** How many of the lamp's points a floor point sees past the ball: our own shadow rays. */
export function pointsSeen(point, normal, lamp, bias) {
  const o = [point.x + normal.x * bias, point.y + normal.y * bias, point.z + normal.z * bias];
  let seen = 0;
  for (const p of lamp.points()) {
    const d = [p.x - o[0], p.y - o[1], p.z - o[2]], dist = Math.hypot(...d);
    const u = d.map((c) => c / dist), L = BALL.center.map((c, i) => o[i] - c);
    const B = 2 * (u[0] * L[0] + u[1] * L[1] + u[2] * L[2]), C = L[0] ** 2 + L[1] ** 2 + L[2] ** 2 - BALL.radius ** 2;
    const disc = B * B - 4 * C, t = (-B - Math.sqrt(Math.max(0, disc))) / 2;
    if (!(disc > 0 && t > 0 && t < dist)) seen++;
  }
  return seen;
}

/** The first floor pixel (row by row) whose point sees some of the lamp, not all. */
export function penumbraPixel(scene, camera, lamp) {
  for (let y = 0; y < camera.height; y++) {
    for (let x = 0; x < camera.width; x++) {
      const r = inspectPixel(scene, camera, x, y);
      if (r.hit?.object !== scene.objects[0]) continue;
      const seen = pointsSeen(r.hit.point, r.hit.normal, lamp, scene.bias);
      if (seen > 0 && seen < lamp.samples) return { x, y, seen, record: r };
    }
  }
  return null;
}
