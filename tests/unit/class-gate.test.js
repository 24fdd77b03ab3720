// The class server's gate (scripts/class-gate.js): a student's laptop gets
// what the pages need and nothing of the teacher's. The dev server is started
// as `npm run class` starts it, and each of its own routes is asked for.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { request } from 'node:http';
import { mkdtempSync, mkdirSync, writeFileSync, readFileSync, statSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createServer } from 'vite';
import {
  isStudentRoute, requestPath, foldName, resolvesToGuarded, guardedFiles, isHostAllowed, isTrustworthyHost,
  computerNames, allowedHostsFrom, hostName, STUDENT_ROUTES,
} from '../../scripts/class-gate.js';
import { isTeacherOnly } from '../../scripts/classroom.js';
import { boardKey } from '../../scripts/board/setup.js';

/** One request to the server: its status, headers and body. */
function ask(port, path, { method = 'GET', host = `127.0.0.1:${port}`, json, headers: more = {} } = {}) {
  return new Promise((done, fail) => {
    const headers = { host, ...(json === undefined ? {} : { 'content-type': 'application/json' }), ...more };
    const req = request({ host: '127.0.0.1', port, path: path.replace(/[^\x21-\x7e]/gu, encodeURIComponent), method, headers }, (res) => {
      let body = '';
      res.on('data', (chunk) => { body += chunk; });
      res.on('end', () => done({ status: res.statusCode, headers: res.headers, body }));
    });
    req.on('error', fail);
    req.end(json === undefined ? undefined : JSON.stringify(json));
  });
}

describe('the class server, started as npm run class starts it', () => {
  let server;
  let port;
  let boardFolder;
  beforeAll(async () => {
    boardFolder = mkdtempSync(join(tmpdir(), 'class-gate-board-')); // the class board's: not the teacher's
    process.env.SKETCHBOOK_BOARD_DATA = boardFolder;
    process.env.SKETCHBOOK_CLASS_HOSTS = JSON.stringify(computerNames('teachers-laptop', ['class.test']));
    server = await createServer({ configFile: 'vite.config.js', mode: 'class', logLevel: 'silent', server: { host: '127.0.0.1', port: 0 }, optimizeDeps: { noDiscovery: true, include: [] } });
    await server.listen();
    port = server.httpServer.address().port;
  }, 60_000);
  afterAll(async () => {
    delete process.env.SKETCHBOOK_CLASS_HOSTS;
    delete process.env.SKETCHBOOK_BOARD_DATA;
    await server?.close();
    rmSync(boardFolder, { recursive: true, force: true });
  });

  it('puts the gate before every route of its own and of every plugin', () => {
    const stack = server.middlewares.stack;
    const gate = stack.findIndex((layer) => layer.handle.name === 'classGateMiddleware');
    expect(gate).toBeGreaterThanOrEqual(0);
    // Before it: only Vite's checks of a request's form (invalid requests, CORS, timing).
    const before = stack.slice(0, gate).map((layer) => layer.handle.name);
    for (const name of before) expect(name, `${name} runs before the gate`).toMatch(/^(viteRejectInvalidRequestMiddleware|viteTimeMiddleware)$/);
    expect(stack.map((layer) => layer.handle.name)).not.toContain('corsMiddleware'); // no CORS answers at all
    expect(stack.slice(0, gate).every((layer) => layer.route === '')).toBe(true);
  });

  it('answers 404 to each route the dev server has for the teacher', async () => {
    const routes = server.middlewares.stack.map((layer) => layer.route).filter(Boolean);
    expect(routes).toContain('/__open-in-editor');
    for (const route of routes) {
      const answer = await ask(port, `${route}?file=sketches/solutions/08-traffic-signal.js`);
      expect([route, answer.status, answer.headers['x-refused-by']]).toEqual([route, 404, 'class-gate']);
    }
  });

  it('opens no file in an editor, reads none outside the project, sends no source map', async () => {
    for (const path of ['/__open-in-editor?file=sketches/solutions/08-traffic-signal.js', '/__open-in-editor?file=../x.txt:12:3',
      '/__OPEN-IN-EDITOR?file=x', '/lib/../__open-in-editor?file=x', '/%5F_open-in-editor?file=x', '/@fs/etc/passwd', '/@fs/etc/hosts?raw',
      '/node_modules/.vite-class/deps/p5.js.map', '/lib/index.js.map', '/.git/config', '/.GIT/config', '/.ENV', '/.env',
      '/sketches/solutions/08-traffic-signal.js', '/sketches/ſolutions/08-traffic-signal.js', '/sketches/SOLUTIONS/08-traffic-signal.js',
      '/tests/e2e/homework-answers.js', '/package.json', '/vite.config.js', '/scripts/class.js', '/sketches/%2e%2e/.git/config',
      '/sketch-code/08-traffic-signal.js', '/sketch-code/solutions/08-traffic-signal.js', '/sketch-code/..%2Fsolutions%2F08-traffic-signal.js', '/editor/../vite.config.js']) {
      const answer = await ask(port, path);
      expect([path, answer.status]).toEqual([path, 404]);
    }
  });

  it('serves what the students\' pages need', async () => {
    for (const path of ['/', '/index.html', '/sketches/04-find-the-pink-pixel.html', '/sketches/04-find-the-pink-pixel.js', '/lib/index.js', '/site/gallery.js', '/@vite/client', '/api/',
      '/editor/code-in-page.js', '/editor/code-in-page.css', '/sketch-code/08-homework-traffic-signal.js']) {
      const answer = await ask(port, path);
      expect([path, answer.status]).toEqual([path, 200]);
    }
  });

  it('lets the class board\'s routes through, each with its own methods, and nothing else of scripts/', async () => {
    const passes = async (path, options) => (await ask(port, path, options)).headers['x-refused-by'] === undefined;
    // Through the gate to the board (which wants its key, or refuses a bad submission): the gate refuses none.
    for (const path of ['/board', '/board?key=nope', '/board/state', '/board/events', '/board/class.csv', '/poll.html', '/site/poll.js', '/scripts/board/page/board.js', '/scripts/board/page/board.css']) {
      expect([path, await passes(path)]).toEqual([path, true]);
    }
    for (const path of ['/board/clear', '/class/send', '/class/hello']) expect([path, await passes(path, { method: 'POST', json: {} })]).toEqual([path, true]);
    // What a student's page never asks: a read of the students' routes, a write to the board's, the rest of the board's code.
    for (const [method, path] of [['GET', '/class/send'], ['GET', '/class/'], ['GET', '/board/clear'], ['POST', '/board'], ['POST', '/board/state'], ['PUT', '/class/send'],
      ['GET', '/board/'], ['GET', '/scripts/board/store.js'], ['GET', '/scripts/board/page/../routes.js'], ['GET', '/scripts/board/page/board.html'], ['GET', '/scripts/class-gate.js']]) {
      const answer = await ask(port, path, { method, json: method === 'GET' ? undefined : {} });
      expect([method, path, answer.status, answer.headers['x-refused-by']]).toEqual([method, path, 404, 'class-gate']);
    }
    // A name the server was not told: refused before the board hears of it.
    const rebound = await ask(port, '/class/send', { method: 'POST', host: `rebound.example:${port}`, json: {} });
    expect([rebound.status, rebound.headers['x-refused-by']]).toEqual([403, 'class-gate']);
  });

  it('answers no other origin: no Access-Control-Allow-Origin, preflights and writes refused, nothing stored', async () => {
    const key = boardKey(boardFolder);
    const own = `http://127.0.0.1:${port}`;
    const foreign = [`http://127.0.0.1:${port + 1}`, 'null', `https://127.0.0.1:${port}`, `http://LOCALHOST:${port}`, `http://localhost.:${port}`,
      `http://localhost:${port}`, 'http://class.test', 'http://evil.example', `${own}.evil.example`];
    for (const origin of foreign) {
      for (const path of ['/', '/lib/index.js', `/board/state?key=${key}`, '/board/state']) {
        const read = await ask(port, path, { headers: { origin } });
        expect([origin, path, read.headers['access-control-allow-origin']]).toEqual([origin, path, undefined]);
      }
      for (const path of ['/class/send', '/class/hello', `/board/clear?key=${key}`, '/lib/index.js']) {
        const preflight = await ask(port, path, { method: 'OPTIONS', headers: { origin, 'access-control-request-method': 'POST', 'access-control-request-headers': 'content-type' } });
        expect([origin, path, preflight.status, preflight.headers['access-control-allow-origin']]).toEqual([origin, path, 403, undefined]);
      }
      for (const path of ['/class/hello', '/class/send', `/board/clear?key=${key}`]) {
        const write = await ask(port, path, { method: 'POST', json: { laptop: 'laptop-from-elsewhere', nickname: 'Mallory' }, headers: { origin } });
        expect([origin, path, write.status, write.headers['x-refused-by']]).toEqual([origin, path, 403, 'class-gate']);
      }
    }
    const crossSite = await ask(port, '/class/hello', { method: 'POST', json: { laptop: 'laptop-from-elsewhere' }, headers: { 'sec-fetch-site': 'cross-site' } });
    expect(crossSite.status).toBe(403);
    const before = JSON.parse((await ask(port, `/board/state?key=${key}`)).body);
    expect(before.refusedCount).toBe(0);
    // The class's own page, by the name it was opened with: let through.
    const hello = await ask(port, '/class/hello', { method: 'POST', json: { laptop: 'laptop-own-page' }, headers: { origin: own, 'sec-fetch-site': 'same-origin' } });
    expect(hello.status).toBe(200);
    const named = await ask(port, '/class/hello', { method: 'POST', host: `class.test:${port}`, json: { laptop: 'laptop-own-page-2' }, headers: { origin: `http://class.test:${port}` } });
    expect(named.status).toBe(200);
    expect(JSON.parse(named.body).laptop).toBe('laptop-own-page-2');
  });

  it('gives the editor each sketch\'s own file as its starter, never a solution', async () => {
    const starter = await ask(port, '/sketch-code/08-homework-traffic-signal.js');
    expect(starter.body).toContain('TODO');
    expect(starter.body).toBe(readFileSync('sketches/08-homework-traffic-signal.js', 'utf8'));
  });

  it('answers to the computer\'s names, and says how to add another', async () => {
    expect((await ask(port, '/', { host: `teachers-laptop.local:${port}` })).status).toBe(200);
    expect((await ask(port, '/', { host: `class.test:${port}` })).status).toBe(200);
    expect((await ask(port, '/', { host: `192.168.1.20:${port}` })).status).toBe(200);
    const other = await ask(port, '/', { host: `rebound.example:${port}` });
    expect(other.status).toBe(403);
    expect(other.body).toContain('npm run class -- --allow-host rebound.example');
  });

  it('sends the isolation headers to loopback only, where a browser can use them', async () => {
    expect((await ask(port, '/')).headers['cross-origin-opener-policy']).toBe('same-origin');
    const named = await ask(port, '/', { host: `class.test:${port}` });
    expect(named.headers['cross-origin-opener-policy']).toBeUndefined();
    expect(named.headers['cross-origin-embedder-policy']).toBeUndefined();
  });
});

describe('the list of what students may ask for', () => {
  it('reads a path as the server does', () => {
    expect(requestPath('/lib/%2E%2E/.git/config?x=1')).toBe('/.git/config');
    expect(requestPath('//sketches\\solutions\\x.js')).toBe('/sketches/solutions/x.js');
    expect(requestPath('/%E0%A4%A')).toBeNull();
  });

  it('refuses every hidden file, source map and method that is not a read', () => {
    expect(isStudentRoute('GET', '/lib/index.js')).toBe(true);
    expect(isStudentRoute('POST', '/lib/index.js')).toBe(false);
    expect(isStudentRoute('GET', '/lib/index.js.map')).toBe(false);
    expect(isStudentRoute('GET', '/node_modules/.vite-class/deps/p5.js?v=1')).toBe(true);
    expect(isStudentRoute('GET', '/node_modules/.cache/x.js')).toBe(false);
    expect(isStudentRoute('GET', '/eslint.config.js')).toBe(false);
    expect(isStudentRoute('POST', '/board/answers', [{ path: /^\/board\/answers$/, methods: ['POST'], why: 'a test' }])).toBe(true);
  });

  it('gives a reason for every route', () => {
    for (const route of STUDENT_ROUTES) expect(route.why.length).toBeGreaterThan(10);
  });
});

describe('a case-insensitive disk (a teacher\'s Mac or Windows laptop)', () => {
  let root;
  // The disk of such a laptop, in Node: a path is looked up by its folded spelling.
  const foldingStat = (file) => statSync(join(root, foldName(file.slice(root.length))));
  beforeAll(() => {
    root = mkdtempSync(join(tmpdir(), 'class-gate-'));
    mkdirSync(join(root, 'sketches/solutions'), { recursive: true });
    mkdirSync(join(root, '.git'));
    writeFileSync(join(root, 'sketches/solutions/08-traffic-signal.js'), 'export const addLights = () => {};');
    writeFileSync(join(root, 'sketches/08-homework-traffic-signal.js'), '');
    writeFileSync(join(root, '.git/config'), '[core]');
    writeFileSync(join(root, '.env'), 'KEY=1');
  });
  afterAll(() => rmSync(root, { recursive: true, force: true }));

  it('folds the spellings such a disk takes as one', () => {
    expect(foldName('ſolutions')).toBe('solutions');
    expect(foldName('ﬁle')).toBe('file');
    expect(foldName('SKETCHES')).toBe('sketches');
    expect(foldName('\u212Aey')).toBe('key'); // the Kelvin sign
    expect(isTeacherOnly('/sketches/ſolutions/08-traffic-signal.js', '/home/t/kit')).toBe(true);
    expect(isTeacherOnly('/ſketches/SOLUTIONS/x.js', '/home/t/kit')).toBe(true);
  });

  it('decides by the file a path resolves to, not by its spelling', () => {
    const guarded = guardedFiles(root, ['sketches/solutions', '.git', '.env'], foldingStat);
    expect(guarded).toHaveLength(3);
    for (const path of ['/SKETCHES/Solutions/08-traffic-signal.js', '/sketches/ſolutions/08-traffic-signal.js', '/.GIT/config', '/.ENV', '/.Env']) {
      expect(resolvesToGuarded(requestPath(path), root, guarded, foldingStat), path).toBe(true);
    }
    for (const path of ['/sketches/08-homework-traffic-signal.js', '/SKETCHES/08-homework-traffic-signal.js', '/nothing/here.js']) {
      expect(resolvesToGuarded(requestPath(path), root, guarded, foldingStat), path).toBe(false);
    }
  });
});

describe('the computer\'s names', () => {
  it('are its host name, the same with .local, and the teacher\'s', () => {
    expect(computerNames('Teachers-Laptop.school.org', ['class.test'])).toEqual(['teachers-laptop.school.org', 'teachers-laptop', 'teachers-laptop.local', 'class.test']);
  });

  it('--allow-host takes names, several or one at a time, and refuses what is not one', () => {
    expect(allowedHostsFrom(['--port', '8080', '--allow-host', 'Room12.local', '--allow-host=a.school,b'])).toEqual(['room12.local', 'a.school', 'b']);
    expect(() => allowedHostsFrom(['--allow-host'])).toThrow(/--allow-host must be a computer's name/);
    expect(() => allowedHostsFrom(['--allow-host', 'http://x:80'])).toThrow(/--allow-host .*"http:\/\/x:80"/);
  });

  it('let in addresses and loopback; a secure context is loopback alone', () => {
    expect(hostName('Class.Test:5173')).toBe('class.test');
    expect(hostName('[::1]:5173')).toBe('[::1]');
    expect(isHostAllowed('10.0.0.7:5173', [])).toBe(true);
    expect(isHostAllowed('[fe80::1]:5173', [])).toBe(true);
    expect(isHostAllowed('localhost:5173', [])).toBe(true);
    expect(isHostAllowed('attacker.example', [])).toBe(false);
    expect(isHostAllowed(undefined, [])).toBe(false);
    expect(isTrustworthyHost('127.0.0.1:5173')).toBe(true);
    expect(isTrustworthyHost('10.0.0.7:5173')).toBe(false);
    expect(isTrustworthyHost('class.test:5173')).toBe(false);
  });
});
