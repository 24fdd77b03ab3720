/**
 * The lights a path can aim at (next-event estimation): emissive spheres and
 * boxes, and a gradient sky. `lightTable` lists them once per frame with the
 * probability of picking each, by power; `sampleLight` draws a direction
 * toward one of them from a point, and `lightPdf` says how likely the light
 * sampler was to draw a direction a bounce happened to take (the other half
 * of multiple importance sampling, integrator.js).
 *
 * Power: an emitter of radiance E and area A sends out π·E·A; the sky, of mean
 * brightness L, sends π·L·4πR² into a ball of radius R around the scene (R: half
 * the diagonal of the box around the eye and every bounded shape, at least 1). π is common
 * to all and left out.
 *
 * Left to the bounces alone (hit by chance, their light counted in full):
 * emissive planes and meshes (no area to draw a point from), and a uniform sky,
 * whose best density for a diffuse surface is already the bounce's cosine one
 * (a sky sampled all round would only add noise there: the white furnace).
 *
 * Numbers go in and out through Float64Arrays, and the samplers are called
 * through `apart` with objects and whole numbers only: a number passed to or
 * returned from a call V8 does not inline is boxed (docs/performance.md).
 */
import { Sphere } from '../../shapes/sphere.js';
import { Box } from '../../shapes/box.js';
import { EMISSION, MATERIAL } from './materials.js';
import { isUniform } from './sky.js';
import { apart } from './apart.js';

/** A light's numbers in the table: its kind, shape index, probability of being picked, cumulative probability, six numbers of shape (a sphere: centre, radius; a box: min, max). */
export const LIGHT = 10;
export const KIND = 0, SHAPE_INDEX = 1, PICK = 2, CDF = 3, G = 4;
export const SPHERE_LIGHT = 0, BOX_LIGHT = 1, SKY_LIGHT = 2;

const FOUR_PI = 4 * Math.PI, TWO_PI = 2 * Math.PI;
const mean3 = (a, at) => (a[at] + a[at + 1] + a[at + 2]) / 3;

/**
 * The frame's lights, by power.
 * @param {object[]} objects the scene's shapes
 * @param {Float64Array} materials packMaterials(objects)
 * @param {Float64Array} sky readSky's
 * @param {{ x: number, y: number, z: number }} eye the camera's position
 * @returns {{ table: Float64Array, count: number, of: Int32Array, sky: number, skyNumbers: Float64Array }} `of[i]` the light of shape i (−1: none); `sky` the sky's (−1: none)
 */
export function lightTable(objects, materials, sky, eye) {
  const rows = [], of = new Int32Array(objects.length).fill(-1);
  objects.forEach((o, i) => {
    const glow = mean3(materials, i * MATERIAL + EMISSION);
    if (!(glow > 0)) return;
    if (o.constructor === Sphere && o.radius > 0) {
      const c = o.center;
      rows.push({ kind: SPHERE_LIGHT, index: i, power: glow * FOUR_PI * o.radius ** 2, shape: [c.x, c.y, c.z, o.radius, 0, 0] });
    } else if (o.constructor === Box) {
      const { min, max } = o, a = max.x - min.x, b = max.y - min.y, c = max.z - min.z;
      rows.push({ kind: BOX_LIGHT, index: i, power: glow * 2 * (a * b + b * c + c * a), shape: [min.x, min.y, min.z, max.x, max.y, max.z] });
    }
  });
  const skyGlow = (mean3(sky, 0) + mean3(sky, 3)) / 2, R = sceneRadius(objects, eye);
  if (skyGlow > 0 && !isUniform(sky)) rows.push({ kind: SKY_LIGHT, index: -1, power: skyGlow * FOUR_PI * R * R, shape: [0, 0, 0, 0, 0, 0] });
  const usable = rows.filter((r) => Number.isFinite(r.power) && r.power > 0);
  const total = usable.reduce((sum, r) => sum + r.power, 0);
  const table = new Float64Array(Math.max(1, usable.length) * LIGHT);
  let cumulative = 0, skySlot = -1;
  usable.forEach((r, slot) => {
    const at = slot * LIGHT;
    cumulative += r.power / total;
    table[at + KIND] = r.kind; table[at + SHAPE_INDEX] = r.index; table[at + PICK] = r.power / total;
    table[at + CDF] = slot === usable.length - 1 ? 1 : cumulative;
    table.set(r.shape, at + G);
    if (r.kind === SKY_LIGHT) skySlot = slot; else of[r.index] = slot;
  });
  return { table, count: usable.length, of, sky: skySlot, skyNumbers: skyNumbers(sky) };
}

/** Half the diagonal of the box around the eye and every bounded shape (planes are not). */
function sceneRadius(objects, eye) {
  const lo = [eye.x, eye.y, eye.z], hi = [eye.x, eye.y, eye.z];
  for (const o of objects) {
    const b = typeof o.bounds === 'function' ? o.bounds() : null;
    if (!b) continue;
    const corners = [[b.min.x, b.min.y, b.min.z], [b.max.x, b.max.y, b.max.z]];
    if (!corners.flat().every(Number.isFinite)) continue;
    for (const p of corners) for (let k = 0; k < 3; k++) { lo[k] = Math.min(lo[k], p[k]); hi[k] = Math.max(hi[k], p[k]); }
  }
  return Math.max(1, Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2); // at least 1: with nothing bounded but the eye, the sky is the only light this weighs against
}

/** What sampleLight writes: the direction (unit), the light's slot, the density (pick × solid angle; 0: nothing drawn), the point on the light, its distance. */
export const L_DIRECTION = 0, L_SLOT = 3, L_PDF = 4, L_POINT = 5, L_DISTANCE = 8, LIGHT_SAMPLE = 9;

/**
 * One light picked by power and a direction toward it from `from[0 …]`, by
 * four uniform numbers `u[0 …]` (pick, face, two for the point), into `out`.
 */
export function sampleLight(lights, from, u, out) {
  const table = lights.table;
  let slot = 0;
  while (slot < lights.count - 1 && u[0] >= table[slot * LIGHT + CDF]) slot++;
  const at = slot * LIGHT, kind = table[at + KIND];
  out[L_SLOT] = slot; out[L_PDF] = 0;
  if (kind === SPHERE_LIGHT) apart(sampleSphere, table, at, from, u, out);
  else if (kind === BOX_LIGHT) apart(sampleBox, table, at, from, u, out);
  else apart(sampleSky, lights.skyNumbers, u, out);
  out[L_PDF] *= table[at + PICK];
}

/**
 * A sphere seen from outside: a direction uniform in the cone it subtends
 * (density 1 / 2π(1 − cos θmax)); from inside (or on it), a point uniform on
 * it, its density turned into solid angle (distance² / (cos · area)).
 */
function sampleSphere(table, at, from, u, out) {
  const cx = table[at + G], cy = table[at + G + 1], cz = table[at + G + 2], r = table[at + G + 3];
  const wx = cx - from[0], wy = cy - from[1], wz = cz - from[2], d2 = wx * wx + wy * wy + wz * wz;
  if (d2 > r * r) {
    const d = Math.sqrt(d2), sin2Max = (r * r) / d2, cosMax = Math.sqrt(1 - sin2Max), oneMinusCosMax = sin2Max / (1 + cosMax);
    const cos = 1 - u[2] * oneMinusCosMax, sin = Math.sqrt(Math.max(0, 1 - cos * cos)), phi = TWO_PI * u[3];
    const a = sin * Math.cos(phi), b = sin * Math.sin(phi), ux = wx / d, uy = wy / d, uz = wz / d;
    // cos·w + a·T + b·B in a basis (T, B) around w (as sampling.js's, Duff et al. 2017)
    const sign = uz >= 0 ? 1 : -1, k = -1 / (sign + uz), m = ux * uy * k;
    const Tx = 1 + sign * ux * ux * k, Ty = sign * m, Tz = -sign * ux, Bx = m, By = sign + uy * uy * k, Bz = -uy;
    out[0] = a * Tx + b * Bx + cos * ux; out[1] = a * Ty + b * By + cos * uy; out[2] = a * Tz + b * Bz + cos * uz;
    const along = d * cos - Math.sqrt(Math.max(0, r * r - d2 * (1 - cos * cos))); // the nearer crossing
    out[L_DISTANCE] = along;
    out[L_POINT] = from[0] + out[0] * along; out[L_POINT + 1] = from[1] + out[1] * along; out[L_POINT + 2] = from[2] + out[2] * along;
    out[L_PDF] = 1 / (TWO_PI * oneMinusCosMax);
    return;
  }
  const z = 1 - 2 * u[2], ring = Math.sqrt(Math.max(0, 1 - z * z)), phi = TWO_PI * u[3];
  const nx = ring * Math.cos(phi), ny = ring * Math.sin(phi), nz = z;
  target[0] = cx + r * nx; target[1] = cy + r * ny; target[2] = cz + r * nz; target[3] = nx; target[4] = ny; target[5] = nz; target[6] = FOUR_PI * r * r;
  towardPoint(out, from, target);
}

/**
 * Scratch: a point drawn on a light, its normal, the area it was drawn over;
 * for a box, the area of each face that faces the point (min x, max x, min y,
 * …; 0: turned away) and the chance of picking it.
 */
const target = new Float64Array(7), faces = new Float64Array(6), chances = new Float64Array(6);

/**
 * A box: one of the faces that face the point (all six from inside), picked
 * by the solid angle its centre suggests (area × cos / distance²: a face seen
 * edge-on, the lamp's top seen from the ceiling, is seldom worth a shadow
 * ray), and a point uniform on it.
 */
function sampleBox(table, at, from, u, out) {
  if (!facingFaces(table, at, from)) return;
  let pick = u[1], last = 0;
  for (let face = 0; face < 6; face++) {
    const chance = chances[face];
    if (!(chance > 0)) continue;
    if (pick < chance) { boxFacePoint(table, at, from, u, out, face); return; }
    pick -= chance; last = face;
  }
  boxFacePoint(table, at, from, u, out, last); // rounding left a sliver past the last face
}

/** A point uniform on `face` (2 · axis + 1 for the max side), into `target` with the area it was drawn over (the face's / its chance), and the direction to it. */
function boxFacePoint(table, at, from, u, out, face) {
  const axis = face >> 1, high = face & 1, b = axis === 2 ? 0 : axis + 1, c = axis === 0 ? 2 : axis - 1;
  target[axis] = table[at + G + 3 * high + axis];
  target[b] = table[at + G + b] + u[2] * (table[at + G + 3 + b] - table[at + G + b]);
  target[c] = table[at + G + c] + u[3] * (table[at + G + 3 + c] - table[at + G + c]);
  target[3] = target[4] = target[5] = 0; target[3 + axis] = 1;
  target[6] = faces[face] / chances[face];
  towardPoint(out, from, target);
}

/**
 * The faces of the box that face the point, into `faces` (their areas, 0 for
 * the others) and `chances` (the chance of picking each, ∝ area × cos /
 * distance² at its centre); false when none can be picked. Outside the box,
 * the face of an axis that faces the point is the one on its side, if the
 * point is past it; from inside, all six.
 */
function facingFaces(table, at, from) {
  const g = at + G;
  let outside = false;
  for (let k = 0; k < 3; k++) if (from[k] < table[g + k] || from[k] > table[g + 3 + k]) outside = true;
  let sum = 0;
  for (let face = 0; face < 6; face++) {
    const axis = face >> 1, high = face & 1, b = axis === 2 ? 0 : axis + 1, c = axis === 0 ? 2 : axis - 1;
    const gap = from[axis] - table[g + 3 * high + axis];
    faces[face] = 0; chances[face] = 0;
    if (outside && !(high === 1 ? gap > 0 : gap < 0)) continue; // turned away
    const area = (table[g + 3 + b] - table[g + b]) * (table[g + 3 + c] - table[g + c]);
    const db = 0.5 * (table[g + b] + table[g + 3 + b]) - from[b], dc = 0.5 * (table[g + c] + table[g + 3 + c]) - from[c];
    const d2 = gap * gap + db * db + dc * dc, chance = area > 0 ? (area * Math.abs(gap)) / (d2 * Math.sqrt(d2)) : 0;
    faces[face] = area;
    if (chance > 0 && chance < Infinity) { chances[face] = chance; sum += chance; }
  }
  if (!(sum > 0) || sum === Infinity) return false;
  for (let face = 0; face < 6; face++) chances[face] /= sum;
  return true;
}

/** Which face of the box at `at` holds the point `p[0 …]` whose normal is `p[3 …]` (2 · axis + 1 for the max side). */
function faceOf(table, at, p) {
  const ax = Math.abs(p[3]), ay = Math.abs(p[4]), az = Math.abs(p[5]);
  const axis = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2, g = at + G;
  return 2 * axis + (Math.abs(p[axis] - table[g + 3 + axis]) < Math.abs(p[axis] - table[g + axis]) ? 1 : 0);
}

/** The direction to the point `p[0 …]` on a light, of normal `p[3 …]`, drawn uniformly over the area `p[6]`: density distance² / (|cos| · area) in solid angle. */
function towardPoint(out, from, p) {
  const px = p[0], py = p[1], pz = p[2], nx = p[3], ny = p[4], nz = p[5], area = p[6];
  const dx = px - from[0], dy = py - from[1], dz = pz - from[2], d2 = dx * dx + dy * dy + dz * dz, d = Math.sqrt(d2);
  out[L_POINT] = px; out[L_POINT + 1] = py; out[L_POINT + 2] = pz; out[L_DISTANCE] = d;
  if (!(d > 0)) return;
  out[0] = dx / d; out[1] = dy / d; out[2] = dz / d;
  const cos = Math.abs(nx * out[0] + ny * out[1] + nz * out[2]);
  if (cos > 0) out[L_PDF] = d2 / (cos * area);
}

/**
 * The sky's numbers for sampling: mean brightness at the top and the bottom.
 * @param {Float64Array} sky readSky's
 */
export function skyNumbers(sky) {
  return Float64Array.of(mean3(sky, 0), mean3(sky, 3));
}

/**
 * A direction drawn with density ∝ the sky's brightness. The brightness is
 * linear in t = (dy + 1)/2, and dy is uniform over the sphere, so t has
 * density ∝ bottom·(1 − t) + top·t on [0, 1]: its inverse CDF is a
 * quadratic's root, written in the form that stays exact for a flat sky.
 */
function sampleSky(sky, u, out) {
  const top = sky[0], bottom = sky[1], half = (top - bottom) / 2, c = u[2] * (top + bottom) / 2;
  const t = (2 * c) / (bottom + Math.sqrt(bottom * bottom + 4 * half * c));
  const dy = Math.min(1, Math.max(-1, 2 * t - 1)), ring = Math.sqrt(Math.max(0, 1 - dy * dy)), phi = TWO_PI * u[3];
  out[0] = ring * Math.cos(phi); out[1] = dy; out[2] = ring * Math.sin(phi);
  out[L_DISTANCE] = Infinity;
  out[L_PDF] = (t * top + (1 - t) * bottom) / (FOUR_PI * (top + bottom) / 2); // brightness / (4π · mean brightness)
}

/**
 * The light sampler's density (pick × solid angle) of the direction `ray[3 …]`
 * from `ray[0 …]` that reached light `slot` at `hit[0 …]`, whose normal is
 * `hit[3 …]` (for the sky, no hit), into `out[0]`.
 */
export function lightPdf(lights, slot, ray, hit, out) {
  const table = lights.table, at = slot * LIGHT, kind = table[at + KIND];
  let pdf;
  out[0] = 0;
  if (kind === SKY_LIGHT) {
    const sky = lights.skyNumbers, t = 0.5 * (ray[4] + 1);
    pdf = (t * sky[0] + (1 - t) * sky[1]) / (FOUR_PI * (sky[0] + sky[1]) / 2); // as sampleSky's
  } else {
    const cos = Math.abs(hit[3] * ray[3] + hit[4] * ray[4] + hit[5] * ray[5]);
    const hx = hit[0] - ray[0], hy = hit[1] - ray[1], hz = hit[2] - ray[2], distance2 = hx * hx + hy * hy + hz * hz;
    if (!(cos > 0)) return;
    if (kind === BOX_LIGHT) {
      const face = faceOf(table, at, hit);
      pdf = facingFaces(table, at, ray) && chances[face] > 0 ? (distance2 * chances[face]) / (cos * faces[face]) : 0;
    } else {
      const wx = table[at + G] - ray[0], wy = table[at + G + 1] - ray[1], wz = table[at + G + 2] - ray[2], r = table[at + G + 3];
      const d2 = wx * wx + wy * wy + wz * wz;
      const sin2Max = (r * r) / d2;
      pdf = d2 > r * r ? 1 / (TWO_PI * (sin2Max / (1 + Math.sqrt(1 - sin2Max)))) : distance2 / (cos * FOUR_PI * r * r); // the cone from outside; by area from inside
    }
  }
  out[0] = pdf * table[at + PICK];
}
