// The 3D scene view (lib/p5/scene-view/view.js): linked both ways with its tracer
// view, turned by dragging, and its picture at fixed orbits for a selected
// pixel, with and without shadows and mirrors.
import { test, expect } from '@playwright/test';
import { clickPixel, expectQuietConsole, waitForDone } from './helpers.js';

const PAGE = '/tests/e2e/pages/scene-view.html';
expectQuietConsole(test);

/** Waits until the 3D view shows the finished picture with nothing left to draw. */
async function waitForView(page) {
  await waitForDone(page);
  await expect(page.locator('[data-view3d]')).toHaveAttribute('data-state', 'done');
}

/** The 3D canvas's own pixels, as a PNG. */
async function pixels(canvas) {
  return Buffer.from((await canvas.evaluate((c) => c.toDataURL('image/png'))).split(',')[1], 'base64');
}

test('the 3D view follows clicks and arrow keys in the tracer view', async ({ page }) => {
  await page.goto(PAGE);
  const view3d = page.locator('[data-view3d]');
  await expect(view3d).toHaveAttribute('data-selected', '');
  const tracer = page.locator('[data-tracer]');
  await clickPixel(tracer, 5, 7);
  await expect(view3d).toHaveAttribute('data-selected', '5,7');
  await tracer.press('ArrowRight');
  await tracer.press('ArrowDown');
  await tracer.press('ArrowDown');
  await expect(view3d).toHaveAttribute('data-selected', '6,9');
});

test('a click on a pixel of the image plane in 3D selects it, in both views', async ({ page }) => {
  await page.goto(`${PAGE}?yaw=-20&pitch=10&distance=14`);
  await waitForView(page);
  const view3d = page.locator('[data-view3d]');
  for (const [x, y] of [[3, 4], [20, 15], [31, 0]]) {
    const at = await page.evaluate(([x, y]) => window.sceneView.screenPointOfPixel(x, y), [x, y]);
    await view3d.click({ position: at });
    await expect(view3d).toHaveAttribute('data-selected', `${x},${y}`);
    await expect(page.locator('[data-tracer-view]')).toBeVisible();
    expect(await page.evaluate(() => window.tracerView.selected)).toEqual({ x, y });
  }
});

test('dragging turns the view (the picture changes); Reset brings it back', async ({ page }) => {
  await page.goto(`${PAGE}?select=16,12`);
  await waitForView(page);
  const view3d = page.locator('[data-view3d]');
  const before = await pixels(view3d);
  const orbit = await page.evaluate(() => window.sceneView.orbit);
  const box = await view3d.boundingBox();
  await page.mouse.move(box.x + 200, box.y + 150);
  await page.mouse.down();
  await page.mouse.move(box.x + 260, box.y + 170, { steps: 5 });
  await page.mouse.up();
  await expect(view3d).toHaveAttribute('data-state', 'done');
  const turned = await page.evaluate(() => window.sceneView.orbit);
  expect(turned.yaw).toBeCloseTo(orbit.yaw - 60 * 0.4, 5);
  expect(turned.pitch).toBeCloseTo(orbit.pitch + 20 * 0.4, 5);
  expect((await pixels(view3d)).equals(before)).toBe(false);
  await expect(view3d).toHaveAttribute('data-selected', '16,12'); // a drag is not a click
  await page.locator('[data-view3d-reset]').click();
  await expect(view3d).toHaveAttribute('data-state', 'done');
  expect(await page.evaluate(() => window.sceneView.orbit)).toEqual(orbit);
  expect((await pixels(view3d)).equals(before)).toBe(true);
});

test('the wheel zooms', async ({ page }) => {
  await page.goto(PAGE);
  await waitForView(page);
  const { distance } = await page.evaluate(() => window.sceneView.orbit);
  await page.locator('[data-view3d]').hover();
  await page.mouse.wheel(0, 200);
  await expect.poll(() => page.evaluate(() => window.sceneView.orbit.distance)).toBeGreaterThan(distance);
});

// The same pixel of the pink sphere: its shadow rays (one lit, one facing away), without
// shadows, and in the full scene whose pink sphere is half mirror, half glass.
for (const [name, query] of [
  ['shadows', 'scene=class&select=12,14&yaw=-35&pitch=20'],
  ['shadows-side', 'scene=class&select=20,18&yaw=-100&pitch=8'],
  ['no-shadows', 'scene=noshadows&select=20,18&yaw=-35&pitch=20'],
  ['mirrors', 'scene=full&select=12,14&yaw=-35&pitch=20'],
  ['miss', 'scene=class&select=2,1&yaw=30&pitch=35'],
]) {
  test(`3D view screenshot: ${name}`, async ({ page }) => {
    await page.goto(`${PAGE}?${query}`);
    await waitForView(page);
    expect(await pixels(page.locator('[data-view3d]'))).toMatchSnapshot(`view3d-${name}.png`);
  });
}

test('h and v show every ray of the selected pixel\'s row and column; again hides them', async ({ page }) => {
  await page.goto(`${PAGE}?select=16,12`);
  await waitForView(page);
  const view3d = page.locator('[data-view3d]'), tracer = page.locator('[data-tracer]');
  const plain = await pixels(view3d);
  await tracer.press('h');
  await expect(view3d).toHaveAttribute('data-fan', 'row');
  await expect(view3d).toHaveAttribute('data-state', 'done');
  expect(await pixels(view3d)).toMatchSnapshot('view3d-row.png');
  await view3d.press('v'); // from the 3D view too
  await expect(view3d).toHaveAttribute('data-fan', 'column');
  await expect(view3d).toHaveAttribute('data-state', 'done');
  expect(await pixels(view3d)).toMatchSnapshot('view3d-column.png');
  await tracer.press('v');
  await expect(view3d).toHaveAttribute('data-fan', '');
  await expect(view3d).toHaveAttribute('data-state', 'done');
  expect((await pixels(view3d)).equals(plain)).toBe(true);
});

test('Shoot traces the picture again one ray at a time, each ray flying; the picture comes out the same', async ({ page }) => {
  await page.goto(`${PAGE}?w=16&h=12`);
  await waitForView(page);
  const tracer = page.locator('[data-tracer]');
  const picture = await tracer.evaluate((c) => c.toDataURL());
  await page.locator('[data-view3d-speed]').fill('7'); // the fastest: 120 rays/s
  await expect(page.locator('.rt-view3d-speed-text')).toHaveText('120 rays/s');
  await page.locator('[data-view3d-shoot]').click();
  await expect(page.locator('body')).toHaveAttribute('data-render', 'rendering');
  expect(await page.evaluate(() => window.tracerView.renderMode)).toBe('slow');
  await expect.poll(() => page.evaluate(() => window.sceneView.shots)).toBeGreaterThan(0);
  await waitForView(page);
  expect(await page.evaluate(() => [window.sceneView.shots, window.sceneView.shooting])).toEqual([16 * 12, false]);
  expect(await tracer.evaluate((c) => c.toDataURL())).toBe(picture);
});
