/**
 * A triangle mesh (a bunny, a teapot): many triangles under a bounding
 * volume hierarchy (lib/shapes/bvh.js), so a ray tests the few triangles in the
 * boxes it passes through: the same nearest t as a loop over every triangle,
 * at a cost that grows with the log of their number.
 */
import { toVec3, Vec3, set } from '../math/vec3.js';
import { show } from '../text/check.js';
import { shapeOptions } from './material.js';
import { EPSILON } from '../math/constants.js';
import { BVH } from './bvh.js';
import { intersectTriangle, FLAT, edgeScale, checkSides } from './triangle.js';
import { parseOBJ } from './obj.js';
import { materialToJSON } from './json.js';
import { meshTriangles } from './tessellate.js';
import { P, N, sideTables } from './packed.js';

export class Mesh {
  /**
   * @param {{ positions: number[][], cells: number[][] }} data the vertices `[x, y, z]`
   *   and the triangles, each 3 indices into positions, counterclockwise seen from the front
   * @param {import('./material.js').Material|object} [options] a Material or its options, which may also give the shape a `name`
   * @example
   * // the Stanford bunny (npm package bunny): new Mesh(bunny, { color: [0.9, 0.8, 0.7] }), bunny being { positions, cells }
   * const tetra = new Mesh({ positions: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], cells: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] });
   * // from an OBJ file's text: its v lines are the positions, each f line a face (a square becomes 2 triangles)
   * const square = Mesh.fromOBJ('v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n', { color: 'teal' });
   */
  constructor(data, options) {
    const { positions, cells: given } = checkData(data);
    const shape = shapeOptions(options);
    this.name = shape.name;
    this.material = shape.material;
    this.positions = positions;
    this.vertices = Float64Array.from(positions.flat());
    // A triangle of no area (real OBJ files and UV spheres have some) shows nothing: left out, and counted.
    const flat = [], normals = triangleNormals(this.vertices, Int32Array.from(given.flat()), flat);
    if (flat.length === given.length) {
      throw new RangeError(`cells[${flat[0]}]: a, b, c must not lie on one line: the triangle has zero area${given.length > 1 ? `, as have all ${given.length} triangles` : ''}`);
    }
    /** Indices into the cells given of the zero-area triangles left out. */
    this.zeroAreaCells = flat;
    const left = new Set(flat), cells = flat.length ? given.filter((_, i) => !left.has(i)) : given;
    this.cells = cells;
    this.triangleCount = cells.length;
    this.indices = Int32Array.from(cells.flat());
    this.normals = flat.length ? triangleNormals(this.vertices, this.indices) : normals;
    this.bvh = new BVH(triangleBoxes(this.vertices, this.indices));
    this.corners = cornersInOrder(this.vertices, this.indices, this.bvh.order);
    this.size = boxSize(this.bounds());
    this.lastTriangle = -1;
  }

  /**
   * A Mesh from Wavefront OBJ text: its `v x y z` lines are the positions and
   * each `f` line a face (indices from 1, or from the end when negative;
   * `f 1/4/2 …` keeps the first number of each), a face of n corners fanned
   * into n − 2 triangles; other statements are passed over, and a malformed
   * `v` or `f` line is a RangeError naming its line (lib/shapes/obj.js).
   * @param {string} text
   * @param {import('./material.js').Material|object} [options]
   */
  static fromOBJ(text, options) {
    return new Mesh(parseOBJ(text), options);
  }

  /** Smallest t > tMin where the ray meets a triangle, or Infinity; remembers which (for normalAt). */
  hit(ray, tMin = EPSILON) {
    this.lastTriangle = this.bvh.nearest(ray, tMin, this.corners);
    return this.bvh.t;
  }

  /**
   * The record of the BVH's work, written into `target`: `boxTests` (slab
   * tests), `boxesEntered` and `entered` (those boxes' node numbers, see
   * `bvh.box(i)`), `triangleTests` (Möller–Trumbore tests) beside
   * `bruteForceTests` (what a loop over every triangle would do: all of them),
   * `triangle` (the index into cells of the triangle hit, or null), `steps`
   * (its Möller–Trumbore record) and `t`, the nearest hit past EPSILON or null.
   */
  intersect(ray, target = {}) {
    const stats = { boxTests: 0, boxesEntered: 0, entered: [], itemTests: 0 };
    const triangle = this.bvh.nearest(ray, EPSILON, this.corners, stats);
    const t = this.bvh.t;
    this.lastTriangle = triangle;
    Object.assign(target, {
      boxTests: stats.boxTests, boxesEntered: stats.boxesEntered, entered: stats.entered,
      triangleTests: stats.itemTests, bruteForceTests: this.triangleCount,
      triangle: triangle >= 0 ? triangle : null,
      steps: triangle >= 0 ? intersectTriangle(ray, ...this.cells[triangle].map((i) => new Vec3(...this.positions[i]))) : null,
      t: t === Infinity ? null : t,
    });
    return target;
  }

  /**
   * One ray's walk down the BVH, for a view of the tree: `boxTests` (slab
   * tests), `boxesEntered` (the node numbers of the boxes it went into, in
   * order; `bvh.box(i)` is each one's box), `triangleTests`, `triangle` (the
   * index into cells of the nearest hit, −1 when none), `t` (Infinity when
   * none) and `loopCost`, what a loop over every triangle would test.
   * @param {import('../math/ray.js').Ray} ray
   */
  walk(ray) {
    const stats = { boxTests: 0, boxesEntered: 0, entered: [], itemTests: 0 };
    const triangle = this.bvh.nearest(ray, EPSILON, this.corners, stats);
    return { boxTests: stats.boxTests, boxesEntered: stats.entered, triangleTests: stats.itemTests, triangle, t: this.bvh.t, loopCost: this.triangleCount };
  }

  /**
   * The unit normal (front side, e1 × e2) of the triangle `point` lies on:
   * the last hit's when the point is on it (as after hit or intersect),
   * else the nearest triangle's (a loop over all of them).
   */
  normalAt(point, out = new Vec3()) {
    let triangle = this.lastTriangle;
    const near = 1e-7 * (this.size + Math.abs(point.x) + Math.abs(point.y) + Math.abs(point.z));
    if (triangle < 0 || this.distanceTo(triangle, point) > near) triangle = this.nearestTriangle(point);
    const n = this.normals, j = 3 * triangle;
    return set(out, n[j], n[j + 1], n[j + 2]);
  }

  /** The index of the triangle nearest to `point`. */
  nearestTriangle(point) {
    let best = 0, bestDistance = Infinity;
    for (let i = 0; i < this.triangleCount; i++) {
      const d = this.distanceTo(i, point);
      if (d < bestDistance) { bestDistance = d; best = i; }
    }
    return best;
  }

  /**
   * The distance from `point` to triangle i: to its plane when it lies over
   * the triangle, else to its nearest edge. Numbers only: normalAt runs once a pixel.
   */
  distanceTo(i, point) {
    const v = this.vertices, ia = 3 * this.indices[3 * i], ib = 3 * this.indices[3 * i + 1], ic = 3 * this.indices[3 * i + 2];
    const ax = v[ia], ay = v[ia + 1], az = v[ia + 2];
    const e1x = v[ib] - ax, e1y = v[ib + 1] - ay, e1z = v[ib + 2] - az;
    const e2x = v[ic] - ax, e2y = v[ic + 1] - ay, e2z = v[ic + 2] - az;
    const wx = point.x - ax, wy = point.y - ay, wz = point.z - az;
    const d00 = e1x * e1x + e1y * e1y + e1z * e1z, d01 = e1x * e2x + e1y * e2y + e1z * e2z;
    const d11 = e2x * e2x + e2y * e2y + e2z * e2z;
    const d20 = wx * e1x + wy * e1y + wz * e1z, d21 = wx * e2x + wy * e2y + wz * e2z;
    const denominator = d00 * d11 - d01 * d01;
    const s = (d11 * d20 - d01 * d21) / denominator, t = (d00 * d21 - d01 * d20) / denominator; // point ≈ a + s·e1 + t·e2
    if (s >= 0 && t >= 0 && s + t <= 1) {
      const n = this.normals;
      return Math.abs(wx * n[3 * i] + wy * n[3 * i + 1] + wz * n[3 * i + 2]);
    }
    return Math.min(toSegment(point, v, ia, ib), toSegment(point, v, ib, ic), toSegment(point, v, ic, ia));
  }

  /** The world-space box around every vertex. */
  bounds() {
    const min = new Vec3(Infinity, Infinity, Infinity), max = new Vec3(-Infinity, -Infinity, -Infinity);
    for (const [x, y, z] of this.positions) {
      set(min, Math.min(min.x, x), Math.min(min.y, y), Math.min(min.z, z));
      set(max, Math.max(max.x, x), Math.max(max.y, y), Math.max(max.z, z));
    }
    return { min, max };
  }
  /** The record's lines for the inspector: the BVH's work beside a loop over every triangle, and t. */
  recordRows(record) {
    const rows = [['box tests', record.boxTests], ['triangle tests', record.triangleTests], ['a loop would test', this.triangleCount], ['t', record.t]];
    return this.zeroAreaCells.length ? [...rows, ['zero-area triangles left out', this.zeroAreaCells.length]] : rows;
  }

  /** Draws itself into a 3D view's mesh with the view's own tools (lib/p5/scene-view/mesh.js). */
  drawIn3D(kit, into, rgb) {
    kit.triangles(into, meshTriangles(this.vertices, this.indices), rgb);
  }

  /** Its scene JSON (lib/scene/json.js): its positions and cells. */
  toJSON() {
    return { type: 'mesh', name: this.name ?? '', positions: this.positions.map((p) => [...p]), cells: this.cells.map((c) => [...c]), material: materialToJSON(this.material) };
  }

  /** Its type in scene JSON. */
  static get type() { return 'mesh'; }
  /** The class's name in the code that builds it (lib/scene/json.js, sceneToCode). */
  static get codeName() { return 'Mesh'; }
  /** What its drawing in the 3D view depends on (the view's mesh cache, lib/p5/scene-view/mesh.js). */
  viewKey() { return meshKey(this); }

  /** Its JSON fields. */
  static get fields() { return ['positions', 'cells', 'material']; }
  /** The triangles its JSON makes, counted before any check (lib/scene/work.js), and the field that says so. */
  static workOf(o) { return { triangles: Array.isArray(o.cells) ? o.cells.length : 0, field: 'cells' }; }

  /** A mesh from its fields (checked by the constructor). */
  static build(o, material) {
    return new Mesh({ positions: o.positions, cells: o.cells }, material);
  }

  /**
   * A mesh checked again as it is now (a restart's check, lib/scene/check.js):
   * when its positions and cells still hold what it was built from, nothing
   * is built (restarts built every BVH again: 4 s for a million triangles);
   * when they were changed in place, they are checked as the constructor
   * does and the mesh takes the new triangles and BVH.
   */
  static check(mesh, material) {
    if (sameData(mesh)) return;
    const fresh = new Mesh({ positions: mesh.positions, cells: mesh.cells }, material);
    for (const key of ['positions', 'cells', 'triangleCount', 'vertices', 'indices', 'normals', 'bvh', 'corners', 'size']) mesh[key] = fresh[key];
    mesh.lastTriangle = -1;
  }

  /** Its constructor's arguments in scene code: the data, then the material. */
  static codeArguments(o, material) {
    return [{ positions: o.positions, cells: o.cells }, material];
  }

  /** Its packed form for render()'s kernel (lib/shapes/packed.js): its side table's index (the mesh itself, for its tree). */
  static get packed() { return PACKED; }
}

/** normalAt's point and normal for the packed form (no allocation per ray). */
const _point = new Vec3(), _normal = new Vec3();

const PACKED = Object.freeze({
  pack(mesh, shapes, at, tables) {
    shapes[at] = tables.push(mesh) - 1;
  },
  /** Mesh#hit in numbers: the same walk of its tree, remembering the triangle as hit does. */
  hit(s, b, ox, oy, oz, dx, dy, dz, tMin) {
    const mesh = sideTables.current[s[b]], bvh = mesh.bvh;
    mesh.lastTriangle = bvh.nearestAlong(ox, oy, oz, dx, dy, dz, tMin, mesh.corners);
    return bvh.t;
  },
  /** Mesh#normalAt itself, at the point in `surface` (the last hit's triangle, as in trace.js). */
  normal(s, b, surface) {
    const n = sideTables.current[s[b]].normalAt(set(_point, surface[P], surface[P + 1], surface[P + 2]), _normal);
    surface[N] = n.x; surface[N + 1] = n.y; surface[N + 2] = n.z;
  },
});

/** `data`'s positions and cells, checked and copied as plain lists; an error names the field. */
function checkData(data) {
  if (!data || typeof data !== 'object') throw new TypeError(`mesh data must be { positions, cells }, got ${show(data)}`);
  const positions = Object.hasOwn(data, 'positions') ? data.positions : undefined; // its own fields: nothing from a prototype
  const cells = Object.hasOwn(data, 'cells') ? data.cells : undefined;
  if (!Array.isArray(positions) || positions.length < 3) {
    throw new TypeError(`positions must be a list of at least 3 points [x, y, z], got ${show(positions)}`);
  }
  if (!Array.isArray(cells) || cells.length < 1) {
    throw new TypeError(`cells must be a list of triangles [i, j, k], at least one, got ${show(cells)}`);
  }
  const points = new Array(positions.length);
  for (let i = 0; i < positions.length; i++) {
    const p = entry(positions, i, 'positions');
    points[i] = isTriple(p) ? [p[0], p[1], p[2]] : vec3List(p, `positions[${i}]`);
  }
  const checkedCells = new Array(cells.length);
  for (let i = 0; i < cells.length; i++) checkedCells[i] = checkCell(entry(cells, i, 'cells'), i, points.length);
  return { positions: points, cells: checkedCells };
}

/** list[i], or a TypeError when it is a hole (map and flat pass over holes, so they came out later as odd errors or nulls). */
function entry(list, i, field) {
  if (!Object.hasOwn(list, i)) throw new TypeError(`${field}[${i}] is missing (a hole in the list)`);
  return list[i];
}

/** cells[i] as [i, j, k], each a whole index into `count` positions. */
function checkCell(cell, i, count) {
  const list = /** @type {ArrayLike<number>} */ (cell);
  if (!(Array.isArray(cell) || ArrayBuffer.isView(cell)) || list.length !== 3) {
    throw new TypeError(`cells[${i}] must be a triple of vertex indices [i, j, k], got ${show(cell)}`);
  }
  for (let k = 0; k < 3; k++) {
    const index = list[k];
    if (!Number.isInteger(index) || index < 0 || index >= count) {
      throw new RangeError(`cells[${i}][${k}] must be a whole number from 0 to ${count - 1} (an index into positions), got ${show(index)}`);
    }
  }
  return [list[0], list[1], list[2]];
}

/** Do the mesh's positions and cells hold just the numbers it was built from? One pass, no allocation. */
function sameData({ positions, cells, vertices, indices }) {
  if (!Array.isArray(positions) || !Array.isArray(cells) || 3 * positions.length !== vertices.length || 3 * cells.length !== indices.length) return false;
  for (let i = 0; i < positions.length; i++) {
    const p = positions[i];
    if (!Array.isArray(p) || p.length !== 3 || p[0] !== vertices[3 * i] || p[1] !== vertices[3 * i + 1] || p[2] !== vertices[3 * i + 2]) return false;
  }
  for (let i = 0; i < cells.length; i++) {
    const c = cells[i];
    if (!Array.isArray(c) || c.length !== 3 || c[0] !== indices[3 * i] || c[1] !== indices[3 * i + 1] || c[2] !== indices[3 * i + 2]) return false;
  }
  return true;
}

/** Is p already three finite numbers [x, y, z] (the common case, checked without a Vec3)? */
function isTriple(p) {
  return Array.isArray(p) && p.length === 3 && Number.isFinite(p[0]) && Number.isFinite(p[1]) && Number.isFinite(p[2]) &&
    typeof p[0] === 'number' && typeof p[1] === 'number' && typeof p[2] === 'number';
}

/** Any other point form toVec3 takes ({x, y, z}, a typed array), or its error naming `field`. */
function vec3List(p, field) {
  const v = toVec3(p, field);
  return [v.x, v.y, v.z];
}

/** Every triangle's box, 6 numbers each (the BVH's items). */
function triangleBoxes(vertices, indices) {
  const boxes = new Float64Array(2 * indices.length);
  for (let i = 0; i < indices.length / 3; i++) {
    for (let a = 0; a < 3; a++) {
      const p = vertices[3 * indices[3 * i] + a], q = vertices[3 * indices[3 * i + 1] + a], r = vertices[3 * indices[3 * i + 2] + a];
      boxes[6 * i + a] = Math.min(p, q, r);
      boxes[6 * i + 3 + a] = Math.max(p, q, r);
    }
  }
  return boxes;
}

/** Corner a and edges e1 = b − a, e2 = c − a of every triangle, 9 numbers each, in the BVH's order: a leaf's triangles sit side by side. */
function cornersInOrder(vertices, indices, order) {
  const corners = new Float64Array(3 * indices.length);
  for (let k = 0; k < order.length; k++) {
    const i = order[k], ia = 3 * indices[3 * i], ib = 3 * indices[3 * i + 1], ic = 3 * indices[3 * i + 2];
    for (let a = 0; a < 3; a++) {
      corners[9 * k + a] = vertices[ia + a];
      corners[9 * k + 3 + a] = vertices[ib + a] - vertices[ia + a];
      corners[9 * k + 6 + a] = vertices[ic + a] - vertices[ia + a];
    }
  }
  return corners;
}

/**
 * Every triangle's unit normal e1 × e2, 3 numbers each, in cells' order. A
 * triangle of (next to) no area, as a Triangle judges it, goes into `flat` when
 * given (its normal stays 0), else it is a RangeError naming the cell.
 */
function triangleNormals(vertices, indices, flat) {
  const normals = new Float64Array(indices.length);
  for (let i = 0; i < indices.length / 3; i++) {
    const ia = 3 * indices[3 * i], ib = 3 * indices[3 * i + 1], ic = 3 * indices[3 * i + 2];
    let e1x = vertices[ib] - vertices[ia], e1y = vertices[ib + 1] - vertices[ia + 1], e1z = vertices[ib + 2] - vertices[ia + 2];
    let e2x = vertices[ic] - vertices[ia], e2y = vertices[ic + 1] - vertices[ia + 1], e2z = vertices[ic + 2] - vertices[ia + 2];
    checkSides(e1x, e1y, e1z, e2x, e2y, e2z, `cells[${i}]: `);
    const k = edgeScale(e1x, e1y, e1z, e2x, e2y, e2z); // exact: the same bits, the test relative to the size
    e1x *= k; e1y *= k; e1z *= k; e2x *= k; e2y *= k; e2z *= k;
    const nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
    const length = Math.hypot(nx, ny, nz);
    if (!(length > FLAT * Math.hypot(e1x, e1y, e1z) * Math.hypot(e2x, e2y, e2z))) {
      if (flat) { flat.push(i); continue; }
      throw new RangeError(`cells[${i}]: a, b, c must not lie on one line: the triangle has zero area`);
    }
    normals[3 * i] = nx / length; normals[3 * i + 1] = ny / length; normals[3 * i + 2] = nz / length;
  }
  return normals;
}

function boxSize({ min, max }) {
  return Math.hypot(max.x - min.x, max.y - min.y, max.z - min.z);
}

/** The distance from p to the segment between the vertices at v[i] and v[j]. */
function toSegment(p, v, i, j) {
  const abx = v[j] - v[i], aby = v[j + 1] - v[i + 1], abz = v[j + 2] - v[i + 2];
  const apx = p.x - v[i], apy = p.y - v[i + 1], apz = p.z - v[i + 2];
  const s = Math.min(1, Math.max(0, (apx * abx + apy * aby + apz * abz) / (abx * abx + aby * aby + abz * abz)));
  return Math.hypot(apx - s * abx, apy - s * aby, apz - s * abz);
}

/** Each mesh's number, in the order they were first drawn: a mesh's triangles are fixed once built (its tree is built on them), so the mesh itself is its key. */
const MESH_KEYS = new WeakMap();
let meshes = 0;
function meshKey(mesh) {
  if (!MESH_KEYS.has(mesh)) MESH_KEYS.set(mesh, `mesh ${++meshes}`);
  return MESH_KEYS.get(mesh);
}
