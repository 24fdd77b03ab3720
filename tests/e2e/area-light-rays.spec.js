// An area light's shadow rays (tests/e2e/pages/area-light.html: a ball under a
// disc of 16 points). The inspector gives the area light one row, "N of 16
// shadow rays reached it", N counted here by our own shadow rays; its rays one
// by one in a closed <details>. The 3D view draws the disc, every shadow ray
// (lit, or blocked on the ball) and, with several rays per pixel, the sub-pixel rays.
import { test, expect } from '@playwright/test';
import { clickPixel, expectQuietConsole, waitForDone } from './helpers.js';
import { inspectPixel } from '../../lib/lesson/inspect.js';
import { penumbraScene, penumbraCamera, pointsSeen } from '../unit/penumbra-scene.js';

const PAGE = '/tests/e2e/pages/area-light.html';
expectQuietConsole(test);

/** The floor pixel whose point sees nearest half of the disc (the first, row by row), and how many points it sees. */
function halfLitPixel() {
  const { scene, lamp } = penumbraScene(), camera = penumbraCamera();
  let best = null;
  for (let y = 0; y < camera.height; y++) {
    for (let x = 0; x < camera.width; x++) {
      const { hit } = inspectPixel(scene, camera, x, y);
      if (hit?.object !== scene.objects[0]) continue;
      const seen = pointsSeen(hit.point, hit.normal, lamp, scene.bias);
      if (!best || Math.abs(seen - 8) < Math.abs(best.seen - 8)) best = { x, y, seen };
    }
  }
  return best;
}
const penumbra = halfLitPixel();

async function waitForView(page) {
  await waitForDone(page);
  await expect(page.locator('[data-view3d]')).toHaveAttribute('data-state', 'done');
}

async function pixels(canvas) {
  return Buffer.from((await canvas.evaluate((c) => c.toDataURL('image/png'))).split(',')[1], 'base64');
}

test('a penumbra pixel: the inspector says how many of the 16 shadow rays reached the area light', async ({ page }) => {
  expect(penumbra.seen).toBeGreaterThan(0);
  expect(penumbra.seen).toBeLessThan(16);
  await page.goto(PAGE);
  await waitForDone(page);
  await clickPixel(page.locator('[data-tracer]'), penumbra.x, penumbra.y);
  const panel = page.locator('[data-inspector]');
  await expect(panel).toHaveAttribute('data-x', String(penumbra.x));
  const percent = Math.round((100 * penumbra.seen) / 16);
  const line = panel.locator('[data-area-light="0"][data-field="area-reached"]');
  await expect(line).toHaveText(`area light 'lamp': ${penumbra.seen} of 16 shadow rays reached it (${percent} %)`);
  await expect(line).toHaveAttribute('data-value', `${penumbra.seen}/16`);
  // one row for the area light, not 16: its points wait in a closed <details>
  const details = panel.locator('.rt-area-rays');
  await expect(details).not.toHaveAttribute('open', '');
  await expect(details.locator('tbody tr').first()).toBeHidden();
  await details.locator('summary').focus();
  await page.keyboard.press('Enter'); // from the keyboard
  await expect(details).toHaveAttribute('open', '');
  await expect(details.locator('tbody tr')).toHaveCount(16);
  await expect(details.locator('tbody tr.rt-light-lit')).toHaveCount(penumbra.seen);
  await expect(details.locator('tbody tr.rt-light-in-shadow')).toHaveCount(16 - penumbra.seen);
  await expect(details.getByRole('region', { name: "Shadow rays of area light 'lamp' table" })).toBeVisible();
});

test('the 3D view draws the disc and every shadow ray of the pixel, lit or blocked on the ball', async ({ page }) => {
  await page.goto(`${PAGE}?select=${penumbra.x},${penumbra.y}&yaw=-70&pitch=25&distance=30`);
  await waitForView(page);
  const view3d = page.locator('[data-view3d]');
  await expect(view3d).toHaveAttribute('data-selected', `${penumbra.x},${penumbra.y}`);
  const kinds = await page.evaluate(() => window.sceneView.segments.map((s) => `${s.kind}:${s.kind === 'shadow' ? (s.lit ? 'lit' : s.blockedAt ? 'blocked' : 'other') : ''}`));
  expect(kinds.filter((k) => k === 'shadow:lit')).toHaveLength(penumbra.seen);
  expect(kinds.filter((k) => k === 'shadow:blocked')).toHaveLength(16 - penumbra.seen);
  expect(kinds.some((k) => k.startsWith('sample'))).toBe(false); // one ray per pixel
  expect(await pixels(view3d)).toMatchSnapshot('view3d-area-light.png');
});

test('several rays per pixel: the 3D view draws the pixel\'s n × n sub-pixel rays too', async ({ page }) => {
  await page.goto(`${PAGE}?samples=4&select=${penumbra.x},${penumbra.y}&yaw=-70&pitch=25&distance=30`);
  await waitForView(page);
  const view3d = page.locator('[data-view3d]');
  const samples = await page.evaluate(() => window.sceneView.segments.filter((s) => s.kind === 'sample').map((s) => [s.dx, s.dy]));
  expect(samples).toHaveLength(4);
  expect(new Set(samples.map(String)).size).toBe(4);
  const one = await page.evaluate(() => window.sceneView.segments.filter((s) => s.kind === 'shadow').length);
  expect(one).toBe(16);
  expect(await pixels(view3d)).toMatchSnapshot('view3d-area-light-samples.png');
});
