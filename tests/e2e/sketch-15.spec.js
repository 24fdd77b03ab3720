// Sketch 15, live on the GPU: the class scene with mirrors and glass on the
// GPU engine (data-engine="gpu"), its picture within 2 per channel of the
// CPU's; a click opens the pixel's story and the inspector compares the GPU's
// byte with it; a drag orbits the camera, + moves it closer; the CPU | GPU
// switch; frames per second shown; without WebGL2 the CPU, and a line saying why.
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, expectQuietConsole, waitForDone } from './helpers.js';

const PAGE = '/sketches/15-live-on-the-gpu.html';

expectQuietConsole(test);

/** The tracer canvas's bytes, RGBA. */
const bytesOf = (canvas) => canvas.evaluate((c) => [...c.getContext('2d').getImageData(0, 0, c.width, c.height).data]);

/** How many pixels differ by more than 2 in some channel. */
function beyond2(a, b) {
  let n = 0;
  for (let i = 0; i < a.length; i += 4) if ([0, 1, 2].some((c) => Math.abs(a[i + c] - b[i + c]) > 2)) n++;
  return n;
}

test('the GPU draws the class scene, the same picture as the CPU within 2 per channel', async ({ page }) => {
  test.setTimeout(120_000);
  await page.goto(PAGE);
  await waitForDone(page, 60_000);
  const canvas = page.locator('[data-tracer]');
  await expect(canvas).toHaveAttribute('data-engine', 'gpu');
  await expectCanvasScreenshot(canvas, 'class-scene-gpu.png');
  const gpu = await bytesOf(canvas);
  await page.getByLabel('CPU').check();
  await expect(canvas).toHaveAttribute('data-engine', 'cpu');
  await waitForDone(page, 60_000);
  expect(beyond2(gpu, await bytesOf(canvas))).toBe(0);
  await expect(page.locator('[data-fps]')).toHaveText(/^\d+\.\d frames per second on the (CPU|GPU)$/);
});

test('a click tells the pixel\'s story; the inspector compares the GPU\'s byte with the record\'s colour', async ({ page }) => {
  await page.goto(PAGE);
  await waitForDone(page, 60_000);
  await clickPixel(page.locator('[data-tracer]'), 80, 60);
  const inspector = page.locator('[data-inspector]');
  await expect(inspector.locator('[data-answer]')).toHaveText(/^Pixel: 80,60;/);
  const difference = inspector.locator('[data-gpu-difference]');
  await expect(difference).toBeVisible();
  expect(Number(await difference.getAttribute('data-gpu-difference'))).toBeLessThanOrEqual(2);
});

test('a drag orbits the camera and + moves it closer: a new picture, the GPU still', async ({ page }) => {
  test.setTimeout(120_000);
  await page.goto(PAGE);
  await waitForDone(page, 60_000);
  const canvas = page.locator('[data-tracer]');
  const before = await bytesOf(canvas);
  const box = await canvas.boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 60, box.y + box.height / 2, { steps: 4 });
  await page.mouse.up();
  await waitForDone(page, 60_000);
  await expect.poll(async () => beyond2(before, await bytesOf(canvas)), { timeout: 30_000 }).toBeGreaterThan(1000);
  const turned = await bytesOf(canvas);
  await page.keyboard.press('Escape'); // the press selected a pixel: let it go, then the arrows turn the camera
  await canvas.press('+');
  await waitForDone(page, 60_000);
  await expect.poll(async () => beyond2(turned, await bytesOf(canvas)), { timeout: 30_000 }).toBeGreaterThan(1000);
  await expect(canvas).toHaveAttribute('data-engine', 'gpu');
});

test('without WebGL2 the view traces on the CPU and says why', async ({ page }) => {
  test.setTimeout(120_000);
  await page.addInitScript(() => {
    const getContext = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
      return type === 'webgl2' ? null : getContext.call(this, type, ...rest);
    };
  });
  await page.goto(PAGE);
  await waitForDone(page, 60_000);
  await expect(page.locator('[data-tracer]')).toHaveAttribute('data-engine', 'cpu');
  await expect(page.locator('[data-message="view-engine"]')).toHaveText(/^Traced on the CPU: .*WebGL2/);
  await expect(page.getByLabel('CPU')).toBeChecked();
});

test('when the browser takes the GPU\'s context away, the view goes back to the CPU and says why', async ({ page }) => {
  test.setTimeout(120_000);
  await page.addInitScript(() => { // keep the WebGL2 contexts the page makes, to lose one
    const getContext = HTMLCanvasElement.prototype.getContext;
    window.contexts = [];
    HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
      const context = getContext.call(this, type, ...rest);
      if (type === 'webgl2' && context) window.contexts.push(context);
      return context;
    };
  });
  await page.goto(PAGE);
  await waitForDone(page, 60_000);
  const canvas = page.locator('[data-tracer]');
  await expect(canvas).toHaveAttribute('data-engine', 'gpu');
  await page.evaluate(() => window.contexts[0].getExtension('WEBGL_lose_context').loseContext());
  await canvas.press('+'); // a new camera: the next frame finds the context lost
  await expect(canvas).toHaveAttribute('data-engine', 'cpu');
  await expect(page.locator('[data-message="view-engine"]')).toHaveText('Traced on the CPU: the GPU context was lost.');
  await waitForDone(page, 60_000);
});
