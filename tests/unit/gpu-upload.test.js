// The GPU engine's upload (lib/gpu/upload.js): the packed scene the kernel
// reads, as float32, the same numbers in the same places; a mesh's side table
// points at its tree; a shape the GPU cannot draw is named. And in Node,
// lib/index.js imports with renderGPU in it, which says it needs a browser.
import { describe, it, expect } from 'vitest';
import { classScene, Scene, Sphere, Mesh, Triangle, PointLight, Camera, renderGPU } from '../../lib/index.js';
import { gpuScene, inRows } from '../../lib/gpu/upload.js';
import { packScene } from '../../lib/tracing/kernel.js';
import { LIGHT, LIGHT_EMISSION } from '../../lib/lights/packed.js';
import { MATERIAL_NUMBERS, MATERIAL_AT } from '../../lib/shapes/material.js';
import { SHAPE, KIND } from '../../lib/shapes/packed.js';
import { SHAPE_CODES, ROW, kernelSource } from '../../lib/gpu/glsl-kernel.js';

describe('gpuScene: the packed scene as float32', () => {
  it('the class scene: the kernel\'s shapes, materials and lights, number for number', () => {
    const scene = classScene({ full: true }), numbers = gpuScene(scene), packed = packScene(scene);
    expect([...numbers.shapes]).toEqual([...packed.shapes].map(Math.fround));
    expect([...numbers.materials]).toEqual([...packed.materials].map(Math.fround));
    expect([...numbers.lights]).toEqual([...packed.lights].map(Math.fround));
    expect(numbers.kindTypes[packed.shapes[KIND]]).toBe(SHAPE_CODES.sphere);
  });

  it('a triangle\'s and a mesh\'s side tables: each table\'s start, then the tables; a mesh\'s starts point at its tree and corners', () => {
    const mesh = new Mesh({ positions: [[0, 0, -5], [1, 0, -5], [0, 1, -5], [0, 0, -6]], cells: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] });
    const triangle = new Triangle([0, 0, -3], [1, 0, -3], [0, 1, -3]);
    const scene = new Scene().add(triangle).add(mesh).add(new PointLight([0, 5, 0]));
    const { tables, shapes, kindTypes } = gpuScene(scene);
    const tableOf = (i) => tables[shapes[i * SHAPE]];
    expect(kindTypes[shapes[KIND]]).toBe(SHAPE_CODES.triangle);
    expect(kindTypes[shapes[SHAPE + KIND]]).toBe(SHAPE_CODES.mesh);
    expect([...tables.subarray(tableOf(0), tableOf(0) + 3)]).toEqual([0, 0, -3]); // corner a
    const at = tableOf(1), [boxes, nodes, order, corners, normals] = tables.subarray(at, at + 5);
    expect([...tables.subarray(boxes, boxes + 6)]).toEqual([...mesh.bvh.boxes.subarray(0, 6)].map(Math.fround));
    expect([...tables.subarray(nodes, nodes + 2)]).toEqual([...mesh.bvh.nodes.subarray(0, 2)]);
    expect([...tables.subarray(order, order + 4)]).toEqual([...mesh.bvh.order]);
    expect([...tables.subarray(corners, corners + 9)]).toEqual([...mesh.corners.subarray(0, 9)].map(Math.fround));
    expect([...tables.subarray(normals, normals + 3)]).toEqual([...mesh.normals.subarray(0, 3)].map(Math.fround));
  });

  it('names a shape it cannot draw: a subclass, a shape added twice', () => {
    class Bubble extends Sphere {}
    expect(() => gpuScene(new Scene().add(new Bubble([0, 0, -5], 1, { name: 'b' })))).toThrow(/renderGPU cannot draw shape 0 \("b", a Bubble\): its hit or normalAt is not its class's own/);
    const ball = new Sphere([0, 0, -5], 1);
    expect(() => gpuScene(new Scene().add(ball).add(ball))).toThrow(/shape 1 \(a Sphere\): it is added to the scene twice/);
  });

  it('rows of ROW numbers for a texture, at least one', () => {
    expect(inRows(new Float32Array(0)).rows).toBe(1);
    const { data, rows } = inRows(new Float32Array(ROW + 1).fill(2));
    expect(rows).toBe(2);
    expect(data.length).toBe(2 * ROW);
    expect(data[ROW]).toBe(2);
    expect(data[ROW + 1]).toBe(0);
  });

  it('the shader reads the layout\'s offsets from the modules that own them', () => {
    const source = kernelSource();
    expect(source).toContain(`#define SHAPE ${SHAPE}`);
    expect(source).toContain(`#define LIGHT ${LIGHT}\n`);
    expect(source).toContain(`#define LIGHT_EMISSION ${LIGHT_EMISSION}\n`);
    expect(source).toContain(`#define MATERIAL ${MATERIAL_NUMBERS}\n`);
    expect(source).toContain(`#define SHININESS ${MATERIAL_AT.shininess}\n`);
    expect(source).toContain('#define HAS_MESH 1');
    expect(kernelSource(false)).toContain('#define HAS_MESH 0');
  });
});

it('in Node, lib/index.js imports with renderGPU, which says it needs a browser with WebGL2', () => {
  expect(() => renderGPU(classScene(), new Camera({ width: 4, height: 3 }))).toThrow(/the GPU engine needs WebGL2: there is no canvas here/);
  expect(() => renderGPU({}, new Camera({ width: 4, height: 3 }))).toThrow(/scene must be a Scene/);
});
