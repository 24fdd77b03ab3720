// Sketch 13, meshes and a BVH: the bunny traced on the render workers; a click on it
// counts its ray's box and triangle tests, far fewer than the 3,674 of a loop over every
// triangle; a click on the sky says the ray missed the root box; the BVH in 3D.
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';

test('the bunny is traced, and a click counts its ray\'s walk down the BVH', async ({ page }) => {
  const errors = watchConsole(page);
  const workers = [];
  page.on('worker', (worker) => workers.push(worker.url()));
  await page.goto('/sketches/13-meshes-and-a-bvh.html');
  await waitForDone(page);
  expect(workers.length).toBeGreaterThan(0); // traced on Web Workers
  const view = page.locator('[data-tracer]');
  await expectCanvasScreenshot(view, 'bunny.png');

  const counts = page.locator('[data-bvh-counts]');
  await expect(counts).toHaveText(/^Pixel 200,150: the ray tested \d+ boxes and \d+ triangles?, and hit triangle \d+; a loop over every triangle: 3,674 tests\.$/);
  const [boxes, triangles] = (await counts.textContent()).match(/tested (\d+) boxes and (\d+)/).slice(1).map(Number);
  expect(boxes).toBeGreaterThan(1);
  expect(boxes + triangles).toBeLessThan(3674 / 10); // much less than the loop
  const bvh = page.locator('[data-bvh-view]');
  await expect(bvh).toHaveAttribute('aria-label', /the \d+ boxes the ray of pixel 200,150 entered and the triangle it hit/);
  await expectCanvasScreenshot(bvh, 'bvh.png');

  await clickPixel(view, 10, 10); // the sky, above the bunny
  await expect(counts).toHaveText('Pixel 10,10: the ray missed the root box: 1 box test, no triangle tested; a loop over every triangle: 3,674 tests.');
  await expect(bvh).toHaveAttribute('aria-label', /the ray of pixel 10,10 misses the root box\.$/);

  // keyboard: the depth slider and the arrows turn the view (its label follows what it draws)
  await page.locator('#rt-bvh-depth').fill('1');
  await expect(bvh).toHaveAttribute('aria-label', /^The bunny's bounding volume hierarchy in 3D: 2 boxes at depth 1 of \d+/);
  const before = await bvh.evaluate((c) => c.toDataURL());
  await bvh.focus();
  await page.keyboard.press('ArrowLeft');
  expect(await bvh.evaluate((c) => c.toDataURL())).not.toBe(before);
  expect(errors).toEqual([]);
});
