// The API reference (scripts/api-reference.js, built into dist/api/): it names
// every public export of the two entry points and every p5 method of the
// addon, most with an example; the library's examples run as written; and
// every lesson page's "API:" line names only what the reference documents.
import { describe, it, expect, beforeAll } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';
import * as library from '../../lib/index.js';
import { collectAPI, apiReferenceHTML, namesUsedBy, factoryNames } from '../../scripts/api-reference.js';

/** The names a module exports, read from its text (lib/p5/index.js imports p5, which needs a browser). */
function exportedNames(file) {
  const source = readFileSync(file, 'utf8');
  const names = [];
  for (const [, list] of source.matchAll(/export\s*\{([^}]*)\}/g)) {
    names.push(...list.split(',').map((part) => part.trim().split(/\s+as\s+/).pop()).filter(Boolean));
  }
  for (const [, name] of source.matchAll(/export\s+\*\s+as\s+(\w+)/g)) names.push(name);
  for (const [, name] of source.matchAll(/export\s+(?:async\s+)?(?:function\*?|class|const|let)\s+(\w+)/g)) names.push(name);
  return names;
}

let api, html;
beforeAll(() => {
  api = collectAPI();
  html = apiReferenceHTML();
}, 120_000);

describe('the API reference', () => {
  it('names every export of lib/index.js and lib/p5/index.js, each with an entry of its own', () => {
    const publicNames = [...Object.keys(library), ...exportedNames('lib/p5/index.js')];
    expect(publicNames.length).toBeGreaterThan(10);
    for (const name of publicNames) expect(html, name).toContain(`<section class="item" id="${name}">`);
  });

  it('names every p5 method the addon adds, with its options', () => {
    const methods = factoryNames();
    expect([...methods]).toEqual(api.methods.map((m) => m.name));
    for (const name of methods) expect(html, name).toContain(`<section class="item" id="${name}">`);
    const tracerView = api.methods.find((m) => m.name === 'createTracerView');
    if (tracerView) {
      const options = tracerView.doc.params.map((p) => p.name);
      for (const option of ['options.scene', 'options.camera', 'options.scale', 'options.budgetMs', 'options.parent', 'options.label', 'options.legend']) {
        expect(options).toContain(option);
      }
      expect(tracerView.doc.params.find((p) => p.name === 'options.budgetMs')).toMatchObject({ type: 'number', optional: true, defaultValue: '8' });
    }
  });

  it('gives most names a short example', () => {
    const items = [...api.entries.flatMap((e) => e.items), ...api.methods];
    const without = items.filter((item) => item.doc.examples.length === 0).map((item) => item.name);
    expect(without.length, `no example: ${without.join(', ')}`).toBeLessThanOrEqual(items.length / 3);
  });

  it("runs the library's examples as written, with the library's names in scope", () => {
    const examples = api.entries.find((e) => e.id === 'library').items.flatMap((item) => item.doc.examples.map((code) => [item.name, code]));
    expect(examples.length).toBeGreaterThan(5);
    for (const [name, code] of examples) {
      const run = new Function(...Object.keys(library), code);
      expect(() => run(...Object.values(library)), `the example of ${name}`).not.toThrow();
    }
  });

  it('says what each of the course\'s later names is in the lesson, from its module\'s opening comment when it has none of its own', () => {
    const library = api.entries.find((e) => e.id === 'library').items;
    const text = (name) => (library.find((i) => i.name === name) ?? api.methods.find((m) => m.name === name)).doc.text;
    expect(text('Cylinder')).toContain('A = Xd² + Zd², not 1');
    expect(text('Cone')).toContain('A = Xd² + Zd² − k²·Yd²');
    expect(text('Triangle')).toContain('Möller and Trumbore');
    expect(text('Mesh')).toContain('bounding');
    expect(text('AreaLight')).toContain('penumbra');
    expect(text('SpotLight')).toContain('cone');
    expect(text('createSampleRays')).toMatch(/^The selected pixel's rays/);
    expect(library.find((i) => i.name === 'Camera').doc.params.map((p) => p.name)).toContain('options.samples');
    expect(library.find((i) => i.name === 'Mesh').members.find((m) => m.name === 'fromOBJ').doc.text).toContain('OBJ');
    // a comment's indented code sample is shown as code, not run together into a paragraph
    expect(html).toContain('<pre class="aside" tabindex="0" role="region" aria-label="Code in the description of createSampleRays"><code>const view = p.createTracerView(');
  });

  it("links each lesson page's names: its API line names only what the reference documents", () => {
    const documented = new Set([...api.entries.flatMap((e) => e.items.map((i) => i.name)), ...api.methods.map((m) => m.name)]);
    const sketches = readdirSync('sketches').filter((f) => /^\d\d-.*\.js$/.test(f));
    for (const file of sketches) {
      const names = namesUsedBy(readFileSync(`sketches/${file}`, 'utf8'));
      expect(names.length, file).toBeGreaterThan(0);
      for (const name of names) expect(documented.has(name), `${file} uses ${name}`).toBe(true);
    }
  });
});
