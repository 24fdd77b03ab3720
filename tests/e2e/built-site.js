/**
 * The built site for browser tests: `vite build` into a folder of its own
 * (the solutions left out, as `npm run build` does), served by a plain static
 * server from a sub-path, as GitHub Pages serves https://NAME.github.io/REPO/.
 */
import { spawn } from 'node:child_process';
import { createServer } from 'node:http';
import { mkdtempSync, readFileSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { extname, join, normalize, resolve, sep } from 'node:path';
import { BUILT_SITE, builtSiteIsFresh, builtSiteLog } from '../../scripts/built-site-cache.js';

const TYPES = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css',
  '.png': 'image/png', '.json': 'application/json', '.svg': 'image/svg+xml', '.zip': 'application/zip' };

/** What the last buildSite() printed (warnings and errors: it builds with --logLevel warn). */
export let buildOutput = '';

/**
 * The built site: the build the project `built` is served from (scripts/built-site-cache.js)
 * when it is up to date with the sources, else a new build into a temporary folder.
 * Resolves with the folder; `buildOutput` then holds what that build printed.
 */
export async function builtSite() {
  if (!builtSiteIsFresh()) return buildSite();
  buildOutput = builtSiteLog();
  return resolve(BUILT_SITE);
}

/** Removes a folder builtSite() made, never the shared build. */
export const removeBuiltSite = (folder) => { if (folder !== resolve(BUILT_SITE)) removeFolder(folder); };

/** Builds the site into a new temporary folder; resolves with the folder. */
export function buildSite() {
  const outDir = mkdtempSync(join(tmpdir(), 'rt-built-site-'));
  const env = { ...process.env };
  delete env.SKETCHBOOK_WITH_SOLUTIONS;
  return new Promise((done, fail) => {
    const child = spawn(process.execPath, ['node_modules/vite/bin/vite.js', 'build', '--outDir', outDir, '--emptyOutDir', '--logLevel', 'warn'], { env, stdio: ['ignore', 'pipe', 'pipe'] });
    let output = '';
    child.stdout.on('data', (d) => { output += d; });
    child.stderr.on('data', (d) => { output += d; });
    child.on('exit', (code) => {
      buildOutput = output;
      if (code === 0) done(outDir); else fail(new Error(`vite build failed (${code}):\n${output}`));
    });
  });
}

/**
 * Serves `folder` at http://127.0.0.1:PORT/<base>/ (a folder's index.html for
 * a folder), nothing anywhere else; no special headers, as a static host.
 * Resolves with { url, close, requests } (every path asked for).
 */
export function serveFolder(folder, base) {
  const requests = [];
  const server = createServer((req, res) => {
    const path = decodeURIComponent(req.url.split(/[?#]/)[0]);
    requests.push(path);
    let file = path.startsWith(base) ? normalize(join(folder, path.slice(base.length))) : null;
    if (file && file !== folder && !file.startsWith(folder + sep)) file = null;
    try {
      if (file && statSync(file).isDirectory()) file = join(file, 'index.html');
      const body = readFileSync(file);
      res.writeHead(200, { 'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream' });
      res.end(body);
    } catch {
      res.writeHead(404, { 'Content-Type': 'text/plain' });
      res.end('Not found');
    }
  });
  return new Promise((done) => server.listen(0, '127.0.0.1', () => done({
    url: `http://127.0.0.1:${server.address().port}${base}`,
    requests,
    close: () => new Promise((closed) => { server.closeAllConnections(); server.close(closed); }),
  })));
}

export const removeFolder = (folder) => rmSync(resolve(folder), { recursive: true, force: true });
