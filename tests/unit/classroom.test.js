// Serving a class (scripts/classroom.js) and the API reference kept in memory
// (scripts/site-plugins.js): what a request gets, tested without a server.
import { describe, it, expect } from 'vitest';
import { EventEmitter } from 'node:events';
import { gunzipSync, brotliDecompressSync } from 'node:zlib';
import { isTeacherOnly, encodingFor, withoutInlineSourceMap, compressAndRevalidate, teachersAnswers, ELSEWHERE } from '../../scripts/classroom.js';
import { apiReference } from '../../scripts/site-plugins.js';

const ROOT = '/home/teacher/sketchbook';

describe('the teacher\'s files', () => {
  it('are named however a URL spells them', () => {
    for (const url of ['/sketches/solutions/08-traffic-signal.js', '/sketches/solutions/08-traffic-signal.js?raw',
      '/tests/unit/homework.test.js', '/tests', '/Sketches/Solutions/08-traffic-signal.js', '/sketches/%73olutions/x.js',
      '/sketches/./solutions/x.js', '/lib/../sketches/solutions/x.js', '//sketches/solutions/x.js',
      `/@fs${ROOT}/sketches/solutions/x.js`, `/@id/${ROOT}/tests/e2e/helpers.js`, '/sketches\\solutions\\x.js', '/sketches/solutions/%E0%A4%A.js',
      '/tests/e2e/__screenshots__/sketches-08-10.spec.js/08-homework-traffic-signal-solution.png',
      '/tests/e2e/__screenshots__/gallery.spec.js/../sketches-08-10.spec.js/x.png', '/tests/e2e/__screenshots__/gallery.spec.js/a/b.png',
      '/tests/e2e/__screenshots__/gallery.spec.js/x.js']) {
      expect(isTeacherOnly(url, ROOT), url).toBe(true);
    }
  });

  it('leave every other file alone', () => {
    for (const url of ['/', '/sketches/08-homework-traffic-signal.js', '/sketches/solutions-notes.html', '/testsuite.html',
      '/lib/lesson/homework.js', '/api/', '/sketches/08-homework-traffic-signal.html?solution=1', '/%E0%A4%A',
      '/tests/e2e/__screenshots__/gallery.spec.js/05-value-boxes-view0.png?import']) { // the gallery's thumbnails
      expect(isTeacherOnly(url, ROOT), url).toBe(false);
    }
  });

  it('an import of a solution gets no answer and the line saying where it is, unless solutions are served', async () => {
    const away = teachersAnswers({ served: false });
    const id = away.resolveId('./solutions/08-traffic-signal.js', `${ROOT}/sketches/08-homework-traffic-signal.js`);
    expect(id).not.toBeNull();
    const code = away.load(id);
    expect(code).toContain('export const addLights = null;');
    expect(code).toContain(JSON.stringify(ELSEWHERE));
    expect(away.load(`${ROOT}/sketches/solutions/09-rear-lights.js?import`)).toContain('addLights = null');
    expect(away.resolveId('./08-homework-traffic-signal.js', `${ROOT}/index.html`)).toBeNull();
    const served = teachersAnswers({ served: true });
    expect(served.resolveId('./solutions/08-traffic-signal.js', `${ROOT}/sketches/08-homework-traffic-signal.js`)).toBeNull();
    expect(served.load(`${ROOT}/sketches/solutions/08-traffic-signal.js`)).toBeNull();
  });
});

describe('what a student\'s browser gets', () => {
  it('brotli first, then gzip, never an encoding refused with q=0', () => {
    expect(encodingFor('gzip, deflate, br, zstd')).toBe('br');
    expect(encodingFor('gzip;q=1.0, br;q=0')).toBe('gzip');
    expect(encodingFor('deflate')).toBeNull();
    expect(encodingFor(undefined)).toBeNull();
  });

  it('a script without the source map at its end; a script that only mentions one, whole', () => {
    const code = 'export const a = 1;\n';
    const mapped = Buffer.from(`${code}//# sourceMappingURL=data:application/json;base64,eyJ2ZXJzaW9uIjozfQ==`);
    expect(withoutInlineSourceMap(mapped).toString()).toBe(code);
    const mentions = Buffer.from('const s = "\\n//# sourceMappingURL=data:application/json;";\nrun(s);\n');
    expect(withoutInlineSourceMap(mentions)).toBe(mentions);
  });

  /** Runs the middleware on one request; `answer(res)` plays the server behind it. */
  function request(middleware, headers, answer) {
    return new Promise((done) => {
      const res = new EventEmitter();
      const sent = { headers: {}, body: null, status: 200 };
      Object.assign(res, {
        statusCode: 200,
        setHeader: (name, value) => { sent.headers[name.toLowerCase()] = value; },
        getHeader: (name) => sent.headers[name.toLowerCase()],
        getHeaders: () => ({ ...sent.headers }),
        removeHeader: (name) => { delete sent.headers[name.toLowerCase()]; },
        writeHead() { throw new Error('replaced by the middleware'); },
        write() { throw new Error('replaced by the middleware'); },
        end(body) { sent.status = res.statusCode; sent.body = body ?? null; done(sent); },
      });
      middleware({ headers, method: 'GET', url: '/x.js' }, res, () => answer(res));
    });
  }

  it('compresses a text answer, gives it an ETag, and answers 304 to the same ETag', async () => {
    const middleware = compressAndRevalidate();
    const script = `${'export const long = "a text long enough to be worth compressing";\n'.repeat(60)}//# sourceMappingURL=data:application/json;base64,AAAA`;
    const serve = (res) => { res.writeHead(200, { 'Content-Type': 'text/javascript' }); res.write(script.slice(0, 100)); res.end(script.slice(100)); };
    const first = await request(middleware, { 'accept-encoding': 'gzip, br' }, serve);
    expect(first.status).toBe(200);
    expect(first.headers['content-encoding']).toBe('br');
    expect(brotliDecompressSync(first.body).toString()).toBe(script.slice(0, script.indexOf('//#')));
    expect(first.body.length).toBeLessThan(script.length / 10);
    expect(first.headers.etag).toMatch(/^W\/"/);
    const gzipped = await request(middleware, { 'accept-encoding': 'gzip' }, serve);
    expect(gunzipSync(gzipped.body).toString()).toBe(script.slice(0, script.indexOf('//#')));
    const again = await request(middleware, { 'accept-encoding': 'br', 'if-none-match': first.headers.etag }, serve);
    expect(again.status).toBe(304);
    expect(again.body).toBeNull();
  });

  it('keeps an immutable answer and gives it again without asking the server behind', async () => {
    const middleware = compressAndRevalidate();
    const script = 'export default "p5, pre-bundled";\n'.repeat(100);
    let asked = 0;
    const serve = (res) => { asked += 1; res.setHeader('Content-Type', 'text/javascript'); res.setHeader('Cache-Control', 'max-age=31536000,immutable'); res.end(script); };
    const first = await request(middleware, { 'accept-encoding': 'gzip' }, serve);
    const second = await request(middleware, { 'accept-encoding': 'gzip' }, serve);
    expect(asked).toBe(1);
    expect(gunzipSync(second.body).toString()).toBe(script);
    expect([second.status, second.headers.etag, second.headers['cache-control']]).toEqual([200, first.headers.etag, 'max-age=31536000,immutable']);
    const revalidated = await request(middleware, { 'if-none-match': first.headers.etag }, serve);
    expect([revalidated.status, asked]).toEqual([304, 1]);
  });

  it('lets a live stream (Server-Sent Events) go as it is written, never held until it ends', () => {
    const middleware = compressAndRevalidate();
    const written = [];
    const res = new EventEmitter();
    const headers = {};
    Object.assign(res, {
      statusCode: 200,
      setHeader: (name, value) => { headers[name.toLowerCase()] = value; },
      getHeader: (name) => headers[name.toLowerCase()],
      writeHead(status) { written.push(`head ${status}`); return res; },
      write(chunk) { written.push(String(chunk)); return true; },
      end() { written.push('end'); },
    });
    middleware({ headers: { 'accept-encoding': 'br' }, method: 'GET', url: '/board/events?key=k' }, res, () => {
      res.writeHead(200, { 'Content-Type': 'text/event-stream; charset=utf-8' });
      res.write('event: state\ndata: {}\n\n');
    });
    expect(written).toEqual(['head 200', 'event: state\ndata: {}\n\n']); // not ended, and already out
    expect(headers['content-encoding']).toBeUndefined();
  });

  it('passes an error and a small answer through as they are', async () => {
    const middleware = compressAndRevalidate();
    const missing = await request(middleware, { 'accept-encoding': 'br' }, (res) => { res.statusCode = 404; res.end('Not found'); });
    expect([missing.status, String(missing.body), missing.headers['content-encoding']]).toEqual([404, 'Not found', undefined]);
    const small = await request(middleware, { 'accept-encoding': 'br' }, (res) => { res.setHeader('Content-Type', 'text/html'); res.end('<p>hi</p>'); });
    expect([small.status, String(small.body), small.headers['content-encoding']]).toEqual([200, '<p>hi</p>', undefined]);
  });
});

describe('the API reference on a server', () => {
  function serverWith(plugin) {
    const watcher = new EventEmitter();
    let middleware;
    plugin.configureServer({ config: { root: ROOT }, watcher, middlewares: { use: (fn) => { middleware = fn; } } });
    const get = (headers = {}) => new Promise((done) => {
      const sent = { headers: {} };
      const res = { statusCode: 200, setHeader: (n, v) => { sent.headers[n.toLowerCase()] = v; }, end: (body) => done({ ...sent, status: res.statusCode, body }) };
      middleware({ url: '/api/', headers }, res, () => done(null));
    });
    return { watcher, get };
  }

  it('is made once, answered from memory, and made again after a change to lib/', async () => {
    let made = 0;
    const { watcher, get } = serverWith(apiReference(() => `<!doctype html><p>reference ${++made}</p>`));
    const answers = await Promise.all(Array.from({ length: 100 }, () => get()));
    expect(made).toBe(1);
    expect(new Set(answers.map((a) => a.body))).toEqual(new Set(['<!doctype html><p>reference 1</p>']));
    const revisit = await get({ 'if-none-match': answers[0].headers.etag });
    expect(revisit.status).toBe(304);
    watcher.emit('change', `${ROOT}/sketches/05-value-boxes.js`);
    expect((await get()).body).toContain('reference 1');
    watcher.emit('change', `${ROOT}/lib/shapes/sphere.js`);
    const after = await get({ 'if-none-match': answers[0].headers.etag });
    expect([after.status, after.body, made]).toEqual([200, '<!doctype html><p>reference 2</p>', 2]);
  });
});
