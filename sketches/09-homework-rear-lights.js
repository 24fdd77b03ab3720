/**
 * 09 · Homework 2: a car's two rear lights (slide "Homework", Task 2).
 *
 * The camera stands behind a car made of boxes and spheres. Your task: the
 * two red rear lights, side by side at the same height. Write them in
 * addLights() below, here in the page's editor, press Run, then "Check my
 * scene" under the picture.
 * The teacher's answer: open this page with ?solution=1 (on the teacher's own
 * `npm start`; the class server and the built site do not have it).
 */
import p5 from 'p5';
import { Sphere, rearLightsScene, rearLightsCamera, checkRearLights, solutionParameter } from '../lib/index.js';
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

/** A road, a car seen from behind (lib/lesson/homework-scenes.js), the sun; then the lights. */
export function makeScene(addTheLights = addLights) {
  const scene = rearLightsScene();
  addTheLights(scene);
  return scene;
}

export const makeCamera = rearLightsCamera; // 160 × 120 pixels, behind the car

new p5((p) => {
  p.setup = async () => {
    p.noCanvas(); // the tracer view brings its own canvas
    const { solution, message } = solutionParameter(location.search); // ?solution=1: the teacher's answer
    // Served to a class or built, the answer stays on the teacher's computer: `elsewhere` says so (scripts/classroom.js).
    const reference = solution ? await import('./solutions/09-rear-lights.js') : null;
    const answer = reference?.addLights;
    const scene = makeScene(answer ?? addLights);
    const view = p.createTracerView({ scene, camera: makeCamera(), parent: 'picture',
      label: answer ? 'The reference solution (sketches/solutions/09-rear-lights.js)' : 'Your car, seen from behind' });
    p.createInspector({ view, parent: 'sketch' });

    p.createTaskList({ page: '09', view }); // the page's tasks, ticked off as they are done
    p.createHomeworkCheck({ view, check: checkRearLights, parent: 'check', problem: reference?.elsewhere ?? message });
  };
}, 'sketch');
