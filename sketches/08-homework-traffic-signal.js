/**
 * 08 · Homework 1: a traffic signal (slide "Homework", Task 1).
 *
 * A scene is shapes with materials, and a sphere with an emission is a light
 * you can see. The road, the pole and the signal's housing are here already;
 * your task is the three lights: write them in addLights() below, save (the
 * page reloads), then press "Check my scene".
 * The teacher's answer: open this page with ?solution=1.
 */
import p5 from 'p5';
import { Scene, Sphere, Box, Plane, PointLight, Camera, checkTrafficSignal, solutionParameter } from '../lib/index.js';
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

const WIDTH = 160, HEIGHT = 120; // traced pixels

/** The street: a road, the pole, the signal's housing, the sun; then the lights. */
export function makeScene(addTheLights = addLights) {
  const scene = new Scene({ background: [0.62, 0.78, 0.95], ambient: 0.2 });
  scene.add(new Plane([0, 0, 0], [0, 1, 0], { color: [0.32, 0.33, 0.36], name: 'road' }));
  scene.add(new Box([-0.15, 0, -16.65], [0.15, 3.4, -16.35], { color: [0.35, 0.36, 0.38], name: 'pole' }));
  scene.add(new Box([-0.8, 3.4, -16.8], [0.8, 7.4, -16.2], { color: [0.15, 0.15, 0.16], name: 'housing' }));
  scene.add(new PointLight([40, 200, 60], { intensity: 0.8, name: 'sun' }));
  addTheLights(scene);
  return scene;
}

export function makeCamera() {
  return new Camera({ width: WIDTH, height: HEIGHT, fov: 35, position: [0, 1.6, 0], pitch: 7 });
}

new p5((p) => {
  p.setup = async () => {
    p.noCanvas(); // the tracer view brings its own canvas
    const { solution, message } = solutionParameter(location.search); // ?solution=1: the teacher's answer
    const scene = makeScene(solution ? (await import('./solutions/08-traffic-signal.js')).addLights : addLights);
    const view = p.createTracerView({ scene, camera: makeCamera(), parent: 'picture',
      label: solution ? 'The reference solution (sketches/solutions/08-traffic-signal.js)' : 'Your traffic signal' });
    p.createInspector({ view, parent: 'sketch' });

    p.createTaskList({ page: '08', view }); // the page's tasks, ticked off as they are done
    p.createHomeworkCheck({ view, check: checkTrafficSignal, parent: 'check', problem: message });
  };
}, 'sketch');
