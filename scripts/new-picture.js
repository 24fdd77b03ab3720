#!/usr/bin/env node
/**
 * `npm run test:new-picture -- sketches/11-my-sketch.html`: makes the first
 * reference picture of ONE new sketch (each of its tracer views), and no other.
 *
 * It runs that sketch's screenshot test (tests/e2e/gallery.spec.js) with
 * Playwright's --update-snapshots=missing, which writes pictures that do not
 * exist yet and never rewrites one that does; then runs it again without, so
 * the new picture must come out the same a second time. It prints the files
 * made: look at them, and commit them if they show what you meant.
 */
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync } from 'node:fs';
import { basename, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const ROOT = resolve(import.meta.dirname, '..');
const SPEC = 'tests/e2e/gallery.spec.js';
const SHOTS = join(ROOT, 'tests/e2e/__screenshots__/gallery.spec.js');

/**
 * The sketch page an argument names (`sketches/11-my-sketch.html`, or just
 * `11-my-sketch.html`): its file name; else a TypeError that says what to type.
 * @param {string} [arg]
 * @param {string} [root] the project's folder
 */
export function sketchPage(arg, root = ROOT) {
  const usage = 'usage: npm run test:new-picture -- sketches/NN-name.html';
  if (!arg) throw new TypeError(`which sketch? ${usage}`);
  const file = basename(arg);
  if (!/^\d\d-[\w-]+\.html$/.test(file)) throw new TypeError(`a sketch page is named like sketches/11-my-sketch.html, got "${arg}"; ${usage}`);
  if (!existsSync(join(root, 'sketches', file))) throw new TypeError(`there is no sketches/${file}; ${usage}`);
  return file;
}

/** The reference pictures of a sketch page's views that exist now. */
export function referencesOf(file, dir = SHOTS) {
  const stem = file.replace(/\.html$/, '');
  return existsSync(dir) ? readdirSync(dir).filter((f) => f.startsWith(`${stem}-view`) && f.endsWith('.png')).sort() : [];
}

/** Only that page's screenshot test: its title, as a regular expression. */
export const testTitle = (file) => `${file.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')} renders`;

function playwright(file, ...extra) {
  const cli = join(ROOT, 'node_modules/@playwright/test/cli.js');
  return spawnSync(process.execPath, [cli, 'test', SPEC, '-g', testTitle(file), '--workers=1', '--reporter=line', ...extra], { cwd: ROOT, stdio: 'inherit' }).status;
}

function main() {
  let file;
  try {
    file = sketchPage(process.argv[2]);
  } catch (error) {
    console.error(error.message);
    process.exit(2);
  }
  const before = referencesOf(file);
  playwright(file, '--update-snapshots=missing'); // fails when it writes: the picture was missing
  const made = referencesOf(file).filter((f) => !before.includes(f));
  if (!made.length) {
    console.error(before.length
      ? `\nsketches/${file} already has its reference picture(s): ${before.join(', ')}. This script never rewrites one.\n` +
        `To change one on purpose: npx playwright test ${SPEC} -g "${testTitle(file)}" --update-snapshots, then look at it.`
      : `\nNo picture was made for sketches/${file}: see the test's output above (a console error, or no data-render="done").`);
    process.exit(1);
  }
  console.log(`\nChecking that sketches/${file} draws the same picture a second time…`);
  if (playwright(file) !== 0) {
    console.error(`\nThe second run differs or fails: see above. The new picture(s) are still there to look at: ${made.join(', ')}.`);
    process.exit(1);
  }
  console.log(`\nMade ${made.length} reference picture(s) for sketches/${file}:`);
  for (const f of made) console.log(`  ${join('tests/e2e/__screenshots__/gallery.spec.js', f)}`);
  console.log('Look at each one; if it is the picture you meant, commit it with the sketch.');
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) main();
