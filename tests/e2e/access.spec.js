// Access: every page passes axe-core's WCAG 2.2 A and AA rules; every traced
// picture is an image described by its scene; one arrow press says a few
// words, not the whole inspector; the 3D view turns by keyboard; buttons
// answer Enter and Space.
import { test, expect } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { readdirSync } from 'node:fs';
import { expectQuietConsole, waitForDone } from './helpers.js';
import { ANNOUNCE_DELAY_MS } from '../../lib/p5/page/announce.js';

const SKETCHES = readdirSync(new URL('../../sketches/', import.meta.url)).filter((f) => f.endsWith('.html')).sort();
const PAGES = ['/', ...SKETCHES.map((f) => `/sketches/${f}`), '/web-editor.html', '/teacher.html', '/api/'];
const TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa'];

expectQuietConsole(test);

/** Waits for the page's pictures when it has any (the gallery's and the API reference's have none to trace). */
async function settle(page) {
  await page.waitForLoadState('load');
  if (await page.locator('[data-tracer]').count()) await waitForDone(page);
  // The pictures size themselves to their room a frame after it changes (tracer-layout.js's
  // watchRoom): on a busy machine axe could audit the page mid-move, buttons overlapping.
  await page.evaluate(() => document.fonts.ready.then(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)))));
}

/** The serious and critical violations, one line each: rule, impact, the first few elements. */
async function violations(page) {
  const { violations: found } = await new AxeBuilder({ page }).withTags(TAGS).analyze();
  return found.filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.id} (${v.impact}): ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}${v.nodes.length > 3 ? ` and ${v.nodes.length - 3} more` : ''}`);
}

/**
 * Every traced picture of a sketch is an image described by what its scene holds:
 * a colour name and a kind of shape, or a floor, or the word "Nothing" for an empty
 * scene; a second picture of the same scene from the same eye names the first
 * instead of saying it all again.
 */
async function expectDescribedPictures(page, file) {
  const pictures = page.locator('[data-tracer]');
  expect(await pictures.count(), file).toBeGreaterThan(0);
  const captions = [];
  for (const picture of await pictures.all()) {
    await expect(picture, file).toHaveAttribute('role', 'img');
    await expect(picture, file).toHaveAccessibleName(/.+/);
    const twin = captions.length ? `|The same scene as (${captions.map((c) => c.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')).join('|')}), seen from the same eye\\.$` : '';
    await expect(picture, file).toHaveAccessibleDescription(new RegExp(`\\b(sphere|box|plane|floor|wall|ceiling)\\b|Nothing${twin}`));
    captions.push(await picture.evaluate((c) => c.closest('figure')?.querySelector('figcaption')?.textContent.trim() || 'the picture before'));
  }
}

// Each page opened once: axe as it opens and with a pixel selected; on a sketch, its pictures' descriptions as it opens.
for (const path of PAGES) {
  test(`axe: no serious or critical WCAG 2.2 A/AA violation on ${path}${path.startsWith('/sketches/') ? '; every traced picture an image described by its scene' : ''}`, async ({ page }) => {
    test.setTimeout(path === '/api/' ? 180_000 : 90_000); // the API reference is one long page: axe reads it twice
    await page.goto(path);
    await settle(page);
    if (path.startsWith('/sketches/')) await expectDescribedPictures(page, path.slice('/sketches/'.length));
    expect(await violations(page), 'as it opens').toEqual([]);
    const tracer = page.locator('[data-tracer]').first();
    if (await tracer.count()) { // the inspector filled in, the 3D view drawn
      await tracer.focus();
      await page.keyboard.press('ArrowRight');
      await waitForDone(page);
      expect(await violations(page), 'with a pixel selected').toEqual([]);
    }
  });
}

test('sketch 01\'s picture is described as the scene shows it', async ({ page }) => {
  await page.goto('/sketches/01-rays-through-pixels.html');
  await waitForDone(page);
  await expect(page.locator('[data-tracer]')).toHaveAccessibleDescription(
    '32 by 24 pixels. A pink sphere in the middle; a blue sphere on the right, behind the pink sphere; and a gray floor, on a blue background. One light.');
});

test('the description follows the camera (sketch 04: turn it away from the spheres)', async ({ page }) => {
  await page.goto('/sketches/04-find-the-pink-pixel.html');
  await waitForDone(page);
  const picture = page.locator('[data-tracer]');
  await expect(picture).toHaveAccessibleDescription(/pink sphere in the middle/);
  const h = page.getByLabel('Camera H');
  await h.fill('180');
  await h.press('Tab'); // leaving the box turns the camera
  await waitForDone(page);
  await expect(picture).toHaveAccessibleDescription(/^32 by 24 pixels\. A gray floor, on a white background\. Four shapes are out of view\./);
});

test('"Picture as text" reads the traced picture row by row in colour names', async ({ page }) => {
  await page.goto('/sketches/01-rays-through-pixels.html');
  await waitForDone(page);
  await page.getByText('Picture as text').click();
  const rows = page.locator('[data-picture-rows] li');
  await expect(rows).toHaveCount(24); // one per row of pixels
  await expect(rows.nth(0)).toHaveText(/^Row 0: 0–\d+ blue/);
  await expect(page.locator('[data-picture-rows]')).toContainText('pink');
});

/**
 * Words that reach live regions (aria-live, role status / alert / log) while
 * `act` runs and `ms` after: each region's text as it is after each change.
 */
async function liveWords(page, act, ms = 700) {
  await page.evaluate(() => {
    window.liveText = [];
    const live = '[aria-live]:not([aria-live="off"]), [role="status"], [role="alert"], [role="log"]';
    window.liveObserver = new MutationObserver((records) => {
      const regions = new Set(records.map((r) => (r.target.nodeType === 1 ? r.target : r.target.parentElement)?.closest(live)).filter(Boolean));
      for (const region of regions) window.liveText.push(region.textContent.trim());
    });
    window.liveObserver.observe(document.body, { subtree: true, childList: true, characterData: true });
  });
  await act();
  await page.waitForTimeout(ms);
  return page.evaluate(() => {
    window.liveObserver.disconnect();
    return window.liveText.filter(Boolean);
  });
}

const words = (texts) => texts.join(' ').split(/\s+/).filter(Boolean).length;

for (const path of ['/sketches/01-rays-through-pixels.html', '/sketches/04-find-the-pink-pixel.html', '/sketches/10-playground.html']) {
  // on 04 the verdict speaks for the pixel: the line to type (the camera's H and V), then right or wrong
  const said = path.includes('04-') ? /^Pixel: \d+,\d+; H: 0; V: 0\. (Right|Wrong): .+\.$/ : /Pixel: \d+,\d+; H: -?\d+\.\d; V: -?\d+\.\d\. [A-Z][a-z]+, .+\./;
  test(`one arrow press says at most 40 words: the pixel's line, colour and hit (${path})`, async ({ page }) => {
    await page.goto(path);
    await waitForDone(page);
    const picture = page.locator('[data-tracer]').first();
    await picture.focus();
    await picture.press('ArrowRight');
    await page.waitForTimeout(500); // whatever the first selection said has been said
    const texts = await liveWords(page, () => picture.press('ArrowRight'));
    expect(words(texts), texts.join(' | ')).toBeLessThanOrEqual(40);
    expect(texts).toHaveLength(1); // one message, however many parts of the page had news
    expect(texts[0]).toMatch(said);
    await expect(page.locator('[data-inspector]').first()).not.toHaveAttribute('aria-live');
  });
}

test('sketch 01: the status says the pixel\'s line, its colour name and what the ray hit', async ({ page }) => {
  await page.goto('/sketches/01-rays-through-pixels.html');
  await waitForDone(page);
  const picture = page.locator('[data-tracer]');
  await picture.focus();
  await picture.press('ArrowRight'); // from nothing: the middle pixel, 16,12
  await expect(page.locator('[data-announce="pixel"]')).toHaveText(/^Pixel: 16,12; H: 0\.\d; V: -0\.\d\. Pink, the pink sphere\.$/);
  // said by the page's one atomic status, first, with the tasks the press did
  const status = page.locator('[data-announce="page"]');
  await expect(status).toHaveAttribute('role', 'status');
  await expect(status).toHaveAttribute('aria-atomic', 'true');
  await expect(status).toHaveText(/^Pixel: 16,12; H: 0\.\d; V: -0\.\d\. Pink, the pink sphere\. Tasks done \(2 of 6\): Select any pixel; /);
});

test('a held arrow key is said once, when it rests (debounced)', async ({ page }) => {
  await page.goto('/sketches/01-rays-through-pixels.html');
  await waitForDone(page);
  const picture = page.locator('[data-tracer]');
  await picture.focus();
  // A key's own repeat, in the page: a keydown every 40 ms. A repeat is a held key only if it
  // comes within the rest time (ANNOUNCE_DELAY_MS, 200 ms): on a machine so busy that the page's
  // thread stalled longer between two, the burst is made again from where it ended (at most twice).
  let texts, longestGap, from = 16;
  for (let tries = 0; tries < 3; tries++) {
    let gaps;
    texts = await liveWords(page, async () => {
      gaps = await page.evaluate(async () => {
        const picture = document.querySelector('[data-tracer]');
        const at = [];
        for (let i = 0; i < 8; i++) {
          at.push(performance.now());
          picture.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowRight', bubbles: true }));
          await new Promise((resolve) => setTimeout(resolve, 40));
        }
        return at.slice(1).map((t, i) => t - at[i]);
      });
    });
    longestGap = Math.max(...gaps);
    from += 8;
    if (longestGap < ANNOUNCE_DELAY_MS) break;
  }
  expect(longestGap, 'the repeats came within the rest time').toBeLessThan(ANNOUNCE_DELAY_MS);
  const pixelLines = texts.filter((text) => text.startsWith('Pixel:')); // the page's task list may say a task is done, too
  expect(pixelLines).toHaveLength(1);
  expect(pixelLines[0]).toMatch(new RegExp(`^Pixel: ${Math.min(from - 1, 31)},12;`));
});

test('the 3D view turns with the arrow keys and zooms with + and −, and by its buttons (Enter, Space)', async ({ page }) => {
  await page.goto('/sketches/01-rays-through-pixels.html');
  await waitForDone(page);
  const view3d = page.locator('[data-view3d]');
  await expect(view3d).toHaveAttribute('data-yaw', '-35');
  await expect(view3d).toHaveAttribute('tabindex', '0');
  await expect(view3d).toHaveAccessibleName(/arrow keys/);
  await view3d.focus();
  const scrolled = await page.evaluate(() => window.scrollY);
  await view3d.press('ArrowLeft');
  await expect(view3d).toHaveAttribute('data-yaw', '-25');
  await view3d.press('ArrowDown');
  await expect(view3d).toHaveAttribute('data-pitch', '30');
  const distance = Number(await view3d.getAttribute('data-distance'));
  await view3d.press('+');
  await expect.poll(async () => Number(await view3d.getAttribute('data-distance'))).toBeLessThan(distance);
  expect(await page.evaluate(() => window.scrollY)).toBe(scrolled); // the keys turn the view, not the page
  await page.getByRole('button', { name: 'Turn right' }).press('Enter');
  await expect(view3d).toHaveAttribute('data-yaw', '-35');
  await page.getByRole('button', { name: 'Turn right' }).press(' ');
  await expect(view3d).toHaveAttribute('data-yaw', '-45');
  await page.getByRole('button', { name: 'Reset view' }).press('Enter');
  await expect(view3d).toHaveAttribute('data-yaw', '-35');
});

test('Shoot rays can be stopped, by the Stop button and by Esc', async ({ page }) => {
  await page.goto('/sketches/01-rays-through-pixels.html');
  await waitForDone(page);
  const shoot = page.getByRole('button', { name: 'Shoot rays' });
  const stop = page.locator('[data-view3d-stop]');
  await expect(stop).toBeDisabled();
  for (const how of ['button', 'Escape']) {
    await shoot.press('Enter');
    await expect(stop).toBeEnabled();
    await expect(page.locator('body')).toHaveAttribute('data-render', 'rendering');
    if (how === 'button') await stop.click(); else await page.locator('[data-view3d]').press('Escape');
    await expect(stop).toBeDisabled();
    await waitForDone(page, 10_000); // the rest at full speed: at 4 rays/s the 768 pixels would take minutes
    expect(await page.evaluate(() => document.querySelector('[data-tracer]') && true)).toBe(true);
  }
});

test('"Trace again" (01) answers Enter and Space', async ({ page }) => {
  await page.goto('/sketches/01-rays-through-pixels.html');
  await waitForDone(page);
  const again = page.getByRole('button', { name: 'Trace again' });
  for (const key of ['Enter', ' ']) {
    await page.evaluate(() => { window.restarted = false; new MutationObserver(() => { if (document.body.dataset.render === 'rendering') window.restarted = true; }).observe(document.body, { attributes: true }); });
    await again.press(key);
    await expect.poll(() => page.evaluate(() => window.restarted)).toBe(true);
    await waitForDone(page);
  }
});

test('the photon picture (00) takes focus and moves the selected pixel with the arrow keys', async ({ page }) => {
  await page.goto('/sketches/00-light-or-eye.html');
  await waitForDone(page);
  const photons = page.locator('[data-photons]');
  await expect(photons).toHaveAttribute('role', 'img');
  await photons.focus();
  await expect(photons).toBeFocused();
  await photons.press('ArrowRight');
  await photons.press('ArrowDown');
  await expect(page.locator('[data-view3d]')).toHaveAttribute('data-selected', '17,15'); // from 16,14
});

test('sketch 04: the overlay is hidden from the tree and the pink count is a status', async ({ page }) => {
  await page.goto('/sketches/04-find-the-pink-pixel.html');
  await waitForDone(page);
  await expect(page.locator('[data-overlay]').last()).toHaveAttribute('aria-hidden', 'true');
  const count = page.locator('[data-pink-count]');
  await expect(count).toHaveAttribute('role', 'status');
  await page.locator('[data-show-pink]').check();
  await expect(count).toContainText(/\d+ of 768 pixels are pink/);
});

test('the homework self-check says "to fix" in words and announces its verdict', async ({ page }) => {
  await page.goto('/sketches/08-homework-traffic-signal.html');
  await waitForDone(page);
  await page.getByRole('button', { name: 'Check my scene' }).press('Enter');
  const failed = page.locator('[data-check-item="failed"]');
  await expect(failed.first()).toContainText('To fix: '); // the ✗ before it is hidden from screen readers
  await expect(failed.first().locator('.hw-mark')).toHaveAttribute('aria-hidden', 'true');
  await expect(page.locator('[data-announce="check"]')).toHaveText(/^Not yet: \d+ checks? to fix\. To fix: .+\.$/);
});
