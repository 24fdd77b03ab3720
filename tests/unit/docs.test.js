// The README is a teacher's first page: short, and every link in it and in docs/ leads somewhere
// (a file that exists, and a heading that exists when the link names one). Its first library
// example draws what it says: a lit pink ball.
import { describe, it, expect } from 'vitest';
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { dirname, join, normalize } from 'node:path';
import * as library from '../../lib/index.js';

const README_MAX_LINES = 150;
const documents = ['README.md', ...readdirSync('docs').filter((f) => f.endsWith('.md')).map((f) => `docs/${f}`)];

/** The text without fenced code blocks: a `#` line there is code, and so is a link. */
const withoutCode = (text) => text.replace(/^```[\s\S]*?^```/gm, '');

/** GitHub's anchor for each heading: lower case, punctuation (backticks too) dropped, each space a hyphen; repeats get -1, -2. */
function anchorsOf(file) {
  const seen = new Map(), anchors = new Set();
  for (const [, heading] of withoutCode(readFileSync(file, 'utf8')).matchAll(/^#{1,6} +(.+?) *#*$/gm)) {
    const slug = heading.toLowerCase().replace(/[^\p{L}\p{N}\s_-]/gu, '').replace(/\s/g, '-');
    const n = seen.get(slug) ?? 0;
    seen.set(slug, n + 1);
    anchors.add(n ? `${slug}-${n}` : slug);
  }
  return anchors;
}

/** Every relative link of a Markdown file: `[text](target)` and `![alt](target)`, outside code. */
function relativeLinks(file) {
  const text = withoutCode(readFileSync(file, 'utf8')).replace(/`[^`\n]*`/g, '');
  return [...text.matchAll(/\]\(([^)\s]+)(?: "[^"]*")?\)/g)].map((m) => m[1]).filter((target) => !/^[a-z][a-z+.-]*:/i.test(target));
}

describe('the README', () => {
  it(`is at most ${README_MAX_LINES} lines: the teacher's path first, the details in docs/`, () => {
    const lines = readFileSync('README.md', 'utf8').trimEnd().split('\n').length;
    expect(lines).toBeLessThanOrEqual(README_MAX_LINES);
  });

  it('says how to install the package today (a git URL or a packed tarball), not from the registry alone', () => {
    const readme = readFileSync('README.md', 'utf8');
    expect(readme).not.toMatch(/npm install raytracing-sketchbook\b/);
    expect(readme).toMatch(/npm install git\+https:\/\/\S+\.git/);
    expect(readme).toMatch(/npm pack/);
    expect(readme).toMatch(/npm install \.\/raytracing-sketchbook-[\d.]+\.tgz/);
  });

  it('links the teacher\'s guide, the developer\'s guide, performance, security and access', () => {
    const links = relativeLinks('README.md');
    for (const doc of ['docs/teachers-guide.md', 'docs/DEVELOPERS.md', 'docs/performance.md', 'docs/security.md', 'docs/access.md']) expect(links, doc).toContain(doc);
  });

  it('tells a teacher serving a class the two things only the terminal said: --allow-host and npm 11\'s allowScripts notice', () => {
    for (const file of ['README.md', 'docs/teachers-guide.md']) {
      const text = readFileSync(file, 'utf8');
      expect(text, file).toMatch(/npm run class -- --allow-host \S+/);
      expect(text, file).toMatch(/allowScripts/);
    }
  });

  it('says the homework is written and run in the page (its editor), not saved to a file that reloads', () => {
    const homework = /## Homework\n([\s\S]*?)\n## /.exec(readFileSync('docs/teachers-guide.md', 'utf8'))[1];
    expect(homework).toMatch(/editor in the\s+page/);
    expect(homework).toMatch(/\*\*Run\*\*/);
    expect(homework).not.toMatch(/saves? \(the page re-?(traces|loads)\)/);
  });

  it('has a first library example that draws a lit ball, not an almost black one', () => {
    const readme = readFileSync('README.md', 'utf8');
    const code = /```js\n(import \{[^}]*\} from '\.\/lib\/index\.js';\n[\s\S]*?render\([\s\S]*?)```/.exec(readme)[1];
    const body = code.replace(/^import .*\n/, '') + '\nreturn { rgba, camera, pixel };';
    const { rgba, camera, pixel } = new Function(...Object.keys(library), body)(...Object.values(library));
    expect(pixel.hit).not.toBeNull(); // the middle pixel is on the ball
    const i = (24 * camera.width + 32) * 4;
    const brightness = Math.max(rgba[i], rgba[i + 1], rgba[i + 2]);
    expect(brightness, 'the ball\'s middle, its brightest channel').toBeGreaterThan(150);
    expect(library.colorName([rgba[i], rgba[i + 1], rgba[i + 2]])).toMatch(/pink|red/);
  });
});

describe('links in README.md and docs/*.md', () => {
  it.each(documents)('%s: every relative link leads to a file that exists, and to a heading that exists', (file) => {
    const broken = [];
    for (const link of relativeLinks(file)) {
      const [path, anchor] = link.split('#');
      const target = path === '' ? file : normalize(join(dirname(file), decodeURIComponent(path)));
      if (!existsSync(target)) { broken.push(`${link} (no file ${target})`); continue; }
      if (anchor && target.endsWith('.md') && !anchorsOf(target).has(anchor)) broken.push(`${link} (no heading #${anchor} in ${target})`);
    }
    expect(broken).toEqual([]);
  });

  it('finds the links it checks (the check itself works)', () => {
    expect(relativeLinks('README.md')).toContain('docs/teachers-guide.md');
    expect(relativeLinks('README.md').length).toBeGreaterThan(20);
    expect(anchorsOf('docs/teachers-guide.md').has('serving-a-class')).toBe(true);
    expect(anchorsOf('docs/performance.md').has('a-class-of-30-on-one-laptop-npm-run-benchclass')).toBe(true);
  });
});

describe('the workflows', () => {
  const pages = readFileSync('.github/workflows/pages.yml', 'utf8');
  const release = readFileSync('.github/workflows/release.yml', 'utf8');

  it('pages.yml builds with npm run build and publishes dist/ to GitHub Pages', () => {
    expect(pages).toMatch(/- run: npm ci\b/);
    expect(pages).toMatch(/- run: npm run build\n/);
    expect(pages).toMatch(/actions\/upload-pages-artifact@v\d+\n\s+with:\n\s+path: dist\n/);
    expect(pages).toMatch(/actions\/deploy-pages@v\d+/);
    expect(pages).toMatch(/pages: write/);
  });

  it('release.yml attaches the two files the build writes, by the names the build gives them', () => {
    const onefile = readFileSync('vite.onefile.config.js', 'utf8'), ready = readFileSync('scripts/ready-folder.js', 'utf8');
    expect(onefile).toContain("'raytracing-sketchbook.js'");
    expect(ready).toContain('raytracing-sketchbook-web-editor.zip');
    expect(release).toMatch(/- run: npm run build\n/);
    expect(release).toMatch(/gh release upload "\$TAG" dist\/raytracing-sketchbook\.js dist\/raytracing-sketchbook-web-editor\.zip/);
    expect(release).toMatch(/contents: write/);
  });
});
