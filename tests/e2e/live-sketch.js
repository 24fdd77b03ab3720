/**
 * A temporary sketch for the live-coding tests: a page and a script built
 * from the README's recipe, written under tests/e2e/pages/ (live-*.html and
 * .js, ignored by git) so a test can save a new version while the page is
 * open, as a teacher does, and removed afterwards.
 */
import { mkdirSync, writeFileSync, rmSync } from 'node:fs';
import { resolve } from 'node:path';
import { expect } from '@playwright/test';

/** The README's page recipe, for tests/e2e/pages/<slug>.js; `main` what the page's main holds (nothing: the sketch makes it all). */
function page(slug, main = '') {
  return `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <meta name="viewport" content="width=device-width, initial-scale=1">
  <link rel="icon" href="data:,">
  <title>99 · Live coding</title>
  <meta name="description" content="A sketch a test edits while the page is open.">
  <link rel="stylesheet" href="../../../sketches/sketch.css">
</head>
<body class="live-coding">
  <header><h1>99 · Live coding</h1></header>
  <main id="sketch" class="rt-layout">${main}</main>
  <script type="module" src="./${slug}.js"></script>
</body>
</html>
`;
}

/**
 * The README's sketch, with pieces swapped in: `sphere` (the Sphere line),
 * `before` (lines at the start of setup), `after` (lines at the end of setup),
 * `top` (lines after the imports), `draw` (the body of draw()).
 */
export function sketchSource({ sphere = 'new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] })', before = '', after = '', top = '', draw = '' } = {}) {
  return `import p5 from 'p5';
import { Scene, Sphere, PointLight, Camera } from '../../../lib/index.js';
import '../../../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …
${top}
new p5((p) => {
  let view;
  p.setup = () => {
    p.noCanvas();
${before}
    const scene = new Scene({ background: [0.85, 0.92, 1] })
      .add(${sphere})
      .add(new PointLight([-10, 20, 0]));
    view = p.createTracerView({ scene, camera: new Camera({ width: 64, height: 48 }), grid: true });
    p.createInspector({ view }); // click a pixel: its whole story
${after}
  };
  p.draw = () => {
${draw}
  };
}, 'sketch');
`;
}

/** The 1-based number of the first line of `source` holding `text`. */
export function lineOf(source, text) {
  const index = source.split('\n').findIndex((line) => line.includes(text));
  if (index < 0) throw new Error(`no line holds ${text}`);
  return index + 1;
}

/**
 * Writes tests/e2e/pages/<slug>.html and .js; returns the page's URL and helpers.
 * @param {{ main?: string, folder?: string }} [options] `main`: markup inside the page's main (a column the sketch draws into);
 * `folder`: another folder three levels down (the class server does not serve tests/)
 */
export function liveSketch(slug, source, { main = '', folder = 'tests/e2e/pages' } = {}) {
  const dir = resolve(folder);
  mkdirSync(dir, { recursive: true });
  writeFileSync(resolve(dir, `${slug}.html`), page(slug, main));
  writeFileSync(resolve(dir, `${slug}.js`), source);
  return {
    url: `/${folder}/${slug}.html`,
    file: `${folder}/${slug}.js`,
    /** Saves a new version of the script, as an editor does. */
    save: (text) => writeFileSync(resolve(dir, `${slug}.js`), text),
    /** Saves as an editor whose save reaches the disk in two steps: the file emptied (or written as `first`, a formatter's input), then written `gapMs` later. */
    saveInTwoSteps: async (text, gapMs, first = '') => {
      writeFileSync(resolve(dir, `${slug}.js`), first);
      await new Promise((done) => setTimeout(done, gapMs));
      writeFileSync(resolve(dir, `${slug}.js`), text);
    },
    remove: () => {
      rmSync(resolve(dir, `${slug}.js`), { force: true });
      rmSync(resolve(dir, `${slug}.html`), { force: true });
    },
  };
}

/**
 * Saves `text` as the sketch and waits for the page to take it: a swap in
 * place (lib/p5/page/hot-swap.js counts them in window.__sketchbookSwaps) or a
 * reload. An editor's save can reach the file watcher as two changes, so a
 * second update may follow the first; it returns once none came for
 * `quietMs`. Returns how the page took the save: 'swap' or 'reload'.
 */
export async function saveAndWaitForUpdate(page, sketch, text, quietMs = 800) {
  let loads = 0;
  const count = () => { loads += 1; };
  const reasons = []; // hot-swap.js says why it reloads; none said: Vite's own full reload
  const said = (message) => { if (message.text().startsWith('Reloading the page')) reasons.push(message.text()); };
  page.on('console', said);
  const swaps = () => page.evaluate(() => window.__sketchbookSwaps ?? 0).catch(() => -1); // -1: the page is going away
  page.on('load', count);
  try {
    const before = await swaps();
    sketch.save(text);
    let now = before;
    await expect.poll(async () => { now = await swaps(); return loads > 0 || now > before; }, { timeout: 15_000 }).toBe(true);
    for (let seen = ''; seen !== `${loads}:${now}`;) {
      seen = `${loads}:${now}`;
      await page.waitForTimeout(quietMs);
      now = await swaps();
    }
    if (loads > 0) console.log(`${sketch.file}: the save reloaded the page (${reasons.join(' ') || 'no reason said by hot-swap.js: a full reload from the server'})`); // for a run that expected a swap
    return loads > 0 ? 'reload' : 'swap';
  } finally {
    page.off('load', count);
    page.off('console', said);
  }
}
