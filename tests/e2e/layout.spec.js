// Pages that fit the room. On a 1024×768 and a 1920×1080 projector (and in
// Projector at 1024) no sketch scrolls sideways and the answer line is one
// line; at 1920×1080 every picture takes at least a third of the window's
// width or half its height. At 320 CSS px (a phone, a page zoomed to 400%,
// WCAG 1.4.10) no page scrolls sideways, and a picture scaled down to fit
// still maps a click to the right traced pixel.
import { test, expect } from '@playwright/test';
import { readdirSync } from 'node:fs';
import { clickPixel, expectQuietConsole, sharedPage, waitForDone } from './helpers.js';

const SKETCHES = readdirSync(new URL('../../sketches/', import.meta.url)).filter((f) => f.endsWith('.html')).sort();
const PAGES = ['/', ...SKETCHES.map((f) => `/sketches/${f}`), '/web-editor.html', '/teacher.html', '/api/'];
const PROJECTOR_KEY = 'raytracing-sketchbook:projector';

/** How far the page reaches past the window's right edge, in CSS px (0: no sideways scrolling). */
const overflow = (page) => page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);

/** Opens a sketch, waits for its pictures and selects the middle pixel of its tracer view (not the photons' picture). */
async function openAndSelect(page, path) {
  await page.goto(path);
  await waitForDone(page);
  const view = page.locator('[data-tracer]:not([data-photons])').first();
  const w = Number(await view.getAttribute('data-width')), h = Number(await view.getAttribute('data-height'));
  await clickPixel(view, Math.floor(w / 2), Math.floor(h / 2));
  await waitForDone(page);
}

/** Each inspector's answer line: its text, how many lines it takes, and whether its text is cut off. */
const answerLines = (page) => page.locator('[data-inspector] [data-answer]').evaluateAll((lines) => lines.map((a) => {
  const style = getComputedStyle(a);
  return { text: a.textContent, lines: Math.round(a.getBoundingClientRect().height / parseFloat(style.lineHeight)), cut: a.scrollWidth > a.clientWidth + 1 };
}));

async function expectFits(page) {
  expect(await overflow(page), 'px past the right edge').toBe(0);
  const answers = await answerLines(page);
  expect(answers.length, 'answer lines').toBeGreaterThan(0);
  for (const a of answers) {
    expect(a.text).toMatch(/^Pixel: \d+,\d+; H: -?\d+(\.\d)?; V: -?\d+(\.\d)?$/);
    expect(a, a.text).toMatchObject({ lines: 1, cut: false });
  }
  // The progress line's words are all there (they wrap in a narrow bar, never cut off).
  const progress = await page.locator('[data-progress-text]').evaluateAll((lines) => lines.map((l) => ({ text: l.textContent, cut: l.scrollWidth > l.clientWidth + 1 })));
  for (const line of progress) expect(line, line.text).toMatchObject({ cut: false });
}

// Each sketch at each size in one serial group with one page: opened again at
// each size (laid out as it opens there), its scripts from the context's cache.
for (const file of SKETCHES) {
  test.describe(file, () => {
    const shared = sharedPage(test);

    for (const [width, height] of [[1024, 768], [1920, 1080]]) {
      test(`at ${width}×${height}: no sideways scrolling, the answer line on one line${width === 1920 ? ', pictures grown into the room' : ''}`, async () => {
        const { page } = shared;
        await page.setViewportSize({ width, height });
        await openAndSelect(page, `/sketches/${file}`);
        await expectFits(page);
        if (width !== 1920) return;
        const sizes = await page.locator('[data-tracer]').evaluateAll((views) => views.map((v) => v.getBoundingClientRect()).map((r) => [Math.round(r.width), Math.round(r.height)]));
        expect(sizes.length).toBeGreaterThan(0);
        for (const [w, h] of sizes) expect(w >= width / 3 || h >= height / 2, `a ${w}×${h} picture: at least ${width / 3} px wide or ${height / 2} px tall`).toBe(true);
      });
    }

    test('at 320 CSS px wide: does not scroll sideways, the answer line too', async () => {
      const { page } = shared;
      await page.setViewportSize({ width: 320, height: 640 });
      await openAndSelect(page, `/sketches/${file}`);
      await expectFits(page);
    });

    test('in Projector at 1024×768: no sideways scrolling, the answer line on one line', async () => {
      const { page } = shared;
      await page.setViewportSize({ width: 1024, height: 768 });
      await page.evaluate((key) => localStorage.setItem(key, '1'), PROJECTOR_KEY); // the switch remembered, before the page opens
      await openAndSelect(page, `/sketches/${file}`);
      await expect(page.locator('html')).toHaveClass(/projector/);
      await expectFits(page);
    });
  });
}

test.describe('in Projector at 1024×768', () => {
  test.use({ viewport: { width: 1024, height: 768 } });
  test.beforeEach(({ page }) => page.addInitScript((key) => localStorage.setItem(key, '1'), PROJECTOR_KEY));
  expectQuietConsole(test);

  test('04: the activity and its answer panel stay beside the picture', async ({ page }) => {
    await openAndSelect(page, '/sketches/04-find-the-pink-pixel.html');
    const picture = await page.locator('[data-tracer]').boundingBox();
    for (const selector of ['#activity', '[data-inspector]']) {
      const box = await page.locator(selector).boundingBox();
      expect(box.x, `${selector} right of the picture`).toBeGreaterThanOrEqual(picture.x + picture.width);
    }
  });
});

test.describe('at 320 CSS px wide', () => {
  test.use({ viewport: { width: 320, height: 640 } });
  expectQuietConsole(test);

  for (const path of PAGES.filter((p) => !p.startsWith('/sketches/'))) { // the sketches: in their groups above
    test(`${path} does not scroll sideways`, async ({ page }) => {
      await page.goto(path);
      await page.waitForLoadState('load');
      expect(await overflow(page), 'px past the right edge').toBe(0);
    });
  }

  // 01's 32×24 picture at 9 screen px per pixel (16 on a wide screen); 05's 160×120 at 1.8.
  for (const [file, x, y] of [['01-rays-through-pixels', 20, 7], ['05-value-boxes', 101, 59]]) {
    test(`${file}: the picture scaled down to fit still selects the pixel clicked`, async ({ page }) => {
      await page.goto(`/sketches/${file}.html`);
      await waitForDone(page);
      const view = page.locator('[data-tracer]').first();
      const box = await view.boundingBox();
      const w = Number(await view.getAttribute('data-width'));
      expect(box.width, 'the picture fits the page').toBeLessThanOrEqual(288);
      expect(box.width / w, 'screen px per traced pixel').toBeLessThan(file.startsWith('01') ? 16 : 3);
      await clickPixel(view, x, y);
      await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(new RegExp(`^Pixel: ${x},${y};`));
    });
  }
});
