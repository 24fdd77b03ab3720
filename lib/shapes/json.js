/**
 * The pieces of scene JSON every shape writes the same way (lib/serialize.js
 * reads them back).
 */

/** A point or direction as `[x, y, z]`. */
export function vector(v) {
  return [v.x, v.y, v.z];
}

/** A material as `{ color, emission, reflection, transparency, ior, specular, shininess }`, and `fuzz` when a mirror blurs (> 0). */
export function materialToJSON(m) {
  return {
    color: [...m.color], emission: [...m.emission], reflection: m.reflection, transparency: m.transparency,
    ior: m.ior, specular: m.specular, shininess: m.shininess, ...(m.fuzz > 0 ? { fuzz: m.fuzz } : {}),
  };
}
