// The diagrams of lib/p5/diagrams/index.js for the class scene: each canvas draws
// without console errors, and matches its reference screenshot.
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';

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

test('with a wall in front of a sphere, the diagrams explain the sphere the discriminant mode shows', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/tests/e2e/pages/focus-wall.html');
  await waitForDone(page);
  const view = page.locator('[data-tracer]');
  await clickPixel(view, 16, 12); // the wall hides the sphere this ray goes through
  await expect(page.locator('body')).toHaveAttribute('data-focus', 'behind the wall');
  // The mode's colour there is that sphere's discriminant, with two roots: the colour of what the diagram draws.
  const [shown, expected] = await page.evaluate(async () => {
    const { Camera, intersectQuadratic } = await import('/lib/index.js');
    const { discriminantColor } = await import('/lib/tracing/modes.js');
    const c = document.querySelector('[data-tracer]');
    const shown = Array.from(c.getContext('2d').getImageData(16, 12, 1, 1).data.slice(0, 3));
    const { ray } = new Camera({ width: 32, height: 24, fov: 30 }).primaryRay(16, 12);
    const { Sphere } = await import('/lib/index.js');
    const q = intersectQuadratic(ray, new Sphere([0, 0, -20], 3));
    return [shown, [q.roots, ...Array.from(Uint8ClampedArray.from(discriminantColor(q.discriminant, q.roots)))]];
  });
  expect(expected[0]).toBe(2);
  expect(shown).toEqual(expected.slice(1));
  // A pixel whose ray misses both spheres: the closest miss, as the mode shows it.
  await clickPixel(view, 31, 0);
  await expect(page.locator('body')).toHaveAttribute('data-focus', 'missed');
  await clickPixel(view, 16, 12);
  await expectCanvasScreenshot(page.locator('canvas[data-diagram="wall"]'), 'diagram-wall-behind.png');
  expect(errors).toEqual([]);
});
