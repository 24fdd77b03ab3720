// Sketch 14, spot and area lights: the same ball under a point light (a hard
// shadow) and under a disc of light (a soft one), a spot light's circle with a
// smooth rim; a click at the shadow's edge says how many of the disc's 16
// shadow rays reached the point, one outside the spot's circle says so.
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';

const PAGE = '/sketches/14-spot-and-area-lights.html';

/** Pixel (x, y) of a tracer canvas as bytes [r, g, b]. */
const pixelOf = (canvas, x, y) => canvas.evaluate((c, [px, py]) => [...c.getContext('2d').getImageData(px, py, 1, 1).data.slice(0, 3)], [x, y]);

test.beforeEach(async ({ page }) => {
  await page.goto(PAGE);
  await waitForDone(page);
});

test('both pictures are traced: the point light\'s shadow is hard, the disc\'s soft, and they differ at its edge', async ({ page }) => {
  const errors = watchConsole(page);
  const [hard, soft] = [page.locator('[data-tracer]').nth(0), page.locator('[data-tracer]').nth(1)];
  // The shadow's edge at the preselected pixel: the disc's picture is lighter there than the point light's shadow or darker than its light.
  expect(await pixelOf(hard, 73, 33)).not.toEqual(await pixelOf(soft, 73, 33));
  await expectCanvasScreenshot(hard, 'point-light.png');
  await expectCanvasScreenshot(soft, 'area-light-16.png');
  expect(errors).toEqual([]);
});

test('the preselected pixel is in the penumbra: some of the 16 shadow rays reach the disc, not all', async ({ page }) => {
  const inspector = page.locator('[data-inspector]');
  await expect(inspector.locator('[data-answer]')).toHaveText(/^Pixel: 73,33;/);
  const line = inspector.locator('[data-field="area-reached"]');
  await expect(line).toHaveText(/^area light 'disc': \d+ of 16 shadow rays reached it/);
  const [n, of] = (await line.getAttribute('data-value')).split('/').map(Number);
  expect(of).toBe(16);
  expect(n).toBeGreaterThan(0);
  expect(n).toBeLessThan(16);
  // The spot's row, inside its cone or not, fades with distance.
  await expect(inspector.locator('tr', { has: page.locator('[data-field="light"]', { hasText: 'spot' }) }).locator('[data-field="falloff"]')).toHaveText(/^falloff ×0\.\d+ at distance /);
});

test('a floor pixel outside the spot\'s circle says so; one inside does not', async ({ page }) => {
  const soft = page.locator('[data-tracer]').nth(1);
  const inspector = page.locator('[data-inspector]');
  const spotRow = inspector.locator('tr', { has: page.locator('[data-field="light"]', { hasText: 'spot' }) });
  await clickPixel(soft, 80, 60); // the floor in front, right: far from the spot's circle
  await expect(inspector.locator('[data-answer]')).toHaveText(/^Pixel: 80,60;/);
  await expect(spotRow.locator('[data-field="in-shadow"]')).toHaveText('outside its cone');
  await clickPixel(soft, 12, 38); // the floor in the spot's circle, in front of the cylinder
  await expect(inspector.locator('[data-answer]')).toHaveText(/^Pixel: 12,38;/);
  await expect(spotRow.locator('[data-field="in-shadow"]')).toHaveText('lit');
});

test('1 shadow ray: the disc is a point again and its picture is the point light\'s; a wider spot lights more floor', async ({ page }) => {
  const [hard, soft] = [page.locator('[data-tracer]').nth(0), page.locator('[data-tracer]').nth(1)];
  const bytes = (c) => c.evaluate((el) => el.toDataURL('image/png'));
  await page.getByRole('radio', { name: '1', exact: true }).check();
  await waitForDone(page);
  await expect(page.locator('figcaption.rt-label').nth(1)).toHaveText('A disc with 1 shadow ray: a point again');
  expect(await bytes(soft)).toEqual(await bytes(hard)); // 1 sample: the disc's centre, the point light's place
  await expect(page.locator('[data-inspector] [data-field="area-reached"]')).toHaveText(/ of 1 shadow ray/);
  const before = await pixelOf(soft, 8, 44); // the floor just past the rim of a 20° cone, inside one of 30°
  await page.getByRole('radio', { name: '30°' }).check();
  await waitForDone(page);
  const after = await pixelOf(soft, 8, 44);
  expect(after.reduce((a, b) => a + b)).toBeGreaterThan(before.reduce((a, b) => a + b));
});
