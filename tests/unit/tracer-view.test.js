// The tracer view's modules do nothing when imported: no page touched, no
// global added, no view registered. A view's work (the stylesheet, the
// Projector switch, the page's render state) starts with createTracerView.
import { it, expect } from 'vitest';
import { pageViews } from '../../lib/p5/page/page-state.js';

const MODULES = ['tracer/view.js', 'tracer/layout.js', 'tracer/overlay.js', 'tracer/input.js', 'tracer/export.js', 'tracer/events.js'];

it('importing the tracer view and its parts touches no page, adds no global and registers no view', async () => {
  const touched = [];
  const watch = (name) => new Proxy({}, { get: (_, key) => { touched.push(`${name}.${String(key)}`); return undefined; } });
  const before = new Set(Object.keys(globalThis));
  globalThis.document = watch('document');
  globalThis.window = watch('window');
  try {
    for (const file of MODULES) await import(`../../lib/p5/${file}`);
  } finally {
    delete globalThis.document;
    delete globalThis.window;
  }
  expect(touched).toEqual([]);
  expect(Object.keys(globalThis).filter((key) => !before.has(key))).toEqual([]);
  expect(pageViews()).toEqual([]);
});
