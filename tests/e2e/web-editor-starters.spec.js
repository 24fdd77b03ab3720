// Every global-mode starter the web-editor page offers, run as the p5 web
// editor runs it: each .js file of the sketch through the editor's loop
// protection (editor-rewrite.js; the one-file build passes as it is, for its
// `// noprotect` line), with p5 2.x and with p5 1.11, from a plain static
// server. The picture traces whole, a click inspects, no loop was cut short
// (window.loopProtect.hit never called) and the console stays quiet; the
// homework starters fail their self-check as given and pass with the
// reference solution's lights. And without the `// noprotect` line the
// editor could not even print the bundle again.
import { test, expect } from '@playwright/test';
import { mkdtempSync, readFileSync, rmSync, writeFileSync, copyFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { clickPixel, waitForDone, watchConsole } from './helpers.js';
import { buildOneFile, serveFolder } from './static-folder.js';
import { protectLoops, hasNoProtect } from './editor-rewrite.js';

test.describe.configure({ mode: 'default' }); // one build and one server for the file

/** The starters the web-editor page shows (its `<!-- text of examples/web-editor/….js -->` lines). */
const STARTERS = [...readFileSync('web-editor.html', 'utf8').matchAll(/<!-- text of examples\/web-editor\/([\w-]+)\.js -->/g)].map((m) => m[1]);
/** The p5s a class may have: 2.x, and 1.11 minified and whole (p5.js: its friendly errors on, as the editor's templates often load it). */
const P5S = {
  '2.x': { file: 'node_modules/p5/lib/p5.min.js', version: /^2\./ },
  '1.11': { file: 'node_modules/p5-v1/lib/p5.min.js', version: /^1\.11\./ },
  '1.11-p5.js': { file: 'node_modules/p5-v1/lib/p5.js', version: /^1\.11\./ },
  // The editor's 1.x template loads p5.sound too: its names (record, …) are reserved for the friendly errors then.
  '1.11-p5.js-sound': { file: 'node_modules/p5-v1/lib/p5.js', sound: 'node_modules/p5-v1/lib/addons/p5.sound.js', version: /^1\.11\./ },
};
const HOMEWORK = {
  'homework-traffic-signal': { solution: 'sketches/solutions/08-traffic-signal.js' },
  'homework-rear-lights': { solution: 'sketches/solutions/09-rear-lights.js' },
};

/** The editor's loopProtect, which logs a warning when it cuts a loop short; here it also counts. */
const LOOP_PROTECT = `<script>window.loopHits = []; window.loopProtect = { hit(line) { loopHits.push(line); console.warn('Exiting potential infinite loop at line ' + line); } };</script>`;

/** examples/web-editor/index.html with this p5 (and p5.sound), this sketch, and the editor's loopProtect before everything. */
function page(p5File, sketchFile, soundFile) {
  const sound = soundFile ? `\n    <script src="${soundFile}"></script>` : '';
  return readFileSync('examples/web-editor/index.html', 'utf8')
    .replace('<script src="p5.min.js"></script>', `${LOOP_PROTECT}\n    <script src="${p5File}"></script>${sound}`)
    .replace('<script src="sketch.js"></script>', `<script src="${sketchFile}"></script>`);
}

/**
 * A homework starter with the reference solution's lights: the solution's
 * addLights and its constants, in global mode's names (RT.Sphere).
 */
function withSolution(starter, solutionFile) {
  const solution = readFileSync(solutionFile, 'utf8').replace(/^import .*\n/m, '').replace(/new Sphere\(/g, 'new RT.Sphere(').replace(/^export /gm, '');
  const yours = /function addLights\(scene\) \{\n[^}]*\}\n/;
  if (!yours.test(starter)) throw new Error('the homework starter has no addLights(scene) { … } to replace');
  return starter.replace(yours, solution);
}

let folder, server;
const rewrites = {}; // file → what the editor's rewrite did to it

test.beforeAll(async () => {
  folder = mkdtempSync(join(tmpdir(), 'rt-web-editor-starters-'));
  buildOneFile(folder);
  const served = (name, code) => {
    const rewritten = protectLoops(code);
    rewrites[name] = rewritten;
    writeFileSync(join(folder, name), rewritten.code); // what the editor's preview runs
  };
  served('raytracing-sketchbook.js', readFileSync(join(folder, 'raytracing-sketchbook.js'), 'utf8'));
  for (const name of STARTERS) served(`${name}.js`, readFileSync(`examples/web-editor/${name}.js`, 'utf8'));
  for (const [name, { solution }] of Object.entries(HOMEWORK)) {
    served(`${name}-solved.js`, withSolution(readFileSync(`examples/web-editor/${name}.js`, 'utf8'), solution));
  }
  for (const [version, { file, sound }] of Object.entries(P5S)) {
    copyFileSync(file, join(folder, `p5-${version}.js`));
    if (sound) copyFileSync(sound, join(folder, `p5.sound-${version}.js`));
    for (const name of [...STARTERS, ...Object.keys(HOMEWORK).map((n) => `${n}-solved`)]) {
      writeFileSync(join(folder, `${name}-p5-${version}.html`), page(`p5-${version}.js`, `${name}.js`, sound && `p5.sound-${version}.js`));
    }
  }
  server = await serveFolder(folder);
});

test.afterAll(async () => {
  await server?.close();
  if (folder) rmSync(folder, { recursive: true, force: true });
});

test('the page offers the starters this file runs', () => {
  expect(STARTERS).toEqual(['sketch', 'diagrams', 'animation', 'gpu', 'homework-traffic-signal', 'homework-rear-lights']);
});

test('the one-file build passes the editor\'s rewrite untouched (its // noprotect line); the starters go through it', () => {
  const bundle = readFileSync(join(folder, 'raytracing-sketchbook.js'), 'utf8');
  expect(bundle.split('\n', 1)[0]).toMatch(/^\/\/ noprotect\b/); // a line comment, first line of the file
  expect(rewrites['raytracing-sketchbook.js'].skipped).toBe(true);
  for (const name of STARTERS) expect(rewrites[`${name}.js`], name).toMatchObject({ skipped: false });
  // The starters have no loop that could run 100 ms: none at all.
  expect(STARTERS.map((name) => rewrites[`${name}.js`].loops)).toEqual(STARTERS.map(() => 0));
});

test('without the // noprotect line, the editor cannot print the bundle again: the preview would not start', () => {
  const bundle = readFileSync(join(folder, 'raytracing-sketchbook.js'), 'utf8');
  const unprotected = bundle.split('\n').filter((line) => !/^\/\/ noprotect\b|^\/\/ leaving pictures traced part-way/.test(line)).join('\n');
  expect(hasNoProtect(unprotected)).toBe(false);
  // The rewrite parses it and finds its loops, then escodegen stops on modern syntax (class members).
  expect(() => protectLoops(unprotected)).toThrow('this[type] is not a function');
});

test('the rewrite does what the editor does to a loop: a 100 ms time check that breaks out, calling loopProtect.hit(line)', () => {
  const { code, loops } = protectLoops('function spin() {\n  let n = 0;\n  while (true) n++;\n  return n;\n}');
  expect(loops).toBe(1);
  expect(code).toContain('var _LP0 = Date.now();');
  expect(code).toMatch(/while \(true\) \{\s*if \(Date\.now\(\) - _LP0 > 100\) \{\s*window\.loopProtect\.hit\(3\);\s*break;\s*\}\s*n\+\+;\s*\}/);
  const hits = [];
  const spin = new Function('window', `${code}; return spin();`);
  expect(spin({ loopProtect: { hit: (line) => hits.push(line) } })).toBeGreaterThan(0); // it ended: the check broke out
  expect(hits).toEqual([3]);
});

/** The console's lines, without p5.sound's own banner (Tone.js prints its version when it loads). */
const ours = (lines, version) => (P5S[version].sound ? lines.filter((line) => !/^log: %c \* Tone\.js r\d+ \* /.test(line)) : lines);

/** Every pixel of the tracer view's canvas written (a pixel not traced yet is transparent). */
function unwrittenPixels(canvas) {
  return canvas.evaluate((c) => {
    const { data } = c.getContext('2d').getImageData(0, 0, c.width, c.height);
    let missing = 0;
    for (let i = 3; i < data.length; i += 4) if (data[i] !== 255) missing++;
    return missing;
  });
}

/** Opens a starter page, waits for a whole picture (the animation: paused first), clicks a pixel: the inspector's line. */
async function traceAndInspect(page, name, version) {
  await page.goto(`${server.origin}/${name}-p5-${version}.html`);
  if (name === 'animation') {
    await expect(page.locator('[data-tracer]').locator('xpath=ancestor::figure')).toContainText(/frame ([3-9]|\d\d+)\b/, { timeout: 20_000 });
    await page.getByRole('button', { name: 'Pause' }).click();
  }
  await waitForDone(page);
  const canvas = page.locator('[data-tracer]');
  expect(await unwrittenPixels(canvas), 'pixels the frame left unwritten').toBe(0);
  await clickPixel(canvas, 20, 18);
  await expect(page.locator('[data-inspector]')).toContainText(/Pixel: 20,18; H: -?\d+\.\d; V: -?\d+\.\d/);
  return canvas;
}

for (const version of Object.keys(P5S)) {
  test.describe(`with p5 ${version}`, () => {
    for (const name of STARTERS) {
      test(`${name}: rewritten as the editor does, it traces a whole frame, a click inspects, no loop cut short, a quiet console`, async ({ page }) => {
        const errors = watchConsole(page);
        await traceAndInspect(page, name, version);
        expect(await page.evaluate(() => p5.VERSION)).toMatch(P5S[version].version);

        if (name === 'diagrams') {
          // The diagrams drew into the sketch's own canvas; the 3D view follows the selected pixel.
          expect(await page.evaluate(() => {
            const c = document.querySelector('canvas.p5Canvas:not([data-view3d])');
            const { data } = c.getContext('2d').getImageData(0, 0, c.width, c.height);
            const colours = new Set();
            for (let i = 0; i < data.length; i += 4 * 97) colours.add(data[i] << 16 | data[i + 1] << 8 | data[i + 2]);
            return colours.size;
          })).toBeGreaterThan(20);
          const view3d = page.locator('[data-view3d]');
          await expect(view3d).toHaveAttribute('data-selected', '20,18');
          await expect(view3d).toHaveAttribute('data-state', 'done');
          const { data } = PNG.sync.read(await view3d.screenshot()); // WebGL: read what the screen shows
          const colours = new Set();
          for (let i = 0; i < data.length; i += 4 * 89) colours.add(data[i] << 16 | data[i + 1] << 8 | data[i + 2]);
          expect(colours.size, 'colours in the 3D view').toBeGreaterThan(20);
        }
        if (name === 'gpu') await expect(page.locator('[data-tracer]')).toHaveAttribute('data-engine', 'gpu'); // the GPU engine is in the one file, on either p5
        if (HOMEWORK[name]) {
          // As given: the check fails on the lights, its hint in global mode's names, its list styled.
          await page.getByRole('button', { name: 'Check my scene' }).click();
          const results = page.locator('[data-check-results]');
          await expect(results).toHaveAttribute('data-check', 'not-yet');
          await expect(results.locator('[data-check-item="failed"]').first()).toContainText('new RT.Sphere([0, 1, -10], 0.5,');
          expect(await results.locator('.hw-checks').evaluate((ul) => getComputedStyle(ul).listStyleType)).toBe('none');
          expect(await results.locator('.hw-failed .hw-mark').first().evaluate((m) => getComputedStyle(m).color)).toBe('rgb(196, 50, 27)');
        }
        expect(await page.evaluate(() => window.loopHits)).toEqual([]);
        expect(ours(errors, version)).toEqual([]);
      });
    }

    for (const name of Object.keys(HOMEWORK)) {
      test(`${name} with the reference solution's lights passes its self-check`, async ({ page }) => {
        const errors = watchConsole(page);
        await traceAndInspect(page, `${name}-solved`, version);
        await page.getByRole('button', { name: 'Check my scene' }).click();
        const results = page.locator('[data-check-results]');
        await expect(results).toHaveAttribute('data-check', 'passed');
        await expect(results.locator('.hw-headline')).toHaveText('Passed! Your scene does what the task asks.');
        expect(await page.evaluate(() => window.loopHits)).toEqual([]);
        expect(ours(errors, version)).toEqual([]);
      });
    }
  });
}
