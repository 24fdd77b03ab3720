// The README's sketch list is the gallery's: every sketch page, in order, by its title.
import { describe, it, expect } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';

const plain = (text) => text.replace(/[’‘]/g, "'").trim();

describe('README', () => {
  it('lists every sketch page in lesson order, with the title the gallery shows', () => {
    const pages = readdirSync('sketches').filter((f) => f.endsWith('.html')).sort();
    const readme = readFileSync('README.md', 'utf8');
    const rows = [...readme.matchAll(/^\| (\d+) \| \[([^\]]+)\]\(sketches\/([^)]+\.html)\) \|/gm)];
    expect(rows.map((r) => r[3])).toEqual(pages);
    for (const [, number, title, file] of rows) {
      const html = readFileSync(`sketches/${file}`, 'utf8');
      const pageTitle = /<title>([^<]*)<\/title>/.exec(html)[1];
      expect(plain(pageTitle)).toBe(`${number} · ${plain(title)}`);
    }
  });
});
