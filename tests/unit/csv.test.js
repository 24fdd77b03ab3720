// The inspector's CSV export: names a spreadsheet would run as formulas are
// written as text, numbers stay numbers, and CR, LF, quotes and commas are
// quoted so rows never split.
import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Camera, inspectPixel } from '../../lib/index.js';
import { pixelCSV, csvCell as inspectorsCell } from '../../lib/p5/pixel/inspector.js';
import { csvCell } from '../../lib/text/csv.js';

/** A tiny CSV reader (RFC 4180): rows of cells. */
function parseCSV(text) {
  const rows = [[]];
  let cell = '', quoted = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (quoted) {
      if (c === '"' && text[i + 1] === '"') { cell += '"'; i++; } else if (c === '"') quoted = false; else cell += c;
    } else if (c === '"') quoted = true;
    else if (c === ',') { rows.at(-1).push(cell); cell = ''; } else if (c === '\n') { rows.at(-1).push(cell); cell = ''; rows.push([]); } else cell += c;
  }
  if (cell !== '' || rows.at(-1).length) rows.at(-1).push(cell);
  if (rows.at(-1).length === 0) rows.pop();
  return rows;
}

describe('csvCell', () => {
  it('writes formula starters as text', () => {
    for (const name of ['=HYPERLINK("http://x","y")', '+1+2', '-2+3', '@SUM(A1)', '\t=1', '\r=1', '=1+1',
      ' =1+1', '\u200B=1+1', '\u202E=1+1', '\uFEFF=1', '＝1+1', '|cmd', '"=1+1', "'=1+1"]) {
      const cell = csvCell(name);
      const text = parseCSV(cell)[0][0];
      expect(text.startsWith("'"), JSON.stringify(name)).toBe(true);
      expect(text.slice(1)).toBe(name);
    }
  });

  it('keeps numbers as numbers, negative ones too', () => {
    for (const n of ['-3.25', '+4', '1e-7', '-0.5', '0', '12', -1.5]) expect(csvCell(n)).toBe(String(n));
  });

  it('quotes quotes, commas, LF and a bare CR', () => {
    expect(csvCell('a"b')).toBe('"a""b"');
    expect(csvCell('a,b')).toBe('"a,b"');
    expect(csvCell('a\nb')).toBe('"a\nb"');
    expect(csvCell('a\rb')).toBe('"a\rb"');
  });

  it('is one function: the inspector hands on lib/text/csv.js\'s, as the class board imports it', () => {
    expect(inspectorsCell).toBe(csvCell);
  });
});

describe('pixelCSV with hostile names', () => {
  it('one row per sphere, whatever the names, and no live formula', () => {
    const names = ['=HYPERLINK("http://evil.example","click")', 'two\rrows', 'three\nrows', '@cmd', '+x', '-y', 'plain, "quoted"'];
    const scene = new Scene();
    names.forEach((name, i) => scene.add(Object.assign(new Sphere([i - 3, 0, -20], 0.4), { name })));
    const camera = new Camera({ width: 32, height: 24 });
    const record = inspectPixel(scene, camera, 16, 12);
    const rows = parseCSV(pixelCSV(record));
    expect(rows).toHaveLength(1 + names.length);
    for (const row of rows) expect(row).toHaveLength(rows[0].length);
    const sphereColumn = rows[0].indexOf('sphere');
    for (const row of rows.slice(1)) expect(row[sphereColumn]).not.toMatch(/^[=+\-@\t\r]/);
    expect(rows.slice(1).map((row) => row[sphereColumn])).toEqual(names.map((n) => (/^[=+\-@]/.test(n) ? `'${n}` : n)));
    expect(rows[1][rows[0].indexOf('B')]).toMatch(/^-?\d/); // numbers untouched
  });
});
