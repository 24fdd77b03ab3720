/**
 * Homework 1, a reference solution: three lights in the signal's housing.
 * Same x and z (the housing's front, so half of each sphere shows), and
 * red higher than yellow, higher than green — a larger y is higher.
 * A light is a sphere whose material has an emission; its colour black
 * means the other lights do not tint it: it shows its own light only.
 */
import { Sphere } from '../../lib/index.js';

const X = 0, Z = -16;      // the front of the housing
const LAMP_RADIUS = 0.5;

export function addLights(scene) {
  scene.add(new Sphere([X, 6.6, Z], LAMP_RADIUS, { color: [0, 0, 0], emission: [1, 0.1, 0.05] })); // red
  scene.add(new Sphere([X, 5.4, Z], LAMP_RADIUS, { color: [0, 0, 0], emission: [1, 0.8, 0] }));    // yellow
  scene.add(new Sphere([X, 4.2, Z], LAMP_RADIUS, { color: [0, 0, 0], emission: [0.1, 1, 0.3] }));  // green
}
