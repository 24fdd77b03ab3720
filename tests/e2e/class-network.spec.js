// The class as a student's laptop sees it: the teacher's computer by a name,
// over plain http, an origin the browser does not trust (not a secure
// context). The name is mapped to loopback in Chromium itself, so the
// traffic never leaves this machine. Every page loads with nothing refused
// and a quiet console, and every copy button copies or says how; the poll
// reaches the class board, which the teacher opens by the same name.
import { test, expect } from '@playwright/test';
import { readdirSync } from 'node:fs';
import { findBrowser } from '../../scripts/find-browser.js';
import { watchConsole, waitForDone, clickPixel } from './helpers.js';
import { startClassServer, freePort } from './class-server.js';

const NAME = 'class.test';
const WITHOUT_PICTURE = ['index.html', 'web-editor.html', 'teacher.html', 'poll.html', 'api/'];
const PAGES = [...WITHOUT_PICTURE, ...readdirSync('sketches').filter((f) => f.endsWith('.html')).map((f) => `sketches/${f}`)];

test.use({ launchOptions: { executablePath: findBrowser() ?? undefined, args: [`--host-resolver-rules=MAP ${NAME} 127.0.0.1`] } });

let server;
let origin;
test.describe.configure({ mode: 'serial' });
test.beforeAll(async () => {
  test.setTimeout(120_000);
  const port = Number(process.env.CLASS_PORT ?? 0) + 10 || await freePort();
  server = await startClassServer(port, ['--allow-host', NAME]);
  origin = `http://${NAME}:${server.port}/`;
});
test.afterAll(async () => { await server?.close(); });

test('the terminal names the computer\'s names and how to add one', async () => {
  await expect.poll(() => server.output()).toContain(`http://${NAME}:${server.port}/`);
  expect(server.output()).toContain('--allow-host NAME');
});

for (const path of PAGES) {
  test(`${path} through ${NAME}: not a secure context, nothing refused, a quiet console`, async ({ page }) => {
    test.setTimeout(120_000);
    const errors = watchConsole(page);
    const refused = [];
    page.on('response', (response) => { if (response.headers()['x-refused-by']) refused.push(`${response.status()} ${response.url()}`); });
    await page.goto(origin + path);
    expect(await page.evaluate(() => window.isSecureContext)).toBe(false);
    if (!WITHOUT_PICTURE.includes(path)) await waitForDone(page, 90_000);
    await page.waitForLoadState('networkidle');
    expect(refused).toEqual([]);
    expect(errors).toEqual([]);
  });
}

test('sketch 04\'s Copy answer copies on a plain-http address, and says so', async ({ page }) => {
  await page.goto(`${origin}sketches/04-find-the-pink-pixel.html`);
  await waitForDone(page);
  expect(await page.evaluate(() => navigator.clipboard === undefined)).toBe(true); // what an untrusted origin gets
  await clickPixel(page.locator('[data-tracer]').first(), 10, 12);
  await page.locator('[data-check]').click();
  await expect(page.locator('[data-answer-line]')).toContainText('Pixel:');
  await page.getByRole('button', { name: 'Copy answer' }).click();
  await expect(page.locator('[data-copied]')).toHaveText(/^(Copied|Select the answer and press Ctrl\+C)/);
  await expect(page.locator('[data-copied]')).toHaveText(/^Copied/); // execCommand('copy') within the click
});

/** Watches a page for answers the class gate refused. */
function refusals(page) {
  const refused = [];
  page.on('response', (response) => { if (response.headers()['x-refused-by']) refused.push(`${response.status()} ${response.url()}`); });
  return refused;
}

test(`the poll through ${NAME} reaches the class board, open by the same name: live, nothing refused, quiet consoles`, async ({ browser }) => {
  test.setTimeout(120_000);
  await expect.poll(() => server.output()).toMatch(/\/board\?key=[\w-]+/);
  const key = /\/board\?key=([\w-]+)/.exec(server.output())[1];
  const board = await browser.newPage();
  const student = await browser.newPage();
  const consoles = [watchConsole(board), watchConsole(student)];
  const refused = [...[board, student].map(refusals)];
  await board.goto(`${origin}board?key=${key}`);
  expect(await board.evaluate(() => window.isSecureContext)).toBe(false);
  await expect(board.locator('[data-live]')).toHaveAttribute('data-live', 'live', { timeout: 30_000 });
  const before = Number(await board.locator('[data-poll="2"] .bar-count').textContent());

  await student.goto(`${origin}poll.html`);
  await expect(student.locator('[data-poll-where]')).toContainText('Your teacher sees how many chose each answer');
  await student.getByLabel('2 · neutral').check();
  await student.getByRole('button', { name: 'Send my answer' }).press('Enter');
  await expect(student.locator('[data-poll-form] [data-received]')).toContainText('Received by the class board');
  await expect(board.locator('[data-poll="2"] .bar-count')).toHaveText(String(before + 1));

  const stranger = await browser.newPage();
  expect((await stranger.goto(`${origin}board`)).status()).toBe(403); // without the key, by name as by number
  await stranger.close();
  for (const list of refused) expect(list).toEqual([]);
  for (const errors of consoles) expect(errors).toEqual([]);
});
