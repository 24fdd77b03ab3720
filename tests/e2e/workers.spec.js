// Rendering over Web Workers in a real browser: the picture of 1, 2 and 3
// workers is the single-threaded picture, byte for byte, every row present
// (a path-traced frame too: pathTrace's bytes on any number of workers).
import { test, expect } from '@playwright/test';
import { watchConsole, waitForDone } from './helpers.js';

test('workers render the class scene, and cylinders, cones, triangles and a mesh, traced and path traced, exactly as the main thread does', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/tests/e2e/pages/workers.html');
  await waitForDone(page);
  expect(await page.evaluate(() => window.workersAvailable)).toBe(true);
  const results = await page.evaluate(() => window.results);
  expect(results.error).toBeUndefined();
  expect(results).toHaveLength(12); // four frames, each on 1, 2 and 3 workers
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
  const { render } = await import('/lib/tracing/render.js');
  const c = document.querySelector('[data-tracer]');
  const shown = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  const expected = render(window.sketch.sceneAt(Number(document.querySelector('[data-stats]').dataset.time)), window.sketch.camera);
  let differ = Math.abs(shown.length - expected.length);
  for (let i = 0; i < Math.min(shown.length, expected.length); i++) if (shown[i] !== expected[i]) differ++;
  return { differ, length: shown.length };
});

/** Serves a worker that loads, takes its jobs and never answers (with the headers a cross-origin isolated page needs of a worker). */
const silentWorker = (route) => route.fulfill({
  contentType: 'text/javascript', body: 'self.postMessage({ ready: true }); self.onmessage = () => {};', // loads, then never answers
  headers: { 'Cross-Origin-Embedder-Policy': 'require-corp', 'Cross-Origin-Resource-Policy': 'same-origin' },
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
  await page.route('**/render-worker.js*', silentWorker);
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

// A tracer view of a large frame: coarse passes on the page's thread, the rest on workers.
test('a 640×480 tracer view: coarse previews first, the rest from the workers, render()\'s bytes, and again after a change', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/tests/e2e/pages/tracer-workers.html');
  await waitForDone(page);
  expect(await page.evaluate(() => crossOriginIsolated)).toBe(true); // the dev server's headers: workers share one frame
  for (let round = 0; round < 2; round++) {
    const steps = await page.evaluate(() => window.steps.splice(0));
    expect(steps.every((s) => s.usingWorkers)).toBe(true);
    expect(steps[0].progress).toBeGreaterThan(0); // the first frame shows something: coarse blocks (or, on a fast day, workers' rows over them)
    expect(steps.at(-1)).toMatchObject({ done: true, progress: 1, pass: 1 });
    for (let i = 1; i < steps.length; i++) expect(steps[i].pass).toBeLessThanOrEqual(steps[i - 1].pass); // coarse to fine
    expect(await page.evaluate(() => window.differing())).toBe(0);
    await expect(page.locator('[data-progress-text]')).toHaveText(/^100% · /);
    await expect(page.locator('[data-message="view-workers"]')).toBeHidden(); // nothing to say when the workers work
    await page.evaluate(() => window.view.setScene(window.classSceneAt(2))); // the page says "rendering" from here on
    await waitForDone(page);
  }
  expect(errors).toEqual([]);
});

// A tracer view whose workers fail says so in a quiet note (never the mistake panel) and finishes the picture itself.
const workerNote = (page) => page.locator('[data-message="view-workers"]');

async function finishedOnThePage(page, reason, timeout) {
  await waitForDone(page, timeout);
  expect(await page.evaluate(() => window.differing())).toBe(0);
  await expect(workerNote(page)).toBeVisible();
  await expect(workerNote(page)).toHaveText(new RegExp(`^Workers unavailable: rendering on the page's thread instead — ${reason}\\.$`));
  await expect(page.locator('[data-error]')).toBeHidden();
  // The next frame is traced here from the start, and the note stays.
  await page.evaluate(() => window.view.setScene(window.classSceneAt(2)));
  await waitForDone(page, timeout);
  expect(await page.evaluate(() => [window.view.renderer.usingWorkers, window.differing()])).toEqual([false, 0]);
  await expect(workerNote(page)).toBeVisible();
}

test('a 640×480 tracer view whose workers never answer: the page finishes the picture itself, the same bytes, and says why', async ({ page }) => {
  test.slow();
  await page.route('**/render-worker.js*', silentWorker);
  await page.goto('/tests/e2e/pages/tracer-workers.html');
  await finishedOnThePage(page, 'render worker \\d did not answer within 6 s', 40_000);
  expect(await page.evaluate(() => window.view.renderer.problem)).toMatch(/^render worker \d did not answer within 6 s$/);
});

test('a 640×480 tracer view whose worker script is missing (404): a note, and render()\'s bytes traced on the page', async ({ page }) => {
  await page.route('**/render-worker.js*', (route) => route.fulfill({ status: 404, contentType: 'text/plain', body: 'gone' }));
  await page.goto('/tests/e2e/pages/tracer-workers.html');
  await finishedOnThePage(page, 'render worker \\d failed \\(.+\\)');
});

test('a 640×480 tracer view on a page that may start no worker: a note, and render()\'s bytes traced on the page', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/tests/e2e/pages/tracer-workers.html?worker=throw');
  await finishedOnThePage(page, 'render workers could not start \\(Web Workers are not allowed on this page\\)');
  expect(errors).toEqual([]);
});
