/**
 * A scrubbed number's first coarse picture (editor/number-scrub.js): what the
 * frame does when the page sends a new value of a scene field. The class
 * scene's pink sphere's radius is stepped by 0.1, back and forth: its scene
 * and camera written as JSON, the field set and read back (scene-values.js),
 * the renderer restarted with the new scene and stepped until its first
 * coarse pass (blocks of 16 px) is on the picture, as a tracer view would
 * (one thread, 8 ms steps, minus the waits between animation frames).
 * Target: 50 ms on CPU. Printed, never asserted: it depends on the machine.
 */
import { performance } from 'node:perf_hooks';
import { Camera, classScene } from '../lib/index.js';
import { ProgressiveRenderer, COARSE_PASSES } from '../lib/tracing/frames.js';
import { withValues } from '../editor/scene-values.js';

const STEPS = 40;
const WARMUP = 5;

const median = (values) => {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
};

/** Milliseconds from a new radius to the first coarse pass done, for each of `steps` steps. */
function timeSteps(width, height, full, steps) {
  const camera = new Camera({ width, height, fov: 30, position: [0, 0, 0] });
  let scene = classScene({ full });
  const pink = scene.objects.findIndex((o) => o.name === 'pink');
  const renderer = new ProgressiveRenderer({ scene, camera });
  while (!renderer.step(8).done);
  const times = [], json = [];
  for (let i = 0; i < WARMUP + steps; i++) {
    const radius = i % 2 ? 4 : 4.1;
    const start = performance.now();
    scene = withValues(scene, camera, [{ path: ['scene', 'objects', String(pink), 'radius'], value: radius }]).scene;
    const read = performance.now();
    renderer.restart({ scene });
    while (renderer.blockSize === COARSE_PASSES[0] && !renderer.step(8).done);
    if (i >= WARMUP) {
      times.push(performance.now() - start);
      json.push(read - start);
    }
  }
  return { times, json };
}

export function runScrubBench() {
  console.log(`\nA scrubbed number's first coarse picture (bench/scrub.js): the class scene's radius stepped ${STEPS} times, JSON in and out, then the 16 px pass (target 50 ms):`);
  for (const [width, height, full] of [[160, 120, false], [160, 120, true], [640, 480, false], [640, 480, true]]) {
    const { times, json } = timeSteps(width, height, full, STEPS);
    console.log(`  ${width}×${height}, ${full ? 'full shading' : 'Lambert + shadows'}: median ${median(times).toFixed(2)} ms`
      + ` (of which the JSON ${median(json).toFixed(2)} ms), slowest ${Math.max(...times).toFixed(2)} ms`);
  }
}

if (import.meta.url === `file://${process.argv[1]}`) runScrubBench();
