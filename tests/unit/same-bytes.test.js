// The renderer's shortcuts must never show: over random scenes (spheres,
// planes, boxes, cylinders, cones, triangles, meshes, point lights and emissive shapes, mirrors, glass, shadows and
// highlights on or off) and random cameras, render() — which tests each
// primary ray only against its tile's candidate shapes (lib/bounds.js) — gives
// the very bytes of the plain reference, every pixel traced against every
// shape; so does every visual mode, however its pictures are traced; and so
// does a ProgressiveRenderer's finished buffer, in every order; and the
// inspector, which records every step of the same trace, gives render()'s colour.
import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import { Camera, Scene, Sphere, Plane, Box, Cylinder, Cone, Triangle, Mesh, PointLight, SpotLight, AreaLight, render, inspectPixel } from '../../lib/index.js';
import { renderPixel, prepareFrame } from '../../lib/render.js';
import { packScene, tracePrimary, outOfReach } from '../../lib/kernel.js';
import { trace } from '../../lib/trace.js';
import { Ray } from '../../lib/ray.js';
import { Vec3 } from '../../lib/vec3.js';
import { MODES, modeShader } from '../../lib/modes.js';
import { ProgressiveRenderer, ORDERS } from '../../lib/progressive.js';
import { shapeClasses } from '../../lib/shapes/index.js';
import { lightClasses } from '../../lib/lights/index.js';

/**
 * A number in [min, max]: half the time fast-check's own double, drawn to the
 * ends and to tiny values (0, 1, 5e-324), half the time spread evenly, so that
 * colours and places in between, where a last bit shows in a byte, come up too.
 */
const between = (min, max) => fc.oneof(
  fc.double({ min, max, noNaN: true }),
  fc.noBias(fc.integer({ min: 0, max: 2 ** 53 - 1 })).map((n) => Math.min(max, min + (max - min) * (n / 2 ** 53))),
);
const coord = (size) => between(-size, size);
const point = (size) => fc.tuple(coord(size), coord(size), coord(size));
/** Anywhere near the eye, or ahead of it (down −z, where a camera that looks ahead sees it small). */
const place = fc.oneof(point(15), fc.tuple(coord(10), coord(8), between(-40, -3)));
const unit = between(0, 1);
/** Zero half the time: most surfaces are plain, some mirror, some glass, some shine. */
const sometimes = (value) => fc.oneof(fc.constant(0), value);
const color = fc.tuple(unit, unit, unit);

const material = fc.record({
  color,
  emission: fc.oneof({ weight: 3, arbitrary: fc.constant(0) }, { weight: 1, arbitrary: fc.tuple(unit, unit, unit).map((c) => c.map((v) => 2 * v)) }),
  reflection: sometimes(unit),
  transparency: sometimes(unit),
  ior: between(1, 2.5),
  specular: sometimes(unit),
  shininess: between(1, 200),
});

const sphere = fc.tuple(place, fc.oneof(
  { weight: 4, arbitrary: between(0.05, 1.5) }, // small: many tiles leave it out
  { weight: 2, arbitrary: between(0.05, 8) },
  { weight: 1, arbitrary: between(100, 10000) }, // a ground or a wall
), material).map(([center, radius, m]) => new Sphere(center, radius, m));

const direction = point(1).filter(([x, y, z]) => x * x + y * y + z * z > 0.01);
const plane = fc.tuple(point(10), direction, material).map(([p, normal, m]) => new Plane(p, normal, m));

const size = between(0.1, 4);
const box = fc.tuple(place, size, size, size, material)
  .map(([[x, y, z], dx, dy, dz, m]) => new Box([x, y, z], [x + dx, y + dy, z + dz], m));

/** Lights fade with distance now and then (attenuation 0: not at all). */
const attenuation = fc.oneof({ weight: 2, arbitrary: fc.constant(0) }, { weight: 1, arbitrary: between(0, 0.5) });
const pointLight = fc.tuple(point(20), color, between(0, 2), attenuation)
  .map(([position, c, intensity, k]) => (k === 0 ? new PointLight(position, c, intensity) : new PointLight(position, { color: c, intensity, attenuation: k })));
const spotLight = fc.tuple(point(20), point(10), between(1, 89), color, between(0, 2), attenuation)
  .filter(([p, t]) => p.some((v, i) => v !== t[i]))
  .map(([position, target, angle, c, intensity, k]) => new SpotLight(position, target, { angle, color: c, intensity, attenuation: k }));
const areaLight = fc.tuple(point(20), between(0.1, 4), fc.constantFrom(1, 4, 9), direction, color, between(0, 2), attenuation)
  .map(([center, radius, samples, normal, c, intensity, k]) => new AreaLight(center, radius, { samples, normal, color: c, intensity, attenuation: k }));

/**
 * A random one of each listed light class, by its type. The scenes below draw
 * from every class of the list (lib/lights/index.js), so a light is in the
 * property the day it is listed; one listed with no entry here fails the test
 * 'has a random one of every listed shape and light' until it has one.
 */
const LIGHTS = { pointLight: { weight: 3, arbitrary: pointLight }, spotLight: { weight: 1, arbitrary: spotLight }, areaLight: { weight: 1, arbitrary: areaLight } };
const light = fc.oneof(...lightClasses().map((Light) => LIGHTS[Light.type]).filter(Boolean));

/** Cylinders and cones, capped and open. */
const axial = (Shape) => fc.tuple(place, between(0.1, 3), between(0.1, 4), fc.boolean(), material)
  .map(([center, radius, height, capped, m]) => new Shape(center, radius, height, { ...m, capped }));
const cylinder = axial(Cylinder), cone = axial(Cone);

/** Three corners near a place, kept only when they span an area (a Triangle refuses a flat one). */
const corners = fc.tuple(place, point(3), point(3)).filter(([, u, v]) => {
  const cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
  return Math.hypot(cx, cy, cz) > 1e-3 * Math.hypot(...u) * Math.hypot(...v) && Math.hypot(...u) > 0.05 && Math.hypot(...v) > 0.05;
}).map(([[x, y, z], u, v]) => [[x, y, z], [x + u[0], y + u[1], z + u[2]], [x + v[0], y + v[1], z + v[2]]]);
const triangle = fc.tuple(corners, material).map(([[a, b, c], m]) => new Triangle(a, b, c, m));

/** A small mesh: a tetrahedron scaled and placed, or a few separate triangles (enough for the tree to split). */
const tetrahedron = fc.tuple(place, between(0.2, 3), material).map(([[x, y, z], r, m]) => new Mesh({
  positions: [[x, y, z], [x + r, y, z], [x, y + r, z], [x, y, z + r]], cells: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
}, m));
const soup = fc.tuple(fc.array(corners, { minLength: 1, maxLength: 12 }), material).map(([list, m]) => new Mesh({
  positions: list.flat(), cells: list.map((_, i) => [3 * i, 3 * i + 1, 3 * i + 2]),
}, m));
const mesh = fc.oneof(tetrahedron, soup);

/** A scene's switches, and its items drawn from `item`. */
const sceneOf = (item) => fc.record({
  background: color,
  ambient: sometimes(unit),
  shadows: fc.boolean(),
  specular: fc.boolean(),
  maxDepth: fc.integer({ min: 0, max: 4 }),
  bias: fc.constantFrom(1e-4, 0, 0.01),
  epsilon: fc.constantFrom(1e-6, 0),
  items: fc.array(item, { minLength: 1, maxLength: 7 }),
  again: fc.oneof({ weight: 9, arbitrary: fc.constant(null) }, { weight: 1, arbitrary: fc.nat() }), // now and then one item added twice
}).map(({ items, again, ...options }) => [...items, ...(again === null ? [] : [items[again % items.length]])]
  .reduce((s, it) => s.add(it), new Scene(options)));

const scene = sceneOf(fc.oneof({ weight: 5, arbitrary: sphere }, { weight: 1, arbitrary: plane }, { weight: 3, arbitrary: box }, { weight: 2, arbitrary: light }));
/**
 * A random one of each listed shape class, by its type, as LIGHTS: the scenes
 * of every listed shape draw from the list (lib/shapes/index.js).
 */
const SHAPES = {
  sphere: { weight: 2, arbitrary: sphere }, plane: { weight: 1, arbitrary: plane }, box: { weight: 1, arbitrary: box },
  cylinder: { weight: 2, arbitrary: cylinder }, cone: { weight: 2, arbitrary: cone }, triangle: { weight: 2, arbitrary: triangle }, mesh: { weight: 2, arbitrary: mesh },
};
/** Every listed shape (the course's cylinders, cones, triangles and small meshes among spheres, planes and boxes) and every listed light. */
const shapeScene = sceneOf(fc.oneof(...shapeClasses().map((Shape) => SHAPES[Shape.type]).filter(Boolean), { weight: 2, arbitrary: light }));
/** The lesson's scenes: spheres only (the fast path then skips asking each shape its kind), lit by their glow and point lights. */
const sphereScene = sceneOf(fc.oneof({ weight: 3, arbitrary: sphere }, { weight: 1, arbitrary: light }));

/** Small frames of a few tiles (16 px), rarely whole ones; from anywhere looking anywhere, or from near the origin looking ahead. */
const camera = fc.record({
  width: fc.integer({ min: 1, max: 48 }),
  height: fc.integer({ min: 1, max: 36 }),
  fov: fc.oneof(between(10, 60), between(10, 150)),
  yaw: fc.oneof(between(-30, 30), between(-180, 180)),
  pitch: fc.oneof(between(-20, 20), between(-89, 89)),
  position: fc.oneof(point(2), point(6)),
}).map((options) => new Camera(options));

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

  it('render() takes the fast path (lib/kernel.js) for scenes of plain shapes, and for spheres only gives the same bytes', () => {
    assertBoth(fc.property(scene, camera, (s, cam) => {
      const twice = new Set(s.objects).size !== s.objects.length; // left to trace.js (see below)
      expect(prepareFrame(s, cam).packed === null).toBe(twice); // so the tests above compare lib/kernel.js with trace.js
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
