// The tasks of pages 10–14, done as a student does them (clicks and choices), each seen ticked off,
// and counted in the gallery. The predicates themselves are tested in Node (tests/unit/lesson-tasks.test.js).
import { test, expect } from '@playwright/test';
import { clickPixel, expectQuietConsole, waitForDone } from './helpers.js';

expectQuietConsole(test);

const task = (page, id) => page.locator(`[data-task="${id}"]`);
const expectDone = (page, id) => expect(task(page, id), id).toHaveAttribute('data-done', 'true');
const expectNotDone = (page, id) => expect(task(page, id), id).toHaveAttribute('data-done', 'false');

async function open(page, path, count) {
  await page.goto(path);
  await waitForDone(page);
  await expect(page.locator('[data-tasks] ol > li[data-task]')).toHaveCount(count);
  for (const item of await page.locator('[data-task]').all()) await expect(item).toHaveAttribute('data-done', 'false'); // the page's own selection does none
}

test('10: the playground\'s tasks, the first by a click', async ({ page }) => {
  await open(page, '/sketches/10-playground.html', 4);
  await clickPixel(page.locator('[data-tracer]'), 32, 24);
  await expectDone(page, 'select');
  await expectNotDone(page, 'own'); // the starter's sphere is not one of the student's own
  await expect(page.locator('[data-task-strip]')).toHaveText('Tasks: 1 of 4 done');
});

test('11: an edge pixel, then 16 rays and 1 ray per pixel', async ({ page }) => {
  await open(page, '/sketches/11-several-rays-per-pixel.html', 3);
  const smooth = page.locator('[data-tracer]').nth(1);
  await clickPixel(smooth, 32, 24); // the middle of the pink sphere: every ray hits it
  await expectNotDone(page, 'edge');
  await clickPixel(smooth, 31, 5);
  await expectDone(page, 'edge');
  await page.getByRole('radio', { name: '16' }).check();
  await expectDone(page, 'sixteen');
  await expectNotDone(page, 'one');
  await page.getByRole('radio', { name: '1', exact: true }).check();
  await expectDone(page, 'one');
  await expect(page.locator('[data-task-status]')).toContainText('every task of this page');
});

test('12: the cylinder\'s side, the cone, the triangle and a ray just beside it', async ({ page }) => {
  await open(page, '/sketches/12-cylinders-cones-triangles.html', 4);
  const view = page.locator('[data-tracer]');
  await clickPixel(view, 34, 14);
  await expectDone(page, 'cone');
  // No spheres in this scene: the panel shows the other shapes' tests, not two empty sphere tables.
  await expect(page.locator('[data-inspector]')).toContainText('Other shapes');
  await expect(page.locator('[data-inspector]')).not.toContainText('No spheres');
  await expectNotDone(page, 'side');
  await clickPixel(view, 8, 20);
  await expectDone(page, 'side');
  await clickPixel(view, 56, 20);
  await expectDone(page, 'triangle');
  await expectNotDone(page, 'beside');
  await clickPixel(view, 52, 20);
  await expectDone(page, 'beside');

  await page.goto('/');
  await expect(page.locator('a[href$="12-cylinders-cones-triangles.html"] [data-progress]')).toHaveText('4 of 4');
  await expect(page.locator('[data-achievement="page-12"]')).toContainText('Cylinders, cones and triangles');
});

test('13: the bunny, a ray its boxes let in that misses it, a ray no box let in, its shadow', async ({ page }) => {
  await open(page, '/sketches/13-meshes-and-a-bvh.html', 4);
  const view = page.locator('[data-tracer]');
  await clickPixel(view, 184, 16);
  await expectDone(page, 'bunny');
  await expect(page.locator('[data-inspector]')).toContainText('a loop would test');
  await expect(page.locator('[data-inspector]')).not.toContainText('No spheres');
  await clickPixel(view, 176, 16);
  await expectDone(page, 'loose');
  await expectNotDone(page, 'skip');
  await clickPixel(view, 0, 0);
  await expectDone(page, 'skip');
  await clickPixel(view, 296, 192);
  await expectDone(page, 'shadow');
});

test('14: the penumbra, the full shadow, outside the spot\'s cone, and the disc with one shadow ray', async ({ page }) => {
  await open(page, '/sketches/14-spot-and-area-lights.html', 4);
  const soft = page.locator('[data-tracer]').nth(1);
  await clickPixel(soft, 64, 21);
  await expectDone(page, 'penumbra');
  await expectNotDone(page, 'umbra');
  await clickPixel(soft, 66, 27);
  await expectDone(page, 'umbra');
  await clickPixel(soft, 0, 4);
  await expectDone(page, 'cone');
  await page.locator('#samples').getByRole('radio', { name: '1', exact: true }).check();
  await waitForDone(page);
  await expectNotDone(page, 'one-ray'); // a pixel must be selected under the new disc
  await clickPixel(soft, 0, 70);
  await expectDone(page, 'one-ray');
});
