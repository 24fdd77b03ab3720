/**
 * render()'s fast path: the story of trace.js — nearest hit, light the point,
 * mirror and glass — step for step, by the same formulas (lib/tracing/optics.js), but
 * with the scene packed into typed arrays and each ray's numbers in local
 * variables, so no step reads through a chain of objects.
 *
 * Same bytes as trace.js, proven by tests/unit/same-bytes.test.js over random
 * scenes (spheres, planes, boxes, cylinders, cones, triangles, meshes, lights,
 * mirrors, glass). trace.js stays the
 * lesson's readable version and the one the inspector runs; a formula changed
 * in lib/tracing/optics.js changes both. Full shading of the class scene is 1.17–1.2× faster
 * this way (docs/performance.md). A shape with a `hit` or `normalAt` of its
 * own (a subclass, or a method replaced), a shape whose class has no packed
 * form, or a shape added twice, is not packed: `packScene` says no and
 * render() uses trace.js. Each shape class packs itself and does its own hit
 * and normal in numbers (its static `packed`, layout in lib/shapes/packed.js).
 */
import { plainClassOf, classOf, ballOf } from '../shapes/index.js';
import * as shapeLayout from '../shapes/packed.js';
import { scratchNumbers, sideTables, checkCopies } from '../shapes/packed.js';
import * as lightLayout from '../lights/packed.js';
import { packSource } from '../lights/packed.js';
import { reflectInto } from '../math/vec3.js';
import { MATERIAL_LAYOUT, packMaterial } from '../shapes/material.js';
import { lambert, specular, lightShare, spotShare, falloff, refract, fresnel as fresnelShare, mix } from './optics.js';

/*
 * The packed layout's offsets, as literals. The modules named here own them
 * (the GPU engine reads them there); the loops below run on copies because V8
 * folds a module's own literal into them but reads an imported number from its
 * module at every use (render() of the class scene 6–7 % slower).
 * checkCopies throws at load when a copy and its owner part.
 */
/** lib/shapes/packed.js: numbers per shape, where its kind lies; P and N in `surface`. */
const SHAPE = 7, KIND = 6, P = 0, N = 3;
/** lib/lights/packed.js: numbers per light source, and where each of its fields lies. */
const LIGHT = 14, LIGHT_EMISSION = 3, LIGHT_SHAPE = 6, ATTENUATION = 7, IS_SPOT = 8, AXIS = 9, COS_OUTER = 12, COS_INNER = 13;
/** lib/shapes/material.js's table: numbers per material (r g b, emission r g b, reflection, transparency, ior, specular, shininess, fuzz), where each field lies. */
const MATERIAL = 12, EMISSION = 3, REFLECTION = 6, TRANSPARENCY = 7, IOR = 8, SPECULAR = 9, SHININESS = 10;
checkCopies({ SHAPE, KIND, P, N }, shapeLayout, 'lib/shapes/packed.js');
checkCopies({ LIGHT, LIGHT_EMISSION, LIGHT_SHAPE, ATTENUATION, IS_SPOT, AXIS, COS_OUTER, COS_INNER }, lightLayout, 'lib/lights/packed.js');
checkCopies({ MATERIAL, EMISSION, REFLECTION, TRANSPARENCY, IOR, SPECULAR, SHININESS }, MATERIAL_LAYOUT, 'lib/shapes/material.js');

/** The deepest bounce a scene allows (Scene's maxDepth is 0–16), plus the primary ray. */
const LEVELS = 17;
/** The ray being traced at each bounce depth: origin xyz, direction xyz. */
const rays = scratchNumbers(LEVELS * 6);
/**
 * Colours: slot 0 is the pixel's; the bounce at depth d writes what its mirror
 * ray brings back at (d + 1)·6 and what its glass lets through at (d + 1)·6 + 3.
 */
const colors = scratchNumbers((LEVELS + 1) * 6);

/**
 * A shadow ray toward a light meets nothing farther from the light than its
 * own length (plus twice the bias it starts off the surface by): each point
 * Q on it has |Q − light| < reach + 2·bias. So a sphere whose nearest point is
 * farther from the light than that cannot shade: `apart[light·count + shape]`
 * is that distance, |C − light| − r, less a margin of 1e-5·(|C − light| + r + 1)
 * and 1e-5·reach (below) for rounding and the tangent band (which lets a ray
 * graze a sphere up to 1e-6·(r + |C − origin|) outside it). The sphere test it
 * saves (28 % of the class scene's shadow tests) would have said "no hit"
 * anyway; other shapes are never skipped (−Infinity).
 */
const APART_MARGIN = 1e-5;

/** How far from the light a sphere's nearest point must be (`apart`) to be out of a shadow ray's way. */
export function outOfReach(k, reach) {
  return reach + 2 * k.bias + APART_MARGIN * reach;
}

/**
 * The scene in numbers: its shapes, their materials and its lights in typed
 * arrays, in the scene's order (ties between shapes resolve as in trace.js).
 */
export class PackedScene {
  constructor(scene) {
    const { objects, lights } = scene;
    this.count = objects.length;
    this.shapes = new Float64Array(objects.length * SHAPE);
    this.materials = new Float64Array(objects.length * MATERIAL);
    this.index = new Map(objects.map((object, i) => [object, i]));
    /** What shapes of more than six numbers keep beside them (lib/shapes/packed.js): a triangle's, a mesh's. */
    this.tables = [];
    objects.forEach((object, i) => this.#packShape(object, i));
    this.lightCount = lights.length;
    this.lights = new Float64Array(lights.length * LIGHT);
    lights.forEach((light, i) => packSource(light, light.object ? this.index.get(light.object) ?? -1 : -1, this.lights, i * LIGHT)); // layout: lib/lights/packed.js
    this.apart = this.#apart(objects, lights);
    this.background = Float64Array.from(scene.background);
    this.ambient = scene.ambient;
    this.shadows = scene.shadows;
    this.specular = scene.specular;
    this.bias = scene.bias;
    this.epsilon = scene.epsilon;
    this.maxDepth = scene.maxDepth;
    /** Every shape's index, in order: the list a mirror, glass or shadow ray tests. */
    this.all = Int32Array.from(objects.keys());
    /**
     * The shapes' hit test, `hit(shapes, at, ox, oy, oz, dx, dy, dz, tMin)`: when
     * every shape is of one kind (the lesson's scenes: spheres) that kind's
     * test itself, which saves asking each shape its kind (about 6 %).
     */
    const kinds = new Set(objects.map((object) => kindIndex(object.constructor)));
    const only = kinds.size === 1 ? KINDS[[...kinds][0]] : null;
    this.hit = only ? only.hit : hitShape;
    /** The normal, `normal(shapes, at, surface)`: that kind's own too, for a scene of one kind. */
    this.normal = only ? only.normal : normalShape;
  }

  /** For each light and shape, how far the shape's near side is from the light, less a margin (balls; −Infinity otherwise). */
  #apart(objects, lights) {
    const apart = new Float64Array(lights.length * objects.length).fill(-Infinity);
    lights.forEach(({ position: p }, l) => objects.forEach((object, i) => {
      const ball = ballOf(object);
      if (!ball) return;
      const c = ball.center, D = Math.hypot(c.x - p.x, c.y - p.y, c.z - p.z), r = ball.radius;
      apart[l * objects.length + i] = D - r - APART_MARGIN * (D + r + 1);
    }));
    return apart;
  }

  /** Shape i's numbers (its class packs them) and its material's into `shapes` and `materials`. */
  #packShape(object, i) {
    const s = i * SHAPE, m = object.material, kind = kindIndex(object.constructor);
    packInSlot(KINDS[kind], object, i, this.shapes, s, this.tables);
    this.shapes[s + KIND] = kind;
    packMaterial(m, this.materials, i * MATERIAL);
  }
}

/**
 * A shape's packed numbers go first to a slot with room to spare, every spare
 * number NaN: a packed form that writes past its KIND numbers would
 * otherwise overwrite its kind (or the next shape's numbers) and give a wrong
 * picture with no error. It throws instead, naming the shape.
 */
const _slot = new Float64Array(4 * SHAPE);

function packInSlot(packed, object, i, shapes, at, tables) {
  _slot.fill(NaN);
  packed.pack(object, _slot, 0, tables);
  let past = _slot.length;
  while (past > KIND && Number.isNaN(_slot[past - 1])) past--;
  if (past > KIND) {
    const name = object.name ? ` '${object.name}'` : '';
    throw new RangeError(`objects[${i}] (${object.constructor.type}${name}): its packed form wrote ${past} numbers, more than the ${KIND} a shape's slot holds (lib/shapes/packed.js: a shape of more numbers keeps them in a side table)`);
  }
  for (let n = 0; n < KIND; n++) shapes[at + n] = Number.isNaN(_slot[n]) ? 0 : _slot[n]; // numbers it did not write stay 0
}

/** The packed form of every shape class the kernel has met, by kind: `shapes[at + KIND]` indexes this. */
const KINDS = [];
/** Each class's kind number. */
const KIND_OF = new Map();

/** The kind number of a shape class (its packed form read once). */
function kindIndex(Shape) {
  if (!KIND_OF.has(Shape)) KIND_OF.set(Shape, KINDS.push(Shape.packed) - 1);
  return KIND_OF.get(Shape);
}

/**
 * Why the scene cannot be packed: the first shape that stops it, `{ index, why }`,
 * or null when it packs. A shape must be a plain listed shape with a packed form,
 * so that trace.js would ask it exactly what the kernel computes (not a subclass,
 * nor a `hit` or `normalAt` of its own, on the shape or its class); and added
 * once (trace.js tells shapes apart by identity, the packed scene by their place
 * in the list). The one answer for the kernel, the GPU engines and the path tracer.
 */
export function unpackable(scene) {
  const seen = new Set();
  for (const [index, shape] of scene.objects.entries()) {
    if (!plainClassOf(shape)?.packed) {
      return { index, why: classOf(shape) ? "its hit or normalAt is not its class's own (a subclass, or a method replaced)" : 'its class has no packed form' };
    }
    if (seen.has(shape)) return { index, why: 'it is added to the scene twice, and the packed scene tells shapes apart by their place in the list (add a copy instead)' };
    seen.add(shape);
  }
  return null;
}

/** The scene packed, or null for trace.js to handle (unpackable says why). */
export function packScene(scene) {
  return unpackable(scene) === null ? new PackedScene(scene) : null;
}

/**
 * The colour of the primary ray from `origin` along `direction` (Vec3s),
 * tested first against the shapes `candidates[from … to)` (indices, in scene
 * order): trace(scene, ray, color, undefined, 0, those shapes) in numbers.
 * The direction comes as its Vec3, not as three numbers (docs/performance.md, "Notes on V8").
 * @returns {Float64Array} [r, g, b] in its first three entries (reused: read it before the next call)
 */
export function tracePrimary(k, origin, direction, candidates, from, to) {
  sideTables.current = k.tables;
  rays[0] = origin.x; rays[1] = origin.y; rays[2] = origin.z;
  rays[3] = direction.x; rays[4] = direction.y; rays[5] = direction.z;
  traceRay(k, 0, 0, candidates, from, to);
  return colors;
}

/**
 * The hit being shaded, as trace.js's frame holds it: the point P, the unit
 * normal N facing the ray, the ray's direction, and 1 when it meets the
 * surface from inside. Numbers pass between the steps here, not as arguments
 * (docs/performance.md, "Notes on V8").
 */
const surface = scratchNumbers(10);
const D = 6, INSIDE = 9; // P and N: lib/shapes/packed.js

/** trace(): the ray at `depth` in `rays`; its colour into `colors[out …]`. */
function traceRay(k, depth, out, candidates, from, to) {
  const r = depth * 6, ox = rays[r], oy = rays[r + 1], oz = rays[r + 2], dx = rays[r + 3], dy = rays[r + 4], dz = rays[r + 5];
  let t = Infinity, object = -1;
  for (let n = from; n < to; n++) { // nearestHit
    const i = candidates[n], ti = k.hit(k.shapes, i * SHAPE, ox, oy, oz, dx, dy, dz, k.epsilon);
    if (ti < t) { t = ti; object = i; }
  }
  if (object < 0) {
    colors[out] = k.background[0]; colors[out + 1] = k.background[1]; colors[out + 2] = k.background[2];
    return;
  }
  surface[P] = ox + dx * t; surface[P + 1] = oy + dy * t; surface[P + 2] = oz + dz * t; // P = Ro + Rd·t
  surface[D] = dx; surface[D + 1] = dy; surface[D + 2] = dz;
  surfaceAt(k, object);
  lightPoint(k, object, out);
  const m = object * MATERIAL, reflection = k.materials[m + REFLECTION], transparency = k.materials[m + TRANSPARENCY];
  if (depth < k.maxDepth && (reflection > 0 || transparency > 0)) mirrorAndGlass(k, object, depth, out);
}

/** surfaceAt: the unit normal at P, turned to face the ray, into `surface`. */
function surfaceAt(k, object) {
  k.normal(k.shapes, object * SHAPE, surface);
  const dx = surface[D], dy = surface[D + 1], dz = surface[D + 2];
  const inside = dx * surface[N] + dy * surface[N + 1] + dz * surface[N + 2] > 0;
  if (inside) { surface[N] = -surface[N]; surface[N + 1] = -surface[N + 1]; surface[N + 2] = -surface[N + 2]; } // shade the side the ray sees
  surface[INSIDE] = inside ? 1 : 0;
}

/**
 * mirrorAndGlass: the mirror ray and the glass ray, both traced at depth + 1,
 * mixed into `colors[out …]` with the Fresnel share (Schlick).
 */
function mirrorAndGlass(k, object, depth, out) {
  const Px = surface[P], Py = surface[P + 1], Pz = surface[P + 2]; // read before the rays below overwrite them
  const Nx = surface[N], Ny = surface[N + 1], Nz = surface[N + 2];
  const dx = surface[D], dy = surface[D + 1], dz = surface[D + 2];
  const m = object * MATERIAL, reflection = k.materials[m + REFLECTION], transparency = k.materials[m + TRANSPARENCY], ior = k.materials[m + IOR];
  const cosi = -(dx * Nx + dy * Ny + dz * Nz);
  const eta = surface[INSIDE] === 1 ? ior : 1 / ior;
  const next = (depth + 1) * 6, bias = k.bias, mirrored = next, through = next + 3;
  const refracts = transparency > 0 && refract(rays, next + 3, dx, dy, dz, Nx, Ny, Nz, cosi, eta); // the glass ray's direction
  const fresnel = fresnelShare(transparency, refracts, cosi, ior);
  if (refracts) { // traced first, where refract wrote it (the two rays' colours do not depend on their order)
    rays[next] = Px + Nx * -bias; rays[next + 1] = Py + Ny * -bias; rays[next + 2] = Pz + Nz * -bias; // start just inside
    traceRay(k, depth + 1, through, k.all, 0, k.count);
  } else {
    colors[through] = 0; colors[through + 1] = 0; colors[through + 2] = 0;
  }
  rays[next] = Px + Nx * bias; rays[next + 1] = Py + Ny * bias; rays[next + 2] = Pz + Nz * bias;
  reflectInto(rays, next + 3, dx, dy, dz, Nx, Ny, Nz); // the mirror ray's direction
  traceRay(k, depth + 1, mirrored, k.all, 0, k.count);
  for (let c = 0; c < 3; c++) {
    colors[out + c] = mix(colors[out + c], colors[mirrored + c], colors[through + c], k.materials[m + c], reflection, transparency, fresnel);
  }
}

/**
 * lightPoint: emission + ambient + each light the point can see, into
 * `colors[out …]`; the shadow ray starts off the surface and stops short of the light.
 */
function lightPoint(k, object, out) {
  const Px = surface[P], Py = surface[P + 1], Pz = surface[P + 2];
  const Nx = surface[N], Ny = surface[N + 1], Nz = surface[N + 2];
  const mat = k.materials, m = object * MATERIAL, ambient = k.ambient, lights = k.lights, bias = k.bias;
  const red = mat[m], green = mat[m + 1], blue = mat[m + 2];
  const e = m + EMISSION;
  let cr = mat[e] + ambient * red, cg = mat[e + 1] + ambient * green, cb = mat[e + 2] + ambient * blue;
  for (let l = 0; l < k.lightCount * LIGHT; l += LIGHT) {
    const lightObject = lights[l + LIGHT_SHAPE];
    if (lightObject === object) continue; // a light does not light itself
    const x = lights[l] - Px, y = lights[l + 1] - Py, z = lights[l + 2] - Pz;
    const distance = Math.sqrt(x * x + y * y + z * z), inverse = 1 / distance;
    const Lx = x * inverse, Ly = y * inverse, Lz = z * inverse;
    const cos = lambert(Nx, Ny, Nz, Lx, Ly, Lz);
    if (cos <= 0) continue;
    const beam = lights[l + IS_SPOT] === 1 ? spotShare(lights[l + AXIS], lights[l + AXIS + 1], lights[l + AXIS + 2], lights[l + COS_OUTER], lights[l + COS_INNER], Lx, Ly, Lz) : 1;
    if (beam === 0) continue; // outside a spot light's cone
    const transmission = (k.shadows
      ? shadowRay(k, Px + Nx * bias, Py + Ny * bias, Pz + Nz * bias, Lx, Ly, Lz, distance - bias, l / LIGHT)
      : 1) * beam;
    if (transmission === 0) continue;
    const attenuation = lights[l + ATTENUATION];
    const reach = attenuation === 0 ? transmission : transmission * falloff(attenuation, distance); // falloff(0, d) is exactly 1: no division for a light that does not fade
    const diffuse = cos * reach;
    const highlight = k.specular
      ? specular(mat[m + SPECULAR], mat[m + SHININESS], cos, Lx, Ly, Lz, Nx, Ny, Nz, surface[D], surface[D + 1], surface[D + 2]) * reach
      : 0;
    const glow = l + LIGHT_EMISSION; // the light's colour
    cr += lightShare(lights[glow], red, diffuse, highlight);
    cg += lightShare(lights[glow + 1], green, diffuse, highlight);
    cb += lightShare(lights[glow + 2], blue, diffuse, highlight);
  }
  colors[out] = cr; colors[out + 1] = cg; colors[out + 2] = cb;
}

/** How much light gets through from the shadow ray's origin to `reach` along it toward light `light` (1 clear, 0 blocked). */
function shadowRay(k, ox, oy, oz, dx, dy, dz, reach, light) {
  const lightObject = k.lights[light * LIGHT + LIGHT_SHAPE], apart = k.apart, row = light * k.count;
  const beyond = outOfReach(k, reach);
  let transmission = 1;
  for (let i = 0; i < k.count; i++) {
    if (i === lightObject || apart[row + i] > beyond || k.hit(k.shapes, i * SHAPE, ox, oy, oz, dx, dy, dz, k.epsilon) >= reach) continue;
    transmission *= k.materials[i * MATERIAL + TRANSPARENCY];
    if (transmission === 0) return 0;
  }
  return transmission;
}

/** The smallest t > tMin along the ray of the shape at `shapes[at]`, or Infinity: its kind's `hit`, in numbers. */
function hitShape(s, at, ox, oy, oz, dx, dy, dz, tMin) {
  return KINDS[s[at + KIND]].hit(s, at, ox, oy, oz, dx, dy, dz, tMin);
}

/** The unit normal at P of the shape at `shapes[at]`, facing out, into `surface`: its kind's `normalAt`, in numbers. */
function normalShape(s, at, out) {
  KINDS[s[at + KIND]].normal(s, at, out);
}
