/**
 * Saves while the page is open, as a teacher live-coding does.
 */
import { test, expect } from '@playwright/test';
import { waitForDone, clickPixel } from './helpers.js';
import { liveSketch, sketchSource, saveAndWaitForUpdate } from './live-sketch.js';

/** A line that reaches outside p5 (a timer): the dev server does not swap such a sketch, a save reloads its page. */
const TIMER = '    setTimeout(() => {}, 0);';
const GREEN = 'new Sphere([0, 0, -20], 5, { color: [0.2, 0.9, 0.3] })';

// The file watcher passes on one change of a file per 50 ms: the second step of such a save came
// within it and was dropped, and the page stayed on the empty file (scripts/every-save-arrives.js).
// The first step of a save its formatter rewrites at once: another picture (a bigger pink sphere), which must not stay.
const BEFORE_FORMATTING = sketchSource({ sphere: 'new Sphere([0, 0, -20], 4.5, { color: [1, 0.32, 0.36] })' });
for (const [gapMs, first, how] of [[15, '', 'emptied'], [35, '', 'emptied'], [35, BEFORE_FORMATTING, 'written, then rewritten by a formatter']]) {
  test(`a save that reaches the disk in two steps, ${gapMs} ms apart (${how}), shows its last version`, async ({ page }) => {
    const sketch = liveSketch(`live-save-two-steps-${gapMs}-${first ? 'formatted' : 'emptied'}`, sketchSource());
    try {
      await page.goto(sketch.url);
      await waitForDone(page);
      await sketch.saveInTwoSteps(sketchSource({ sphere: GREEN }), gapMs, first);
      const green = () => page.locator('[data-tracer]').evaluate((c) => {
        const [r, g] = c.getContext('2d').getImageData(32, 24, 1, 1).data;
        return document.body.dataset.render === 'done' && g > r + 40;
      }).catch(() => false); // between versions the page has no picture
      await expect.poll(green, { message: 'the new, green sphere', timeout: 15_000 }).toBe(true);
    } finally {
      sketch.remove();
    }
  });
}

// A script deleted while no page is open: Vite would show an error of the dev server's (a file it could
// not read) on the next page that opens, and the kit read that page with Vite's error overlay in it.
test('a script deleted while no page is open leaves the next page quiet, with its picture', async ({ page }) => {
  const gone = liveSketch('live-save-gone', sketchSource());
  const sketch = liveSketch('live-save-after-gone', sketchSource());
  try {
    const errors = [];
    page.on('pageerror', (error) => errors.push(error.message));
    gone.save(sketchSource({ sphere: GREEN })); // a change the dev server reads as it comes
    await page.waitForTimeout(300);
    gone.remove();
    await page.waitForTimeout(500);
    await page.goto(sketch.url);
    await waitForDone(page);
    await page.waitForTimeout(500); // what Vite kept for the next page comes once it connects
    await expect(page.locator('vite-error-overlay')).toHaveCount(0);
    await expect(page.locator('[data-error]')).toHaveCount(0);
    expect(errors).toEqual([]);
  } finally {
    sketch.remove();
    gone.remove();
  }
});

for (const [how, before] of [['swap', ''], ['reload', TIMER]]) {
  test(`a save (${how}) updates the pages running that sketch, not every page on the server`, async ({ browser }) => {
    const edited = liveSketch(`live-save-edited-${how}`, sketchSource({ before }));
    const other = liveSketch(`live-save-other-${how}`, sketchSource());
    const context = await browser.newContext();
    try {
      const [page, bystander] = [await context.newPage(), await context.newPage()];
      await page.goto(edited.url);
      await bystander.goto(other.url);
      await Promise.all([waitForDone(page), waitForDone(bystander)]);
      await bystander.evaluate(() => { window.stillHere = true; });
      let bystanderLoads = 0;
      bystander.on('load', () => { bystanderLoads += 1; });

      expect(await saveAndWaitForUpdate(page, edited, sketchSource({ before, sphere: GREEN }))).toBe(how);
      await waitForDone(page);
      const centre = await page.locator('[data-tracer]').evaluate((c) => [...c.getContext('2d').getImageData(32, 24, 1, 1).data]);
      expect(centre[1]).toBeGreaterThan(centre[0] + 40); // the new, green sphere
      await page.waitForTimeout(500); // time for a stray update of the other page to begin
      expect(await bystander.evaluate(() => [window.stillHere, window.__sketchbookSwaps])).toEqual([true, undefined]);
      expect(bystanderLoads).toBe(0);
    } finally {
      await context.close();
      edited.remove();
      other.remove();
    }
  });
}

/** A sketch with a box that turns the camera, and a tall page to scroll. */
const PLACE = {
  after: [
    '    window.view = view;',
    "    const yaw = p.createInput('0').id('yaw');",
    '    yaw.changed(() => view.setCamera(new Camera({ width: 64, height: 48, yaw: Number(yaw.value()) })));',
    "    p.createDiv().style('height', '2400px');",
  ].join('\n'),
};

for (const [how, timer] of [['swap', ''], ['reload', TIMER]]) {
  test(`a save (${how}) keeps the selected pixel, the mode, the boxes and the scroll position; the code wins where it changed`, async ({ page }) => {
    const place = { ...PLACE, before: timer };
    const sketch = liveSketch(`live-save-place-${how}`, sketchSource(place));
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

      expect(await saveAndWaitForUpdate(page, sketch, sketchSource({ ...place, sphere: 'new Sphere([0, 0, -20], 5, { color: [1, 0.32, 0.36] })' }))).toBe(how);
      await waitForDone(page);
      await expect(answer).toHaveText(before); // the same pixel, through the same turned camera
      expect(await page.evaluate(() => window.view.mode)).toBe('discriminant');
      await expect(page.locator('#yaw')).toHaveValue('5');
      expect(await page.evaluate(() => window.view.camera.yaw)).toBe(5);
      await expect.poll(() => page.evaluate(() => window.scrollY)).toBe(700);

      // The code changes the box's value: the new code's value shows, the rest of the place stays.
      expect(await saveAndWaitForUpdate(page, sketch, sketchSource({ ...place, after: PLACE.after.replace("createInput('0')", "createInput('-5')") }))).toBe(how);
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
}

for (const [how, timer] of [['swap', ''], ['reload', TIMER]]) {
  test(`a save (${how}) that breaks setup, then one that fixes it, comes back to the place before the mistake`, async ({ page }) => {
    const place = { ...PLACE, before: timer };
    const sketch = liveSketch(`live-save-broken-${how}`, sketchSource(place));
    try {
      await page.goto(sketch.url);
      await waitForDone(page);
      await clickPixel(page.locator('[data-tracer]'), 20, 30);
      expect(await saveAndWaitForUpdate(page, sketch, sketchSource({ ...place, sphere: 'new Sphere([0, 0, -20], "4")' }))).toBe(how);
      await expect(page.locator('[data-error]')).toBeVisible();
      expect(await saveAndWaitForUpdate(page, sketch, sketchSource(place))).toBe(how);
      await waitForDone(page);
      await expect(page.locator('[data-error]')).toHaveCount(0);
      await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(/^Pixel: 20,30; H: /);
    } finally {
      sketch.remove();
    }
  });
}
