// The one-file build, run the way the p5 web editor runs a sketch: a plain
// index.html with p5's own <script>, raytracing-sketchbook.js after it and a
// global-mode sketch.js (the files of examples/web-editor/), served by a plain
// static server and opened from file://. The picture traces, a click
// inspects, the render worker runs from inside the one file, the console
// stays quiet, and both ways give the same picture. So does the ES module
// build, raytracing-sketchbook.mjs, on a page that maps 'p5' to p5's own ES
// module with an import map.
// Then the gallery's page that teaches it shows those same files, and the
// gallery and the lesson pages link into the API reference.
import { test, expect } from '@playwright/test';
import { copyFileSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import vm from 'node:vm';
import { clickPixel, expectCanvasScreenshot, waitForDone, watchConsole } from './helpers.js';
import { buildOneFile, readStoredZip, serveFolder } from './static-folder.js';
import { FOLDER, ZIP_NAME, writeReadyFolder } from '../../scripts/ready-folder.js';

// One build and one server for the file's tests, in order, in one worker.
test.describe.configure({ mode: 'default' });

let folder, server, origin;

/** The starter of examples/web-editor/ in instance mode, importing the ES module build; 'p5' is p5's own ES module. */
const MODULE_PAGE = `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <link rel="icon" href="data:,">
  <title>Raytracing Sketchbook as an ES module</title>
  <script type="importmap">{ "imports": { "p5": "./p5.esm.js" } }</script>
</head>
<body>
  <main></main>
  <script type="module">
    import p5 from 'p5';
    import { Scene, Sphere, PointLight, Camera, ParallelRenderer, classScene, render } from './raytracing-sketchbook.mjs';
    window.RT = { ParallelRenderer, Camera, classScene, render };
    new p5((p) => {
      p.setup = () => {
        p.noCanvas();
        const scene = new Scene({ background: [0.85, 0.92, 1], ambient: 0.1 });
        scene.add(new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] }));
        scene.add(new Sphere([6, 1, -26], 2, { color: [0.3, 0.6, 1] }));
        scene.add(new PointLight([-10, 20, 0]));
        const view = p.createTracerView({ scene, camera: new Camera({ width: 64, height: 48, fov: 30 }), grid: true });
        p.createInspector({ view });
      };
    });
  </script>
</body>
</html>
`;

test.beforeAll(async () => {
  folder = mkdtempSync(join(tmpdir(), 'rt-web-editor-'));
  buildOneFile(folder);
  copyFileSync('node_modules/p5/lib/p5.min.js', join(folder, 'p5.min.js'));
  for (const file of ['index.html', 'sketch.js']) copyFileSync(join('examples/web-editor', file), join(folder, file));
  writeFileSync(join(folder, 'no-p5.html'), '<!doctype html><meta charset="utf-8"><link rel="icon" href="data:,"><script src="raytracing-sketchbook.js"></script>');
  // p5 1.9 as far as the one file can tell (its VERSION; 1.x has registerMethod, not registerAddon).
  const oldP5 = '<script>function p5() {} p5.VERSION = "1.9.4"; p5.prototype.registerMethod = function () {};</script>';
  writeFileSync(join(folder, 'old-p5.html'), `<!doctype html><meta charset="utf-8"><link rel="icon" href="data:,">${oldP5}<script src="raytracing-sketchbook.js"></script>`);
  copyFileSync('node_modules/p5/lib/p5.esm.js', join(folder, 'p5.esm.js'));
  writeFileSync(join(folder, 'module.html'), MODULE_PAGE);
  writeReadyFolder(folder); // what npm run build writes after the one-file builds: web-editor/ and its .zip

  server = await serveFolder(folder);
  origin = server.origin;
});

/** Two render workers started from inside the built file (the page's `RT`): did they give render()'s bytes, with no fallback? */
function twoWorkersRender(page) {
  return page.evaluate(async () => {
    const scene = RT.classScene(), camera = new RT.Camera({ width: 40, height: 30 });
    const renderer = new RT.ParallelRenderer({ workers: 2 });
    const frame = await renderer.render(scene, camera);
    const one = RT.render(scene, camera);
    renderer.terminate();
    return { problem: renderer.problem && String(renderer.problem.message ?? renderer.problem), same: frame.every((v, i) => v === one[i]) };
  });
}

test.afterAll(async () => {
  await server?.close();
  if (folder) rmSync(folder, { recursive: true, force: true });
});

test('the build is one classic script: no import, no export, no import.meta; it defines RT', () => {
  const code = readFileSync(join(folder, 'raytracing-sketchbook.js'), 'utf8');
  expect(() => new vm.Script(code)).not.toThrow(); // a classic script: import, export and import.meta are syntax errors in one
  expect(code).toMatch(/^var RT = /m);
  const esm = readFileSync(join(folder, 'raytracing-sketchbook.mjs'), 'utf8');
  expect(esm).toMatch(/^import \w+ from "p5";/m);
  expect(esm).not.toMatch(/import\.meta/);
});

for (const how of ['http', 'file']) {
  test(`over ${how}: the starter traces, a click inspects, the console stays quiet`, async ({ page }) => {
    const errors = watchConsole(page);
    const requests = [];
    page.on('request', (request) => requests.push(request.url()));
    await page.goto(how === 'http' ? `${origin}/index.html` : pathToFileURL(join(folder, 'index.html')).href);
    await waitForDone(page);

    expect(await page.evaluate(() => [typeof RT.Scene, typeof RT.classScene, typeof createTracerView, typeof createInspector]))
      .toEqual(['function', 'function', 'function', 'function']);
    const canvas = page.locator('[data-tracer]');
    await expect(canvas).toHaveAttribute('data-width', '64');
    await expect(canvas).toHaveAttribute('data-height', '48');
    // The reference picture: the web-editor starter's 64×48 view, a pink sphere lit from the upper
    // left with a blue one behind it on a pale-blue sky, at 10 screen pixels per traced pixel.
    // Both ways (http and file://) must give exactly this picture.
    await expectCanvasScreenshot(canvas, 'web-editor-starter.png');

    await clickPixel(canvas, 30, 22);
    const inspector = page.locator('[data-inspector]');
    await expect(inspector).toContainText(/Pixel: 30,22; H: -?\d+\.\d; V: -?\d+\.\d/);
    await expect(inspector).toContainText('B² − 4AC');
    await expect(inspector).toContainText('two hits');
    await page.keyboard.press('ArrowRight');
    await expect(inspector).toContainText('Pixel: 31,22;');

    // The render worker is inside the one file too: two workers make render()'s bytes, with no fallback.
    expect(await twoWorkersRender(page)).toEqual({ problem: null, same: true });

    const base = how === 'http' ? origin : pathToFileURL(folder).href;
    expect(requests.filter((url) => !url.startsWith(base) && !url.startsWith('data:') && !url.startsWith('blob:'))).toEqual([]);
    expect(errors).toEqual([]);
  });
}

test('the ready folder (npm run build\'s dist/web-editor/), opened from file:// by double-click, traces and inspects; the .zip holds it', async ({ page }) => {
  const ready = join(folder, FOLDER);
  const files = ['index.html', 'sketch.js', 'p5.min.js', 'raytracing-sketchbook.js'];
  const zipped = readStoredZip(readFileSync(join(folder, ZIP_NAME)));
  expect(zipped.map((f) => f.name)).toEqual(files.map((name) => `raytracing-sketchbook/${name}`));
  zipped.forEach((f, i) => expect(Buffer.compare(f.data, readFileSync(join(ready, files[i]))), f.name).toBe(0));
  expect(readFileSync(join(ready, 'sketch.js'), 'utf8')).toBe(readFileSync('examples/web-editor/sketch.js', 'utf8'));

  const errors = watchConsole(page);
  await page.goto(pathToFileURL(join(ready, 'index.html')).href);
  await waitForDone(page);
  const canvas = page.locator('[data-tracer]');
  await expectCanvasScreenshot(canvas, 'web-editor-starter.png'); // the starter's picture, as above
  await clickPixel(canvas, 30, 22);
  await expect(page.locator('[data-inspector]')).toContainText(/Pixel: 30,22; H: -?\d+\.\d; V: -?\d+\.\d/);
  await expect(page.locator('[data-inspector]')).toContainText('two hits');
  expect(errors).toEqual([]);
});

test('as an ES module (import map: p5 → p5.esm.js): the starter traces the same picture, a click inspects, workers run', async ({ page }) => {
  const errors = watchConsole(page);
  const requests = [];
  page.on('request', (request) => requests.push(request.url()));
  await page.goto(`${origin}/module.html`);
  await waitForDone(page);
  const canvas = page.locator('[data-tracer]');
  await expectCanvasScreenshot(canvas, 'web-editor-starter.png'); // the classic build's picture, above
  await clickPixel(canvas, 30, 22);
  await expect(page.locator('[data-inspector]')).toContainText(/Pixel: 30,22; H: -?\d+\.\d; V: -?\d+\.\d/);
  expect(await twoWorkersRender(page)).toEqual({ problem: null, same: true });
  expect(requests.filter((url) => !url.startsWith(origin) && !url.startsWith('data:') && !url.startsWith('blob:'))).toEqual([]);
  expect(errors).toEqual([]);
});

for (const [file, found] of [['no-p5.html', 'this page has no p5'], ['old-p5.html', 'this page has p5 1.9.4']]) {
  test(`loaded with ${found.replace('this page has ', '')} before it, the one file says what to change: in the console and on the page`, async ({ page }) => {
    const errors = [];
    page.on('pageerror', (error) => errors.push(error.message));
    await page.goto(`${origin}/${file}`);
    const message = `raytracing-sketchbook.js needs p5.js 1.11 or 2.x loaded before it: put p5's own <script> first (${found})`;
    expect(errors).toEqual([message]);
    await expect(page.locator('[data-error]')).toHaveText(message);
    await expect(page.locator('[data-error]')).toHaveAttribute('role', 'alert');
    expect(await page.evaluate(() => 'needP5' in window)).toBe(false); // the check leaves no global behind
  });
}

test('the gallery\'s web-editor page shows the steps with the very files tested above', { tag: '@dev-server' }, async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/');
  await page.getByRole('link', { name: 'Use it in the p5 web editor' }).first().click();
  await expect(page).toHaveURL(/web-editor\.html$/);
  await expect(page.locator('#starter')).toHaveText(readFileSync('examples/web-editor/sketch.js', 'utf8'));
  await expect(page.locator('#page')).toHaveText(readFileSync('examples/web-editor/index.html', 'utf8'));
  await expect(page.locator('#script-line')).toHaveText('<script src="raytracing-sketchbook.js"></script>');
  const download = await page.request.get(await page.locator('#download').getAttribute('href', { timeout: 1000 }).then((href) => new URL(href, page.url()).href));
  expect(download.ok()).toBe(true);
  expect(await download.text()).toMatch(/^var RT = /m);
  // Every starter on the page is its file of examples/web-editor/ (web-editor-starters.spec.js runs them), each with its copy button.
  for (const name of ['diagrams', 'animation', 'homework-traffic-signal', 'homework-rear-lights']) {
    await expect(page.locator(`#starter-${name}`)).toHaveText(readFileSync(`examples/web-editor/${name}.js`, 'utf8'));
    await expect(page.locator(`button[data-copy="starter-${name}"]`)).toHaveCount(1);
  }
  await expect(page.locator('#noprotect')).toContainText('// noprotect');
  // The ready folder as one .zip: the four files, the one-file build made by the dev server just now.
  const zipped = await page.request.get(new URL(await page.locator('#ready-zip').getAttribute('href'), page.url()).href);
  expect(zipped.ok()).toBe(true);
  expect(zipped.headers()['content-type']).toBe('application/zip');
  const files = readStoredZip(await zipped.body());
  expect(files.map((f) => f.name)).toEqual(['index.html', 'sketch.js', 'p5.min.js', 'raytracing-sketchbook.js'].map((name) => `raytracing-sketchbook/${name}`));
  expect(files[3].data.toString('utf8')).toMatch(/^\/\/ noprotect\b/);
  expect(errors).toEqual([]);
});

test('the gallery links the API reference, and a lesson page links the names its sketch uses', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/');
  await page.getByRole('link', { name: 'API reference' }).first().click();
  await expect(page).toHaveURL(/\/api\/$/);
  await expect(page.locator('h1')).toHaveText('API reference');
  for (const name of ['Scene', 'Sphere', 'Camera', 'render', 'createTracerView', 'createInspector']) {
    await expect(page.locator(`section.item[id="${name}"]`)).toHaveCount(1);
  }
  await page.goto('/sketches/10-playground.html');
  const line = page.locator('.api-line');
  await expect(line).toContainText('API: Scene, Sphere, PointLight, Camera, createTracerView, createInspector');
  await line.getByRole('link', { name: 'createTracerView' }).click();
  await expect(page).toHaveURL(/\/api\/#createTracerView$/);
  await expect(page.locator('#createTracerView')).toContainText('budgetMs');
  expect(errors).toEqual([]);
});
