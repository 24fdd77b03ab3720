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
