// Code in the page (editor/, pages 08, 09, 10): the editor runs its code in a
// sandboxed frame; a link's code waits for Run and cannot read the kit's
// storage; mistakes at the editor's line; the pixel kept across runs; the
// code kept in this browser, reset, downloaded and shared.
import { readFileSync } from 'node:fs';
import { test, expect } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { clickPixel, waitForDone, watchConsole } from './helpers.js';
import { setCode, editorText, waitForRun, sketchFrame, codeLink } from './code-editor.js';
import { Scene, Sphere, PointLight, Camera, inspectPixel } from '../../lib/index.js';

const PLAYGROUND = '/sketches/10-playground.html';
const STARTER = readFileSync('sketches/10-playground.js', 'utf8');
// Each run starts a frame with p5 and the kit in it: seconds on a busy machine.
test.describe.configure({ timeout: 180_000 });

const SECRET = 'the teacher\'s board key 8c1f';

test('the editor holds the sketch\'s own file, labelled, with line numbers, and the sketch runs in a frame sandboxed without allow-same-origin', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto(PLAYGROUND);
  await waitForDone(page);
  const editor = page.locator('[data-editor]');
  await expect(editor).toHaveAttribute('aria-label', 'Code of the sketch, 10-playground.js');
  await expect(editor).toHaveAttribute('contenteditable', 'true');
  expect(await editorText(page)).toBe(STARTER.replace(/\n$/, '\n'));
  await expect(page.locator('.cm-lineNumbers .cm-gutterElement').filter({ hasText: /^12$/ })).toHaveCount(1);
  await page.getByRole('button', { name: 'Run' }).click();
  await waitForRun(page, 1);
  const frame = page.locator('iframe[data-code-frame="running"]');
  const sandbox = await frame.getAttribute('sandbox');
  expect(sandbox.split(/\s+/)).toContain('allow-scripts');
  expect(sandbox).not.toMatch(/allow-same-origin/);
  await expect(sketchFrame(page).locator('[data-tracer]')).toHaveAttribute('data-width', '64');
  await expect(page.locator('main#sketch [data-tracer]')).toHaveCount(0); // the page's own sketch made way
  expect(errors).toEqual([]);
});

test('a link\'s code does not run before Run, and when it runs it cannot read the kit\'s storage or page', async ({ page }) => {
  await page.goto(PLAYGROUND);
  await page.evaluate((secret) => localStorage.setItem('raytracing-sketchbook:secret', secret), SECRET);
  const spy = STARTER.replace('new p5((p) => {', `const seen = [];
for (const read of [() => localStorage.getItem('raytracing-sketchbook:secret'), () => parent.localStorage.getItem('raytracing-sketchbook:secret'),
  () => parent.document.title, () => top.location.href]) {
  try { seen.push(String(read())); } catch (error) { seen.push(error.name); }
}
document.body.dataset.ran = 'yes';
document.body.dataset.seen = JSON.stringify(seen);
new p5((p) => {`);
  await page.goto(codeLink(PLAYGROUND, spy));
  await waitForDone(page); // the page's own sketch, the starter, is traced as ever
  await expect(page.locator('[data-code-status]')).toContainText('This code came in a link: read it first, then press Run.');
  expect(await editorText(page)).toContain('document.body.dataset.ran');
  await page.locator('[data-editor]').focus();
  await page.keyboard.type(' '); // typing does not run it either
  await page.waitForTimeout(2_000); // more than the pause after which typed code runs
  await expect(page.locator('iframe')).toHaveCount(0);
  expect(await page.evaluate(() => localStorage.getItem('raytracing-sketchbook:code:v1:10-playground'))).toBeNull(); // nor is it kept

  await page.getByRole('button', { name: 'Run' }).click();
  await waitForRun(page, 1);
  const body = sketchFrame(page).locator('body');
  await expect(body).toHaveAttribute('data-ran', 'yes');
  const seen = JSON.parse(await body.getAttribute('data-seen'));
  expect(seen).toEqual(['null', 'SecurityError', 'SecurityError', 'SecurityError']); // its own empty storage; the page's is out of reach
  expect(seen.join(' ')).not.toContain(SECRET);
});

test('a mistake shows in the page\'s mistakes panel at the editor\'s line, and the last good picture stays', async ({ page }) => {
  await page.goto(PLAYGROUND);
  await waitForDone(page);
  await page.getByRole('button', { name: 'Run' }).click();
  await waitForRun(page, 1);
  const lines = STARTER.split('\n');
  const at = lines.findIndex((line) => line.includes('new Sphere(')) + 1; // 1-based
  await setCode(page, STARTER.replace('new Sphere(', 'new Sphre('));
  const panel = page.locator('[data-error]');
  await expect(panel).toBeVisible({ timeout: 30_000 });
  await expect(panel.locator('[data-error-message]')).toContainText('ReferenceError: Sphre is not defined');
  await expect(panel.locator('[data-error-where]')).toHaveText(`10-playground.js (the editor):${at}`);
  await expect(panel.locator('[data-error-source]')).toContainText(`${at} │ scene.add(new Sphre(`);
  await expect(panel.locator('[data-error-suggestion]')).toContainText('Sphere');
  await expect(page.locator('[data-code-status]')).toHaveText(`Your code stopped at a mistake on line ${at}: the picture is the last one that ran.`);
  await expect(page.locator('iframe')).toHaveCount(1); // the run before it, still showing its picture
  await expect(sketchFrame(page).locator('[data-tracer]')).toBeVisible();

  await setCode(page, STARTER.replace('[1, 0.32, 0.36]', '[0.2, 0.4, 1]'));
  await waitForRun(page, 3);
  await expect(panel).toHaveCount(0); // mended: the panel goes, as after a save
});

test('the selected pixel stays selected when the edited code runs again', async ({ page }) => {
  await page.goto(PLAYGROUND);
  await waitForDone(page);
  await clickPixel(page.locator('[data-tracer]'), 20, 10); // in the page's own sketch, before any run
  await page.getByRole('button', { name: 'Run' }).click();
  await waitForRun(page, 1);
  const answer = sketchFrame(page).locator('[data-inspector] [data-answer]');
  await expect(answer).toHaveText(/^Pixel: 20,10; /);
  await clickPixel(sketchFrame(page).locator('[data-tracer]'), 30, 12);
  await expect(answer).toHaveText(/^Pixel: 30,12; /);
  await setCode(page, STARTER.replace('[1, 0.32, 0.36]', '[0.2, 0.4, 1]'));
  await waitForRun(page, 2);
  await expect(answer).toHaveText(/^Pixel: 30,12; /);
  await expect(sketchFrame(page).locator('[data-inspector] .rt-color-name')).toHaveText('blue');
});

test('the page\'s own task list judges what the edited code built, through every Run; a scene it cannot read is named, and nothing breaks', async ({ page }) => {
  const errors = watchConsole(page);
  const OWN = 'scene.add(new Sphere([6, 1, -26], 2, { color: [0, 0, 0], emission: 1 }));';
  // A pixel of that sphere, as the page's own tracer finds it.
  const scene = new Scene({ background: [0.85, 0.92, 1], ambient: 0.1 }).add(new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] }))
    .add(new PointLight([-10, 20, 0])).add(new Sphere([6, 1, -26], 2, { color: [0, 0, 0], emission: 1 }));
  const camera = new Camera({ width: 64, height: 48, fov: 30 });
  let own = null;
  for (let y = 0; y < 48 && !own; y++) for (let x = 0; x < 64 && !own; x++) if (inspectPixel(scene, camera, x, y).hit?.object === scene.objects[1]) own = { x, y };
  await page.goto(PLAYGROUND);
  await waitForDone(page);
  await setCode(page, STARTER.replace('scene.add(new PointLight', `${OWN}\n  scene.add(new PointLight`));
  await waitForRun(page, 1);
  const tasks = page.locator('[data-code-judged] [data-tasks="10"]');
  await expect(tasks.locator('[data-task="glow"]')).toHaveAttribute('data-done', 'true');
  await expect(sketchFrame(page).locator('[data-tasks]')).toHaveCount(0); // the frame shows no list of its own
  await clickPixel(sketchFrame(page).locator('[data-tracer]'), own.x, own.y);
  await expect(tasks.locator('[data-task="select"]')).toHaveAttribute('data-done', 'true');
  await expect(tasks.locator('[data-task="own"]')).toHaveAttribute('data-done', 'true');
  expect(await page.evaluate(() => JSON.parse(localStorage.getItem('raytracing-sketchbook:tasks:v1')).pages['10'])).toEqual(expect.arrayContaining(['glow', 'select', 'own']));

  // Code that sends the page a scene that is not JSON: the page names it, keeps its list, and judges nothing from it.
  await setCode(page, `${STARTER}\nsetTimeout(() => parent.postMessage({ type: 'scene', scene: '{"objects": [', camera: '{}', mode: 'shaded', order: 'coarse' }, '*'), 1000);\n`);
  await waitForRun(page, 2);
  await expect(page.locator('[data-judge-status]')).toHaveText(/^The scene your code built could not be read: scene is not valid JSON/);
  await expect(tasks.locator('[data-task="own"]')).toHaveAttribute('data-done', 'true');
  await clickPixel(sketchFrame(page).locator('[data-tracer]'), 3, 3); // no scene to judge it by: no task, no mistake
  await expect(tasks.locator('[data-task="mirror"]')).toHaveAttribute('data-done', 'false');
  await setCode(page, STARTER);
  await waitForRun(page, 3);
  await expect(page.locator('[data-judge-status]')).toBeHidden(); // the next run's scene is read again
  await expect(page.locator('[data-tasks]')).toHaveCount(1);
  expect(errors).toEqual([]);
});

test('the student\'s code is kept in this browser; Reset brings back the starter, Download saves the file, Copy share link carries the code', async ({ page }) => {
  await page.goto(PLAYGROUND);
  await waitForDone(page);
  const mine = STARTER.replace('const WIDTH = 64, HEIGHT = 48;', 'const WIDTH = 32, HEIGHT = 24;');
  await setCode(page, mine);
  await waitForRun(page, 1);
  await expect(sketchFrame(page).locator('[data-tracer]')).toHaveAttribute('data-width', '32');

  await page.reload();
  await waitForRun(page, 1); // the kept code runs at once: it is the student's own
  expect(await editorText(page)).toBe(mine);
  await expect(sketchFrame(page).locator('[data-tracer]')).toHaveAttribute('data-width', '32');

  const download = page.waitForEvent('download');
  await page.getByRole('button', { name: 'Download', exact: true }).click();
  const file = await download;
  expect(file.suggestedFilename()).toBe('10-playground.js');
  expect(readFileSync(await file.path(), 'utf8')).toBe(mine);

  await page.getByRole('button', { name: 'Copy share link' }).click();
  const linkBox = page.locator('input.code-link');
  await expect(linkBox).toHaveValue(/\/sketches\/10-playground\.html#code=z\.[\w-]+$/); // made once the code is compressed (async)
  const link = await linkBox.inputValue();

  await page.getByRole('button', { name: 'Reset to the starter' }).click();
  await waitForRun(page, 2);
  expect(await editorText(page)).toBe(STARTER);
  await expect(sketchFrame(page).locator('[data-tracer]')).toHaveAttribute('data-width', '64');
  expect(await page.evaluate(() => localStorage.getItem('raytracing-sketchbook:code:v1:10-playground'))).toBeNull();

  await page.goto(link);
  await expect(page.locator('[data-code-status]')).toContainText('This code came in a link');
  expect(await editorText(page)).toBe(mine);
});

test('with its code running: axe finds no serious violation, the page reflows at 320 px, and Esc then Tab leaves the editor', async ({ page }) => {
  await page.goto('/sketches/08-homework-traffic-signal.html');
  await waitForDone(page);
  await page.getByRole('button', { name: 'Run' }).click();
  await waitForRun(page, 1);
  const { violations } = await new AxeBuilder({ page }).withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa']).analyze();
  expect(violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.id}: ${v.nodes[0].target.join(' ')}`)).toEqual([]);

  await page.locator('[data-editor]').focus();
  await page.keyboard.press('Tab');
  await expect(page.locator('[data-editor]')).toBeFocused(); // Tab indents
  await page.keyboard.press('Escape');
  await page.keyboard.press('Tab');
  await expect(page.locator('[data-editor]')).not.toBeFocused();
  await expect(page.locator('#code-help')).toContainText('press Esc, then Tab');

  await page.setViewportSize({ width: 320, height: 700 });
  await page.waitForTimeout(500);
  expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(320);
  const frameWidth = await sketchFrame(page).locator('html').evaluate((html) => html.scrollWidth);
  expect(frameWidth).toBeLessThanOrEqual(320);
});

test('a loop that never ends is stopped and said, the page answers all the while, and the mended code runs again', async ({ page }) => {
  await page.goto(PLAYGROUND);
  await waitForDone(page);
  await page.getByRole('button', { name: 'Run' }).click();
  await waitForRun(page, 1);
  await setCode(page, STARTER.replace('function makeScene() {', 'function makeScene() {\n  for (let i = 0; i < 10; i--) {}'));
  await expect(page.locator('[data-code-status]')).toHaveText('Running your code (run 2)…');
  expect(await page.evaluate(() => document.title)).toBe('10 · Playground'); // the page is not held up by the frame's loop
  const panel = page.locator('[data-error]');
  await expect(panel.locator('[data-error-message]')).toHaveText(/^Your code did not answer for 8 s: is there a loop that never ends/, { timeout: 30_000 });
  await expect(panel).toContainText('Fix it in the editor');
  await expect(page.locator('[data-code-status]')).toHaveText(/^Your code was stopped/);
  await expect(page.locator('iframe[data-code-frame="starting"]')).toHaveCount(0); // the stuck frame is gone, and its loop with it

  await setCode(page, STARTER);
  await waitForRun(page, 3, 120_000);
  await expect(panel).toHaveCount(0);
});
