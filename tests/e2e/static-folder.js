/**
 * The web editor's files, outside the dev server: the one-file build made
 * into a folder of its own, and a plain static server for a folder (its
 * files and nothing else), as any host or the p5 web editor's preview
 * serves them.
 */
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join } from 'node:path';

/** npm run build's one-file builds (raytracing-sketchbook.js and .mjs), written into `folder`. */
export function buildOneFile(folder) {
  execFileSync(process.execPath, ['node_modules/vite/bin/vite.js', 'build', '-c', 'vite.onefile.config.js', '--outDir', folder, '--logLevel', 'error'], { stdio: 'pipe' });
}

const TYPES = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.mjs': 'text/javascript; charset=utf-8' };

/** Serves `folder` on a free port of 127.0.0.1: `{ origin, close() }`. */
export async function serveFolder(folder) {
  const server = createServer((req, res) => {
    const name = new URL(req.url, 'http://x').pathname.slice(1) || 'index.html';
    try {
      const body = readFileSync(join(folder, name.replace(/[^\w.-]/g, '')));
      res.writeHead(200, { 'Content-Type': TYPES[extname(name)] ?? 'application/octet-stream' }).end(body);
    } catch {
      res.writeHead(404).end();
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve)); // any free port: nobody else's
  return { origin: `http://127.0.0.1:${server.address().port}`, close: () => new Promise((resolve) => server.close(resolve)) };
}
