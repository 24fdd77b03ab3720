// Homework 2: a car's two rear lights. The camera stands behind a car made of
// boxes and spheres; your task is its two red rear lights. Write them in
// addLights() below, press Play, then "Check my scene".
// (Raytracing Sketchbook, global mode.)

/* ---------------------------- YOUR HOMEWORK ----------------------------
 * TODO: add the car's two rear lights: red, side by side, at the same
 * height, one on the left and one on the right of the car's back.
 * The car goes from x = -1 to x = 1 and from y = 0.3 to y = 1 (the body);
 * its back is at z = -6.6: put the lights at z = -6.5 so they stick out.
 * A light is a sphere that gives off light, like this yellow one:
 *   scene.add(new RT.Sphere([2, 0.5, -6.5], 0.14, { color: [0, 0, 0], emission: [1, 0.8, 0] }));
 */
function addLights(scene) {
  // TODO: your two rear lights here.
}
/* ----------------------------------------------------------------------- */

function setup() {
  noCanvas(); // the tracer view brings its own canvas

  const scene = RT.rearLightsScene(); // the road, the car, the sun
  addLights(scene);
  const view = createTracerView({ scene, camera: RT.rearLightsCamera(), label: 'Your car, seen from behind' });
  createHomeworkCheck({ view, check: RT.checkRearLights }); // the "Check my scene" button
  createInspector({ view });
}
