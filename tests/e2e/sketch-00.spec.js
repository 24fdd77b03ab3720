// Sketch 00: light-based tracing beside eye-based tracing. The photon picture
// and its count come from the seed: the page shows what lib/tracing/photons.js gives
// in Node for the same seed; the 3D view follows the selection.
import { test, expect } from '@playwright/test';
import { PhotonTracer } from '../../lib/tracing/photons.js';
import { classScene } from '../../lib/scene/examples.js';
import { Camera } from '../../lib/math/camera.js';
import { clickPixel, expectQuietConsole, waitForDone } from './helpers.js';

const PAGE = '/sketches/00-light-or-eye.html';
expectQuietConsole(test);

test('the photon count and picture are the ones the seed gives, and the 3D view shows the selected pixel', async ({ page }) => {
  await page.goto(PAGE);
  const photons = new PhotonTracer({ scene: classScene(), camera: new Camera({ width: 32, height: 24 }), seed: 1968, eyeRadius: 2, samplePaths: 12 });
  photons.emit(1_000_000);
  await waitForDone(page, 60_000);
  const count = page.locator('[data-photon-count]');
  await expect(count).toContainText(`Of 1,000,000 rays from the light, ${photons.reached} reached the eye:`);
  expect(photons.reached).toBeLessThan(1_000_000 * 0.001); // the lesson's point: hardly any
  const expected = photons.writePicture(new Uint8ClampedArray(32 * 24 * 4));
  const shown = await page.locator('canvas[data-photons]').evaluate((c) => [...c.getContext('2d').getImageData(0, 0, c.width, c.height).data]);
  expect(shown).toEqual([...expected]);

  const view3d = page.locator('[data-view3d]');
  await expect(view3d).toHaveAttribute('data-selected', '16,14');
  await clickPixel(page.locator('canvas[data-photons]'), 3, 5); // the photon picture selects too
  await expect(view3d).toHaveAttribute('data-selected', '3,5');
  await expect(page.locator('[data-inspector]')).toContainText('Pixel: 3,5;');
});
