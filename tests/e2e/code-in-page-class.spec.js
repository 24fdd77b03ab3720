// The homework done in the page on the class server, as a student's laptop
// reaches it: by a name the browser does not trust (plain http, not
// localhost), mapped to 127.0.0.1 by Chromium, so nothing leaves loopback.
// The student edits the starter in the editor until the self-check passes.
import { readFileSync } from 'node:fs';
import { test, expect } from '@playwright/test';
import { findBrowser } from '../../scripts/find-browser.js';
import { startClassServer } from './class-server.js';
import { setCode, editorText, waitForRun, sketchFrame } from './code-editor.js';

const HOST = 'class.test';
const STARTER = readFileSync('sketches/08-homework-traffic-signal.js', 'utf8');
const TODO = '  // TODO: your three lights here.';
const lights = (...lines) => STARTER.replace(TODO, lines.map((line) => `  scene.add(${line});`).join('\n'));
const RED = 'new Sphere([0, 6.5, -15.9], 0.45, { color: [0, 0, 0], emission: [1, 0, 0] })';
const YELLOW = 'new Sphere([0, 5.4, -15.9], 0.45, { color: [0, 0, 0], emission: [1, 0.85, 0] })';
const GREEN = 'new Sphere([0, 4.3, -15.9], 0.45, { color: [0, 0, 0], emission: [0, 1, 0.2] })';

test.use({ launchOptions: { executablePath: findBrowser() ?? undefined, args: [`--host-resolver-rules=MAP ${HOST} 127.0.0.1`] } });
test.describe.configure({ timeout: 300_000 });

let server;
test.beforeAll(async () => {
  // The name a student types for the teacher's computer, as the teacher lets it in.
  server = await startClassServer(undefined, ['--allow-host', HOST]);
});
test.afterAll(async () => { await server?.close(); });

test('on the class server, reached by a name: the homework starter edited in the page until its self-check passes', async ({ page }) => {
  const url = server.url.replace('127.0.0.1', HOST);
  await page.goto(`${url}sketches/08-homework-traffic-signal.html`);
  expect(await page.evaluate(() => window.isSecureContext)).toBe(false); // as on a classroom's network
  await expect(page.locator('[data-editor]')).toBeVisible({ timeout: 60_000 });
  expect(await editorText(page)).toBe(STARTER); // the starter, read as the student saves it

  await setCode(page, lights(RED));
  await waitForRun(page, 1, 120_000);
  const frame = sketchFrame(page);
  await frame.getByRole('button', { name: 'Check my scene' }).click();
  await expect(frame.locator('[data-check-results]')).toHaveAttribute('data-check', 'not-yet');
  await expect(frame.locator('[data-check-item="failed"]').first()).toContainText('Found 1 light (red)');
  await expect(page.locator('[data-code-panel]')).toHaveAttribute('data-check', 'not-yet');

  await setCode(page, lights(RED, YELLOW, GREEN));
  await waitForRun(page, 2, 120_000);
  await frame.getByRole('button', { name: 'Check my scene' }).click();
  await expect(frame.locator('[data-check-results]')).toHaveAttribute('data-check', 'passed');
  await expect(frame.locator('.hw-headline')).toHaveText(/^Passed!/);
  await expect(page.locator('[data-code-panel]')).toHaveAttribute('data-check', 'passed');
  // The frame's task list ticked "pass the self-check"; the page kept it with the student's progress.
  await expect.poll(() => page.evaluate(() => JSON.parse(localStorage.getItem('raytracing-sketchbook:tasks:v1') ?? '{}').pages?.['08'] ?? [])).toContain('pass');
  expect(await page.evaluate(() => localStorage.getItem('raytracing-sketchbook:code:v1:08-homework-traffic-signal'))).toContain(GREEN);
});
