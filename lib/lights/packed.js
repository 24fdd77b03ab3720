/**
 * The packed layout of the scene's light sources, as render()'s kernel
 * (lib/tracing/kernel.js) reads them and the GPU engine uploads them: LIGHT numbers
 * per source, each at its named offset. Every light answers with its
 * sources (`sources()`: position, emission, attenuation, an optional cone),
 * so one function packs any light, a light of a test's own too.
 *
 *   0–2  POSITION       x y z
 *   3–5  LIGHT_EMISSION r g b (what the source gives off)
 *   6    LIGHT_SHAPE    the index of its shape (an emissive shape), −1 for none
 *   7    ATTENUATION    k of the falloff 1 / (1 + k·d²)
 *   8    IS_SPOT        1 when it shines in a cone (a spot light), else 0
 *   9–11 AXIS           the cone's unit axis x y z (0 without a cone)
 *   12   COS_OUTER      cos of the cone's rim (0 without a cone)
 *   13   COS_INNER      cos of where its fading starts (0 without a cone)
 */

/** Numbers per light source. */
export const LIGHT = 14;
export const POSITION = 0, LIGHT_EMISSION = 3, LIGHT_SHAPE = 6, ATTENUATION = 7, IS_SPOT = 8, AXIS = 9, COS_OUTER = 12, COS_INNER = 13;

/**
 * Writes one light source (an entry of `scene.lights`) into `lights` at `at`.
 * @param {{ position: {x,y,z}, emission: number[], attenuation: number, spot?: { axis: {x,y,z}, cosOuter: number, cosInner: number } }} source
 * @param {number} shape the index of its shape among the packed shapes, −1 for none
 * @param {Float64Array} lights
 * @param {number} at
 */
export function packSource(source, shape, lights, at) {
  const { position: p, emission: e, spot } = source;
  lights[at + POSITION] = p.x; lights[at + POSITION + 1] = p.y; lights[at + POSITION + 2] = p.z;
  lights[at + LIGHT_EMISSION] = e[0]; lights[at + LIGHT_EMISSION + 1] = e[1]; lights[at + LIGHT_EMISSION + 2] = e[2];
  lights[at + LIGHT_SHAPE] = shape;
  lights[at + ATTENUATION] = source.attenuation;
  lights[at + IS_SPOT] = spot ? 1 : 0;
  lights[at + AXIS] = spot ? spot.axis.x : 0; lights[at + AXIS + 1] = spot ? spot.axis.y : 0; lights[at + AXIS + 2] = spot ? spot.axis.z : 0;
  lights[at + COS_OUTER] = spot ? spot.cosOuter : 0;
  lights[at + COS_INNER] = spot ? spot.cosInner : 0;
}
