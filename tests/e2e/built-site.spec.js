// The built site as a class gets it: published from a sub-path (GitHub Pages
// serves https://NAME.github.io/REPO/) by a plain static server, every page
// works, a share link round-trips, and no solution is in it.
import { test, expect } from '@playwright/test';
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { stripVTControlCharacters } from 'node:util';
import { watchConsole, waitForDone } from './helpers.js';
import { builtSite, serveFolder, removeBuiltSite, buildOutput } from './built-site.js';
import { setCode, waitForRun, sketchFrame } from './code-editor.js';
import { HOMEWORK, answerFingerprints, ELSEWHERE } from './homework-answers.js';

const BASE = '/some-name/';
const SKETCHES = readdirSync('sketches').filter((f) => /^\d\d-.*\.html$/.test(f));

let folder, site;
test.describe.configure({ mode: 'serial' });
test.beforeAll(async () => {
  test.setTimeout(300_000);
  folder = await builtSite(); // the build the project `built` is served from, when up to date
  site = await serveFolder(folder, BASE);
});
test.afterAll(async () => {
  await site?.close();
  if (folder) removeBuiltSite(folder);
});

test('the build prints no warning and no timings report: nothing a teacher running it must wonder about', () => {
  // At log level warn a clean build prints nothing at all: any line is a warning (rolldown's are [NAME] in colour).
  expect(stripVTControlCharacters(buildOutput).trim()).toBe('');
});

/** Every file of the built site, with its path inside it. */
function builtFiles(dir = folder, prefix = '') {
  return readdirSync(join(dir)).flatMap((name) => {
    const path = join(dir, name);
    try { return builtFiles(path, `${prefix}${name}/`); } catch { return [{ name: `${prefix}${name}`, text: readFileSync(path, 'latin1') }]; }
  });
}

test('from a sub-path every page loads only from it; every sketch traces to the end', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = watchConsole(page);
  const outside = [];
  page.on('request', (r) => {
    const url = new URL(r.url());
    if (!/^(data|blob):/.test(r.url()) && !(url.origin === new URL(site.url).origin && url.pathname.startsWith(BASE))) outside.push(r.url());
  });
  for (const path of ['', 'web-editor.html', 'api/']) {
    const answer = await page.goto(site.url + path);
    expect(answer.status(), path).toBe(200);
  }
  await page.goto(site.url);
  await expect(page.locator('#sketches a[href]')).toHaveCount(SKETCHES.length);
  for (const file of SKETCHES) {
    await page.goto(`${site.url}sketches/${file}`);
    await waitForDone(page, 60_000);
    await expect(page.locator('[data-tracer]').first()).toBeVisible();
    await expect(page.locator('.from-file')).toBeHidden();
    expect(errors.splice(0), `console on ${file}`).toEqual([]);
  }
  expect(outside).toEqual([]);
  expect(site.requests.filter((p) => !p.startsWith(BASE))).toEqual([]);
});

test('a share link made on the published site opens the same scene there', async ({ page, context }) => {
  const radius = 'objects[1].radius';
  await page.goto(`${site.url}sketches/05-value-boxes.html`);
  await waitForDone(page);
  const box = page.locator(`input[name="${radius}"]`);
  await box.fill('6');
  await box.press('Enter');
  await expect(page).toHaveURL(/\/some-name\/sketches\/05-value-boxes\.html#scene=z\.[A-Za-z0-9_-]+$/);
  const other = await context.newPage();
  await other.goto(page.url());
  await waitForDone(other);
  await expect(other.locator(`input[name="${radius}"]`)).toHaveValue('6');
  await expect(other.locator('[data-link-problem]')).toBeEmpty();
});

test('the playground\'s code, edited in the page, runs in its sandboxed frame from the sub-path', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = watchConsole(page);
  await page.goto(`${site.url}sketches/10-playground.html`);
  await waitForDone(page, 60_000);
  await setCode(page, readFileSync('sketches/10-playground.js', 'utf8').replace('const WIDTH = 64, HEIGHT = 48;', 'const WIDTH = 40, HEIGHT = 30;'));
  await waitForRun(page, 1, 120_000);
  await expect(sketchFrame(page).locator('[data-tracer]')).toHaveAttribute('data-width', '40');
  expect(site.requests).toContain(`${BASE}sketch-runtime.js`);
  expect(site.requests).toContain(`${BASE}sketch-code/10-playground.js`);
  expect(errors).toEqual([]);
});

test('"Edit this sketch" on a lesson page opens its code and runs it in its sandboxed frame from the sub-path', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = watchConsole(page);
  await page.goto(`${site.url}sketches/04-find-the-pink-pixel.html`);
  await waitForDone(page, 60_000);
  await page.locator('[data-edit-sketch]').click();
  await expect(page.locator('[data-editor]')).toContainText('Find the pink pixel', { timeout: 60_000 });
  await setCode(page, readFileSync('sketches/04-find-the-pink-pixel.js', 'utf8').replace('label: `The class scene: ', 'label: `My class scene: '));
  await waitForRun(page, 1, 120_000);
  await expect(sketchFrame(page).getByText('My class scene: 32 × 24 pixels')).toBeVisible();
  expect(site.requests).toContain(`${BASE}sketch-code/04-find-the-pink-pixel.js`);
  expect(errors).toEqual([]);
});

test('no solution is in the built files, only the line saying where it is', () => {
  const files = builtFiles();
  expect(files.filter((f) => /solutions\/|traffic-signal-[\w-]*\.js$|rear-lights-[\w-]*\.js$/.test(f.name) && !/homework/.test(f.name)).map((f) => f.name)).toEqual([]);
  for (const hw of HOMEWORK) {
    const prints = answerFingerprints(hw.solution);
    expect(prints.length, hw.solution).toBeGreaterThan(0);
    for (const print of prints) expect(files.filter((f) => f.text.includes(print)).map((f) => f.name), `${print} of ${hw.solution}`).toEqual([]);
  }
  expect(files.some((f) => f.name.endsWith('.js') && f.text.includes(ELSEWHERE))).toBe(true);
});

for (const hw of HOMEWORK) {
  test(`${hw.page}?solution=1 on the published site: the student's own scene, the line, and the check does not pass`, async ({ page }) => {
    const errors = watchConsole(page);
    await page.goto(`${site.url}sketches/${hw.page}?solution=1`);
    await waitForDone(page);
    await expect(page.locator('.rt-label')).toHaveText(hw.ownLabel);
    await expect(page.locator('.hw-warning')).toHaveText(ELSEWHERE);
    await page.getByRole('button', { name: 'Check my scene' }).click();
    await expect(page.locator('[data-check-results]')).toHaveAttribute('data-check', 'not-yet');
    expect(errors).toEqual([]);
  });
}
