// Sketch 11, several rays per pixel: the jagged picture beside the smoothed
// one, a shared selected pixel, the panel of that pixel's rays, and the
// choice of 1, 4, 9 or 16 rays.
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';

const PAGE = '/sketches/11-several-rays-per-pixel.html';

/** Pixel (x, y) of a tracer canvas as bytes [r, g, b]. */
const pixelOf = (canvas, x, y) => canvas.evaluate((c, [px, py]) => [...c.getContext('2d').getImageData(px, py, 1, 1).data.slice(0, 3)], [x, y]);
const hex = (rgb) => `#${rgb.map((c) => c.toString(16).padStart(2, '0')).join('')}`;

test.beforeEach(async ({ page }) => {
  await page.goto(PAGE);
  await waitForDone(page);
});

test('the smoothed picture differs from the jagged one on the edges only, and both are as they were', async ({ page }) => {
  const [jagged, smooth] = [page.locator('[data-tracer]').nth(0), page.locator('[data-tracer]').nth(1)];
  const differ = await page.evaluate(() => {
    const [a, b] = [...document.querySelectorAll('[data-tracer]')].map((c) => c.getContext('2d').getImageData(0, 0, c.width, c.height).data);
    let pixels = 0;
    for (let i = 0; i < a.length; i += 4) if (a[i] !== b[i] || a[i + 1] !== b[i + 1] || a[i + 2] !== b[i + 2]) pixels++;
    return { pixels, of: a.length / 4 };
  });
  expect(differ.pixels).toBeGreaterThan(50); // the edges
  expect(differ.pixels).toBeLessThan(differ.of / 3); // not the insides
  await expectCanvasScreenshot(jagged, 'jagged.png');
  await expectCanvasScreenshot(smooth, 'smooth-4.png');
});

test('a click on an edge pixel shows its four rays, what each hit, and their average: the pixel shown', async ({ page }) => {
  const errors = watchConsole(page);
  const [jagged, smooth] = [page.locator('[data-tracer]').nth(0), page.locator('[data-tracer]').nth(1)];
  await clickPixel(jagged, 26, 6); // the pink sphere's top edge, clicked in the other picture
  const panel = page.locator('[data-sample-rays]');
  await expect(panel).toHaveAttribute('data-rays', '4');
  await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(/^Pixel: 26,6;/); // one selected pixel for both
  const hits = await panel.locator('tbody [data-field="hit"]').allTextContents();
  expect(hits).toHaveLength(4);
  expect(new Set(hits)).toEqual(new Set(['pink', 'nothing']));
  await expect(panel).toContainText('They do not all hit the same thing');
  const shown = hex(await pixelOf(smooth, 26, 6));
  await expect(panel.locator('[data-field="average-words"]')).toContainText(shown);
  await expect(page.locator('[data-inspector] [data-field="hex"]')).toHaveText(shown);
  expect(shown).not.toBe(hex(await pixelOf(jagged, 26, 6))); // the edge pixel is a mix, not all sky or all sphere
  expect(errors).toEqual([]);
});

test('16 rays: the picture is traced again, the panel lists 16 rays; 1 ray: it says the one ray decides', async ({ page }) => {
  const smooth = page.locator('[data-tracer]').nth(1);
  await page.getByRole('radio', { name: '16' }).check();
  await waitForDone(page);
  await expect(page.locator('figcaption.rt-label').nth(1)).toHaveText('16 rays per pixel');
  const panel = page.locator('[data-sample-rays]');
  await expect(panel).toHaveAttribute('data-rays', '16');
  await expect(panel.locator('tbody tr')).toHaveCount(16);
  await expectCanvasScreenshot(smooth, 'smooth-16.png');
  await page.getByRole('radio', { name: '1', exact: true }).check();
  await waitForDone(page);
  await expect(panel).toHaveAttribute('data-rays', '1');
  await expect(panel).toContainText('One ray through the pixel');
  const [a, b] = await page.evaluate(() => [...document.querySelectorAll('[data-tracer]')].map((c) => c.toDataURL()));
  expect(a).toBe(b); // one ray per pixel on both sides: the same picture
});
