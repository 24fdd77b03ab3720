/**
 * The GPU engine: a WebGL2 context on a canvas of its own, the kernel's
 * shader (lib/gpu/glsl-kernel.js), the packed scene as float textures
 * (lib/gpu/upload.js), and a frame drawn in one pass, one fragment a pixel.
 * Nothing here runs until a GpuTracer is made: importing it touches no WebGL.
 */
import { kernelSource, VERTEX_SOURCE, ROW, SHAPE_CODES } from './glsl-kernel.js';
import { gpuScene, inRows } from './upload.js';

/** The textures, by their sampler's name, and what of gpuScene's each holds. */
export const TEXTURES = [['uShapes', 'shapes'], ['uMaterials', 'materials'], ['uLights', 'lights'], ['uApart', 'apart'], ['uTables', 'tables']];

/** Why there is no WebGL2 here, or null when there is (tested before any context is made). */
export function noWebGL2() {
  if (typeof document === 'undefined' && typeof OffscreenCanvas === 'undefined') return 'there is no canvas here (a browser is needed)';
  if (typeof WebGL2RenderingContext === 'undefined') return 'this browser has no WebGL2';
  return null;
}

/**
 * A canvas (the one given, else a new one) and its WebGL2 context, as both GPU tracers want it;
 * an Error saying why when there is none.
 * @param {HTMLCanvasElement|OffscreenCanvas|undefined} canvas
 * @param {boolean} preserveDrawingBuffer
 * @returns {{ canvas: HTMLCanvasElement|OffscreenCanvas, gl: WebGL2RenderingContext }}
 */
export function webgl2Context(canvas, preserveDrawingBuffer) {
  const why = noWebGL2();
  if (why) throw new Error(`the GPU engine needs WebGL2: ${why}`);
  const made = canvas ?? (typeof document !== 'undefined' ? document.createElement('canvas') : new OffscreenCanvas(1, 1));
  const gl = /** @type {WebGL2RenderingContext | null} */ (made.getContext('webgl2', { antialias: false, depth: false, stencil: false, preserveDrawingBuffer, premultipliedAlpha: false }));
  if (!gl) throw new Error('the GPU engine needs WebGL2: this browser gives no WebGL2 context (switched off, or no GPU driver)');
  return { canvas: made, gl };
}

export class GpuTracer {
  /**
   * @param {HTMLCanvasElement|OffscreenCanvas} [canvas] where frames are drawn (a new one when left out)
   * @param {{ preserveDrawingBuffer?: boolean }} [options] keep the last frame readable after the page shows it (a view's)
   */
  constructor(canvas, { preserveDrawingBuffer = false } = {}) {
    const made = webgl2Context(canvas, preserveDrawingBuffer);
    this.canvas = made.canvas;
    const gl = this.gl = made.gl;
    /** The shader with the BVH walk and without it (made when a scene first needs it), and their uniforms. */
    this.programs = new Map();
    /** @type {WebGLProgram | null} the program of the scene set last */
    this.program = null;
    /** @type {any} its uniforms' locations by name */
    this.locations = null;
    this.textures = TEXTURES.map(() => gl.createTexture());
    this.scene = null;
    this.counts = null;
    this.vertices = gl.createVertexArray();
  }

  /** True when the browser took the context away (a driver reset, too many contexts). */
  get lost() {
    return this.gl.isContextLost();
  }

  /** Uploads the scene's packed form; an Error naming a shape the GPU cannot draw. */
  setScene(scene) {
    const numbers = gpuScene(scene), gl = this.gl;
    uploadScene(gl, this.textures, numbers);
    const meshes = numbers.kindTypes.includes(SHAPE_CODES.mesh);
    if (!this.programs.has(meshes)) {
      const program = link(gl, kernelSource(meshes));
      this.programs.set(meshes, { program, locations: locate(gl, program) });
    }
    ({ program: this.program, locations: this.locations } = this.programs.get(meshes));
    this.scene = scene;
    this.kindTypes = numbers.kindTypes;
    this.packed = numbers.packed;
  }

  /** Draws the frame of `camera` (the scene last set) into the engine's canvas; allocates nothing. */
  draw(camera) {
    const gl = this.gl, u = this.locations, k = this.packed;
    if (this.canvas.width !== camera.width) this.canvas.width = camera.width;
    if (this.canvas.height !== camera.height) this.canvas.height = camera.height;
    gl.viewport(0, 0, camera.width, camera.height);
    gl.useProgram(this.program);
    bindScene(gl, u, this.textures);
    gl.uniform1iv(u.uKindType, this.kindTypes);
    gl.uniform1i(u.uCount, k.count);
    gl.uniform1i(u.uLightCount, k.lightCount);
    gl.uniform1i(u.uMaxDepth, k.maxDepth);
    gl.uniform3f(u.uBackground, k.background[0], k.background[1], k.background[2]);
    gl.uniform1f(u.uAmbient, k.ambient);
    gl.uniform1f(u.uBias, k.bias);
    gl.uniform1f(u.uEpsilon, k.epsilon);
    gl.uniform1i(u.uShadows, k.shadows ? 1 : 0);
    gl.uniform1i(u.uSpecular, k.specular ? 1 : 0);
    setCamera(gl, u, camera, camera.width, camera.height);
    gl.uniform1i(u.uSamples, camera.samples);
    gl.bindVertexArray(this.vertices);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  /**
   * The last frame's bytes into `target` (RGBA, row 0 at the top, as render()
   * writes them). GL's rows run from the bottom, so they are turned over.
   */
  read(target, width, height) {
    const gl = this.gl, row = width * 4;
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, target);
    const swap = new Uint8ClampedArray(row);
    for (let top = 0, bottom = height - 1; top < bottom; top++, bottom--) {
      swap.set(target.subarray(top * row, top * row + row));
      target.copyWithin(top * row, bottom * row, bottom * row + row);
      target.set(swap, bottom * row);
    }
    return target;
  }

  /** Gives the GPU's resources back. */
  dispose() {
    const gl = this.gl;
    this.textures.forEach((texture) => gl.deleteTexture(texture));
    for (const { program } of this.programs.values()) gl.deleteProgram(program);
    gl.deleteVertexArray(this.vertices);
  }
}

/**
 * The packed scene's float arrays (gpuScene's) into `textures`, one R32F
 * texture each in rows of ROW numbers; an Error when one is larger than
 * this GPU's textures hold. `where` names the caller in that error.
 */
export function uploadScene(gl, textures, numbers, where = 'renderGPU') {
  const limit = gl.getParameter(gl.MAX_TEXTURE_SIZE);
  TEXTURES.forEach(([, field], t) => {
    const { data, rows } = inRows(numbers[field]);
    if (rows > limit) throw new Error(`${where} cannot draw this scene: its ${field} take ${numbers[field].length} numbers, more than this GPU's textures hold (${ROW * limit})`);
    gl.bindTexture(gl.TEXTURE_2D, textures[t]);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.R32F, ROW, rows, 0, gl.RED, gl.FLOAT, data);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  });
}

/** The scene's textures on units 0 … 4, each sampler told its unit (the program in use); allocates nothing. */
export function bindScene(gl, locations, textures) {
  for (let t = 0; t < TEXTURES.length; t++) {
    gl.activeTexture(gl.TEXTURE0 + t);
    gl.bindTexture(gl.TEXTURE_2D, textures[t]);
    gl.uniform1i(locations[TEXTURES[t][0]], t);
  }
}

/** The compiled and linked program; an Error with the compiler's log. */
export function link(gl, fragmentSource) {
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, VERTEX_SOURCE], [gl.FRAGMENT_SHADER, fragmentSource]]) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS) && !gl.isContextLost()) {
      throw new Error(`the GPU engine's shader did not compile: ${gl.getShaderInfoLog(shader)}`);
    }
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS) && !gl.isContextLost()) {
    throw new Error(`the GPU engine's shader did not link: ${gl.getProgramInfoLog(program)}`);
  }
  return program;
}

/**
 * The camera's uniforms, the same in both GPU shaders (glsl-kernel.js's primary ray): the eye,
 * its right, up and forward, the image plane's half size, and the picture's size in pixels.
 */
export function setCamera(gl, u, camera, width, height) {
  const { position: e, right: r, up, forward: f } = camera;
  gl.uniform3f(u.uEye, e.x, e.y, e.z);
  gl.uniform3f(u.uRight, r.x, r.y, r.z);
  gl.uniform3f(u.uUp, up.x, up.y, up.z);
  gl.uniform3f(u.uForward, f.x, f.y, f.z);
  gl.uniform2f(u.uHalf, camera.halfWidth, camera.halfHeight);
  gl.uniform2i(u.uSize, width, height);
}

/** Every uniform's location, by name. */
function locate(gl, program) {
  const names = ['uShapes', 'uMaterials', 'uLights', 'uApart', 'uTables', 'uKindType', 'uCount', 'uLightCount', 'uMaxDepth', 'uSamples',
    'uBackground', 'uAmbient', 'uBias', 'uEpsilon', 'uShadows', 'uSpecular', 'uEye', 'uRight', 'uUp', 'uForward', 'uHalf', 'uSize'];
  return Object.fromEntries(names.map((name) => [name, gl.getUniformLocation(program, name)]));
}
