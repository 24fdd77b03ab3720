// The 3D view's parts (lib/p5/scene-view/*.js) do nothing when imported, and
// get what they need passed in: none imports the view, scene-view/view.js, back.
import { it, expect } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';

const DIR = new URL('../../lib/p5/scene-view/', import.meta.url);
/** The parts with no p5 import (draw.js draws with p5 itself). */
const PLAIN = ['mesh.js', 'flight.js', 'labels.js', 'input.js', 'rays.js', 'controls.js', 'keys.js'];

it('importing the 3D view\'s plain parts touches no page and adds no global', async () => {
  const touched = [];
  const watch = (name) => new Proxy({}, { get: (_, key) => { touched.push(`${name}.${String(key)}`); return undefined; } });
  const before = new Set(Object.keys(globalThis));
  globalThis.document = watch('document');
  globalThis.window = watch('window');
  try {
    for (const file of PLAIN) await import(/* @vite-ignore */ new URL(file, DIR).href);
  } finally {
    delete globalThis.document;
    delete globalThis.window;
  }
  expect(touched).toEqual([]);
  expect(Object.keys(globalThis).filter((key) => !before.has(key))).toEqual([]);
});

it('no part of the 3D view imports the view (no circle of imports)', () => {
  const parts = readdirSync(DIR).filter((f) => f.endsWith('.js') && f !== 'view.js');
  expect(parts).toEqual(expect.arrayContaining([...PLAIN, 'draw.js']));
  for (const file of parts) {
    const imports = readFileSync(new URL(file, DIR), 'utf8').match(/from '[^']+'/g) ?? [];
    expect(imports, file).not.toContain("from './view.js'");
  }
});
