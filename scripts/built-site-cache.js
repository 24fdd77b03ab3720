/**
 * The built site the browser tests share: `vite build` as `npm run build` makes it
 * (the solutions left out) into node_modules/.cache/built-site, made again only
 * when a source file is newer than the last build. scripts/serve-built.js serves it
 * to the project `built`; built-site.spec.js reads the same build (and what it
 * printed) instead of building the site a second time.
 * It lives in node_modules/.cache: Playwright empties test-results/ as a run
 * starts, and the dev server ignores node_modules.
 */
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

export const BUILT_SITE = 'node_modules/.cache/built-site';
// Beside the folder, not in it: the folder holds the site's files only.
const STAMP = `${BUILT_SITE}.built`;
const LOG = `${BUILT_SITE}.log`;
const SOURCES = ['lib', 'sketches', 'scripts', 'editor', 'site', 'examples', 'index.html', 'web-editor.html', 'teacher.html', 'poll.html',
  'gallery.css', 'vite.config.js', 'package.json'];

/** Whether the cached build is there and no source changed since it was made. */
export function builtSiteIsFresh() {
  return existsSync(STAMP) && existsSync(BUILT_SITE) && newestChange(SOURCES) <= statSync(STAMP).mtimeMs;
}

/**
 * Builds the site into the cache unless it is fresh; prints what the build printed.
 * Returns the build's exit status (0 when nothing had to be built).
 */
export function buildSiteOnce() {
  if (builtSiteIsFresh()) return 0;
  const env = { ...process.env };
  delete env.SKETCHBOOK_WITH_SOLUTIONS; // the site as published, as npm run build makes it
  const build = spawnSync(process.execPath, ['node_modules/vite/bin/vite.js', 'build', '--outDir', BUILT_SITE, '--emptyOutDir', '--logLevel', 'warn'],
    { env, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  const printed = `${build.stdout ?? ''}${build.stderr ?? ''}`;
  process.stderr.write(printed);
  if (build.status !== 0) return build.status ?? 1;
  writeFileSync(LOG, printed);
  writeFileSync(STAMP, new Date().toISOString());
  return 0;
}

/** What the cached build printed (warnings and errors). */
export const builtSiteLog = () => readFileSync(LOG, 'utf8');

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
