// Share links of sketch 05: the scene compressed in the fragment, old ?scene=
// links still open, a warning when a link is long, and a page that opens in
// the same time whatever the length of its link.
import { test, expect } from '@playwright/test';
import { watchConsole, waitForDone } from './helpers.js';
import { Scene, Sphere, classScene } from '../../lib/index.js';
import { sceneToJSON } from '../../lib/scene/json.js';
import { encodeScene } from '../../lib/scene/codec.js';
import { encodeSceneLink, LINK_WARN_LENGTH } from '../../lib/p5/page/scene-link.js';

const BOXES = '/sketches/05-value-boxes.html';
const radius = 'objects[1].radius';

/** n spheres at made-up places, each with a name. */
function manySpheres(n) {
  const scene = new Scene();
  let seed = 7;
  const random = () => ((seed = (seed * 16807) % 2147483647) / 2147483647);
  for (let i = 0; i < n; i++) {
    scene.add(Object.assign(new Sphere([random() * 40 - 20, random() * 20 - 10, -40 - random() * 40], 0.3 + random(),
      { color: [random(), random(), random()] }), { name: `ball ${i}` }));
  }
  return sceneToJSON(scene);
}

test('an edit puts the scene, compressed, in the fragment; the link opens the same scene', async ({ page, context }) => {
  const errors = watchConsole(page);
  await page.goto(BOXES);
  await waitForDone(page);
  const box = page.locator(`input[name="${radius}"]`);
  await box.fill('6');
  await box.press('Enter');
  await expect(page).toHaveURL(/#scene=z\.[A-Za-z0-9_-]+$/);
  expect(new URL(page.url()).search).toBe('');
  await waitForDone(page);

  const other = await context.newPage();
  await other.goto(page.url());
  await waitForDone(other);
  await expect(other.locator(`input[name="${radius}"]`)).toHaveValue('6');
  await expect(other.locator('[data-link-problem]')).toBeEmpty();
  expect(errors).toEqual([]);
});

test('an old ?scene= link still opens, and an edit moves it to the fragment', async ({ page }) => {
  const json = sceneToJSON(classScene());
  json.objects[1].radius = 3;
  await page.goto(`${BOXES}?scene=${encodeScene(json)}`);
  await waitForDone(page);
  await expect(page.locator(`input[name="${radius}"]`)).toHaveValue('3');
  const box = page.locator(`input[name="${radius}"]`);
  await box.fill('5');
  await box.press('Enter');
  await expect(page).toHaveURL(/05-value-boxes\.html#scene=z\./);
});

test('a damaged fragment says so and shows the class scene', async ({ page }) => {
  await page.goto(`${BOXES}#scene=z.AAAA`);
  await waitForDone(page);
  await expect(page.locator('[data-link-problem]')).toContainText('cut short or damaged');
  await expect(page.locator(`input[name="${radius}"]`)).toHaveValue('4');
});

test('"Copy link" warns when the link is long enough for a chat to cut', async ({ page, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  const link = await encodeSceneLink(manySpheres(400));
  expect(link.length).toBeGreaterThan(LINK_WARN_LENGTH);
  await page.goto(`${BOXES}#scene=${link}`);
  await waitForDone(page, 60_000);
  await page.getByRole('button', { name: 'Copy link' }).click();
  await expect(page.locator('.share [role="status"]')).toContainText(/characters long: a chat or an e-mail may cut it/);
});

test('a page opens as fast whatever the length of its link', async ({ page }) => {
  // p5's language detector once ran a regex over location.href that was quadratic on a link without dots
  // (base64url): 60 kB took one 1.5 s task, 270 kB would take about 30 s. The longest task while a page
  // opens says it whatever the machine's load (the link's fragment: the server never sees it).
  await page.addInitScript(() => {
    window.longestTask = 0;
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) window.longestTask = Math.max(window.longestTask, e.duration);
    }).observe({ type: 'longtask', buffered: true });
  });
  const longestTaskOpening = async (url) => {
    await page.goto('about:blank'); // a real load each time, not a move within the page
    await page.goto(url);
    await expect(page.locator('body')).toHaveAttribute('data-render', /rendering|done/, { timeout: 60_000 });
    return page.evaluate(() => Math.round(window.longestTask));
  };
  const page10 = '/sketches/10-playground.html';
  const short = await longestTaskOpening(page10);
  const long = await longestTaskOpening(`${page10}#pad=${'xyz'.repeat(90_000)}`); // 270 kB, no dots
  test.info().annotations.push({ type: 'longest task opening (ms)', description: `short link ${short}, 270 kB link ${long}` });
  expect(long).toBeLessThan(Math.max(2000, 3 * short));
});
