/**
 * What colour is this pixel? The lesson's story of one ray, top to bottom:
 *   1. find the nearest thing the ray hits (none: the background);
 *   2. light that point: emission + ambient + each light it can see (a shadow
 *      ray toward each light; Lambert's cos term; an optional highlight);
 *   3. mix in what a mirror reflects and what glass lets through (Fresnel).
 *
 * `trace` fills `color` ([r, g, b], 0–1 and above) and allocates nothing;
 * given a `steps` object it also records every intermediate value for the
 * inspector, computed apart from the colour by the same functions.
 * The formulas at its leaves (Lambert, Phong, Snell, Schlick, the mirror and
 * glass mix) live in lib/tracing/optics.js, which render()'s fast path, lib/tracing/kernel.js,
 * calls too (tests/unit/same-bytes.test.js proves the two give the same bytes).
 */
import { Vec3, dot, copy, set, scaleAndAdd, reflect } from '../math/vec3.js';
import { lambert, specular as phong, lightShare, spotShare, falloff, refract, fresnel as fresnelShare, mix } from './optics.js';
import { Ray } from '../math/ray.js';
import { EPSILON, DEG_PER_RAD } from '../math/constants.js';

/**
 * Traces `ray` through `scene`; writes its colour into `color` and returns it.
 * @param {import('../scene/scene.js').Scene} scene
 * @param {Ray} ray
 * @param {number[]} color [r, g, b] target
 * @param {object} [steps] filled with the hit record when given (the inspector's)
 * @param {number} [depth=0] how many bounces led here
 * @param {object[]} [objects=scene.objects] the shapes this ray may hit: all of them, or for a
 *   primary ray the few that `render` knows can be under its pixel (the nearest hit is the same)
 */
export function trace(scene, ray, color, steps, depth = 0, objects = scene.objects) {
  const frame = frames[depth] ?? newFrame(depth);
  if (!nearestHit(objects, ray, frame.hit, scene.epsilon)) {
    if (steps) steps.hit = null;
    return copyColor(color, scene.background);
  }
  frame.scene = scene;
  frame.ray = ray;
  surfaceAt(frame);

  lightPoint(frame, color);
  const record = steps ? recordHit(steps, frame) : null;
  const { reflection, transparency } = frame.hit.object.material;
  if (depth < scene.maxDepth && (reflection > 0 || transparency > 0)) mirrorAndGlass(frame, color, record);
  return color;
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
 * `frame.inside` when the ray meets the surface from inside. (Numbers stay in
 * the frame rather than passing between steps: docs/performance.md, "Notes on V8".)
 */
function surfaceAt(frame) {
  const o = frame.ray.origin, d = frame.ray.direction, t = frame.hit.t, P = frame.point, N = frame.normal;
  P.x = o.x + d.x * t; P.y = o.y + d.y * t; P.z = o.z + d.z * t;
  frame.hit.object.normalAt(P, N);
  frame.inside = d.x * N.x + d.y * N.y + d.z * N.z > 0;
  if (frame.inside) { N.x = -N.x; N.y = -N.y; N.z = -N.z; } // shade the side the ray sees
}

/** Emission + ambient + every light the point can see (diffuse and specular). */
function lightPoint(frame, color) {
  const { scene } = frame, object = frame.hit.object, { emission, color: surface } = object.material;
  const ambient = scene.ambient, lights = scene.lights;
  setColor(color, emission[0] + ambient * surface[0], emission[1] + ambient * surface[1], emission[2] + ambient * surface[2]);
  for (let i = 0; i < lights.length; i++) {
    const light = lights[i];
    if (light.object === object) continue; // a light does not light itself
    const distance = directionTo(frame.toLight, frame.point, light.position);
    const cos = cosToLight(frame); // Lambert: light falls at an angle
    if (cos <= 0) continue; // the light is behind the surface
    const beam = light.spot ? beamShare(light.spot, frame.toLight) : 1; // a spot light's cone
    if (beam === 0) continue; // outside it
    const transmission = (scene.shadows ? shadowRay(frame, distance, light.object) : 1) * beam;
    if (transmission === 0) continue; // in shadow
    const reach = transmission * falloff(light.attenuation, distance); // what arrives, less the fall with distance
    const diffuse = cos * reach;
    const highlight = scene.specular ? specular(frame, cos) * reach : 0;
    const lightColor = light.emission;
    color[0] += lightShare(lightColor[0], surface[0], diffuse, highlight);
    color[1] += lightShare(lightColor[1], surface[1], diffuse, highlight);
    color[2] += lightShare(lightColor[2], surface[2], diffuse, highlight);
  }
}

/** How much of a spot light's cone reaches along the unit direction `toLight` (optics.js). */
function beamShare(spot, toLight) {
  return spotShare(spot.axis.x, spot.axis.y, spot.axis.z, spot.cosOuter, spot.cosInner, toLight.x, toLight.y, toLight.z);
}

/** Unit vector from `from` toward `to` into `out`; returns the distance. */
function directionTo(out, from, to) {
  const x = to.x - from.x, y = to.y - from.y, z = to.z - from.z;
  const distance = Math.sqrt(x * x + y * y + z * z), k = 1 / distance;
  out.x = x * k; out.y = y * k; out.z = z * k;
  return distance;
}

/**
 * Shadow ray from the hit point along `frame.toLight`: how much light gets
 * through to the light `distance` away (1 none in the way, 0 blocked; glass
 * lets its `transparency` through). The ray stops at the light: whatever lies
 * beyond it, or around it (`lightObject`, the light's own shape), casts no shadow.
 */
function shadowRay(frame, distance, lightObject) {
  const { scene } = frame, shadow = frame.shadowRay, objects = scene.objects, epsilon = scene.epsilon;
  scaleAndAdd(shadow.origin, frame.point, frame.normal, scene.bias); // step off the surface: no acne
  copy(shadow.direction, frame.toLight);
  const reach = distance - scene.bias; // stop short of the light: a light on a face is not behind it
  let transmission = 1;
  for (let i = 0; i < objects.length; i++) {
    const blocker = objects[i];
    if (blocker === lightObject || blocker.hit(shadow, epsilon) >= reach) continue;
    transmission *= blocker.material.transparency;
    if (transmission === 0) return 0;
  }
  return transmission;
}

/** Lambert's cos θ between the normal and `frame.toLight`. */
function cosToLight(frame) {
  const N = frame.normal, L = frame.toLight;
  return lambert(N.x, N.y, N.z, L.x, L.y, L.z);
}

/** Phong highlight toward `frame.toLight` (`cos` the normal's cos to it): specular·(R·V)^shininess, R the light mirrored about the normal. */
function specular(frame, cos) {
  const { specular: strength, shininess } = frame.hit.object.material;
  const L = frame.toLight, N = frame.normal, D = frame.ray.direction;
  return phong(strength, shininess, cos, L.x, L.y, L.z, N.x, N.y, N.z, D.x, D.y, D.z);
}

/**
 * Mirror and glass: what the mirror ray and the glass ray bring back, mixed
 * into the local colour (`mix`), F the Fresnel share of light reflected.
 */
function mirrorAndGlass(frame, color, record) {
  const { scene, ray, reflected, refracted } = frame;
  const { reflection, transparency, ior, color: surface } = frame.hit.object.material;
  const d = ray.direction, n = frame.normal, cosi = -dot(d, n);
  const eta = frame.inside ? ior : 1 / ior;
  const refracts = transparency > 0 && refract(frame.bent, 0, d.x, d.y, d.z, n.x, n.y, n.z, cosi, eta); // Snell
  const fresnel = fresnelShare(transparency, refracts, cosi, ior);

  const mirrored = frame.reflectedColor, through = frame.refractedColor, depth = frame.depth + 1;
  reflect(reflected.direction, d, n);
  scaleAndAdd(reflected.origin, frame.point, frame.normal, scene.bias);
  trace(scene, reflected, mirrored, record && (record.reflection = bounce(reflected)), depth);
  if (refracts) {
    set(refracted.direction, frame.bent[0], frame.bent[1], frame.bent[2]);
    scaleAndAdd(refracted.origin, frame.point, frame.normal, -scene.bias); // start just inside
    trace(scene, refracted, through, record && (record.refraction = bounce(refracted)), depth);
  } else setColor(through, 0, 0, 0);

  for (let i = 0; i < 3; i++) color[i] = mix(color[i], mirrored[i], through[i], surface[i], reflection, transparency, fresnel);
  if (record) record.fresnel = fresnel;
}

function setColor(out, r, g, b) {
  out[0] = r; out[1] = g; out[2] = b;
  return out;
}

function copyColor(out, c) {
  out[0] = c[0]; out[1] = c[1]; out[2] = c[2];
  return out;
}

/*
 * Scratch space, one frame per bounce depth, so tracing allocates nothing.
 * A frame is also the bounce's context: the scene and ray being traced, what
 * it hit, where and facing which way, passed whole to each step of the story.
 */
const frames = [];
function newFrame(depth) {
  while (frames.length <= depth) {
    frames.push({
      depth: frames.length, scene: null, ray: null,
      hit: { object: null, t: Infinity }, point: new Vec3(), normal: new Vec3(), inside: false,
      toLight: new Vec3(), shadowRay: new Ray(), reflected: new Ray(), refracted: new Ray(), bent: new Float64Array(3),
      reflectedColor: [0.5, 0.5, 0.5], refractedColor: [0.5, 0.5, 0.5],
    });
  }
  return frames[depth];
}

/* ---- the inspector's record (only built when `steps` is given) ---- */

/** The hit and how each light coloured it, by the lighting's own functions; the colour stays trace's. */
function recordHit(steps, frame) {
  const { scene, ray } = frame, { object, t } = frame.hit, { material } = object;
  const cos = Math.min(1, Math.abs(dot(ray.direction, frame.normal)));
  steps.hit = {
    object, index: scene.objects.indexOf(object), t,
    point: copy(new Vec3(), frame.point), normal: copy(new Vec3(), frame.normal), inside: frame.inside,
    incidence: Math.acos(cos) * DEG_PER_RAD,
    lights: scene.lights.filter((light) => light.object !== object).map((light) => recordLight(frame, light)),
    emission: [...material.emission],
    ambient: material.color.map((c) => c * scene.ambient),
    reflection: null, refraction: null, fresnel: null,
  };
  return steps.hit;
}

/** A bounce's record: the direction its ray leaves in (the mirror's, or Snell's through glass); trace adds what it hit. */
function bounce(ray) {
  return { direction: copy(new Vec3(), ray.direction), hit: null };
}

/**
 * The first shape in the way of the shadow ray toward a light `distance`
 * away (never the light's own shape), `{ object, t, point }`, or null: where
 * the 3D view draws a blocked shadow ray stop. The same ray as shadowRay's.
 */
function firstBlocker(frame, distance, lightObject) {
  const { scene } = frame, shadow = frame.shadowRay, hit = { object: null, t: Infinity };
  scaleAndAdd(shadow.origin, frame.point, frame.normal, scene.bias);
  copy(shadow.direction, frame.toLight);
  const objects = scene.objects.filter((o) => o !== lightObject);
  if (!nearestHit(objects, shadow, hit, scene.epsilon) || hit.t >= distance - scene.bias) return null;
  return { object: hit.object, t: hit.t, point: scaleAndAdd(new Vec3(), shadow.origin, shadow.direction, hit.t) };
}

/** One light's share at the hit point, as lightPoint adds it (zero when it faces away or is blocked). */
function recordLight(frame, light) {
  const { scene } = frame, surface = frame.hit.object.material.color, lightColor = light.emission;
  const distance = directionTo(frame.toLight, frame.point, light.position);
  const cos = cosToLight(frame);
  const beam = light.spot ? beamShare(light.spot, frame.toLight) : 1;
  const transmission = cos <= 0 || beam === 0 ? 0 : (scene.shadows ? shadowRay(frame, distance, light.object) : 1) * beam;
  const fall = falloff(light.attenuation, distance), reach = transmission * fall;
  const diffuse = transmission > 0 ? cos * reach : 0;
  const highlight = transmission > 0 && scene.specular ? specular(frame, cos) * reach : 0;
  const inShadow = cos > 0 && beam > 0 && transmission < beam;
  const blocker = inShadow ? firstBlocker(frame, distance, light.object) : null;
  return {
    light: light.source, position: copy(new Vec3(), light.position), distance,
    cos, facing: cos > 0, inShadow, transmission, beam,
    blocker: blocker?.object ?? null, blockerT: blocker?.t ?? null, blockedAt: blocker?.point ?? null,
    attenuation: light.attenuation, falloff: fall,
    contribution: [0, 1, 2].map((i) => lightShare(lightColor[i], surface[i], diffuse, highlight)),
    specular: highlight,
  };
}
