// A scene broken after it was built (a student's draw() sets a radius to NaN,
// pushes null into scene.lights) and the view asked to trace it again: the
// page shows the mistake, naming the field, in the data-error panel; the last
// good picture stays, not a black one; nothing reaches the console.
import { test, expect } from '@playwright/test';
import { waitForDone, expectQuietConsole } from './helpers.js';

expectQuietConsole(test);

/** The traced canvas's pixels, as a string to compare. */
const picture = (page) => page.evaluate(() => {
  const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector('canvas[data-tracer]'));
  return Array.from(canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data).join(',');
});

/** Runs `change` on the view's scene and restarts the view in an animation frame, as a sketch's draw() would. */
const inDraw = (page, change) => page.evaluate((code) => new Promise((done) => requestAnimationFrame(() => {
  const { view } = /** @type {any} */ (window);
  new Function('scene', code)(view.scene); // the test's change, written as a sketch would write it
  view.restart();
  requestAnimationFrame(() => done());
})), change);

for (const [what, change, field] of [
  ['a radius set to NaN', 'scene.objects[1].radius = NaN;', 'objects[1].radius must be a finite number, got NaN'],
  ['null pushed into scene.lights', 'scene.lights.push(null);', 'lights[2] must be a light source'],
  ['a colour that is no colour', "scene.objects[0].material.color = 'blurple';", 'objects[0].material.color must be a colour'],
]) {
  test(`${what}: the panel names the field and the last good picture stays`, async ({ page }) => {
    await page.goto('/tests/e2e/pages/inspector.html');
    await waitForDone(page);
    const before = await picture(page);
    expect(before).not.toMatch(/^(0,0,0,255,?)+$/); // a real picture to keep

    await inDraw(page, change);
    const panel = page.locator('[data-error]');
    await expect(panel).toBeVisible();
    await expect(panel).toContainText(field);
    expect(await picture(page)).toBe(before);
    await expect(page.locator('body')).toHaveAttribute('data-render', 'done');

    // a click on a pixel of the broken scene says nothing new and throws nothing
    await page.locator('canvas[data-tracer]').click({ position: { x: 20, y: 20 } });
    expect(await picture(page)).toBe(before);
  });
}

test('the scene mended, the view traces it again', async ({ page }) => {
  await page.goto('/tests/e2e/pages/inspector.html');
  await waitForDone(page);
  const before = await picture(page);
  await inDraw(page, 'scene.objects[1].radius = NaN;');
  await expect(page.locator('[data-error]')).toContainText('objects[1].radius');
  await inDraw(page, 'scene.objects[1].radius = 1;'); // smaller than it was: another picture
  await waitForDone(page);
  expect(await picture(page)).not.toBe(before);
});
