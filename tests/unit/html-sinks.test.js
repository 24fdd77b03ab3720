// Nothing that came from outside is parsed as HTML: a static look at the
// project's code (lib/, sketches/, site/, editor/). Nothing written to innerHTML & co.; p5's create* functions that set
// innerHTML (createP, createDiv, createElement(tag, text), createButton, …)
// only with a plain string literal. And every link parameter the code reads is
// in the hostile-link test's list (tests/e2e/link-parameters.js).
import { describe, it, expect } from 'vitest';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { OWN_NAMES } from '../e2e/link-parameters.js';

function sources(dir) {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? sources(path) : path.endsWith('.js') ? [path] : [];
  });
}
const FILES = [...sources('lib'), ...sources('sketches'), ...sources('site'), ...sources('editor')].map((path) => ({ path, text: readFileSync(path, 'utf8') }));

/** Lines of code (comments out) matching `pattern`, as "file:line: text". */
function find(pattern) {
  const found = [];
  for (const { path, text } of FILES) {
    text.split('\n').forEach((line, i) => {
      const code = line.replace(/^\s*(\*|\/\/).*$/, '').replace(/\s\/\/ .*$/, '');
      if (pattern.test(code)) found.push(`${path}:${i + 1}: ${line.trim()}`);
    });
  }
  return found;
}

// A plain literal: '…' or "…" with no concatenation, or `…` with no ${…}.
const LITERAL = String.raw`(?:'[^'\\]*'|"[^"\\]*"|\x60[^\x60$\\]*\x60)`;

describe('no HTML parsing of text', () => {
  it('finds the files it looks at', () => {
    expect(FILES.length).toBeGreaterThan(30);
    expect(FILES.some((f) => f.path.endsWith('homework.js'))).toBe(true);
  });

  // Reading a page's own markup (outerHTML, for the code frame's page) parses nothing; writing it does.
  const SINKS = /(?:innerHTML|outerHTML)\s*(?:=(?!=)|\+=)|insertAdjacentHTML|document\.write|createContextualFragment|\.html\(\s*[^)\s]/;

  it('nothing written to innerHTML or outerHTML; no insertAdjacentHTML, document.write or .html(…)', () => {
    expect(find(SINKS)).toEqual([]);
  });

  it('the sink check catches a write and lets a read pass', () => {
    for (const write of ['el.innerHTML = text', 'el.innerHTML += text', 'el.outerHTML=text', "el.insertAdjacentHTML('beforeend', t)", "p.select('#a').html(t)"]) expect(SINKS.test(write), write).toBe(true);
    for (const read of ['const markup = main.outerHTML;', 'if (el.innerHTML === "")']) expect(SINKS.test(read), read).toBe(false);
  });

  it("p5's HTML-setting create* functions get no text, or a plain literal", () => {
    const oneArg = new RegExp(String.raw`\.create(?:P|Div|Span|Button|A|Checkbox)\((?!\s*\)|\s*${LITERAL}\s*[,)])`);
    const tagAndText = new RegExp(String.raw`\.createElement\(\s*${LITERAL}\s*,(?!\s*${LITERAL}\s*\))`);
    expect(find(oneArg)).toEqual([]);
    expect(find(tagAndText)).toEqual([]);
  });

  it('the checks themselves catch what they are for', () => {
    const oneArg = new RegExp(String.raw`\.create(?:P|Div|Span|Button|A|Checkbox)\((?!\s*\)|\s*${LITERAL}\s*[,)])`);
    expect(oneArg.test('p.createP(message)')).toBe(true);
    expect(oneArg.test('p.createP(`got ${x}`)')).toBe(true);
    expect(oneArg.test("p.createDiv('a' + b)")).toBe(true);
    expect(oneArg.test("p.createDiv('<h2>Fixed</h2>')")).toBe(false);
    expect(oneArg.test('p.createP()')).toBe(false);
  });
});

describe('link parameters', () => {
  const READS = /\.(?:get|getAll|has)\(\s*(['"])([^'"]+)\1\s*\)/g;
  const readers = FILES.filter(({ text }) => /URLSearchParams|searchParams|location\.(search|hash)/.test(text));

  it('every parameter the code reads is in the hostile-link list, and the other way round', () => {
    const names = new Set();
    for (const { text } of readers) {
      // Only the .get('x') calls of a parameter object: a Map or a p5 method is not a link.
      for (const m of text.matchAll(READS)) {
        const before = text.slice(Math.max(0, m.index - 160), m.index);
        if (/URLSearchParams|searchParams|params|query|fragment|hash|search/i.test(before)) names.add(m[2]);
      }
    }
    expect([...names].sort()).toEqual(OWN_NAMES);
  });

  it('no parameter is read with a name the test cannot see', () => {
    const hidden = find(/(?:URLSearchParams\([^)]*\)|searchParams|params)\.(?:get|getAll|has)\(\s*(?!['"])/);
    expect(hidden).toEqual([]);
  });
});
