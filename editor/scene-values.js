/**
 * New values of a scene's or a camera's fields, as the frame sets them when
 * the page sends a scrubbed number (frame-runtime.js): the scene and camera
 * written as JSON, the fields set there, and read back as any scene is, so a
 * bad value is a mistake naming its field and nothing changes.
 */
import { sceneToJSON, cameraToJSON, sceneFromJSON, cameraFromJSON } from '../lib/scene/json.js';

/**
 * @param {import('../lib/scene/scene.js').Scene} scene
 * @param {import('../lib/math/camera.js').Camera} camera
 * @param {{ path: string[], value: number }[]} changes checked paths (frame-protocol.js's readValues)
 * @returns {{ scene: object|null, camera: object|null }} the new scene and camera, null for the one that keeps its values
 */
export function withValues(scene, camera, changes) {
  const data = { scene: sceneToJSON(scene), camera: cameraToJSON(camera) };
  for (const { path, value } of changes) setField(data, path, value);
  return {
    scene: changes.some((c) => c.path[0] === 'scene') ? sceneFromJSON(data.scene) : null,
    camera: changes.some((c) => c.path[0] === 'camera') ? cameraFromJSON(data.camera) : null,
  };
}

/** Sets the field at `path` (['scene', 'objects', '0', 'radius']) in plain data; only a number that is there already. */
function setField(data, path, value) {
  let node = data;
  for (const key of path.slice(0, -1)) node = node !== null && typeof node === 'object' && Object.hasOwn(node, key) ? node[key] : undefined;
  const key = path.at(-1);
  if (node === null || typeof node !== 'object' || typeof node[key] !== 'number') throw new RangeError(`${path.slice(1).join('.')} is not a number of the scene`);
  node[key] = value;
}
