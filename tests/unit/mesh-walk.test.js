// mesh.walk(ray): one ray's walk down the BVH, as the BVH view of sketch 13 draws it.
// Its counts are checked against the tree itself (walked here, not by the BVH's code),
// its boxes against a slab test of our own, its triangle against a loop over every triangle.
import { describe, it, expect } from 'vitest';
import bunny from 'bunny';
import { Ray, EPSILON } from '../../lib/index.js';
import { Mesh } from '../../lib/shapes/mesh.js';
import { triangleHit } from '../../lib/shapes/triangle.js';
import { seeded } from './convex-reference.js';

const mesh = new Mesh(bunny);

function bruteForce(ray) {
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

/** Where the ray is inside node i's box: [tIn, tOut], or null when it misses it. */
function slab(ray, i) {
  const { min, max } = mesh.bvh.box(i);
  let tIn = -Infinity, tOut = Infinity;
  for (const a of ['x', 'y', 'z']) {
    const o = ray.origin[a], d = ray.direction[a];
    if (d === 0) { if (o < min[a] || o > max[a]) return null; continue; }
    let lo = (min[a] - o) / d, hi = (max[a] - o) / d;
    if (lo > hi) [lo, hi] = [hi, lo];
    tIn = Math.max(tIn, lo); tOut = Math.min(tOut, hi);
  }
  return tIn <= tOut && tOut >= EPSILON ? [tIn, tOut] : null;
}

/** Each node's parent, and each leaf's triangles, read from the tree's arrays. */
function readTree() {
  const { nodes, order, nodeCount } = mesh.bvh;
  const parent = new Map([[0, -1]]), leafTriangles = new Map();
  for (let node = 0; node < nodeCount; node++) {
    const first = nodes[2 * node], n = nodes[2 * node + 1];
    if (n === 0) { parent.set(first, node); parent.set(first + 1, node); } else leafTriangles.set(node, Array.from(order.subarray(first, first + n)));
  }
  return { parent, leafTriangles };
}

function raysAtTheBunny(random, count) {
  const { min, max } = mesh.bounds();
  return Array.from({ length: count }, () => {
    const origin = [random() * 40 - 20, random() * 40 - 10, 25];
    const aim = [min.x + random() * (max.x - min.x), min.y + random() * (max.y - min.y), min.z + random() * (max.z - min.z)];
    return new Ray(origin, aim.map((a, k) => a - origin[k]));
  });
}

describe('mesh.walk(ray)', () => {
  const { parent, leafTriangles } = readTree();
  const rays = raysAtTheBunny(seeded(13), 200);

  it('finds the triangle a loop over every triangle finds, and says what that loop costs', () => {
    let hits = 0;
    for (const ray of rays) {
      const walk = mesh.walk(ray), expected = bruteForce(ray);
      expect(walk.triangle).toBe(expected.triangle);
      expect(walk.t).toBe(expected.t);
      expect(walk.loopCost).toBe(3674);
      if (walk.triangle >= 0) hits++;
    }
    expect(hits).toBeGreaterThan(50); // the rays do meet the bunny
  });

  it('counts its tests as the tree says: 1 for the root, 2 for each inner box entered, a leaf\'s triangles for each leaf', () => {
    for (const ray of rays) {
      const walk = mesh.walk(ray);
      const inner = walk.boxesEntered.filter((node) => !leafTriangles.has(node));
      const leaves = walk.boxesEntered.filter((node) => leafTriangles.has(node));
      expect(walk.boxTests).toBe(1 + 2 * inner.length);
      expect(walk.triangleTests).toBe(leaves.reduce((sum, leaf) => sum + leafTriangles.get(leaf).length, 0));
      expect(new Set(walk.boxesEntered).size).toBe(walk.boxesEntered.length); // none twice
      if (walk.triangle >= 0) {
        expect(walk.boxesEntered[0]).toBe(0); // the root first
        expect(leaves.some((leaf) => leafTriangles.get(leaf).includes(walk.triangle))).toBe(true); // the hit's own leaf was entered
        expect(walk.triangleTests).toBeLessThan(0.05 * walk.loopCost);
      }
    }
  });

  it('enters only boxes the ray really passes through, each inside a box entered before it', () => {
    for (const ray of rays) {
      const walk = mesh.walk(ray), seen = new Set();
      for (const node of walk.boxesEntered) {
        const span = slab(ray, node);
        expect(span).not.toBeNull();
        if (node !== 0) expect(seen.has(parent.get(node))).toBe(true);
        seen.add(node);
      }
    }
  });

  it('a ray past the bunny tests the root box only, enters none and hits nothing', () => {
    expect(mesh.walk(new Ray([100, 0, 0], [0, 1, 0]))).toEqual({ boxTests: 1, boxesEntered: [], triangleTests: 0, triangle: -1, t: Infinity, loopCost: 3674 });
  });
});
