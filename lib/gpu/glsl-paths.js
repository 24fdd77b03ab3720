/**
 * The path tracer (lib/tracing/pathtrace/integrator.js) as a WebGL2 fragment
 * shader, one pixel a fragment, reading the packed scene the Whitted shader
 * reads: its nearestHit and surfaceAt and each shape's hit test
 * (lib/gpu/glsl-kernel.js sceneSource), its Snell and Schlick
 * (lib/gpu/glsl-optics.js). A pass adds `uPassSamples` paths of each pixel
 * to the sums of the passes before it (a float texture read, another
 * written: ping-pong), so a picture grows sample after sample.
 *
 * The steps and the draws are the CPU's, in the same order: two numbers for
 * the point in the pixel, six for each bounce (always six), one for the
 * roulette. The numbers come from the same PCG chain seeded by (seed, x, y, s)
 * (lib/tracing/pathtrace/random.js), in 32-bit unsigned integers; a draw
 * keeps the top 24 bits, as many as a float32 holds (the CPU's 32 bits over
 * 2³² would round up to 1.0 here), so the paths are the CPU's kind, not its
 * bytes.
 *
 * As the Whitted shader, a ray that leaves a sphere carries it (`self`, see
 * glsl-kernel.js): leaving its outside it is not tested against it, running
 * inside it only its far root counts, and meets it from inside; float32
 * does not know a point on the surface well enough to start a ray `bias`
 * off it (a nearly tangent bounce inside a ball tipped D·N and escaped: the
 * closed-room test of tests/e2e/gpu-paths.spec.js lost 5 pixels of 4,096).
 */
import { sceneSource } from './glsl-kernel.js';
import { ROULETTE_FROM } from '../tracing/pathtrace/integrator.js';

const PATHS = /* glsl */ `
#define ROULETTE_FROM ${ROULETTE_FROM}
const float TWO_PI = 6.283185307179586;
uniform sampler2D uSum;           // the sums of the passes before (unit 5)
uniform bool uFirst;              // the first pass: no sums yet
uniform int uFirstSample, uPassSamples, uMaxBounces;
uniform uint uSeed;
uniform bool uRoulette;
uniform float uBias;
uniform vec3 uSkyTop, uSkyBottom;
uniform vec3 uEye, uRight, uUp, uForward;
uniform vec2 uHalf;               // the image plane's half width and half height at distance 1
uniform ivec2 uSize;
out vec4 sum;

// random.js: PCG's output permutation, the hash, a generator per (seed, x, y, s).
uint permute(uint state) {
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
uint pcgHash(uint v) { return permute(v * 747796405u + 2891336453u); }
uint randomState;
void startRandom(uint seed, uint x, uint y, uint s) { randomState = pcgHash(seed ^ pcgHash(x ^ pcgHash(y ^ pcgHash(s)))); }
float nextRandom() { // uniform in [0, 1): the top 24 bits
  randomState = randomState * 747796405u + 2891336453u;
  return float(permute(randomState) >> 8u) * (1.0 / 16777216.0);
}

// sampling.js: a cosine-weighted direction about N (Malley; the basis of Duff et al. 2017).
vec3 cosineHemisphere(vec3 N, float u1, float u2) {
  float r = sqrt(u1), phi = TWO_PI * u2, a = r * cos(phi), b = r * sin(phi), cosTheta = sqrt(1.0 - u1);
  float sign = N.z >= 0.0 ? 1.0 : -1.0, k = -1.0 / (sign + N.z), m = N.x * N.y * k;
  vec3 T = vec3(1.0 + sign * N.x * N.x * k, sign * m, -sign * N.x), B = vec3(m, sign + N.y * N.y * k, -N.y);
  return a * T + b * B + cosTheta * N;
}

// sampling.js: a point uniform in the unit ball (a direction on the sphere, at radius ∛u3).
vec3 inUnitBall(float u1, float u2, float u3) {
  float z = 1.0 - 2.0 * u1, ring = sqrt(max(0.0, 1.0 - z * z)), phi = TWO_PI * u2;
  return pow(u3, 1.0 / 3.0) * vec3(ring * cos(phi), ring * sin(phi), z);
}

// The eye's ray through the point (px, py) of the picture (integrator.js primaryRay).
vec3 primaryDirection(float px, float py) {
  float sx = (2.0 * px / float(uSize.x) - 1.0) * uHalf.x, sy = (1.0 - 2.0 * py / float(uSize.y)) * uHalf.y;
  return normalize(sx * uRight + sy * uUp + uForward);
}

// materials.js scatter: one bounce off material m; false when the path is absorbed. Glass T, metal (1 − T)·R, the rest diffuse.
bool scatter(int m, vec3 N, vec3 D, bool inside, out vec3 direction, out vec3 weight, out bool below) {
  float u0 = nextRandom(), u1 = nextRandom(), u2 = nextRandom(), u3 = nextRandom(), u4 = nextRandom(), u5 = nextRandom();
  float T = material(m + TRANSPARENCY), R = material(m + REFLECTION);
  weight = vec3(material(m), material(m + 1), material(m + 2));
  below = false;
  if (u0 < T) { // glass: Schlick's share mirrored (untinted), the rest refracted by Snell (tinted)
    float cosi = -dot(D, N), ior = material(m + IOR);
    bool refracts = refraction(D, N, cosi, inside ? ior : 1.0 / ior, direction);
    float F = refracts ? schlick(cosi, ior) : 1.0;
    if (u1 < F) { direction = D + 2.0 * cosi * N; weight = vec3(1.0); }
    else below = true;
    return true;
  }
  if (u0 < T + (1.0 - T) * R) { // metal: the mirror direction plus fuzz × a point of the unit ball
    direction = normalize(D - 2.0 * dot(D, N) * N + material(m + FUZZ) * inUnitBall(u3, u4, u5));
    return dot(direction, N) > 0.0; // below the surface: absorbed
  }
  direction = cosineHemisphere(N, u1, u2); // diffuse: f = colour/π, pdf = cos/π, the weight is the colour
  return true;
}

// integrator.js tracePath: sample s of pixel (x, y).
vec3 tracePath(int x, int y, int s) {
  startRandom(uSeed, uint(x), uint(y), uint(s));
  float jx = nextRandom(), jy = nextRandom();
  vec3 o = uEye, d = primaryDirection(float(x) + jx, float(y) + jy);
  vec3 throughput = vec3(1.0), radiance = vec3(0.0);
  ivec2 self = ivec2(-1);
  for (int bounce = 0; bounce <= uMaxBounces; bounce++) {
    float t;
    int item;
    int object = nearestHit(o, d, self, t, item);
    if (object < 0) { radiance += throughput * mix(uSkyBottom, uSkyTop, 0.5 * (d.y + 1.0)); break; } // the sky (sky.js)
    vec3 P = o + d * t;
    bool inside;
    vec3 N = surfaceAt(object, item, P, d, inside);
    if (object == self.y && !inside) { inside = true; N = -N; } // a ray running inside meets its sphere from inside (float32 can tip D·N at a nearly tangent far root)
    int m = object * MATERIAL;
    radiance += throughput * vec3(material(m + EMISSION), material(m + EMISSION + 1), material(m + EMISSION + 2));
    if (bounce >= uMaxBounces) break;
    vec3 direction, weight;
    bool below;
    if (!scatter(m, N, d, inside, direction, weight, below)) break;
    throughput *= weight;
    float brightest = max(max(throughput.r, throughput.g), throughput.b);
    if (brightest <= 0.0) break;
    if (uRoulette && bounce + 1 >= ROULETTE_FROM && brightest < 1.0) { // Russian roulette
      if (nextRandom() >= brightest) break;
      throughput /= brightest; // the survivors carry the paths that ended: unbiased
    }
    o = P + N * (below ? -uBias : uBias); // off the surface, on the side the path goes
    d = direction;
    self = kindOf(object) != SPHERE ? ivec2(-1) : inside ? ivec2(-1, object) : ivec2(object, -1);
    if (below) self = self.yx;
  }
  return radiance;
}

void main() {
  ivec2 at = ivec2(gl_FragCoord.xy);
  int x = at.x, y = uSize.y - 1 - at.y; // row 0 at the top, as render()'s
  vec3 total = uFirst ? vec3(0.0) : texelFetch(uSum, at, 0).rgb;
  for (int k = 0; k < uPassSamples; k++) total += tracePath(x, y, uFirstSample + k);
  sum = vec4(total, 1.0);
}
`;

/** The path tracer's fragment shader; `meshes`: with the BVH walk (as kernelSource). */
export function pathSource(meshes = true) {
  return `${sceneSource(meshes)}${PATHS}`;
}

/** The sums shown: each pixel's mean, sum / samples, onto the canvas (the view's picture). */
export const SHOW_SOURCE = /* glsl */ `#version 300 es
precision highp float;
precision highp sampler2D;
uniform sampler2D uSum;
uniform float uScale; // 1 / samples
out vec4 pixel;
void main() { pixel = vec4(texelFetch(uSum, ivec2(gl_FragCoord.xy), 0).rgb * uScale, 1.0); }
`;
