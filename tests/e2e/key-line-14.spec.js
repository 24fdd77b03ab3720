// Sketch 14's key line, "8 of 16 shadow rays reached it", on a laptop's screen (1280×800) without
// scrolling: under the two pictures, following the selected pixel and the disc's shadow rays.
import { test, expect } from '@playwright/test';
import { clickPixel, expectQuietConsole, waitForDone } from './helpers.js';

expectQuietConsole(test);
test.use({ viewport: { width: 1280, height: 800 } });

test('the key line is above the fold at 1280×800 and follows the pixel and the number of shadow rays', async ({ page }) => {
  await page.goto('/sketches/14-spot-and-area-lights.html');
  await waitForDone(page);
  const line = page.locator('[data-shadow-rays]');
  await expect(line).toHaveText('Pixel 73,33: 8 of 16 shadow rays reached it (50 % of the disc seen).');
  const box = await line.boundingBox();
  expect(box.y + box.height, 'the line\'s bottom, in CSS px from the top').toBeLessThanOrEqual(800);
  expect(await page.evaluate(() => scrollY)).toBe(0);

  const soft = page.locator('[data-tracer]').nth(1);
  await clickPixel(soft, 66, 27); // under the ball: no point of the disc in sight
  await expect(line).toHaveText('Pixel 66,27: 0 of 16 shadow rays reached it (0 % of the disc seen).');
  await clickPixel(soft, 0, 0); // the sky
  await expect(line).toHaveText('Pixel 0,0: its ray hits nothing.');
  await clickPixel(soft, 66, 27);
  await page.locator('#samples').getByRole('radio', { name: '1', exact: true }).check();
  await expect(line).toHaveText(/^Pixel 66,27: [01] of 1 shadow ray reached it \((0|100) % of the disc seen\)\.$/);
});
