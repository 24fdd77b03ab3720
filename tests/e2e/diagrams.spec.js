// The diagrams of lib/p5/diagrams.js for the class scene: each canvas draws
// without console errors, and matches its reference screenshot.
import { test, expect } from '@playwright/test';
import { expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';

const PAGE = '/tests/e2e/pages/diagrams.html';

/** Every canvas of the page, as [diagram, case] (kept in step with the page). */
const CANVASES = [
  ['side', 'pink'], ['top', 'pink'], ['geometric', 'pink'], ['parabola', 'pink'],
  ['side', 'ground'], ['top', 'ground'], ['geometric', 'ground'], ['parabola', 'ground'],
  ['side', 'miss'], ['top', 'miss'], ['geometric', 'miss'], ['parabola', 'miss'],
  ['side', 'none'], ['geometric', 'none'], ['side', 'inside'], ['geometric', 'inside'],
  ['parabola', 'inside'], ['geometric', 'tangent'], ['parabola', 'tangent'], ['parabola', 'none'],
  ['legend', 'discriminant'], ['legend', 'roots'],
];

test('every diagram draws, for a hit, a shadow, a miss, no pixel, inside and tangent, with no console errors', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto(PAGE);
  await waitForDone(page);
  const found = await page.locator('canvas[data-diagram]').evaluateAll((cs) => cs.map((c) => [c.dataset.diagram, c.dataset.case]));
  expect(found).toEqual(CANVASES);
  // each canvas has something drawn on it (more than its background)
  const inked = await page.locator('canvas[data-diagram]').evaluateAll((cs) => cs.map((c) => {
    const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const colours = new Set();
    for (let i = 0; i < data.length; i += 4 * 97) colours.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
    return colours.size;
  }));
  for (const n of inked) expect(n).toBeGreaterThan(5);
  await expect(page.locator('[data-legend]')).toContainText('H angle');
  expect(errors).toEqual([]);
});

for (const [diagram, kase] of CANVASES) {
  test(`${diagram} diagram, ${kase}: matches its screenshot`, async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    await expectCanvasScreenshot(page.locator(`canvas[data-diagram="${diagram}"][data-case="${kase}"]`), `diagram-${diagram}-${kase}.png`);
  });
}
