// The gallery links every sketch; each reaches data-render="done" with no
// console errors, and each traced view matches its reference screenshot.
// A lesson page opened from a file (a built page double-clicked) cannot run
// its scripts: it says so, and what to run; served, it does not.
import { test, expect } from '@playwright/test';
import { mkdtempSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
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
    await expect(page.locator('.from-file')).toBeHidden(); // served: no word about files
    await expect(page.locator('h1')).toHaveText(new RegExp(`^${file.slice(0, 2)} · \\S`)); // "08 · Homework 1: …", as the title
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

for (const [what, path] of [['a lesson page', '/sketches/01-rays-through-pixels.html'], ['the gallery', '/']]) {
  test(`${what} opened from a file says why nothing traces, and what to run, in its own style`, async ({ page, baseURL }) => {
    const folder = mkdtempSync(join(tmpdir(), 'rt-from-file-'));
    try {
      // The page as the server sends it, saved and opened by double-click: its module script and stylesheets cannot load from there.
      const html = await (await page.request.get(`${baseURL}${path}`)).text();
      writeFileSync(join(folder, 'page.html'), html);
      await page.goto(pathToFileURL(join(folder, 'page.html')).href);
      const notice = page.locator('.from-file');
      await expect(notice).toBeVisible();
      await expect(notice).toContainText('opened from a file');
      await expect(notice).toContainText('npm run preview');
      // Its style is inline: a framed box, not bare text among the page's.
      expect(await notice.evaluate((e) => { const s = getComputedStyle(e); return [s.borderTopStyle, s.borderTopWidth, s.borderTopColor]; }))
        .toEqual(['solid', '2px', 'rgb(214, 51, 108)']);
      await expect(page.locator('[data-tracer]')).toHaveCount(0);
    } finally {
      rmSync(folder, { recursive: true, force: true });
    }
  });
}
