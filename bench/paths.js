/**
 * Path tracing's benchmark (part of `npm run bench`): samples per second on
 * one core at 320×240 (each sample a whole path, its bounces until the lamp,
 * the sky, absorption or the roulette), and the heap allocated per sample.
 * Three scenes: sketch 16's Cornell box (planes, boxes, a fuzzy mirror ball:
 * long paths in a closed room), the class's example (balls under a sky:
 * short paths) and sketch 17's 90 balls (each path tests every ball). Figures are printed, never asserted (docs/path-tracing.md).
 *
 * Then light sampling against bounces alone, side by side in one run (the
 * machine's load cancels in the ratios): the Cornell box and the same box lit
 * by a lamp of 1/16 the area and the same power. Samples per second on one
 * core, the variance per sample of the picture's mean, and the efficiency
 * 1 / (time per sample × variance): how much less time the same noise takes.
 */
import { performance } from 'node:perf_hooks';
import { bytesAllocatedBy } from '../tests/shared/heap.js';
import { Scene, Sphere, Box, Camera, classScene, pathTrace } from '../lib/index.js';
import { readPathOptions, preparePaths } from '../lib/tracing/pathtrace/path-trace.js';
import { tracePath, radiance } from '../lib/tracing/pathtrace/integrator.js';
import { cornellBox, cornellCamera } from '../tests/shared/cornell-box.js';

/** Sketch 16's room, as the page builds it with its lamp at 8, at 320×240. */
const cornellRoom = () => ({ scene: cornellBox(8), camera: cornellCamera(320, 240) });

/** Sketch 17's scene, *Ray Tracing in One Weekend*'s last picture small: 90 balls on a ground ball under the book's sky. */
function oneWeekend() {
  let state = 7;
  const random = () => { state = (Math.imul(state, 1664525) + 1013904223) >>> 0; return state / 2 ** 32; };
  const scene = new Scene({ background: [0.7, 0.8, 1] });
  scene.add(new Sphere([0, -1000, 0], 1000, { color: [0.5, 0.5, 0.5] }));
  for (let a = -5; a < 5; a++) {
    for (let b = -5; b < 5; b++) {
      const center = [a + 0.9 * random(), 0.2, b + 0.9 * random()], pick = random();
      if (![[4, 0], [0, 0], [-4, 0]].every(([x, z]) => Math.hypot(center[0] - x, center[2] - z) > 1.2)) continue;
      if (pick < 0.8) scene.add(new Sphere(center, 0.2, { color: [random() * random(), random() * random(), random() * random()] }));
      else if (pick < 0.95) scene.add(new Sphere(center, 0.2, { color: [0.5 + random() / 2, 0.5 + random() / 2, 0.5 + random() / 2], reflection: 1, fuzz: random() / 2 }));
      else scene.add(new Sphere(center, 0.2, { transparency: 1, ior: 1.5 }));
    }
  }
  scene.add(new Sphere([0, 1, 0], 1, { transparency: 1, ior: 1.5 }));
  scene.add(new Sphere([-4, 1, 0], 1, { color: [0.4, 0.2, 0.1] }));
  scene.add(new Sphere([4, 1, 0], 1, { color: [0.7, 0.6, 0.5], reflection: 1 }));
  return { scene, camera: new Camera({ width: 320, height: 240, fov: 20, position: [13, 2, 3], yaw: -77, pitch: -8.5 }) };
}

const median = (values) => [...values].sort((a, b) => a - b)[values.length >> 1];

/** Samples per second and bytes per sample of one scene at 320×240, `samples` paths a pixel a frame. */
function measure(label, { scene, camera }, given) {
  const options = { ...given, blocking: true }; // a whole frame at once, on purpose: a benchmark, not a page
  const paths = camera.width * camera.height * options.samples;
  for (let i = 0; i < 2; i++) pathTrace(scene, camera, options); // warm up
  const times = [];
  for (let i = 0; i < 5; i++) {
    const start = performance.now();
    pathTrace(scene, camera, options);
    times.push(performance.now() - start);
  }
  const bytes = bytesAllocatedBy(() => pathTrace(scene, camera, options));
  const rate = paths / (median(times) / 1000);
  console.log(`  ${label.padEnd(44)} ${(rate / 1e6).toFixed(2).padStart(6)} M samples/s ${(rate / (camera.width * camera.height)).toFixed(1).padStart(7)} samples/pixel/s ${(bytes / paths).toFixed(2).padStart(8)} B/sample`);
}

/** The Cornell box with its lamp (5 × 5 under the ceiling) shrunk to 1/16 of the area, 16× as bright: the same power. */
export function smallLampRoom(width, height) {
  const scene = cornellBox(8), at = scene.objects.findIndex((o) => o.name === 'lamp');
  scene.objects[at] = new Box([-0.625, 9.8, -15.125], [0.625, 9.99, -13.875], { color: [0, 0, 0], emission: [128, 128, 115.2], name: 'lamp' });
  return { scene, camera: cornellCamera(width, height) };
}

/**
 * The noise of one sample per pixel: each pixel's variance (the mean of its
 * channels, from `samples` samples, unbiased), summed over the pixels / N²:
 * the variance of the picture's mean; and the same over the pixels that see
 * no light straight (whose first hit gives off no light in any of their
 * samples: the eye's ray of a sample is the same with maxBounces 0), where
 * the noise is the light the surfaces receive.
 */
function noise({ scene, camera }, options, samples) {
  const frame = preparePaths(scene, camera, readPathOptions({ ...options, samples }, scene, camera));
  const eye = preparePaths(scene, camera, readPathOptions({ ...options, samples, maxBounces: 0, lightSampling: false }, scene, camera));
  const all = [], unlit = [];
  for (let y = 0; y < camera.height; y++) {
    for (let x = 0; x < camera.width; x++) {
      let sum = 0, squares = 0, seesLight = false;
      for (let s = 0; s < samples; s++) {
        tracePath(eye, x, y, s);
        if (radiance[0] + radiance[1] + radiance[2] > 0) seesLight = true;
        tracePath(frame, x, y, s);
        const v = (radiance[0] + radiance[1] + radiance[2]) / 3;
        sum += v; squares += v * v;
      }
      const variance = (squares - (sum * sum) / samples) / (samples - 1);
      all.push(variance);
      if (!seesLight) unlit.push(variance);
    }
  }
  const ofMean = (list) => list.reduce((a, v) => a + v, 0) / (list.length * list.length);
  return { imageMean: ofMean(all), unlit: ofMean(unlit), unlitShare: unlit.length / all.length };
}

/** CPU seconds of this thread's process spent in `work` (not the wall clock: other programs on the machine do not count). */
function cpuSeconds(work) {
  const start = process.cpuUsage();
  work();
  const { user, system } = process.cpuUsage(start);
  return (user + system) / 1e6;
}

/**
 * Seconds per sample (per pixel) of pathTrace for each of `optionsList`, frames
 * taken in turn (one of each, then again: a busy spell falls on all alike),
 * the median of 5 after a warm-up, in CPU time.
 */
function secondsPerSample({ scene, camera }, optionsList) {
  const times = optionsList.map(() => []), paths = camera.width * camera.height;
  for (const options of optionsList) pathTrace(scene, camera, options);
  for (let round = 0; round < 5; round++) {
    optionsList.forEach((options, k) => times[k].push(cpuSeconds(() => pathTrace(scene, camera, options)) / (paths * options.samples)));
  }
  return times.map(median);
}

/** Light sampling on and off, in one run: samples/s, variance, efficiency, and the ratios. */
export function compareLightSampling(label, room) {
  const times = secondsPerSample(room, [false, true].map((lightSampling) => ({ samples: 2, lightSampling })));
  const rows = [false, true].map((lightSampling, k) => {
    const time = times[k];
    const { imageMean, unlit, unlitShare } = noise(room, { lightSampling, seed: 11 }, 16);
    return { lightSampling, time, imageMean, unlit, unlitShare, efficiency: 1 / (time * imageMean) };
  });
  for (const r of rows) {
    console.log(`  ${`${label}, ${r.lightSampling ? 'light sampling' : 'bounces alone'}`.padEnd(44)} ${(1 / r.time / 1e6).toFixed(3).padStart(6)} M samples/s` +
      `   variance of the mean ${r.imageMean.toExponential(2)} (of the ${(100 * r.unlitShare).toFixed(0)} % that see no light straight: ${r.unlit.toExponential(2)})   efficiency ${r.efficiency.toExponential(2)}`);
  }
  const [off, on] = rows;
  console.log(`  ${''.padEnd(44)} light sampling: ×${(off.time / on.time).toFixed(2)} the samples/s, ÷${(off.imageMean / on.imageMean).toFixed(1)} the variance ` +
    `(÷${(off.unlit / on.unlit).toFixed(1)} where no light is seen straight), efficiency ×${(on.efficiency / off.efficiency).toFixed(2)} ` +
    `(×${((off.unlit * off.time) / (on.unlit * on.time)).toFixed(2)} where no light is seen straight)`);
}

export function runPathBench() {
  console.log('\nPath tracing, one core, 320×240 (pathTrace; median of 5 frames; heap per sample over one more):');
  measure('Cornell box (sketch 16), 4 samples, 16 bounces', cornellRoom(), { samples: 4, maxBounces: 16 });
  measure('Cornell box, 1 bounce (direct light only)', cornellRoom(), { samples: 4, maxBounces: 1 });
  const scene = classScene();
  measure('the class scene under its sky, 4 samples', { scene, camera: new Camera({ width: 320, height: 240 }) }, { samples: 4 });
  measure('One weekend\'s final scene (sketch 17), 2 samples', oneWeekend(), { samples: 2, sky: { top: [0.5, 0.7, 1], bottom: [1, 1, 1] } });
  console.log('\nLight sampling against bounces alone, one core, 160×120 (CPU time per sample, the median of 5 frames each, taken in turn; variance per sample from 16 samples a pixel; efficiency = 1 / (time per sample × variance)):');
  compareLightSampling('Cornell box (sketch 16)', { scene: cornellBox(8), camera: cornellCamera(160, 120) });
  compareLightSampling('the box with a small lamp (1/16 the area)', smallLampRoom(160, 120));
}
