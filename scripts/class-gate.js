/**
 * The class server's gate: what a student's laptop may ask `npm run class`
 * for. The dev server behind it has routes meant for the teacher alone
 * (`/__open-in-editor` opens any file in the teacher's editor, `/@fs/` reads
 * files outside the project, source maps carry the sources whole): the gate
 * answers 404 to every request that is not on the list of what the pages
 * need (STUDENT_ROUTES), and to every source map.
 *
 * It also answers to the computer's names: plain http on a name is what a
 * student's browser sees (`http://teachers-laptop.local:5173/`), and Vite
 * refuses names it was not told. The names are the machine's own and those
 * the teacher adds (`npm run class -- --allow-host NAME`); any other gets a
 * page saying how to add it, and the terminal says so once.
 *
 * No other origin may write to it (a page elsewhere, on another port of this
 * computer too): a write or a preflight from another origin gets 403 (isOwnOrigin),
 * and Vite's CORS answers are off (`server.cors: false`, ./classroom.js).
 *
 * How the list is kept: docs/security.md. tests/unit/class-gate.test.js
 * walks the dev server's own routes and asks for each.
 */
import { statSync } from 'node:fs';
import { posix, join } from 'node:path';

/**
 * Every kind of request the students' pages make, as a path pattern (the
 * path decoded and normalised, without its query) and the reason it is there.
 * @type {{ path: RegExp, why: string, methods?: string[] }[]}
 */
export const STUDENT_ROUTES = [
  { path: /^\/$/, why: 'the gallery' },
  { path: /^\/(?![^/]*\.config\.)[\w.-]+\.(html|js|mjs|css|zip)$/, why: 'the pages at the root (gallery, web editor, teacher\'s progress codes), their styles, the one-file build and its zip, sketch-runtime.js (p5 and the kit for the editor\'s frame); not the tools\' config files' },
  { path: /^\/sketches\/[\w.-]+$/, why: 'the sketches: pages, scripts, styles (the solutions are refused after, by what file they are)' },
  { path: /^\/lib\/[\w./-]+$/, why: 'the library\'s modules and workers' },
  { path: /^\/site\/[\w.-]+$/, why: 'the site\'s own page scripts: the gallery\'s, the teacher\'s progress codes, the poll' },
  { path: /^\/editor\/[\w.-]+$/, why: 'code in the page: the editor (CodeMirror\'s modules come from node_modules), its style, and the sandboxed frame\'s host' },
  { path: /^\/sketch-code\/\d\d-[a-z0-9-]+\.js$/, why: 'each sketch\'s own file as text, the editor\'s starter (the plugin reads sketches/ only, never a solution)' },
  { path: /^\/node_modules\/[\w.@/+-]+$/, why: 'p5 and the other packages, pre-bundled or as modules' },
  { path: /^\/@vite\/(client|env)$/, why: 'live reload: a teacher\'s save reaches the students\' pages' },
  { path: /^\/@id\/[\w.@/:+-]+$/, why: 'modules Vite names itself (the stand-in for a solution)' },
  { path: /^\/api\/?(index\.html)?$/, why: 'the API reference' },
  { path: /^\/bench\/live\/[\w./-]+$/, why: 'a sketch written while the class watches, outside the gallery (the live-coding tests write theirs there)' },
  { path: /^\/tests\/e2e\/__screenshots__\/gallery\.spec\.js\/[\w-]+\.png$/, why: 'the gallery\'s thumbnails' },
];

const READ = ['GET', 'HEAD'];

/**
 * The request's path as the server will read it: decoded, `.` and `..`
 * resolved, backslashes as slashes, no query; null when it cannot be decoded.
 * @param {string} url
 */
export function requestPath(url) {
  try {
    const path = decodeURIComponent(url.split(/[?#]/)[0]);
    return posix.normalize(`/${path.replaceAll('\\', '/')}`).replace(/^\/+/, '/');
  } catch {
    return null;
  }
}

/**
 * Whether a student may ask for this URL with this method.
 * @param {string} method
 * @param {string} url
 * @param {{ path: RegExp, methods?: string[] }[]} [routes]
 */
export function isStudentRoute(method, url, routes = STUDENT_ROUTES) {
  const path = requestPath(url);
  if (path === null || path.endsWith('.map') || path.split('/').some((part) => part.startsWith('.') && part !== '.vite-class')) return false;
  return routes.some((route) => route.path.test(path) && (route.methods ?? READ).includes(method));
}

/**
 * A file name as a case-insensitive disk compares it: `ſ` and `s`, `ﬁ` and
 * `fi`, `K` (Kelvin) and `k`, any letter case are one.
 * @param {string} text
 */
export function foldName(text) {
  return text.normalize('NFKC').toUpperCase().toLowerCase().normalize('NFKC');
}

/**
 * Whether a path names, or lies inside, one of the guarded files, decided by
 * the file it resolves to on this disk (device and inode), not by its
 * spelling: on a Mac's or Windows' disk `/SKETCHES/Solutions/` is
 * `sketches/solutions`.
 * @param {string} path a request path (requestPath)
 * @param {string} root the project's folder
 * @param {{ dev: number, ino: number }[]} guarded identities of the guarded files (guardedFiles)
 * @param {(file: string) => { dev: number, ino: number }} [stat]
 */
export function resolvesToGuarded(path, root, guarded, stat = statSync) {
  const parts = path.split('/').filter(Boolean);
  for (let n = parts.length; n > 0; n -= 1) {
    let found;
    try { found = stat(join(root, ...parts.slice(0, n))); } catch { continue; }
    if (guarded.some((g) => g.dev === found.dev && g.ino === found.ino)) return true;
  }
  return false;
}

/**
 * The identities of the files no student may read: the teacher-only folders
 * and the project's secrets, those that exist.
 * @param {string} root
 * @param {string[]} names paths from the root
 * @param {(file: string) => { dev: number, ino: number }} [stat]
 */
export function guardedFiles(root, names, stat = statSync) {
  return names.flatMap((name) => {
    try {
      const { dev, ino } = stat(join(root, name));
      return [{ dev, ino }];
    } catch {
      return [];
    }
  });
}

/** Names that are this machine whatever it is called: loopback and addresses typed as numbers. */
const LOOPBACK = /^(localhost|[\w-]+\.localhost|127(\.\d{1,3}){3}|\[::1\])$/i;
const IPV4 = /^\d{1,3}(\.\d{1,3}){3}$/;

/**
 * The host name of a Host header, lower-case, without its port.
 * @param {string | undefined} header
 */
export function hostName(header) {
  const host = String(header ?? '').trim().toLowerCase();
  return host.startsWith('[') ? host.slice(0, host.indexOf(']') + 1) : host.replace(/:\d*$/, '');
}

/**
 * Whether the class server answers a request that names this host: an
 * address (IPv4 or IPv6), loopback, or one of the computer's names. A name
 * not on the list is refused, so a web page elsewhere cannot reach the class
 * through a name of its own that it points at this computer (DNS rebinding).
 * @param {string | undefined} header the request's Host header
 * @param {string[]} names the computer's names (lower-case)
 */
export function isHostAllowed(header, names) {
  const host = hostName(header);
  if (host === '') return false;
  return LOOPBACK.test(host) || IPV4.test(host) || host.startsWith('[') || names.includes(host);
}

/**
 * Whether a browser treats a page of this host as a secure context (over
 * plain http: loopback only). Only there may the page be cross-origin
 * isolated: elsewhere a browser ignores the headers and says so in red in the
 * console of every page.
 * @param {string | undefined} header
 */
export function isTrustworthyHost(header) {
  return LOOPBACK.test(hostName(header));
}

/**
 * The names of this computer a student may type: its host name, the same
 * with `.local` (mDNS, on every Mac and most Linux and Windows laptops) and
 * without its domain, and the teacher's own additions.
 * @param {string} machine os.hostname()
 * @param {string[]} added from --allow-host
 */
export function computerNames(machine, added = []) {
  const own = String(machine ?? '').toLowerCase();
  const short = own.split('.')[0];
  const names = own ? [own, short, `${short}.local`] : [];
  return [...new Set([...names, ...added.map((name) => name.toLowerCase())])].filter(Boolean);
}

/**
 * The names asked for with `--allow-host NAME` (as often as needed, or
 * `NAME,NAME`); each a host name without scheme or port.
 * @param {string[]} argv
 */
export function allowedHostsFrom(argv) {
  const names = [];
  argv.forEach((arg, i) => {
    const value = arg === '--allow-host' ? argv[i + 1] : arg.startsWith('--allow-host=') ? arg.slice('--allow-host='.length) : null;
    if (value === null) return;
    for (const name of String(value ?? '').split(',')) {
      if (!/^[a-z0-9]([a-z0-9-]*[a-z0-9])?(\.[a-z0-9]([a-z0-9-]*[a-z0-9])?)*$/i.test(name)) {
        throw new RangeError(`--allow-host must be a computer's name such as teachers-laptop.local (letters, digits, - and .), got ${JSON.stringify(name ?? '')}`);
      }
      names.push(name.toLowerCase());
    }
  });
  return names;
}

/**
 * Whether a request comes from a page of the class server itself. With an
 * Origin (a browser sends one with every write, and with every request made
 * across origins), that origin must be `http://` and the very host and port
 * the request came to: another port, `null` (a sandboxed frame, a file), https,
 * another spelling of the name are other origins. Without one, a browser's
 * Sec-Fetch-Site must not say it came from another site; a request with
 * neither is not a page's (a terminal's, a test's).
 * @param {Record<string, string | string[] | undefined>} headers
 */
export function isOwnOrigin(headers) {
  const origin = headers.origin;
  if (origin !== undefined) return origin === `http://${String(headers.host ?? '').toLowerCase()}`;
  const site = headers['sec-fetch-site'];
  return site === undefined || site === 'same-origin' || site === 'none';
}

const READS = new Set(['GET', 'HEAD']);

/** What a student sees for a name the server was not told. */
export function unknownHostPage(host) {
  return `This class server does not answer to the name ${JSON.stringify(host)} yet.\n\n` +
    `Ask your teacher to start it with:   npm run class -- --allow-host ${host}\n` +
    'or type the address the teacher\'s terminal shows (its numbers).\n';
}

/**
 * The gate, as a connect middleware.
 * @param {{ root: string, names: string[], routes?: typeof STUDENT_ROUTES, guarded: string[], isolation: Record<string, string>, log?: (line: string) => void }} options
 */
export function classGate({ root, names, routes = STUDENT_ROUTES, guarded, isolation, log = console.log }) {
  const guardedIds = guardedFiles(root, guarded);
  const told = new Set();
  return function classGateMiddleware(req, res, next) {
    if (!isHostAllowed(req.headers.host, names)) {
      const host = hostName(req.headers.host);
      if (!told.has(host) && told.size < 20) {
        told.add(host);
        log(`\n  A laptop asked for this computer as "${host}": to let it in, stop (Ctrl+C) and run  npm run class -- --allow-host ${host}\n`);
      }
      return refuse(res, 403, unknownHostPage(host));
    }
    // No other origin may write, nor ask whether it may (a preflight): the class's pages are its own origin.
    const asking = req.method === 'OPTIONS' && req.headers.origin !== undefined;
    if (asking || (!READS.has(req.method ?? 'GET') && !isOwnOrigin(req.headers))) {
      return refuse(res, 403, 'Refused: only the class server\'s own pages may send to it.\n');
    }
    const path = requestPath(req.url ?? '/');
    if (!isStudentRoute(req.method ?? 'GET', req.url ?? '/', routes) || resolvesToGuarded(path, root, guardedIds)) {
      return refuse(res, 404, 'Not found: the class server serves the sketches, not the teacher\'s files.\n');
    }
    if (isTrustworthyHost(req.headers.host)) for (const [name, value] of Object.entries(isolation)) res.setHeader(name, value);
    next();
  };
}

function refuse(res, status, text) {
  res.statusCode = status;
  res.setHeader('Content-Type', 'text/plain; charset=utf-8');
  res.setHeader('X-Refused-By', 'class-gate');
  res.end(text);
}
