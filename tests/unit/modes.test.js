import { describe, it, expect } from 'vitest';
import { modeShader, modeLegend, MODES, discriminantColor, angleColor, angleRange, depthRange, isHuge, sphereFocus } from '../../lib/tracing/modes.js';
import { focusTest } from '../../lib/p5/diagrams/focus.js';
import { Plane } from '../../lib/shapes/plane.js';
import { Box } from '../../lib/shapes/box.js';
import { Camera } from '../../lib/math/camera.js';
import { Scene } from '../../lib/scene/scene.js';
import { Sphere, intersectQuadratic } from '../../lib/shapes/sphere.js';
import { render } from '../../lib/tracing/render.js';
import { classScene } from '../../lib/scene/examples.js';
import { inspectPixel } from '../../lib/lesson/inspect.js';

const camera = new Camera({ width: 64, height: 48, fov: 30 });
const scene = classScene();

/** The whole frame of one mode. */
function frame(name, sc = scene, cam = camera) {
  const shader = modeShader(name);
  const target = new Uint8ClampedArray(cam.width * cam.height * 4);
  for (let y = 0; y < cam.height; y++) for (let x = 0; x < cam.width; x++) shader(sc, cam, x, y, target);
  return target;
}
const pixel = (buffer, cam, x, y) => Array.from(buffer.slice((y * cam.width + x) * 4, (y * cam.width + x) * 4 + 4));
const isBlue = ([r, , b]) => b > r;
const isWarm = ([r, , b]) => r > b;

describe('modeShader', () => {
  it('has a shader and a one-line description for every mode', () => {
    expect(MODES.map((m) => m.name)).toEqual(['shaded', 'discriminant', 'roots', 'h', 'v', 'normals', 'depth']);
    for (const mode of MODES) {
      expect(typeof modeShader(mode.name)).toBe('function');
      expect(mode.description.length).toBeGreaterThan(10);
    }
  });

  it('rejects an unknown mode, naming the choices', () => {
    expect(() => modeShader('rainbow')).toThrow(RangeError);
    expect(() => modeShader('rainbow')).toThrow(/discriminant/);
  });

  it("'shaded' is exactly the rendered picture", () => {
    expect(Array.from(frame('shaded'))).toEqual(Array.from(render(scene, camera)));
  });

  it('writes every pixel opaque and only its own 4 bytes', () => {
    for (const { name } of MODES) {
      const target = new Uint8ClampedArray(camera.width * camera.height * 4);
      modeShader(name)(scene, camera, 10, 12, target);
      const i = (12 * camera.width + 10) * 4;
      expect(target[i + 3]).toBe(255);
      const others = Array.from(target).filter((v, j) => (j < i || j >= i + 4) && v !== 0);
      expect(others).toEqual([]);
    }
  });
});

describe("'discriminant' mode", () => {
  const picture = frame('discriminant');

  it("colours a pixel warm when the sphere it hits has B² − 4AC > 0, blue when the closest miss's is < 0", () => {
    let checked = 0;
    for (const [x, y] of [[32, 24], [10, 12], [40, 20], [60, 5], [32, 2], [2, 2], [50, 30], [20, 40]]) {
      const record = inspectPixel(scene, camera, x, y);
      const hitTest = record.tests.find((t) => t.quadratic.t !== null && t.sphere === record.hit?.object);
      const color = pixel(picture, camera, x, y);
      if (hitTest) {
        expect(hitTest.quadratic.discriminant).toBeGreaterThan(0);
        expect(isWarm(color), `pixel ${x},${y}`).toBe(true);
      } else {
        // a miss: the largest discriminant among spheres not wholly behind the eye
        const inFront = record.tests.filter((t) => t.quadratic.roots === 0);
        const best = Math.max(...inFront.map((t) => t.quadratic.discriminant));
        expect(best).toBeLessThan(0);
        expect(isBlue(color), `pixel ${x},${y}`).toBe(true);
      }
      checked++;
    }
    expect(checked).toBe(8);
  });

  it('matches the sign of intersectQuadratic for a single sphere, pixel by pixel', () => {
    const one = new Scene().add(new Sphere([0, 0, -10], 2));
    const cam = new Camera({ width: 16, height: 12, fov: 40 });
    const shown = frame('discriminant', one, cam);
    let hits = 0, misses = 0;
    for (let y = 0; y < 12; y++) {
      for (let x = 0; x < 16; x++) {
        const q = intersectQuadratic(cam.primaryRay(x, y).ray, one.objects[0]);
        const color = pixel(shown, cam, x, y);
        expect(color.slice(0, 3)).toEqual(Array.from(discriminantColor(q.discriminant, q.roots), Math.round));
        if (q.discriminant > 0) { hits++; expect(isWarm(color)).toBe(true); } else { misses++; expect(isBlue(color)).toBe(true); }
      }
    }
    expect(hits).toBeGreaterThan(0);
    expect(misses).toBeGreaterThan(0);
  });

  it('shows a bigger |discriminant| in a darker shade, and 0 (tangent) apart from both sides', () => {
    const lum = (c) => c[0] + c[1] + c[2];
    expect(lum(discriminantColor(1e4, 2))).toBeLessThan(lum(discriminantColor(10, 2)));
    expect(lum(discriminantColor(-1e4, 0))).toBeLessThan(lum(discriminantColor(-10, 0)));
    expect(discriminantColor(0, 1)).not.toEqual(discriminantColor(1, 2));
    expect(discriminantColor(0, 1)).not.toEqual(discriminantColor(-1, 0));
  });

  it('paints black where there is no sphere at all', () => {
    const empty = new Scene({ background: [1, 1, 1] });
    const cam = new Camera({ width: 2, height: 2 });
    expect(pixel(frame('discriminant', empty, cam), cam, 0, 0)).toEqual([0, 0, 0, 255]);
  });
});

describe("'roots' mode", () => {
  const colors = modeLegend('roots', scene, camera).stops.map((s) => s.color);
  const hex = (c) => '#' + c.slice(0, 3).map((v) => v.toString(16).padStart(2, '0')).join('');

  it('uses three flat colours: 2 roots on the spheres and the ground, 0 in the sky', () => {
    const picture = frame('roots');
    const used = new Set();
    for (let i = 0; i < picture.length; i += 4) used.add(hex(Array.from(picture.slice(i, i + 3))));
    expect([...used].every((c) => colors.includes(c))).toBe(true);
    expect(hex(pixel(picture, camera, 32, 24))).toBe(colors[2]); // the pink sphere
    expect(hex(pixel(picture, camera, 32, 47))).toBe(colors[2]); // the ground
    expect(hex(pixel(picture, camera, 2, 0))).toBe(colors[0]); // the sky
  });

  it('shows 1 root for a ray that grazes a sphere', () => {
    // camera at the origin, sphere centred 1 unit up: the centre ray (0, 0, −1) is tangent to it.
    const one = new Scene().add(new Sphere([0, 1, -10], 1));
    const cam = new Camera({ width: 1, height: 1 });
    expect(intersectQuadratic(cam.primaryRay(0, 0).ray, one.objects[0]).roots).toBe(1);
    expect(hex(pixel(frame('roots', one, cam), cam, 0, 0))).toBe(colors[1]);
  });
});

describe("'h' and 'v' modes", () => {
  const h = frame('h');
  const v = frame('v');

  it('are mirror-symmetric about the image centre: same colour for the same angle, opposite ends for opposite angles', () => {
    const range = angleRange(camera);
    const hex = (c) => Array.from(c.slice(0, 3), Math.round);
    for (const [x, y] of [[0, 0], [5, 20], [20, 3], [31, 10]]) {
      const mx = camera.width - 1 - x, my = camera.height - 1 - y; // (x, y) is in the top-left quarter
      const { h: hAngle, v: vAngle } = camera.primaryRay(x, y);
      expect(pixel(h, camera, x, y)).toEqual(pixel(h, camera, x, my)); // H is the same up and down a column
      expect(pixel(v, camera, x, y)).toEqual(pixel(v, camera, mx, y)); // V is the same left and right along a row
      expect(pixel(h, camera, mx, y).slice(0, 3)).toEqual(hex(angleColor(-hAngle, range.h)));
      expect(pixel(v, camera, x, my).slice(0, 3)).toEqual(hex(angleColor(-vAngle, range.v)));
      expect(isBlue(pixel(h, camera, x, y))).toBe(true); // left: negative H, purple
      expect(isWarm(pixel(h, camera, mx, y))).toBe(true); // right: positive H, orange
      expect(isWarm(pixel(v, camera, x, y))).toBe(true); // top: positive V
      expect(isBlue(pixel(v, camera, x, my))).toBe(true); // bottom: negative V
    }
  });

  it("scale to the camera's angle range, 0 in the middle", () => {
    const range = angleRange(camera);
    expect(range.v).toBe(15); // fov 30: ±15°
    expect(range.h).toBeGreaterThanOrEqual(15);
    const legend = modeLegend('h', scene, camera);
    expect(legend.stops.map((s) => s.value)).toEqual([-range.h, -range.h / 2, 0, range.h / 2, range.h]);
    const wide = new Camera({ width: 64, height: 48, fov: 90, yaw: 30 });
    expect(angleRange(wide).v).toBe(45);
    expect(angleRange(wide).h).toBeGreaterThan(60); // yaw 30 plus half the width
  });
});

describe("'normals' and 'depth' modes", () => {
  it('colours the normal (n + 1)/2 and the background black', () => {
    const one = new Scene({ background: [1, 1, 1] }).add(new Sphere([0, 0, -10], 2));
    const cam = new Camera({ width: 9, height: 9, fov: 30 });
    const normals = frame('normals', one, cam);
    const centre = pixel(normals, cam, 4, 4);
    expect(centre[2]).toBe(255); // facing the eye: n = (0, 0, 1)
    expect(Math.abs(centre[0] - 128)).toBeLessThanOrEqual(1);
    expect(pixel(normals, cam, 0, 0)).toEqual([0, 0, 0, 255]);
  });

  it('shows near hits brighter than far ones, scaled to the scene', () => {
    const depth = frame('depth');
    const { near, far } = depthRange(scene, camera);
    expect(near).toBeGreaterThan(5);
    expect(far).toBeLessThan(60); // the ground's far horizon does not set the scale
    const white = pixel(depth, camera, 6, 24); // the white sphere, z = −15
    const blue = pixel(depth, camera, 52, 18); // the blue sphere, z = −25
    expect(inspectPixel(scene, camera, 6, 24).hit.object.name).toBe('white');
    expect(inspectPixel(scene, camera, 52, 18).hit.object.name).toBe('blue');
    expect(white[0]).toBeGreaterThan(blue[0]);
    expect(pixel(depth, camera, 2, 0)).toEqual([0, 0, 0, 255]); // sky: no hit
  });

  it('treats a radius of 100 and more as a ground or a wall', () => {
    expect(isHuge(scene.objects[0])).toBe(true);
    expect(isHuge(scene.objects[1])).toBe(false);
    // the threshold itself: 100 is huge, just under it is not; only spheres are
    expect(isHuge(new Sphere([0, 0, 0], 100))).toBe(true);
    expect(isHuge(new Sphere([0, 0, 0], 99.9))).toBe(false);
    expect(isHuge(new Box([-500, -1, -500], [500, 0, 500]))).toBe(false);
    expect(isHuge(new Plane([0, 0, 0], [0, 1, 0]))).toBe(false);
  });
});

describe('modeLegend', () => {
  it('gives a title, a note and stops with a label and a #hex colour for every mode', () => {
    for (const { name, label } of MODES) {
      const legend = modeLegend(name, scene, camera);
      expect(legend.title).toBe(label);
      expect(typeof legend.note).toBe('string');
      expect(legend.note, `${name}'s note is a sentence`).toMatch(/^\S.{20,}\.$/);
      expect(['gradient', 'swatches']).toContain(legend.kind);
      expect(legend.stops.length).toBeGreaterThanOrEqual(2);
      for (const stop of legend.stops) {
        expect(stop.color).toMatch(/^#[0-9a-f]{6}$/);
        expect(typeof stop.label).toBe('string');
      }
    }
  });

  it('orders gradient stops by value, with 0 in the middle of the discriminant and angle scales', () => {
    for (const name of ['discriminant', 'h', 'v', 'depth']) {
      const values = modeLegend(name, scene, camera).stops.map((s) => s.value);
      expect([...values].sort((a, b) => a - b)).toEqual(values);
      if (name !== 'depth') expect(values[(values.length - 1) / 2]).toBe(0);
    }
  });

  it("uses the same colours as the mode's pixels", () => {
    const stops = modeLegend('discriminant', scene, camera).stops;
    const minus100 = stops.find((s) => s.value === -100);
    const rgb = discriminantColor(-100, 0).map((c) => Math.round(c).toString(16).padStart(2, '0')).join('');
    expect(minus100.color).toBe('#' + rgb);
  });

  it('rejects an unknown mode', () => {
    expect(() => modeLegend('nope', scene, camera)).toThrow(RangeError);
  });
});

describe('sphereFocus: one choice for the discriminant mode and the diagrams', () => {
  // A wall at z = -10 hides a sphere the centre ray goes through; a second sphere, off to the side, is missed.
  const wall = new Scene({ background: [1, 1, 1] })
    .add(new Plane([0, 0, -10], [0, 0, 1], { color: [0.6, 0.6, 0.6] }))
    .add(new Sphere([6, 0, -20], 2, { color: [0, 1, 0] }))
    .add(new Sphere([0, 0, -20], 3, { color: [1, 0, 0] }));
  const cam = new Camera({ width: 9, height: 9, fov: 30 });
  const behind = wall.objects[2];

  it('takes the sphere the ray goes through, even when a plane is the nearest hit', () => {
    const record = inspectPixel(wall, cam, 4, 4);
    expect(record.hit.object).toBe(wall.objects[0]); // the wall is what the pixel shows
    const test = focusTest(record);
    expect(test.sphere).toBe(behind);
    expect(test.quadratic.roots).toBe(2);
    // The discriminant mode colours that pixel for the same sphere.
    const q = intersectQuadratic(record.ray, behind);
    expect(pixel(frame('discriminant', wall, cam), cam, 4, 4)).toEqual([...Uint8ClampedArray.from(discriminantColor(q.discriminant, q.roots)), 255]);
    expect(sphereFocus(wall.objects, record.ray)).toBe(2);
  });

  it('agrees with the diagrams on every pixel, wall or no wall', () => {
    for (const sc of [wall, scene]) {
      for (let y = 0; y < cam.height; y++) {
        for (let x = 0; x < cam.width; x++) {
          const record = inspectPixel(sc, cam, x, y);
          const focus = { index: -1, discriminant: 0, roots: 0 };
          const index = sphereFocus(sc.objects, record.ray, focus);
          expect(focusTest(record).sphere).toBe(sc.objects[index]);
          expect(focusTest(record).quadratic.discriminant).toBe(focus.discriminant);
        }
      }
    }
  });

  it('finds no sphere in a scene of planes and boxes', () => {
    const flat = new Scene().add(new Plane([0, -1, 0], [0, 1, 0])).add(new Box([-1, -1, -12], [1, 1, -10]));
    const record = inspectPixel(flat, cam, 4, 4);
    expect(sphereFocus(flat.objects, record.ray)).toBe(-1);
    expect(focusTest(record)).toBeNull();
  });
});
