/**
 * Vite plugins for serving the sketchbook to a class (vite.config.js):
 *
 * - teachersAnswers: the homework's reference solutions
 *   (sketches/solutions/*.js) stay on the teacher's computer. Where they are
 *   not served (`npm run class`, `npm run build`), an import of one gets a
 *   module without the answer (`addLights = null`) and with the line the page
 *   shows instead (`elsewhere`): the solution is neither in the built files
 *   nor in what the class server sends.
 * - classroom (`npm run class` only): one laptop serving 30 students over
 *   the classroom's Wi-Fi. p5 pre-bundled minified, no source maps sent,
 *   every text response compressed (brotli or gzip, made once per content and
 *   kept), an ETag on every answer so a repeat visit is a 304, and the
 *   teacher's files (solutions, tests) answered 404. Vite's own live reload
 *   and sketch swaps are untouched: a save still reaches the students' pages.
 */
import { createHash } from 'node:crypto';
import { posix, resolve, sep } from 'node:path';
import { promisify } from 'node:util';
import { brotliCompress, gzip, constants } from 'node:zlib';
import { hostname } from 'node:os';
import { classGate, foldName, STUDENT_ROUTES } from './class-gate.js';

/** The folders only the teacher's own server (`npm start`) serves, from the project's root. */
export const TEACHER_ONLY = ['sketches/solutions', 'tests'];

/** In tests/, what the gallery shows: its thumbnails are the gallery test's pictures of each sketch's first view. */
export const GALLERY_THUMBNAILS = 'tests/e2e/__screenshots__/gallery.spec.js/';

/** What a page gets instead of a reference solution. */
export const ELSEWHERE = 'The reference solution is on the teacher\'s computer: this is your own scene.';
const ANSWER_ELSEWHERE = '\0answer-on-the-teachers-computer';

/** A file of a reference solution (an absolute path or a module id). */
const isAnswerFile = (id) => /[\\/]sketches[\\/]solutions[\\/][^\\/]+$/.test(id.split('?')[0]);

/**
 * @param {{ served: boolean }} options served: the solutions are the real files (the teacher's `npm start`)
 */
export function teachersAnswers({ served }) {
  return {
    name: 'teachers-answers',
    enforce: 'pre',
    resolveId(source, importer) {
      if (served || !importer) return null;
      return isAnswerFile(resolve(importer, '..', source)) ? ANSWER_ELSEWHERE : null;
    },
    load(id) {
      if (served) return null;
      if (id === ANSWER_ELSEWHERE || isAnswerFile(id)) return `export const addLights = null;\nexport const elsewhere = ${JSON.stringify(ELSEWHERE)};\n`;
      return null;
    },
  };
}

/**
 * Whether a request's URL names a teacher-only file, however it is spelt:
 * percent-encoded, with `./` or `../`, another letter case (the teacher's
 * disk may not care), through Vite's `/@fs/` or `/@id/`, with any query.
 * @param {string} url the request's URL (path and query)
 * @param {string} root the project's root folder (absolute)
 */
export function isTeacherOnly(url, root) {
  let path = url.split(/[?#]/)[0];
  try { path = decodeURIComponent(path); } catch { /* a malformed escape: the path as it is */ }
  path = foldName(posix.normalize(path.replaceAll('\\', '/')));
  const base = foldName(root.split(sep).join('/')).replace(/\/?$/, '/');
  path = path.replace(/^\/@id\//, '/').replace(/^\/@fs\//, '/').replace(/^\/+/, '/');
  if (path.startsWith(base)) path = `/${path.slice(base.length)}`;
  if (path.startsWith(`/${GALLERY_THUMBNAILS}`) && /^[\w-]+\.png$/.test(path.slice(GALLERY_THUMBNAILS.length + 1))) return false;
  return TEACHER_ONLY.some((folder) => path === `/${folder}` || path.startsWith(`/${folder}/`));
}

const COMPRESSIBLE = /^(text\/|application\/(javascript|json|xml|wasm)|image\/svg\+xml)/;
const SMALLEST = 1024; // bytes: a smaller answer costs more to compress than it saves
const compressors = {
  br: promisify(brotliCompress),
  gzip: promisify(gzip),
};
const options = {
  br: (size) => ({ params: { [constants.BROTLI_PARAM_QUALITY]: 5, [constants.BROTLI_PARAM_SIZE_HINT]: size } }),
  gzip: () => ({ level: 6 }),
};

/** The encoding a request accepts that we send: brotli first, then gzip, else none. */
export function encodingFor(acceptEncoding = '') {
  const accepted = new Set(String(acceptEncoding).split(',').map((part) => {
    const [name, q] = part.trim().toLowerCase().split(/\s*;\s*q\s*=\s*/);
    return Number(q ?? 1) > 0 ? name : null;
  }));
  return accepted.has('br') ? 'br' : accepted.has('gzip') ? 'gzip' : null;
}

/** The compressed bodies made so far, by encoding and ETag (a few MB: p5 and the kit once). */
class CompressedCache {
  constructor(limitBytes = 64 * 1024 * 1024) { this.entries = new Map(); this.bytes = 0; this.limit = limitBytes; }
  /** @returns {Promise<Buffer>} */
  get(encoding, etag, makeBody) {
    const key = `${encoding} ${etag}`;
    const found = this.entries.get(key);
    if (found) return found.promise;
    const body = makeBody();
    const promise = compressors[encoding](body, options[encoding](body.length));
    const entry = { promise, size: 0 };
    this.entries.set(key, entry);
    promise.then((out) => {
      entry.size = out.length;
      this.bytes += out.length;
      for (const [k, e] of this.entries) { // the oldest go first
        if (this.bytes <= this.limit) break;
        this.entries.delete(k);
        this.bytes -= e.size;
      }
    }, () => this.entries.delete(key));
    return promise;
  }
}

/**
 * A connect middleware: holds an answer's body until it ends, then gives it
 * an ETag (its own, or one of its content), answers 304 to a request that
 * has it already, and compresses a text body for a browser that accepts it.
 * An answer marked immutable (p5's pre-bundle: its URL names its version) is
 * kept as sent, and given again without asking Vite, which would make its
 * 8 MB source map again for each student. A live stream (Server-Sent Events:
 * the class board's) never ends: it goes as it is written.
 */
export function compressAndRevalidate(cache = new CompressedCache()) {
  const kept = new Map(); // URL → { headers, body } of immutable answers
  return (req, res, next) => {
    if (req.headers.upgrade) return next(); // the live-reload WebSocket
    const found = req.method === 'GET' || req.method === 'HEAD' ? kept.get(req.url) : undefined;
    if (found) {
      for (const [name, value] of Object.entries(found.headers)) res.setHeader(name, value);
      return void send(req, res, () => found.body, cache);
    }
    const chunks = [];
    const original = { write: res.write, end: res.end, writeHead: res.writeHead };
    res.writeHead = (status, reason, headers) => {
      if (typeof reason === 'object' && reason !== null) headers = reason;
      res.statusCode = status;
      if (Array.isArray(headers)) for (let i = 0; i < headers.length; i += 2) res.setHeader(headers[i], headers[i + 1]);
      else for (const [name, value] of Object.entries(headers ?? {})) res.setHeader(name, value);
      if (/^text\/event-stream\b/.test(String(res.getHeader('content-type') ?? ''))) {
        Object.assign(res, original);
        return res.writeHead(status);
      }
      return res;
    };
    const add = (chunk, encoding) => {
      if (chunk != null && typeof chunk !== 'function') chunks.push(Buffer.isBuffer(chunk) ? chunk : Buffer.from(chunk, typeof encoding === 'string' ? encoding : 'utf8'));
    };
    res.write = (chunk, encoding, done) => {
      add(chunk, encoding);
      (typeof encoding === 'function' ? encoding : done)?.();
      return true;
    };
    res.end = (chunk, encoding, done) => {
      add(chunk, encoding);
      Object.assign(res, original);
      finish(req, res, Buffer.concat(chunks), cache, kept).then(() => {
        if (typeof chunk === 'function') chunk();
        else (typeof encoding === 'function' ? encoding : done)?.();
      }, (error) => { res.statusCode = 500; res.end(String(error)); });
      return res;
    };
    next();
  };
}

const KEPT_AT_MOST = 100; // immutable answers: p5 and a few more pre-bundled packages

/** An answer from the server behind: its ETag, and kept when immutable; then sent. */
function finish(req, res, body, cache, kept) {
  if (res.statusCode !== 200) return Promise.resolve(void res.end(body));
  if (!res.getHeader('etag')) res.setHeader('ETag', `W/"${createHash('sha1').update(body).digest('base64url')}"`);
  if (!res.getHeader('cache-control')) res.setHeader('Cache-Control', 'no-cache'); // revalidate each visit
  const script = /javascript/.test(String(res.getHeader('content-type') ?? ''));
  if (req.method === 'GET' && /immutable/.test(String(res.getHeader('cache-control')))) {
    const headers = res.getHeaders();
    for (const name of ['content-length', 'content-encoding', 'vary']) delete headers[name];
    const whole = script ? withoutInlineSourceMap(body) : body;
    kept.set(req.url, { headers, body: whole });
    if (kept.size > KEPT_AT_MOST) kept.delete(kept.keys().next().value);
    return send(req, res, () => whole, cache);
  }
  return send(req, res, () => (script ? withoutInlineSourceMap(body) : body), cache);
}

/** A 200 answer whose headers are set: a 304 to a request that has it, else its body, compressed when it is worth it. */
async function send(req, res, body, cache) {
  const etag = res.getHeader('etag');
  res.statusCode = 200;
  if (req.headers['if-none-match'] === etag) {
    for (const name of ['content-type', 'content-length']) res.removeHeader(name);
    res.statusCode = 304;
    return void res.end();
  }
  if (req.method === 'HEAD') return void res.end();
  const type = String(res.getHeader('content-type') ?? '');
  const encoding = encodingFor(req.headers['accept-encoding']);
  const whole = body();
  if (!encoding || whole.length < SMALLEST || !COMPRESSIBLE.test(type) || res.getHeader('content-encoding')) {
    res.setHeader('Content-Length', whole.length);
    return void res.end(whole);
  }
  const out = await cache.get(encoding, etag, () => whole);
  res.setHeader('Content-Encoding', encoding);
  res.setHeader('Vary', 'Accept-Encoding');
  res.setHeader('Content-Length', out.length);
  res.end(out);
}

const INLINE_MAP = '\n//# sourceMappingURL=data:application/json;';

/**
 * A script without the source map the dev server puts at its end (base64,
 * often larger than the script: p5's is 8 MB): students do not need it.
 * @param {Buffer} body
 */
export function withoutInlineSourceMap(body) {
  const at = body.lastIndexOf(INLINE_MAP);
  if (at < 0) return body;
  const after = body.indexOf(10, at + 1); // the map is the script's last line
  if (after >= 0 && body.subarray(after).toString().trim() !== '') return body;
  return body.subarray(0, at + 1);
}

/** The teacher's files answer 404, before Vite looks for them. */
function teacherOnlyIsNotFound(root) {
  return (req, res, next) => {
    if (!isTeacherOnly(req.url ?? '/', root)) return next();
    res.statusCode = 404;
    res.setHeader('Content-Type', 'text/plain; charset=utf-8');
    res.end('Not found: this file stays on the teacher\'s computer.');
  };
}

/** Vite's own server.fs.deny, which a list of ours replaces. */
const VITE_DENIES = ['.env', '.env.*', '*.{crt,pem}', '**/.git/**'];

/** What no student may read, by the file it is (scripts/class-gate.js): the solutions and the project's secrets. */
const GUARDED = ['sketches/solutions', '.git', '.env', '.env.local', '.ci'];

/**
 * The computer's names a student may type: set by scripts/class.js (its host
 * name, NAME.local, --allow-host), else this machine's own.
 */
function classNames() {
  try {
    const names = JSON.parse(process.env.SKETCHBOOK_CLASS_HOSTS ?? 'null');
    if (Array.isArray(names)) return names.map(String);
  } catch { /* not set by class.js: the machine's own names */ }
  const own = hostname().toLowerCase();
  return [own, `${own.split('.')[0]}.local`];
}

/**
 * `npm run class`: the dev server, made light enough for a class on one
 * laptop, and no more than the students' pages need (scripts/class-gate.js).
 * @param {{ isolation?: Record<string, string>, routes?: typeof STUDENT_ROUTES }} [options]
 *   isolation: the cross-origin isolation headers, sent to loopback only;
 *   routes: more routes students may ask for (a plugin's)
 */
export function classroom({ isolation = {}, routes = [] } = {}) {
  return {
    name: 'classroom',
    apply: 'serve',
    enforce: 'pre', // its middlewares before every other plugin's
    config() {
      return {
        // Its own pre-bundle (minified), so the teacher's `npm start` keeps its readable one.
        cacheDir: 'node_modules/.vite-class',
        optimizeDeps: { rolldownOptions: { output: { minify: true } } },
        // Vite's own refusal too (a 403), but for the gallery's thumbnails, which are in tests/.
        // The gate checks the host names itself, with a message that says how to add one.
        // No CORS answers: no other origin may read or write (the gate refuses their writes and preflights).
        server: { cors: false, allowedHosts: true, fs: { deny: [...VITE_DENIES, '**/sketches/solutions/**', '**/tests/**/*.js', '**/tests/**/*solution*'] } },
      };
    },
    configureServer(server) {
      const root = server.config.root;
      server.middlewares.use(classGate({ root, names: classNames(), routes: [...STUDENT_ROUTES, ...routes], guarded: GUARDED, isolation }));
      server.middlewares.use(teacherOnlyIsNotFound(root));
      server.middlewares.use(compressAndRevalidate());
    },
  };
}
