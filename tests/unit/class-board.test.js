// The class board's server side (scripts/board/): every field of a submission
// checked, the answer judged again on the server, each submission kept once,
// kept across a reopen, archived by "Clear the board", the size cap, the rate
// limit, the key (403) and the CSV, through the routes as the class server mounts them.
import { describe, it, expect, beforeEach, afterEach } from 'vitest';
import { createServer } from 'node:http';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { Camera, classScene, inspectPixel, pinkPixelVerdict } from '../../lib/index.js';
import { checkSubmission, checkHello, BadSubmission, NICKNAME_MAX } from '../../scripts/board/checks.js';
import { judgeAnswer } from '../../scripts/board/judge.js';
import { openStore, BoardFullError } from '../../scripts/board/store.js';
import { RateLimit } from '../../scripts/board/limits.js';
import { boardRoutes, BOARD_ROUTES, groupCommit } from '../../scripts/board/routes.js';
import { boardCSV } from '../../scripts/board/csv.js';
import { isStudentRoute } from '../../scripts/class-gate.js';
import { folderFrom, boardKey, loadDatabase } from '../../scripts/board/setup.js';

// better-sqlite3 is an optional dependency: where it could not be built, each
// test of the database fails with the reason and what to install (CI builds it: .ci/run).
const loaded = await loadDatabase();
const Database = loaded.Database ?? class { constructor() { throw new Error(loaded.problem); } };

const LAPTOP = 'laptop-0001';
const SCREEN = { width: 32, height: 24, fov: 30 };
/** The pink and the not pink pixels of sketch 04's first picture, found as the page finds them. */
const camera = new Camera(SCREEN);
const verdicts = [];
for (let y = 0; y < 24; y++) for (let x = 0; x < 32; x++) verdicts.push({ x, y, pink: pinkPixelVerdict(inspectPixel(classScene(), camera, x, y)).pink });
const PINK = verdicts.find((p) => p.pink);
const WHITE = verdicts.find((p) => !p.pink);
const answer = (p, more = {}) => ({ laptop: LAPTOP, id: `a${p.x}-${p.y}`, kind: 'answer', line: `Pixel: ${p.x},${p.y}; H: 0; V: 0`, ...SCREEN, ...more });

let folder;
beforeEach(() => { folder = mkdtempSync(join(tmpdir(), 'board-')); });
afterEach(() => rmSync(folder, { recursive: true, force: true }));

describe('a submission, field by field', () => {
  it('reads the answer line with the lesson\'s reader and judges it again: the page\'s verdict is only what the page said', () => {
    const right = checkSubmission(answer(PINK, { verdict: 'wrong', color: '#000000' }));
    expect(right).toMatchObject({ x: PINK.x, y: PINK.y, h: 0, v: 0, verdict: 'right', colorName: 'pink', pageSaid: 'wrong #000000' });
    const wrong = checkSubmission(answer(WHITE, { verdict: 'right' }));
    expect(wrong.verdict).toBe('wrong');
    expect(wrong.line).toBe(`Pixel: ${WHITE.x},${WHITE.y}; H: 0; V: 0`);
    expect(judgeAnswer({ ...PINK, h: 0, v: 0, ...SCREEN }).verdict).toBe('right');
  });

  it('refuses each bad field with a message naming it', () => {
    const bad = (sent, message) => expect(() => checkSubmission(sent)).toThrow(message);
    bad(null, /JSON object/);
    bad([], /JSON object/);
    bad({ ...answer(PINK), kind: 'vote' }, /kind must be one of/);
    bad({ ...answer(PINK), kind: '__proto__' }, /kind must be one of/);
    bad({ ...answer(PINK), extra: 1 }, /unknown field "extra"/);
    bad({ ...answer(PINK), laptop: 'x' }, /laptop must be/);
    bad({ ...answer(PINK), id: '../../etc' }, /id must be/);
    bad({ ...answer(PINK), nickname: 'n'.repeat(NICKNAME_MAX + 1) }, /^name is too long/);
    bad({ ...answer(PINK), nickname: 'a\u202Eb' }, /^name must not hold control, format or direction characters \(it holds U\+202E\)/);
    bad({ ...answer(PINK), nickname: 12 }, /^name must be text/);
    bad({ ...answer(PINK), line: '<img src=x onerror=alert(1)>' }, /line must read like/);
    bad({ ...answer(PINK), line: `Pixel: 1,1; H: 0; V: 0${' '.repeat(300)}` }, /at most 200/);
    bad({ ...answer(PINK), line: 'Pixel: 99,1; H: 0; V: 0' }, /pixel's x must be a whole number from 0 to 31/);
    bad({ ...answer(PINK), line: 'Pixel: 1.5,1; H: 0; V: 0' }, /pixel's x/);
    bad({ ...answer(PINK), line: 'Pixel: 1,1; H: 500; V: 0' }, /H must be a number from -180 to 180/);
    bad({ ...answer(PINK), width: 1e9 }, /width must be a whole number/);
    bad({ ...answer(PINK), fov: 'wide' }, /fov must be a number/);
    bad({ ...answer(PINK), verdict: 'pink!' }, /verdict must be/);
    bad({ ...answer(PINK), color: 'red; background: url(x)' }, /color must be like/);
    bad({ laptop: LAPTOP, id: 't1', kind: 'task', page: '01', task: 'nope' }, /task must be one of page 01's/);
    bad({ laptop: LAPTOP, id: 't1', kind: 'task', page: '99', task: 'select' }, /page must be one of/);
    bad({ laptop: LAPTOP, id: 'c1', kind: 'check', page: '04', passed: true, toFix: 0 }, /page must be 08 or 09/);
    bad({ laptop: LAPTOP, id: 'c1', kind: 'check', page: '08', passed: 'yes', toFix: 0 }, /passed must be true or false/);
    bad({ laptop: LAPTOP, id: 'p1', kind: 'poll', value: 4 }, /value must be a whole number from 1 to 3/);
    expect(() => checkHello({ laptop: LAPTOP, nickname: 'Nina', admin: true })).toThrow(BadSubmission);
  });

  it('keeps a nickname as text, trimmed; an empty one is no nickname', () => {
    expect(checkHello({ laptop: LAPTOP, nickname: '  <b>Nina</b> ' }).nickname).toBe('<b>Nina</b>');
    expect(checkHello({ laptop: LAPTOP, nickname: '   ' }).nickname).toBeUndefined();
    expect(checkHello({ laptop: LAPTOP, nickname: '👩‍🔬'.repeat(8) }).nickname).toHaveLength(40); // emoji with joiners are fine
  });
});

describe('the store', () => {
  it('keeps a submission once, however often it is sent; names a laptop "student N" until it has a nickname', () => {
    const store = openStore(folder, { Database });
    const first = store.add(checkSubmission(answer(PINK)));
    expect(first).toEqual({ number: 1, name: 'student 1', stored: true });
    expect(store.add(checkSubmission(answer(PINK))).stored).toBe(false);
    store.hello('laptop-0002');
    store.rename('laptop-0002', 'Nina');
    store.add(checkSubmission({ ...answer(WHITE), laptop: 'laptop-0002' }));
    const state = store.state();
    expect(state.answers.map((a) => a.verdict)).toEqual(['right', 'wrong']);
    expect(state.students).toEqual([{ number: 1, name: 'student 1' }, { number: 2, name: 'Nina' }]);
    store.close();
  });

  it('keeps everything across a reopen; Clear archives the class and starts a new one', () => {
    let store = openStore(folder, { Database });
    store.add(checkSubmission(answer(PINK)));
    store.add(checkSubmission({ laptop: LAPTOP, id: 't1', kind: 'task', page: '04', task: 'pink' }));
    store.add(checkSubmission({ laptop: LAPTOP, id: 'p1', kind: 'poll', value: 1 }));
    store.add(checkSubmission({ laptop: LAPTOP, id: 'p2', kind: 'poll', value: 3 })); // the last answer counts
    store.add(checkSubmission({ laptop: LAPTOP, id: 'c1', kind: 'check', page: '08', passed: false, toFix: 2 }));
    store.add(checkSubmission({ laptop: LAPTOP, id: 'c2', kind: 'check', page: '08', passed: true, toFix: 0 }));
    store.close();
    store = openStore(folder, { Database });
    const state = store.state();
    expect(state.answers).toHaveLength(1);
    expect(state.tasks).toEqual([{ page: '04', task: 'pink', students: 1 }]);
    expect(state.poll).toEqual([{ value: 3, students: 1 }]);
    expect(state.homework).toEqual([{ page: '08', passed: 1, students: 1, checks: 2 }]);
    const before = store.currentClass.id;
    expect(store.clear().id).toBeGreaterThan(before);
    expect(store.state()).toMatchObject({ answers: [], students: [], tasks: [], poll: [], homework: [] });
    store.close();
    store = openStore(folder, { Database }); // the new class stays the current one
    expect(store.currentClass.id).toBeGreaterThan(before);
    store.close();
  });

  it('stops at its size cap with a BoardFullError (what was stored stays)', () => {
    const store = openStore(folder, { Database, maxBytes: 200 * 1024 });
    let full = null;
    for (let i = 0; i < 5000 && !full; i++) {
      try {
        store.add(checkSubmission({ laptop: `laptop-${String(i).padStart(6, '0')}`, nickname: 'n'.repeat(40), id: `a${i}`, kind: 'answer', line: 'Pixel: 1,1; H: 0; V: 0', ...SCREEN }));
      } catch (error) { full = error; }
    }
    expect(full).toBeInstanceOf(BoardFullError);
    expect(full.message).toMatch(/full/);
    expect(store.state().answers.length).toBeGreaterThan(100);
    store.close();
  });
});

describe('group commit', () => {
  it('writes what arrives together in one transaction, each told its own result; a failed write fails each', async () => {
    const writes = [];
    const keep = groupCommit((items) => { writes.push(items); return items.map((i) => i * 10); });
    expect(await Promise.all([keep(1), keep(2), keep(3)])).toEqual([10, 20, 30]);
    expect(await keep(4)).toBe(40);
    expect(writes).toEqual([[1, 2, 3], [4]]);
    const failing = groupCommit(() => { throw new BoardFullError('full'); });
    await expect(Promise.all([failing(1), failing(2)])).rejects.toThrow('full');
  });
});

describe('the rate limit', () => {
  it('lets a burst through, then one a second, and says how long to wait', () => {
    let t = 0;
    const limit = new RateLimit({ burst: 3, perSecond: 1, now: () => t });
    expect([limit.take('a'), limit.take('a'), limit.take('a')]).toEqual([0, 0, 0]);
    expect(limit.take('a')).toBe(1);
    expect(limit.take('b')).toBe(0); // another laptop has its own
    t = 1000;
    expect(limit.take('a')).toBe(0);
  });
});

describe('the routes', () => {
  let server, base, store, key;
  beforeEach(async () => {
    store = openStore(folder, { Database });
    key = boardKey(folder);
    const routes = boardRoutes({ store, key, limits: { laptop: new RateLimit({ burst: 5, perSecond: 0.001 }), address: new RateLimit({ burst: 1000, perSecond: 100 }) } });
    server = createServer((req, res) => routes(req, res, () => { res.statusCode = 204; res.end(); }));
    await new Promise((done) => server.listen(0, '127.0.0.1', done));
    base = `http://127.0.0.1:${server.address().port}`;
    server.on('close', () => routes.close());
  });
  afterEach(async () => {
    await new Promise((done) => server.close(done));
    store.close();
  });
  let secret;
  const post = (path, body, type = 'application/json') => fetch(base + path, { method: 'POST', headers: { 'Content-Type': type, 'X-RT-Laptop-Secret': secret ?? '' }, body: typeof body === 'string' ? body : JSON.stringify(body) });
  /** Says hello as LAPTOP (its secret is then sent with each post). */
  const hello = async (nickname) => {
    secret = undefined;
    const answer = await (await post('/class/hello', { laptop: LAPTOP, nickname })).json();
    secret = answer.secret;
    return answer;
  };

  it('answers 403 to the board and its actions without the key, or with a wrong one', async () => {
    for (const path of ['/board', '/board/state', '/board/events', '/board/class.csv']) {
      for (const k of ['', '?key=', `?key=${key}x`, `?key=${key.slice(1)}`, `?KEY=${key}`]) {
        expect((await fetch(base + path + k)).status, path + k).toBe(403);
      }
    }
    expect((await post('/board/clear', {})).status).toBe(403);
    expect((await fetch(`${base}/board/state?key=${key}`)).status).toBe(200);
    expect((await fetch(`${base}/board?key=${key}`)).headers.get('content-security-policy')).toMatch(/default-src 'self'/);
    // A student's routes only take: nothing of theirs reads what others sent.
    expect((await fetch(`${base}/class/send`)).status).toBe(404);
    expect((await fetch(`${base}/class/state`)).status).toBe(404);
    expect((await fetch(`${base}/sketches/04-find-the-pink-pixel.html`)).status).toBe(204); // not the board's: passed on
  });

  it('stores a submission and says so; refuses bad JSON, a bad field, a long body; limits one laptop', async () => {
    await hello();
    const ok = await post('/class/send', answer(PINK));
    expect(ok.status).toBe(200);
    expect(await ok.json()).toEqual({ received: true, name: 'student 1', number: 1, again: false });
    expect(await (await post('/class/send', answer(PINK))).json()).toMatchObject({ received: true, again: true });
    expect((await post('/class/send', '{not json')).status).toBe(400);
    expect((await post('/class/send', JSON.stringify(answer(PINK)), 'text/plain')).status).toBe(400);
    const bad = await post('/class/send', { ...answer(PINK), line: 'pink!' });
    expect(bad.status).toBe(400);
    expect((await bad.json()).error).toMatch(/^line must/);
    expect((await post('/class/send', { ...answer(PINK), nickname: 'x'.repeat(10_000) })).status).toBe(413);
    await post('/class/send', answer(PINK, { id: 'more' })); // the fifth of five: the hello, two sends, the bad line and this
    const limited = await post('/class/send', answer(PINK, { id: 'one-too-many' }));
    expect(limited.status).toBe(429);
    expect(limited.headers.get('retry-after')).toMatch(/^\d+$/);
    expect((await limited.json()).error).toMatch(/too many sends from this laptop/);
    expect(store.state().answers).toHaveLength(2);
  });

  it('writes the CSV with a formula-like nickname as text, and pushes the state to a live board', async () => {
    await hello('=HYPERLINK("http://x")');
    await post('/class/send', answer(PINK));
    const csv = await (await fetch(`${base}/board/class.csv?key=${key}`)).text();
    expect(csv.split('\r\n')[0]).toMatch(/^time,student,name,kind/);
    expect(csv).toContain('"\'=HYPERLINK(""http://x"")"');
    expect(boardCSV(store.rows())).toBe(csv);

    const events = await fetch(`${base}/board/events?key=${key}`);
    const reader = events.body.getReader();
    const next = async () => new TextDecoder().decode((await reader.read()).value);
    expect(await next()).toMatch(/event: state\ndata: .*"answers":\[\{/);
    await post('/class/send', answer(WHITE));
    expect(await next()).toMatch(/"verdict":"wrong"/);
    await reader.cancel();
  });

  it('names every route it answers for the class gate, each with its reason, POST only where a page sends', () => {
    const gate = (method, path) => isStudentRoute(method, path, BOARD_ROUTES);
    for (const path of ['/board', '/board/state', '/board/events', '/board/class.csv', '/scripts/board/page/board.js', '/scripts/board/page/board.css', '/poll.html', '/site/poll.js']) {
      expect([path, gate('GET', path), gate('POST', path)]).toEqual([path, true, false]);
    }
    for (const path of ['/board/clear', '/class/send', '/class/hello']) expect([path, gate('POST', path), gate('GET', path)]).toEqual([path, true, false]);
    for (const path of ['/board/', '/class/', '/class/state', '/scripts/board/store.js', '/scripts/board/page/board.html']) expect([path, gate('GET', path)]).toEqual([path, false]);
    for (const route of BOARD_ROUTES) expect(route.why.length).toBeGreaterThan(10);
  });
});

describe('the board\'s folder', () => {
  it('is --data DIR, else the variable the class script sets, else one in the home folder; the key is kept', () => {
    expect(folderFrom(['node', 'class.js', '--data', 'here'], {})).toMatch(/here$/);
    expect(folderFrom(['node', 'class.js'], { SKETCHBOOK_BOARD_DATA: '/tmp/x' })).toBe('/tmp/x');
    expect(folderFrom(['node', 'class.js'], {})).toMatch(/raytracing-sketchbook-board$/);
    expect(() => folderFrom(['node', 'class.js', '--data'], {})).toThrow(/--data needs a folder/);
    const key = boardKey(folder);
    expect(key).toMatch(/^[\w-]{32}$/);
    expect(boardKey(folder)).toBe(key);
  });
});
