/**
 * The work a scene from a link or a paste may make, counted from its JSON
 * before anything is built: objects alone said too little (a 740-byte link of
 * 156 area lights × 64 samples made one click a 6 s task; 300 meshes of 800
 * triangles, a 2.6 s task to open). Each limit is in units of work, and its
 * message names the field where the scene passes it.
 */
import { lightWork } from '../lights/index.js';
import { shapeWork } from '../shapes/index.js';

/** Shadow rays from one hit point: an area light's samples, one for every other light (an emissive shape is one). */
export const MAX_SHADOW_RAYS = 1_024;
/** Rays a camera ray may lead to: its bounces (a glass both reflects and refracts, so 2^(maxDepth+1) − 1) × (1 + shadow rays at each). */
export const MAX_PIXEL_RAYS = 16_384;
/** Triangles in the scene, every mesh's and every triangle: each one's share of the BVHs is built as the link opens. */
export const MAX_SCENE_TRIANGLES = 20_000;

const DEPTH_DEFAULT = 5;

/**
 * A RangeError when scene JSON's objects (already a checked-to-be array) make
 * more work than the limits above; the field named is the first where the
 * count passes its limit. Text and odd values are left for the fields' own checks.
 * @param {any[]} objects
 * @param {{ maxDepth?: number }} scene the scene's own fields
 */
export function checkWork(objects, scene) {
  let shadowRays = 0, triangles = 0, reflects = false, refracts = false, busiest = null;
  for (let i = 0; i < objects.length; i++) {
    const o = objects[i];
    if (o === null || typeof o !== 'object') continue;
    const light = lightWork(o);
    const rays = light ? light.shadowRays : isEmissive(o.material?.emission) ? 1 : 0; // an emissive shape is one light
    if (rays > 0) busiest = light?.field ? `objects[${i}].${light.field}` : `objects[${i}]`;
    shadowRays += rays;
    if (shadowRays > MAX_SHADOW_RAYS) {
      throw new RangeError(`${busiest}: the scene's lights cast ${shadowRays.toLocaleString('en')} shadow rays or more from each hit point, more than the ${MAX_SHADOW_RAYS.toLocaleString('en')} a scene from a link or a paste may have (fewer lights, or fewer samples)`);
    }
    const shape = shapeWork(o);
    triangles += shape.triangles;
    if (triangles > MAX_SCENE_TRIANGLES) {
      throw new RangeError(`objects[${i}]${shape.field ? `.${shape.field}` : ''}: the scene has ${triangles.toLocaleString('en')} triangles or more, more than the ${MAX_SCENE_TRIANGLES.toLocaleString('en')} a scene from a link or a paste may have`);
    }
    const m = o.material;
    if (m && typeof m === 'object') {
      reflects ||= m.reflection > 0;
      refracts ||= m.transparency > 0;
    }
  }
  const depth = typeof scene.maxDepth === 'number' && scene.maxDepth >= 0 ? Math.min(scene.maxDepth, 64) : DEPTH_DEFAULT;
  const bounces = refracts ? 2 ** (depth + 1) - 1 : reflects ? depth + 1 : 1;
  const perPixel = bounces * (1 + shadowRays);
  if (perPixel > MAX_PIXEL_RAYS) {
    throw new RangeError(`maxDepth: ${depth} bounces${refracts ? ' through glass (each reflects and refracts)' : ' between mirrors'} make ${perPixel.toLocaleString('en')} rays a pixel with the scene's ${shadowRays.toLocaleString('en')} shadow rays, more than the ${MAX_PIXEL_RAYS.toLocaleString('en')} a scene from a link or a paste may have (a smaller maxDepth, or fewer lights)`);
  }
}

/** An emission that may light the scene: counted before its checks, so a colour's name counts too. */
function isEmissive(emission) {
  if (Array.isArray(emission)) return emission.some((c) => c > 0);
  return typeof emission === 'number' ? emission > 0 : typeof emission === 'string';
}
