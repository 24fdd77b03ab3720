// The README's sketch list is the gallery's: every sketch page, in order, by its title.
// And every page is made the way "Writing a sketch" says.
import { describe, it, expect } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';

const plain = (text) => text.replace(/[’‘]/g, "'").trim();
const pages = readdirSync('sketches').filter((f) => f.endsWith('.html')).sort();

describe('README', () => {
  it('lists every sketch page in lesson order, with the title the gallery shows', () => {
    const readme = readFileSync('README.md', 'utf8');
    const rows = [...readme.matchAll(/^\| (\d+) \| \[([^\]]+)\]\(sketches\/([^)]+\.html)\) \|/gm)];
    expect(rows.map((r) => r[3])).toEqual(pages);
    for (const [, number, title, file] of rows) {
      const html = readFileSync(`sketches/${file}`, 'utf8');
      const pageTitle = /<title>([^<]*)<\/title>/.exec(html)[1];
      expect(plain(pageTitle)).toBe(`${number} · ${plain(title)}`);
    }
  });

  it.each(pages)('%s has a title and a heading with its number, a description, the shared stylesheet, <main id="sketch"> and its script', (file) => {
    const html = readFileSync(`sketches/${file}`, 'utf8');
    const [, number, slug] = /^(\d\d)-(.+)\.html$/.exec(file);
    expect(html).toMatch(new RegExp(`<title>${number} · [^<]+</title>`));
    expect(html).toMatch(new RegExp(`<h1>${number} · [^<]+</h1>`)); // the heading has its number, as the title
    expect(html).toMatch(/<meta name="description" content="[^"]+">/);
    expect(html).toContain('<link rel="stylesheet" href="./sketch.css">');
    expect(html).toContain('<main id="sketch"');
    expect(html).toContain(`<script type="module" src="./${number}-${slug}.js"></script>`);
  });
});

describe('sketches/sketch.css', () => {
  // The built site puts the shared stylesheet after a page's own <style>, the
  // dev server before it: only a cascade layer lets the page's rules win in both.
  it('keeps every rule inside one cascade layer', () => {
    const css = readFileSync('sketches/sketch.css', 'utf8').replace(/\/\*[\s\S]*?\*\//g, '').trim();
    expect(css).toMatch(/^@layer [\w-]+ \{/);
    let depth = 0, closedAt = -1;
    for (let i = 0; i < css.length; i++) {
      if (css[i] === '{') depth++;
      if (css[i] === '}' && --depth === 0) { closedAt = i; break; }
    }
    expect(closedAt).toBe(css.length - 1);
  });
});

describe('the p5 web editor: README and docs/web-editor.md', () => {
  it('shows the starter sketch the browser tests run, as it is, and the <script> line', () => {
    const guide = readFileSync('docs/web-editor.md', 'utf8');
    expect(guide).toContain('```js\n' + readFileSync('examples/web-editor/sketch.js', 'utf8') + '```');
    expect(guide).toContain('<script src="raytracing-sketchbook.js"></script>');
    expect(readFileSync('README.md', 'utf8')).toContain('<script src="raytracing-sketchbook.js"></script>');
  });
});
