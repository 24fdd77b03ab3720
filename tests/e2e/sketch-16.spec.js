// Sketch 16, light that bounces: a Cornell box by Whitted's tracer beside a
// path tracer whose sample count grows live; the path-traced picture at its
// fixed 128 samples is the reference; light sampling on and off, its noise measured; a pixel's path listed bounce by bounce,
// its mean the picture's bytes; 1 bounce darkens the room; the tasks tick.
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';

const PAGE = '/sketches/16-light-that-bounces.html';
const DONE = 60_000; // 128 paths a pixel on the page's thread, light sampled: a few seconds, more on a busy machine

/** Pixel (x, y) of a tracer canvas as bytes [r, g, b]. */
const pixelOf = (canvas, x, y) => canvas.evaluate((c, [px, py]) => [...c.getContext('2d').getImageData(px, py, 1, 1).data.slice(0, 3)], [x, y]);
/** Every byte of a canvas's picture, summed over r, g and b. */
const brightness = (canvas) => canvas.evaluate((c) => c.getContext('2d').getImageData(0, 0, c.width, c.height).data.reduce((sum, v, i) => sum + (i % 4 === 3 ? 0 : v), 0));

test('the sample count grows live to 128; both pictures are the references; the path tracer lights the ceiling Whitted leaves black', async ({ page }) => {
  test.setTimeout(120_000);
  const errors = watchConsole(page);
  await page.goto(PAGE);
  const progress = page.locator('[data-progress-text]').nth(1);
  await expect(progress).toHaveText(/^Sample ([1-9]|[1-9]\d) of 128 · /, { timeout: DONE }); // an early sample: the picture shown already
  await waitForDone(page, DONE);
  await expect(progress).toHaveText(/^Sample 128 of 128 · .+ paths\/s$/);
  const [whitted, paths] = [page.locator('[data-tracer]').nth(0), page.locator('[data-tracer]').nth(1)];
  await expectCanvasScreenshot(whitted, 'whitted.png');
  await expectCanvasScreenshot(paths, 'paths-128.png');
  // The ceiling, above the lamp's edge: no light reaches it straight, only by bounces.
  const [w, p] = [await pixelOf(whitted, 32, 1), await pixelOf(paths, 32, 1)];
  expect(w[0] + w[1] + w[2]).toBeLessThan(60); // the ambient term alone
  expect(p[0] + p[1] + p[2]).toBeGreaterThan(2 * (w[0] + w[1] + w[2]));
  expect(errors).toEqual([]);
});

test('a pixel\'s path, bounce by bounce; its mean × 255 is the picture\'s byte; the next sample is another path', async ({ page }) => {
  test.setTimeout(120_000);
  await page.goto(PAGE);
  await waitForDone(page, DONE);
  const paths = page.locator('[data-tracer]').nth(1);
  await clickPixel(paths, 12, 58); // the floor by the red wall
  await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(/^Pixel: 12,58;/);
  const panel = page.locator('[data-path-inspector]');
  await expect(panel.locator('caption')).toHaveText(/^Sample 0 of pixel 12,58: \d+ hits?$/);
  await expect(panel.locator('[data-bounce="0"] [data-field="surface"]')).toHaveText('floor');
  await expect(panel.locator('[data-bounce="0"] [data-field="lobe"]')).toHaveText(/^diffuse/);
  // Its light sample: the lamp aimed at from the floor, seen (with its MIS weight) or blocked by a named shape.
  await expect(panel.locator('[data-bounce="0"] [data-field="light"]')).toHaveText(/^lamp at \(.+\): (seen, pdf .+, MIS weight .+, added \(|blocked by |behind the surface)/);
  await expect(panel.locator('[data-field="end"]')).toHaveText(/^Then the path (left the scene|was absorbed|was ended by Russian roulette|stopped)/);
  await expect(panel.locator('[data-field="estimate"]')).toHaveText(/^The pixel after 128 samples: mean \(/);
  const mean = (await panel.locator('[data-field="estimate"]').getAttribute('data-value')).split(' ').map(Number);
  expect(mean.map((m) => Math.min(255, Math.max(0, Math.round(m * 255))))).toEqual(await pixelOf(paths, 12, 58));
  await expect(panel.locator('[data-field="chart"]')).toHaveAttribute('aria-label', /after each of 128 samples/);
  // The 3D view draws the same path: a segment from the eye to the first hit, then one a bounce.
  const hits = Number((await panel.locator('caption').textContent()).match(/(\d+) hits?$/)[1]);
  const view3d = page.locator('[data-view3d]');
  await expect(view3d).toHaveAttribute('data-selected', '12,58');
  const toSky = /left the scene/.test(await panel.locator('[data-field="end"]').textContent()) ? 1 : 0; // one more segment toward the sky
  await expect(view3d).toHaveAttribute('data-extra-rays', String(hits + toSky));
  const first = await panel.locator('tbody').textContent();
  await panel.getByRole('button', { name: 'Next sample →' }).click();
  await expect(panel.locator('caption')).toHaveText(/^Sample 1 of pixel 12,58:/);
  expect(await panel.locator('tbody').textContent()).not.toBe(first);
  // Arrow keys move the selection; the panel follows.
  await paths.focus();
  await page.keyboard.press('ArrowRight');
  await expect(panel.locator('caption')).toHaveText(/^Sample 0 of pixel 13,58:/);
});

test('1 bounce: direct light only, a darker room; the tasks tick as they are done', async ({ page }) => {
  test.setTimeout(150_000);
  await page.goto(PAGE);
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await waitForDone(page, DONE);
  const paths = page.locator('[data-tracer]').nth(1);
  const many = await brightness(paths);
  await clickPixel(paths, 10, 60); // after the picture is whole: the floor by the red wall is redder than Whitted's
  await expect(page.locator('[data-task="path"]')).toHaveAttribute('data-done', 'true');
  await expect(page.locator('[data-task="bleed"]')).toHaveAttribute('data-done', 'true');
  await expect(page.locator('[data-task="settled"]')).toHaveAttribute('data-done', 'true');
  await page.getByRole('radio', { name: /^1 bounce/ }).check();
  await waitForDone(page, DONE);
  await expect(page.locator('[data-task="direct"]')).toHaveAttribute('data-done', 'true');
  expect(await brightness(paths)).toBeLessThan(many * 0.85);
  await expect(page.locator('[data-path-inspector] tbody tr')).toHaveCount(2); // the floor, then where its one bounce went
});

test('light sampling is a toggle: off, the same 128 samples leave more noise, measured under the buttons', async ({ page }) => {
  test.setTimeout(150_000);
  await page.goto(PAGE);
  const noise = page.locator('[data-noise]');
  await expect(noise).toHaveText(/^Noise left: \d\.\d{4} after 128 samples \(light sampling on\)$/, { timeout: DONE });
  const on = Number(await noise.getAttribute('data-value'));
  const toggle = page.getByRole('button', { name: 'Light sampling' });
  await expect(toggle).toHaveAttribute('aria-pressed', 'true');
  await toggle.focus();
  await page.keyboard.press('Space'); // by keyboard
  await expect(toggle).toHaveAttribute('aria-pressed', 'false');
  await expect(noise).toHaveText(/^Noise left: \d\.\d{4} after 128 samples \(light sampling off\)$/, { timeout: DONE });
  const off = Number(await noise.getAttribute('data-value'));
  expect(off).toBeGreaterThan(1.5 * on);
  await page.keyboard.press('Enter');
  await expect(toggle).toHaveAttribute('aria-pressed', 'true');
});
