/**
 * Saves while the page is open, as a teacher live-coding does.
 */
import { test, expect } from '@playwright/test';
import { waitForDone, clickPixel } from './helpers.js';
import { liveSketch, sketchSource, saveAndWaitForReload } from './live-sketch.js';

test('a save reloads the pages running that sketch, not every page on the server', async ({ browser }) => {
  const edited = liveSketch('live-save-edited', sketchSource());
  const other = liveSketch('live-save-other', sketchSource());
  const context = await browser.newContext();
  try {
    const [page, bystander] = [await context.newPage(), await context.newPage()];
    await page.goto(edited.url);
    await bystander.goto(other.url);
    await Promise.all([waitForDone(page), waitForDone(bystander)]);
    await bystander.evaluate(() => { window.stillHere = true; });

    const reloaded = page.waitForEvent('load');
    edited.save(sketchSource({ sphere: 'new Sphere([0, 0, -20], 5, { color: [1, 0.32, 0.36] })' }));
    await reloaded;
    await waitForDone(page);
    await page.waitForTimeout(500); // time for a stray reload of the other page to begin
    expect(await bystander.evaluate(() => window.stillHere)).toBe(true);
  } finally {
    await context.close();
    edited.remove();
    other.remove();
  }
});

/** A sketch with a box that turns the camera, and a tall page to scroll. */
const PLACE = {
  after: [
    '    window.view = view;',
    "    const yaw = p.createInput('0').id('yaw');",
    '    yaw.changed(() => view.setCamera(new Camera({ width: 64, height: 48, yaw: Number(yaw.value()) })));',
    "    p.createDiv().style('height', '2400px');",
  ].join('\n'),
};

test('a save keeps the selected pixel, the mode, the boxes and the scroll position; the code wins where it changed', async ({ page }) => {
  const sketch = liveSketch('live-save-place', sketchSource(PLACE));
  try {
    await page.goto(sketch.url);
    await waitForDone(page);
    await clickPixel(page.locator('[data-tracer]'), 10, 12);
    await page.evaluate(() => window.view.setMode('discriminant'));
    await page.locator('#yaw').fill('5');
    await page.locator('#yaw').press('Tab'); // change: the camera turns
    await waitForDone(page);
    const answer = page.locator('[data-inspector] [data-answer]');
    const before = await answer.textContent();
    expect(before).toMatch(/^Pixel: 10,12; H: /);
    await page.evaluate(() => window.scrollTo(0, 700));

    await saveAndWaitForReload(page, sketch, sketchSource({ ...PLACE, sphere: 'new Sphere([0, 0, -20], 5, { color: [1, 0.32, 0.36] })' }));
    await waitForDone(page);
    await expect(answer).toHaveText(before); // the same pixel, through the same turned camera
    expect(await page.evaluate(() => window.view.mode)).toBe('discriminant');
    await expect(page.locator('#yaw')).toHaveValue('5');
    expect(await page.evaluate(() => window.view.camera.yaw)).toBe(5);
    await expect.poll(() => page.evaluate(() => window.scrollY)).toBe(700);

    // The code changes the box's value: the new code's value shows, the rest of the place stays.
    await saveAndWaitForReload(page, sketch, sketchSource({ ...PLACE, after: PLACE.after.replace("createInput('0')", "createInput('-5')") }));
    await waitForDone(page);
    await expect(page.locator('#yaw')).toHaveValue('-5');
    expect(await page.evaluate(() => window.view.camera.yaw)).toBe(0); // the sketch's own camera: the box was not typed in
    await expect(answer).toHaveText(/^Pixel: 10,12; H: /);
    expect(await page.evaluate(() => window.view.mode)).toBe('discriminant');

    // A plain visit starts fresh (from another page: Chromium counts going to the same address as a reload).
    await page.goto('/index.html');
    await page.goto(sketch.url);
    await waitForDone(page);
    await expect(answer).toHaveText('');
    expect(await page.evaluate(() => window.view.mode)).toBe('shaded');
  } finally {
    sketch.remove();
  }
});

test('a save that breaks setup, then one that fixes it, comes back to the place before the mistake', async ({ page }) => {
  const sketch = liveSketch('live-save-broken', sketchSource(PLACE));
  try {
    await page.goto(sketch.url);
    await waitForDone(page);
    await clickPixel(page.locator('[data-tracer]'), 20, 30);
    await saveAndWaitForReload(page, sketch, sketchSource({ ...PLACE, sphere: 'new Sphere([0, 0, -20], "4")' }));
    await expect(page.locator('[data-error]')).toBeVisible();
    await saveAndWaitForReload(page, sketch, sketchSource(PLACE));
    await waitForDone(page);
    await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(/^Pixel: 20,30; H: /);
  } finally {
    sketch.remove();
  }
});
