// Sketch 12, cylinders, cones and triangles: the picture, and for a clicked pixel each
// shape's own test in the inspector (a cylinder's A = Xd² + Zd², not 1; the triangle's
// determinant), the hit shape's row marked.
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';

test('the shapes are traced, and a click shows each one\'s own record, the hit one marked', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/sketches/12-cylinders-cones-triangles.html');
  await waitForDone(page);
  const view = page.locator('[data-tracer]');
  await expectCanvasScreenshot(view, 'shapes.png');

  const inspector = page.locator('[data-inspector]');
  await expect(inspector.locator('[data-answer]')).toHaveText(/^Pixel: 8,20;/); // the page's own choice: the cylinder
  const row = (name) => inspector.locator('tr', { has: page.locator('th', { hasText: name }) });
  await expect(row('pink cylinder')).toHaveClass(/rt-hit-row/);
  const A = Number(await row('pink cylinder').locator('[data-label="A"]').getAttribute('data-value'));
  const direction = (await inspector.locator('[data-field="ray-direction"]').getAttribute('data-value')).split(',').map(Number);
  expect(A).toBeCloseTo(direction[0] ** 2 + direction[2] ** 2, 12); // Xd² + Zd²: y left out
  expect(A).toBeLessThan(1);

  await clickPixel(view, 33, 25); // the cone
  await expect(inspector.locator('[data-answer]')).toHaveText(/^Pixel: 33,25;/);
  await expect(row('yellow cone')).toHaveClass(/rt-hit-row/);
  const t = Number(await row('yellow cone').locator('[data-label="t (side)"]').getAttribute('data-value'));
  expect(t).toBeGreaterThan(0);

  await clickPixel(view, 53, 28); // the triangle
  await expect(row('green triangle')).toHaveClass(/rt-hit-row/);
  const det = Number(await row('green triangle').locator('[data-label="det"]').getAttribute('data-value'));
  expect(det).not.toBe(0); // not parallel: the ray crosses its plane
  expect(errors).toEqual([]);
});
