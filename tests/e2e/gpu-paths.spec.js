// The GPU's path tracer (pathTraceGPU) in headless Chromium (SwiftShader):
// the white furnace and a closed room whose light is known exactly, sketch
// 16's Cornell box against pathTrace() region by region within the noise,
// the same bytes for the same seed, and errors that say why.
import { test, expect } from '@playwright/test';
import { expectQuietConsole } from './helpers.js';

expectQuietConsole(test);

test.beforeEach(async ({ page }) => {
  await page.goto('/tests/e2e/pages/gpu-paths.html');
  await page.waitForFunction(() => window.pathsTest);
});

test('the white furnace: white paint, glass and a mirror under a uniform sky of L are L; albedo a with one bounce is a·L', async ({ page }) => {
  test.setTimeout(120_000);
  const result = await page.evaluate(() => {
    const { Scene, Sphere, Plane, Camera, pathTraceGPU } = window.RT, L = 0.5;
    const white = new Scene({ background: [L, L, L] })
      .add(new Plane([0, -1, 0], [0, 1, 0], { color: [1, 1, 1] }))
      .add(new Sphere([-2.2, 0, -8], 1, { color: [1, 1, 1] }))
      .add(new Sphere([0, 0, -8], 1, { color: [1, 1, 1], transparency: 1, ior: 1.5 }))
      .add(new Sphere([2.2, 0, -8], 1, { color: [1, 1, 1], reflection: 1 }));
    const camera = new Camera({ width: 48, height: 32, position: [0, 1, 0], pitch: -10 });
    const furnace = pathTraceGPU(white, camera, { samples: 64, maxBounces: 64 });
    const a = 0.6, ball = new Scene({ background: [L, L, L] }).add(new Sphere([0, 0, -6], 2.5, { color: [a, a, a] }));
    const once = pathTraceGPU(ball, camera, { samples: 16, maxBounces: 1 });
    const centre = (16 * 48 + 24) * 4;
    const worst = (frame, expected) => Math.max(...Array.from(frame).filter((_, i) => i % 4 !== 3).map((v) => Math.abs(v / 255 - expected) / expected));
    return { furnace: worst(furnace, L), onceCentre: once[centre] / 255, corner: once[0] / 255, expectedOnce: a * L };
  });
  console.log(`white furnace on the GPU: every channel of every pixel within ${(100 * result.furnace).toFixed(2)} % of L; one bounce: ${result.onceCentre.toFixed(4)} against a·L = ${result.expectedOnce}`);
  expect(result.furnace).toBeLessThanOrEqual(0.02);
  expect(Math.abs(result.onceCentre - result.expectedOnce) / result.expectedOnce).toBeLessThanOrEqual(0.02);
  expect(Math.abs(result.corner - 0.5) / 0.5).toBeLessThanOrEqual(0.02); // the sky around the ball
});

test('a closed room: the eye inside a glowing ball of albedo a gathers E·(1 − a⁴¹)/(1 − a) in 40 bounces; with the roulette, the same within 4 standard errors', async ({ page }) => {
  test.setTimeout(120_000);
  const result = await page.evaluate(() => {
    const { Scene, Sphere, Camera, pathTraceGPU } = window.RT, a = 0.8, E = 0.1;
    const room = new Scene({ background: [0, 0, 0] }).add(new Sphere([0, 0, 0], 5, { color: [a, a, a], emission: [E, E, E] }));
    const camera = new Camera({ width: 64, height: 64 });
    const stats = (frame) => {
      const red = Array.from(frame).filter((_, i) => i % 4 === 0), n = red.length;
      const mean = red.reduce((s, v) => s + v, 0) / n, variance = red.reduce((s, v) => s + (v - mean) ** 2, 0) / (n - 1);
      return { mean, stderr: Math.sqrt(variance / n), min: Math.min(...red), max: Math.max(...red) };
    };
    return {
      expected: (255 * E * (1 - a ** 41)) / (1 - a),
      plain: stats(pathTraceGPU(room, camera, { samples: 16, maxBounces: 40, roulette: false })),
      roulette: stats(pathTraceGPU(room, camera, { samples: 16, maxBounces: 40 })),
    };
  });
  const { expected, plain, roulette } = result;
  console.log(`closed room on the GPU: expected ${expected.toFixed(2)}; without the roulette ${plain.min}…${plain.max}; with it ${roulette.mean.toFixed(2)} ± ${roulette.stderr.toFixed(2)}`);
  expect(Math.abs(plain.min - expected)).toBeLessThanOrEqual(1); // every path alike: the byte, rounded
  expect(Math.abs(plain.max - expected)).toBeLessThanOrEqual(1);
  expect(roulette.stderr).toBeGreaterThan(0); // the roulette ended paths at random
  // Pixels are independent and alike, so the picture's mean is the estimate's; 0.5 for the byte's rounding.
  expect(Math.abs(roulette.mean - expected)).toBeLessThanOrEqual(4 * roulette.stderr + 0.5);
});

/** The regions compared: each a shape's name in the scene. */
const REGIONS = ['floor', 'ceiling', 'back wall', 'red wall', 'green wall', 'tall block', 'lamp'];

/** |GPU − CPU| of a region's mean byte, channel by channel, over the bound: 4 standard errors of the difference, at least half a byte (rounding, float32). */
function offBy({ gpu, cpu }) {
  return [0, 1, 2].map((c) => {
    const bound = Math.max(0.5, 4 * Math.hypot(gpu.stderr[c], cpu.stderr[c]));
    return { c, difference: Math.abs(gpu.mean[c] - cpu.mean[c]), bound };
  });
}

test('sketch 16\'s Cornell box: each region\'s mean colour on the GPU is the CPU\'s within 4 standard errors; direct light alone is not', async ({ page }) => {
  test.setTimeout(300_000);
  const options = { width: 40, height: 40, samples: 64, names: REGIONS };
  const full = await page.evaluate((o) => window.pathsTest.cornell(o), options);
  const lines = [];
  for (const name of REGIONS) {
    const { gpu, cpu } = full[name];
    expect(gpu.pixels, name).toBeGreaterThan(8);
    lines.push(`${name} (${gpu.pixels} px): GPU ${gpu.mean.map((m) => m.toFixed(1))} CPU ${cpu.mean.map((m) => m.toFixed(1))}, ` +
      `bound ${offBy(full[name]).map(({ bound }) => bound.toFixed(2))}`);
  }
  console.log(`Cornell box, 40×40, 64 samples, seeds 1 and 2 on each engine:\n  ${lines.join('\n  ')}`);
  for (const name of REGIONS) {
    for (const { c, difference, bound } of offBy(full[name])) expect(difference, `${name}, channel ${c}`).toBeLessThanOrEqual(bound);
  }
  // The same comparison tells a picture that misses the bounces: the GPU with 2 bounces against the CPU's 16.
  const short = await page.evaluate((o) => window.pathsTest.cornell(o), { ...options, gpuBounces: 2 });
  const failing = REGIONS.filter((name) => offBy(short[name]).some(({ difference, bound }) => difference > bound));
  console.log(`with 2 bounces on the GPU, regions beyond the bound: ${failing.join(', ')}`);
  expect(failing.length).toBeGreaterThanOrEqual(3);
});

test('the same seed gives the same bytes twice; another seed, other bytes', async ({ page }) => {
  test.setTimeout(120_000);
  const result = await page.evaluate(() => {
    const { pathTraceGPU } = window.RT, { cornellBox, cornellCamera } = window.pathsTest;
    const scene = cornellBox(), camera = cornellCamera(32, 32);
    const first = pathTraceGPU(scene, camera, { samples: 8, seed: 7 }), again = pathTraceGPU(scene, camera, { samples: 8, seed: 7 });
    const other = pathTraceGPU(scene, camera, { samples: 8, seed: 8 });
    let same = 0, differ = 0;
    for (let i = 0; i < first.length; i++) { if (first[i] !== again[i]) same++; if (first[i] !== other[i]) differ++; }
    return { length: first.length, type: first.constructor.name, sameSeedDiffers: same, otherSeedDiffers: differ };
  });
  expect(result.type).toBe('Uint8ClampedArray');
  expect(result.length).toBe(32 * 32 * 4);
  expect(result.sameSeedDiffers).toBe(0);
  expect(result.otherSeedDiffers).toBeGreaterThan(0.3 * result.length);
});

test('errors: a shape the GPU cannot trace, pathTrace\'s option checks, no WebGL2', async ({ page }) => {
  const messages = await page.evaluate(() => {
    const { pathTraceGPU, Scene, Camera } = window.RT, { errorOf, Bubble } = window.pathsTest, camera = new Camera({ width: 4, height: 3 });
    const scene = new Scene().add(new Bubble([0, 0, -5], 1));
    return {
      bubble: errorOf(() => pathTraceGPU(scene, camera, { samples: 1 })),
      samples: errorOf(() => pathTraceGPU(new Scene(), camera, { samples: 0 })),
      none: errorOf(() => pathTraceGPU(new Scene(), camera)),
      seed: errorOf(() => pathTraceGPU(new Scene(), camera, { samples: 1, seed: -1 })),
      cpuSeed: errorOf(() => window.RT.pathTrace(new Scene(), camera, { samples: 1, seed: -1 })),
    };
  });
  expect(messages.bubble).toMatch(/^pathTraceGPU cannot path trace shape 0 \(a Bubble\): .*not its class's own.*; pathTrace\(\) traces it on the CPU$/);
  expect(messages.samples).toMatch(/samples/);
  expect(messages.none).toBe('pathTraceGPU needs options { samples } (how many paths per pixel)');
  expect(messages.seed).toBe(messages.cpuSeed);
  expect(messages.seed).toMatch(/^seed must be a whole number/);
});

test('no WebGL2: pathTraceGPU throws an Error saying so', async ({ page }) => {
  await page.addInitScript(() => {
    const getContext = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
      return type === 'webgl2' ? null : getContext.call(this, type, ...rest);
    };
  });
  await page.goto('/tests/e2e/pages/gpu-paths.html');
  await page.waitForFunction(() => window.pathsTest);
  const message = await page.evaluate(() => window.pathsTest.errorOf(() => window.RT.pathTraceGPU(new window.RT.Scene(), new window.RT.Camera({ width: 8, height: 6 }), { samples: 1 })));
  expect(message).toMatch(/^the GPU engine needs WebGL2: /);
});

test.describe('a path-traced tracer view on the GPU (engine: \'gpu\' with path)', () => {
  test.beforeEach(async ({ page }) => {
    await page.goto('/tests/e2e/pages/gpu-path-view.html');
    await page.waitForFunction(() => window.view);
  });

  test('traces sample after sample on the GPU with the CPU\'s progress line, and ends on pathTraceGPU\'s bytes', async ({ page }) => {
    test.setTimeout(180_000);
    await page.goto('/tests/e2e/pages/gpu-path-view.html?samples=256');
    await page.waitForFunction(() => window.view);
    const canvas = page.locator('[data-tracer]'), progress = page.locator('[data-progress-text]');
    await page.evaluate(() => { // every line the page shows, from here on
      const line = document.querySelector('[data-progress-text]');
      window.lines = [line.textContent];
      new MutationObserver(() => window.lines.push(line.textContent)).observe(line, { childList: true, characterData: true, subtree: true });
    });
    await expect(canvas).toHaveAttribute('data-engine', 'gpu');
    await expect(page.locator('[data-message="view-engine"]')).toBeHidden();
    await page.waitForFunction(() => window.view.pathState.sample === 256, null, { timeout: 150_000 });
    await expect(page.locator('body')).toHaveAttribute('data-render', 'done');
    const { buffer, expected, canvasBytes, state, lines } = await page.evaluate(() => {
      const c = document.querySelector('[data-tracer]');
      return {
        buffer: Array.from(window.view.buffer), expected: window.gpuPicture({}), state: window.view.pathState, lines: window.lines,
        canvasBytes: Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data),
      };
    });
    const counts = [...new Set(lines.map((line) => line.match(/^Sample (\d+) of 256 · /)?.[1]).filter(Boolean).map(Number))];
    console.log(`the view's progress line on the GPU showed samples ${counts.join(', ')}`);
    expect(counts.length, 'the picture grew in passes, each shown').toBeGreaterThanOrEqual(3);
    expect(counts).toEqual([...counts].sort((a, b) => a - b));
    expect(state).toEqual({ sample: 256, samples: 256, options: { samples: 256, maxBounces: 16 }, noise: null }); // the noise is measured on the CPU only
    expect(buffer).toEqual(expected); // the sums add sample after sample in order, whatever the passes
    const off = canvasBytes.filter((v, i) => Math.abs(v - expected[i]) > 1).length; // the canvas shows the mean (rounded by the GPU)
    expect(off).toBe(0);
    await expect(progress).toHaveText(/^Sample 256 of 256 · [\d.]+[kM]? paths\/s$/);
  });

  test('setPath traces again on the GPU; a click opens the pixel\'s path by inspectPath on the CPU; the switch to the CPU keeps the path options', async ({ page }) => {
    test.setTimeout(120_000);
    await page.waitForFunction(() => window.view.pathState.sample === 16, null, { timeout: 90_000 });
    await page.evaluate(() => window.view.setPath({ maxBounces: 1 }));
    await page.waitForFunction(() => window.view.pathState.sample === 16 && window.view.pathState.options.maxBounces === 1, null, { timeout: 90_000 });
    const direct = await page.evaluate(() => ({ buffer: Array.from(window.view.buffer), expected: window.gpuPicture({ maxBounces: 1 }) }));
    expect(direct.buffer).toEqual(direct.expected);
    await page.evaluate(() => window.view.select(12, 20));
    await expect(page.locator('[data-path-inspector] caption')).toHaveText(/^Sample \d+ of pixel 12,20: \d+ hits?$/); // inspectPath, on the CPU
    await page.evaluate(() => window.view.setEngine('cpu'));
    await expect(page.locator('[data-tracer]')).toHaveAttribute('data-engine', 'cpu');
    await page.waitForFunction(() => window.view.pathState.sample === 16, null, { timeout: 90_000 });
    const cpu = await page.evaluate(() => ({ buffer: Array.from(window.view.buffer), expected: window.cpuPicture({ maxBounces: 1 }), state: window.view.pathState }));
    expect(cpu.state.options).toEqual({ samples: 16, maxBounces: 1 });
    expect(cpu.buffer).toEqual(cpu.expected);
  });
});
