// The work a scene from a link or a paste may make, counted before it is built:
// shadow rays from each hit point, rays a pixel, triangles. Each refusal names the field.
import { describe, it, expect } from 'vitest';
import { decodeScene, encodeScene } from '../../lib/scene/codec.js';
import { sceneFromJSON, sceneToJSON } from '../../lib/scene/json.js';
import { MAX_SHADOW_RAYS, MAX_PIXEL_RAYS, MAX_SCENE_TRIANGLES } from '../../lib/scene/work.js';
import { classScene } from '../../lib/scene/examples.js';
import { trafficSignalScene, rearLightsScene } from '../../lib/lesson/homework-scenes.js';

const ball = { type: 'sphere', center: [0, 0, -10], radius: 1 };
const areaLights = (n, samples) => Array.from({ length: n }, (_, i) => ({ type: 'areaLight', center: [i, 10, -10], radius: 1, samples }));
const link = (json) => JSON.stringify(json);
const errorOf = (read) => { try { read(); } catch (error) { return error; } return null; };

/** n triangles in a strip, as one mesh. */
function strip(n) {
  const positions = [], cells = [];
  for (let i = 0; i < n + 2; i++) positions.push([i, i % 2, -10]);
  for (let i = 0; i < n; i++) cells.push([i, i + 1, i + 2]);
  return { type: 'mesh', positions, cells };
}

describe('a scene from a link or a paste makes a limited amount of work', () => {
  it('156 area lights × 64 samples (a 740-byte link, 6 s a click): refused, naming the area light that passes the limit', () => {
    const error = errorOf(() => decodeScene(link({ objects: [ball, ...areaLights(156, 64)] })));
    expect(error).toBeInstanceOf(RangeError);
    expect(error.message).toMatch(/^objects\[17\]\.samples: the scene's lights cast 1,088 shadow rays or more from each hit point, more than the 1,024/);
    expect(errorOf(() => decodeScene(encodeScene({ objects: [ball, ...areaLights(9_998, 64)] }))).message).toMatch(/^objects\[17\]\.samples/);
  });

  it('up to the limit is read, and the same scene from code is not limited', () => {
    const json = { objects: [ball, ...areaLights(MAX_SHADOW_RAYS / 64, 64)] };
    expect(decodeScene(link(json)).lights).toHaveLength(MAX_SHADOW_RAYS); // a light entry a sample
    expect(sceneFromJSON({ objects: [ball, ...areaLights(156, 64)] }).lights).toHaveLength(156 * 64);
  });

  it('triangles: 300 meshes of 800 (2.6 s to open) refused at the mesh that passes the limit, before any is built', () => {
    const meshes = Array.from({ length: 300 }, () => strip(800));
    const error = errorOf(() => decodeScene(link({ objects: meshes })));
    expect(error.message).toMatch(/^objects\[25\]\.cells: the scene has 20,800 triangles or more, more than the 20,000/);
    expect(decodeScene(link({ objects: [strip(MAX_SCENE_TRIANGLES)] })).objects[0].triangleCount).toBe(MAX_SCENE_TRIANGLES);
  });

  it('bounces: glass at maxDepth 16 is 131,071 bounces a pixel, refused naming maxDepth; mirrors at 16 are not', () => {
    const glass = { ...ball, material: { transparency: 0.9, reflection: 0.1 } };
    const lamp = { type: 'pointLight', position: [0, 10, 0] };
    expect(errorOf(() => decodeScene(link({ maxDepth: 16, objects: [glass, lamp] }))).message).toMatch(/^maxDepth: 16 bounces through glass .* make 262,142 rays a pixel/);
    expect(decodeScene(link({ maxDepth: 8, objects: [glass, lamp] })).maxDepth).toBe(8); // 511 × 2
    const mirror = { ...ball, material: { reflection: 1 } };
    expect(decodeScene(link({ maxDepth: 16, objects: [mirror, lamp] })).maxDepth).toBe(16);
    expect(2 ** 17 - 1).toBeGreaterThan(MAX_PIXEL_RAYS);
  });

  it('the kit\'s own scenes are far inside every limit', () => {
    for (const scene of [classScene(), classScene({ full: true }), trafficSignalScene(), rearLightsScene()]) {
      expect(() => decodeScene(encodeScene(sceneToJSON(scene)))).not.toThrow();
    }
  });
});
