/**
 * 09 · Homework 2: a car's two rear lights (slide "Homework", Task 2).
 *
 * The camera stands behind a car made of boxes and spheres. Your task: the
 * two red rear lights, side by side at the same height. Write them in
 * addLights() below, save (the page reloads), then press "Check my scene".
 * The teacher's answer: open this page with ?solution=1.
 */
import p5 from 'p5';
import { Scene, Sphere, Box, Plane, PointLight, Camera, checkRearLights, solutionParameter } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …

/* ---------------------------- YOUR HOMEWORK ----------------------------
 * TODO: add the car's two rear lights: red, side by side, at the same
 * height, one on the left and one on the right of the car's back.
 * The car goes from x = -1 to x = 1 and from y = 0.3 to y = 1 (the body);
 * its back is at z = -6.6: put the lights at z = -6.5 so they stick out.
 * A light is a sphere that gives off light, like this yellow one:
 *   scene.add(new Sphere([2, 0.5, -6.5], 0.14, { color: [0, 0, 0], emission: [1, 0.8, 0] }));
 */
export function addLights(scene) {
  // TODO: your two rear lights here.
}
/* ----------------------------------------------------------------------- */

const WIDTH = 160, HEIGHT = 120; // traced pixels
const PAINT = { color: [0.2, 0.42, 0.85], specular: 0.4 };
const TYRE = { color: [0.08, 0.08, 0.09] };

/** A road, a car seen from behind (body, cabin, rear window, plate, wheels), the sun; then the lights. */
export function makeScene(addTheLights = addLights) {
  const scene = new Scene({ background: [0.62, 0.78, 0.95], ambient: 0.2 });
  scene.add(new Plane([0, 0, 0], [0, 1, 0], { color: [0.32, 0.33, 0.36], name: 'road' }));
  scene.add(new Box([-1, 0.3, -10.6], [1, 1, -6.6], { ...PAINT, name: 'body' }));
  scene.add(new Box([-0.8, 1, -9.6], [0.8, 1.55, -7.3], { ...PAINT, name: 'cabin' }));
  scene.add(new Box([-0.65, 1.08, -7.32], [0.65, 1.48, -7.26], { color: [0.1, 0.12, 0.16], specular: 0.8, name: 'rear window' }));
  scene.add(new Box([-0.3, 0.42, -6.62], [0.3, 0.6, -6.56], { color: [0.95, 0.95, 0.9], name: 'number plate' }));
  for (const x of [-0.92, 0.92]) for (const z of [-7.3, -9.9]) scene.add(new Sphere([x, 0.33, z], 0.33, { ...TYRE, name: 'wheel' }));
  scene.add(new PointLight([40, 120, 120], { intensity: 0.8, name: 'sun' }));
  addTheLights(scene);
  return scene;
}

export function makeCamera() {
  return new Camera({ width: WIDTH, height: HEIGHT, position: [0, 1.4, 0], pitch: -5 });
}

new p5((p) => {
  p.setup = async () => {
    p.noCanvas(); // the tracer view brings its own canvas
    const { solution, message } = solutionParameter(location.search); // ?solution=1: the teacher's answer
    const scene = makeScene(solution ? (await import('./solutions/09-rear-lights.js')).addLights : addLights);
    const view = p.createTracerView({ scene, camera: makeCamera(), parent: 'picture',
      label: solution ? 'The reference solution (sketches/solutions/09-rear-lights.js)' : 'Your car, seen from behind' });
    p.createInspector({ view, parent: 'sketch' });

    p.createTaskList({ page: '09', view }); // the page's tasks, ticked off as they are done
    p.createHomeworkCheck({ view, check: checkRearLights, parent: 'check', problem: message });
  };
}, 'sketch');
