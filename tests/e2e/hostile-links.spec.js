// Hostile links: an HTML payload in every parameter every page reads (the
// query and the fragment; list in link-parameters.js) and in a shared scene's
// names never runs and never becomes an element; the page says what it got,
// as text.
import { test, expect } from '@playwright/test';
import { readdirSync } from 'node:fs';
import { watchConsole, waitForDone, clickPixel } from './helpers.js';
import { EVERY_PAGE, PAGE_PARAMETERS } from './link-parameters.js';
import { sceneToJSON } from '../../lib/scene/json.js';
import { classScene } from '../../lib/scene/examples.js';
import { encodeScene } from '../../lib/scene/codec.js';
import { encodeSceneLink, readSceneLink } from '../../lib/p5/page/scene-link.js';

const PAGES = ['index.html', 'teacher.html', ...readdirSync('sketches').filter((f) => f.endsWith('.html')).map((f) => `sketches/${f}`)];
const PAYLOADS = [
  '<img src=x onerror="window.__pwned=1;alert(1)">',
  '"><svg onload="window.__pwned=2;alert(2)"></svg>',
];

/** Watches a page for dialogs and console errors; `expectInert` checks and clears them. */
function guard(page) {
  const dialogs = [];
  page.on('dialog', (d) => { dialogs.push(d.message()); d.dismiss().catch(() => {}); });
  return { page, dialogs, errors: watchConsole(page) };
}

/** Opens `url`, and checks that nothing in it ran or became an element. */
async function expectInert({ page, dialogs, errors }, url) {
  await page.goto(url);
  if (url.startsWith('/sketches/')) await expect(page.locator('body')).toHaveAttribute('data-render', /rendering|done/);
  await page.waitForLoadState('load');
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => setTimeout(r, 50)))); // an injected <img> would have failed by now
  expect(dialogs.splice(0), `dialogs on ${url}`).toEqual([]);
  expect(await page.evaluate(() => window.__pwned), `script ran on ${url}`).toBeUndefined();
  expect(await page.locator('[onerror], [onload], img[src="x"]').count(), `injected element on ${url}`).toBe(0);
  expect(errors.splice(0), `console on ${url}`).toEqual([]);
}

test.describe('an HTML payload in each parameter of each page', () => {
  for (const path of PAGES) {
    const params = [...EVERY_PAGE.map((name) => ({ name, where: 'query' })), ...(PAGE_PARAMETERS[path] ?? [])];
    test(path, async ({ page }) => {
      const watched = guard(page);
      for (const { name, where } of params) {
        for (const payload of PAYLOADS) {
          const part = `${name}=${encodeURIComponent(payload)}`;
          await expectInert(watched, `/${path}${where === 'query' ? `?${part}` : `#${part}`}`);
        }
      }
    });
  }

  test('the homework pages show what the link said, as text', async ({ page }) => {
    await page.goto(`/sketches/08-homework-traffic-signal.html?solution=${encodeURIComponent(PAYLOADS[0])}`);
    await expect(page.locator('.hw-warning')).toContainText('<img src=x onerror=');
  });

  test('every page of the gallery is in the list', () => {
    for (const path of Object.keys(PAGE_PARAMETERS)) expect(PAGES).toContain(path);
    expect(PAGES.length).toBeGreaterThanOrEqual(11);
  });
});

test('a shared scene whose names are HTML shows them as text', async ({ page }) => {
  const json = sceneToJSON(classScene());
  json.objects.forEach((o, i) => { o.name = PAYLOADS[i % PAYLOADS.length]; });
  const path = '/sketches/05-value-boxes.html';
  await expectInert(guard(page), `${path}?scene=${encodeScene(json)}`);
  await expect(page.locator('body')).toHaveAttribute('data-render', 'done', { timeout: 30_000 });
  await page.locator('[data-tracer]').first().click({ position: { x: 240, y: 180 } });
  expect(await page.locator('[onerror], [onload]').count()).toBe(0);
  await expect(page.locator('#values')).toContainText('<img src=x');
});

test('a link too long for the dev server says so on the page (not Node\'s bare 431)', async ({ page }) => {
  const answer = await page.goto(`/sketches/05-value-boxes.html?scene=${'A'.repeat(20_000)}`);
  expect(answer.status()).toBe(431);
  await expect(page.locator('h1')).toHaveText('This link is too long');
  await expect(page.locator('[data-link-too-long]')).toContainText('#scene=');
});

test('a 100,000-character name is cut on page 05 (the whole name in its title), and kept whole in the link', async ({ page }) => {
  const errors = watchConsole(page);
  const long = `pink ${'x'.repeat(100_000)}`;
  const json = sceneToJSON(classScene());
  json.objects.find((o) => o.name === 'pink').name = long;
  await page.goto(`/sketches/05-value-boxes.html#scene=${await encodeSceneLink(json)}`);
  await waitForDone(page);
  const width = () => page.evaluate(() => document.documentElement.scrollWidth);
  expect(await width()).toBeLessThanOrEqual(1280); // the viewport: a million pixels wide before
  const th = page.locator('[data-table="sphere"] tbody th[title]');
  await expect(th).toHaveCount(1);
  expect(await th.getAttribute('title')).toBe(long);
  expect(await th.textContent()).toBe(`${long.slice(0, 39)}…`);
  await expect(page.locator(`input[aria-label^="Sphere 2 (${long.slice(0, 39)}…) "]`).first()).toBeAttached(); // labels and messages name it cut

  await clickPixel(page.locator('[data-tracer]'), 80, 60); // the pink sphere, in the middle
  const hit = page.locator('[data-inspector] [data-field="hit-object"]');
  await expect(hit).toHaveText(`${long.slice(0, 39)}…`);
  expect(await hit.getAttribute('data-value')).toBe(long);
  expect(await width()).toBeLessThanOrEqual(1280);

  // An edit puts the scene in the link again: the name whole.
  const before = await page.evaluate(() => location.hash);
  const radius = page.locator('input[name="objects[2].radius"]');
  await radius.fill('2.5');
  await radius.press('Enter');
  await expect.poll(() => page.evaluate(() => location.hash)).not.toBe(before);
  // read back here, by the kit's own reader (the built site has no module of that name to import)
  const names = (await readSceneLink(page.url())).objects.map((o) => o.name);
  expect(names).toContain(long);
  expect(errors).toEqual([]);
});
