// The homework done in the page on the class server, as a student's laptop
// reaches it: by a name the browser does not trust (plain http, not
// localhost), mapped to 127.0.0.1 by Chromium, so nothing leaves loopback.
// The student edits the starter in the editor and presses Run; the page
// itself judges the scene the code built, keeps its task list and the
// board's "Received" lines through every Run, and the teacher's board gets
// the self-checks and the tasks. A student's code that claims a verdict,
// progress or a task by posting messages to the page changes nothing. The
// playground's tasks, done in its edited code, reach the board too.
import { readFileSync } from 'node:fs';
import { test, expect } from '@playwright/test';
import { findBrowser } from '../../scripts/find-browser.js';
import { startClassServer } from './class-server.js';
import { setCode, editorText, waitForRun, sketchFrame } from './code-editor.js';
import { watchConsole, clickPixel } from './helpers.js';
import { MAX_HEIGHT } from '../../editor/frame-protocol.js';

const HOST = 'class.test';
const STARTER = readFileSync('sketches/08-homework-traffic-signal.js', 'utf8');
const TODO = '  // TODO: your three lights here.';
const lights = (...lines) => STARTER.replace(TODO, lines.map((line) => `  scene.add(${line});`).join('\n'));
const RED = 'new Sphere([0, 6.5, -15.9], 0.45, { color: [0, 0, 0], emission: [1, 0, 0] })';
const YELLOW = 'new Sphere([0, 5.4, -15.9], 0.45, { color: [0, 0, 0], emission: [1, 0.85, 0] })';
const GREEN = 'new Sphere([0, 4.3, -15.9], 0.45, { color: [0, 0, 0], emission: [0, 1, 0.2] })';
/** A pixel of the red light, in the 160 × 120 picture (found with inspectPixel). */
const RED_PIXEL = { x: 77, y: 21 };
const PROGRESS = 'raytracing-sketchbook:tasks:v1';
/** The starter with no light at all, and code that tells the page it passed, ticked every task and is 20,000 px tall, again and again. */
const HOSTILE = `${STARTER}
const claims = [
  { type: 'check', passed: true, toFix: 0 },
  { type: 'progress', text: JSON.stringify({ v: 1, pages: { '08': ['check', 'light', 'pass'] } }) },
  { type: 'task', page: '08', tasks: ['check', 'light', 'pass'] },
  { type: 'size', height: 20000 },
];
setInterval(() => {
  for (const claim of claims) parent.postMessage(claim, '*');
  document.dispatchEvent(new CustomEvent('rt-check', { bubbles: true, detail: { passed: true, toFix: 0 } }));
  document.dispatchEvent(new CustomEvent('rt-task', { bubbles: true, detail: { page: '08', tasks: ['pass'] } }));
}, 100);
`;

test.use({ launchOptions: { executablePath: findBrowser() ?? undefined, args: [`--host-resolver-rules=MAP ${HOST} 127.0.0.1`] } });
test.describe.configure({ mode: 'serial', timeout: 300_000 });

let server, board;
test.beforeAll(async () => {
  // The name a student types for the teacher's computer, as the teacher lets it in.
  server = await startClassServer(Number(process.env.CLASS_PORT) || undefined, ['--allow-host', HOST]);
  await expect.poll(() => /\/board\?key=([\w-]+)/.exec(server.output())?.[1] ?? null, { timeout: 30_000 }).not.toBeNull();
  board = { key: /\/board\?key=([\w-]+)/.exec(server.output())[1] };
  board.url = `${server.url}board?key=${board.key}`;
});
test.afterAll(async () => { await server?.close(); });

/**
 * Presses the page's "Check my scene" from the keyboard: the frame above it
 * takes its new picture's height when it is ready, and a click could land
 * where the button was a moment before.
 */
async function pressCheck(check) {
  const button = check.getByRole('button', { name: 'Check my scene' });
  await button.focus();
  await button.press('Enter');
}

/** What the board shows, as JSON. */
const boardState = async () => (await fetch(`${server.url}board/state?key=${board.key}`)).json();
const homework08 = async () => (await boardState()).homework.find((h) => h.page === '08') ?? null;
const tasks08 = async () => (await boardState()).tasks.filter((t) => t.page === '08').map((t) => t.task).sort();
/** The student's kept progress of page 08. */
const progress08 = (page) => page.evaluate((key) => JSON.parse(localStorage.getItem(key) ?? '{}').pages?.['08'] ?? [], PROGRESS);

test('on the class server, reached by a name: the homework edited in the page is judged by the page, kept through every Run, and on the board', async ({ browser }) => {
  const teacher = await browser.newPage();
  await teacher.goto(board.url);
  await expect(teacher.locator('[data-live]')).toHaveAttribute('data-live', 'live', { timeout: 60_000 });
  const page = await (await browser.newContext()).newPage();
  const errors = watchConsole(page);
  const url = server.url.replace('127.0.0.1', HOST);
  await page.goto(`${url}sketches/08-homework-traffic-signal.html`);
  expect(await page.evaluate(() => window.isSecureContext)).toBe(false); // as on a classroom's network
  await expect(page.locator('[data-editor]')).toBeVisible({ timeout: 60_000 });
  expect(await editorText(page)).toBe(STARTER); // the starter, read as the student saves it
  // Before any Run, the page's own sketch: its Check, received by the board.
  await page.locator('main#sketch').getByRole('button', { name: 'Check my scene' }).click();
  await expect(page.locator('main#sketch .rt-check [data-received]')).toBeVisible();
  await expect(page.locator('#tasks [data-received]')).toBeVisible();

  await setCode(page, lights(RED));
  await waitForRun(page, 1, 120_000);
  // The task list and the self-check are the page's, under the frame; the frame shows neither.
  const check = page.locator('[data-code-judged] [data-page-check]');
  const tasks = page.locator('[data-code-judged] [data-tasks="08"]');
  await expect(tasks).toBeVisible();
  await expect(tasks.locator('[data-task="check"]')).toHaveAttribute('data-done', 'true');
  // What the page's own parts were told stays said, under the page's judge.
  await expect(check.locator('[data-received]')).toHaveText(/Received by the class board/);
  await expect(tasks.locator('[data-received]')).toHaveText(/Received by the class board/);
  await expect(sketchFrame(page).locator('[data-tasks]')).toHaveCount(0);
  await expect(sketchFrame(page).getByRole('button', { name: 'Check my scene' })).toHaveCount(0);
  await pressCheck(check);
  await expect(check.locator('[data-check-results]')).toHaveAttribute('data-check', 'not-yet');
  await expect(check.locator('[data-check-item="failed"]').first()).toContainText('Found 1 light (red)');
  await expect(check.locator('[data-received]')).toHaveText(/Received by the class board/);
  await expect(teacher.locator('[data-homework="08"]')).toContainText('0 passed');
  await expect(teacher.locator('[data-homework="08"]')).toContainText('of 1 who checked (2 checks run)');
  // A pixel of the red light, selected in the frame: the page finds it is a light, from the scene it read.
  await clickPixel(sketchFrame(page).locator('[data-tracer]'), RED_PIXEL.x, RED_PIXEL.y);
  await expect(tasks.locator('[data-task="light"]')).toHaveAttribute('data-done', 'true');
  await expect(tasks.locator('[data-received]')).toHaveText(/Received by the class board/);

  await setCode(page, lights(RED, YELLOW, GREEN));
  await waitForRun(page, 2, 120_000);
  // After Run the task list, its ticks and both "Received" lines are still on the page.
  await expect(tasks.locator('[data-task="light"]')).toHaveAttribute('data-done', 'true');
  await expect(tasks.locator('[data-received]')).toBeVisible();
  await expect(check.locator('[data-received]')).toBeVisible();
  await pressCheck(check);
  await expect(check.locator('[data-check-results]')).toHaveAttribute('data-check', 'passed');
  await expect(check.locator('.hw-headline')).toHaveText(/^Passed!/);
  await expect(tasks.locator('[data-task="pass"]')).toHaveAttribute('data-done', 'true');
  await expect(tasks.locator('[data-received]')).toHaveText(/Received by the class board/);
  await expect(teacher.locator('[data-homework="08"]')).toContainText('1 passed');
  await expect(teacher.locator('[data-homework="08"]')).toContainText('(3 checks run)');
  // Page 08's tasks on the board: each done by this student.
  for (const id of ['check', 'light', 'pass']) {
    await expect(teacher.locator(`[data-page="08"] [data-task="${id}"] .bar-count`)).toHaveText('1 of 1');
  }
  expect(await progress08(page)).toEqual(expect.arrayContaining(['check', 'light', 'pass']));
  expect(await page.evaluate(() => localStorage.getItem('raytracing-sketchbook:code:v1:08-homework-traffic-signal'))).toContain(GREEN);

  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await waitForRun(page, 3, 120_000);
  await expect(check.locator('[data-check-results]')).toHaveAttribute('data-check', 'passed'); // the last verdict stays
  await expect(tasks.locator('[data-received]')).toBeVisible();
  await expect(check.locator('[data-received]')).toBeVisible();
  await expect(page.locator('[data-tasks]')).toHaveCount(1);
  expect(errors).toEqual([]);
});

test('a student\'s code that posts a passed check, progress and tasks to the page changes nothing: no tick, no progress, nothing on the board', async ({ browser }) => {
  const before = { homework: await homework08(), tasks: await tasks08() };
  const page = await (await browser.newContext()).newPage();
  const errors = watchConsole(page);
  await page.goto(`${server.url.replace('127.0.0.1', HOST)}sketches/08-homework-traffic-signal.html`);
  await expect(page.locator('[data-editor]')).toBeVisible({ timeout: 60_000 });
  await setCode(page, HOSTILE);
  await waitForRun(page, 1, 120_000);
  const frame = page.locator('iframe[data-code-frame="running"]');
  // Its claims go on every 100 ms: give them two seconds to do anything they could.
  await page.waitForTimeout(2_000);
  await expect(page.locator('[data-code-judged] [data-tasks="08"]')).toBeVisible();
  expect(await page.locator('[data-task][data-done="true"]').count()).toBe(0);
  expect(await progress08(page)).toEqual([]);
  expect(await page.locator('[data-class-sent]').count()).toBe(0); // nothing was sent from this page
  const height = await frame.evaluate((f) => f.getBoundingClientRect().height);
  expect(height).toBeLessThanOrEqual(Math.max(MAX_HEIGHT, page.viewportSize().height));
  expect({ homework: await homework08(), tasks: await tasks08() }).toEqual(before);

  // The page's own Check judges the scene the code built: no light, not passed.
  const check = page.locator('[data-code-judged] [data-page-check]');
  await pressCheck(check);
  await expect(check.locator('[data-check-results]')).toHaveAttribute('data-check', 'not-yet');
  await expect(check.locator('[data-received]')).toBeVisible();
  await expect(page.locator('[data-task="pass"]')).toHaveAttribute('data-done', 'false');
  const after = await homework08();
  expect([after.passed, after.students, after.checks]).toEqual([before.homework.passed, before.homework.students + 1, before.homework.checks + 1]);
  expect(errors).toEqual([]);
});

test('the playground\'s tasks done in the edited code reach the board from the page', async ({ browser }) => {
  const teacher = await browser.newPage();
  await teacher.goto(board.url);
  await expect(teacher.locator('[data-live]')).toHaveAttribute('data-live', 'live', { timeout: 60_000 });
  const page = await (await browser.newContext()).newPage();
  const errors = watchConsole(page);
  await page.goto(`${server.url.replace('127.0.0.1', HOST)}sketches/10-playground.html`);
  await expect(page.locator('[data-editor]')).toBeVisible({ timeout: 60_000 });
  const starter = readFileSync('sketches/10-playground.js', 'utf8');
  await setCode(page, starter.replace('scene.add(new PointLight', 'scene.add(new Sphere([6, 1, -26], 2, { color: [0, 0, 0], emission: 1 }));\n  scene.add(new PointLight'));
  await waitForRun(page, 1, 120_000);
  const glow = page.locator('[data-code-judged] [data-tasks="10"] [data-task="glow"]');
  await expect(glow).toHaveAttribute('data-done', 'true');
  await expect(page.locator('[data-code-judged] [data-tasks="10"] [data-received]')).toHaveText(/Received by the class board/);
  await expect(teacher.locator('[data-page="10"] [data-task="glow"] .bar-count')).toHaveText(/^1 of \d+$/);
  expect(errors).toEqual([]);
});
