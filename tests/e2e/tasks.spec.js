// The lesson pages' tasks, done as a student does them (clicks, boxes, keys), each seen ticked off;
// the progress kept in the browser, shown in the gallery, and read on the teacher's page.
import { test, expect } from '@playwright/test';
import { clickPixel, expectQuietConsole, waitForDone } from './helpers.js';
import { progressCode } from '../../lib/lesson/progress.js';
import { LESSONS } from '../../lib/lesson/tasks.js';

expectQuietConsole(test);

const KEY = 'raytracing-sketchbook:tasks:v1';
const task = (page, id) => page.locator(`[data-task="${id}"]`);
const expectDone = (page, id) => expect(task(page, id), id).toHaveAttribute('data-done', 'true');
const expectNotDone = (page, id) => expect(task(page, id), id).toHaveAttribute('data-done', 'false');

async function open(page, path) {
  await page.goto(path);
  await waitForDone(page);
}

/** The first pixel of a canvas whose colour passes `test(r, g, b)`, read from the canvas itself. */
function findPixel(canvas, test) {
  return canvas.evaluate((c, source) => {
    const pass = new Function('r', 'g', 'b', `return ${source};`);
    const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    for (let i = 0; i < data.length; i += 4) if (pass(data[i], data[i + 1], data[i + 2])) return { x: (i / 4) % c.width, y: Math.floor(i / 4 / c.width) };
    return null;
  }, test);
}

test('01: the tasks are a list, each ticked off by a click or a key, announced, kept, and started again', async ({ page }) => {
  await open(page, '/sketches/01-rays-through-pixels.html');
  const view = page.locator('[data-tracer]');
  await expect(page.locator('[data-tasks] ol > li[data-task]')).toHaveCount(6);
  await expect(task(page, 'select')).toContainText('Select any pixel');
  await expectNotDone(page, 'select');

  await view.focus();
  await page.keyboard.press('ArrowRight'); // the keyboard selects too: the middle pixel, whose ray goes straight ahead
  await expectDone(page, 'select');
  await expectDone(page, 'ahead');
  // both tasks the press did are named, and said by the page's one voice with the pixel
  await expect(page.locator('[data-task-status]')).toHaveText('Tasks done (2 of 6): Select any pixel; Find a pixel whose ray goes almost straight ahead.');
  await expect(page.locator('[role="status"][data-announce="page"]')).toContainText('Tasks done (2 of 6): Select any pixel;');

  await clickPixel(view, 3, 3);
  await expectDone(page, 'miss');
  await clickPixel(view, 25, 7);
  await expectDone(page, 'blue');
  await clickPixel(view, 25, 17);
  await expectDone(page, 'shadow');
  await expectNotDone(page, 'slow');
  await page.getByLabel('Slow motion').check();
  await expectDone(page, 'slow');
  await expect(page.locator('[data-task-strip]')).toHaveText('Tasks: 6 of 6 done: page finished ★');

  await page.reload();
  await expectDone(page, 'shadow'); // kept
  await page.getByLabel('Slow motion').uncheck(); // (a task of what the page shows is done again while it shows it)
  await page.getByRole('button', { name: 'Start again' }).click();
  await expectNotDone(page, 'select');
  await expectNotDone(page, 'slow');
  await expectNotDone(page, 'shadow');
  expect(JSON.parse(await page.evaluate((key) => localStorage.getItem(key), KEY)).pages['01']).toBeUndefined();
});

test('01: a hint shows after a few tries without the task', async ({ page }) => {
  await open(page, '/sketches/01-rays-through-pixels.html');
  const hint = task(page, 'blue').locator('[data-hint]');
  await expect(hint).toBeHidden();
  for (let x = 0; x < 7; x++) await clickPixel(page.locator('[data-tracer]'), x, 0); // sky, sky, sky…
  await expect(hint).toBeVisible();
  await expect(hint).toContainText('blue sphere');
  await expect(task(page, 'select').locator('[data-hint]')).toBeHidden(); // done: no hint
});

test('00: the eye\'s picture, a pixel no photon reached, more photons, the 3D view dragged round', async ({ page }) => {
  await open(page, '/sketches/00-light-or-eye.html');
  const eye = page.locator('#eye [data-tracer]');
  await clickPixel(eye, 20, 8);
  await expectDone(page, 'select');
  await clickPixel(eye, 0, 0);
  await expectDone(page, 'miss');
  const photons = page.locator('[data-photons]');
  const black = await findPixel(photons, 'r + g + b === 0');
  await clickPixel(photons, black.x, black.y);
  await expectDone(page, 'dark');
  await page.locator('[data-photons-more]').click();
  await waitForDone(page, 60_000);
  await expectDone(page, 'more');
  await expectNotDone(page, 'turn');
  const box = await page.locator('[data-view3d]').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 80, box.y + box.height / 2 + 10, { steps: 5 });
  await page.mouse.up();
  await expectDone(page, 'turn');
});

test('02: negative, about zero and positive discriminants; a bigger sphere; a sphere behind the eye', async ({ page }) => {
  await open(page, '/sketches/02-the-quadratic.html');
  const shaded = page.locator('[data-tracer]').first();
  await clickPixel(shaded, 0, 0);
  await expectDone(page, 'negative');
  await clickPixel(page.locator('[data-tracer]').nth(1), 27, 5); // the discriminant map: the pale edge
  await expectDone(page, 'zero');
  await clickPixel(shaded, 32, 30);
  await expectDone(page, 'positive');
  await page.locator('#field-r').fill('5');
  await waitForDone(page);
  await expectNotDone(page, 'grow'); // not yet big enough
  await page.locator('#field-r').fill('6');
  await expectDone(page, 'grow');
  await page.locator('#field-z').fill('10');
  await waitForDone(page);
  await clickPixel(shaded, 30, 20);
  await expectDone(page, 'behind');
});

test('03: a miss, a hit, the eye inside, tca < 0 and still a hit', async ({ page }) => {
  await open(page, '/sketches/03-the-geometric-approach.html');
  const view = page.locator('[data-tracer]');
  await clickPixel(view, 0, 0);
  await expectDone(page, 'pass-by');
  await clickPixel(view, 30, 20);
  await expectDone(page, 'hit');
  await expectNotDone(page, 'tca-negative');
  await page.locator('#inside').check();
  await expectDone(page, 'inside');
  await waitForDone(page);
  await clickPixel(view, 31, 23);
  await expectDone(page, 'tca-negative');
});

test('04: the activity: an answer checked, a pink pixel, two right answers, a turned camera', async ({ page }) => {
  await open(page, '/sketches/04-find-the-pink-pixel.html');
  await expectNotDone(page, 'check'); // the page's own first check is not the student's
  const view = page.locator('[data-tracer]');
  await clickPixel(view, 0, 0);
  await expectDone(page, 'check');
  await expectNotDone(page, 'pink');
  await clickPixel(view, 15, 4);
  await expectDone(page, 'pink');
  await expectNotDone(page, 'two');
  await clickPixel(view, 16, 4);
  await expectDone(page, 'two');
  for (const [name, value] of [['x', '5'], ['y', '3'], ['h', '10'], ['v', '0']]) await page.locator(`input[name="${name}"]`).fill(value);
  await page.locator('[data-check]').click();
  await expectDone(page, 'turned');
});

test('05: a pixel, a sphere made a light, a shadow thrown on another sphere', async ({ page }) => {
  await open(page, '/sketches/05-value-boxes.html');
  await clickPixel(page.locator('[data-tracer]'), 80, 60);
  await expectDone(page, 'select');
  const enter = async (name, value) => {
    const box = page.locator(`input[name="${name}"]`);
    await box.fill(value);
    await box.press('Enter');
    await waitForDone(page);
  };
  await enter('objects[1].material.emission', '1');
  await expectDone(page, 'glow');
  await expectNotDone(page, 'shadow');
  await enter('objects[2].center.0', '0');
  await enter('objects[2].center.1', '7');
  await enter('objects[2].center.2', '-20');
  await expectDone(page, 'shadow');
});

test('06: a shadow, acne at offset 0, the red ball in the mirror, no bounces, through the glass', async ({ page }) => {
  await open(page, '/sketches/06-lights-shadows-reflections.html');
  const view = page.locator('[data-tracer]');
  await clickPixel(view, 120, 36);
  await expectDone(page, 'glass');
  await clickPixel(view, 50, 48);
  await expectDone(page, 'mirror');
  await clickPixel(view, 2, 44);
  await expectDone(page, 'in-shadow');
  await page.getByLabel('shadow-ray offset').selectOption('0');
  await waitForDone(page);
  await clickPixel(view, 25, 0);
  await expectDone(page, 'acne');
  await page.getByLabel('mirror bounces').fill('0');
  await waitForDone(page);
  await clickPixel(view, 51, 49);
  await expectDone(page, 'no-bounce');
});

test('07: the still scene, the 640×480 original, the animation on both threads, a paused frame', async ({ page }) => {
  await open(page, '/sketches/07-original-examples.html');
  const view = page.locator('[data-tracer]');
  await clickPixel(view, 80, 60);
  await expectDone(page, 'still');
  await page.locator('[data-example="original"]').click();
  await waitForDone(page);
  await clickPixel(view, 320, 240);
  await expectDone(page, 'original');
  await page.locator('[data-example="animated"]').click();
  await expectDone(page, 'animated');
  await page.locator('[data-example="workers"]').click();
  await expectDone(page, 'workers');
  await page.locator('[data-pause]').click();
  await waitForDone(page);
  await clickPixel(view, 100, 100);
  await expectDone(page, 'frame');
});

for (const [page08, path, light] of [
  ['08', '/sketches/08-homework-traffic-signal.html', 'r > 200 && g < 90 && b < 90'],
  ['09', '/sketches/09-homework-rear-lights.html', 'r > 200 && g < 90 && b < 90'],
]) {
  test(`${page08}: the self-check run on the starter, then passed, and a light selected`, { tag: '@dev-server' }, async ({ page }) => {
    await open(page, path);
    await page.getByRole('button', { name: 'Check my scene' }).click();
    await expectDone(page, 'check');
    await expectNotDone(page, 'pass'); // the starter has no lights yet
    await open(page, `${path}?solution=1`); // the lights written, as a student's finished file has them
    await page.getByRole('button', { name: 'Check my scene' }).click();
    await expectDone(page, 'pass');
    const view = page.locator('[data-tracer]');
    const red = await findPixel(view, light);
    await clickPixel(view, red.x, red.y);
    await expectDone(page, 'light');
  });
}

test('corrupt or foreign stored progress is ignored without an error, and the page works', async ({ page }) => {
  for (const stored of ['{not json', JSON.stringify({ v: 9, pages: { '01': ['select'] } }), JSON.stringify({ v: 1, pages: { '01': ['<img src=x onerror=alert(1)>', 'miss'] } })]) {
    await page.addInitScript(([key, value]) => { if (!sessionStorage.getItem('seeded')) { localStorage.setItem(key, value); sessionStorage.setItem('seeded', '1'); } }, [KEY, stored]);
    await page.goto('/');
    await page.evaluate(() => sessionStorage.clear());
    await open(page, '/sketches/01-rays-through-pixels.html');
    await expectNotDone(page, 'select');
    await clickPixel(page.locator('[data-tracer]'), 3, 3);
    await expectDone(page, 'select');
    const kept = JSON.parse(await page.evaluate((key) => localStorage.getItem(key), KEY));
    expect(kept.v).toBe(1);
    expect(kept.pages['01']).toEqual(['select', 'miss']);
    await page.evaluate(() => localStorage.clear());
  }
});

test('the gallery shows each lesson\'s progress, the achievements and a code the teacher\'s page reads', async ({ page }) => {
  await page.addInitScript((key) => localStorage.setItem(key, JSON.stringify({ v: 1, pages: { '01': ['select', 'miss'], '03': ['pass-by', 'hit', 'inside', 'tca-negative'] } })), KEY);
  await page.goto('/');
  await expect(page.locator('a[href$="01-rays-through-pixels.html"] [data-progress]')).toHaveText('2 of 6');
  await expect(page.locator('a[href$="02-the-quadratic.html"] [data-progress]')).toHaveText('0 of 5');
  await expect(page.locator('[data-progress]')).toHaveCount(17); // 00–14, 16 and 17, each lesson page (15 has no tasks)
  await expect(page.locator('[data-achievement="page-03"]')).toContainText('The geometric approach');
  const code = await page.locator('[data-progress-code]').textContent();
  expect(code).toMatch(/^RT1(-[0-9A-F]{4}){8}-[0-9A-F]{2}-[0-9A-F]{2}$/); // 17 pages, two hex digits each, in fours

  await page.goto(`/teacher.html#code=${code}`);
  await expect(page.locator('[data-teacher-summary]')).toHaveText('1 of 1 code read.');
  const student = page.locator('[data-student="read"]');
  await expect(student).toContainText('6 of 72 tasks done.');
  await expect(student.locator('[data-page="01"]')).toContainText('Rays through pixels: 2 of 6');
  await expect(student.locator('[data-page="01"]')).toContainText('✓ Find a pixel whose ray hits nothing.');
  await expect(student).toContainText('★ Finished 03');

  let dialogs = 0;
  page.on('dialog', (d) => { dialogs++; d.dismiss(); });
  const changed = code.slice(0, 5) + (code[5] === '0' ? '1' : '0') + code.slice(6);
  await page.locator('#codes').fill(`Ana ${code}\nBob ${changed}\n<img src=x onerror=alert(1)> RT1-<script>`);
  await page.getByRole('button', { name: 'Read the codes' }).click();
  await expect(page.locator('[data-teacher-summary]')).toHaveText('1 of 3 codes read.');
  await expect(page.locator('[data-student="refused"]')).toHaveCount(2);
  await expect(page.locator('[data-student="refused"]').first()).toContainText('check sum');
  await expect(page.locator('[data-students] img, [data-students] script')).toHaveCount(0); // shown as text
  await expect(page.locator('[data-student="refused"]').nth(1).locator('h2')).toHaveText('<img src=x onerror=alert(1)>');
  expect(dialogs).toBe(0);

  await page.goto('/');
  await page.getByRole('button', { name: 'Start again: every page' }).click();
  await expect(page.locator('a[href$="01-rays-through-pixels.html"] [data-progress]')).toHaveText('0 of 6');
});

test('the teacher\'s page reads a code after any name: ß and ﬁ change length when upper-cased, "(started)" holds RT', async ({ page }) => {
  const code = progressCode({ '01': ['select'] }, LESSONS);
  await page.goto('/teacher.html');
  await page.locator('#codes').fill([`Weiß ${code}`, `ﬁona: ${code}`, `Ana (started) ${code}`, `Straße ﬁﬁ ${code.toLowerCase()}`].join('\n'));
  await page.getByRole('button', { name: 'Read the codes' }).click();
  await expect(page.locator('[data-teacher-summary]')).toHaveText('4 of 4 codes read.');
  await expect(page.locator('[data-student="read"] h2')).toHaveText(['Weiß', 'ﬁona', 'Ana (started)', 'Straße ﬁﬁ']);
});

// Not timed (the machine is noisy): the work a task makes is counted. 200 students' cards are about
// 11,000 elements; the page builds them 25 to a task, so the page answers between batches.
test('the teacher\'s page reads 200 codes and builds their cards 25 to a task, never all at once', async ({ page }) => {
  const all = Object.fromEntries(LESSONS.map((l) => [l.page, l.tasks.map((t) => t.id)]));
  const lines = Array.from({ length: 200 }, (_, i) => `Student ${i} ${progressCode(all, LESSONS)}`);
  await page.goto('/teacher.html');
  await page.locator('#codes').fill(lines.join('\n'));
  await page.evaluate(() => {
    // A mutation observer hears each task's changes together, at the end of that task.
    window.cardsPerTask = [];
    new MutationObserver((records) => {
      window.cardsPerTask.push(records.reduce((n, r) => n + [...r.addedNodes].filter((node) => node instanceof HTMLElement && node.dataset.student).length, 0));
    }).observe(document.getElementById('students'), { childList: true });
  });
  await page.getByRole('button', { name: 'Read the codes' }).click();
  await expect(page.locator('[data-teacher-summary]')).toHaveText('200 of 200 codes read.');
  await expect(page.locator('[data-student="read"]')).toHaveCount(200);
  const perTask = (await page.evaluate(() => window.cardsPerTask)).filter((n) => n > 0);
  expect(perTask.reduce((a, b) => a + b, 0)).toBe(200);
  expect(Math.max(...perTask)).toBeLessThanOrEqual(25);
  expect(perTask.length).toBeGreaterThanOrEqual(8);
});
