/**
 * What colour is this pixel? The lesson's story of one ray, top to bottom:
 *   1. find the nearest thing the ray hits (none: the background);
 *   2. light that point: emission + ambient + each light it can see (a shadow
 *      ray toward each light; Lambert's cos term; an optional highlight);
 *   3. mix in what a mirror reflects and what glass lets through (Fresnel).
 *
 * `trace` fills `out` ([r, g, b], 0–1 and above) and allocates nothing; given a
 * `steps` object it also records every intermediate value for the inspector.
 */
import { Vec3, dot, copy, scaleAndAdd, reflect } from './vec3.js';
import { Ray } from './ray.js';
import { EPSILON, DEG_PER_RAD } from './constants.js';

/**
 * Traces `ray` through `scene`; writes its colour into `out` and returns it.
 * @param {import('./scene.js').Scene} scene
 * @param {Ray} ray
 * @param {number[]} out [r, g, b] target
 * @param {object} [steps] filled with the hit record when given (the inspector's)
 * @param {number} [depth=0] how many bounces led here
 * @param {object[]} [objects=scene.objects] the shapes this ray may hit: all of them, or for a
 *   primary ray the few that `render` knows can be under its pixel (the nearest hit is the same)
 */
export function trace(scene, ray, out, steps, depth = 0, objects = scene.objects) {
  const f = frames[depth] ?? newFrame(depth);
  if (!nearestHit(objects, ray, f.hit, scene.epsilon)) {
    if (steps) steps.hit = null;
    return copyColor(out, scene.background);
  }
  const object = f.hit.object, m = object.material;
  const inside = surfaceAt(f, ray);
  const record = steps ? hitRecord(steps, object, f, ray, inside, scene) : null;

  lightPoint(scene, object, f, ray, out, record);
  if (depth < scene.maxDepth && (m.reflection > 0 || m.transparency > 0)) {
    mirrorAndGlass(scene, m, f, ray, inside, out, record, depth);
  }
  return out;
}

/**
 * Nearest object along the ray (t > tMin): writes `{ object, t }` into `hit`;
 * false when none.
 */
export function nearestHit(objects, ray, hit, tMin = EPSILON) {
  let nearest = Infinity, found = null;
  for (let i = 0; i < objects.length; i++) {
    const t = objects[i].hit(ray, tMin);
    if (t < nearest) { nearest = t; found = objects[i]; }
  }
  hit.object = found;
  hit.t = nearest;
  return found !== null;
}

/**
 * The hit point P = Ro + Rd·t and its unit normal, turned to face the ray;
 * true when the ray meets the surface from inside. (Numbers stay in `f`
 * rather than passing between functions: a bare number handed to a function
 * the engine did not inline costs an allocation, once per pixel.)
 */
function surfaceAt(f, ray) {
  const o = ray.origin, d = ray.direction, t = f.hit.t, P = f.point, N = f.normal;
  P.x = o.x + d.x * t; P.y = o.y + d.y * t; P.z = o.z + d.z * t;
  f.hit.object.normalAt(P, N);
  const inside = d.x * N.x + d.y * N.y + d.z * N.z > 0;
  if (inside) { N.x = -N.x; N.y = -N.y; N.z = -N.z; } // shade the side the ray sees
  return inside;
}

/** Emission + ambient + every light the point can see (diffuse and specular). */
function lightPoint(scene, object, f, ray, out, record) {
  const m = object.material, c = m.color, a = scene.ambient, lights = scene.lights;
  setColor(out, m.emission[0] + a * c[0], m.emission[1] + a * c[1], m.emission[2] + a * c[2]);
  for (let i = 0; i < lights.length; i++) {
    const light = lights[i];
    if (light.object === object) continue; // a light does not light itself
    const distance = directionTo(f.toLight, f.point, light.position);
    const cos = dot(f.normal, f.toLight); // Lambert: light falls at an angle
    if (cos <= 0 && !record) continue; // the light is behind the surface
    const transmission = cos <= 0 ? 0 : scene.shadows ? shadowRay(scene, f, distance, light.object) : 1;
    if (transmission === 0 && !record) continue;
    const diffuse = cos * transmission;
    const highlight = transmission > 0 && scene.specular && m.specular > 0 ? specular(m, f, ray) * transmission : 0;
    const e = light.emission;
    out[0] += e[0] * (c[0] * diffuse + highlight);
    out[1] += e[1] * (c[1] * diffuse + highlight);
    out[2] += e[2] * (c[2] * diffuse + highlight);
    if (record) recordLight(record, light, cos, transmission, Math.max(0, diffuse), highlight, c, distance);
  }
}

/** Unit vector from `from` toward `to` into `out`; returns the distance. */
function directionTo(out, from, to) {
  const x = to.x - from.x, y = to.y - from.y, z = to.z - from.z;
  const distance = Math.sqrt(x * x + y * y + z * z), k = 1 / distance;
  out.x = x * k; out.y = y * k; out.z = z * k;
  return distance;
}

/**
 * Shadow ray: how much light gets from the point to the light (1 none in the
 * way, 0 blocked; glass lets its `transparency` through). The ray stops at
 * the light: whatever lies beyond it, or around it, casts no shadow.
 */
function shadowRay(scene, f, distance, lightObject) {
  const shadow = f.shadowRay, objects = scene.objects, epsilon = scene.epsilon;
  scaleAndAdd(shadow.origin, f.point, f.normal, scene.bias); // step off the surface: no acne
  copy(shadow.direction, f.toLight);
  const reach = distance - scene.bias; // stop short of the light: a light on a face is not behind it
  let transmission = 1;
  for (let i = 0; i < objects.length; i++) {
    const o = objects[i];
    if (o === lightObject || o.hit(shadow, epsilon) >= reach) continue;
    transmission *= o.material.transparency;
    if (transmission === 0) return 0;
  }
  return transmission;
}

/** Phong highlight: (R·V)^shininess, R the light mirrored about the normal. */
function specular(m, f, ray) {
  reflect(f.mirror, f.toLight, f.normal);
  const rv = dot(f.mirror, ray.direction); // mirror = −R, ray = −V: R·V
  return rv > 0 ? m.specular * Math.pow(rv, m.shininess) : 0;
}

/**
 * Mirror and glass: opaque = (1 − reflection)·local + reflection·colour·mirror;
 * result = (1 − transparency)·opaque + transparency·(F·mirror + (1 − F)·colour·refracted),
 * F the Fresnel share of light reflected (Schlick's approximation).
 */
function mirrorAndGlass(scene, m, f, ray, inside, out, record, depth) {
  const kr = m.reflection, kt = m.transparency, c = m.color;
  const cosi = -dot(ray.direction, f.normal);
  const eta = inside ? m.ior : 1 / m.ior;
  const refracts = kt > 0 && refractDirection(f.refracted.direction, ray.direction, f.normal, cosi, eta);
  const F = kt > 0 ? (refracts ? schlick(cosi, m.ior) : 1) : 0;

  const mirror = f.mirrorColor, through = f.throughColor;
  reflect(f.reflected.direction, ray.direction, f.normal);
  scaleAndAdd(f.reflected.origin, f.point, f.normal, scene.bias);
  trace(scene, f.reflected, mirror, record && (record.reflection = {}), depth + 1);
  if (refracts) {
    scaleAndAdd(f.refracted.origin, f.point, f.normal, -scene.bias); // start just inside
    trace(scene, f.refracted, through, record && (record.refraction = {}), depth + 1);
  } else setColor(through, 0, 0, 0);

  for (let i = 0; i < 3; i++) {
    const opaque = (1 - kr) * out[i] + kr * c[i] * mirror[i];
    out[i] = (1 - kt) * opaque + kt * (F * mirror[i] + (1 - F) * c[i] * through[i]);
  }
  if (record) record.fresnel = F;
}

/** Snell's law: refracted unit direction into `out`; false on total internal reflection. */
function refractDirection(out, d, n, cosi, eta) {
  const k = 1 - eta * eta * (1 - cosi * cosi);
  if (k < 0) return false;
  const s = eta * cosi - Math.sqrt(k);
  out.x = eta * d.x + s * n.x; out.y = eta * d.y + s * n.y; out.z = eta * d.z + s * n.z;
  return true;
}

/** Schlick's approximation of the Fresnel reflectance at cos θ for index `ior`. */
function schlick(cosi, ior) {
  const r0 = ((1 - ior) / (1 + ior)) ** 2;
  return r0 + (1 - r0) * (1 - cosi) ** 5;
}

function setColor(out, r, g, b) {
  out[0] = r; out[1] = g; out[2] = b;
  return out;
}

function copyColor(out, c) {
  out[0] = c[0]; out[1] = c[1]; out[2] = c[2];
  return out;
}

/* Scratch space, one frame per bounce depth, so tracing allocates nothing. */
const frames = [];
function newFrame(depth) {
  while (frames.length <= depth) {
    frames.push({
      hit: { object: null, t: Infinity }, point: new Vec3(), normal: new Vec3(), toLight: new Vec3(),
      mirror: new Vec3(), shadowRay: new Ray(), reflected: new Ray(), refracted: new Ray(),
      mirrorColor: [0.5, 0.5, 0.5], throughColor: [0.5, 0.5, 0.5],
    });
  }
  return frames[depth];
}

/* ---- the inspector's record (only built when `steps` is given) ---- */

function hitRecord(steps, object, f, ray, inside, scene) {
  const cos = Math.min(1, Math.abs(dot(ray.direction, f.normal)));
  steps.hit = {
    object, index: scene.objects.indexOf(object), t: f.hit.t,
    point: copy(new Vec3(), f.point), normal: copy(new Vec3(), f.normal), inside,
    incidence: Math.acos(cos) * DEG_PER_RAD, lights: [],
    emission: [...object.material.emission],
    ambient: object.material.color.map((c) => c * scene.ambient),
    reflection: null, refraction: null, fresnel: null,
  };
  return steps.hit;
}

function recordLight(record, light, cos, transmission, diffuse, highlight, c, distance) {
  const e = light.emission;
  record.lights.push({
    light: light.source, position: copy(new Vec3(), light.position), distance,
    cos, facing: cos > 0, inShadow: cos > 0 && transmission < 1, transmission,
    contribution: [0, 1, 2].map((i) => e[i] * (c[i] * diffuse + highlight)),
    specular: highlight,
  });
}
