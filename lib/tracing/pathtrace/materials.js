/**
 * What a surface does with a path, as in *Ray Tracing in One Weekend*, read
 * from the kit's material model so that one scene serves both tracers:
 *   transparency → a dielectric (glass of index `ior`: Schlick's share F
 *                  mirrored, untinted; the rest refracted by Snell, tinted by `color`);
 *   reflection   → a metal (the mirror direction, blurred by `fuzz`, tinted by `color`);
 *   the rest     → diffuse (a cosine-weighted bounce, tinted by `color`);
 *   emission     → light the surface gives off (an emissive shape is a light).
 * Whitted's tracer mixes these shares on every hit (optics.js's `mix`); a path
 * takes one of them at random with the probability of its share, so on
 * average it gathers the same mix: transparency T picks glass, then
 * reflection R of what is left picks metal, the rest is diffuse.
 *
 * `scatter` reads the hit from `surface` and writes the bounce into `event`,
 * both Float64Arrays: numbers go between the steps in arrays, not as
 * arguments or results, which V8 boxes when it does not inline a call
 * (docs/performance.md, "Notes on V8").
 */
import { refract, schlick } from '../optics.js';
import { cosineHemisphere, inUnitBall } from './sampling.js';
import { apart } from './apart.js';
import { MATERIAL_LAYOUT, packMaterial } from '../../shapes/material.js';
import { checkCopies } from '../../shapes/packed.js';

/** Where the hit lies in `surface`: the point P, the unit normal N facing the ray, the ray's direction D, 1 when it came from inside. */
export const P = 0, N = 3, D = 6, INSIDE = 9, SURFACE = 10;
/**
 * Where the bounce lies in `event`: the new direction (and, for a diffuse
 * bounce, its cos θ to the normal), its weight per channel (what the
 * throughput is multiplied by: f·cos / pdf, which is the colour for every
 * lobe here), the density it was drawn with (for a mirror or glass: the
 * probability of choosing that lobe), which lobe, 1 when the new ray starts
 * below the surface (refraction).
 */
export const DIRECTION = 0, COS = 3, WEIGHT = 4, PDF = 7, LOBE = 8, BELOW = 9, EVENT = 10;

/** The lobes, by number: what `event[LOBE]` holds; ABSORBED when the path ends there (a fuzzed mirror ray below the surface). */
export const DIFFUSE = 0, METAL = 1, GLASS_MIRROR = 2, GLASS_THROUGH = 3, ABSORBED = -1;
export const LOBE_NAMES = { [DIFFUSE]: 'diffuse', [METAL]: 'metal', [GLASS_MIRROR]: 'glass, mirrored', [GLASS_THROUGH]: 'glass, through', [ABSORBED]: 'absorbed' };

/**
 * The scene's materials in numbers, MATERIAL per shape in scene order, as the
 * kernel packs them (lib/shapes/material.js's table: colour r g b, emission
 * r g b, reflection, transparency, ior, specular, shininess, fuzz). Read from a
 * typed array, every number is a plain double; read from the Material
 * objects, whose fields V8 stores as small integers in one and as doubles in
 * another, they cost an allocation now and then in the hot loop. The offsets
 * are literal copies of the table's (V8 folds them), checked against it at load.
 */
export const MATERIAL = 12;
export const COLOR = 0, EMISSION = 3, REFLECTION = 6, TRANSPARENCY = 7, IOR = 8, FUZZ = 11;
checkCopies({ MATERIAL, COLOR, EMISSION, REFLECTION, TRANSPARENCY, IOR, FUZZ }, MATERIAL_LAYOUT, 'lib/shapes/material.js');

/** The materials of `objects`, packed as the kernel's packScene packs them (see MATERIAL): for tests and tables made without a packed scene. */
export function packMaterials(objects) {
  const packed = new Float64Array(objects.length * MATERIAL);
  objects.forEach(({ material }, i) => packMaterial(material, packed, i * MATERIAL));
  return packed;
}

/** Scratch: the uniform numbers of a bounce (lobe, two for the direction, three for the fuzz), and the fuzz's point. */
const u = new Float64Array(6), fuzzPoint = new Float64Array(3);

/**
 * One bounce off the material at `materials[m …]` (packMaterials) at the hit
 * in `surface`, drawn with `random` (a PathRandom), into `event`.
 */
export function scatter(materials, m, random, surface, event) {
  const T = materials[m + TRANSPARENCY], R = materials[m + REFLECTION];
  random.draw(u, 6); // always six: each bounce starts its numbers at the same place in the sequence
  event[WEIGHT] = materials[m + COLOR]; event[WEIGHT + 1] = materials[m + COLOR + 1]; event[WEIGHT + 2] = materials[m + COLOR + 2];
  event[BELOW] = 0;
  const choose = u[0];
  if (choose < T) {
    event[PDF] = T;
    apart(glass, materials, m, surface, event); // compiled on its own, Snell and Schlick inlined in it (apart.js)
  } else if (choose < T + (1 - T) * R) {
    event[PDF] = (1 - T) * R;
    metal(materials, m, surface, event);
  } else {
    event[PDF] = (1 - T) * (1 - R);
    diffuse(surface, event);
  }
}

/** Lambertian: a cosine-weighted direction; f = colour/π, pdf = cos/π, so the weight is the colour. */
function diffuse(surface, event) {
  cosineHemisphere(event, DIRECTION, surface, N, u, 1);
  event[PDF] *= event[COS] / Math.PI;
  event[LOBE] = DIFFUSE;
}

/** A metal: the mirror direction plus fuzz × a point in the unit ball, renormalised; below the surface the path is absorbed. */
function metal(materials, m, surface, event) {
  const Nx = surface[N], Ny = surface[N + 1], Nz = surface[N + 2], dx = surface[D], dy = surface[D + 1], dz = surface[D + 2];
  const twice = 2 * (dx * Nx + dy * Ny + dz * Nz), fuzz = materials[m + FUZZ];
  let x = dx - twice * Nx, y = dy - twice * Ny, z = dz - twice * Nz;
  inUnitBall(fuzzPoint, 0, u, 3); // (drawn even without fuzz: one branch fewer)
  x += fuzz * fuzzPoint[0]; y += fuzz * fuzzPoint[1]; z += fuzz * fuzzPoint[2];
  const length = Math.sqrt(x * x + y * y + z * z);
  event[DIRECTION] = x / length; event[DIRECTION + 1] = y / length; event[DIRECTION + 2] = z / length;
  event[LOBE] = x * Nx + y * Ny + z * Nz > 0 ? METAL : ABSORBED;
}

/** Fuzz below which a metal counts as a mirror (one direction only, no light aimed at): the density of a finer blur is past what doubles carry. */
export const AIMED_FUZZ = 1e-3;

/**
 * The density (per solid angle) with which a metal of fuzz f, at the hit in
 * `surface`, draws the unit direction `dir[0 …]`, into `out[0]`: the mirror
 * direction r plus f × a point uniform in the unit ball is a point uniform in
 * the ball of radius f around r, and a direction's share of it is the volume
 * of the ball along that ray, ∫ t² dt from where the ray enters (t0) to where
 * it leaves (t1), over the ball's volume: (t1³ − t0³) / (4π f³). A direction
 * below the surface is drawn with this density too, but the path ends there.
 */
export function metalDensity(materials, m, surface, dir, out) {
  const Nx = surface[N], Ny = surface[N + 1], Nz = surface[N + 2], dx = surface[D], dy = surface[D + 1], dz = surface[D + 2];
  const twice = 2 * (dx * Nx + dy * Ny + dz * Nz), f = materials[m + FUZZ];
  const b = (dx - twice * Nx) * dir[0] + (dy - twice * Ny) * dir[1] + (dz - twice * Nz) * dir[2]; // cos of the angle to r
  const gap = f * f - (1 - b) * (1 + b); // f² − sin²: the ray meets the ball when positive
  out[0] = 0;
  if (!(gap > 0)) return;
  const root = Math.sqrt(gap), t1 = b + root, t0 = Math.max(0, b - root);
  if (t1 > 0) out[0] = (t1 * t1 * t1 - t0 * t0 * t0) / (4 * Math.PI * f * f * f);
}

/** Glass: Schlick's share F mirrored (untinted), 1 − F refracted by Snell's law (tinted); all mirrored on total internal reflection. */
function glass(materials, m, surface, event) {
  const Nx = surface[N], Ny = surface[N + 1], Nz = surface[N + 2], dx = surface[D], dy = surface[D + 1], dz = surface[D + 2];
  const cosi = -(dx * Nx + dy * Ny + dz * Nz), ior = materials[m + IOR];
  const eta = surface[INSIDE] === 1 ? ior : 1 / ior;
  const refracts = refract(event, DIRECTION, dx, dy, dz, Nx, Ny, Nz, cosi, eta);
  const F = refracts ? schlick(cosi, ior) : 1;
  if (u[1] < F) {
    event[DIRECTION] = dx + 2 * cosi * Nx; event[DIRECTION + 1] = dy + 2 * cosi * Ny; event[DIRECTION + 2] = dz + 2 * cosi * Nz;
    event[WEIGHT] = 1; event[WEIGHT + 1] = 1; event[WEIGHT + 2] = 1;
    event[PDF] *= F;
    event[LOBE] = GLASS_MIRROR;
  } else {
    event[PDF] *= 1 - F;
    event[LOBE] = GLASS_THROUGH;
    event[BELOW] = 1;
  }
}
