// In front of a class: at a 1024×768 and a 1920×1080 projector, every sketch
// shows its picture and what explains the selected pixel (the panel or the
// diagram) at once, without scrolling; on the big screen the text, the
// pictures and the diagrams are bigger than at 1280×900. The pictures at
// 1280×900 (every other screenshot test) do not change with this.
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, expectQuietConsole, waitForDone } from './helpers.js';

expectQuietConsole(test);

const PANEL = ['[data-inspector] [data-answer]', '[data-inspector] .rt-color'];
/** Each sketch and what explains its selected pixel: the diagram, else the inspector's answer line and colour. */
const SKETCHES = [
  ['00-light-or-eye', PANEL],
  ['01-rays-through-pixels', ['#diagram canvas']],
  ['02-the-quadratic', ['#left canvas']],
  ['03-the-geometric-approach', ['#diagram canvas']],
  ['04-find-the-pink-pixel', ['[data-answer-line]', '[data-result]']],
  ['05-value-boxes', PANEL],
  ['06-lights-shadows-reflections', PANEL],
  ['07-original-examples', PANEL],
  ['08-homework-traffic-signal', PANEL],
  ['09-homework-rear-lights', PANEL],
  ['10-playground', PANEL],
];
const SIZES = [[1024, 768], [1920, 1080]];

/** The element's box, and whether it lies wholly inside the window (nothing scrolled). */
const inView = (locator) => locator.first().evaluate((el) => {
  const r = el.getBoundingClientRect();
  return { box: [Math.round(r.left), Math.round(r.top), Math.round(r.width), Math.round(r.height)], inside: r.width > 0 && r.left >= 0 && r.top >= 0 && r.right <= innerWidth && r.bottom <= innerHeight };
});

async function openAndSelect(page, file) {
  await page.goto(`/sketches/${file}.html`);
  await waitForDone(page);
  const view = page.locator('[data-tracer]').first();
  const w = Number(await view.getAttribute('data-width')), h = Number(await view.getAttribute('data-height'));
  await clickPixel(view, Math.floor(w / 2), Math.floor(h / 2));
  await page.evaluate(() => window.scrollTo(0, 0));
  return view;
}

for (const [width, height] of SIZES) {
  test.describe(`at ${width}×${height}`, () => {
    test.use({ viewport: { width, height } });

    for (const [file, explainers] of SKETCHES) {
      test(`${file}: the picture and what explains the selected pixel, together without scrolling`, async ({ page }) => {
        const view = await openAndSelect(page, file);
        // polled: the diagrams settle their size a frame after the picture is done
        await expect.poll(() => inView(view), { message: 'the picture' }).toMatchObject({ inside: true });
        for (const selector of explainers) await expect.poll(() => inView(page.locator(selector)), { message: selector }).toMatchObject({ inside: true });
      });
    }
  });
}

// One test per sketch (each opens it at three sizes), so that two workers share them.
for (const [file, diagram] of [['03-the-geometric-approach', '#diagram > canvas'], ['06-lights-shadows-reflections'], ['05-value-boxes']]) {
  test(`${file}: on a 1920 px screen the text${diagram ? ', the pictures and the diagrams' : ' and the pictures'} are bigger than at 1280 px; at 1024 px the text is not smaller`, async ({ page }) => {
    const measure = async () => {
      const view = await openAndSelect(page, file);
      return {
        rem: await page.evaluate(() => parseFloat(getComputedStyle(document.documentElement).fontSize)),
        label: await page.locator('h1').evaluate((h) => parseFloat(getComputedStyle(h).fontSize)),
        picture: (await view.boundingBox()).width,
        diagram: diagram ? (await page.locator(diagram).first().boundingBox()).width : 0,
      };
    };
    await page.setViewportSize({ width: 1280, height: 900 });
    const usual = await measure();
    expect(usual.rem).toBe(16);
    await page.setViewportSize({ width: 1920, height: 1080 });
    const big = await measure();
    expect(big.rem, file).toBeGreaterThan(20);
    expect(big.label / usual.label, file).toBeGreaterThan(1.25);
    expect(big.picture / usual.picture, file).toBeGreaterThan(1.2);
    if (diagram) expect(big.diagram / usual.diagram, file).toBeGreaterThan(1.2);
    await page.setViewportSize({ width: 1024, height: 768 });
    expect((await measure()).rem).toBe(16);
  });
}

test('the Projector switch makes the text bigger, keeps the panel beside the picture, and is remembered on the next page', async ({ page }) => {
  const view = await openAndSelect(page, '06-lights-shadows-reflections');
  const answerSize = () => page.locator('[data-inspector] [data-answer]').evaluate((a) => parseFloat(getComputedStyle(a).fontSize));
  const textBefore = await answerSize();
  await page.locator('[data-projector]').click();
  await expect(page.locator('[data-projector]')).toHaveAttribute('aria-pressed', 'true');
  expect(await answerSize()).toBeGreaterThan(textBefore * 1.2);
  await page.evaluate(() => window.scrollTo(0, 0));
  for (const el of [view, ...PANEL.map((s) => page.locator(s))]) await expect.poll(async () => (await inView(el)).inside).toBe(true);
  await openAndSelect(page, '04-find-the-pink-pixel');
  await expect(page.locator('[data-projector]')).toHaveAttribute('aria-pressed', 'true');
  await page.locator('[data-projector]').click();
  await expect(page.locator('html')).not.toHaveClass(/projector/);
});

// The traced canvas at both projector sizes: whole screen pixels per traced pixel, the picture unchanged.
for (const [width, height] of SIZES) {
  test.describe(`screenshots at ${width}×${height}`, () => {
    test.use({ viewport: { width, height } });
    for (const file of ['04-find-the-pink-pixel', '06-lights-shadows-reflections']) {
      test(`${file}: the picture at ${width}×${height}`, async ({ page }) => {
        await page.goto(`/sketches/${file}.html`);
        await waitForDone(page);
        await expectCanvasScreenshot(page.locator('[data-tracer]').first(), `${file}-${width}x${height}.png`);
      });
    }
  });
}
