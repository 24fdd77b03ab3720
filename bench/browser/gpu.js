/**
 * Section 7 of `npm run bench:browser`: the class scene with full shading
 * (mirrors, glass, shadows) at a given size, as frames per second
 *   - on the GPU engine (lib/gpu/engine.js): each frame a new camera (turning),
 *     drawn, and one pixel read back, which waits for the GPU to finish it;
 *   - on the CPU, on one Web Worker per core (ParallelRenderer), as the CPU
 *     view traces a large frame;
 * and checks the GPU's frame against render()'s (per channel within 2).
 * window.bench.run({ width, height, seconds }) → { gpu: { fps, frames, ms }, cpu: {…}, beyond2 }
 */
import { classScene, Camera, render } from '../../lib/index.js';
import { GpuTracer } from '../../lib/gpu/engine.js';
import { ParallelRenderer } from '../../lib/tracing/workers/parallel.js';

/** The class scene's camera turned `yaw` degrees about the pink sphere (the orbit a drag makes). */
function turned(width, height, yaw) {
  const r = (yaw * Math.PI) / 180, distance = 26;
  return new Camera({ width, height, fov: 40, yaw, pitch: -8, position: [Math.sin(r) * -distance, 3, -20 + Math.cos(r) * distance] });
}

/** Frames of `frame(i)` for about `seconds` (at least `least`): { fps, frames, ms } after one to warm up. */
async function timed(frame, seconds, least) {
  await frame(0); // compiles the shader, starts the workers
  const start = performance.now();
  let frames = 0;
  while (frames < least || performance.now() - start < seconds * 1000) await frame(++frames);
  const ms = performance.now() - start;
  return { fps: (frames * 1000) / ms, frames, ms: ms / frames };
}

async function run({ width = 640, height = 480, seconds = 10, least = 2 } = {}) {
  const scene = classScene({ full: true });
  const tracer = new GpuTracer();
  tracer.setScene(scene);
  const gl = tracer.gl, one = new Uint8Array(4);
  const gpu = await timed((i) => {
    tracer.draw(turned(width, height, i));
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, one); // waits for the frame
  }, seconds, least);
  const cores = navigator.hardwareConcurrency || 2, workers = new ParallelRenderer({ workers: cores }).warm();
  const cpu = await timed((i) => workers.render(scene, turned(width, height, i)), seconds, least);
  workers.terminate();
  const camera = turned(width, height, 0);
  tracer.draw(camera);
  const frame = tracer.read(new Uint8ClampedArray(width * height * 4), width, height), reference = render(scene, camera);
  let beyond2 = 0;
  for (let p = 0; p < frame.length; p += 4) {
    if (Math.abs(frame[p] - reference[p]) > 2 || Math.abs(frame[p + 1] - reference[p + 1]) > 2 || Math.abs(frame[p + 2] - reference[p + 2]) > 2) beyond2++;
  }
  const info = gl.getExtension('WEBGL_debug_renderer_info'); // the GPU's own name (RENDERER alone says "WebKit WebGL")
  const renderer = gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER);
  tracer.dispose();
  return { gpu, cpu: { ...cpu, cores }, beyond2, renderer };
}

window.bench = { run, ready: true };
