// Rendering over Web Workers in a real browser: the picture of 1, 2 and 3
// workers is the single-threaded picture, byte for byte, every row present.
import { test, expect } from '@playwright/test';
import { watchConsole, waitForDone } from './helpers.js';

test('workers render the class scene exactly as the main thread does', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/tests/e2e/pages/workers.html');
  await waitForDone(page);
  expect(await page.evaluate(() => window.workersAvailable)).toBe(true);
  const results = await page.evaluate(() => window.results);
  expect(results.error).toBeUndefined();
  expect(results).toHaveLength(6);
  for (const r of results) {
    expect(r.length, `${r.name}, ${r.workers} worker(s)`).toBe(r.expectedLength);
    expect(r.differing, `${r.name}, ${r.workers} worker(s): bytes that differ`).toBe(0);
    expect(r.everyRowOnce, `${r.name}, ${r.workers} worker(s): every row arrived once`).toBe(true);
  }
  expect(errors).toEqual([]);
});

// Sketch 07's workers example when the workers let it down: it must neither
// hang nor go blank, but say why and trace its frames on the page's thread.
const SKETCH_07 = '/sketches/07-original-examples.html?example=workers';
const frameShown = (page) => page.locator('[data-stats]').evaluate((el) => Number(el.dataset.frame ?? 0));

/** Bytes of the paused canvas that differ from render() of the frame's moment on this thread. */
const canvasVersusRender = (page) => page.evaluate(async () => {
  const { render } = await import('/lib/render.js');
  const c = document.querySelector('[data-tracer]');
  const shown = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  const expected = render(window.sketch.sceneAt(Number(document.querySelector('[data-stats]').dataset.time)), window.sketch.camera);
  let differ = Math.abs(shown.length - expected.length);
  for (let i = 0; i < Math.min(shown.length, expected.length); i++) if (shown[i] !== expected[i]) differ++;
  return { differ, length: shown.length };
});

async function fallsBackToTheMainThread(page, message) {
  await expect(page.locator('[data-message="example"]')).toHaveText(message, { timeout: 30_000 });
  await expect(page.locator('[data-stats]')).toHaveText(/· main thread$/);
  const before = await frameShown(page);
  await expect.poll(() => frameShown(page), { timeout: 30_000 }).toBeGreaterThan(before + 1); // frames go on
  await page.locator('[data-pause]').click();
  await waitForDone(page);
  expect(await canvasVersusRender(page)).toEqual({ differ: 0, length: 320 * 240 * 4 });
}

test('sketch 07: a worker that never answers is given up on with a message, and the frames go on on the main thread', async ({ page }) => {
  test.slow();
  const errors = watchConsole(page);
  await page.route('**/render-worker.js*', (route) => route.fulfill({ contentType: 'text/javascript', body: 'self.onmessage = () => {};' }));
  await page.goto(SKETCH_07);
  await expect(page.locator('body')).toHaveAttribute('data-render', 'rendering');
  await fallsBackToTheMainThread(page, /^render worker \d did not answer within 6 s; rendering on the main thread instead$/);
  expect(errors).toEqual([]);
});

test('sketch 07: a worker that fails to start: a message, and the frames are traced on the main thread', async ({ page }) => {
  test.slow();
  await page.route('**/render-worker.js*', (route) => route.fulfill({ status: 404, contentType: 'text/plain', body: 'gone' }));
  await page.goto(SKETCH_07);
  await fallsBackToTheMainThread(page, /^render worker \d failed \(.+\); rendering on the main thread instead$/);
});
