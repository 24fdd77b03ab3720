// The GPU engine in step with render(): random scenes (tests/shared/random-scenes.js,
// every shape, light and material) traced by renderGPU in headless Chromium
// (SwiftShader) and by render(), compared per channel; a shape the GPU cannot
// draw, and a browser without WebGL2, give errors that say why.
import { test, expect } from '@playwright/test';
import fc from 'fast-check';
import { sceneToJSON } from '../../lib/index.js';
import { scene, shapeScene, sphereScene, camera } from '../shared/random-scenes.js';
import { expectQuietConsole } from './helpers.js';

expectQuietConsole(test);

/**
 * Scenes the two can share: a shadow-ray offset (bias 0 draws shadow acne,
 * rounding noise that float32 draws differently, as the lesson shows) and
 * each shape once (the GPU tells shapes apart by their place in the list).
 */
const fair = (s) => s.bias > 0 && new Set(s.objects).size === s.objects.length;
const CASES = fc.sample(fc.tuple(fc.oneof(scene, shapeScene, sphereScene).filter(fair), camera), { seed: 34, numRuns: 100 })
  .map(([s, cam]) => ({
    json: sceneToJSON(s),
    options: { width: cam.width, height: cam.height, fov: cam.fov, position: [cam.position.x, cam.position.y, cam.position.z], yaw: cam.yaw, pitch: cam.pitch, samples: cam.samples },
  }));

/** How far the camera turns to find the pixels float32 can tip: a thousandth of a degree. */
const NUDGE = 1e-3;

test('renderGPU ≈ render over random scenes: per channel |Δ| ≤ 2 on at least 99.5 % of pixels, the rest grazing', async ({ page }) => {
  test.setTimeout(600_000);
  await page.goto('/tests/e2e/pages/gpu.html');
  await page.waitForFunction(() => window.gpuTest);
  let pixels = 0, off = 0, grazing = 0, worst = 0;
  const steady = [];
  for (const [i, { json, options }] of CASES.entries()) {
    const result = await page.evaluate(([j, o, n]) => window.gpuTest.inStep(j, o, n), [json, options, NUDGE]);
    pixels += result.pixels; off += result.off; grazing += result.grazing; worst = Math.max(worst, result.worst);
    if (result.steady.length) steady.push({ case: i, options, pixels: result.steady });
  }
  const within = pixels - off;
  console.log(`GPU ≈ render: ${CASES.length} scenes, ${pixels} pixels, ${within} within 2 per channel (${((100 * within) / pixels).toFixed(3)} %), ` +
    `${off} beyond (the largest |Δ| ${worst}), ${grazing} of them grazing (render() itself moves them when the camera turns ${NUDGE}°)`);
  expect(within / pixels).toBeGreaterThanOrEqual(0.995);
  expect(steady, 'pixels beyond 2 that no nudge of the camera moves on the CPU').toEqual([]);
});

test('the class scene with mirrors and glass: every pixel within 2', async ({ page }) => {
  test.setTimeout(120_000);
  await page.goto('/tests/e2e/pages/gpu.html');
  await page.waitForFunction(() => window.gpuTest);
  const result = await page.evaluate(() => {
    const { Camera, classScene, render, renderGPU } = window.RT;
    const scene = classScene({ full: true }), cam = new Camera({ width: 80, height: 60, samples: 4 });
    const gpu = renderGPU(scene, cam);
    return { ...window.gpuTest.compare(gpu, render(scene, cam), 2), length: gpu.length, type: gpu.constructor.name };
  });
  expect(result.type).toBe('Uint8ClampedArray');
  expect(result.length).toBe(80 * 60 * 4);
  expect(result.off).toEqual([]);
});

test('a shape the GPU cannot draw: an Error naming the shape and why', async ({ page }) => {
  await page.goto('/tests/e2e/pages/gpu.html');
  await page.waitForFunction(() => window.gpuTest);
  const message = await page.evaluate(() => window.gpuTest.errorFor('bubble'));
  expect(message).toMatch(/renderGPU cannot draw shape 0 \(a Bubble\).*not its class's own/);
});

test('no WebGL2: renderGPU throws an Error saying so', async ({ page }) => {
  await page.addInitScript(() => {
    const getContext = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
      return type === 'webgl2' ? null : getContext.call(this, type, ...rest);
    };
  });
  await page.goto('/tests/e2e/pages/gpu.html');
  await page.waitForFunction(() => window.gpuTest);
  const message = await page.evaluate(() => {
    try {
      window.RT.renderGPU(window.RT.classScene(), new window.RT.Camera({ width: 8, height: 6 }));
      return null;
    } catch (error) {
      return error.message;
    }
  });
  expect(message).toMatch(/needs WebGL2.*no WebGL2 context/);
});

test('each GLSL optics formula gives lib/tracing/optics.js\'s number on sampled inputs (a float texture read back)', async ({ page }) => {
  await page.goto('/tests/e2e/pages/gpu-formulas.html');
  await page.waitForFunction(() => window.gpuFormulas);
  const names = await page.evaluate(() => window.gpuFormulas.names);
  expect(names).toEqual(['lambert', 'specular', 'spotShare', 'falloff', 'lightShare', 'refraction', 'schlick', 'fresnel', 'mixShares']);
  for (const name of names) {
    const { compared, worst } = await page.evaluate((n) => window.gpuFormulas.check(n), name);
    expect(compared, name).toBeGreaterThan(400);
    expect(worst, `${name}: the sample farthest outside float32's tolerance`).toEqual({ excess: 0, sample: -1 });
  }
});

test('a GPU view: a visual mode other than the shaded picture goes back to the CPU and says why; setEngine brings the GPU back', async ({ page }) => {
  test.setTimeout(120_000);
  await page.goto('/tests/e2e/pages/inspector.html?engine=gpu');
  await expect(page.locator('body')).toHaveAttribute('data-render', 'done', { timeout: 60_000 });
  const canvas = page.locator('[data-tracer]');
  await expect(canvas).toHaveAttribute('data-engine', 'gpu');
  await page.evaluate(() => window.view.setMode('normals'));
  await expect(canvas).toHaveAttribute('data-engine', 'cpu');
  await expect(page.locator('[data-message="view-engine"]')).toHaveText('Traced on the CPU: the GPU draws the shaded picture only.');
  await expect(page.locator('body')).toHaveAttribute('data-render', 'done', { timeout: 60_000 });
  await page.evaluate(() => window.view.setMode('shaded').setEngine('gpu'));
  await expect(canvas).toHaveAttribute('data-engine', 'gpu');
  await expect(page.locator('[data-message="view-engine"]')).toBeHidden();
  await expect(page.evaluate(() => window.view.setEngine('metal'))).rejects.toThrow(/engine must be 'cpu' or 'gpu', got "metal"/);
});
