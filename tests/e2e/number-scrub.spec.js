// Number scrubbing in the page's editor (editor/number-scrub.js, live-numbers.js):
// Alt+↑/↓ and Alt+drag on a number of the scene move the picture without a new
// run, and the picture is the same bytes as the rewritten code run from scratch;
// a number that is not a field of the scene runs the code again; one Undo brings
// code and picture back; Alt+↑/↓ elsewhere still move the line; nothing the frame
// sends changes the code.
import { readFileSync } from 'node:fs';
import { test, expect } from '@playwright/test';
import { waitForDone, watchConsole, clickPixel } from './helpers.js';
import { setCode, editorText, waitForRun, sketchFrame } from './code-editor.js';

const PLAYGROUND = '/sketches/10-playground.html';
const STARTER = readFileSync('sketches/10-playground.js', 'utf8');
test.describe.configure({ timeout: 180_000 });

/** The traced picture's bytes in the running frame, as one string (to compare). */
const picture = (page) => sketchFrame(page).locator('canvas[data-tracer]').evaluate((canvas) => {
  const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
  let text = '';
  for (let i = 0; i < data.length; i += 4096) text += String.fromCharCode(...data.subarray(i, i + 4096));
  return btoa(text);
});

/** The frame's picture, once it differs from `before` and is traced to the end. */
async function pictureAfter(page, before) {
  // A frame out of view gets no animation frames (Chromium's throttling): look at it, as the student does.
  await page.locator('iframe[data-code-frame="running"]').scrollIntoViewIfNeeded();
  await expect.poll(() => picture(page), { timeout: 30_000 }).not.toBe(before);
  await expect(sketchFrame(page).locator('body')).toHaveAttribute('data-render', 'done', { timeout: 30_000 });
  return picture(page);
}

/** The editor's text (Download), the caret back in the editor where it was. */
async function codeNow(page) {
  const text = await editorText(page);
  await page.locator('[data-editor]').focus();
  return text;
}

/** The number `n` (0-based) among the marked numbers of the line holding `text`. */
const numberIn = (page, text, n) => page.locator('.cm-line', { hasText: text }).locator('.cm-scrub-number').nth(n);

/** The page, its own sketch traced and its editor loaded, then its first Run. */
async function openAndRun(page, path) {
  await page.goto(path);
  await waitForDone(page);
  await expect(page.locator('[data-editor]')).toBeVisible();
  await page.getByRole('button', { name: 'Run' }).click();
  await waitForRun(page, 1);
}

/** Runs the editor's code from scratch (Run) as run `n`, and returns its finished picture. */
async function runFromScratch(page, n) {
  await page.getByRole('button', { name: 'Run' }).click();
  await waitForRun(page, n);
  return picture(page);
}

/** Marks the frame on show, to tell later whether the same frame is still there. */
const markFrame = (page) => page.locator('iframe[data-code-frame="running"]').evaluate((f) => { f.dataset.marked = 'yes'; });
const markedFrame = (page) => page.locator('iframe[data-code-frame="running"][data-marked="yes"]');

test('Alt+↑ on the radius: the first step runs the code, the next ones reach the picture as values, the same bytes as the code run from scratch, and Undo brings it back', async ({ page }) => {
  const errors = watchConsole(page);
  await openAndRun(page, PLAYGROUND);
  const first = await picture(page);
  const status = page.locator('[data-code-status]');

  await numberIn(page, 'new Sphere(', 3).click(); // the radius, 4
  await page.keyboard.press('Alt+ArrowUp');
  expect(await codeNow(page)).toBe(STARTER.replace('-20], 4,', '-20], 5,'));
  await waitForRun(page, 2); // the literal's first step runs the code: the page learns that it is the sphere's radius
  const five = await picture(page);
  expect(five).not.toBe(first);

  await markFrame(page);
  await page.keyboard.press('Alt+ArrowUp');
  await expect(status).toHaveText('radius 6'); // the live region says what changed
  const six = await pictureAfter(page, five);
  await expect(markedFrame(page)).toHaveCount(1); // no new run: the same frame traced again
  expect(await codeNow(page)).toBe(STARTER.replace('-20], 4,', '-20], 6,'));

  await page.keyboard.press('ControlOrMeta+z'); // one Undo: the code and the picture of radius 5
  await expect(status).toHaveText('radius 5');
  expect(await codeNow(page)).toBe(STARTER.replace('-20], 4,', '-20], 5,'));
  expect(await pictureAfter(page, six)).toBe(five);

  await page.keyboard.press('Control+y'); // Redo, and the picture of 6 from scratch is the scrubbed one
  await expect(status).toHaveText('radius 6');
  expect(await pictureAfter(page, five)).toBe(six);
  expect(await runFromScratch(page, 3)).toBe(six);
  expect(errors).toEqual([]);
});

test('Shift+Alt+↑ moves ten steps; Alt+↑ outside a number still moves the line; a number that is no field of the scene runs the code again', async ({ page }) => {
  await openAndRun(page, PLAYGROUND);
  const status = page.locator('[data-code-status]');

  await numberIn(page, 'new Sphere(', 0).click(); // the centre's x, 0
  await page.keyboard.press('Alt+ArrowUp');
  await waitForRun(page, 2);
  const one = await picture(page);
  await page.keyboard.press('Shift+Alt+ArrowUp');
  await expect(status).toHaveText('center x 11');
  const eleven = await pictureAfter(page, one);
  expect(await codeNow(page)).toBe(STARTER.replace('[0, 0, -20], 4', '[11, 0, -20], 4'));
  expect(await runFromScratch(page, 3)).toBe(eleven);

  await page.locator('.cm-line', { hasText: 'new PointLight(' }).getByText('scene.add').click(); // not a number
  await page.keyboard.press('Alt+ArrowUp'); // CodeMirror's own key: the line moves up
  const lines = (await codeNow(page)).split('\n');
  const light = lines.findIndex((line) => line.includes('new PointLight('));
  expect(lines[light + 1]).toContain('new Sphere(');
  await waitForRun(page, 4); // an edit as any other: the code runs again after the pause

  await numberIn(page, 'const WIDTH', 0).click(); // the canvas's width: not a field of the scene
  await page.keyboard.press('Alt+ArrowUp');
  await waitForRun(page, 5);
  await expect(sketchFrame(page).locator('canvas[data-tracer]')).toHaveAttribute('data-width', '65');
  await page.keyboard.press('Alt+ArrowUp'); // known now not to be a field of the scene: it runs after the pause, as typing does
  await expect(status).toHaveText('66: your code runs again');
  await waitForRun(page, 6);
  await expect(sketchFrame(page).locator('canvas[data-tracer]')).toHaveAttribute('data-width', '66');
});

test('Alt+drag on a homework light\'s number: a sideways cursor shows it can be dragged, the picture follows, one Undo brings code and picture back', async ({ page }) => {
  await page.goto('/sketches/09-homework-rear-lights.html');
  await waitForDone(page);
  const starter = await codeNow(page);
  const code = starter.replace('  // TODO: your two rear lights here.', '  scene.add(new Sphere([2, 0.5, -6.5], 0.5, { color: [0, 0, 0], emission: [1, 0, 0] }));');
  await setCode(page, code);
  await waitForRun(page, 1);
  const before = await picture(page);

  const x = numberIn(page, 'emission: [1, 0, 0]', 0); // the light's x, 2
  await x.scrollIntoViewIfNeeded();
  const box = await x.boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.keyboard.down('Alt');
  await page.mouse.move(box.x + box.width / 2 + 1, box.y + box.height / 2);
  expect(await x.evaluate((el) => getComputedStyle(el).cursor)).toBe('ew-resize'); // the cue
  await page.mouse.down();
  for (let dx = 6; dx <= 30; dx += 6) await page.mouse.move(box.x + box.width / 2 - dx, box.y + box.height / 2); // 5 steps to the left
  await page.mouse.up();
  await page.keyboard.up('Alt');
  const moved = code.replace('new Sphere([2, 0.5, -6.5], 0.5,', 'new Sphere([-3, 0.5, -6.5], 0.5,');
  await expect.poll(() => codeNow(page)).toBe(moved);
  await expect(page.locator('[data-code-status]')).toHaveText('center x -3', { timeout: 60_000 });
  const dragged = await pictureAfter(page, before);

  await page.locator('[data-editor]').focus();
  await page.keyboard.press('ControlOrMeta+z'); // the whole drag is one step of the history
  expect(await codeNow(page)).toBe(code);
  await expect(page.locator('[data-code-status]')).toHaveText('center x 2');
  expect(await pictureAfter(page, dragged)).toBe(before);

  await page.keyboard.press('Control+y');
  expect(await pictureAfter(page, before)).toBe(dragged);
  await page.getByRole('button', { name: 'Run' }).click();
  await expect(page.locator('[data-code-status]')).toHaveText(/Your code ran \(run \d+\)\./, { timeout: 60_000 });
  await expect(page.locator('body')).toHaveAttribute('data-render', 'done', { timeout: 60_000 });
  expect(await picture(page)).toBe(dragged); // the rewritten code from scratch: the same bytes
});

test('nothing the frame sends changes the code: forged values, edits and scenes are no message the page acts on', async ({ page }) => {
  await openAndRun(page, PLAYGROUND);
  const code = await codeNow(page);
  const frame = page.frames().find((f) => f !== page.mainFrame() && f.url().includes('srcdoc'));
  await frame.evaluate(() => {
    const forged = [
      { type: 'values', changes: [{ path: ['scene', 'objects', '0', 'radius'], value: 9 }] },
      { type: 'code', code: 'alert(1)' }, { type: 'edit', from: 0, to: 10, insert: 'evil' },
      { type: 'scrub', from: 0, to: 3, was: 'imp', now: '999' },
      { type: 'scene', scene: JSON.stringify({ objects: [] }), camera: JSON.stringify({ width: 64, height: 48, fov: 30, position: [0, 0, 0] }) },
    ];
    for (const message of forged) parent.postMessage(message, '*');
  });
  await page.waitForTimeout(1_500); // longer than any answer the page would make
  expect(await codeNow(page)).toBe(code);
  await expect(page.locator('[data-code-status]')).toHaveText('Your code ran (run 1).'); // nor did it run again
});

test('the inspector keeps its pixel while the radius is scrubbed, and its discriminant goes from positive to negative as the sphere shrinks off it', async ({ page }) => {
  await openAndRun(page, PLAYGROUND);
  await clickPixel(sketchFrame(page).locator('canvas[data-tracer]'), 44, 24); // 12 px right of the centre: on the sphere of radius 4
  const discriminant = sketchFrame(page).locator('[data-inspector] [data-route="quadratic"][data-sphere="0"][data-field="discriminant"]');
  await expect(discriminant).toHaveAttribute('data-value', /^\d/); // two hits
  await numberIn(page, 'new Sphere(', 3).click(); // the radius, 4
  await page.keyboard.press('Alt+ArrowDown');
  await waitForRun(page, 2); // the first step runs the code: the selected pixel goes along
  await expect(discriminant).toHaveAttribute('data-value', /^\d/); // radius 3: still on it
  await markFrame(page);
  await page.keyboard.press('Alt+ArrowDown');
  await expect(page.locator('[data-code-status]')).toHaveText('radius 2');
  await expect(discriminant).toHaveAttribute('data-value', /^-/); // the sphere slid off the pixel: no hit
  await expect(markedFrame(page)).toHaveCount(1); // live, in the same frame
  await expect(sketchFrame(page).locator('[data-inspector] [data-route="quadratic"][data-sphere="0"][data-field="meaning"]')).toHaveText('no hit');
});
