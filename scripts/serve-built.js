/**
 * The built site for the browser tests that only read pages (Playwright's
 * project `built`): `vite build` into node_modules/.cache/built-site, then `vite preview`
 * of it on the port given. A bundled page loads several times faster than
 * the dev server's page of many modules transformed on request.
 * The build is skipped when no source file is newer than the last one, so
 * running one spec again does not wait for it.
 * It lives in node_modules/.cache: Playwright empties test-results/ as a run
 * starts, and the dev server ignores node_modules.
 *   node scripts/serve-built.js --port 5200
 */
import { spawnSync, spawn } from 'node:child_process';
import { existsSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const OUT = 'node_modules/.cache/built-site';
const STAMP = join(OUT, '.built');
const SOURCES = ['lib', 'sketches', 'scripts', 'editor', 'site', 'examples', 'index.html', 'web-editor.html', 'teacher.html', 'poll.html',
  'gallery.css', 'vite.config.js', 'package.json'];
const port = process.argv[process.argv.indexOf('--port') + 1];
if (!/^\d+$/.test(port ?? '')) {
  console.error('serve-built: give the port, as --port 5200');
  process.exit(2);
}

if (!existsSync(STAMP) || newestChange(SOURCES) > statSync(STAMP).mtimeMs) {
  const env = { ...process.env };
  delete env.SKETCHBOOK_WITH_SOLUTIONS; // the site as published, as npm run build makes it
  const build = spawnSync(process.execPath, ['node_modules/vite/bin/vite.js', 'build', '--outDir', OUT, '--emptyOutDir', '--logLevel', 'error'], { stdio: 'inherit', env });
  if (build.status !== 0) process.exit(build.status ?? 1);
  writeFileSync(STAMP, new Date().toISOString());
}
const preview = spawn(process.execPath, ['node_modules/vite/bin/vite.js', 'preview', '--outDir', OUT, '--port', port, '--strictPort'], { stdio: 'inherit' });
for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, () => preview.kill(signal));
preview.on('exit', (code) => process.exit(code ?? 0));

/** The latest modification time of the files and folders given, in ms. */
function newestChange(paths) {
  let newest = 0;
  for (const path of paths) {
    if (!existsSync(path)) continue;
    const stat = statSync(path);
    newest = Math.max(newest, stat.mtimeMs);
    if (stat.isDirectory()) newest = Math.max(newest, newestChange(readdirSync(path).map((name) => join(path, name))));
  }
  return newest;
}
