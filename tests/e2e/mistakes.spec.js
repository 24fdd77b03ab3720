/**
 * The mistake on the page: a sketch built from the README's recipe, with one
 * kind of mistake each, shows the panel [data-error] with the message and the
 * sketch's own file:line (the console keeps the error too); after a fix is
 * saved (swapped in place or reloaded), the panel is gone and the picture traced.
 */
import { test, expect } from '@playwright/test';
import { writeFileSync, rmSync } from 'node:fs';
import { waitForDone, clickPixel } from './helpers.js';
import { liveSketch, sketchSource, lineOf, saveAndWaitForUpdate } from './live-sketch.js';

const FIXED = sketchSource();

/** Each mistake: the sketch, the text its line holds, what the panel must say. */
const MISTAKES = [
  {
    name: 'a radius given as a string',
    source: sketchSource({ sphere: 'new Sphere([0, 0, -20], "4", { color: [1, 0.32, 0.36] })' }),
    line: '"4"',
    message: 'TypeError: radius must be a finite number, got "4"',
  },
  {
    name: 'a NaN centre',
    source: sketchSource({ top: 'const DEPTH = -20 * undefined;', sphere: 'new Sphere([0, 0, DEPTH], 4)' }),
    line: 'new Sphere([0, 0, DEPTH]',
    message: 'TypeError: center.z must be a finite number, got NaN',
  },
  {
    name: 'a call to a function that does not exist',
    source: sketchSource({ before: '    makeSky(scene);' }),
    line: 'makeSky(',
    message: 'ReferenceError: makeSky is not defined',
  },
  {
    name: 'a misspelt option',
    source: sketchSource({ sphere: 'new Sphere([0, 0, -20], 4, { colour: [1, 0.32, 0.36] })' }),
    line: 'colour',
    message: 'TypeError: unknown material option "colour" (did you mean "color"?)',
  },
  {
    name: 'a throw in draw, after a good picture',
    source: sketchSource({ draw: "    if (document.body.dataset.render === 'done') view.setCamera(new Camera({ width: 64, hieght: 48 }));" }),
    line: 'hieght',
    message: 'TypeError: unknown camera option "hieght" (did you mean "height"?)',
    picture: true,
  },
  {
    name: 'a throw in a click handler',
    source: sketchSource({ after: "    p.createButton('Dimmer').id('dimmer').mousePressed(() => scene.add(new PointLight([0, 9, 0], { intensity: -1 })));" }),
    line: 'intensity: -1',
    message: 'RangeError: intensity must not be negative, got -1',
    act: (page) => page.locator('#dimmer').click(),
    picture: true,
  },
  {
    name: 'a throw in a promise',
    source: sketchSource({ after: "    new Promise((resolve) => setTimeout(resolve, 100)).then(() => view.setMode('discriminat'));" }),
    line: "'discriminat'",
    message: "RangeError: mode must be one of 'shaded', 'discriminant', 'roots', 'h', 'v', 'normals', 'depth', got 'discriminat'",
    picture: true,
  },
  {
    name: 'a mistake at the top of the file',
    source: sketchSource({ top: 'const SIZE = WIDHT * 2;' }),
    line: 'WIDHT',
    message: 'ReferenceError: WIDHT is not defined',
  },
  {
    name: "a misspelling of the sketch's own name",
    source: sketchSource({ top: 'const WIDTH = 64;', before: '    const half = WIDHT / 2;' }),
    line: 'WIDHT',
    message: 'ReferenceError: WIDHT is not defined',
    suggestion: 'did you mean WIDTH?', // the sketch's own, before p5's width
  },
  // Did you mean …: the nearest name of the kit or p5 (lib/p5/page/mistake-hints.js).
  {
    name: 'a misspelt kit method on p',
    source: sketchSource().replace('p.createTracerView(', 'p.createTracerVeiw('),
    line: 'createTracerVeiw',
    message: 'TypeError: p.createTracerVeiw is not a function',
    suggestion: 'did you mean p.createTracerView?',
  },
  {
    name: 'a misspelt kit export',
    source: sketchSource({ sphere: 'new Spehre([0, 0, -20], 4)' }),
    line: 'Spehre',
    message: 'ReferenceError: Spehre is not defined',
    suggestion: 'did you mean Sphere?',
  },
  {
    name: 'a kit class used but not imported',
    source: sketchSource({ before: '    const box = new Box([-1, -1, -9], [1, 1, -7]);' }),
    line: 'new Box',
    message: 'ReferenceError: Box is not defined',
    suggestion: "Box is the kit's: add it to the sketch's import from lib/index.js",
  },
  {
    name: 'a misspelt p5 function',
    source: sketchSource({ before: '    p.creatCanvas(64, 48);' }),
    line: 'creatCanvas',
    message: 'TypeError: p.creatCanvas is not a function',
    suggestion: 'did you mean p.createCanvas?',
  },
  {
    name: 'a p5 function called bare in instance mode',
    source: sketchSource({ before: '    createCanvas(64, 48);' }),
    line: 'createCanvas(64',
    message: 'ReferenceError: createCanvas is not defined',
    suggestion: "createCanvas is p5's: in instance mode write p.createCanvas(…)",
  },
  {
    name: 'a kit factory called bare in instance mode',
    source: sketchSource({ before: '    createInspector({ view });' }),
    line: '    createInspector({ view });',
    message: 'ReferenceError: createInspector is not defined',
    suggestion: 'createInspector is a p5 method of the kit: in instance mode write p.createInspector(…)',
  },
  {
    name: 'a misspelt colour name',
    source: sketchSource({ sphere: "new Sphere([0, 0, -20], 4, { color: 'pinkk' })" }),
    line: "'pinkk'",
    message: `TypeError: color must be a colour like '#ff5160', 'rgb(255, 81, 96)' or 'pink', got "pinkk" (did you mean 'pink'?)`,
  },
];
// A name of the sketch's own, near nothing of the kit's or p5's: no guess.
MISTAKES[2].suggestion = null;

/** Syntax errors: the page's own panel, at the line and column of the sketch file. */
const SYNTAX = [
  { name: 'an unclosed string', before: "    const label = 'big sphere;", message: 'SyntaxError: Unterminated string', at: "'" },
  { name: 'a stray operator', before: '    const r = 4 +* 2;', message: 'SyntaxError: Unexpected token', at: '*' },
  // The parser notices at the end of the statement, the line after: where any JavaScript engine says it is.
  { name: 'a missing bracket', sphere: 'new Sphere([0, 0, -20], 4', message: 'SyntaxError: Expected `,` or `)` but found `;`', at: ';', line: '.add(new PointLight' },
];

SYNTAX.forEach((mistake, i) => {
  test(`a syntax error, ${mistake.name}: the panel shows the line and column; a fixed save clears it`, async ({ page }) => {
    const source = sketchSource(mistake);
    const sketch = liveSketch(`live-syntax-${i}`, source);
    try {
      const consoleErrors = [];
      page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(m.text()); });
      await page.goto(sketch.url);
      const panel = page.locator('[data-error]');
      await expect(panel).toBeVisible();
      await expect(panel.locator('[data-error-message]')).toContainText(mistake.message);
      const line = lineOf(source, mistake.line ?? (mistake.before ?? mistake.sphere).trim());
      const text = source.split('\n')[line - 1].trim();
      const where = await panel.locator('[data-error-where]').textContent();
      expect(where).toMatch(new RegExp(`^${sketch.file}:${line}:\\d+$`));
      if (mistake.at) { // the column is the offending character's (1-based)
        const column = Number(where.split(':').at(-1));
        expect(source.split('\n')[line - 1][column - 1]).toBe(mistake.at);
      }
      await expect(panel.locator('[data-error-source]')).toContainText(`${line} │ ${text}`);
      expect(consoleErrors.some((e) => e.startsWith('SyntaxError') && e.includes(`${sketch.file}:${line}:`))).toBe(true);

      await saveAndWaitForUpdate(page, sketch, FIXED);
      await waitForDone(page);
      await expect(panel).toHaveCount(0);
      await expectPicture(page);
    } finally {
      sketch.remove();
    }
  });
});

MISTAKES.forEach((mistake, i) => {
  test(`${mistake.name}: the panel names it and the sketch's line; a fixed save clears it`, async ({ page }) => {
    const sketch = liveSketch(`live-mistake-${i}`, mistake.source);
    try {
      const pageErrors = [];
      page.on('pageerror', (error) => pageErrors.push(error.message));
      await page.goto(sketch.url);
      if (mistake.picture) await waitForDone(page); // the good picture first
      await mistake.act?.(page);

      const panel = page.locator('[data-error]');
      await expect(panel).toBeVisible();
      await expect(panel.locator('[data-error-message]').first()).toContainText(mistake.message);
      const line = lineOf(mistake.source, mistake.line);
      await expect(panel.locator('[data-error-where]').first()).toHaveText(`${sketch.file}:${line}`);
      await expect(panel.locator('[data-error-source]').first()).toContainText(`${line} │ `);
      await expect(panel.locator('[data-error-source]').first()).toContainText(mistake.line.trim());
      if (mistake.suggestion) await expect(panel.locator('[data-error-suggestion]').first()).toHaveText(mistake.suggestion);
      if (mistake.suggestion === null) {
        await page.waitForTimeout(500); // the hint module has had its time
        await expect(panel.locator('[data-error-suggestion]')).toHaveCount(0);
      }
      expect(pageErrors.length, 'the console keeps the error').toBeGreaterThan(0);
      await expect(page.locator('.loading-indicator')).toHaveCount(0); // no spinner spinning for ever
      await expect(page.locator('body')).toHaveAttribute('data-render', mistake.picture ? 'done' : 'error');
      if (mistake.picture) await expectPicture(page); // the last good picture stays under the panel

      await saveAndWaitForUpdate(page, sketch, FIXED);
      await waitForDone(page);
      await expect(panel).toHaveCount(0);
      await expectPicture(page);
    } finally {
      sketch.remove();
    }
  });
});

/**
 * Imports the browser refuses: the page's modules never run, the kit's panel
 * included. The dev server finds those from the kit (at the import's line
 * and column); a classic script on the page shows the rest.
 */
const KIT = "import { Scene, Sphere, PointLight, Camera } from '../../../lib/index.js';";
const ADDON = "import '../../../lib/p5/index.js';";
const IMPORTS = [
  {
    name: 'a name the addon does not export',
    source: FIXED.replace(ADDON, `${ADDON}\nimport { createTracerVeiw } from '../../../lib/p5/index.js';`),
    at: 'createTracerVeiw',
    message: "SyntaxError: The requested module '../../../lib/p5/index.js' does not provide an export named 'createTracerVeiw'",
    suggestion: 'did you mean createTracerView? It is a method of p, not an export: write p.createTracerView({ … })',
  },
  {
    name: 'a misspelt export of the library',
    source: FIXED.replace(KIT, KIT.replace('Sphere', 'Spehre')),
    at: 'Spehre',
    message: "SyntaxError: The requested module '../../../lib/index.js' does not provide an export named 'Spehre'",
    suggestion: 'did you mean Sphere?',
  },
  {
    name: 'a kit file that is not there',
    source: FIXED.replace(ADDON, ADDON.replace('index.js', 'indx.js')),
    at: "'../../../lib/p5/indx.js'",
    message: "TypeError: Failed to fetch the module '../../../lib/p5/indx.js': there is no lib/p5/indx.js",
    suggestion: "did you mean '../../../lib/p5/index.js'?",
  },
  {
    name: "a name the sketch's own module does not export (the page's classic script)",
    helper: 'export function makeSky(scene) { return scene; }\n',
    source: FIXED.replace(ADDON, `${ADDON}\nimport { makeSyk } from './live-import-helper.js';`),
    at: 'makeSyk',
    message: "SyntaxError: The requested module '/tests/e2e/pages/live-import-helper.js' does not provide an export named 'makeSyk'",
    suggestion: 'did you mean makeSky?',
    exact: false, // the browser gives the line (and its own column): no caret at the name
  },
];

IMPORTS.forEach((mistake, i) => {
  test(`an import the page cannot have, ${mistake.name}: the panel shows it at the import, with the nearest name`, async ({ page }) => {
    const helper = 'tests/e2e/pages/live-import-helper.js';
    if (mistake.helper) writeFileSync(helper, mistake.helper);
    const sketch = liveSketch(`live-import-${i}`, mistake.source);
    try {
      await page.goto(sketch.url);
      const panel = page.locator('[data-error]');
      await expect(panel).toBeVisible();
      await expect(panel.locator('[data-error-message]')).toContainText(mistake.message);
      await expect(panel.locator('[data-error-suggestion]')).toHaveText(mistake.suggestion);
      const line = lineOf(mistake.source, mistake.at);
      const where = await panel.locator('[data-error-where]').textContent();
      if (mistake.exact === false) {
        expect(where).toBe(`${sketch.file}:${line}`);
      } else { // line and column: the column is where the name (or the file's name) starts
        expect(where).toMatch(new RegExp(`^${sketch.file}:${line}:\\d+$`));
        const column = Number(where.split(':').at(-1));
        expect(mistake.source.split('\n')[line - 1].slice(column - 1)).toMatch(new RegExp(`^${mistake.at}`));
      }
      await expect(panel.locator('[data-error-source]')).toContainText(`${line} │ `);
      await expect(page.locator('body')).toHaveAttribute('data-render', 'error');

      await saveAndWaitForUpdate(page, sketch, FIXED);
      await waitForDone(page);
      await expect(panel).toHaveCount(0);
      await expectPicture(page);
    } finally {
      sketch.remove();
      rmSync(helper, { force: true });
    }
  });
});

/**
 * The page's place for the picture and text after it, as on the homework
 * pages: a column of the page's own, the picture in it, a line of text under it.
 */
const COLUMN = '<div class="column"><div id="picture"></div><p id="api">API: Scene, Sphere, PointLight, Camera, createTracerView, createInspector</p></div>';

test('two different mistakes in a row after a good picture: the picture keeps its box and covers no text', async ({ page }) => {
  const inColumn = (source) => source.replace('grid: true });', "grid: true, parent: 'picture' });");
  const good = inColumn(FIXED);
  const sketch = liveSketch('live-mistake-twice', good, { main: COLUMN });
  const box = (selector) => page.locator(selector).evaluate((e) => {
    const r = e.getBoundingClientRect();
    return [r.left + scrollX, r.top + scrollY, r.width, r.height];
  });
  /** Text on the page (the panel's aside) that a picture over it hides. */
  const coveredText = () => page.evaluate(() => {
    const ghost = document.querySelector('[data-sketchbook-ghost]').getBoundingClientRect();
    const covered = [];
    const walk = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    for (let node = walk.nextNode(); node; node = walk.nextNode()) {
      if (!node.textContent.trim() || node.parentElement.closest('[data-error], [hidden]')) continue;
      const range = document.createRange();
      range.selectNodeContents(node);
      for (const r of range.getClientRects()) {
        if (r.right > ghost.left && r.left < ghost.right && r.bottom > ghost.top && r.top < ghost.bottom) covered.push(node.textContent.trim());
      }
    }
    return covered;
  });
  try {
    await page.goto(sketch.url);
    await waitForDone(page);
    const first = await box('canvas[data-tracer]');
    expect(first[2]).toBeGreaterThan(64); // scaled up: a box worth keeping

    await saveAndWaitForUpdate(page, sketch, good.replace('[1, 0.32, 0.36]', '[1, 0.3, 0.4]')); // a working save first
    await waitForDone(page);
    expect(await box('canvas[data-tracer]'), 'a good save keeps the picture\'s size').toEqual(first);

    const mistakes = [
      [good.replace('{ color: [1, 0.32, 0.36] }', '{ colour: [1, 0.32, 0.36] }'), 'unknown material option "colour"', 'swap'],
      [good.replace('p.noCanvas();', 'p.noCanvas();\n    const r = 4 +* 2;'), 'SyntaxError: Unexpected token', 'swap'],
      // A mistake at the top: the new version does not load, so the page reloads; the picture comes back under the panel.
      [good.replace('new p5((p) => {', 'const SIZE = WIDHT * 2;\nnew p5((p) => {'), 'ReferenceError: WIDHT is not defined', 'reload'],
      [good.replace('{ color: [1, 0.32, 0.36] }', "{ color: 'pinkk' }"), "(did you mean 'pink'?)", 'swap'],
    ];
    for (const [source, message, how] of mistakes) {
      expect(await saveAndWaitForUpdate(page, sketch, source)).toBe(how);
      await expect(page.locator('[data-error-message]')).toContainText(message);
      await expect(page.locator('canvas[data-sketchbook-ghost]')).toHaveCount(1);
      const kept = await box('canvas[data-sketchbook-ghost]');
      kept.forEach((x, i) => expect(x, `after "${message}": the last good picture where it was, at its size`).toBeCloseTo(first[i], 1));
      expect(await coveredText(), `after "${message}": no text under the picture`).toEqual([]);
      await expect(page.locator('#api')).toBeVisible();
      const centre = await page.locator('canvas[data-sketchbook-ghost]').evaluate((c) => [...c.getContext('2d').getImageData(32, 24, 1, 1).data]);
      expect(centre[0]).toBeGreaterThan(centre[2] + 40); // the picture itself, not a white box
    }

    await saveAndWaitForUpdate(page, sketch, good);
    await waitForDone(page);
    await expect(page.locator('[data-error]')).toHaveCount(0);
    await expect(page.locator('[data-sketchbook-ghost]')).toHaveCount(0);
    expect(await box('canvas[data-tracer]')).toEqual(first);
  } finally {
    sketch.remove();
  }
});

test('the panel builds its text as text: a message with markup shows the markup', async ({ page }) => {
  const sketch = liveSketch('live-mistake-markup', sketchSource({ before: "    throw new Error('<img src=x onerror=alert(1)> is not a sphere');" }));
  try {
    await page.goto(sketch.url);
    const message = page.locator('[data-error-message]');
    await expect(message).toContainText('<img src=x onerror=alert(1)> is not a sphere');
    await expect(page.locator('[data-error] img')).toHaveCount(0);
  } finally {
    sketch.remove();
  }
});

test('the same mistake every frame shows once, with a count', async ({ page }) => {
  const sketch = liveSketch('live-mistake-repeat', sketchSource({ draw: "    setTimeout(() => { throw new RangeError('again'); });" }));
  try {
    await page.goto(sketch.url);
    await expect(page.locator('[data-error-count]')).toHaveText(/^×([3-9]|\d\d+)$/);
    await expect(page.locator('[data-error-message]')).toHaveCount(1);
  } finally {
    sketch.remove();
  }
});

/** The traced canvas holds a picture: the sphere's pink at the centre, the sky at a corner. */
async function expectPicture(page) {
  const canvas = page.locator('[data-tracer]');
  const [centre, corner] = await canvas.evaluate((c) => {
    const g = c.getContext('2d');
    return [[...g.getImageData(32, 24, 1, 1).data], [...g.getImageData(0, 0, 1, 1).data]];
  });
  expect(centre[0]).toBeGreaterThan(centre[2] + 40); // pink-red sphere
  expect(corner).toEqual([217, 235, 255, 255]); // [0.85, 0.92, 1] sky
  await clickPixel(canvas, 32, 24); // and the page still answers
  await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(/^Pixel: 32,24; /);
  await expect(page.locator('[data-inspector] [data-field="hit-object"]')).toHaveText('sphere 1'); // unnamed: its kind and number
}
