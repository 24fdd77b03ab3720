/**
 * The library's reference pictures: the scenes, how each is rendered, and PNG
 * reading, writing and comparing. Used by tests/unit/pictures.test.js (which
 * compares) and scripts/update-pictures.js (which rewrites the references on
 * purpose, `npm run test:update`).
 */
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';
import pixelmatch from 'pixelmatch';
import { Scene, Camera, Sphere, Plane, Box, PointLight, classScene, render } from '../../lib/index.js';

/** Folder of the checked-in reference PNGs. */
export const PICTURES_DIR = path.dirname(fileURLToPath(import.meta.url));
/** Where a failed comparison leaves the actual picture and a diff (git-ignored). */
export const DIFF_DIR = path.join(PICTURES_DIR, '__diff__');

/** A floor, a box and a mirror-ish ball under one point light: planes, boxes, shadows. */
function planeBoxScene() {
  const scene = new Scene({ background: [0.1, 0.12, 0.2], ambient: 0.1 });
  scene.add(new Plane([0, -2, 0], [0, 1, 0], { color: [0.8, 0.8, 0.8] }));
  scene.add(new Box([-3, -2, -16], [0, 1, -12], { color: '#ff5160' }));
  scene.add(new Sphere([2.5, -0.5, -13], 1.5, { color: 'skyblue', reflection: 0.3, specular: 0.5 }));
  scene.add(new PointLight([-6, 8, -4], [1, 1, 1], 1));
  return scene;
}

/** Every reference picture: `name` (the PNG's file name) and how to make its scene and camera. */
export const pictures = [
  {
    name: 'class-scene',
    about: "the class's example scene, straight ahead",
    make: () => ({ scene: classScene(), camera: new Camera({ width: 160, height: 120 }) }),
  },
  {
    name: 'class-scene-full',
    about: 'the class scene with its mirrors and glass',
    make: () => ({ scene: classScene({ full: true }), camera: new Camera({ width: 160, height: 120 }) }),
  },
  {
    name: 'plane-box-point-light',
    about: 'a floor, a box and a ball lit by a point light, with shadows',
    make: () => ({
      scene: planeBoxScene(),
      camera: new Camera({ width: 160, height: 120, fov: 45, position: [0, 1, 0], pitch: -8 }),
    }),
  },
  {
    name: 'class-scene-yaw-pitch',
    about: 'the class scene seen from higher up, turned right and looking down',
    make: () => ({
      scene: classScene(),
      camera: new Camera({ width: 160, height: 120, fov: 40, position: [-4, 6, 2], yaw: 12, pitch: -15 }),
    }),
  },
];

/** Renders one picture: `{ width, height, data }` (RGBA bytes). */
export function renderPicture(picture) {
  const { scene, camera } = picture.make();
  return { width: camera.width, height: camera.height, data: render(scene, camera) };
}

/** The checked-in reference PNG's path for a picture. */
export function referencePath(name) {
  return path.join(PICTURES_DIR, `${name}.png`);
}

/** `{ width, height, data }` of a PNG file. */
export function readPng(file) {
  const png = PNG.sync.read(fs.readFileSync(file));
  return { width: png.width, height: png.height, data: new Uint8ClampedArray(png.data) };
}

/** Writes RGBA bytes as a PNG file (creating its folder). */
export function writePng(file, { width, height, data }) {
  const png = new PNG({ width, height });
  png.data = Buffer.from(data.buffer, data.byteOffset, data.byteLength);
  fs.mkdirSync(path.dirname(file), { recursive: true });
  fs.writeFileSync(file, PNG.sync.write(png));
}

/**
 * Compares two pictures strictly (pixelmatch with threshold 0, anti-aliasing
 * counted): `{ differing, diff }`, `diff` the pixelmatch diff picture's bytes.
 */
export function comparePictures(actual, expected) {
  if (actual.width !== expected.width || actual.height !== expected.height) {
    return { differing: actual.width * actual.height, diff: null, sizeMismatch: true };
  }
  const diff = new Uint8ClampedArray(actual.width * actual.height * 4);
  const differing = pixelmatch(actual.data, expected.data, diff, actual.width, actual.height, {
    threshold: 0,
    includeAA: true,
  });
  return { differing, diff, sizeMismatch: false };
}
