// The harness of tests/e2e/gpu.spec.js's formula test: each GLSL formula of
// lib/gpu/glsl-optics.js on sampled inputs (up to 12 numbers each, three RGBA
// float texels a sample), its result (up to 4 numbers) written to an RGBA32F
// texture and read back, beside lib/tracing/optics.js on the same inputs (rounded to
// float32 first, so only the formula's own rounding is measured).
import { OPTICS_GLSL } from '../../../lib/gpu/glsl-optics.js';
import * as optics from '../../../lib/tracing/optics.js';

/** A unit vector from three numbers in [-1, 1]. */
const unit = (x, y, z) => { const n = Math.hypot(x, y, z) || 1; return [x / n, y / n, z / n]; };

/** Each formula: its inputs from a random draw, its GLSL call, and optics.js on the same inputs. */
export const FORMULAS = {
  lambert: {
    inputs: (r) => [...unit(r(), r(), r()), ...unit(r(), r(), r())],
    glsl: 'vec4(lambert(vec3(a[0], a[1], a[2]), vec3(a[3], a[4], a[5])), 0.0, 0.0, 0.0)',
    js: (a) => [optics.lambert(...a.slice(0, 6))],
  },
  specular: {
    inputs: (r) => { const N = unit(r(), r(), r()), L = unit(r(), r(), r()), D = unit(r(), r(), r()); return [Math.abs(r()), 1 + 99 * Math.abs(r()), N[0] * L[0] + N[1] * L[1] + N[2] * L[2], ...L, ...N, ...D]; },
    glsl: 'vec4(specular(a[0], a[1], a[2], vec3(a[3], a[4], a[5]), vec3(a[6], a[7], a[8]), vec3(a[9], a[10], a[11])), 0.0, 0.0, 0.0)',
    js: (a) => [optics.specular(...a.slice(0, 12))],
    relative: 2e-3, // GLSL's pow is exp2(y·log2(x)): float32 loses about shininess × 2⁻²³ of it
  },
  spotShare: {
    inputs: (r) => { const outer = 0.5 + 0.4 * Math.abs(r()); return [...unit(r(), r(), r()), outer, outer + (1 - outer) * Math.abs(r()), ...unit(r(), r(), r())]; },
    glsl: 'vec4(spotShare(vec3(a[0], a[1], a[2]), a[3], a[4], vec3(a[5], a[6], a[7])), 0.0, 0.0, 0.0)',
    js: (a) => [optics.spotShare(...a.slice(0, 8))],
  },
  falloff: {
    inputs: (r) => [Math.abs(r()), 50 * Math.abs(r())],
    glsl: 'vec4(falloff(a[0], a[1]), 0.0, 0.0, 0.0)',
    js: (a) => [optics.falloff(a[0], a[1])],
  },
  lightShare: {
    inputs: (r) => [2 * Math.abs(r()), Math.abs(r()), Math.abs(r()), Math.abs(r())],
    glsl: 'vec4(lightShare(a[0], a[1], a[2], a[3]), 0.0, 0.0, 0.0)',
    js: (a) => [optics.lightShare(a[0], a[1], a[2], a[3])],
  },
  refraction: {
    inputs: (r) => { const D = unit(r(), r(), r()); let N = unit(r(), r(), r()); const d = D[0] * N[0] + D[1] * N[1] + D[2] * N[2]; if (d > 0) N = N.map((v) => -v); return [...D, ...N, -(D[0] * N[0] + D[1] * N[1] + D[2] * N[2]), r() > 0 ? 1 / (1 + Math.abs(r())) : 1 + Math.abs(r())]; },
    glsl: '(refraction(vec3(a[0], a[1], a[2]), vec3(a[3], a[4], a[5]), a[6], a[7], T) ? vec4(T, 1.0) : vec4(0.0))',
    js: (a) => { const out = new Float64Array(3); return optics.refract(out, 0, ...a.slice(0, 8)) ? [...out, 1] : [0, 0, 0, 0]; },
    edge: (a) => Math.abs(1 - a[7] * a[7] * (1 - a[6] * a[6])) < 1e-5, // on the edge of total internal reflection float32 may go either way
  },
  schlick: {
    inputs: (r) => [Math.abs(r()), 1 + 1.5 * Math.abs(r())],
    glsl: 'vec4(schlick(a[0], a[1]), 0.0, 0.0, 0.0)',
    js: (a) => [optics.schlick(a[0], a[1])],
  },
  fresnel: {
    inputs: (r) => [r() > 0 ? Math.abs(r()) : 0, r() > 0 ? 1 : 0, Math.abs(r()), 1 + 1.5 * Math.abs(r())],
    glsl: 'vec4(fresnel(a[0], a[1] == 1.0, a[2], a[3]), 0.0, 0.0, 0.0)',
    js: (a) => [optics.fresnel(a[0], a[1] === 1, a[2], a[3])],
  },
  mixShares: {
    inputs: (r) => [2 * Math.abs(r()), 2 * Math.abs(r()), 2 * Math.abs(r()), Math.abs(r()), Math.abs(r()), Math.abs(r()), Math.abs(r())],
    glsl: 'vec4(mixShares(a[0], a[1], a[2], a[3], a[4], a[5], a[6]), 0.0, 0.0, 0.0)',
    js: (a) => [optics.mix(...a.slice(0, 7))],
  },
};

const VERTEX = `#version 300 es
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}`;

const fragment = (call) => `#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
uniform sampler2D uInputs;
out vec4 result;
${OPTICS_GLSL}
void main() {
  int s = int(gl_FragCoord.x);
  float a[12];
  for (int k = 0; k < 3; k++) {
    vec4 v = texelFetch(uInputs, ivec2(3 * s + k, 0), 0);
    a[4 * k] = v.x; a[4 * k + 1] = v.y; a[4 * k + 2] = v.z; a[4 * k + 3] = v.w;
  }
  vec3 T;
  result = ${call};
}`;

/** A seeded random number in [-1, 1). */
function random(seed) {
  let s = seed >>> 0;
  return () => { s = (Math.imul(s, 1664525) + 1013904223) >>> 0; return (s / 2 ** 32) * 2 - 1; };
}

/**
 * Runs formula `name` on `samples` sampled inputs on the GPU and in optics.js:
 * the largest error (beyond relative × |expected| + 1e-6) and its sample, and how many were compared.
 */
export function check(name, samples = 512, seed = 1) {
  const f = FORMULAS[name], r = random(seed);
  const inputs = new Float32Array(samples * 12);
  for (let s = 0; s < samples; s++) inputs.set(f.inputs(r), s * 12);
  const canvas = document.createElement('canvas'), gl = canvas.getContext('webgl2');
  if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('no EXT_color_buffer_float: float textures cannot be drawn into here');
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, VERTEX], [gl.FRAGMENT_SHADER, fragment(f.glsl)]]) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader));
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  const texture = (width, data) => {
    const t = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, 1, 0, gl.RGBA, gl.FLOAT, data);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    return t;
  };
  const output = texture(samples, null), framebuffer = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, output, 0);
  gl.activeTexture(gl.TEXTURE0);
  gl.bindTexture(gl.TEXTURE_2D, texture(samples * 3, inputs));
  gl.useProgram(program);
  gl.uniform1i(gl.getUniformLocation(program, 'uInputs'), 0);
  gl.viewport(0, 0, samples, 1);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  const results = new Float32Array(samples * 4);
  gl.readPixels(0, 0, samples, 1, gl.RGBA, gl.FLOAT, results);
  let worst = { excess: 0, sample: -1 }, compared = 0;
  for (let s = 0; s < samples; s++) {
    const a = [...inputs.subarray(s * 12, s * 12 + 12)];
    if (f.edge?.(a)) continue;
    compared++;
    f.js(a).forEach((expected, k) => {
      const excess = Math.abs(results[s * 4 + k] - expected) - ((f.relative ?? 1e-5) * Math.abs(expected) + 1e-6);
      if (excess > worst.excess) worst = { excess, sample: s, inputs: a, gpu: results[s * 4 + k], js: expected };
    });
  }
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return { name, compared, worst };
}

window.gpuFormulas = { names: Object.keys(FORMULAS), check };
