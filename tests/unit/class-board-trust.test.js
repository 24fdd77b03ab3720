// What the class board trusts, through real HTTP on loopback (scripts/board/routes.js
// as the class server mounts it): only its own origin writes, each laptop proves
// its secret, names a teacher can trust, 413 for a long body (never a reset
// connection), students counted by what they sent, and what was refused kept
// for the board with the reason.
import { describe, it, expect, beforeEach, afterEach } from 'vitest';
import { createServer, request } from 'node:http';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { checkNickname, nameKey, BadSubmission } from '../../scripts/board/checks.js';
import { openStore } from '../../scripts/board/store.js';
import { RateLimit } from '../../scripts/board/limits.js';
import { boardRoutes } from '../../scripts/board/routes.js';
import { boardKey, loadDatabase } from '../../scripts/board/setup.js';
import { isOwnOrigin } from '../../scripts/class-gate.js';

const loaded = await loadDatabase();
const Database = loaded.Database ?? class { constructor() { throw new Error(loaded.problem); } };

const SCREEN = { width: 32, height: 24, fov: 30 };
const answer = (laptop, id, more = {}) => ({ laptop, id, kind: 'answer', line: 'Pixel: 1,1; H: 0; V: 0', ...SCREEN, ...more });

/** One request: status, headers, body (text); rejects on a reset connection. */
function ask(port, path, { method = 'POST', headers = {}, body } = {}) {
  return new Promise((done, fail) => {
    const req = request({ host: '127.0.0.1', port, path, method, headers: { host: `127.0.0.1:${port}`, ...headers } }, (res) => {
      let text = '';
      res.on('data', (chunk) => { text += chunk; });
      res.on('end', () => done({ status: res.statusCode, headers: res.headers, body: text, json: () => JSON.parse(text) }));
    });
    req.on('error', fail);
    req.end(body);
  });
}

let folder, store, server, port, key;
beforeEach(async () => {
  folder = mkdtempSync(join(tmpdir(), 'board-trust-'));
  store = openStore(folder, { Database });
  key = boardKey(folder);
  const routes = boardRoutes({ store, key, limits: { laptop: new RateLimit({ burst: 100, perSecond: 100 }), address: new RateLimit({ burst: 1000, perSecond: 1000 }) } });
  server = createServer((req, res) => routes(req, res, () => { res.statusCode = 204; res.end(); }));
  await new Promise((done) => server.listen(0, '127.0.0.1', done));
  port = server.address().port;
  server.on('close', () => routes.close());
});
afterEach(async () => {
  server.closeAllConnections();
  await new Promise((done) => server.close(done));
  store.close();
  rmSync(folder, { recursive: true, force: true });
});

/** A JSON POST as a page sends it, with its laptop's secret (when it has one) and any other headers. */
const post = (path, value, { secret, laptop, headers = {} } = {}) => ask(port, path, {
  headers: { 'content-type': 'application/json', ...(secret ? { 'x-rt-laptop-secret': secret } : {}), ...(laptop ? { 'x-rt-laptop': laptop } : {}), ...headers },
  body: typeof value === 'string' ? value : JSON.stringify(value),
});
/** A laptop that said hello: its id, secret and name. */
async function laptop(id, nickname) {
  const hello = await post('/class/hello', { laptop: id, nickname });
  expect(hello.status, hello.body).toBe(200);
  return hello.json();
}
const state = () => store.state();

describe('only the class\'s own pages write', () => {
  it('reads a request\'s origin as the browser sent it: the very host and port, over http', () => {
    const host = 'class.test:5173';
    expect(isOwnOrigin({ host, origin: 'http://class.test:5173' })).toBe(true);
    expect(isOwnOrigin({ host })).toBe(true); // no Origin, no Sec-Fetch-Site: not a browser's page
    expect(isOwnOrigin({ host, 'sec-fetch-site': 'same-origin' })).toBe(true);
    expect(isOwnOrigin({ host, 'sec-fetch-site': 'none' })).toBe(true);
    for (const origin of ['http://class.test:5174', 'http://class.test', 'null', 'https://class.test:5173', 'http://CLASS.TEST:5173', 'http://class.test.:5173',
      'http://evil.example', 'http://class.test:5173.evil.example', 'http://class.test:5173/', '']) {
      expect([origin, isOwnOrigin({ host, origin })]).toEqual([origin, false]);
    }
    for (const site of ['cross-site', 'same-site']) expect([site, isOwnOrigin({ host, 'sec-fetch-site': site })]).toEqual([site, false]);
  });

  it('answers 403 to a write from another origin and stores nothing; sends no Access-Control-Allow-Origin', async () => {
    const me = await laptop('laptop-origin-1');
    for (const origin of [`http://127.0.0.1:${port + 1}`, 'null', `https://127.0.0.1:${port}`, `http://LOCALHOST:${port}`, `http://127.0.0.1.:${port}`, 'http://evil.example']) {
      const sent = await post('/class/send', answer(me.laptop, 'x1'), { secret: me.secret, headers: { origin } });
      expect([origin, sent.status]).toEqual([origin, 403]);
      expect(sent.headers['access-control-allow-origin']).toBeUndefined();
      expect((await post('/class/hello', { laptop: 'laptop-origin-2', nickname: 'Mallory' }, { headers: { origin } })).status).toBe(403);
      expect((await post(`/board/clear?key=${key}`, {}, { headers: { origin } })).status).toBe(403);
    }
    const crossSite = await post('/class/send', answer(me.laptop, 'x2'), { secret: me.secret, headers: { 'sec-fetch-site': 'cross-site' } });
    expect(crossSite.status).toBe(403);
    expect(state().answers).toEqual([]);
    expect(state().students).toEqual([]);
    const board = await ask(port, `/board/state?key=${key}`, { method: 'GET', headers: { origin: 'http://evil.example' } });
    expect(board.headers['access-control-allow-origin']).toBeUndefined();
    // Its own page: stored.
    const own = await post('/class/send', answer(me.laptop, 'x3'), { secret: me.secret, headers: { origin: `http://127.0.0.1:${port}`, 'sec-fetch-site': 'same-origin' } });
    expect(own.status).toBe(200);
    expect(state().answers).toHaveLength(1);
  });
});

describe('each laptop proves its secret', () => {
  it('gives a new laptop a secret of 256 bits, and never the secret of a laptop that exists', async () => {
    const anna = await laptop('laptop-anna-0001', 'Anna');
    expect(anna).toMatchObject({ laptop: 'laptop-anna-0001', number: 1, name: 'Anna' });
    expect(anna.secret).toMatch(/^[\w-]{43}$/);
    // The same id again, with no secret, a wrong one, another laptop's: not Anna, not renamed.
    const bob = await laptop('laptop-bob-00001');
    for (const secret of [undefined, '', 'x', `${anna.secret}x`, anna.secret.slice(1), bob.secret]) {
      const hello = await post('/class/hello', { laptop: anna.laptop, nickname: 'Mallory' }, { secret });
      const body = hello.json();
      expect(body.laptop).not.toBe(anna.laptop);
      expect(body.secret).not.toBe(anna.secret);
      expect(body.name).not.toBe('Anna');
    }
    // Anna with her secret: herself, no secret given again.
    const again = await post('/class/hello', { laptop: anna.laptop }, { secret: anna.secret });
    expect(again.json()).toEqual({ laptop: anna.laptop, number: 1, name: 'Anna' });
    await post('/class/send', answer(anna.laptop, 'a1'), { secret: anna.secret });
    expect(state().students).toEqual([{ number: 1, name: 'Anna' }]);
  });

  it('refuses a send (403, stores nothing) without the laptop\'s own secret', async () => {
    const anna = await laptop('laptop-anna-0002');
    const bob = await laptop('laptop-bob-00002');
    for (const [who, secret] of [['none', undefined], ['empty', ''], ['another laptop\'s', bob.secret], ['a guess', 'A'.repeat(43)], ['too long', anna.secret.repeat(10)]]) {
      const sent = await post('/class/send', answer(anna.laptop, `s-${who.length}`), { secret });
      expect([who, sent.status, sent.json().hello]).toEqual([who, 403, true]);
    }
    expect((await post('/class/send', answer('laptop-never-said-hello', 'n1'), { secret: anna.secret })).status).toBe(403);
    expect(state().answers).toEqual([]);
    expect((await post('/class/send', answer(anna.laptop, 'ok'), { secret: anna.secret })).status).toBe(200);
  });

  it('keeps a laptop\'s secret hashed in the database, not as it was given', async () => {
    const anna = await laptop('laptop-anna-0003');
    store.close();
    const db = new Database(join(folder, 'board.sqlite'), { readonly: true });
    const kept = db.prepare('SELECT secret FROM laptops WHERE laptop = ?').get(anna.laptop).secret;
    db.close();
    store = openStore(folder, { Database });
    expect(Buffer.isBuffer(kept)).toBe(true);
    expect(kept.toString('utf8')).not.toContain(anna.secret);
    expect(kept.toString('base64url')).not.toBe(anna.secret);
  });
});

describe('names a teacher can trust', () => {
  it('keeps a name NFC and trimmed', () => {
    expect(checkNickname('  Zoe\u0301 ')).toBe('Zoé');
    expect(checkNickname('\u3000Ana\u00A0')).toBe('Ana');
    expect(checkNickname('👩‍🔬 Ada')).toBe('👩‍🔬 Ada'); // an emoji's joiner is part of it
    expect(checkNickname('')).toBeUndefined();
  });

  it('refuses names that show nothing, or hold control, format or direction characters, or half a character', () => {
    const refused = (name, message) => expect(() => checkNickname(name), JSON.stringify(name)).toThrow(message);
    for (const blank of ['\u200B', '\u3164', '\u115F', '\u1160', '\uFFA0', '\u2800', '\u2800\u2800', '\u3164\u3164 \u200B', '\u034F', '\uFE0F', '\u0301', '\u200D', '\u200C\u200D']) {
      refused(blank, /^name is blank once its invisible characters are removed/);
    }
    for (const hidden of ['a\u202Eb', 'a\u202Ab', 'a\u2066b', 'a\u2069', 'a\u200Eb', 'a\u200Fb', 'a\u061Cb', '\u200Bab', 'a\u00ADb', 'a\u2060b', 'a\uFEFFb', 'a\u0000b', 'a\u0007', 'a\nb', 'a\u0085b', 'a\u2028b', 'a\u{E0041}b']) {
      refused(hidden, /^name must not hold control, format or direction characters/);
    }
    for (const half of ['a\uD800', '\uDC00b', 'a\uDBFF\uDBFFb']) refused(half, /^name must not hold lone surrogates/);
    refused(42, /^name must be text/);
    refused('n'.repeat(41), /^name is too long/);
  });

  it('refuses a name that reads like the board\'s label of a student without a name', () => {
    for (const label of ['student 3', 'Student 3', 'STUDENT 3', 'student３', 'student  3', 'student3', ' student 12 ', 'ｓｔｕｄｅｎｔ 3', 'student\u00A03', 'student\u30003',
      'student 3.', 'student-3', 'ѕtudent 3', 'studеnt 3', 'student ٣', 'Student 03']) {
      expect(() => checkNickname(label), label).toThrow(/^name reads like the board's label of a student without a name/);
    }
    for (const fine of ['student', 'students 3', 'Student Ana', 'student 3b', '3 students']) expect(checkNickname(fine), fine).toBe(fine);
  });

  it('reads names that look the same as one', () => {
    const same = [['ＡＮＮＡ', 'anna'], ['Anna', 'ANNA'], ['an na', 'anna'], ['Ａnna', 'anna'], ['аnnа', 'anna'], ['Zoé', 'Zoe\u0301'], ['ﬁona', 'fiona']];
    for (const [a, b] of same) expect([a, nameKey(a)]).toEqual([a, nameKey(b)]);
    expect(nameKey('Anna')).not.toBe(nameKey('Anne'));
  });

  it('refuses (400, naming the field) a name another laptop has, however it is spelt; the old name stays', async () => {
    const anna = await laptop('laptop-anna-0004', 'Anna');
    const bob = await laptop('laptop-bob-00004', 'Bob');
    for (const name of ['Anna', 'anna', 'ANNA', 'ＡＮＮＡ', 'An na', 'аnna', 'Anna\u200D']) {
      const hello = await post('/class/hello', { laptop: bob.laptop, nickname: name }, { secret: bob.secret });
      expect([name, hello.status]).toEqual([name, 400]);
      expect(hello.json()).toMatchObject({ field: 'name', name: 'Bob', laptop: bob.laptop });
      expect(hello.json().error).toMatch(/^name ".*" is taken/);
    }
    for (const name of ['student 1', '\u3164', 'a\u202Eb']) {
      const hello = await post('/class/hello', { laptop: bob.laptop, nickname: name }, { secret: bob.secret });
      expect([name, hello.status, hello.json().field, hello.json().name]).toEqual([name, 400, 'name', 'Bob']);
    }
    // A name taken through a send is refused too, and the answer with it.
    const viaSend = await post('/class/send', answer(bob.laptop, 'b1', { nickname: 'anna' }), { secret: bob.secret });
    expect([viaSend.status, viaSend.json().field]).toEqual([400, 'name']);
    // Anna may keep hers; Bob may take a free one.
    expect((await post('/class/hello', { laptop: anna.laptop, nickname: 'Anna' }, { secret: anna.secret })).json().name).toBe('Anna');
    expect((await post('/class/hello', { laptop: bob.laptop, nickname: 'Bobby' }, { secret: bob.secret })).json().name).toBe('Bobby');
    // A new laptop asking for a taken name still gets its id and secret, without the name.
    const carol = await post('/class/hello', { laptop: 'laptop-carol-004', nickname: 'ANNA' });
    expect(carol.status).toBe(400);
    expect(carol.json()).toMatchObject({ laptop: 'laptop-carol-004', name: 'student 3', field: 'name' });
    expect(carol.json().secret).toMatch(/^[\w-]{43}$/);
  });
});

describe('a body over the limit', () => {
  for (const [size, label] of [[1024 * 1024, '1 MB'], [10 * 1024 * 1024, '10 MB']]) {
    it(`gets 413 with a JSON message, not a reset connection (${label})`, async () => {
      const me = await laptop(`laptop-big-${size}`);
      const body = JSON.stringify(answer(me.laptop, 'big', { nickname: 'x'.repeat(size) }));
      const sent = await post('/class/send', body, { secret: me.secret, laptop: me.laptop });
      expect(sent.status).toBe(413);
      expect(sent.json().error).toMatch(/too long: at most 4096 bytes/);
      expect(state().refused).toMatchObject([{ what: 'send', reason: expect.stringMatching(/too long/), student: 1 }]);
      // The server still answers.
      expect((await post('/class/send', answer(me.laptop, 'small'), { secret: me.secret })).status).toBe(200);
    }, 30_000);
  }
});

describe('the board\'s count and what was refused', () => {
  it('counts as students the laptops that sent something kept, never a visit', async () => {
    const visitor = await laptop('laptop-visit-001');
    const worker = await laptop('laptop-work-0001', 'Wen');
    expect(state().students).toEqual([]);
    await post('/class/send', { laptop: worker.laptop, id: 't1', kind: 'task', page: '01', task: 'select' }, { secret: worker.secret });
    expect(state().students).toEqual([{ number: worker.number, name: 'Wen' }]);
    await post('/class/send', answer(visitor.laptop, 'bad', { line: 'pink!' }), { secret: visitor.secret }); // refused: still not a student
    expect(state().students).toHaveLength(1);
  });

  it('keeps each refusal from a known laptop with its reason, newest first, as text', async () => {
    const me = await laptop('laptop-refused-1', 'Rae');
    const bad = await post('/class/send', answer(me.laptop, 'r1', { line: '<img src=x onerror=alert(1)>' }), { secret: me.secret });
    expect(bad.status).toBe(400);
    await post('/class/send', { laptop: me.laptop, id: 'r2', kind: 'poll', value: 9 }, { secret: me.secret });
    await post('/class/hello', { laptop: me.laptop, nickname: 'student 2' }, { secret: me.secret });
    // Nothing is kept of a laptop that does not prove itself (anyone could fill the board).
    await post('/class/send', answer(me.laptop, 'r3', { line: 'x' }));
    const { refused, refusedCount } = state();
    expect(refusedCount).toBe(3);
    expect(refused.map((r) => [r.name, r.what, r.reason])).toEqual([
      ['Rae', 'name', expect.stringMatching(/^name reads like the board's label/)],
      ['Rae', 'poll', expect.stringMatching(/^value must be a whole number from 1 to 3/)],
      ['Rae', 'answer', expect.stringMatching(/^line must read like/)],
    ]);
    expect(JSON.stringify(refused)).not.toContain('<img');
    const shown = await ask(port, `/board/state?key=${key}`, { method: 'GET' });
    expect(shown.json().refused).toHaveLength(3);
  });

  it('refuses a name through its own message class, as every bad field', () => {
    expect(() => checkNickname('\u200B')).toThrow(BadSubmission);
  });
});

describe('a board made before laptops had secrets', () => {
  it('gives an old laptop\'s id to nobody, and keeps its name from being taken in another spelling', () => {
    store.close();
    const db = new Database(join(folder, 'board.sqlite'));
    db.exec('DROP TABLE laptops');
    db.exec(`CREATE TABLE laptops (class INTEGER NOT NULL, laptop TEXT NOT NULL, number INTEGER NOT NULL, nickname TEXT, seen TEXT NOT NULL, PRIMARY KEY (class, laptop))`);
    db.prepare('INSERT INTO laptops VALUES (1, ?, 1, ?, ?)').run('old-laptop-0001', 'Anna', new Date().toISOString());
    db.close();
    store = openStore(folder, { Database });
    expect(store.proves('old-laptop-0001', '')).toBe(false);
    const hello = store.hello('old-laptop-0001', undefined);
    expect(hello.laptop).not.toBe('old-laptop-0001');
    expect(() => store.rename(hello.laptop, 'ANNA')).toThrow(/^name "ANNA" is taken/);
  });
});
