/**
 * 08 · Homework 1: a traffic signal (slide "Homework", Task 1).
 *
 * A scene is shapes with materials, and a sphere with an emission is a light
 * you can see. The road, the pole and the signal's housing are here already;
 * your task is the three lights: write them in addLights() below, here in
 * the page's editor, press Run, then "Check my scene" under the picture.
 * The teacher's answer: open this page with ?solution=1 (on the teacher's own
 * `npm start`; the class server and the built site do not have it).
 */
import p5 from 'p5';
import { Sphere, trafficSignalScene, trafficSignalCamera, checkTrafficSignal, solutionParameter } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …

/* ---------------------------- YOUR HOMEWORK ----------------------------
 * TODO: add three lights to the signal: red on top, yellow in the middle,
 * green at the bottom, one above the other at the housing's front
 * (x = 0, z = -16; the housing goes from y = 3.4 up to y = 7.4).
 * A light is a sphere that gives off light, like this blue one:
 *   scene.add(new Sphere([3, 1, -16], 0.5, { color: [0, 0, 0], emission: [0, 0, 1] }));
 */
export function addLights(scene) {
  // TODO: your three lights here.
}
/* ----------------------------------------------------------------------- */

/** The street (lib/lesson/homework-scenes.js: a road, the pole, the signal's housing, the sun); then the lights. */
export function makeScene(addTheLights = addLights) {
  const scene = trafficSignalScene();
  addTheLights(scene);
  return scene;
}

export const makeCamera = trafficSignalCamera; // 160 × 120 pixels, looking up at the signal

new p5((p) => {
  p.setup = async () => {
    p.noCanvas(); // the tracer view brings its own canvas
    const { solution, message } = solutionParameter(location.search); // ?solution=1: the teacher's answer
    // Served to a class or built, the answer stays on the teacher's computer: `elsewhere` says so (scripts/classroom.js).
    const reference = solution ? await import('./solutions/08-traffic-signal.js') : null;
    const answer = reference?.addLights;
    const scene = makeScene(answer ?? addLights);
    const view = p.createTracerView({ scene, camera: makeCamera(), parent: 'picture',
      label: answer ? 'The reference solution (sketches/solutions/08-traffic-signal.js)' : 'Your traffic signal' });
    p.createInspector({ view, parent: 'sketch' });

    p.createTaskList({ page: '08', view }); // the page's tasks, ticked off as they are done
    p.createHomeworkCheck({ view, check: checkTrafficSignal, parent: 'check', problem: reference?.elsewhere ?? message });
  };
}, 'sketch');
