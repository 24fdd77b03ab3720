// The renderer's shortcuts must never show: over random scenes (spheres,
// planes, boxes, cylinders, cones, triangles, meshes, point lights and emissive shapes, mirrors, glass, shadows and
// highlights on or off) and random cameras, render() — which tests each
// primary ray only against its tile's candidate shapes (lib/tracing/bounds.js) — gives
// the very bytes of the plain reference, every pixel traced against every
// shape; so does every visual mode, however its pictures are traced; and so
// does a ProgressiveRenderer's finished buffer, in every order; and the
// inspector, which records every step of the same trace, gives render()'s colour.
import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import { Camera, Scene, Sphere, Plane, Box, Cylinder, Mesh, PointLight, render, inspectPixel } from '../../lib/index.js';
import { renderPixel, prepareFrame } from '../../lib/tracing/render.js';
import { packScene, unpackable, tracePrimary, outOfReach } from '../../lib/tracing/kernel.js';
import { trace } from '../../lib/tracing/trace.js';
import { Ray } from '../../lib/math/ray.js';
import { Vec3 } from '../../lib/math/vec3.js';
import { MODES, modeShader } from '../../lib/tracing/modes.js';
import { between, point, direction, scene, shapeScene, sphereScene, camera, SHAPES, LIGHTS } from '../shared/random-scenes.js';
import { ProgressiveRenderer, ORDERS } from '../../lib/tracing/frames.js';
import { shapeClasses } from '../../lib/shapes/index.js';
import { lightClasses } from '../../lib/lights/index.js';

/** The plain reference: `shader` called for every pixel, in reading order, each primary ray against every shape. */
function pixelByPixel(scene, cam, shader = renderPixel) {
  const out = new Uint8ClampedArray(cam.width * cam.height * 4);
  for (let y = 0; y < cam.height; y++) for (let x = 0; x < cam.width; x++) shader(scene, cam, x, y, out);
  return out;
}

/** A ProgressiveRenderer run to its end, in short steps (its clock never moves: each step traces a few pixels). */
function progressively(scene, cam, order, shader) {
  const renderer = new ProgressiveRenderer({ scene, camera: cam, mode: order, slowRaysPerStep: 13, now: () => 0, ...(shader && { shader }) });
  while (!renderer.step(0).done);
  return renderer.buffer;
}

/** The index of the first byte where two pictures differ, or -1: a failing run names the pixel. */
function firstDifference(a, b) {
  if (a.length !== b.length) return 0;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return i;
  return -1;
}

const RUNS = { seed: 12, numRuns: 300 };

/**
 * This run's own seed: new cases every run, beside the fixed seeds' (the same
 * cases every run). A failure names it; `SEED=… vitest run` replays it.
 */
const FRESH_SEED = freshSeed(process.env.SEED);

function freshSeed(text) {
  if (text === undefined) return Math.floor(Math.random() * 2 ** 31);
  const seed = Number(text);
  if (!Number.isSafeInteger(seed)) throw new TypeError(`SEED must be a whole number (a failure prints one), got ${JSON.stringify(text)}`);
  return seed;
}

const TEST_FILE = 'tests/unit/same-bytes.test.js';

/**
 * fc.assert from the fixed seed in `params`, then from this run's fresh seed.
 * A failure is reported as found, not shrunk (shrinking a scene of shapes can
 * take minutes), unless SEED is given: a replay shrinks it to a small case.
 */
function assertBoth(property, params) {
  fc.assert(property, { endOnFailure: process.env.SEED === undefined, ...params });
  assertFresh(property, params);
}

/** fc.assert from this run's fresh seed; a failure says how to replay it. */
function assertFresh(property, params) {
  try {
    fc.assert(property, { endOnFailure: process.env.SEED === undefined, ...params, seed: FRESH_SEED });
  } catch (error) {
    error.message = `with this run's fresh seed ${FRESH_SEED} (replay: SEED=${FRESH_SEED} node_modules/.bin/vitest run ${TEST_FILE})\n${error.message}`;
    throw error;
  }
}

describe('the same bytes as the plain reference, for random scenes and cameras (property)', () => {
  it('has a random one of every listed shape and light (a new class is in the property the day it is listed)', () => {
    expect(shapeClasses().map((Shape) => Shape.type).filter((type) => !SHAPES[type])).toEqual([]);
    expect(lightClasses().map((Light) => Light.type).filter((type) => !LIGHTS[type])).toEqual([]);
  });

  it('render(), and render() of a band of rows', () => {
    assertBoth(fc.property(scene, camera, fc.nat(), fc.nat(), (s, cam, a, b) => {
      const reference = pixelByPixel(s, cam);
      expect(firstDifference(render(s, cam), reference)).toBe(-1);
      const y0 = a % (cam.height + 1), y1 = y0 + (b % (cam.height - y0 + 1));
      const band = render(s, cam, undefined, { y0, y1 });
      const rows = (buffer) => buffer.subarray(y0 * cam.width * 4, y1 * cam.width * 4);
      expect(firstDifference(rows(band), rows(reference))).toBe(-1);
    }), RUNS);
  });

  it('every visual mode, whole or traced progressively in every order', () => {
    assertBoth(fc.property(scene, camera, (s, cam) => {
      for (const { name } of MODES) {
        const shader = modeShader(name);
        const reference = pixelByPixel(s, cam, shader);
        for (const order of ORDERS) {
          expect(firstDifference(progressively(s, cam, order, shader), reference), `${name}, ${order}`).toBe(-1);
        }
      }
    }), { ...RUNS, numRuns: 100 });
  });

  it("inspectPixel's colour, which records every step on the way, is render()'s pixel", () => {
    assertBoth(fc.property(scene, camera, fc.nat(), fc.nat(), (s, cam, a, b) => {
      const pixels = render(s, cam);
      for (let k = 0; k < 8; k++) { // a few pixels, anywhere in the frame
        const x = (a + 7 * k) % cam.width, y = (b + 5 * k) % cam.height, i = (y * cam.width + x) * 4;
        expect(inspectPixel(s, cam, x, y).color, `pixel ${x},${y}`).toEqual([pixels[i], pixels[i + 1], pixels[i + 2]]);
      }
    }), { ...RUNS, numRuns: 150 });
  });

  it('render() takes the fast path (lib/tracing/kernel.js) for scenes of plain shapes, and for spheres only gives the same bytes', () => {
    assertBoth(fc.property(scene, camera, (s, cam) => {
      const twice = new Set(s.objects).size !== s.objects.length; // left to trace.js (see below)
      expect(prepareFrame(s, cam).packed === null).toBe(twice); // so the tests above compare lib/tracing/kernel.js with trace.js
    }), { ...RUNS, numRuns: 50 });
    assertBoth(fc.property(sphereScene, camera, (s, cam) => {
      expect(firstDifference(render(s, cam), pixelByPixel(s, cam))).toBe(-1);
    }), RUNS);
  });

  it('render() of scenes with every listed shape (cylinders, cones, triangles, meshes, …): the fast path, and the same bytes', () => {
    assertBoth(fc.property(shapeScene, camera, (s, cam) => {
      const twice = new Set(s.objects).size !== s.objects.length;
      expect(prepareFrame(s, cam).packed === null).toBe(twice);
      expect(firstDifference(render(s, cam), pixelByPixel(s, cam))).toBe(-1);
    }), { ...RUNS, numRuns: 200 });
  });

  it("a ProgressiveRenderer's finished buffer is render()'s, in every order", () => {
    assertBoth(fc.property(scene, camera, (s, cam) => {
      const expected = render(s, cam);
      for (const order of ORDERS) expect(firstDifference(progressively(s, cam, order), expected), order).toBe(-1);
    }), { ...RUNS, numRuns: 150 });
  });
});

describe('a shape of its own class (a subclass with its own hit test)', () => {
  /** A sphere that hides itself from rays starting left of x = 0: only its own `hit` knows. */
  class HalfSeen extends Sphere {
    hit(ray, tMin) {
      return ray.origin.x < 0 ? Infinity : super.hit(ray, tMin);
    }
  }

  it('is not packed for the fast path: render() asks the shape itself, as trace.js does', () => {
    const scene = new Scene({ background: [0, 0, 1] }).add(new HalfSeen([0, 0, -10], 3, { color: [1, 0, 0], emission: [1, 0, 0] }));
    expect(packScene(scene)).toBeNull();
    expect(unpackable(scene)).toEqual({ index: 0, why: "its hit or normalAt is not its class's own (a subclass, or a method replaced)" });
    const seen = render(scene, new Camera({ width: 8, height: 8, position: [1, 0, 0] }));
    const hidden = render(scene, new Camera({ width: 8, height: 8, position: [-1, 0, 0] }));
    const middle = (4 * 8 + 4) * 4;
    expect([...seen.subarray(middle, middle + 3)]).toEqual([255, 0, 0]);
    expect([...hidden.subarray(middle, middle + 3)]).toEqual([0, 0, 255]);
    expect(firstDifference(seen, pixelByPixel(scene, new Camera({ width: 8, height: 8, position: [1, 0, 0] })))).toBe(-1);
  });

  it('nor is a plain shape whose hit test a sketch replaced, on the shape or on its class', () => {
    const ball = new Sphere([0, 0, -10], 3, { color: [1, 0, 0], emission: [1, 0, 0] });
    const scene = new Scene({ background: [0, 0, 1] }).add(ball);
    const camera = new Camera({ width: 8, height: 8 });
    expect(packScene(scene)).not.toBeNull();
    expect(unpackable(scene)).toBeNull();
    expect(unpackable(new Scene().add(ball).add(new Sphere([0, 0, -5], 1)).add(ball))).toMatchObject({ index: 2, why: expect.stringContaining('added to the scene twice') });
    ball.hit = () => Infinity; // the ball no longer meets any ray
    expect(packScene(scene)).toBeNull();
    expect(render(scene, camera).every((v, i) => v === [0, 0, 255, 255][i % 4])).toBe(true); // every pixel the background's blue
    expect(firstDifference(render(scene, camera), pixelByPixel(scene, camera))).toBe(-1);
    delete ball.hit;
    const original = Sphere.prototype.normalAt;
    try {
      Sphere.prototype.normalAt = function (point, out) { return original.call(this, point, out); }; // the same, but not the kernel's to know
      expect(packScene(scene)).toBeNull();
    } finally {
      Sphere.prototype.normalAt = original;
    }
    expect(packScene(scene)).not.toBeNull();
  });
});

describe('the fast path on exact edges and corners, where ties decide', () => {
  it("a ray that meets a box on an edge or corner gets trace.js's normal, so trace.js's colour", () => {
    // Lit from +x only: the x face's normal is lit, the y or z face's is not.
    const scene = new Scene({ background: [0, 0, 0] })
      .add(new Box([-1, -1, -1], [1, 1, 1], { color: [1, 1, 1] }))
      .add(new PointLight([10, 0.5, 0.25]));
    const packed = packScene(scene);
    const rays = [ // each ends exactly on an edge or corner of the box, along an axis
      [[3, 1, 0], [-1, 0, 0]], [[3, -1, 0], [-1, 0, 0]], [[3, 1, 1], [-1, 0, 0]], [[1, 3, 0], [0, -1, 0]],
      [[0, 1, 3], [0, 0, -1]], [[1, 1, 3], [0, 0, -1]], [[-3, 1, 0], [1, 0, 0]],
    ];
    for (const [origin, direction] of rays) {
      const expected = trace(scene, new Ray(origin, direction), [0, 0, 0]);
      const color = tracePrimary(packed, new Vec3(...origin), new Vec3(...direction), packed.all, 0, packed.count);
      expect([...color.subarray(0, 3)], `from ${origin} along ${direction}`).toEqual(expected);
    }
  });
});

describe("the fast path's shadow-ray shortcut", () => {
  it('skips a sphere only when its test says "not in the way": near the limit, for random lights, points and biases (property)', () => {
    let skipped = 0, nearLimit = 0;
    const unitVector = direction.map(([x, y, z]) => { const n = Math.hypot(x, y, z); return [x / n, y / n, z / n]; });
    assertBoth(fc.property(
      point(20), between(0.01, 20), point(30), unitVector, unitVector,
      fc.integer({ min: -1000, max: 1000 }).map((n) => n / 20000), fc.constantFrom(0, 1e-4, 0.01, 0.5),
      (center, radius, light, w, normal, jitter, bias) => {
        // The shaded point P lies about as far from the light as the sphere's near side: the limit of the shortcut.
        const scene = new Scene({ bias }).add(new Sphere(center, radius)).add(new PointLight(light));
        const [c, L] = [new Vec3(...center), new Vec3(...light)];
        const near = Math.hypot(c.x - L.x, c.y - L.y, c.z - L.z) - radius;
        if (!(near > 0)) return; // the light inside the sphere: never skipped
        const P = new Vec3(L.x + w[0] * near * (1 + jitter), L.y + w[1] * near * (1 + jitter), L.z + w[2] * near * (1 + jitter));
        // lightPoint's shadow ray, as both trace.js and the kernel build it
        const x = L.x - P.x, y = L.y - P.y, z = L.z - P.z, distance = Math.sqrt(x * x + y * y + z * z), k = 1 / distance;
        const ray = new Ray([P.x + normal[0] * bias, P.y + normal[1] * bias, P.z + normal[2] * bias], [x * k, y * k, z * k]);
        ray.direction.x = x * k; ray.direction.y = y * k; ray.direction.z = z * k; // (the Ray constructor would normalise it again)
        const reach = distance - bias, packed = packScene(scene);
        if (Math.abs(packed.apart[0] - outOfReach(packed, reach)) < 0.01 * reach) nearLimit++;
        if (packed.apart[0] > outOfReach(packed, reach)) {
          skipped++;
          expect(scene.objects[0].hit(ray, scene.epsilon)).toBeGreaterThanOrEqual(reach);
        }
      }), { seed: 7, numRuns: 2000 });
    expect(skipped).toBeGreaterThan(200); // the property was put to the test, not passed by skipping nothing
    expect(nearLimit).toBeGreaterThan(200);
  });
});

describe('the fast path at the deepest bounce a scene allows', () => {
  it('two facing mirrors and a glass ball at maxDepth 16: the same bytes as trace.js', () => {
    const scene = new Scene({ background: [0.2, 0.4, 0.9], ambient: 0.1, maxDepth: 16 })
      .add(new Plane([0, 0, -8], [0, 0, 1], { color: [0.9, 0.9, 0.9], reflection: 0.95 }))
      .add(new Plane([0, 0, 8], [0, 0, -1], { color: [0.9, 0.8, 0.9], reflection: 0.95 }))
      .add(new Sphere([0, 0, -4], 1.5, { color: [1, 0.4, 0.4], transparency: 0.8, reflection: 0.2, ior: 1.5 }))
      .add(new PointLight([2, 5, 0]));
    const cam = new Camera({ width: 24, height: 18, fov: 50 });
    expect(prepareFrame(scene, cam).packed).not.toBeNull();
    expect(firstDifference(render(scene, cam), pixelByPixel(scene, cam))).toBe(-1);
  });
});

describe('a mesh that mirrors and shades itself', () => {
  it("a corner of a room as one mesh: its mirror and shadow rays meet its own triangles, yet every normal is trace.js's", () => {
    // A floor and two walls, two triangles each; the mesh remembers the triangle its last ray hit.
    const room = new Mesh({
      positions: [[-4, -2, -4], [4, -2, -4], [4, -2, -14], [-4, -2, -14], [-4, 5, -14], [4, 5, -14], [-4, 5, -4]],
      cells: [[0, 1, 2], [0, 2, 3], [3, 2, 5], [3, 5, 4], [0, 3, 4], [0, 4, 6]],
    }, { color: [0.8, 0.7, 0.6], reflection: 0.6, specular: 0.3 });
    const scene = new Scene({ background: [0.1, 0.2, 0.4], ambient: 0.05, maxDepth: 4 })
      .add(room)
      .add(new Cylinder([1, -1, -9], 1, 2, { color: [0.2, 0.6, 0.9], reflection: 0.3 }))
      .add(new PointLight([-6, 3, -2])) // outside the room's open side: many shadow rays cross its walls
      .add(new PointLight([2, 4, -6]));
    const cam = new Camera({ width: 40, height: 30, fov: 70 });
    expect(prepareFrame(scene, cam).packed).not.toBeNull();
    expect(firstDifference(render(scene, cam), pixelByPixel(scene, cam))).toBe(-1);
  });
});

describe('a scene with the same shape added twice (a slip in a sketch)', () => {
  it('gives trace.js\'s bytes: a glowing ball added twice still does not light itself', () => {
    const lamp = new Sphere([0, 2, -10], 1.5, { color: [0.5, 0.5, 0.5], emission: [1, 0.9, 0.6] });
    const scene = new Scene({ background: [0.1, 0.1, 0.2], ambient: 0.05 })
      .add(lamp)
      .add(new Sphere([0, -1001, -10], 1000, { color: [0.8, 0.8, 0.8] }))
      .add(lamp) // again
      .add(new PointLight([5, 8, 0]));
    const cam = new Camera({ width: 32, height: 24 });
    expect(firstDifference(render(scene, cam), pixelByPixel(scene, cam))).toBe(-1);
  });
});

describe("each run's fresh seed", () => {
  it('is named by a failure, with the command that replays it', () => {
    const neverLarge = fc.property(fc.nat(), (n) => n < 10);
    expect(() => assertFresh(neverLarge, { numRuns: 100 })).toThrow(`SEED=${FRESH_SEED} node_modules/.bin/vitest run ${TEST_FILE}`);
  });

  it('comes from SEED when given, a whole number', () => {
    expect(freshSeed('-1234567')).toBe(-1234567);
    expect(() => freshSeed('12abc')).toThrow('SEED must be a whole number');
    expect(Number.isSafeInteger(freshSeed(undefined))).toBe(true);
  });
});
