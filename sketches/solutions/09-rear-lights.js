/**
 * Homework 2, a reference solution: a car's two rear lights. Both at the
 * same height (same y) and the same z (just behind the car's back, so they
 * stick out), one on each side: x = −0.72 and x = +0.72, symmetric about the
 * car's middle, x = 0. Red emission, black surface colour.
 */
import { Sphere } from '../../lib/index.js';

const Y = 0.8, Z = -6.5;   // height and depth of both lights
const SIDE = 0.72;         // how far each is from the car's middle
const LAMP_RADIUS = 0.14;
const RED = { color: [0, 0, 0], emission: [1, 0.05, 0.05] };

export function addLights(scene) {
  scene.add(new Sphere([-SIDE, Y, Z], LAMP_RADIUS, RED)); // left
  scene.add(new Sphere([SIDE, Y, Z], LAMP_RADIUS, RED));  // right
}
