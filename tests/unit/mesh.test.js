import { describe, it, expect } from 'vitest';
import bunny from 'bunny';
import { Ray, EPSILON } from '../../lib/index.js';
import { Vec3 } from '../../lib/math/vec3.js';
import { Mesh } from '../../lib/shapes/mesh.js';
import { triangleHit, Triangle } from '../../lib/shapes/triangle.js';
import { seeded, randomDirection } from './convex-reference.js';

/** The loop over every triangle that the BVH must agree with: the nearest t, the lowest index on a tie. */
function bruteForce(mesh, ray) {
  const o = ray.origin, d = ray.direction;
  let best = Infinity, triangle = -1;
  mesh.cells.forEach(([i, j, k], index) => {
    const [a, b, c] = [mesh.positions[i], mesh.positions[j], mesh.positions[k]];
    const t = triangleHit(a[0], a[1], a[2], b[0] - a[0], b[1] - a[1], b[2] - a[2], c[0] - a[0], c[1] - a[1], c[2] - a[2],
      o.x, o.y, o.z, d.x, d.y, d.z, EPSILON);
    if (t < best) { best = t; triangle = index; }
  });
  return { t: best, triangle };
}

/** Rays from around the mesh's box toward points inside it (and a few anywhere). */
function raysAround(mesh, random, count) {
  const { min, max } = mesh.bounds();
  const lo = [min.x, min.y, min.z], hi = [max.x, max.y, max.z].map((h, k) => Math.max(h, lo[k] + 1)); // a flat mesh too
  return Array.from({ length: count }, (_, i) => {
    const origin = lo.map((l, k) => l + (random() * 3 - 1) * (hi[k] - l));
    const aim = lo.map((l, k) => l + random() * (hi[k] - l));
    return new Ray(origin, i % 8 ? aim.map((a, k) => a - origin[k]) : randomDirection(random));
  });
}

function randomSoup(random, count, size) {
  const positions = [], cells = [];
  for (let i = 0; i < count; i++) {
    const centre = [random() * 10 - 5, random() * 10 - 5, random() * 10 - 5];
    for (let k = 0; k < 3; k++) positions.push(centre.map((c) => c + (random() - 0.5) * size));
    cells.push([3 * i, 3 * i + 1, 3 * i + 2]);
  }
  return { positions, cells };
}

function expectSameAsLoop(mesh, rays) {
  let hits = 0;
  for (const ray of rays) {
    const expected = bruteForce(mesh, ray);
    expect(mesh.hit(ray)).toBe(expected.t);
    const record = mesh.intersect(ray);
    expect(record.t ?? Infinity).toBe(expected.t);
    expect(record.triangle ?? -1).toBe(expected.triangle);
    if (expected.t !== Infinity) hits++;
  }
  return hits;
}

describe('the BVH gives the same t and triangle as a loop over every triangle (seeded random rays)', () => {
  it('random soups of big, overlapping triangles and of small ones', () => {
    const random = seeded(7);
    for (const [count, size] of [[300, 6], [2000, 0.8], [5, 3]]) {
      const mesh = new Mesh(randomSoup(random, count, size));
      expect(expectSameAsLoop(mesh, raysAround(mesh, random, 600))).toBeGreaterThan(20);
    }
  });

  it('the bunny (3674 triangles)', () => {
    const mesh = new Mesh(bunny);
    expect(mesh.triangleCount).toBe(3674);
    expect(expectSameAsLoop(mesh, raysAround(mesh, seeded(3674), 1500))).toBeGreaterThan(400);
  });

  it('a soup whose triangles share one spot and one plane (no split helps)', () => {
    const positions = [], cells = [];
    for (let i = 0; i < 40; i++) {
      positions.push([0, 0, 0], [1, i / 40, 0], [0.5, 1, 0]);
      cells.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    const mesh = new Mesh({ positions, cells });
    expect(expectSameAsLoop(mesh, raysAround(mesh, seeded(40), 200))).toBeGreaterThan(20);
  });
});

describe('the record of the BVH\'s work', () => {
  const mesh = new Mesh(bunny);
  it('a ray at the bunny tests a few boxes and triangles, not all 3674', () => {
    const random = seeded(1);
    let triangleTests = 0, boxTests = 0, n = 0;
    for (const ray of raysAround(mesh, random, 300)) {
      const r = mesh.intersect(ray);
      expect(r.bruteForceTests).toBe(3674);
      expect(r.boxesEntered).toBe(r.entered.length);
      expect(r.boxesEntered).toBeLessThanOrEqual(r.boxTests);
      triangleTests += r.triangleTests; boxTests += r.boxTests; n++;
    }
    expect(triangleTests / n).toBeLessThan(0.02 * 3674);
    expect(boxTests / n).toBeLessThan(0.05 * 3674);
  });
  it('names the triangle hit and records its Möller–Trumbore steps', () => {
    const ray = new Ray([0, 5, 20], [0, 0, -1]); // at the bunny's middle, from the front
    const r = mesh.intersect(ray);
    expect(r.triangle).toBe(bruteForce(mesh, ray).triangle);
    expect(r.steps.t).toBe(r.t);
    expect(r.steps.u).toBeGreaterThanOrEqual(0);
    expect(r.steps.u + r.steps.v).toBeLessThanOrEqual(1);
    const box = mesh.bvh.box(r.entered[0]);
    expect(box.min.x).toBeLessThan(-4.9); // the root: around the whole bunny
  });
  it('a miss: t and triangle null, and the one root box tested', () => {
    expect(mesh.intersect(new Ray([100, 0, 0], [0, 1, 0]))).toMatchObject({ t: null, triangle: null, steps: null, boxTests: 1, boxesEntered: 0 });
  });
});

describe('normals', () => {
  const mesh = new Mesh(bunny);
  const front = (i) => Array.from(mesh.normals.subarray(3 * i, 3 * i + 3));
  it('after a hit: the hit triangle\'s unit normal e1 × e2', () => {
    for (const ray of raysAround(mesh, seeded(9), 200)) {
      const t = mesh.hit(ray);
      if (t === Infinity) continue;
      const n = mesh.normalAt(ray.at(t));
      expect([n.x, n.y, n.z]).toEqual(front(bruteForce(mesh, ray).triangle));
      expect(Math.hypot(n.x, n.y, n.z)).toBeCloseTo(1, 12);
    }
  });
  it('with no hit before it, the nearest triangle\'s', () => {
    const tetra = new Mesh({ positions: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], cells: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] });
    expect(tetra.normalAt(new Vec3(0.2, 0.2, 0))).toEqual({ x: 0, y: 0, z: -1 }); // the bottom, facing out
    const n = tetra.normalAt(new Vec3(0.3, 0.3, 0.4)); // on the slanted face
    [n.x, n.y, n.z].forEach((x) => expect(x).toBeCloseTo(1 / Math.sqrt(3), 12));
    expect(tetra.bounds()).toEqual({ min: { x: 0, y: 0, z: 0 }, max: { x: 1, y: 1, z: 1 } });
  });
});

describe('bad data is refused, naming the field', () => {
  const square = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]];
  it.each([
    [{ positions: square, cells: [[0, 1, 2], [0, 2]] }, TypeError, /cells\[1\] must be a triple of vertex indices/],
    [{ positions: square, cells: [[0, 1, 2], [0, 2, 4]] }, RangeError, /cells\[1\]\[2\] must be a whole number from 0 to 3 \(an index into positions\), got 4/],
    [{ positions: square, cells: [[0, 1.5, 2]] }, RangeError, /cells\[0\]\[1\] must be a whole number/],
    [{ positions: square, cells: [[0, 1, 1]] }, RangeError, /cells\[0\]: a, b, c must not lie on one line/],
    [{ positions: [[0, 0, 0], [1, 0, 0], [2, 0, 0]], cells: [[0, 1, 2]] }, RangeError, /cells\[0\]: .*zero area/],
    [{ positions: [[0, 0, 0], [1, NaN, 0], [0, 1, 0]], cells: [[0, 1, 2]] }, TypeError, /positions\[1\]\.y must be a finite number/],
    [{ positions: square, cells: [] }, TypeError, /cells must be a list of triangles/],
    [{ cells: [[0, 1, 2]] }, TypeError, /positions must be a list/],
    [null, TypeError, /mesh data must be \{ positions, cells \}/],
  ])('%#', (data, type, message) => {
    expect(() => new Mesh(data)).toThrow(type);
    expect(() => new Mesh(data)).toThrow(message);
  });
  it('takes {x, y, z} points too, and a name and material', () => {
    const mesh = new Mesh({ positions: [{ x: 0, y: 0, z: 0 }, { x: 1, y: 0, z: 0 }, { x: 0, y: 1, z: 0 }], cells: [[0, 1, 2]] }, { name: 'flag', color: 'red' });
    expect(mesh.name).toBe('flag');
    expect(mesh.hit(new Ray([0.2, 0.2, 1], [0, 0, -1]))).toBe(1);
  });
});

describe('data as written, read as written', () => {
  const square = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]];
  it('a hole in positions or cells is named, not "is not iterable" or a null written back', () => {
    const holeyPositions = [[0, 0, 0], , [1, 1, 0], [0, 1, 0]]; // eslint-disable-line no-sparse-arrays
    expect(() => new Mesh({ positions: holeyPositions, cells: [[0, 2, 3]] })).toThrow(new TypeError('positions[1] is missing (a hole in the list)'));
    const holeyCells = [[0, 1, 2], , [0, 2, 3]]; // eslint-disable-line no-sparse-arrays
    expect(() => new Mesh({ positions: square, cells: holeyCells })).toThrow(new TypeError('cells[1] is missing (a hole in the list)'));
  });

  it('reads positions and cells as the data\'s own fields, not through its prototype', () => {
    const inherited = Object.create({ positions: square, cells: [[0, 1, 2]] });
    expect(() => new Mesh(inherited)).toThrow(/^positions must be a list/);
    expect(() => new Mesh(Object.assign(Object.create({ cells: [[0, 1, 2]] }), { positions: square }))).toThrow(/^cells must be a list/);
  });

  it.each([1e-200, 1e-300, 1e-20, 1e20, 1e30])('a triangle with sides of %s has area: the test is relative to its size, the normal a unit vector', (size) => {
    const positions = [[0, 0, 0], [size, 0, 0], [0, size, 0]];
    const mesh = new Mesh({ positions, cells: [[0, 1, 2]] });
    expect(mesh.normals[2]).toBe(1);
    const n = new Triangle(...positions).normalAt(new Vec3(0, 0, 0));
    expect([n.x, n.y, n.z]).toEqual([0, 0, expect.closeTo(1, 15)]);
    expect(() => new Mesh({ positions: [[0, 0, 0], [size, 0, 0], [size / 2, 0, 0]], cells: [[0, 1, 2]] })).toThrow(/zero area/);
    expect(() => new Triangle([0, 0, 0], [size, size, 0], [size / 2, size / 2, 0])).toThrow(/zero area/);
  });

  it('a side longer than the limit is refused as too long, not as zero area', () => {
    const positions = [[0, 0, 0], [1e200, 0, 0], [0, 1e200, 0]];
    expect(() => new Mesh({ positions, cells: [[0, 1, 2]] })).toThrow(/^cells\[0\]: a side is longer than 1e\+30/);
    expect(() => new Triangle(...positions)).toThrow(/^a side is longer than 1e\+30/);
  });
});

describe('OBJ text (The Ray Tracer Challenge, ch. 15 "OBJ files")', () => {
  it('vertex records', () => {
    const mesh = Mesh.fromOBJ('v -1 1 0\nv -1.0000 0.5000 0.0000\nv 1 0 0\nv 1 1 0\nf 1 2 3\n');
    expect(mesh.positions).toEqual([[-1, 1, 0], [-1, 0.5, 0], [1, 0, 0], [1, 1, 0]]);
  });
  it('triangle faces, with unknown lines and comments skipped', () => {
    const text = 'There was a young lady named Bright\n# a comment\nv -1 1 0\nv -1 0 0\nv 1 0 0\nv 1 1 0\n\ng FirstGroup\nf 1 2 3\nf 1 3 4\n';
    expect(Mesh.fromOBJ(text).cells).toEqual([[0, 1, 2], [0, 2, 3]]);
  });
  it('a polygon becomes a fan of triangles', () => {
    const text = 'v -1 1 0\nv -1 0 0\nv 1 0 0\nv 1 1 0\nv 0 2 0\nf 1 2 3 4 5\n';
    expect(Mesh.fromOBJ(text).cells).toEqual([[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
  });
  it('faces with texture and normal indices, and negative (relative) ones', () => {
    const text = 'v 0 1 0\nv -1 0 0\nv 1 0 0\nvn -1 0 0\nvn 1 0 0\nvn 0 1 0\nf 1//3 2//1 3//2\nf 1/0/3 2/102/1 3/14/2\nf -3 -2 -1\n';
    expect(Mesh.fromOBJ(text).cells).toEqual([[0, 1, 2], [0, 1, 2], [0, 1, 2]]);
  });
  it.each([
    ['v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3', /OBJ line 2: a vertex needs 3 numbers "v x y z", got "v 1 0"/],
    ['v 0 0 0\nv 1 0 zero\nv 0 1 0\nf 1 2 3', /OBJ line 2: a vertex needs 3 numbers/],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9', /OBJ line 5: the face refers to vertex 9, but only 3 vertices are defined above it/],
    ['v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0', /OBJ line 2: the face refers to vertex 2, but only 1 vertex is defined above it/],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0', /OBJ line 4: the face refers to vertex 0/],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3', /OBJ line 4: a face's corners must be vertex numbers/],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2', /OBJ line 4: a face needs at least 3 vertices/],
    ['v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3', /OBJ line 4: a, b, c must not lie on one line/],
    ['There was a young lady named Bright\nwho traveled much faster than light', /OBJ text has no faces/],
  ])('bad text %#: an error with its line number', (text, message) => {
    expect(() => Mesh.fromOBJ(text)).toThrow(RangeError);
    expect(() => Mesh.fromOBJ(text)).toThrow(message);
  });
  it('text that is no string', () => {
    expect(() => Mesh.fromOBJ(42)).toThrow(/OBJ text must be a string, got 42/);
  });
});

