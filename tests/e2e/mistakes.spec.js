/**
 * The mistake on the page: a sketch built from the README's recipe, with one
 * kind of mistake each, shows the panel [data-error] with the message and the
 * sketch's own file:line (the console keeps the error too); after a fix is
 * saved (swapped in place or reloaded), the panel is gone and the picture traced.
 */
import { test, expect } from '@playwright/test';
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
];

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
      await expect(panel.locator('[data-error-source]').first()).toContainText(mistake.line);
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
}
