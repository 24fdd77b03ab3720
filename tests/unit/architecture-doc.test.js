// docs/ARCHITECTURE.md is the map of lib/, editor/, site/ and scripts/: every
// file there has its own line, `- \`path\`: what it is`, in the section of its
// own folder (a heading naming the folder in backticks, `lib/p5/pixel/`), the
// path written with its folder (`p5/pixel/record.js` under lib/, or whole:
// `lib/p5/pixel/record.js`, `editor/code-panel.js`); and every file the doc
// names is there. And no file of lib/ grows past 450 lines.
import { it, expect } from 'vitest';
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { relative, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = new URL('../../', import.meta.url);
const doc = readFileSync(new URL('docs/ARCHITECTURE.md', ROOT), 'utf8');

/** Every file under a folder of the project, as its path from the root ('lib/p5/diagrams/draw.js'). */
function filesUnder(folder) {
  const dir = fileURLToPath(new URL(`${folder}/`, ROOT));
  return readdirSync(dir, { recursive: true, withFileTypes: true })
    .filter((entry) => entry.isFile())
    .map((entry) => `${folder}/${relative(dir, join(entry.parentPath ?? entry.path, entry.name)).split('\\').join('/')}`);
}
const MAPPED = ['lib', 'editor', 'site', 'scripts'];
const files = MAPPED.flatMap(filesUnder);
const libFiles = files.filter((f) => f.startsWith('lib/')).map((f) => f.slice('lib/'.length));
const folderOf = (path) => path.slice(0, path.lastIndexOf('/') + 1);
const baseName = (path) => path.split('/').at(-1);

/** A path as the doc writes it, from the root: lib/'s own files may leave out 'lib/' ('shapes/sphere.js'). */
const fromRoot = (name) => (MAPPED.some((folder) => name.startsWith(`${folder}/`)) ? name : `lib/${name}`);

/** The map's lines: each `- \`path\`: …` with the folder of the section it stands in. */
function mapLines() {
  const lines = [];
  let section = null;
  for (const line of doc.split('\n')) {
    const heading = line.match(/^##+ `([\w./-]+\/)`/);
    if (line.startsWith('## ')) section = heading ? heading[1] : null;
    const entry = line.match(/^- `([\w./-]+\.\w+)`: \S/);
    if (entry) lines.push({ path: fromRoot(entry[1]), section });
  }
  return lines;
}
const lines = mapLines();

it('gives every file of lib/, editor/, site/ and scripts/ its own line, named with its folder', () => {
  const named = new Set(lines.map((l) => l.path));
  expect(files.filter((f) => !named.has(f)), 'files docs/ARCHITECTURE.md does not name on a line of its own').toEqual([]);
  const twice = lines.map((l) => l.path).filter((path, i, all) => all.indexOf(path) !== i);
  expect(twice, 'files named on two lines of the map').toEqual([]);
});

it('puts each file\'s line in the section of its own folder', () => {
  const misplaced = lines.filter((l) => l.section !== folderOf(l.path)).map((l) => `${l.path} under ${l.section ?? 'no folder\'s heading'}`);
  expect(misplaced, 'lines of the map in another folder\'s section').toEqual([]);
});

/** The file names the doc writes in backticks ('vec3.js', 'shapes/packed.js', 'lib/p5/page/scene-link.js'). */
const named = [...doc.matchAll(/`([\w./-]+\.(?:js|css|html))`/g)].map((m) => m[1])
  .filter((name) => !/\bNN-/.test(name) && !/^[\w-]+\.html$/.test(name)); // not a placeholder ('sketches/NN-name.js'), nor a page at the root

it('names no file that is gone', () => {
  const gone = named.filter((name) => {
    if (!name.includes('/')) return !files.some((f) => baseName(f) === name); // a bare name in the prose: some file has it
    if (/^(tests|sketches|bench|docs)\//.test(name)) return !existsSync(new URL(name, ROOT));
    return !files.includes(fromRoot(name));
  });
  expect(gone, 'files docs/ARCHITECTURE.md names that are not there').toEqual([]);
});

// Small modules: a file that grows past this is two ideas, and the map names one.
const MAX_LINES = 450;

it(`keeps every file of lib/ to ${MAX_LINES} lines at most`, () => {
  const long = libFiles.filter((f) => f.endsWith('.js'))
    .map((f) => [f, readFileSync(new URL(`lib/${f}`, ROOT), 'utf8').split('\n').length - 1])
    .filter(([, lines]) => lines > MAX_LINES);
  expect(long, 'files of lib/ over the limit, with their lines').toEqual([]);
});
