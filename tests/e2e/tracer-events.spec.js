// What a tracer view tells its listeners (view.on('select' | 'restart' |
// 'progress')), and its render order under one name, the old one still working.
import { test, expect } from '@playwright/test';
import { clickPixel, expectQuietConsole, waitForDone } from './helpers.js';

const PAGE = '/tests/e2e/pages/inspector.html';
expectQuietConsole(test);

test('select, restart and progress reach their listeners until removed', async ({ page }) => {
  await page.goto(PAGE);
  await waitForDone(page);
  await page.evaluate(() => {
    window.heard = [];
    const { view } = window;
    window.stops = [
      view.on('select', (pixel) => window.heard.push(['select', pixel])),
      view.on('restart', (v) => window.heard.push(['restart', v === view, v.progress])),
      view.on('progress', ({ progress, done }) => window.heard.push(['progress', progress, done])),
    ];
  });
  await clickPixel(page.locator('[data-tracer]'), 10, 12);
  expect(await page.evaluate(() => window.heard)).toEqual([['select', { x: 10, y: 12 }]]);
  await page.evaluate(() => window.view.setMode('discriminant'));
  await waitForDone(page);
  const heard = await page.evaluate(() => window.heard);
  expect(heard[1]).toEqual(['restart', true, 0]);
  expect(heard[2]).toEqual(['select', { x: 10, y: 12 }]); // its story changed
  const progress = heard.filter(([name]) => name === 'progress');
  expect(progress.length).toBeGreaterThan(0);
  expect(progress.at(-1)).toEqual(['progress', 1, true]);
  for (let i = 1; i < progress.length; i++) expect(progress[i][1]).toBeGreaterThanOrEqual(progress[i - 1][1]);
  const count = heard.length;
  await page.evaluate(() => { for (const stop of window.stops) stop(); window.view.restart(); });
  await waitForDone(page);
  expect(await page.evaluate(() => window.heard.length)).toBe(count);
  expect(await page.evaluate(() => { try { window.view.on('selected', () => {}); } catch (e) { return e.message; } })).toMatch(/^on\(\) takes one of 'select', 'restart', 'progress'/);
});

test('the render order is order / setOrder; renderMode / setRenderMode still work', async ({ page }) => {
  await page.goto(`${PAGE}?render=scanline`); // the page passes renderMode, the old name
  await waitForDone(page);
  expect(await page.evaluate(() => [window.view.order, window.view.renderMode])).toEqual(['scanline', 'scanline']);
  expect(await page.evaluate(() => window.view.current)).toEqual({ x: 63, y: 47 }); // the last pixel traced
  await page.evaluate(() => window.view.setOrder('coarse'));
  expect(await page.evaluate(() => [window.view.order, window.view.current])).toEqual(['coarse', null]);
  await page.evaluate(() => window.view.setRenderMode('slow'));
  expect(await page.evaluate(() => window.view.order)).toBe('slow');
  const message = (method) => page.evaluate((m) => { try { window.view[m]('fast'); } catch (e) { return e.message; } return null; }, method);
  expect(await message('setOrder')).toBe("order must be one of 'coarse', 'scanline', 'slow', got \"fast\"");
  expect(await message('setRenderMode')).toBe("renderMode must be one of 'coarse', 'scanline', 'slow', got \"fast\"");
  expect(await page.evaluate(() => window.view.order)).toBe('slow'); // a bad order changes nothing
});

test('what a sketch needs is the view\'s own: the picture\'s bytes, the slow-motion speed and the pictures done', async ({ page }) => {
  await page.goto(PAGE);
  await waitForDone(page);
  expect(await page.evaluate(() => window.view.picturesDone)).toBe(1); // one picture traced to its end
  await page.evaluate(() => { window.view.draw(); window.view.draw(); }); // drawing a whole picture again is no new picture
  expect(await page.evaluate(() => window.view.picturesDone)).toBe(1);
  await page.evaluate(() => window.view.restart());
  await expect.poll(() => page.evaluate(() => window.view.picturesDone)).toBe(2); // traced again to its end
  expect(await page.evaluate(() => {
    const { view, lib } = window;
    const expected = lib.render(view.scene, view.camera);
    return view.buffer.length === expected.length && view.buffer.every((b, i) => b === expected[i]);
  })).toBe(true);
  expect(await page.evaluate(() => { window.view.slowRaysPerSecond = 8; window.view.slowRaysPerStep = 3; return [window.view.slowRaysPerSecond, window.view.slowRaysPerStep]; })).toEqual([8, 3]);
});

/**
 * Counts the page's inspectPixel calls: lib/lesson/inspect.js as the dev server sends
 * it, with inspectPixel wrapped to count into window.inspections.
 */
async function countInspections(page) {
  await page.route(/\/lib\/lesson\/inspect\.js(\?.*)?$/, async (route) => {
    const response = await route.fetch();
    const body = (await response.text()).replace('export function inspectPixel(', 'function tracedInspectPixel(')
      + '\nexport function inspectPixel(...args) { globalThis.inspections = (globalThis.inspections ?? 0) + 1; return tracedInspectPixel(...args); }\n';
    await route.fulfill({ response, body });
  });
}

for (const [sketch, panels] of [['06-lights-shadows-reflections', 'the inspector, the 3D view and the tasks'], ['11-several-rays-per-pixel', 'the inspector and the sample rays']]) {
  test(`one record per click: ${panels} of sketch ${sketch.slice(0, 2)} share the pixel's one inspectPixel`, async ({ page }) => {
    await countInspections(page);
    await page.goto(`/sketches/${sketch}.html`);
    await waitForDone(page);
    const canvas = page.locator('[data-tracer]').last();
    for (const [x, y] of [[10, 12], [20, 8]]) {
      await page.evaluate(() => { window.inspections = 0; });
      await clickPixel(canvas, x, y);
      await expect(page.locator('[data-inspector] [data-field="hit-object"]').first()).toBeAttached();
      await page.waitForTimeout(100); // listeners that run later (the 3D view's redraw, the tasks) have run
      expect(await page.evaluate(() => window.inspections)).toBe(1);
    }
  });
}

test('one record per key press: the inspector and the side and top views of sketch 01 share the pixel\'s one inspectPixel', async ({ page }) => {
  await countInspections(page);
  await page.goto('/sketches/01-rays-through-pixels.html');
  await waitForDone(page);
  await page.locator('[data-tracer]').focus(); // by keyboard: no pixel under a pointer, the views draw the selected one
  for (const key of ['ArrowRight', 'ArrowDown']) {
    await page.evaluate(() => { window.inspections = 0; });
    await page.keyboard.press(key);
    await expect(page.locator('[data-inspector] [data-field="hit-object"]').first()).toBeAttached();
    await page.waitForTimeout(200); // the diagrams' draw() has run
    expect(await page.evaluate(() => window.inspections)).toBe(1);
  }
});
