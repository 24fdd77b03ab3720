// A blind student's walk through the lesson: keys only, choices made from
// what a screen reader says (tests/e2e/screen-reader.js models NVDA's browse
// and focus modes on the browser's accessibility tree). Each walk is held to
// a budget: at most twice a sighted student's actions (a search by ear along
// an edge, ten keys more), a bounded number of words, and on sketch 04 no
// answer said that would be judged otherwise if typed (lib/lesson/activity.js
// judges it, as the class server does).
import { test, expect } from '@playwright/test';
import { expectQuietConsole, waitForDone } from './helpers.js';
import { ScreenReader, countWords } from './screen-reader.js';
import { Camera, classScene, inspectPixel, pinkPixelVerdict, readAnswerLine } from '../../lib/index.js';

expectQuietConsole(test);

/** The key budget of a walk a sighted student does in `actions` clicks and keys. */
const keyBudget = (actions) => 2 * actions;
/** The budget of a walk that searches by ear, a key a pixel, for what a sighted student sees at once (an edge, a penumbra). */
const searchBudget = (actions) => 2 * actions + 10;
/** Words a walk may say, focus and news together (a read-all is counted on its own). */
const WORD_BUDGET = 180; // about a minute of speech at NVDA's default rate

async function open(page, path) {
  await page.goto(path);
  await waitForDone(page);
  return ScreenReader.start(page);
}

/** From the top of the page to the picture: one Tab, and the picture is said (it takes the keys). */
async function toPicture(reader) {
  await reader.press('Tab');
  expect(reader.said.at(-1)?.text, reader.text).toMatch(/ graphic /);
}

/** Every answer line said on sketch 04, and the verdict said with it: judged again here as if typed. */
function answersSaid(reader) {
  const out = [];
  for (const { text } of reader.said) {
    for (const m of text.matchAll(/Pixel: \d+,\d+; H: -?\d+(?:\.\d+)?; V: -?\d+(?:\.\d+)?(\. (Right|Wrong))?/g)) {
      const boxes = readAnswerLine(m[0].replace(/\. (Right|Wrong)$/, ''));
      const [x, y, h, v] = [boxes.x, boxes.y, boxes.h, boxes.v].map(Number);
      const camera = new Camera({ width: 32, height: 24, fov: 30, yaw: h, pitch: v });
      const pink = x < 32 && y < 24 && pinkPixelVerdict(inspectPixel(classScene(), camera, x, y)).pink;
      out.push({ line: m[0], said: m[2] ?? 'no verdict', pink });
    }
  }
  return out;
}

test('04: the activity by keys, the answer said as the line to type and judged right when typed', async ({ page }) => {
  const reader = await open(page, '/sketches/04-find-the-pink-pixel.html');
  await expect(page.locator('input[name="x"]')).toHaveValue(''); // no answer filled in and judged before the student's own
  await expect(page.locator('[data-answer-line]')).toHaveText('');
  await toPicture(reader);
  expect(reader.mode, 'the picture takes the keys (focus mode)').toBe('focus');
  await reader.press('p'); // the next pink pixel
  const said = reader.said.filter((s) => s.how === 'live').map((s) => s.text);
  expect(said, reader.text).toHaveLength(1); // pixel, verdict and task in one message
  expect(said[0]).toMatch(/^Pixel: \d+,\d+; H: 0; V: 0\. Right: Pink!/);
  expect(said[0]).toMatch(/Tasks? done \(\d of 4\): Check an answer; Find a pink pixel\./);
  // the line said is the one to type: typed into the boxes, Check says the same
  const line = /^Pixel: [^.]+/.exec(said[0])[0];
  const answers = answersSaid(reader);
  expect(answers.length).toBeGreaterThan(0);
  for (const a of answers) expect(a.pink, `${a.line}, said "${a.said}"`).toBe(a.said === 'Right');
  await expect(page.locator('[data-task="pink"]')).toHaveAttribute('data-done', 'true');
  expect(reader.keys, reader.text).toBeLessThanOrEqual(keyBudget(1)); // sighted: one click on a pink pixel
  expect(reader.words, reader.text).toBeLessThanOrEqual(WORD_BUDGET);
  expect(await page.locator('[data-answer-line]').textContent()).toBe(line);
});

test('04: a held arrow key is one message, its answer line the camera\'s, judged as said', async ({ page }) => {
  const reader = await open(page, '/sketches/04-find-the-pink-pixel.html');
  await toPicture(reader);
  await reader.press('p');
  reader.said = [];
  await page.evaluate(async () => { // a key's own repeat: a keydown every 40 ms
    const picture = document.querySelector('[data-tracer]');
    for (let i = 0; i < 10; i++) {
      picture.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowRight', bubbles: true }));
      await new Promise((resolve) => setTimeout(resolve, 40));
    }
  });
  await reader.press('Shift'); // the reader hears what came
  const said = reader.said.filter((s) => s.how === 'live');
  expect(said, reader.text).toHaveLength(1);
  expect(countWords(said[0].text)).toBeLessThanOrEqual(40);
  for (const a of answersSaid(reader)) expect(a.pink, `${a.line}, said "${a.said}"`).toBe(a.said === 'Right');
});

test('01: the first task by keys, and the task said is the one done', async ({ page }) => {
  const reader = await open(page, '/sketches/01-rays-through-pixels.html');
  const first = page.locator('[data-task="select"]');
  await expect(first).not.toContainText('Done:');
  await toPicture(reader);
  await reader.press('ArrowRight'); // the middle pixel: any pixel does it
  await expect(first).toHaveAttribute('data-done', 'true');
  const said = reader.said.filter((s) => s.how === 'live').map((s) => s.text);
  expect(said, reader.text).toHaveLength(1);
  expect(said[0]).toMatch(/^Pixel: 16,12; .* Tasks? done \(\d of 6\): Select any pixel\b/);
  // the list reads differently once a task is done: its state is in words, not only a ✓
  await expect(first).toContainText('Done: Select any pixel');
  expect(reader.keys, reader.text).toBeLessThanOrEqual(keyBudget(1));
  expect(reader.words, reader.text).toBeLessThanOrEqual(WORD_BUDGET);
});

test('02: the first task by keys on the shaded picture, which says the discriminant too', async ({ page }) => {
  const reader = await open(page, '/sketches/02-the-quadratic.html');
  await toPicture(reader);
  expect(reader.said.at(-1).text).toMatch(/Shaded graphic 64 by 48 pixels\./);
  // white: the background, a miss; the first white pixel by the sphere's edge grazes it (about 0), and is said so
  const news = () => reader.said.filter((s) => s.how === 'live').map((s) => s.text).join(' ');
  for (let i = 0; i < 3 && !/Task done \(\d of 5\): Find a pixel whose discriminant B² − 4AC is negative/.test(news()); i++) await reader.press('w');
  const said = reader.said.filter((s) => s.how === 'live').map((s) => s.text);
  for (const text of said) expect(text).toMatch(/^Pixel: \d+,\d+; H: [-\d.]+; V: [-\d.]+\. White, no hit, the background\. Discriminant -[\d.,]+, (negative: no hit|about 0: one root)/);
  expect(said.at(-1)).toMatch(/Discriminant -[\d.,]+, negative: no hit\..*Task done \(\d of 5\): Find a pixel whose discriminant B² − 4AC is negative/);
  await expect(page.locator('[data-task="negative"]')).toHaveAttribute('data-done', 'true');
  expect(reader.keys, reader.text).toBeLessThanOrEqual(keyBudget(1) + 1); // one key more when the first white pixel grazes the sphere
  expect(reader.words, reader.text).toBeLessThanOrEqual(WORD_BUDGET);
});

test('12: the cone found by its colour\'s letter', async ({ page }) => {
  const reader = await open(page, '/sketches/12-cylinders-cones-triangles.html');
  await toPicture(reader);
  await reader.press('y'); // the next yellow pixel
  expect(reader.said.filter((s) => s.how === 'live').map((s) => s.text).join(' ')).toMatch(/Yellow, the yellow cone\./);
  await expect(page.locator('[data-inspector] tr.rt-hit-row')).toContainText('yellow cone');
  expect(reader.keys, reader.text).toBeLessThanOrEqual(keyBudget(1));
  expect(reader.words, reader.text).toBeLessThanOrEqual(WORD_BUDGET);
});

test('12: a colour\'s letter pressed while the picture is traced is answered from the finished picture', async ({ page }) => {
  // the letter comes the moment the picture's canvas is on the page: its first, coarse blocks are no colours to go by
  await page.addInitScript(() => {
    new MutationObserver((_, observer) => {
      const picture = document.querySelector('[data-tracer]');
      if (!picture?.isConnected) return;
      observer.disconnect();
      window.__pressedWhile = document.body.dataset.render;
      picture.dispatchEvent(new KeyboardEvent('keydown', { key: 'y', bubbles: true }));
    }).observe(document, { childList: true, subtree: true });
  });
  await page.goto('/sketches/12-cylinders-cones-triangles.html');
  await waitForDone(page);
  expect(await page.evaluate(() => window.__pressedWhile)).toBe('rendering');
  await expect(page.locator('[data-inspector] tr.rt-hit-row')).toContainText('yellow cone');
  await expect(page.locator('[data-announce="page"]')).toContainText(/Yellow, the yellow cone\./);
});

test('11: what setup() selects is not said as news: the page\'s voice waits for the student', async ({ page }) => {
  const reader = await open(page, '/sketches/11-several-rays-per-pixel.html');
  await expect(page.locator('[data-announce="pixel"]')).toContainText('Pixel: 24,7'); // on the page, for who reads it
  await page.waitForTimeout(1000);
  await reader.press('Shift');
  expect(reader.said.filter((s) => s.how === 'live'), reader.text).toEqual([]);
  await expect(page.locator('[data-announce="page"]')).toHaveText('');
});

/** What the page said (its live news) since the walk began, as one text. */
const news = (reader) => reader.said.filter((s) => s.how === 'live').map((s) => s.text).join(' ');

/** Presses `key` until `done()` or the walk's key budget is spent; the student decides from what was said. */
async function pressUntil(reader, key, done, budget) {
  while (!done() && reader.keys < budget) await reader.press(key);
}

test('03: the pixel and the sentence under the picture come as one message', async ({ page }) => {
  const reader = await open(page, '/sketches/03-the-geometric-approach.html');
  await toPicture(reader);
  await reader.press('ArrowLeft');
  const said = reader.said.filter((s) => s.how === 'live').map((s) => s.text);
  expect(said, reader.text).toHaveLength(1); // it was two: the inspector's status and the sentence's own live region
  expect(said[0]).toMatch(/^Pixel: \d+,\d+; H: [-\d.]+; V: [-\d.]+\. [A-Z][a-z]+, [^.]+\. (tca|d|The eye) .*(no intersection|t = tca [−+] thc)/);
  expect(await page.locator('[data-explain]').getAttribute('aria-live')).toBeNull();
});

test('10: the first task by keys, said as the task done', async ({ page }) => {
  const reader = await open(page, '/sketches/10-playground.html');
  await toPicture(reader);
  await reader.press('ArrowRight');
  await expect(page.locator('[data-task="select"]')).toHaveAttribute('data-done', 'true');
  const said = reader.said.filter((s) => s.how === 'live').map((s) => s.text);
  expect(said, reader.text).toHaveLength(1); // the pixel and the task, one message
  expect(said[0]).toMatch(/^Pixel: \d+,\d+; H: [-\d.]+; V: [-\d.]+\. \w+, the sphere 1\. Task done \(1 of 4\): Select any pixel/);
  expect(reader.keys, reader.text).toBeLessThanOrEqual(keyBudget(1));
  expect(reader.words, reader.text).toBeLessThanOrEqual(WORD_BUDGET);
});

test('11: an edge pixel by keys: the second picture by Tab, then along the sphere\'s rim until a pixel is said to be an edge', async ({ page }) => {
  const reader = await open(page, '/sketches/11-several-rays-per-pixel.html');
  await toPicture(reader);
  await pressUntil(reader, 'Tab', () => /4 rays per pixel graphic/.test(reader.said.at(-1).text), searchBudget(1));
  expect(reader.said.at(-1).text).toMatch(/4 rays per pixel graphic 64 by 48 pixels\. The same scene as One ray per pixel, seen from the same eye\.$/); // not the scene again
  expect(reader.mode).toBe('focus');
  // the page opens on the pink sphere's top edge: the first arrow says where the student is
  await pressUntil(reader, 'ArrowLeft', () => /an edge: of its 4 rays/.test(news(reader)), searchBudget(1));
  expect(news(reader)).toMatch(/; an edge: of its 4 rays, \d hit (the [a-z ]+|nothing), \d (the [a-z ]+|nothing)[.;].*Task done \(1 of 3\): Find an edge pixel/);
  await expect(page.locator('[data-task="edge"]')).toHaveAttribute('data-done', 'true');
  expect(reader.keys, reader.text).toBeLessThanOrEqual(searchBudget(1));
  expect(reader.words, reader.text).toBeLessThanOrEqual(WORD_BUDGET);
});

test('13: the bunny found by its colour, its BVH counts said with the pixel in one message', async ({ page }) => {
  const reader = await open(page, '/sketches/13-meshes-and-a-bvh.html');
  await toPicture(reader);
  expect(reader.said.at(-1).text).toMatch(/An orange mesh called bunny/);
  await reader.press('o'); // the next orange pixel
  const said = reader.said.filter((s) => s.how === 'live').map((s) => s.text);
  expect(said, reader.text).toHaveLength(1);
  expect(said[0]).toMatch(/^Pixel: \d+,\d+; H: [-\d.]+; V: [-\d.]+\. Orange, the bunny\. Pixel \d+,\d+: the ray tested [\d,]+ boxes and [\d,]+ triangles.* Task done \(1 of 4\): Select a pixel of the bunny/);
  await expect(page.locator('[data-task="bunny"]')).toHaveAttribute('data-done', 'true');
  expect(reader.keys, reader.text).toBeLessThanOrEqual(keyBudget(1));
  expect(reader.words, reader.text).toBeLessThanOrEqual(WORD_BUDGET);
});

test('14: the penumbra by keys, heard as the disc\'s shadow rays that reach the pixel', async ({ page }) => {
  const reader = await open(page, '/sketches/14-spot-and-area-lights.html');
  await toPicture(reader);
  await pressUntil(reader, 'ArrowDown', () => /in the penumbra of disc/.test(news(reader)), searchBudget(1));
  expect(news(reader)).toMatch(/the floor; (outside the cone of spot; )?in the penumbra of disc: ([1-9]|1[0-5]) of 16 shadow rays reach it\..*Tasks? done \(\d of 4\): Find a pixel of the penumbra/);
  await expect(page.locator('[data-task="penumbra"]')).toHaveAttribute('data-done', 'true');
  expect(reader.keys, reader.text).toBeLessThanOrEqual(searchBudget(1));
  expect(reader.words, reader.text).toBeLessThanOrEqual(WORD_BUDGET);
});

test('15: on the GPU the picture says its arrows turn the camera, and a turn is heard in the answer line\'s angles', async ({ page }) => {
  test.setTimeout(120_000);
  const reader = await open(page, '/sketches/15-live-on-the-gpu.html');
  await toPicture(reader);
  expect(reader.said.at(-1).text).toMatch(/^The picture and its panels main landmark Arrow keys: turn the camera, or move the selected pixel \(Escape lets it go\); \+ and −: nearer, farther; p: next pink/);
  expect(reader.mode).toBe('focus');
  await reader.press('ArrowRight');
  await expect(page.locator('[data-announce="camera"]')).toHaveText('Camera: H: 5.0; V: -8.0; 26 from the point it turns about.');
  await reader.press('p'); // a pink pixel: now the arrows move it
  await expect(page.locator('[data-inspector]')).toContainText('pink');
  await reader.press('Escape');
  await expect(page.locator('[data-announce="camera"]')).toHaveText('No pixel selected: the arrow keys turn the camera.');
  await page.waitForTimeout(500);
  const said = news(reader);
  expect(said).toMatch(/Camera: H: 5\.0; V: -8\.0/);
  expect(said).toMatch(/Pixel: \d+,\d+; H: [-\d.]+; V: [-\d.]+\. Pink, the pink sphere/);
  expect(reader.words, reader.text).toBeLessThanOrEqual(WORD_BUDGET);
});

// A read-all as the page opens: the words NVDA says from the top to the end of the page.
// 12 grew by its task list (four tasks); 10, 11, 13, 14 and 15 as measured once their tasks came;
// 11 by 4 words more for the header's "Edit this sketch button" (the others had that room).
const READ_ALL = [['01-rays-through-pixels', 430], ['02-the-quadratic', 660], ['04-find-the-pink-pixel', 330], ['12-cylinders-cones-triangles', 450],
  ['10-playground', 390], ['11-several-rays-per-pixel', 614], ['13-meshes-and-a-bvh', 480], ['14-spot-and-area-lights', 740], ['15-live-on-the-gpu', 460]];
for (const [path, most] of READ_ALL) {
  test(`a read-all of ${path} as it opens says at most ${most} words`, async ({ page }) => {
    const reader = await open(page, `/sketches/${path}.html`);
    expect(await reader.readAll(), reader.text).toBeLessThanOrEqual(most);
  });
}

test('in browse mode the arrows never reach a plain image; the picture is in an application that takes them', async ({ page }) => {
  const reader = await open(page, '/sketches/01-rays-through-pixels.html');
  await toPicture(reader);
  const picture = page.locator('[data-tracer]');
  await expect(picture).toHaveAttribute('role', 'img'); // the page contract: the picture is an image, described
  await expect(page.locator('[role="application"]').filter({ has: picture })).toHaveCount(1);
  reader.toggleMode(); // by hand to browse mode: the arrow stays with the reader
  await reader.press('ArrowRight');
  await expect(page.locator('[data-inspector]')).toHaveAttribute('data-state', 'empty');
});

test('02: the three pictures of one scene have three names, each map described as the map', async ({ page }) => {
  await page.goto('/sketches/02-the-quadratic.html');
  await waitForDone(page);
  const pictures = page.locator('[data-tracer]');
  await expect(pictures.nth(0)).toHaveAccessibleName('Shaded');
  await expect(pictures.nth(1)).toHaveAccessibleName('Discriminant B² − 4AC');
  await expect(pictures.nth(2)).toHaveAccessibleName('Roots: 0, 1 or 2'); // its caption names the map already
  await expect(pictures.nth(1)).toHaveAccessibleDescription(/^64 by 48 pixels\. Discriminant map: positive \(two hits\) on pixels x \d+–\d+, y \d+–\d+;/);
  await expect(pictures.nth(2)).toHaveAccessibleDescription(/^64 by 48 pixels\. Roots map: 2 roots \(two hits\) on pixels/);
});

test('the 3D view says where it looks from as it turns, in its name and once each burst of keys rests, with its angles', async ({ page }) => {
  const reader = await open(page, '/sketches/01-rays-through-pixels.html');
  const view3d = page.locator('[data-view3d]');
  await expect(view3d).toHaveAccessibleName(/^The scene in 3D, seen from behind the eye and to its right, from above: arrow keys turn it/);
  await view3d.focus();
  reader.said = [];
  await view3d.evaluate((canvas) => { // six presses in one burst (a held key): yaw −35 → −95, round to the eye's right side
    for (let i = 0; i < 6; i++) canvas.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowRight', bubbles: true }));
  });
  await reader.press('Shift');
  await expect(view3d).toHaveAccessibleName(/^The scene in 3D, seen from the eye's right, from above:/);
  expect(reader.said.filter((s) => s.how === 'live').map((s) => s.text)).toEqual(['Seen from the eye\'s right, from above: yaw -95°, pitch 20°.']);
  // every key is heard, a turn that stays in one sector of words too (ArrowUp was not said at all)
  for (const [key, said] of [['ArrowUp', 'pitch 10°'], ['ArrowDown', 'pitch 20°'], ['ArrowLeft', 'yaw -85°']]) {
    reader.said = [];
    await reader.press(key);
    expect(reader.said.filter((s) => s.how === 'live').map((s) => s.text), key).toEqual([expect.stringContaining(said)]);
  }
});

test('from the picture to the 3D view in one key, said by the picture\'s name', async ({ page }) => {
  const reader = await open(page, '/sketches/01-rays-through-pixels.html');
  await toPicture(reader);
  expect(reader.said.at(-1).text).toMatch(/3: the 3D view/);
  await reader.press('3');
  await expect(page.locator('[data-view3d]')).toBeFocused();
  expect(reader.said.at(-1).text).toMatch(/^The scene in 3D, seen from/);
});

for (const path of ['00-light-or-eye', '01-rays-through-pixels', '02-the-quadratic', '03-the-geometric-approach', '04-find-the-pink-pixel',
  '05-value-boxes', '06-lights-shadows-reflections', '07-original-examples', '11-several-rays-per-pixel', '12-cylinders-cones-triangles',
  '13-meshes-and-a-bvh', '14-spot-and-area-lights', '15-live-on-the-gpu', '16-light-that-bounces', '17-one-weekend']) {
  test(`${path}: the first Tab lands on the picture, and a named main landmark holds it`, async ({ page }) => {
    test.setTimeout(120_000);
    await page.goto(`/sketches/${path}.html`);
    await page.locator('[data-skip-to-picture]').waitFor({ state: 'attached' }); // the picture takes the keys while it is traced too
    await page.keyboard.press('Tab');
    const picture = page.locator(await page.locator('[data-skip-to-picture]').getAttribute('href'));
    await expect(picture).toHaveAttribute('data-tracer', '');
    await expect(picture).toBeFocused();
    await expect(page.getByRole('main', { name: 'The picture and its panels' }).locator(picture)).toBeVisible();
    // back towards the header: the link stops there, no trap
    await page.keyboard.press('Shift+Tab');
    await expect(picture).not.toBeFocused();
  });
}

test('"Picture as text" reads every row of pixels, in the answer\'s coordinates, and says when they change', async ({ page }) => {
  const reader = await open(page, '/sketches/01-rays-through-pixels.html');
  await page.getByText('Picture as text').click();
  const rows = page.locator('[data-picture-rows] li');
  await expect(rows).toHaveCount(24);
  await expect(rows.nth(12)).toHaveText(/^Row 12: 0–\d+ (white|blue), .*pink/);
  await expect(page.locator('[data-picture-rows-note]')).toHaveText('24 rows of 32 pixels, row 0 at the top, x from 0 at the left.');
  reader.said = [];
  await page.getByRole('button', { name: 'Trace again' }).click(); // the same picture again: nothing to say
  await waitForDone(page);
  await reader.press('Shift');
  expect(reader.text).not.toContain('rows changed');
});

test('"Picture as text" says when its rows change (sketch 04: the camera turned)', async ({ page }) => {
  const reader = await open(page, '/sketches/04-find-the-pink-pixel.html');
  await page.getByText('Picture as text').click();
  const before = await page.locator('[data-picture-rows]').textContent();
  const h = page.getByLabel('Camera H');
  await h.fill('10');
  await h.press('Tab'); // leaving the box turns the camera
  await waitForDone(page);
  await reader.press('Shift');
  expect(reader.said.filter((s) => s.how === 'live').map((s) => s.text)).toContain('Picture as text: the picture was traced again, its rows changed.');
  expect(await page.locator('[data-picture-rows]').textContent()).not.toBe(before);
});

test('a key finds the next pink pixel; the letters of a colour not in the picture say which colours are', async ({ page }) => {
  const reader = await open(page, '/sketches/01-rays-through-pixels.html');
  await toPicture(reader);
  await reader.press('p');
  await expect(page.locator('[data-inspector] [data-field="color-name"], [data-inspector]').first()).toContainText('pink');
  const first = await page.locator('[data-inspector]').getAttribute('data-x');
  await reader.press('p');
  expect(await page.locator('[data-inspector]').getAttribute('data-x')).not.toBe(first); // the next one
  await reader.press('y'); // 01 has no yellow
  expect(reader.said.at(-1).text).toMatch(/^No yellow pixel here\. This picture has .*pink/);
  const before = await page.locator('[data-inspector]').getAttribute('data-x');
  await reader.press('p'); // at once, as a list box's letters: "yp" is no colour, so p alone, the next pink one
  expect(await page.locator('[data-inspector]').getAttribute('data-x')).not.toBe(before);
  expect(reader.said.at(-1).text).toMatch(/^Pixel: \d+,\d+; .* Pink, the pink sphere\.$/);
});

test('from the task list back to the picture in two keys', async ({ page }) => {
  await page.goto('/sketches/01-rays-through-pixels.html');
  await waitForDone(page);
  await page.getByRole('button', { name: 'Start again' }).focus();
  await page.keyboard.press('Tab');
  await expect(page.getByRole('link', { name: 'Back to the picture' })).toBeFocused();
  await page.keyboard.press('Enter');
  await expect(page.locator('[data-tracer]')).toBeFocused();
});

test('"Copy answer" says what it did', async ({ page }) => {
  const reader = await open(page, '/sketches/04-find-the-pink-pixel.html');
  const copy = page.getByRole('button', { name: 'Copy answer' });
  await copy.focus();
  await reader.press('Enter');
  expect(reader.said.at(-1).text).toBe('Check an answer first: nothing to copy yet.');
  await expect(page.locator('[data-copied]')).toHaveText('Check an answer first: nothing to copy yet.'); // shown as said
  await page.locator('input[name="x"]').fill('16');
  await page.locator('input[name="y"]').fill('12');
  await page.locator('[data-check]').click();
  await expect(page.locator('[data-announce="page"]')).toContainText('Right: Pink!'); // the verdict said on its own, before the copy
  await copy.focus();
  await reader.press('Enter');
  const said = reader.said.at(-1).text;
  expect(said).toMatch(/^(Copied: Pixel: 16,12; H: 0; V: 0\. Paste it in the class chat\.|Select the answer and press Ctrl\+C \(⌘C\): Pixel: 16,12; H: 0; V: 0)$/);
  await expect(page.locator('[data-copied]')).toHaveText(said);
  // one voice: the note beside the button is no status of its own (it would be said twice)
  await expect(page.locator('[data-copied]')).not.toHaveAttribute('role', /.*/);
});

test.describe('with reduced motion', () => {
  test.use({ reducedMotion: 'reduce' });

  test('the picture is not shown pass by pass: only once it is traced', async ({ page }) => {
    await page.goto('/sketches/07-original-examples.html');
    // every frame while tracing: has any pixel of the picture been drawn yet?
    const partial = await page.evaluate(() => new Promise((resolve) => {
      let seen = false;
      const look = () => {
        const c = document.querySelector('[data-tracer]');
        if (c && document.body.dataset.render === 'rendering' && c.width > 1) {
          const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
          for (let i = 3; i < data.length; i += 4) if (data[i]) { seen = true; break; }
        }
        if (document.body.dataset.render === 'done') resolve(seen); else requestAnimationFrame(look);
      };
      look();
    }));
    expect(partial).toBe(false);
    await waitForDone(page);
    const drawn = await page.locator('[data-tracer]').evaluate((c) => c.getContext('2d').getImageData(0, 0, c.width, c.height).data.some((v, i) => i % 4 === 3 && v));
    expect(drawn).toBe(true);
  });

  test('sketch 00: the photons\' picture and count show once every photon is sent, not step by step', async ({ page }) => {
    test.setTimeout(120_000);
    await page.goto('/sketches/00-light-or-eye.html');
    // every frame until the page is done: how many different pictures and counts has the photon view shown?
    const shown = await page.evaluate(() => new Promise((resolve) => {
      const pictures = new Set(), counts = new Set();
      const look = () => {
        const c = document.querySelector('[data-photons]');
        if (c) {
          pictures.add(c.toDataURL());
          counts.add(document.querySelector('[data-photon-count]').textContent);
        }
        if (c && document.body.dataset.render === 'done') resolve({ pictures: pictures.size, counts: counts.size }); else requestAnimationFrame(look);
      };
      look();
    }));
    expect(shown.pictures).toBeLessThanOrEqual(2); // the blank canvas, then the last picture
    expect(shown.counts).toBeLessThanOrEqual(2);
    await expect(page.locator('[data-photon-count]')).toHaveText(/^Of 1,000,000 rays from the light, [\d,]+ reached the eye/);
  });

  test('Shoot rays does not fly rays one by one: the picture is traced again at once', async ({ page }) => {
    await page.goto('/sketches/01-rays-through-pixels.html');
    await waitForDone(page);
    await page.getByRole('button', { name: 'Shoot rays' }).click();
    await expect(page.locator('[data-view3d-stop]')).toBeDisabled();
    await waitForDone(page, 5_000); // at 4 rays/s the 768 pixels would take minutes
    expect(await page.evaluate(() => document.querySelector('[data-tracer]').closest('[data-tracer-view]').dataset.state)).toBe('done');
  });
});

test.describe('at 320 CSS px wide', () => {
  test.use({ viewport: { width: 320, height: 640 } });

  test('sketch 11: the pixel\'s rays table scrolls by keyboard (a focusable, named region), and axe finds nothing serious', async ({ page }) => {
    test.setTimeout(120_000);
    await page.goto('/sketches/11-several-rays-per-pixel.html');
    await waitForDone(page);
    await page.locator('[data-tracer]').first().focus();
    await page.keyboard.press('ArrowRight');
    await waitForDone(page);
    const wrap = page.locator('.rt-sample-rays > .rt-table-wrap');
    await expect(wrap).toHaveAttribute('tabindex', '0');
    await expect(wrap).toHaveAccessibleName('The pixel\'s rays table');
    const { default: AxeBuilder } = await import('@axe-core/playwright');
    const { violations } = await new AxeBuilder({ page }).withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa']).analyze();
    expect(violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => v.id)).toEqual([]);
  });
});
