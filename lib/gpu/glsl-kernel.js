/**
 * lib/tracing/kernel.js as a WebGL2 fragment shader, one pixel a fragment: nearestHit,
 * surfaceAt, lightPoint (with shadowRay), mirrorAndGlass, step for step with
 * the same names, reading the packed scene the kernel reads (uploaded by
 * lib/gpu/upload.js as float textures) with its layout's own constants: the
 * offsets below come from lib/shapes/packed.js, lib/lights/packed.js and
 * lib/shapes/material.js's table of fields, so a change of layout there is one edit.
 *
 * GLSL has no recursion, so the tree of mirror and glass rays that
 * kernel.js walks by calling traceRay again is a stack of rays here, each
 * with its weight: the share of the pixel its colour brings, per channel.
 * optics.js's mix is linear in the local, mirrored and through colours, so
 * the weights are mix's own coefficients (mixShares of 1, 0, 0 and so on)
 * and the pixel is the sum of weight × local colour over the tree: the same
 * number as the kernel's nested mix. A ray of weight 0 adds nothing, so it
 * is not traced.
 *
 * One guard float32 needs, for rays that start on a sphere (a shadow ray,
 * a mirror ray, a glass ray): a ray leaving the sphere's outside never meets
 * it again, and a ray running inside it meets it only at its far root. In
 * float64 the kernel's test finds that itself, the ray starting \`bias\` off
 * the surface; in float32 a point on a sphere of radius 10,000 (the class
 * scene's ground) is only known to about 1e-3, ten times the bias, and the
 * test would find the surface the ray starts on: the sphere would shade
 * itself (acne). So each ray carries \`self\`: x, the sphere it leaves (not
 * tested), y, the sphere it runs inside (its far root only); −1 for none.
 */
import { SHAPE, KIND } from '../shapes/packed.js';
import { MATERIAL_LAYOUT } from '../shapes/material.js';
import { LIGHT, POSITION, LIGHT_EMISSION, LIGHT_SHAPE, ATTENUATION, IS_SPOT, AXIS, COS_OUTER, COS_INNER } from '../lights/packed.js';
import { OPTICS_GLSL } from './glsl-optics.js';
import { SHAPES_GLSL } from './glsl-shapes.js';

/** The shader's code for each shape class it can draw, by the class's `type`. */
export const SHAPE_CODES = Object.freeze({ sphere: 0, plane: 1, box: 2, cylinder: 3, cone: 4, triangle: 5, mesh: 6 });

/** How many kind numbers (lib/tracing/kernel.js) the shader maps to its shape codes. */
export const MAX_KINDS = 16;

/** How deep a mesh's tree may be for the shader's walk (its stack). */
export const BVH_STACK = 64;

/** A mirror and glass tree of maxDepth 16 keeps at most 17 rays waiting, depth first. */
const RAY_STACK = 18;

/** Numbers per texture row (lib/gpu/upload.js lays every array out in rows of this many). */
export const ROW = 1024;

/** The material offsets the shader reads, by their names in lib/shapes/material.js's table. */
const { MATERIAL, EMISSION, REFLECTION, TRANSPARENCY, IOR, SPECULAR, SHININESS, FUZZ } = MATERIAL_LAYOUT;

/** The #defines of the layout: every offset from the module that owns it. */
function layout() {
  const defines = {
    SHAPE, KIND, MATERIAL, EMISSION, REFLECTION, TRANSPARENCY, IOR, SPECULAR, SHININESS, FUZZ,
    LIGHT, POSITION, LIGHT_EMISSION, LIGHT_SHAPE, ATTENUATION, IS_SPOT, AXIS, COS_OUTER, COS_INNER, MAX_KINDS, BVH_STACK, RAY_STACK,
    ROW_SHIFT: Math.log2(ROW), ROW_MASK: ROW - 1,
    ...Object.fromEntries(Object.entries(SHAPE_CODES).map(([type, code]) => [type.toUpperCase(), code])),
  };
  return Object.entries(defines).map(([name, value]) => `#define ${name} ${value}`).join('\n');
}

const HEADER = /* glsl */ `#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
`;

const READS = /* glsl */ `
const float NO_HIT = 3.0e38; // the kernel's Infinity
const float TANGENT = 1e-12, PARALLEL = 1e-12;
uniform sampler2D uShapes, uMaterials, uLights, uApart, uTables;
uniform int uKindType[MAX_KINDS]; // the kernel's kind number → the shader's shape code

float number(sampler2D numbers, int i) { return texelFetch(numbers, ivec2(i & ROW_MASK, i >> ROW_SHIFT), 0).r; }
float shape(int i) { return number(uShapes, i); }
float material(int i) { return number(uMaterials, i); }
float light(int i) { return number(uLights, i); }
float table(int i) { return number(uTables, i); }
vec3 table3(int i) { return vec3(table(i), table(i + 1), table(i + 2)); }
int tableStart(int index) { return int(table(index)); }
`;

const NEAREST = /* glsl */ `
uniform int uCount; // shapes
uniform float uEpsilon;

int kindOf(int object) { return uKindType[int(shape(object * SHAPE + KIND))]; }

// The smallest t > tMin along the ray of shape \`object\`, or NO_HIT; a mesh's triangle into item.
float hitShape(int object, vec3 o, vec3 d, float tMin, bool farOnly, out int item) {
  int b = object * SHAPE, kind = kindOf(object);
  item = -1;
  if (kind == SPHERE) return sphereHit(b, o, d, tMin, farOnly);
  if (kind == PLANE) return planeHit(b, o, d, tMin);
  if (kind == BOX) return boxHit(b, o, d, tMin);
  if (kind == CYLINDER) return cylinderHit(b, o, d, tMin);
  if (kind == CONE) return coneHit(b, o, d, tMin);
  if (kind == TRIANGLE) return triangleShapeHit(b, o, d, tMin);
#if HAS_MESH
  return meshHit(b, o, d, tMin, item);
#else
  return NO_HIT;
#endif
}

// nearestHit: the nearest shape along the ray (−1 for none), its t and a mesh's triangle; \`self\`: see above.
int nearestHit(vec3 o, vec3 d, ivec2 self, out float t, out int item) {
  int object = -1, ti_item;
  t = NO_HIT;
  item = -1;
  for (int i = 0; i < uCount; i++) {
    if (i == self.x) continue;
    float ti = hitShape(i, o, d, uEpsilon, i == self.y, ti_item);
    if (ti < t) { t = ti; object = i; item = ti_item; }
  }
  return object;
}

// surfaceAt: the unit normal at P, turned to face the ray; inside when the ray meets it from within.
vec3 surfaceAt(int object, int item, vec3 P, vec3 D, out bool inside) {
  int b = object * SHAPE, kind = kindOf(object);
  vec3 N;
  if (kind == SPHERE) N = sphereNormal(b, P);
  else if (kind == PLANE) N = planeNormal(b);
  else if (kind == BOX) N = boxNormal(b, P);
  else if (kind == CYLINDER) N = cylinderNormal(b, P);
  else if (kind == CONE) N = coneNormal(b, P);
  else N = kind == TRIANGLE ? triangleNormal(b) : meshNormal(b, item);
  inside = D.x * N.x + D.y * N.y + D.z * N.z > 0.0;
  return inside ? -N : N; // shade the side the ray sees
}
`;

const KERNEL = /* glsl */ `
uniform int uLightCount, uMaxDepth, uSamples;
uniform vec3 uBackground;
uniform float uAmbient, uBias;
uniform bool uShadows, uSpecular;
uniform vec3 uEye, uRight, uUp, uForward;
uniform vec2 uHalf; // the image plane's half width and half height at distance 1
uniform ivec2 uSize;
out vec4 pixel;

// How much light gets through from o to reach along the shadow ray toward light l (1 clear, 0 blocked).
float shadowRay(vec3 o, vec3 d, float reach, int l, ivec2 self) {
  int lightObject = int(light(l * LIGHT + LIGHT_SHAPE)), row = l * uCount, item;
  float beyond = reach + 2.0 * uBias + 1e-5 * reach; // lib/tracing/kernel.js outOfReach
  float transmission = 1.0;
  for (int i = 0; i < uCount; i++) {
    if (i == lightObject || i == self.x || number(uApart, row + i) > beyond || hitShape(i, o, d, uEpsilon, i == self.y, item) >= reach) continue;
    transmission *= material(i * MATERIAL + TRANSPARENCY);
    if (transmission == 0.0) return 0.0;
  }
  return transmission;
}

// lightPoint: emission + ambient + each light the point can see.
vec3 lightPoint(int object, vec3 P, vec3 N, vec3 D, ivec2 self) {
  int m = object * MATERIAL;
  vec3 surface = vec3(material(m), material(m + 1), material(m + 2));
  vec3 color = vec3(material(m + EMISSION), material(m + EMISSION + 1), material(m + EMISSION + 2)) + uAmbient * surface;
  for (int at = 0; at < uLightCount * LIGHT; at += LIGHT) {
    if (int(light(at + LIGHT_SHAPE)) == object) continue; // a light does not light itself
    vec3 toLight = vec3(light(at + POSITION), light(at + POSITION + 1), light(at + POSITION + 2)) - P;
    float distance = sqrt(dot(toLight, toLight)), inverse = 1.0 / distance;
    vec3 L = toLight * inverse;
    float cosTheta = lambert(N, L);
    if (cosTheta <= 0.0) continue;
    float beam = light(at + IS_SPOT) == 1.0
      ? spotShare(vec3(light(at + AXIS), light(at + AXIS + 1), light(at + AXIS + 2)), light(at + COS_OUTER), light(at + COS_INNER), L)
      : 1.0;
    if (beam == 0.0) continue; // outside a spot light's cone
    float transmission = (uShadows ? shadowRay(P + N * uBias, L, distance - uBias, at / LIGHT, self) : 1.0) * beam;
    if (transmission == 0.0) continue;
    float reach = transmission * falloff(light(at + ATTENUATION), distance);
    float diffuse = cosTheta * reach;
    float highlight = uSpecular ? specular(material(m + SPECULAR), material(m + SHININESS), cosTheta, L, N, D) * reach : 0.0;
    vec3 glow = vec3(light(at + LIGHT_EMISSION), light(at + LIGHT_EMISSION + 1), light(at + LIGHT_EMISSION + 2)); // the light's colour
    color += vec3(lightShare(glow.r, surface.r, diffuse, highlight), lightShare(glow.g, surface.g, diffuse, highlight),
      lightShare(glow.b, surface.b, diffuse, highlight));
  }
  return color;
}

// The rays still to trace: origin, direction, weight, depth.
vec3 stackOrigin[RAY_STACK], stackDirection[RAY_STACK], stackWeight[RAY_STACK];
int stackDepth[RAY_STACK];
ivec2 stackSelf[RAY_STACK];
int waiting;

void push(vec3 o, vec3 d, vec3 weight, int depth, ivec2 self) {
  if (weight == vec3(0.0)) return; // adds nothing
  stackOrigin[waiting] = o; stackDirection[waiting] = d; stackWeight[waiting] = weight; stackDepth[waiting] = depth;
  stackSelf[waiting] = self;
  waiting++;
}

// mix's share of the local, mirrored and through colours, one channel.
vec3 shares(float color, float reflection, float transparency, float F) {
  return vec3(mixShares(1.0, 0.0, 0.0, color, reflection, transparency, F), mixShares(0.0, 1.0, 0.0, color, reflection, transparency, F),
    mixShares(0.0, 0.0, 1.0, color, reflection, transparency, F));
}

// mirrorAndGlass: the mirror ray and the glass ray, at depth + 1, mixed with the Fresnel share (Schlick); returns the local colour's weight.
vec3 mirrorAndGlass(int object, vec3 P, vec3 N, vec3 D, bool inside, int depth, vec3 weight, ivec2 self) {
  int m = object * MATERIAL;
  float reflection = material(m + REFLECTION), transparency = material(m + TRANSPARENCY), ior = material(m + IOR);
  float cosi = -(D.x * N.x + D.y * N.y + D.z * N.z);
  float eta = inside ? ior : 1.0 / ior;
  vec3 T;
  bool refracts = transparency > 0.0 && refraction(D, N, cosi, eta, T); // the glass ray's direction
  float F = fresnel(transparency, refracts, cosi, ior);
  vec3 r = shares(material(m), reflection, transparency, F), g = shares(material(m + 1), reflection, transparency, F),
    b = shares(material(m + 2), reflection, transparency, F);
  if (refracts) push(P + N * -uBias, T, weight * vec3(r.z, g.z, b.z), depth + 1, self.yx); // starts just inside
  push(P + N * uBias, D - 2.0 * dot(D, N) * N, weight * vec3(r.y, g.y, b.y), depth + 1, self); // vec3.js reflect
  return weight * vec3(r.x, g.x, b.x);
}

// trace(): the colour of the primary ray, the tree of its mirror and glass rays summed by weight.
vec3 tracePrimary(vec3 origin, vec3 direction) {
  vec3 color = vec3(0.0);
  waiting = 0;
  push(origin, direction, vec3(1.0), 0, ivec2(-1));
  while (waiting > 0) {
    waiting--;
    vec3 o = stackOrigin[waiting], d = stackDirection[waiting], weight = stackWeight[waiting];
    int depth = stackDepth[waiting], item;
    float t;
    int object = nearestHit(o, d, stackSelf[waiting], t, item);
    if (object < 0) { color += weight * uBackground; continue; }
    vec3 P = o + d * t; // P = Ro + Rd·t
    bool inside;
    vec3 N = surfaceAt(object, item, P, d, inside);
    ivec2 self = kindOf(object) != SPHERE ? ivec2(-1) : inside ? ivec2(-1, object) : ivec2(object, -1);
    vec3 local = lightPoint(object, P, N, d, self);
    int m = object * MATERIAL;
    float reflection = material(m + REFLECTION), transparency = material(m + TRANSPARENCY);
    if (depth < uMaxDepth && (reflection > 0.0 || transparency > 0.0)) color += local * mirrorAndGlass(object, P, N, d, inside, depth, weight, self);
    else color += weight * local;
  }
  return color;
}

// camera.directionAt: the unit direction through image point (x, y), pixels from the top left.
vec3 directionAt(float x, float y) {
  float sx = (2.0 * (x + 0.5) / float(uSize.x) - 1.0) * uHalf.x;
  float sy = (1.0 - 2.0 * (y + 0.5) / float(uSize.y)) * uHalf.y;
  return normalize(sx * uRight + sy * uUp + uForward);
}

void main() {
  float x = floor(gl_FragCoord.x), y = float(uSize.y - 1) - floor(gl_FragCoord.y); // row 0 at the top, as render()'s
  int n = int(sqrt(float(uSamples)) + 0.5);
  vec3 sum = vec3(0.0);
  for (int s = 0; s < uSamples; s++) { // camera.samples: the centres of an n × n grid of cells, each ray clamped first
    float dx = (float(s % n) + 0.5) / float(n) - 0.5, dy = (float(s / n) + 0.5) / float(n) - 0.5;
    sum += clamp(tracePrimary(uEye, directionAt(x + dx, y + dy)), 0.0, 1.0);
  }
  pixel = vec4(sum / float(uSamples), 1.0);
}
`;

/**
 * The fragment shader's whole source; `meshes`: with the BVH walk. A scene
 * without a mesh gets a shader without it: its stacks in every hit test made
 * SwiftShader's frame of the class scene two to three times slower.
 */
export function kernelSource(meshes = true) {
  return `${sceneSource(meshes)}${KERNEL}`;
}

/**
 * What every shader of the packed scene starts with: the layout's #defines,
 * the texture reads, optics, each shape's hit and normal, nearestHit and
 * surfaceAt (uniforms uCount, uEpsilon). Whitted's kernel and the path
 * tracer (lib/gpu/glsl-paths.js) each add their own loop after it.
 */
export function sceneSource(meshes = true) {
  return `${HEADER}${layout()}\n#define HAS_MESH ${meshes ? 1 : 0}\n${READS}${OPTICS_GLSL}${SHAPES_GLSL}${NEAREST}`;
}

/** A vertex shader drawing one triangle over the whole frame. */
export const VERTEX_SOURCE = `${HEADER}
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
`;
