/**
 * Saves while the page is open, as a teacher live-coding does.
 */
import { test, expect } from '@playwright/test';
import { waitForDone } from './helpers.js';
import { liveSketch, sketchSource } from './live-sketch.js';

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
