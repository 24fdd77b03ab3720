// The gallery links every sketch; each reaches data-render="done" with no
// console errors, and each traced view matches its reference screenshot.
import { test, expect } from '@playwright/test';
import { readdirSync } from 'node:fs';
import { expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';

const sketchPages = readdirSync('sketches').filter((f) => f.endsWith('.html')).sort();

test('the gallery links every sketch, in lesson order, with no console errors', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/');
  const hrefs = await page.locator('a[href*="sketches/"]').evaluateAll((as) => as.map((a) => a.getAttribute('href')));
  const linked = hrefs.map((h) => h.split('/').pop().split('?')[0]);
  expect(linked).toEqual(sketchPages);
  expect(errors).toEqual([]);
});

for (const file of sketchPages) {
  test(`${file} renders, with no console errors`, async ({ page }) => {
    const errors = watchConsole(page);
    await page.goto(`/sketches/${file}`);
    await waitForDone(page);
    const views = page.locator('[data-tracer]');
    const count = await views.count();
    expect(count).toBeGreaterThan(0);
    for (let i = 0; i < count; i++) {
      const view = views.nth(i);
      expect(Number(await view.getAttribute('data-width'))).toBeGreaterThan(0);
      await expectCanvasScreenshot(view, `${file.replace('.html', '')}-view${i}.png`);
    }
    expect(errors).toEqual([]);
  });
}
