// Sketches 01–03 used the way a class uses them: click a pixel and watch the
// diagram and the answer line follow (01), move the sphere with a slider or a
// typed number and see every picture re-render, or keep the last good one
// after a bad number (02), and put the eye inside the sphere to see a hit
// with tca < 0 (03).
import { test, expect } from '@playwright/test';
import { Camera, Scene, Sphere, inspectPixel } from '../../lib/index.js';
import { clickPixel, expectQuietConsole, waitForDone } from './helpers.js';

expectQuietConsole(test);

/** The lesson's answer line for pixel (x, y) of a camera, computed here with the library in Node. */
function answerFor(camera, x, y) {
  const { h, v } = camera.primaryRay(x, y);
  const angle = (a) => (Math.abs(a) < 0.05 ? 0 : a).toFixed(1);
  return `Pixel: ${x},${y}; H: ${angle(h)}; V: ${angle(v)}`;
}

/** A canvas's content, to tell whether it changed. */
function pixelsOf(locator) {
  return locator.evaluate((canvas) => canvas.toDataURL());
}

/** Records every value body[data-render] takes from now on (a re-render can be over in one frame). */
async function watchRenderState(page) {
  await page.evaluate(() => {
    window.renderStates = [];
    new MutationObserver(() => window.renderStates.push(document.body.dataset.render))
      .observe(document.body, { attributes: true, attributeFilter: ['data-render'] });
  });
  return () => page.evaluate(() => window.renderStates);
}

test.describe('01 · rays through pixels', () => {
  const PAGE = '/sketches/01-rays-through-pixels.html';
  const camera = new Camera({ width: 32, height: 24, fov: 30 });

  test('traces a 32×24 picture with the pixel grid over it, no pixel selected yet', async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    const canvas = page.locator('[data-tracer]');
    await expect(canvas).toHaveAttribute('data-width', '32');
    await expect(canvas).toHaveAttribute('data-height', '24');
    // the grid lives on the overlay, never in the traced picture
    const gridPixels = await page.locator('[data-overlay]').evaluate((o) => {
      const data = o.getContext('2d').getImageData(0, 0, o.width, o.height).data;
      let n = 0;
      for (let i = 3; i < data.length; i += 4) if (data[i] > 0) n++;
      return n;
    });
    expect(gridPixels).toBeGreaterThan(0);
    await expect(page.locator('[data-inspector] [data-answer]')).toHaveText('');
  });

  test('clicking a pixel draws its ray in the diagram and writes the answer line', async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    const diagram = page.locator('#diagram > canvas'); // the side and top views (the 3D view has its own)
    const before = await pixelsOf(diagram);

    await clickPixel(page.locator('[data-tracer]'), 20, 10);
    await page.mouse.move(0, 0); // off the picture: the diagram shows the selected pixel
    await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(answerFor(camera, 20, 10));
    await expect.poll(() => pixelsOf(diagram)).not.toBe(before);
    const pixel20 = await pixelsOf(diagram);
    // the pink sphere is hit, as the diagram's ray shows
    await expect(page.locator('[data-inspector] [data-field="hit-object"]')).toHaveAttribute('data-value', 'pink');

    // another pixel: another ray in the diagram, another answer line
    await page.locator('[data-tracer]').press('ArrowDown');
    await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(answerFor(camera, 20, 11));
    await expect.poll(() => pixelsOf(diagram)).not.toBe(pixel20);
  });

  test('pointing at a pixel shows its ray without selecting it', async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    const diagram = page.locator('#diagram > canvas'); // the side and top views (the 3D view has its own)
    const before = await pixelsOf(diagram);
    const box = await page.locator('[data-tracer]').boundingBox();
    await page.mouse.move(box.x + (5.5 * box.width) / 32, box.y + (3.5 * box.height) / 24);
    await expect.poll(() => pixelsOf(diagram)).not.toBe(before);
    await expect(page.locator('[data-inspector] [data-answer]')).toHaveText('');
    await page.mouse.move(0, 0);
    await expect.poll(() => pixelsOf(diagram)).toBe(before);
  });

  test('slow motion traces again one ray at a time, the diagram following the ray, and still finishes', async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    const finished = await pixelsOf(page.locator('[data-tracer]'));
    const diagram = page.locator('#diagram > canvas'); // the side and top views (the 3D view has its own)
    const states = await watchRenderState(page);

    await page.getByLabel('Slow motion').check();
    expect(await states()).toContain('rendering');
    // the diagram follows the ray being traced: it changes while the picture fills in
    const first = await pixelsOf(diagram);
    await expect.poll(() => pixelsOf(diagram)).not.toBe(first);
    await waitForDone(page, 60_000);
    expect(await pixelsOf(page.locator('[data-tracer]'))).toBe(finished); // the same picture, slowly
  });
});

test.describe('02 · the quadratic', () => {
  const PAGE = '/sketches/02-the-quadratic.html';

  test('three views (shaded, discriminant, roots) select the same pixel', async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    const views = page.locator('[data-tracer]');
    await expect(views).toHaveCount(3);
    const overlays = page.locator('[data-overlay]');
    const sameSelection = async () => {
      const [a, b, c] = await overlays.evaluateAll((list) => list.map((o) => o.toDataURL()));
      return a === b && b === c;
    };
    const answer = page.locator('[data-inspector] [data-answer]');
    const camera = new Camera({ width: 64, height: 48 });
    const start = await overlays.first().evaluate((o) => o.toDataURL());

    // click the discriminant map: all three crosshairs move there, the panel follows
    await clickPixel(views.nth(1), 10, 30);
    await expect(answer).toHaveText(answerFor(camera, 10, 30));
    expect(await sameSelection()).toBe(true);
    expect(await overlays.first().evaluate((o) => o.toDataURL())).not.toBe(start);

    // arrow keys on the roots map move all three too
    await views.nth(2).press('ArrowRight');
    await expect(answer).toHaveText(answerFor(camera, 11, 30));
    expect(await sameSelection()).toBe(true);

    // and a click on the shaded picture
    await clickPixel(views.nth(0), 50, 5);
    await expect(answer).toHaveText(answerFor(camera, 50, 5));
    expect(await sameSelection()).toBe(true);
  });

  test('the panel shows A, B, C, the discriminant and the roots of the selected pixel', async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    const camera = new Camera({ width: 64, height: 48 });
    const scene = new Scene().add(new Sphere([0, 0, -20], 4));
    const q = inspectPixel(scene, camera, 32, 24).tests[0].quadratic; // the pixel selected at the start
    const value = (field) => page.locator(`[data-inspector] [data-route="quadratic"][data-field="${field}"]`).getAttribute('data-value');
    for (const field of ['A', 'B', 'C', 'discriminant', 't0', 't1']) expect(Number(await value(field))).toBeCloseTo(q[field], 9);
    expect(q.roots).toBe(2);
  });

  test('moving a slider moves the sphere: every picture re-renders, without a reload', async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    await page.evaluate(() => { window.notReloaded = true; });
    const views = page.locator('[data-tracer]');
    const before = await Promise.all([0, 1, 2].map((i) => pixelsOf(views.nth(i))));
    const states = await watchRenderState(page);

    await page.getByLabel('Centre x (Xc) slider').fill('6');
    await waitForDone(page);
    expect(await states()).toEqual(expect.arrayContaining(['rendering', 'done']));
    await expect(page.locator('#field-x')).toHaveValue('6');
    for (let i = 0; i < 3; i++) expect(await pixelsOf(views.nth(i))).not.toBe(before[i]);
    expect(await page.evaluate(() => window.notReloaded)).toBe(true);

    // a typed number does the same, and moves the slider
    const afterSlider = await pixelsOf(views.nth(0));
    await page.locator('#field-r').fill('7');
    await waitForDone(page);
    await expect(page.getByLabel('Radius r slider')).toHaveValue('7');
    expect(await pixelsOf(views.nth(0))).not.toBe(afterSlider);
  });

  test('a bad number gets a message naming the field, and the picture stays', async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    const views = page.locator('[data-tracer]');
    const before = await pixelsOf(views.nth(0));
    const states = await watchRenderState(page);

    await page.locator('#field-r').fill('-2');
    await expect(page.locator('[data-message-for="r"]')).toContainText('Radius r');
    await expect(page.locator('[data-message-for="r"]')).toContainText('greater than 0');
    await expect(page.locator('#field-r')).toHaveAttribute('aria-invalid', 'true');

    await page.locator('#field-x').fill('abc');
    await expect(page.locator('[data-message-for="x"]')).toContainText('Centre x');
    await expect(page.locator('[data-message-for="x"]')).toContainText('must be a number');

    expect(await states()).toEqual([]); // nothing was traced again
    expect(await pixelsOf(views.nth(0))).toBe(before);

    // a good number clears the message
    await page.locator('#field-r').fill('3');
    await expect(page.locator('[data-message-for="r"]')).toHaveText('');
    await waitForDone(page);
    expect(await pixelsOf(views.nth(0))).not.toBe(before);
  });
});

test.describe('03 · the geometric approach', () => {
  const PAGE = '/sketches/03-the-geometric-approach.html';
  const value = (page, route, field) => page.locator(`[data-inspector] [data-route="${route}"][data-sphere="0"][data-field="${field}"]`).getAttribute('data-value');

  test('both routes give the same t for the selected ray', async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    await clickPixel(page.locator('[data-tracer]'), 36, 20);
    await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(answerFor(new Camera({ width: 64, height: 48, fov: 30 }), 36, 20));
    const compare = page.locator('[data-compare]');
    for (const field of ['t0', 't1', 't']) {
      const quadratic = await compare.locator(`[data-route="quadratic"][data-field="${field}"]`).textContent();
      await expect(compare.locator(`[data-route="geometric"][data-field="${field}"]`)).toHaveText(quadratic);
      expect(quadratic).toMatch(/^\d+\.\d{3}$/);
    }
    // outside the sphere, the centre is ahead of the eye
    expect(Number(await value(page, 'geometric', 'tca'))).toBeGreaterThan(0);
  });

  test('with the eye inside the sphere, the centre pixel hits the sphere although tca < 0', async ({ page }) => {
    await page.goto(PAGE);
    await waitForDone(page);
    const canvas = page.locator('[data-tracer]');
    const outside = await pixelsOf(canvas);
    const states = await watchRenderState(page);

    await page.getByLabel('Eye inside the sphere').check();
    await waitForDone(page);
    expect(await states()).toContain('rendering');
    expect(await pixelsOf(canvas)).not.toBe(outside);

    await clickPixel(canvas, 32, 24);
    await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(/^Pixel: 32,24;/);
    const tca = Number(await value(page, 'geometric', 'tca'));
    const thc = Number(await value(page, 'geometric', 'thc'));
    const t = Number(await page.locator('[data-inspector] [data-field="hit-t"]').getAttribute('data-value'));
    expect(tca).toBeLessThan(0);
    expect(t).toBeGreaterThan(0);
    expect(t).toBeCloseTo(tca + thc, 9); // the way out: t = tca + thc
    await expect(page.locator('[data-inspector] [data-field="hit-object"]')).toHaveAttribute('data-value', 'pink');
    await expect(page.locator('[data-explain]')).toContainText('inside the sphere');
    await expect(page.locator('[data-explain]')).toContainText('< 0, yet the ray hits');
    await expect(page.locator('[data-compare] [data-route="quadratic"][data-field="t"]')).toHaveText(t.toFixed(3));

    // back outside: the same pixel has tca > 0 again
    await page.getByLabel('Eye inside the sphere').uncheck();
    await waitForDone(page);
    expect(Number(await value(page, 'geometric', 'tca'))).toBeGreaterThan(0);
    expect(await pixelsOf(canvas)).toBe(outside);
  });
});
