// Homework 1: a traffic signal. The road, the pole and the signal's housing
// are here; your task is the three lights. Write them in addLights() below,
// press Play, then "Check my scene".
// (Raytracing Sketchbook, global mode.)

/* ---------------------------- YOUR HOMEWORK ----------------------------
 * TODO: add three lights to the signal: red on top, yellow in the middle,
 * green at the bottom, one above the other at the housing's front
 * (x = 0, z = -16; the housing goes from y = 3.4 up to y = 7.4).
 * A light is a sphere that gives off light, like this blue one:
 *   scene.add(new RT.Sphere([3, 1, -16], 0.5, { color: [0, 0, 0], emission: [0, 0, 1] }));
 */
function addLights(scene) {
  // TODO: your three lights here.
}
/* ----------------------------------------------------------------------- */

function setup() {
  noCanvas(); // the tracer view brings its own canvas

  const scene = RT.trafficSignalScene(); // the road, the pole, the housing, the sun
  addLights(scene);
  const view = createTracerView({ scene, camera: RT.trafficSignalCamera(), label: 'Your traffic signal' });
  createHomeworkCheck({ view, check: RT.checkTrafficSignal }); // the "Check my scene" button
  createInspector({ view });
}
