// Links within every limit stay usable in sketch 05: long names are cut in the
// inspector as everywhere, and a hit under many area lights lists a few of them
// with "and N more", not every shadow ray of every light.
import { test, expect } from '@playwright/test';
import { expectQuietConsole, waitForDone, clickPixel } from './helpers.js';
import { Scene, Plane, Cylinder, AreaLight, PointLight } from '../../lib/index.js';
import { sceneToJSON } from '../../lib/scene/json.js';
import { encodeSceneLink } from '../../lib/p5/page/scene-link.js';
import { AREA_LIGHTS_SHOWN } from '../../lib/p5/pixel/inspector.js';

expectQuietConsole(test);

const LONG = 'n'.repeat(100_000);

test('a 100,000-character name of a cylinder or an area light is cut in the inspector; many area lights: a few, and "N more"', async ({ page }) => {
  const scene = new Scene({ background: [0.8, 0.9, 1] })
    .add(new Plane([0, -2, 0], [0, 1, 0], { color: 'white', name: 'floor' }))
    .add(new Cylinder([0, 0, -12], 2, 4, { color: 'teal', name: LONG }))
    .add(new PointLight([0, 30, 0], { name: `${LONG}p` }));
  const AREA = 30;
  for (let i = 0; i < AREA; i++) scene.add(new AreaLight([i - 15, 20, -10], 0.5, { samples: 4, intensity: 0.05, name: `${LONG}${i}` }));
  await page.goto(`/sketches/05-value-boxes.html#scene=${await encodeSceneLink(sceneToJSON(scene))}`);
  await waitForDone(page, 60_000);
  const view = page.locator('[data-tracer]');
  const { w, h } = await view.evaluate((c) => ({ w: Number(c.dataset.width), h: Number(c.dataset.height) }));
  await clickPixel(view, Math.floor(w / 2), Math.floor(h / 2));
  const panel = page.locator('[data-inspector]');
  await expect(panel.locator('[data-field="hit-object"]')).toHaveAttribute('data-value', LONG);
  await expect(panel.locator('.rt-area-light')).toHaveCount(AREA_LIGHTS_SHOWN);
  await expect(panel.locator('[data-field="more-area-lights"]')).toHaveText(`and ${AREA - AREA_LIGHTS_SHOWN} more area lights, not shown`);
  const widest = await page.evaluate(() => Math.max(document.documentElement.scrollWidth, ...[...document.querySelectorAll('[data-inspector] *')].map((e) => e.getBoundingClientRect().right)));
  expect(widest).toBeLessThanOrEqual(1280);
  // Every text shown is short; the sentence a screen reader hears (hidden, one per part) names each light cut too.
  const longest = await panel.evaluate((p) => Math.max(...[...p.querySelectorAll('th, td, p:not([hidden]), span, summary')].map((e) => e.childNodes.length === 1 && e.firstChild.nodeType === 3 ? e.textContent.length : 0)));
  expect(longest).toBeLessThan(200);
  const spoken = await panel.locator('[data-announce="pixel"]').textContent();
  expect(spoken).toMatch(/^Pixel: \d+,\d+; H: /);
  expect(Math.max(...spoken.split(/\s+/).map((word) => word.length)), spoken).toBeLessThanOrEqual(42); // a name of 40 characters and its "…;"
  expect(spoken.length, spoken).toBeLessThan(400);
});
