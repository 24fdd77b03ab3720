// The 3D view's parts (lib/p5/scene-view-*.js) do nothing when imported, and
// get what they need passed in: none imports scene-view.js back.
import { it, expect } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';

const DIR = new URL('../../lib/p5/', import.meta.url);
/** The parts with no p5 import (scene-view-draw.js draws with p5 itself). */
const PLAIN = ['scene-view-mesh.js', 'scene-view-flight.js', 'scene-view-labels.js', 'scene-view-input.js', 'scene-view-rays.js', 'scene-view-controls.js', 'scene-view-keys.js'];

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

it('no part of the 3D view imports scene-view.js (no circle of imports)', () => {
  const parts = readdirSync(DIR).filter((f) => /^scene-view-.+\.js$/.test(f));
  expect(parts).toEqual(expect.arrayContaining([...PLAIN, 'scene-view-draw.js']));
  for (const file of parts) {
    const imports = readFileSync(new URL(file, DIR), 'utf8').match(/from '[^']+'/g) ?? [];
    expect(imports, file).not.toContain("from './scene-view.js'");
  }
});
