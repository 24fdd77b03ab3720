// The class board as a class uses it: a student's page and the teacher's
// board open at once on `npm run class -- --data DIR`; a Check, a task, a
// homework check and the poll appear on the board; the board's key (403
// without it); hostile nicknames and answers shown as text; a crash (kill -9)
// and a restart lose nothing a student was told was received; 30 students
// sending ten answers each while one laptop floods; and on the dev server
// nothing is sent. How fast (a submit to the board, the flood's waits) is
// measured by `npm run bench:class`, not asserted: the machine is shared.
import { test, expect } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { spawn } from 'node:child_process';
import { Camera, classScene, inspectPixel, pinkPixelVerdict } from '../../lib/index.js';
import { watchConsole, waitForDone, clickPixel } from './helpers.js';
import { startBoardServer } from './board-server.js';

const TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa'];
const SCREEN = { width: 32, height: 24, fov: 30 };
const camera = new Camera(SCREEN);
const pixels = [];
for (let y = 0; y < 24; y++) for (let x = 0; x < 32; x++) pixels.push({ x, y, pink: pinkPixelVerdict(inspectPixel(classScene(), camera, x, y)).pink });
const PINK = pixels.filter((p) => p.pink);
const NOT_PINK = pixels.filter((p) => !p.pink);
const HOSTILE = '<img src=x onerror="window.__xss=1">"><svg onload=alert(1)>';

let data, server;
test.describe.configure({ mode: 'serial' });
test.beforeAll(async () => {
  test.setTimeout(120_000);
  data = mkdtempSync(join(tmpdir(), 'class-board-'));
  server = await startBoardServer({ data, port: Number(process.env.CLASS_PORT) || undefined });
});
test.afterAll(async () => {
  await server?.close();
  rmSync(data, { recursive: true, force: true });
});

/** The board, open and live. */
async function openBoard(page) {
  await page.goto(server.board);
  await expect(page.locator('[data-live]')).toHaveAttribute('data-live', 'live', { timeout: 30_000 }); // the first time, the server prepares the board's modules
}

/** Says hello as a student's page does: the laptop's id and secret (and name, status, error). */
async function hello(laptop, nickname, secret = '') {
  const answer = await fetch(`${server.url}class/hello`, { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-RT-Laptop-Secret': secret }, body: JSON.stringify({ laptop, nickname }) });
  return { status: answer.status, ...(await answer.json()) };
}

/** Sends as a student's page does (JSON to /class/send, with the laptop's secret). */
async function send(body, { secret }) {
  const answer = await fetch(`${server.url}class/send`, { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-RT-Laptop-Secret': secret }, body: JSON.stringify(body) });
  return { status: answer.status, body: await answer.json() };
}

const stateOf = async () => (await fetch(`${server.url}board/state?key=${server.key}`)).json();

test('the terminal names the board\'s folder and address; the board passes axe, at 320 px too', async ({ page }) => {
  expect(server.output()).toContain(join(data, 'board.sqlite'));
  expect(server.board).toMatch(/\/board\?key=[\w-]{20,}$/);
  const errors = watchConsole(page);
  await openBoard(page);
  expect((await new AxeBuilder({ page }).withTags(TAGS).analyze()).violations.filter((v) => ['serious', 'critical'].includes(v.impact)).map((v) => v.id)).toEqual([]);
  await page.setViewportSize({ width: 320, height: 800 });
  expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(320);
  expect(errors).toEqual([]);
});

test('a Check on sketch 04 is on the board, marked received on the student\'s page; a wrong one is a cross', async ({ browser }) => {
  test.setTimeout(120_000);
  const board = await (await browser.newContext({ viewport: { width: 1600, height: 1000 } })).newPage();
  const student = await (await browser.newContext()).newPage();
  const errors = [watchConsole(board), watchConsole(student)];
  await openBoard(board);
  await student.goto(`${server.url}sketches/04-find-the-pink-pixel.html`);
  await waitForDone(student, 60_000);
  await student.getByLabel('Your name on the board').fill('Nina');
  await student.getByRole('button', { name: 'Save name' }).click();
  await expect(student.locator('[data-class-name]')).toHaveText('Nina');
  expect(await board.locator('[data-answer]').count()).toBe(0); // selecting pixels on opening sends nothing

  const pink = PINK[5], white = NOT_PINK[0];
  await student.getByLabel('Pixel x').fill(String(pink.x));
  await student.getByLabel('Pixel y').fill(String(pink.y));
  await student.getByRole('button', { name: 'Check', exact: true }).click();
  await expect(board.locator('[data-board-answers]')).toHaveText('1'); // how soon: npm run bench:class
  await expect(student.locator('#activity [data-received]')).toContainText('Received by the class board (as Nina)');
  const mark = board.locator('[data-answer]');
  await expect(mark).toHaveAttribute('data-pixel', `${pink.x},${pink.y}`);
  await expect(mark).toHaveAttribute('data-verdict', 'right');
  await expect(board.locator('[data-count="right"]')).toHaveText('1');
  await mark.focus();
  await expect(mark.locator('.tip')).toBeVisible();
  await expect(mark.locator('.tip')).toHaveText('Nina');

  await student.getByLabel('Pixel x').fill(String(white.x));
  await student.getByLabel('Pixel y').fill(String(white.y));
  await student.getByLabel('Pixel y').press('Enter');
  await expect(board.locator('[data-board-answers]')).toHaveText('2');
  const cross = board.locator(`[data-answer][data-pixel="${white.x},${white.y}"]`);
  await expect(cross).toHaveAttribute('data-verdict', 'wrong');
  await expect(cross).toContainText('✕');
  await board.keyboard.press('ArrowRight'); // from the first mark to the next
  await expect(cross).toBeFocused();
  // Its tasks came too: "check an answer" and "find a pink pixel", by one student.
  await expect(board.locator('[data-page="04"] [data-task="check"] .bar-count')).toHaveText('1 of 1');
  await board.screenshot({ path: test.info().outputPath('board.png') });
  for (const e of errors) expect(e).toEqual([]);
});

test('a task, a homework check and the poll reach the board', async ({ browser }) => {
  test.setTimeout(120_000);
  const board = await browser.newPage();
  await openBoard(board);
  const student = await (await browser.newContext()).newPage();
  const errors = watchConsole(student);
  await student.goto(`${server.url}sketches/01-rays-through-pixels.html`);
  await waitForDone(student, 60_000);
  await clickPixel(student.locator('[data-tracer]').first(), 3, 3);
  await expect(student.locator('#tasks [data-received]')).toBeVisible();
  await expect(board.locator('[data-page="01"] [data-task="select"] .bar-count')).toHaveText(/^1 of \d+$/);

  await student.goto(`${server.url}sketches/08-homework-traffic-signal.html`);
  await waitForDone(student, 60_000);
  await student.getByRole('button', { name: 'Check my scene' }).click();
  await expect(student.locator('.rt-check [data-received]')).toBeVisible();
  await expect(board.locator('[data-homework="08"]')).toContainText('0 passed');
  await expect(board.locator('[data-homework="08"]')).toContainText('of 1 who checked');

  await student.goto(`${server.url}poll.html`);
  await student.getByLabel('3 · positive').check();
  await student.getByRole('button', { name: 'Send my answer' }).click();
  await expect(student.locator('[data-poll-form] [data-received]')).toBeVisible();
  await expect(board.locator('[data-poll="3"] .bar-count')).toHaveText('1');
  expect((await new AxeBuilder({ page: student }).withTags(TAGS).analyze()).violations.filter((v) => ['serious', 'critical'].includes(v.impact)).map((v) => v.id)).toEqual([]);
  expect(errors).toEqual([]);
});

test('the name bar shows the server\'s word next to the box when a name is refused, and the old name stays', async ({ browser }) => {
  test.setTimeout(120_000);
  await hello('name-owner-laptop', 'Noor');
  const student = await (await browser.newContext()).newPage();
  const errors = watchConsole(student);
  await student.goto(`${server.url}poll.html`);
  const shown = student.locator('[data-class-name]');
  await expect(shown).toHaveText(/^student \d+$/);
  const anonymous = await shown.textContent();
  const box = student.getByLabel('Your name on the board');
  const problem = student.locator('[data-class-problem]');
  await expect(box).toHaveAttribute('aria-describedby', await problem.getAttribute('id'));
  await expect(problem).toHaveAttribute('role', 'alert');
  for (const [name, message] of [['NOOR', /^Not saved: name "NOOR" is taken/], ['Student 1', /^Not saved: name reads like the board's label/], ['\u3164', /^Not saved: name is blank/]]) {
    await box.fill(name);
    await student.getByRole('button', { name: 'Save name' }).click();
    await expect(problem).toHaveText(message);
    await expect(box).toHaveAttribute('aria-invalid', 'true');
    await expect(shown).toHaveText(anonymous);
  }
  expect(await student.evaluate(() => localStorage.getItem('rt-class-nickname'))).toBeNull();
  await box.fill('Noor B');
  await student.getByRole('button', { name: 'Save name' }).click();
  await expect(shown).toHaveText('Noor B');
  await expect(problem).toHaveText('');
  await expect(box).toHaveAttribute('aria-invalid', 'false');
  expect((await new AxeBuilder({ page: student }).withTags(TAGS).analyze()).violations.filter((v) => ['serious', 'critical'].includes(v.impact)).map((v) => v.id)).toEqual([]);
  // The console has only the browser's own line for each name refused (a 400): nothing of the page's.
  expect(errors).toEqual(Array(3).fill('error: Failed to load resource: the server responded with a status of 400 (Bad Request)'));
});

test('what waited in the outbox before the laptop had a secret still arrives, under a laptop of its own', async ({ browser }) => {
  test.setTimeout(120_000);
  const taken = await hello('someone-elses-laptop-1', 'Owner'); // its id, written into another page's storage: not handed over
  const context = await browser.newContext();
  const queued = { id: 'queued-before-secret', kind: 'answer', line: `Pixel: ${NOT_PINK[7].x},${NOT_PINK[7].y}; H: 0; V: 0`, ...SCREEN };
  await context.addInitScript(([laptop, item]) => {
    if (sessionStorage.getItem('seeded')) return;
    sessionStorage.setItem('seeded', '1');
    localStorage.setItem('rt-class-laptop', laptop);
    localStorage.setItem('rt-class-outbox', JSON.stringify([item]));
  }, [taken.laptop, queued]);
  const student = await context.newPage();
  const errors = watchConsole(student);
  const before = (await stateOf()).answers.length;
  await student.goto(`${server.url}poll.html`);
  await expect.poll(async () => (await stateOf()).answers.length, { timeout: 30_000 }).toBe(before + 1);
  const state = await stateOf();
  expect(state.answers.at(-1).line).toBe(queued.line);
  expect(state.students.find((s) => s.number === state.answers.at(-1).student)?.name).not.toBe('Owner');
  const kept = await student.evaluate(() => [localStorage.getItem('rt-class-laptop'), localStorage.getItem('rt-class-secret'), localStorage.getItem('rt-class-outbox')]);
  expect(kept[0]).not.toBe(taken.laptop);
  expect(kept[1]).toMatch(/^[\w-]{43}$/);
  expect(JSON.parse(kept[2])).toEqual([]);
  expect(errors).toEqual([]);
});

test('another origin cannot write to the class board: its page\'s POST is refused and nothing is stored', async ({ browser }) => {
  const page = await (await browser.newContext()).newPage();
  const before = await stateOf();
  await page.goto(`${server.url.replace('127.0.0.1', 'localhost')}favicon-elsewhere`).catch(() => {}); // a page of another origin (another name of this server)
  const outcome = await page.evaluate(async (url) => {
    try {
      const answer = await fetch(`${url}class/hello`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify({ laptop: 'cross-origin-laptop', nickname: 'Mallory' }) });
      return `answered ${answer.status}`;
    } catch (error) { return `refused: ${error.name}`; }
  }, server.url);
  expect(outcome).toBe('refused: TypeError'); // the preflight was refused: the browser never sent it
  const simple = await page.evaluate(async (url) => {
    try { await fetch(`${url}class/hello`, { method: 'POST', mode: 'no-cors', headers: { 'Content-Type': 'text/plain' }, body: '{"laptop":"cross-origin-laptop-2"}' }); return 'sent'; } catch { return 'refused'; }
  }, server.url);
  expect(simple).toBe('sent'); // a simple request goes out, opaque to the page: the server refused it (403), as the state shows
  const after = await stateOf();
  expect(after.students).toEqual(before.students);
  expect(after.refusedCount).toBe(before.refusedCount);
});

test('without the key the board and its actions answer 403; a student\'s routes read nothing', async ({ request }) => {
  for (const path of ['board', 'board/state', 'board/events', 'board/class.csv']) {
    for (const key of ['', '?key=', `?key=${server.key}0`, `?key=${server.key.toUpperCase()}`]) {
      const answer = await request.get(server.url + path + key);
      expect(answer.status(), path + key).toBe(403);
      expect(await answer.text()).not.toContain('answers');
    }
  }
  expect((await request.post(`${server.url}board/clear`)).status()).toBe(403);
  expect((await request.post(`${server.url}board/clear?key=nope`)).status()).toBe(403);
  for (const path of ['class/send', 'class/hello', 'class/state', 'class/']) expect((await request.get(server.url + path)).status(), path).toBe(404);
});

test('hostile nicknames and answers: refused with the field named, or shown as text; the board lists what was refused, as text', async ({ page }) => {
  const errors = watchConsole(page);
  let dialogs = 0;
  page.on('dialog', (d) => { dialogs++; d.dismiss(); });
  const me = await hello('hostile-laptop-1');
  const laptop = me.laptop;
  const refused = await send({ laptop, id: 'h1', kind: 'answer', line: HOSTILE, ...SCREEN }, me);
  expect(refused.status).toBe(400);
  expect(refused.body.error).toMatch(/^line must/);
  expect((await send({ laptop, id: 'h2', kind: 'answer', nickname: 'x'.repeat(41), line: 'Pixel: 1,1; H: 0; V: 0', ...SCREEN }, me)).body.error).toMatch(/^name is too long/);
  const liar = await send({ laptop, nickname: HOSTILE.slice(0, 40), id: 'h3', kind: 'answer', line: `Pixel: ${NOT_PINK[3].x},${NOT_PINK[3].y}; H: 0; V: 0`, ...SCREEN, verdict: 'right' }, me);
  expect(liar.status).toBe(200);
  // Without the laptop's secret: refused, and nothing of it on the board.
  expect((await send({ laptop, id: 'h4', kind: 'answer', line: 'Pixel: 2,2; H: 0; V: 0', ...SCREEN }, { secret: '' })).status).toBe(403);
  await openBoard(page);
  const list = page.locator('[data-refused]');
  await expect(list.locator('li[data-refused-what="answer"]').filter({ hasText: 'line must read like' })).toHaveCount(1);
  await expect(list.locator('li[data-refused-what="answer"]').filter({ hasText: 'name is too long' })).toHaveCount(1);
  await expect(list.locator('li').first()).toContainText(HOSTILE.slice(0, 40)); // the newest first, its name as text
  await expect(page.locator('[data-refused-count]')).toHaveText(/^[1-9]\d*$/);
  const mark = page.locator(`[data-answer][data-pixel="${NOT_PINK[3].x},${NOT_PINK[3].y}"]`);
  await expect(mark).toHaveAttribute('data-verdict', 'wrong'); // judged again: the page's "right" is not taken
  await expect(mark).toHaveAttribute('aria-label', new RegExp(`^${HOSTILE.slice(0, 40).replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}:`));
  await expect(page.locator('[data-latest]')).toContainText(HOSTILE.slice(0, 40));
  expect(await page.locator('main img, main svg, main iframe').count()).toBe(0);
  expect(await page.evaluate(() => window.__xss)).toBeUndefined();
  expect(dialogs).toBe(0);
  expect(errors).toEqual([]);
});

test('kill -9, start again with the same folder: the board shows the same', async ({ page }) => {
  test.setTimeout(180_000);
  const before = await stateOf();
  const ada = await hello('restart-laptop', 'Ada');
  const last = await send({ laptop: ada.laptop, id: 'r1', kind: 'answer', line: `Pixel: ${PINK[0].x},${PINK[0].y}; H: 0; V: 0`, ...SCREEN }, ada);
  expect(last.body.received).toBe(true);
  await server.crash(); // right after "received": it must be on disk already
  server = await startBoardServer({ data, port: server.port });
  const after = await stateOf();
  expect(after.answers).toHaveLength(before.answers.length + 1);
  expect(after.answers.at(-1)).toMatchObject({ x: PINK[0].x, y: PINK[0].y, verdict: 'right' });
  expect(after.students.map((s) => s.name)).toContain('Ada');
  await openBoard(page);
  await expect(page.locator('[data-board-answers]')).toHaveText(String(after.answers.length));
  await expect(page.locator('[data-answer]')).toHaveCount(after.answers.length);
  // Sent again (the page was not sure it arrived): still once; the laptop's secret outlived the crash.
  expect((await send({ laptop: ada.laptop, id: 'r1', kind: 'answer', line: `Pixel: ${PINK[0].x},${PINK[0].y}; H: 0; V: 0`, ...SCREEN }, ada)).body.again).toBe(true);
  expect((await stateOf()).answers).toHaveLength(after.answers.length);
});

test('30 students send ten answers each while one laptop floods: every student\'s answer stored once and on the board, the flooder told to wait and its answers sent in turn', async ({ page, browser }) => {
  test.setTimeout(180_000);
  await openBoard(page);
  const start = (await stateOf()).answers.length;
  const flooder = await (await browser.newContext()).newPage();
  const errors = watchConsole(flooder);
  const statuses = [];
  flooder.on('response', (r) => { if (r.url().endsWith('/class/send')) statuses.push(r.status()); });
  await flooder.goto(`${server.url}sketches/04-find-the-pink-pixel.html`);
  await waitForDone(flooder, 60_000);
  await flooder.getByLabel('Your name on the board').fill('Flood');
  await flooder.getByRole('button', { name: 'Save name' }).click();
  await expect(flooder.locator('[data-class-name]')).toHaveText('Flood');
  await flooder.getByLabel('Pixel x').fill(String(PINK[1].x));
  await flooder.getByLabel('Pixel y').fill(String(PINK[1].y));

  const students = spawn(process.execPath, ['tests/e2e/flood-students.js', server.url, '30', '10', JSON.stringify(pixels)], { stdio: ['ignore', 'pipe', 'inherit'] });
  let out = '';
  students.stdout.on('data', (d) => { out += d; });
  const studentsDone = new Promise((done) => students.on('exit', done));
  // 40 Checks in one go, more than a laptop may send at once (30): a page in a loop, or a script.
  await flooder.locator('#activity form').evaluate((form) => { for (let i = 0; i < 40; i++) form.requestSubmit(); });
  const line = flooder.locator('#activity [data-class-sent]');
  await expect(line).toContainText('Not sent yet: too many sends from this laptop. The next goes in', { timeout: 15_000 });
  await expect(line).toHaveAttribute('data-class-sent', 'waiting');
  await studentsDone;

  // The other students were not held back by the flooder: each answer received, stored once, on the board.
  const { results } = JSON.parse(out);
  expect(results.map((r) => r.status)).toEqual(Array(330).fill(200));
  expect(results.filter((r) => r.again)).toHaveLength(30); // the answers sent twice, kept once
  // The flooder's page sends what waited, in turn, until the server has every one.
  await expect(line).toHaveAttribute('data-received', '', { timeout: 90_000 });
  await expect(line).toContainText('Received by the class board (as Flood)');
  expect(statuses.filter((s) => s === 429).length, 'answers refused for now').toBeGreaterThan(0);
  expect(statuses.filter((s) => s !== 200 && s !== 429)).toEqual([]);

  const { answers, students: names } = await stateOf();
  const flood = answers.slice(start);
  const floodNumber = names.find((n) => n.name === 'Flood').number;
  const fromStudents = flood.filter((a) => a.student !== floodNumber);
  expect(fromStudents).toHaveLength(300);
  expect(new Set(fromStudents.map((a) => `${a.student} ${a.line}`)).size).toBe(300);
  expect(flood.filter((a) => a.student === floodNumber)).toHaveLength(40);
  await expect(page.locator('[data-board-answers]')).toHaveText(String(start + 340), { timeout: 15_000 });
  await expect(page.locator('[data-answer]')).toHaveCount(start + 340);
  // The console has only the browser's own line for each answer refused for now (a 429): nothing of the page's.
  const refusedNow = /^error: Failed to load resource: the server responded with a status of 429 \(Too Many Requests\)$/;
  expect(errors.filter((e) => !refusedNow.test(e))).toEqual([]);
  expect(errors.filter((e) => refusedNow.test(e))).toHaveLength(statuses.filter((s) => s === 429).length);
});

test('Clear the board asks first, then archives the class and starts anew; Download CSV has every row', async ({ page }) => {
  await openBoard(page);
  const { answers } = await stateOf();
  expect(answers.length).toBeGreaterThan(0);
  const csv = (await (await fetch(`${server.url}board/class.csv?key=${server.key}`)).text()).trim().split('\r\n');
  expect(csv.slice(1).filter((row) => row.includes(',answer,'))).toHaveLength(answers.length); // each answer once, among the other kinds
  const download = page.waitForEvent('download');
  await page.getByRole('link', { name: 'Download CSV' }).click();
  expect((await download).suggestedFilename()).toMatch(/^class-\d+-\d{4}-\d\d-\d\d\.csv$/);
  await page.getByRole('button', { name: 'Clear the board…' }).click();
  await expect(page.getByRole('dialog')).toBeVisible();
  await page.getByRole('button', { name: 'Keep the board' }).click();
  await expect(page.locator('[data-board-answers]')).toHaveText(String(answers.length));
  await page.getByRole('button', { name: 'Clear the board…' }).click();
  await page.getByRole('button', { name: 'Clear and start anew' }).click();
  await expect(page.locator('[data-board-answers]')).toHaveText('0');
  await expect(page.locator('[data-answer]')).toHaveCount(0);
});

test('on the dev server (npm start) a page sends nothing and shows nothing of the board', async ({ page }) => {
  const errors = watchConsole(page);
  const asked = [];
  page.on('request', (r) => asked.push(new URL(r.url()).pathname));
  await page.goto('/sketches/04-find-the-pink-pixel.html');
  await waitForDone(page);
  await page.getByRole('button', { name: 'Check', exact: true }).click();
  await expect(page.locator('[data-result]')).not.toBeEmpty();
  await page.goto('/poll.html');
  await page.getByLabel('2 · neutral').check();
  await page.getByRole('button', { name: 'Send my answer' }).click();
  await expect(page.locator('[data-poll-result]')).toHaveText('Your answer: 2 · neutral.');
  await expect(page.locator('[data-poll-where]')).toContainText('nothing is sent');
  expect(await page.locator('[data-class-sent], .rt-class-bar').count()).toBe(0);
  expect(asked.filter((p) => p.startsWith('/class/'))).toEqual([]);
  expect(errors).toEqual([]);
});
