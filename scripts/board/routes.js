/**
 * The class board's routes on the class server (a connect middleware):
 *
 *   GET  /board?key=K            the teacher's board (./page/board.html)
 *   GET  /board/state?key=K      what the board shows, as JSON
 *   GET  /board/events?key=K     the same, pushed live (Server-Sent Events)
 *   GET  /board/class.csv?key=K  every submission of the class, as CSV
 *   POST /board/clear?key=K      archive the class and start a new one
 *   POST /class/hello            a student's page: its laptop's name on the board
 *   POST /class/send             a student's page: one submission (./checks.js)
 *
 * The board's routes answer 403 without the key. A student's routes take
 * only what a laptop sends and answer with that laptop's own name: no route
 * for students reads anyone's answers. A hello gives a laptop new to the
 * class its secret; every later request proves it (X-RT-Laptop-Secret), so
 * no laptop speaks as another. Only the class's own pages write: a write
 * from another origin is refused (403) here as at the class gate.
 */
import { createHash, timingSafeEqual } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { checkSubmission, readHello, checkNickname, BadSubmission, BODY_MAX_BYTES } from './checks.js';
import { isOwnOrigin } from '../class-gate.js';
import { BoardFullError } from './store.js';
import { RateLimit, LAPTOP_LIMIT, ADDRESS_LIMIT } from './limits.js';
import { boardCSV } from './csv.js';

/**
 * What the class gate (scripts/class-gate.js) lets in for the board, as its
 * own list is written: a path, its reason, its methods (GET and HEAD when
 * none are named). vite.config.js gives them to `classroom({ routes })`.
 * A student's laptop may POST to its own routes only; the teacher's routes
 * are on the list so that they can answer 403 without the key.
 * @type {{ path: RegExp, why: string, methods?: string[] }[]}
 */
export const BOARD_ROUTES = [
  { path: /^\/board$/, why: 'the teacher\'s board (403 without the key in the terminal)' },
  { path: /^\/board\/(state|events|class\.csv)$/, why: 'what the board shows, pushed live, and its CSV (403 without the key)' },
  { path: /^\/board\/clear$/, methods: ['POST'], why: 'Clear the board: the class archived, a new one started (403 without the key)' },
  { path: /^\/class\/(hello|send)$/, methods: ['POST'], why: 'a student\'s page: its name on the board, one submission (it reads nobody\'s answers)' },
  { path: /^\/scripts\/board\/page\/[\w-]+\.(js|css)$/, why: 'the board page\'s script and style (nothing of the class in them)' },
  { path: /^\/(poll\.html|site\/poll\.js)$/, why: 'the lesson\'s poll, a student\'s page, and its script' },
];

/** Where a student's page sends (the meta tag the class server puts in every page names it). */
export const STUDENT_ROUTE = '/class/';

const BOARD_PAGE = new URL('./page/board.html', import.meta.url);
const SECURITY = {
  'Cache-Control': 'no-store',
  'Referrer-Policy': 'no-referrer', // the key stays out of any Referer
  'X-Content-Type-Options': 'nosniff',
};
const BOARD_POLICY = "default-src 'self'; img-src 'self' data:; style-src 'self'; script-src 'self'; connect-src 'self'; frame-ancestors 'none'";
const HEARTBEAT_MS = 15_000;
/** What a refused submission is called on the board (the kind it said it was, when it is one). */
const KINDS = ['answer', 'task', 'check', 'poll'];
/** A body over the limit is read to its end (and dropped) up to this, so that the page hears 413, not a reset connection. */
const DISCARD_MAX_BYTES = 64 * 1024 * 1024;
/** The headers a student's page names its laptop and proves it with (lib/p5/page/class-board.js). */
export const LAPTOP_HEADER = 'x-rt-laptop';
export const SECRET_HEADER = 'x-rt-laptop-secret';
const PUSH_AFTER_MS = 250; // a burst of submits makes one push, at most this late

/**
 * @param {{ store: import('./store.js').BoardStore, key: string, limits?: { laptop: RateLimit, address: RateLimit } }} options
 * @returns {(req: any, res: any, next: () => void) => void} with `.close()` ending the live streams
 */
export function boardRoutes({ store, key, limits = { laptop: new RateLimit(LAPTOP_LIMIT), address: new RateLimit(ADDRESS_LIMIT) } }) {
  const live = liveStreams(() => JSON.stringify(store.state()));
  const keep = groupCommit((submissions) => store.addMany(submissions));
  const keyed = hashOf(key);
  const hasKey = (url) => timingSafeEqual(hashOf(url.searchParams.get('key') ?? ''), keyed);

  const board = {
    'GET /board': (req, res) => send(res, 200, readFileSync(BOARD_PAGE), { 'Content-Type': 'text/html; charset=utf-8', 'Content-Security-Policy': BOARD_POLICY }),
    'GET /board/state': (req, res) => json(res, 200, store.state()),
    'GET /board/events': (req, res) => live.add(req, res),
    'GET /board/class.csv': (req, res) => {
      const { id, started } = store.currentClass;
      send(res, 200, boardCSV(store.rows()), { 'Content-Type': 'text/csv; charset=utf-8', 'Content-Disposition': `attachment; filename="class-${id}-${started.slice(0, 10)}.csv"` });
    },
    'POST /board/clear': (req, res) => { json(res, 200, { class: store.clear() }); live.changed(); },
  };
  /** The laptop a request proves it is (its id and secret in the headers), or null. */
  const provenLaptop = (req, laptop = req.headers[LAPTOP_HEADER]) => (typeof laptop === 'string' && store.proves(laptop, req.headers[SECRET_HEADER]) ? laptop : null);
  const refused = (laptop, what, error) => {
    if (!laptop || !(error instanceof BadSubmission)) return;
    try { store.refuse(laptop, what, error.message); } catch { return; } // a full board keeps what it has
    live.changed();
  };
  const student = {
    'POST /class/hello': (req, res, body) => {
      const { laptop: asked, nickname: sent } = readHello(body);
      const wait = limits.laptop.take(asked);
      if (wait) return tooMany(res, wait);
      const who = store.hello(asked, req.headers[SECRET_HEADER]);
      try {
        const nickname = checkNickname(sent);
        json(res, 200, nickname === undefined ? who : { ...who, ...store.rename(who.laptop, nickname) });
      } catch (error) {
        if (!(error instanceof BadSubmission)) throw error;
        refused(who.laptop, 'name', error);
        json(res, 400, { error: error.message, field: 'name', ...who });
      }
    },
    'POST /class/send': async (req, res, body) => {
      const laptop = provenLaptop(req, typeof body?.laptop === 'string' ? body.laptop : undefined);
      if (!laptop) return json(res, 403, { error: 'this laptop must say hello to the class board first (its secret is missing or wrong)', hello: true });
      const wait = limits.laptop.take(laptop);
      if (wait) return tooMany(res, wait);
      let submission;
      try {
        submission = checkSubmission(body);
        if (submission.nickname !== undefined) store.rename(laptop, submission.nickname);
      } catch (error) {
        refused(laptop, KINDS.includes(body?.kind) ? body.kind : 'send', error);
        throw error;
      }
      delete submission.nickname;
      const { name, number, stored } = await keep(submission); // on disk when it resolves
      json(res, 200, { received: true, name, number, again: !stored }, { 'Server-Timing': `board;dur=${(performance.now() - req.boardStart).toFixed(1)}` });
      if (stored) live.changed();
    },
  };

  const middleware = (req, res, next) => {
    const url = new URL(req.url ?? '/', 'http://class');
    const route = `${req.method} ${url.pathname}`;
    if (url.pathname === '/board' || url.pathname.startsWith('/board/')) {
      if (req.method !== 'GET' && req.method !== 'HEAD' && !isOwnOrigin(req.headers)) return send(res, 403, 'Only the class board\'s own page may change it.', { 'Content-Type': 'text/plain; charset=utf-8' });
      if (!hasKey(url)) return send(res, 403, 'This is the teacher\'s class board: its address, with its key, is in the terminal of npm run class.', { 'Content-Type': 'text/plain; charset=utf-8' });
      if (!board[route]) return send(res, 404, 'Not found', { 'Content-Type': 'text/plain; charset=utf-8' });
      try { return board[route](req, res); } catch (error) { return answerError(res, error); }
    }
    if (!url.pathname.startsWith(STUDENT_ROUTE)) return next();
    if (!student[route]) return json(res, 404, { error: 'not a route of the class board' });
    if (!isOwnOrigin(req.headers)) return json(res, 403, { error: 'only the class\'s own pages may send to the class board' });
    req.boardStart = performance.now();
    const wait = limits.address.take(req.socket?.remoteAddress ?? '?');
    if (wait) return tooMany(res, wait);
    readJSON(req).then((body) => student[route](req, res, body)).catch((error) => {
      if (error.status === 413) refused(provenLaptop(req), 'send', error);
      answerError(res, error);
    });
  };
  middleware.close = () => live.close();
  return middleware;
}

/**
 * The board's routes where the database cannot be loaded: 503 with the
 * reason (and what to run), not the gallery that Vite would send for an
 * unknown path.
 * @param {string} problem
 */
export function boardIsOff(problem) {
  return function classBoardIsOff(req, res, next) {
    const { pathname } = new URL(req.url ?? '/', 'http://class');
    if (!(pathname === '/board' || pathname.startsWith('/board/') || pathname.startsWith(STUDENT_ROUTE))) return next();
    send(res, 503, `${problem[0].toUpperCase()}${problem.slice(1)}\nThe pages are served as usual; nothing the students do is sent.\n`, { 'Content-Type': 'text/plain; charset=utf-8' });
  };
}

/**
 * Group commit: the submissions that arrive while the database flushes one
 * transaction to the disk (better-sqlite3 holds the event loop meanwhile) go
 * together into the next, each told "received" once it is on disk.
 * @template T, R
 * @param {(items: T[]) => R[]} write
 * @returns {(item: T) => Promise<R>}
 */
export function groupCommit(write) {
  let queue = [];
  const flush = () => {
    const taken = queue;
    queue = [];
    try {
      const results = write(taken.map((t) => t.item));
      taken.forEach((t, i) => t.resolve(results[i]));
    } catch (error) {
      for (const t of taken) t.reject(error);
    }
  };
  return (item) => new Promise((resolve, reject) => {
    queue.push({ item, resolve, reject });
    if (queue.length === 1) setImmediate(flush);
  });
}

/** The streams of the boards open now; `changed()` pushes the new state to each, a burst of changes once. */
function liveStreams(stateText) {
  const streams = new Set();
  let timer = null;
  const push = () => {
    timer = null;
    if (streams.size === 0) return;
    const event = `event: state\ndata: ${stateText()}\n\n`;
    for (const res of streams) res.write(event);
  };
  const heartbeat = setInterval(() => { for (const res of streams) res.write(': still here\n\n'); }, HEARTBEAT_MS);
  heartbeat.unref?.();
  return {
    add(req, res) {
      res.writeHead(200, { ...SECURITY, 'Content-Type': 'text/event-stream; charset=utf-8', Connection: 'keep-alive', 'X-Accel-Buffering': 'no' });
      res.write(`retry: 1000\nevent: state\ndata: ${stateText()}\n\n`);
      streams.add(res);
      req.on('close', () => streams.delete(res));
    },
    changed() { timer ??= setTimeout(push, PUSH_AFTER_MS); },
    close() {
      clearInterval(heartbeat);
      clearTimeout(timer ?? undefined);
      for (const res of streams) res.end();
      streams.clear();
    },
  };
}

/**
 * The request's body as JSON: at most BODY_MAX_BYTES, sent as application/json.
 * A longer body is read to its end and dropped, then answered 413: closing
 * the connection while the page still sends would reset it, and the page
 * would hear nothing. Past DISCARD_MAX_BYTES it is answered and closed.
 */
function readJSON(req) {
  return new Promise((done, fail) => {
    if (!/^application\/json\b/i.test(req.headers['content-type'] ?? '')) {
      req.resume();
      return fail(new BadSubmission('send JSON (Content-Type: application/json)'));
    }
    const tooLong = () => Object.assign(new BadSubmission(`the submission is too long: at most ${BODY_MAX_BYTES} bytes`), { status: 413 });
    const chunks = [];
    let size = 0;
    const onData = (chunk) => {
      size += chunk.length;
      if (size <= BODY_MAX_BYTES) chunks.push(chunk);
      else if (size > DISCARD_MAX_BYTES) {
        req.off('data', onData);
        fail(Object.assign(tooLong(), { close: true }));
      }
    };
    req.on('data', onData);
    req.on('end', () => {
      if (size > DISCARD_MAX_BYTES) return;
      if (size > BODY_MAX_BYTES) return fail(tooLong());
      try { done(JSON.parse(Buffer.concat(chunks).toString('utf8'))); } catch { fail(new BadSubmission('the submission is not JSON')); }
    });
    req.on('error', fail);
  });
}

function answerError(res, error) {
  if (res.headersSent || res.destroyed) return;
  if (error instanceof BadSubmission) {
    json(res, error.status ?? 400, { error: error.message, ...(error.message.startsWith('name ') ? { field: 'name' } : {}) }, error.close ? { Connection: 'close' } : {});
    if (error.close) res.on('finish', () => res.socket?.destroySoon?.());
    return;
  }
  if (error instanceof BoardFullError) return json(res, 507, { error: `${error.message}: ask your teacher` });
  console.error('class board:', error);
  json(res, 500, { error: 'the class board could not store it: it will be sent again' });
}

function tooMany(res, seconds) {
  json(res, 429, { error: `too many sends from this laptop: the next in ${seconds} s`, retryAfter: seconds }, { 'Retry-After': String(seconds) });
}

function json(res, status, value, headers = {}) {
  send(res, status, JSON.stringify(value), { 'Content-Type': 'application/json; charset=utf-8', ...headers });
}

function send(res, status, body, headers) {
  res.writeHead(status, { ...SECURITY, ...headers });
  res.end(body);
}

const hashOf = (text) => createHash('sha256').update(String(text)).digest();
