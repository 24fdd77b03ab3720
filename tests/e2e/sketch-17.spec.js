// Sketch 17, One weekend's final scene: the book's last picture, small, path
// traced under a sky with no lamp; the picture at its fixed 64 samples is the
// reference; its tasks tick as a student does them (the big glass ball, a path
// through glass, a fuzzy metal ball, polished ones, the sky).
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';

const PAGE = '/sketches/17-one-weekend.html';
const DONE = 90_000; // 64 paths a pixel through 90 balls on the page's thread: seconds, more on a busy machine
/** Pixels of the 90 × 60 picture (found with inspectPixel): the middle of each kind of thing. */
const GLASS = [35, 15], FUZZY_METAL = [40, 36], SKY = [70, 4];

test('the sample count grows live to 64; the picture is the reference; the sky lights the balls', async ({ page }) => {
  test.setTimeout(150_000);
  const errors = watchConsole(page);
  await page.goto(PAGE);
  const progress = page.locator('[data-progress-text]');
  await waitForDone(page, DONE);
  await expect(progress).toHaveText(/^Sample 64 of 64 · .+ paths\/s$/);
  const view = page.locator('[data-tracer]');
  await expect(view).toHaveAttribute('data-width', '90');
  await expectCanvasScreenshot(view, 'one-weekend-64.png');
  // The sky, at the top: its gradient's blue, brighter than any ball's shadow on the ground.
  const sky = await view.evaluate((c, [x, y]) => [...c.getContext('2d').getImageData(x, y, 1, 1).data.slice(0, 3)], SKY);
  expect(sky[2]).toBeGreaterThan(sky[0]);
  expect(errors).toEqual([]);
});

test('the tasks: the big glass ball, a path through glass, a fuzzy metal ball, polished ones, the sky', async ({ page }) => {
  test.setTimeout(200_000);
  const errors = watchConsole(page);
  await page.goto(PAGE);
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await waitForDone(page, DONE);
  const view = page.locator('[data-tracer]');
  const done = (id) => expect(page.locator(`[data-task="${id}"]`)).toHaveAttribute('data-done', 'true');
  await expect(page.locator('[data-task="glass"]')).not.toHaveAttribute('data-done', 'true'); // the ground is selected first

  await clickPixel(view, ...SKY);
  await done('sky');
  await clickPixel(view, ...GLASS);
  await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(/^Pixel: 35,15;/);
  await done('glass');
  const panel = page.locator('[data-path-inspector]');
  await expect(panel.locator('[data-bounce="0"] [data-field="surface"]')).toHaveText('big glass ball');
  for (let n = 0; n < 30 && !(await panel.locator('tbody').textContent()).includes('glass, through'); n++) {
    await panel.getByRole('button', { name: 'Next sample →' }).click();
  }
  await done('through');

  await clickPixel(view, ...FUZZY_METAL);
  await done('fuzzy');
  await expect(page.locator('[data-task="polished"]')).not.toHaveAttribute('data-done', 'true');
  await page.getByRole('radio', { name: /^polished/ }).check();
  await waitForDone(page, DONE);
  await clickPixel(view, ...SKY); // elsewhere, then back to the same ball, now polished
  await clickPixel(view, ...FUZZY_METAL);
  await done('polished');
  await expect(page.locator('[data-task-strip]')).toHaveText(/5 of 5 done/);
  expect(errors).toEqual([]);
});
