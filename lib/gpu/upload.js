/**
 * The packed scene (lib/tracing/kernel.js PackedScene: the shapes' numbers, their
 * materials, the lights, the side tables) as the float arrays the GPU engine
 * uploads, one texture each, in rows of ROW numbers: the same numbers in the
 * same places, as float32. No WebGL here, so Node can test it.
 *
 * The side tables become one array: first each table's start, then the
 * tables. A triangle's table is its 12 numbers as they are; a mesh's is five
 * starts (its tree's boxes, nodes and order, its corners in the tree's
 * order, its triangles' normals) followed by those arrays (lib/shapes/bvh.js).
 */
import { PackedScene, unpackable } from '../tracing/kernel.js';
import { SHAPE_CODES, MAX_KINDS, BVH_STACK, ROW } from './glsl-kernel.js';
import { SHAPE, KIND } from '../shapes/packed.js';

/** Who asks, for the errors: renderGPU's words, or the path tracer's (lib/gpu/path-trace-gpu.js). */
export const WHITTED = Object.freeze({ cannot: 'renderGPU cannot draw', cpu: 'render() draws it on the CPU' });

/**
 * The packed scene as float32 arrays, and the map from the kernel's kind
 * numbers to the shader's shape codes. An Error naming the shape when one
 * cannot be drawn on the GPU (in the words of `who`).
 * @param {import('../scene/scene.js').Scene} scene
 * @param {{ cannot: string, cpu: string }} [who]
 * @returns {{ packed: PackedScene, shapes: Float32Array, materials: Float32Array, lights: Float32Array, apart: Float32Array, tables: Float32Array, kindTypes: Int32Array }}
 */
export function gpuScene(scene, who = WHITTED) {
  const problem = unpackable(scene); // the kernel's one answer: the GPU reads the packed scene
  if (problem) throw new Error(`${who.cannot} ${nameOf(scene.objects[problem.index], problem.index)}: ${problem.why}; ${who.cpu}`);
  scene.objects.forEach((object, i) => {
    const { type } = object.constructor;
    if (!(type in SHAPE_CODES)) throw new Error(`${who.cannot} ${nameOf(object, i)}: the GPU engine has no ${type} (it draws ${Object.keys(SHAPE_CODES).join(', ')})`);
  });
  const packed = new PackedScene(scene);
  const kindTypes = new Int32Array(MAX_KINDS).fill(-1);
  scene.objects.forEach((object, i) => {
    const kind = packed.shapes[i * SHAPE + KIND];
    if (kind >= MAX_KINDS) throw new Error(`${who.cannot} ${nameOf(object, i)}: more than ${MAX_KINDS} shape classes met`);
    kindTypes[kind] = SHAPE_CODES[object.constructor.type];
  });
  return {
    packed, kindTypes,
    shapes: Float32Array.from(packed.shapes),
    materials: Float32Array.from(packed.materials),
    lights: Float32Array.from(packed.lights),
    apart: Float32Array.from(packed.apart, (a) => Math.max(a, -3e38)), // −Infinity: never skipped
    tables: flattenTables(packed.tables, scene, who),
  };
}

/** "shape 3 ("lamp", a Torus)": which shape, for an error. */
function nameOf(object, i) {
  const kind = object?.constructor?.name ?? typeof object;
  return `shape ${i} (${object?.name ? `"${object.name}", ` : ''}a ${kind})`;
}

/** The side tables in one array: their starts, then each table. */
function flattenTables(tables, scene, who) {
  const parts = tables.map((table) => (ArrayBuffer.isView(table) ? [table] : meshTable(table, scene, who)));
  const starts = [];
  let at = tables.length;
  for (const part of parts) {
    starts.push(at);
    at += part.reduce((n, array) => n + array.length, 0);
  }
  const flat = new Float32Array(Math.max(at, 1));
  flat.set(starts, 0);
  parts.forEach((part, t) => {
    let offset = starts[t];
    for (const array of part) { flat.set(array, offset); offset += array.length; }
    if (!ArrayBuffer.isView(tables[t])) for (let k = 0; k < MESH_HEADER; k++) flat[starts[t] + k] += starts[t]; // a mesh's starts, made absolute
  });
  return flat;
}

/** Numbers before a mesh's arrays in its table: where each of the five starts. */
const MESH_HEADER = 5;

/** A mesh's table: the starts of its boxes, nodes, order, corners and normals, then those. */
function meshTable(mesh, scene, who) {
  const { bvh } = mesh;
  if (bvh.depth + 2 > BVH_STACK) {
    throw new Error(`${who.cannot} ${nameOf(mesh, scene.objects.indexOf(mesh))}: its tree is ${bvh.depth} deep, the GPU's walk goes to ${BVH_STACK - 2}`);
  }
  const arrays = [bvh.boxes.subarray(0, 6 * bvh.nodeCount), bvh.nodes.subarray(0, 2 * bvh.nodeCount), bvh.order, mesh.corners, mesh.normals];
  const starts = [];
  let at = MESH_HEADER; // from the table's start: flattenTables adds where the table lies

  for (const array of arrays) { starts.push(at); at += array.length; }
  return [Float64Array.from(starts), ...arrays];
}

/** Rows of ROW numbers for a texture: the array padded to whole rows (at least one). */
export function inRows(numbers) {
  const rows = Math.max(1, Math.ceil(numbers.length / ROW));
  if (numbers.length === rows * ROW) return { data: numbers, rows };
  const data = new Float32Array(rows * ROW);
  data.set(numbers);
  return { data, rows };
}
