/**
 * The GPU's path tracer: a WebGL2 context, the packed scene as the float
 * textures the Whitted engine uploads (lib/gpu/upload.js, engine.js
 * uploadScene), the path shader (lib/gpu/glsl-paths.js), and two float
 * framebuffers of per-pixel sums, one read and one written by each pass
 * (ping-pong). Nothing here runs until a GpuPathTracer is made.
 */
import { pathSource, SHOW_SOURCE } from './glsl-paths.js';
import { SHAPE_CODES } from './glsl-kernel.js';
import { gpuScene } from './upload.js';
import { TEXTURES, webgl2Context, uploadScene, bindScene, link, setCamera } from './engine.js';

/** Who asks, in gpuScene's errors. */
export const PATHS = Object.freeze({ cannot: 'pathTraceGPU cannot path trace', cpu: 'pathTrace() traces it on the CPU' });

/** The texture unit of the sums read by a pass (0 … 4 are the scene's). */
const SUM_UNIT = TEXTURES.length;

const UNIFORMS = ['uShapes', 'uMaterials', 'uLights', 'uApart', 'uTables', 'uKindType', 'uCount', 'uEpsilon', 'uSum', 'uFirst', 'uFirstSample',
  'uPassSamples', 'uMaxBounces', 'uSeed', 'uRoulette', 'uBias', 'uSkyTop', 'uSkyBottom', 'uEye', 'uRight', 'uUp', 'uForward', 'uHalf', 'uSize'];

export class GpuPathTracer {
  /**
   * @param {HTMLCanvasElement|OffscreenCanvas} [canvas] where the mean is shown (a new one when left out)
   * @param {{ preserveDrawingBuffer?: boolean }} [options]
   */
  constructor(canvas, { preserveDrawingBuffer = false } = {}) {
    const made = webgl2Context(canvas, preserveDrawingBuffer);
    this.canvas = made.canvas;
    const gl = this.gl = made.gl;
    if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('the GPU engine needs WebGL2 with float colour buffers (EXT_color_buffer_float) to add up paths: this browser has none');
    /** The path shader with the BVH walk and without it, made when a scene first needs it. */
    this.programs = new Map();
    this.program = null;
    /** @type {any} */
    this.locations = null;
    this.textures = TEXTURES.map(() => gl.createTexture());
    this.sums = [gl.createTexture(), gl.createTexture()];
    this.framebuffers = this.sums.map((texture) => {
      const framebuffer = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, 1, 1, 0, gl.RGBA, gl.FLOAT, null);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
      return framebuffer;
    });
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    this.show = null;
    this.vertices = gl.createVertexArray();
    /** The sums' size, the samples in them, which buffer holds them. */
    this.width = 0; this.height = 0; this.samples = 0; this.current = 0; this.before = 0;
    /** @type {Float32Array|null} the sums read back (kept for the next frame of the same size) */
    this.readBack = null;
  }

  /** True when the browser took the context away. */
  get lost() {
    return this.gl.isContextLost();
  }

  /**
   * Uploads the scene's packed form and takes pathTrace's options (readPathOptions's); an Error naming a shape it cannot trace.
   * @param {import('../scene/scene.js').Scene} scene
   * @param {{ seed: number, maxBounces: number, sky: Float64Array, roulette: boolean }} options
   */
  setScene(scene, options) {
    const numbers = gpuScene(scene, PATHS), gl = this.gl;
    uploadScene(gl, this.textures, numbers, 'pathTraceGPU');
    const meshes = numbers.kindTypes.includes(SHAPE_CODES.mesh);
    if (!this.programs.has(meshes)) {
      const program = link(gl, pathSource(meshes));
      this.programs.set(meshes, { program, locations: Object.fromEntries(UNIFORMS.map((name) => [name, gl.getUniformLocation(program, name)])) });
    }
    ({ program: this.program, locations: this.locations } = this.programs.get(meshes));
    this.kindTypes = numbers.kindTypes;
    this.packed = numbers.packed;
    this.options = options;
    this.samples = 0;
  }

  /** Starts a new picture of `camera`: no samples yet (the sums are sized to it). */
  start(camera) {
    const gl = this.gl;
    if (this.width !== camera.width || this.height !== camera.height) {
      this.width = camera.width; this.height = camera.height;
      for (const texture of this.sums) {
        gl.bindTexture(gl.TEXTURE_2D, texture);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, camera.width, camera.height, 0, gl.RGBA, gl.FLOAT, null);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      }
    }
    this.samples = 0;
    this.before = 0;
  }

  /**
   * Adds samples this.samples … this.samples + count − 1 of every pixel of
   * `camera` (the one start() was given) to the sums; allocates nothing.
   */
  pass(camera, count) {
    const gl = this.gl, u = this.locations, k = this.packed, o = this.options;
    const from = this.current, to = 1 - from;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffers[to]);
    gl.viewport(0, 0, this.width, this.height);
    gl.useProgram(this.program);
    bindScene(gl, u, this.textures);
    gl.activeTexture(gl.TEXTURE0 + SUM_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, this.sums[from]);
    gl.uniform1i(u.uSum, SUM_UNIT);
    gl.uniform1i(u.uFirst, this.samples === 0 ? 1 : 0);
    gl.uniform1i(u.uFirstSample, this.samples);
    gl.uniform1i(u.uPassSamples, count);
    gl.uniform1iv(u.uKindType, this.kindTypes);
    gl.uniform1i(u.uCount, k.count);
    gl.uniform1f(u.uEpsilon, k.epsilon);
    gl.uniform1f(u.uBias, k.bias);
    gl.uniform1i(u.uMaxBounces, o.maxBounces);
    gl.uniform1ui(u.uSeed, o.seed);
    gl.uniform1i(u.uRoulette, o.roulette ? 1 : 0);
    gl.uniform3f(u.uSkyTop, o.sky[0], o.sky[1], o.sky[2]);
    gl.uniform3f(u.uSkyBottom, o.sky[3], o.sky[4], o.sky[5]);
    setCamera(gl, u, camera, this.width, this.height);
    gl.bindVertexArray(this.vertices);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    this.current = to;
    this.before = this.samples;
    this.samples += count;
  }

  /**
   * The mean so far as pathTrace's bytes into `target` (RGBA, row 0 at the
   * top): (sum / samples) · 255, clamped, as pathTraceRows writes them.
   * `before`: the mean before the last pass (a view's, while that pass runs).
   * @param {Uint8ClampedArray} target
   */
  read(target, before = false) {
    const gl = this.gl, width = this.width, height = this.height, n = before ? this.before : this.samples;
    if (this.readBack?.length !== width * height * 4) this.readBack = new Float32Array(width * height * 4);
    const sums = this.readBack;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffers[before ? 1 - this.current : this.current]);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, sums);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    for (let row = 0; row < height; row++) { // GL's rows run from the bottom
      for (let i = row * width * 4, j = (height - 1 - row) * width * 4, end = i + width * 4; i < end; i += 4, j += 4) {
        target[j] = (sums[i] / n) * 255; target[j + 1] = (sums[i + 1] / n) * 255; target[j + 2] = (sums[i + 2] / n) * 255; target[j + 3] = 255;
      }
    }
    return target;
  }

  /** Draws the mean so far onto the engine's canvas (sized to the picture); allocates nothing. */
  present() {
    const gl = this.gl;
    if (!this.show) {
      this.show = link(gl, SHOW_SOURCE);
      this.showAt = { uSum: gl.getUniformLocation(this.show, 'uSum'), uScale: gl.getUniformLocation(this.show, 'uScale') };
    }
    if (this.canvas.width !== this.width) this.canvas.width = this.width;
    if (this.canvas.height !== this.height) this.canvas.height = this.height;
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, this.width, this.height);
    gl.useProgram(this.show);
    gl.activeTexture(gl.TEXTURE0 + SUM_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, this.sums[this.current]);
    gl.uniform1i(this.showAt.uSum, SUM_UNIT);
    gl.uniform1f(this.showAt.uScale, this.samples > 0 ? 1 / this.samples : 0);
    gl.bindVertexArray(this.vertices);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  /** Gives the GPU's resources back. */
  dispose() {
    const gl = this.gl;
    [...this.textures, ...this.sums].forEach((texture) => gl.deleteTexture(texture));
    this.framebuffers.forEach((framebuffer) => gl.deleteFramebuffer(framebuffer));
    for (const { program } of this.programs.values()) gl.deleteProgram(program);
    if (this.show) gl.deleteProgram(this.show);
    gl.deleteVertexArray(this.vertices);
  }
}
