/**
 * One path, one sample of a pixel's light: the integrator of a path tracer,
 * read top to bottom.
 *   1. a ray from the eye through a random point of the pixel;
 *   2. at each hit: add the light the surface gives off, times the path's
 *      throughput (how much of the light found later reaches the eye);
 *   3. bounce (materials.js draws the new direction) and multiply the
 *      throughput by the bounce's weight;
 *   4. a path that leaves the scene gathers the sky;
 *   5. after ROULETTE_FROM bounces, Russian roulette: the path goes on with
 *      probability q (its brightest throughput channel) and, if it does,
 *      its throughput is divided by q, so that on average nothing is lost.
 * `maxBounces` stops a path outright: with 1, light that bounced once (direct light only).
 *
 * `tracePath` writes the sample's light into `radiance` and allocates nothing;
 * given a `record` list it also pushes each bounce's story (inspectPath's).
 */
import { Ray } from '../../math/ray.js';
import { Vec3 } from '../../math/vec3.js';
import { scatter, metalDensity, MATERIAL, COLOR, EMISSION, FUZZ, AIMED_FUZZ, P, N, D, INSIDE, SURFACE, DIRECTION, COS, WEIGHT, PDF, LOBE, BELOW, EVENT, DIFFUSE, METAL, ABSORBED, LOBE_NAMES } from './materials.js';
import { skyLight } from './sky.js';
import { sampleLight, lightPdf, LIGHT, SHAPE_INDEX, L_SLOT, L_PDF, L_POINT, L_DISTANCE, LIGHT_SAMPLE } from './lights.js';
import { shapeName } from '../../scene/scene.js';
import { pathNumbers } from './scratch.js';
import { apart } from './apart.js';
import { SHAPE, sideTables } from '../../shapes/packed.js';
import { Sphere } from '../../shapes/sphere.js';
import { Plane } from '../../shapes/plane.js';
import { Box } from '../../shapes/box.js';

/** Bounces before Russian roulette may end a path. */
export const ROULETTE_FROM = 3;

/**
 * The ray being followed, origin x y z then direction x y z, in numbers: a
 * Vec3's fields are boxed by V8 (a new number each write) once any Vec3 has
 * held a non-number, so the hot loop keeps its ray here; `ray` is its copy
 * for a shape of a sketch's own, whose `hit` takes a Ray.
 */
const path = pathNumbers(6);
const ray = new Ray();
const surface = pathNumbers(SURFACE);
const event = pathNumbers(EVENT);
/** The path's throughput and the light it has gathered so far, r g b each. */
const throughput = pathNumbers(3);
/** The light of the last traced sample, [r, g, b] (read it before the next call). */
export const radiance = pathNumbers(3);

/** Scratch: the uniform numbers of the pixel's jitter and of the roulette. */
const u = pathNumbers(2);

/**
 * Multiple importance sampling's numbers: the density of the last bounce's
 * direction when it was diffuse and lights are sampled (0: the light a bounce
 * finds counts in full: from the eye, after a mirror or glass, with light
 * sampling off), and the weight of the light the current hit gives off.
 */
const mis = pathNumbers(2);
const BSDF_PDF = 0, WEIGHT_OF_HIT = 1;
/** Scratch of the light sample: the shadow ray's start, four uniform numbers, what sampleLight drew, a density. */
const from = pathNumbers(3), lightU = pathNumbers(4), aim = pathNumbers(LIGHT_SAMPLE), density = pathNumbers(1);

/**
 * Traces sample `s` of pixel (x, y): its light into `radiance`.
 * @param {object} frame what pathTrace prepared: `{ scene, camera, objects, materials, packed, groups, sky, maxBounces, roulette, seed, random }`
 * @param {any} [record] a list filled with the bounces, and given `ray`, `end` and `sky`, when given
 */
export function tracePath(frame, x, y, s, record) {
  const { random, objects, sky, maxBounces } = frame, bias = frame.scene.bias;
  if (frame.packed) sideTables.current = frame.packed.tables; // a triangle's or a mesh's numbers
  random.start(frame.seed, x, y, s);
  random.draw(u, 2);
  primaryRay(frame.camera, x, y); // through a random point of the pixel: smooth edges
  throughput[0] = throughput[1] = throughput[2] = 1;
  radiance[0] = radiance[1] = radiance[2] = 0;
  if (record) record.ray = { origin: new Vec3(path[0], path[1], path[2]), direction: new Vec3(path[3], path[4], path[5]) };

  let why = 'maxBounces', survival = 1, bounceRecord = null;
  const lights = frame.lightSampling ? frame.lights : null, aiming = lights !== null && lights.count > 0;
  mis[BSDF_PDF] = 0; // from the eye, light counts in full
  for (let bounce = 0; ; bounce++) {
    const index = nearestHit(frame);
    if (index < 0) { // the path leaves the scene: the sky's light, blended from bottom to top (sky.js)
      weighEmission(frame, index); // (after a diffuse bounce, when the sky is also sampled as a light)
      const t = 0.5 * (path[4] + 1), w = mis[WEIGHT_OF_HIT];
      for (let c = 0; c < 3; c++) radiance[c] += throughput[c] * (t * sky[c] + (1 - t) * sky[c + 3]) * w;
      why = 'sky';
      break;
    }
    surfaceAt(frame, index);
    const materials = frame.materials, m = index * MATERIAL, glow = m + EMISSION;
    weighEmission(frame, index);
    const w = mis[WEIGHT_OF_HIT];
    for (let c = 0; c < 3; c++) radiance[c] += throughput[c] * materials[glow + c] * w;
    if (record) bounceRecord = recordHit(record, frame, objects[index], w);
    if (bounce >= maxBounces) break;

    scatter(materials, m, random, surface, event);
    mis[BSDF_PDF] = 0;
    const lobe = event[LOBE], metal = lobe === METAL || lobe === ABSORBED; // (only a fuzzed metal ray is absorbed)
    if (aiming && (lobe === DIFFUSE || (metal && materials[m + FUZZ] >= AIMED_FUZZ))) { // next-event estimation: one shadow ray toward a light, weighed against this bounce
      apart(directLight, frame, m, record ? bounceRecord : null, metal ? 1 : 0); // (also when the metal's own ray is absorbed: the light it would have aimed at is counted on average)
      if (lobe === DIFFUSE) mis[BSDF_PDF] = event[COS] / Math.PI;
      else if (lobe === METAL) { apart(metalDensity, materials, m, surface, event, density); mis[BSDF_PDF] = density[0]; }
    } else if (record && frame.lightSampling) bounceRecord.lightSkipped = skippedWhy(lights, lobe);
    if (lobe === ABSORBED) { why = 'absorbed'; break; }
    for (let c = 0; c < 3; c++) throughput[c] *= event[WEIGHT + c];
    const brightest = Math.max(throughput[0], throughput[1], throughput[2]);
    if (brightest <= 0) { why = 'absorbed'; break; }
    survival = 1;
    if (frame.roulette && bounce + 1 >= ROULETTE_FROM && brightest < 1) {
      survival = brightest;
      random.draw(u, 1);
      if (u[0] >= survival) { why = 'roulette'; break; }
      for (let c = 0; c < 3; c++) throughput[c] /= survival; // the survivors carry the paths that ended: unbiased
    }
    if (record) recordBounce(bounceRecord, survival);
    bounceRecord = null;
    const offset = event[BELOW] === 1 ? -bias : bias; // start off the surface, on the side the path goes
    path[0] = surface[P] + surface[N] * offset; path[1] = surface[P + 1] + surface[N + 1] * offset; path[2] = surface[P + 2] + surface[N + 2] * offset;
    path[3] = event[DIRECTION]; path[4] = event[DIRECTION + 1]; path[5] = event[DIRECTION + 2];
  }
  if (record) endRecord(record, why, bounceRecord, survival, sky, path[4], mis[WEIGHT_OF_HIT]);
}

/**
 * The weight of the light the path has just found (at shape `index`, or the
 * sky for −1), into mis[WEIGHT_OF_HIT]: the power heuristic's
 * pdf_bsdf² / (pdf_bsdf² + pdf_light²) when the bounce was diffuse and light
 * sampling could have drawn the same direction; 1 otherwise.
 */
function weighEmission(frame, index) {
  mis[WEIGHT_OF_HIT] = 1;
  const bsdfPdf = mis[BSDF_PDF];
  if (bsdfPdf <= 0) return;
  const lights = frame.lights, slot = index < 0 ? lights.sky : lights.of[index];
  if (slot < 0) return; // a light the sampler does not aim at (a plane, a mesh, a uniform sky)
  lightPdf(lights, slot, path, surface, density);
  const light = density[0];
  mis[WEIGHT_OF_HIT] = (bsdfPdf * bsdfPdf) / (bsdfPdf * bsdfPdf + light * light);
}

/**
 * Next-event estimation at a diffuse or fuzzy metal hit (the material at
 * `m`; `metal` 1 for the metal): one light picked by power, a direction
 * toward it, one shadow ray; if nothing stands before the light, its light ×
 * the BSDF × cos / the sampler's density, weighed by the power heuristic
 * against the density the bounce would have drawn the same direction with.
 * For both lobes BSDF × cos is the colour × that density: cos/π for the
 * diffuse one, the fuzz ball's share for the metal (materials.js). Overwrites
 * `path` (the loop sets the next ray after). `entry` the inspector's bounce, or null.
 */
function directLight(frame, m, entry, metal) {
  const lights = frame.lights, bias = frame.scene.bias, materials = frame.materials;
  from[0] = surface[P] + surface[N] * bias; from[1] = surface[P + 1] + surface[N + 1] * bias; from[2] = surface[P + 2] + surface[N + 2] * bias;
  frame.random.draw(lightU, 4);
  sampleLight(lights, from, lightU, aim);
  const pdf = aim[L_PDF], cos = surface[N] * aim[0] + surface[N + 1] * aim[1] + surface[N + 2] * aim[2];
  if (!(pdf > 0) || !(cos > 0)) { if (entry) recordLight(entry, frame, -2, 0, 0); return; } // behind the surface: no light this way
  if (metal === 1) metalDensity(materials, m, surface, aim, density);
  const bsdfPdf = metal === 1 ? density[0] : cos / Math.PI; // f·cos is colour × this density for both lobes
  if (!(bsdfPdf > 0)) { if (entry) recordLight(entry, frame, -3, 0, 0); return; } // outside the metal's blur: no shadow ray worth tracing
  path[0] = from[0]; path[1] = from[1]; path[2] = from[2]; path[3] = aim[0]; path[4] = aim[1]; path[5] = aim[2];
  // `| 0`: a whole number, not a double read from the table, since a double passed to a call not inlined is boxed
  const target = lights.table[aim[L_SLOT] * LIGHT + SHAPE_INDEX] | 0; // the sky's shape index is −1
  const blocker = shadowBlocker(frame, target);
  if (blocker >= 0) { if (entry) recordLight(entry, frame, nearestBlocker(frame, blocker), 0, 0); return; }
  const weight = (pdf * pdf) / (pdf * pdf + bsdfPdf * bsdfPdf), k = (bsdfPdf * weight) / pdf;
  const glow = target * MATERIAL + EMISSION, sky = frame.sky, t = 0.5 * (aim[1] + 1);
  for (let c = 0; c < 3; c++) {
    const light = target < 0 ? t * sky[c] + (1 - t) * sky[c + 3] : materials[glow + c];
    radiance[c] += throughput[c] * materials[m + COLOR + c] * light * k;
  }
  if (entry) recordLight(entry, frame, -1, weight, k);
}

/**
 * The shadow ray along `path`: a shape other than the light `target` that it
 * meets before the point drawn on the light (aim[L_DISTANCE]; Infinity for
 * the sky), or −1. A question of yes or no, not of the nearest: it stops at the
 * first blocker, the light itself is not tested, and the kinds most likely to
 * stand in the way (boxes and balls) are asked before the walls (planes).
 */
function shadowBlocker(frame, target) {
  shadow[0] = aim[L_DISTANCE] * (1 - 1e-9); shadow[1] = -1; // a hair short of the light: its own face is no blocker
  const groups = frame.groups;
  if (groups === null) apart(anyBlocker, frame, target);
  else {
    if (groups.boxes.length) apart(boxBlockers, frame, groups.boxes, target);
    if (shadow[1] < 0 && groups.spheres.length) apart(sphereBlockers, frame, groups.spheres, target);
    if (shadow[1] < 0 && groups.others.length) apart(otherBlockers, frame, groups.others, target);
    if (shadow[1] < 0 && groups.planes.length) apart(planeBlockers, frame, groups.planes, target);
  }
  return shadow[1] | 0; // a whole number, never boxed
}

/** The shadow ray's reach (its t must stay under it) and the blocker found (−1: none yet). */
const shadow = pathNumbers(2);

function boxBlockers(frame, list, target) {
  const shapes = frame.packed.shapes, tMin = frame.scene.epsilon, reach = shadow[0];
  for (let n = 0; n < list.length; n++) {
    const i = list[n];
    if (i !== target && boxHit(shapes, i * SHAPE, path[0], path[1], path[2], path[3], path[4], path[5], tMin) < reach) { shadow[1] = i; return; }
  }
}
function sphereBlockers(frame, list, target) {
  const shapes = frame.packed.shapes, tMin = frame.scene.epsilon, reach = shadow[0];
  for (let n = 0; n < list.length; n++) {
    const i = list[n];
    if (i !== target && sphereHit(shapes, i * SHAPE, path[0], path[1], path[2], path[3], path[4], path[5], tMin) < reach) { shadow[1] = i; return; }
  }
}
function planeBlockers(frame, list, target) {
  const shapes = frame.packed.shapes, tMin = frame.scene.epsilon, reach = shadow[0];
  for (let n = 0; n < list.length; n++) {
    const i = list[n];
    if (i !== target && planeHit(shapes, i * SHAPE, path[0], path[1], path[2], path[3], path[4], path[5], tMin) < reach) { shadow[1] = i; return; }
  }
}
function otherBlockers(frame, list, target) {
  const packed = frame.packed, tMin = frame.scene.epsilon, reach = shadow[0];
  for (let n = 0; n < list.length; n++) {
    const i = list[n];
    if (i !== target && packed.hit(packed.shapes, i * SHAPE, path[0], path[1], path[2], path[3], path[4], path[5], tMin) < reach) { shadow[1] = i; return; }
  }
}
function anyBlocker(frame, target) {
  const objects = frame.objects, tMin = frame.scene.epsilon, o = ray.origin, d = ray.direction, reach = shadow[0];
  o.x = path[0]; o.y = path[1]; o.z = path[2]; d.x = path[3]; d.y = path[4]; d.z = path[5];
  for (let i = 0; i < objects.length; i++) if (i !== target && objects[i].hit(ray, tMin) < reach) { shadow[1] = i; return; }
}

/** The inspector's blocker: the nearest shape along the shadow ray, when it is not the light (else the one found). */
function nearestBlocker(frame, found) {
  const nearestIndex = nearestHit(frame);
  return nearestIndex >= 0 && nearestIndex !== frame.lights.table[aim[L_SLOT] * LIGHT + SHAPE_INDEX] ? nearestIndex : found;
}

/** Why a bounce drew no light sample (the inspector's). */
function skippedWhy(lights, lobe) {
  if (lights.count === 0) return 'no light to aim at (lights are emissive spheres and boxes, and a gradient sky)';
  if (lobe === METAL) return 'metal without fuzz (a mirror): one direction only, its light comes from the bounce alone';
  return 'glass: one direction only, its light comes from the bounce alone';
}

/**
 * The eye's ray through the point (x + u[0], y + u[1]) of the picture (pixel
 * x spans x … x + 1), into `ray`: camera.directionAt's formula, whose pixel
 * centre is x + ½, here with the point's own numbers (they vary per sample).
 */
function primaryRay(camera, x, y) {
  const px = x + u[0], py = y + u[1];
  const sx = (2 * px / camera.width - 1) * camera.halfWidth;
  const sy = (1 - 2 * py / camera.height) * camera.halfHeight;
  const r = camera.right, up = camera.up, f = camera.forward, e = camera.position;
  const dx = sx * r.x + sy * up.x + f.x, dy = sx * r.y + sy * up.y + f.y, dz = sx * r.z + sy * up.z + f.z;
  const length = Math.sqrt(dx * dx + dy * dy + dz * dz);
  path[0] = e.x; path[1] = e.y; path[2] = e.z;
  path[3] = dx / length; path[4] = dy / length; path[5] = dz / length;
}

/**
 * The nearest shape along `path`'s ray past the scene's epsilon, its t kept in
 * `nearest[0]` for surfaceAt; -1 for none. When the scene packs
 * (lib/tracing/kernel.js), each kind of shape is tested in numbers (the same t, bit
 * for bit) by a loop of its own: a call V8 does not inline boxes the numbers
 * it passes and returns, and one loop calling several shapes' tests is more
 * than V8 inlines: each loop is called apart (apart.js), compiled on its own
 * with its kind's test inlined.
 */
function nearestHit(frame) {
  nearest[0] = Infinity; nearest[1] = -1;
  const groups = frame.groups;
  if (groups === null) apart(anyShapes, frame);
  else {
    if (groups.spheres.length) apart(spheres, frame, groups.spheres);
    if (groups.planes.length) apart(planes, frame, groups.planes);
    if (groups.boxes.length) apart(boxes, frame, groups.boxes);
    if (groups.others.length) apart(others, frame, groups.others);
  }
  return nearest[1];
}

/** The nearest t so far and its shape's index (shapes tested in scene order within a kind; the smaller index wins a tie, as in trace.js). */
const nearest = pathNumbers(2);

/** Spheres, planes and boxes: their own hit tests, each inlined in its loop. */
function spheres(frame, list) {
  const shapes = frame.packed.shapes, tMin = frame.scene.epsilon;
  for (let n = 0; n < list.length; n++) {
    const t = sphereHit(shapes, list[n] * SHAPE, path[0], path[1], path[2], path[3], path[4], path[5], tMin), i = list[n];
    if (t < nearest[0] || (t === nearest[0] && t < Infinity && i < nearest[1])) { nearest[0] = t; nearest[1] = i; } // a tie: the earlier shape, as trace.js
  }
}
function planes(frame, list) {
  const shapes = frame.packed.shapes, tMin = frame.scene.epsilon;
  for (let n = 0; n < list.length; n++) {
    const t = planeHit(shapes, list[n] * SHAPE, path[0], path[1], path[2], path[3], path[4], path[5], tMin), i = list[n];
    if (t < nearest[0] || (t === nearest[0] && t < Infinity && i < nearest[1])) { nearest[0] = t; nearest[1] = i; } // a tie: the earlier shape, as trace.js
  }
}
function boxes(frame, list) {
  const shapes = frame.packed.shapes, tMin = frame.scene.epsilon;
  for (let n = 0; n < list.length; n++) {
    const t = boxHit(shapes, list[n] * SHAPE, path[0], path[1], path[2], path[3], path[4], path[5], tMin), i = list[n];
    if (t < nearest[0] || (t === nearest[0] && t < Infinity && i < nearest[1])) { nearest[0] = t; nearest[1] = i; } // a tie: the earlier shape, as trace.js
  }
}
/** Cylinders, cones, triangles, meshes: the kernel's test of any kind. */
function others(frame, list) {
  const packed = frame.packed, tMin = frame.scene.epsilon;
  for (let n = 0; n < list.length; n++) {
    const t = packed.hit(packed.shapes, list[n] * SHAPE, path[0], path[1], path[2], path[3], path[4], path[5], tMin), i = list[n];
    if (t < nearest[0] || (t === nearest[0] && t < Infinity && i < nearest[1])) { nearest[0] = t; nearest[1] = i; } // a tie: the earlier shape, as trace.js
  }
}
/** A scene that does not pack (a shape of a sketch's own): each shape's own `hit`. */
function anyShapes(frame) {
  const objects = frame.objects, tMin = frame.scene.epsilon, o = ray.origin, d = ray.direction;
  o.x = path[0]; o.y = path[1]; o.z = path[2]; d.x = path[3]; d.y = path[4]; d.z = path[5];
  for (let i = 0; i < objects.length; i++) {
    const t = objects[i].hit(ray, tMin);
    if (t < nearest[0]) { nearest[0] = t; nearest[1] = i; }
  }
}

const sphereHit = Sphere.packed.hit, planeHit = Plane.packed.hit, boxHit = Box.packed.hit;
const sphereNormal = Sphere.packed.normal, planeNormal = Plane.packed.normal, boxNormal = Box.packed.normal;
/** The kinds nearestHit and surfaceAt call the tests of from places of their own (`frame.kinds`), OTHER for the rest. */
const SPHERE = 0, PLANE = 1, BOX = 2, OTHER = 3;

/** Each shape's kind, as `frame.kinds` holds it. */
export function shapeKinds(objects) {
  const own = [Sphere, Plane, Box];
  return Int32Array.from(objects, (o) => (own.includes(o.constructor) ? own.indexOf(o.constructor) : OTHER));
}

/**
 * The scene's shapes by kind, as indices for nearestHit's loops, or null
 * when the scene does not pack (each shape's own `hit` then).
 * @returns {{ spheres: Int32Array, planes: Int32Array, boxes: Int32Array, others: Int32Array }|null}
 */
export function shapeGroups(objects, packed) {
  if (!packed) return null;
  const of = (Shape) => Int32Array.from(objects.keys()).filter((i) => objects[i].constructor === Shape);
  const known = new Set([Sphere, Plane, Box]);
  return {
    spheres: of(Sphere), planes: of(Plane), boxes: of(Box),
    others: Int32Array.from(objects.keys()).filter((i) => !known.has(objects[i].constructor)),
  };
}

const point = new Vec3(), normal = new Vec3();

/** The hit point, the unit normal turned to face the ray, the ray's direction, and whether it came from inside, into `surface`. */
function surfaceAt(frame, index) {
  const t = nearest[0], dx = path[3], dy = path[4], dz = path[5];
  surface[P] = path[0] + dx * t; surface[P + 1] = path[1] + dy * t; surface[P + 2] = path[2] + dz * t;
  const packed = frame.packed;
  if (packed) { // each kind's own normal in numbers (reads P, writes N), as nearestHit's own hit tests
    const kind = frame.kinds[index], shapes = packed.shapes, at = index * SHAPE;
    if (kind === SPHERE) sphereNormal(shapes, at, surface);
    else if (kind === PLANE) planeNormal(shapes, at, surface);
    else if (kind === BOX) boxNormal(shapes, at, surface);
    else packed.normal(shapes, at, surface);
  } else {
    point.x = surface[P]; point.y = surface[P + 1]; point.z = surface[P + 2];
    frame.objects[index].normalAt(point, normal);
    surface[N] = normal.x; surface[N + 1] = normal.y; surface[N + 2] = normal.z;
  }
  const inside = dx * surface[N] + dy * surface[N + 1] + dz * surface[N + 2] > 0;
  if (inside) { surface[N] = -surface[N]; surface[N + 1] = -surface[N + 1]; surface[N + 2] = -surface[N + 2]; } // the side the ray sees
  surface[D] = dx; surface[D + 1] = dy; surface[D + 2] = dz;
  surface[INSIDE] = inside ? 1 : 0;
}

/* ---- the inspector's record (only built when `record` is given) ---- */

const triple = (a, at = 0) => [a[at], a[at + 1], a[at + 2]];

/** A hit: where, facing which way, and the light it gives off toward the eye (throughput × emission × its MIS weight). */
function recordHit(record, frame, object, weight) {
  const entry = {
    object, index: frame.scene.objects.indexOf(object),
    point: new Vec3(surface[P], surface[P + 1], surface[P + 2]), normal: new Vec3(surface[N], surface[N + 1], surface[N + 2]),
    inside: surface[INSIDE] === 1,
    emitted: object.material.emission.map((e, c) => throughput[c] * e * weight), emissionWeight: weight,
    lobe: null, direction: null, pdf: null, weight: null, throughput: null,
  };
  record.push(entry);
  return entry;
}

/** The bounce drawn at that hit: the lobe, the new direction and its density, the weight, the throughput after it (and the roulette's q). */
function recordBounce(entry, survival) {
  entry.lobe = LOBE_NAMES[event[LOBE]];
  entry.direction = new Vec3(event[DIRECTION], event[DIRECTION + 1], event[DIRECTION + 2]);
  entry.pdf = event[PDF];
  entry.delta = event[LOBE] !== DIFFUSE; // a mirror or glass direction: its pdf is the probability of choosing the lobe
  entry.weight = triple(event, WEIGHT);
  entry.throughput = triple(throughput);
  if (survival < 1) entry.survival = survival;
}

/**
 * A diffuse bounce's light sample: the light, the point aimed at, the
 * direction, the blocker's name (`hit` ≥ 0) or null, the density (pick ×
 * solid angle), the MIS weight and the light it added (throughput × colour ×
 * light × `k`). `hit` −2: the direction lies behind the surface; −3: outside
 * the fuzzy metal's blur (a direction its bounce never draws).
 */
function recordLight(entry, frame, hit, weight, k) {
  const objects = frame.scene.objects, target = frame.lights.table[aim[L_SLOT] * LIGHT + SHAPE_INDEX];
  const sky = frame.sky, t = 0.5 * (aim[1] + 1);
  const light = (c) => (target < 0 ? t * sky[c] + (1 - t) * sky[c + 3] : frame.materials[target * MATERIAL + EMISSION + c]);
  entry.lightSample = {
    light: target < 0 ? 'sky' : shapeName(objects[target], objects),
    point: aim[L_DISTANCE] < Infinity ? new Vec3(aim[L_POINT], aim[L_POINT + 1], aim[L_POINT + 2]) : null,
    direction: new Vec3(aim[0], aim[1], aim[2]),
    blocked: hit >= 0 ? shapeName(objects[hit], objects) : null,
    pdf: aim[L_PDF], weight,
    contribution: [0, 1, 2].map((c) => throughput[c] * frame.materials[frame.objects.indexOf(entry.object) * MATERIAL + COLOR + c] * light(c) * k),
  };
  if (hit === -2) entry.lightSample.below = true;
  if (hit === -3) entry.lightSample.outsideBlur = true;
}

/** How the path ended: a bounce drawn at the last hit is told too (the roulette's zeroes its throughput); a path that left gathers the sky (times the throughput). */
function endRecord(record, why, entry, survival, sky, dy, weight) {
  if (entry && why !== 'maxBounces') {
    recordBounce(entry, survival);
    if (why === 'roulette') entry.throughput = [0, 0, 0];
  }
  record.end = why;
  record.sky = why === 'sky' ? [0, 1, 2].map((c) => throughput[c] * skyLight(sky, c, dy) * weight) : [0, 0, 0];
  if (why === 'sky') record.skyWeight = weight;
}
