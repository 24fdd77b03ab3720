// docs/ARCHITECTURE.md is the map of lib/: every file under lib/ is named in
// it, and every lib/ file it names is there. A file is named by its path under
// lib/ (`shapes/sphere.js`, `p5/scene-view.js`, or with `lib/` in front), or
// by its bare name in backticks when no other file of lib/ has that name. And
// no file of lib/ grows past 450 lines.
import { it, expect } from 'vitest';
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { relative, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = new URL('../../', import.meta.url);
const doc = readFileSync(new URL('docs/ARCHITECTURE.md', ROOT), 'utf8');

/** Every file under lib/, as its path under lib/ ('p5/diagrams/draw.js'). */
const LIB = fileURLToPath(new URL('lib/', ROOT));
const files = readdirSync(LIB, { recursive: true, withFileTypes: true })
  .filter((entry) => entry.isFile())
  .map((entry) => relative(LIB, join(entry.parentPath ?? entry.path, entry.name)).split('\\').join('/'));
const baseName = (path) => path.split('/').at(-1);
const count = new Map();
for (const f of files) count.set(baseName(f), (count.get(baseName(f)) ?? 0) + 1);

/** The file names the doc writes in backticks ('vec3.js', 'shapes/packed.js', 'lib/p5/page/scene-link.js'). */
const named = [...doc.matchAll(/`([\w./-]+\.(?:js|css))`/g)].map((m) => m[1]).filter((name) => !/\bNN-/.test(name)); // not a placeholder ('sketches/NN-name.js')
const underLib = (name) => name.replace(/^lib\//, '');

it('names every file under lib/', () => {
  const names = new Set(named.map(underLib));
  const missing = files.filter((f) => {
    if (names.has(f)) return false;
    // a path under a folder the doc writes whole ('diagrams/plane-views.js' for lib/p5/diagrams/plane-views.js)
    if ([...names].some((n) => n.includes('/') && f.endsWith(`/${n}`))) return false;
    return !(count.get(baseName(f)) === 1 && names.has(baseName(f)));
  });
  expect(missing, 'files under lib/ that docs/ARCHITECTURE.md does not name').toEqual([]);
});

it('names no file of lib/ that is gone', () => {
  const gone = named.filter((name) => {
    const path = underLib(name);
    if (name.startsWith('lib/') || !/^(tests|scripts|sketches|bench|docs|editor)\//.test(name)) {
      return !files.includes(path) && !files.some((f) => f.endsWith(`/${path}`)) && !(name.indexOf('/') < 0 && count.has(name));
    }
    return !existsSync(new URL(name, ROOT)); // a file outside lib/: it is there too
  });
  expect(gone, 'files docs/ARCHITECTURE.md names that are not there').toEqual([]);
});

// Small modules: a file that grows past this is two ideas, and the map names one.
const MAX_LINES = 450;

it(`keeps every file of lib/ to ${MAX_LINES} lines at most`, () => {
  const long = files.filter((f) => f.endsWith('.js'))
    .map((f) => [f, readFileSync(join(LIB, f), 'utf8').split('\n').length - 1])
    .filter(([, lines]) => lines > MAX_LINES);
  expect(long, 'files of lib/ over the limit, with their lines').toEqual([]);
});
