/**
 * The pieces of scene JSON every shape writes the same way (lib/scene/json.js
 * reads them back).
 */
import { materialJSON } from './material.js';

/** A point or direction as `[x, y, z]`. */
export function vector(v) {
  return [v.x, v.y, v.z];
}

/** A material as `{ color, emission, reflection, transparency, ior, specular, shininess }`, and `fuzz` when a mirror blurs (its fields: lib/shapes/material.js MATERIAL_FIELDS). */
export function materialToJSON(m) {
  return materialJSON(m);
}
