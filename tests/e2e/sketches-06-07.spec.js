// Sketch 06 (lights, shadows, reflections): every switch re-traces the
// picture without a reload and changes it the way its idea says.
// Sketch 07 (the original examples): the still scene by default, the
// animation with its frame counter and Pause, and the Web Workers frames equal
// to render()'s picture of the same moment.
import { test, expect } from '@playwright/test';
import { clickPixel, watchConsole, waitForDone } from './helpers.js';

const SKETCH_06 = '/sketches/06-lights-shadows-reflections.html';
const SKETCH_07 = '/sketches/07-original-examples.html';

/** The traced picture's RGBA bytes, read back from the tracer canvas. */
function pixels(page) {
  return page.locator('[data-tracer]').evaluate((c) => Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data));
}

/** [r, g, b] of pixel (x, y) in bytes read by pixels(). */
function rgb(data, width, x, y) {
  const i = (y * width + x) * 4;
  return [data[i], data[i + 1], data[i + 2]];
}

const sum = (c) => c[0] + c[1] + c[2];

/** How many pixels differ between two pictures, and how many got brighter / darker. */
function compare(before, after) {
  let differ = 0, brighter = 0, darker = 0;
  for (let i = 0; i < before.length; i += 4) {
    const d = sum([after[i], after[i + 1], after[i + 2]]) - sum([before[i], before[i + 1], before[i + 2]]);
    if (after[i] !== before[i] || after[i + 1] !== before[i + 1] || after[i + 2] !== before[i + 2]) differ++;
    if (d > 0) brighter++;
    if (d < 0) darker++;
  }
  return { differ, brighter, darker };
}

/** Clicks traced pixel (x, y) and waits for the inspector's answer line to name it. */
async function selectPixel(page, x, y) {
  await clickPixel(page.locator('[data-tracer]'), x, y);
  await expect(page.locator('[data-answer]')).toHaveText(new RegExp(`^Pixel: ${x},${y}; H: -?\\d+\\.\\d; V: -?\\d+\\.\\d$`));
}

/** Runs a change that restarts the render, then waits for the new picture to finish. */
async function retrace(page, change) {
  await change();
  await waitForDone(page);
  return pixels(page);
}

const hitObject = (page) => page.locator('[data-inspector] [data-field="hit-object"]');
const inShadow = (page, light) => page.locator(`[data-inspector] [data-field="in-shadow"][data-light="${light}"]`);

test.describe('06 · lights, shadows and reflections', () => {
  let errors;
  test.beforeEach(async ({ page }) => {
    errors = watchConsole(page);
    await page.goto(SKETCH_06);
    await waitForDone(page);
  });
  test.afterEach(() => expect(errors).toEqual([]));

  test('shadows off: the floor in the lamp\'s shadow gets brighter, nothing gets darker; on again: the same picture', async ({ page }) => {
    const before = await pixels(page);
    await selectPixel(page, 37, 82); // floor behind the mirror ball, in the lamp's shadow
    await expect(hitObject(page)).toHaveText('floor');
    await expect(inShadow(page, 0)).toHaveAttribute('data-value', 'false'); // the point light reaches it
    await expect(inShadow(page, 1)).toHaveAttribute('data-value', 'true'); // the lamp does not

    const off = await retrace(page, () => page.getByLabel('shadows', { exact: true }).uncheck());
    expect(sum(rgb(off, 160, 37, 82))).toBeGreaterThan(sum(rgb(before, 160, 37, 82)));
    const change = compare(before, off);
    expect(change.brighter).toBeGreaterThan(500);
    expect(change.darker).toBe(0); // a shadow only ever takes light away
    await expect(inShadow(page, 1)).toHaveAttribute('data-value', 'false'); // the panel followed

    const on = await retrace(page, () => page.getByLabel('shadows', { exact: true }).check());
    expect(compare(before, on).differ).toBe(0);
  });

  test('mirror bounces 0: the mirror ball shows only its own paint; 5 again: the mirror is back', async ({ page }) => {
    const before = await pixels(page);
    await selectPixel(page, 35, 54);
    await expect(hitObject(page)).toHaveText('mirror');
    const slider = page.locator('.switches input[type="range"]'); // not the 3D view's speed slider

    const flat = await retrace(page, () => slider.fill('0'));
    await expect(page.getByText('mirror bounces: 0')).toBeVisible();
    expect(rgb(flat, 160, 35, 54)).not.toEqual(rgb(before, 160, 35, 54));
    expect(rgb(flat, 160, 125, 54)).not.toEqual(rgb(before, 160, 125, 54)); // the glass ball too
    expect(rgb(flat, 160, 80, 52)).toEqual(rgb(before, 160, 80, 52)); // the red ball is plain paint anyway

    const one = await retrace(page, () => slider.fill('1'));
    expect(compare(flat, one).differ).toBeGreaterThan(100);
    const back = await retrace(page, () => slider.fill('5'));
    expect(compare(before, back).differ).toBe(0);
  });

  test('glass off: the glass ball turns opaque, the rest of the balls stay', async ({ page }) => {
    const before = await pixels(page);
    await selectPixel(page, 125, 54);
    await expect(hitObject(page)).toHaveText('glass');
    const opaque = await retrace(page, () => page.getByLabel('glass', { exact: true }).uncheck());
    expect(rgb(opaque, 160, 125, 54)).not.toEqual(rgb(before, 160, 125, 54));
    expect(rgb(opaque, 160, 80, 52)).toEqual(rgb(before, 160, 80, 52));
  });

  test('highlights off: the shiny spots go, and nothing gets brighter', async ({ page }) => {
    const before = await pixels(page);
    const matte = await retrace(page, () => page.getByLabel('highlights', { exact: true }).uncheck());
    const change = compare(before, matte);
    expect(change.darker).toBeGreaterThan(20); // a highlight only ever adds light
    expect(change.brighter).toBe(0);
  });

  test('shadow-ray offset: too big loosens the shadows; 0 speckles lit surfaces with acne', async ({ page }) => {
    const before = await pixels(page);
    const offset = page.getByLabel('shadow-ray offset');
    const loose = await retrace(page, () => offset.selectOption('0.3'));
    expect(compare(before, loose).differ).toBeGreaterThan(500);

    const acne = await retrace(page, () => offset.selectOption('0'));
    expect(compare(before, acne).darker).toBeGreaterThan(500); // surfaces shadowing themselves
    await selectPixel(page, 100, 80);
    await expect(hitObject(page)).toHaveText('floor');
    await expect(inShadow(page, 1)).toHaveAttribute('data-value', 'true');

    const back = await retrace(page, () => offset.selectOption('0.0001'));
    expect(compare(before, back).differ).toBe(0);
  });
});

test.describe('07 · the original examples', () => {
  let errors;
  test.beforeEach(({ page }) => { errors = watchConsole(page); });
  test.afterEach(() => expect(errors).toEqual([]));

  const stats = (page) => page.locator('[data-stats]');
  const frame = async (page) => Number(await stats(page).getAttribute('data-frame'));

  /**
   * Compares, inside the page, the tracer canvas with render() of the scene it
   * should show: the still class scene, or the animation at the time the stats
   * line shows. Returns `{ differ, length }` (bytes that differ, canvas bytes).
   */
  const canvasVersusRender = (page, example) => page.evaluate(async (example) => {
    const { render, classScene, Camera } = await import('/lib/index.js');
    const c = document.querySelector('[data-tracer]');
    const shown = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const t = Number(document.querySelector('[data-stats]').dataset.time);
    const expected = example === 'still' || example === 'original'
      ? render(classScene(), new Camera(example === 'still' ? { width: 160, height: 120 } : { width: 640, height: 480 }))
      : render(window.sketch.sceneAt(t), window.sketch.camera);
    let differ = Math.abs(shown.length - expected.length);
    for (let i = 0; i < Math.min(shown.length, expected.length); i++) if (shown[i] !== expected[i]) differ++;
    return { differ, length: shown.length };
  }, example);

  /** A short fingerprint of the tracer canvas (FNV-1a over its bytes). */
  const fingerprint = (page) => page.locator('[data-tracer]').evaluate((c) => {
    const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let h = 2166136261;
    for (let i = 0; i < data.length; i++) h = Math.imul(h ^ data[i], 16777619);
    return h >>> 0;
  });

  /** Pixel (x, y) of the tracer canvas as '#rrggbb'. */
  const canvasHex = (page, x, y) => page.locator('[data-tracer]').evaluate((c, [x, y]) => {
    const [r, g, b] = c.getContext('2d').getImageData(x, y, 1, 1).data;
    return `#${[r, g, b].map((v) => v.toString(16).padStart(2, '0')).join('')}`;
  }, [x, y]);

  test('the still example is the default: the class scene traced once, and the inspector answers', async ({ page }) => {
    await page.goto(SKETCH_07);
    await waitForDone(page);
    await expect(page.locator('[data-example="still"]')).toHaveAttribute('aria-pressed', 'true');
    await expect(page.locator('[data-tracer]')).toHaveAttribute('data-width', '160');
    await expect(stats(page)).toBeHidden();
    expect(await canvasVersusRender(page, 'still')).toEqual({ differ: 0, length: 160 * 120 * 4 });
    await selectPixel(page, 80, 60);
    await expect(hitObject(page)).toHaveText('pink');
  });

  test('640×480: example 1 at the class library\'s own size, traced progressively, and the inspector answers', async ({ page }) => {
    await page.goto(SKETCH_07);
    await waitForDone(page);
    // Progressive: traced a frame's worth at a time (8 ms), so the page draws many frames while "rendering".
    await page.evaluate(() => {
      window.framesWhileRendering = 0;
      const count = () => { if (document.body.dataset.render === 'rendering') window.framesWhileRendering++; requestAnimationFrame(count); };
      requestAnimationFrame(count);
    });
    await page.locator('[data-example="original"]').click();
    await expect(page.locator('[data-example="original"]')).toHaveText('640×480');
    await expect(page.locator('[data-example="original"]')).toHaveAttribute('aria-pressed', 'true');
    const view = page.locator('[data-tracer]');
    await expect(view).toHaveAttribute('data-width', '640');
    await expect(view).toHaveAttribute('data-height', '480');
    await selectPixel(page, 320, 240); // a click while it traces is answered at once
    await waitForDone(page);
    expect(await page.evaluate(() => window.framesWhileRendering)).toBeGreaterThanOrEqual(3); // not one long task
    expect(await canvasVersusRender(page, 'original')).toEqual({ differ: 0, length: 640 * 480 * 4 });
    await expect(hitObject(page)).toHaveText('pink');
    await selectPixel(page, 10, 10);
    await expect(hitObject(page)).not.toHaveText('pink');
    // The link opens it too.
    await page.goto(`${SKETCH_07}?example=original`);
    await waitForDone(page);
    await expect(view).toHaveAttribute('data-width', '640');
  });

  test('animated: the frame counter rises with an FPS figure; Pause stops it at "done" and the frame can be inspected', async ({ page }) => {
    test.slow(); // a few whole 320×240 frames on the page's thread
    await page.goto(SKETCH_07);
    await waitForDone(page);
    await page.locator('[data-example="animated"]').click();
    await expect(page.locator('body')).toHaveAttribute('data-render', 'rendering'); // playing
    await expect(page.locator('[data-tracer]')).toHaveAttribute('data-width', '320');
    await expect.poll(() => frame(page), { timeout: 60_000 }).toBeGreaterThanOrEqual(3);
    await expect(stats(page)).toHaveText(/^frame \d+ · \d+\.\d FPS · t = \d+\.\d\d s · main thread$/);

    await page.locator('[data-pause]').click();
    await waitForDone(page);
    await expect(page.locator('[data-pause]')).toHaveText('Play');
    const stopped = await frame(page);
    const picture = await fingerprint(page);
    await page.evaluate(() => new Promise((resolve) => { let n = 10; const tick = () => (--n ? requestAnimationFrame(tick) : resolve()); tick(); }));
    expect(await frame(page)).toBe(stopped);
    expect(await fingerprint(page)).toBe(picture);

    // The paused frame is render()'s picture of the scene at the time shown, and the panel explains it.
    expect(await canvasVersusRender(page, 'animated')).toEqual({ differ: 0, length: 320 * 240 * 4 });
    await selectPixel(page, 160, 120);
    await expect(page.locator('[data-inspector] [data-field="hex"]')).toHaveText(await canvasHex(page, 160, 120));
  });

  test('workers: shows the worker count, checks the box, and a paused frame equals render() of the same moment', async ({ page }) => {
    test.slow(); // whole 320×240 frames, with 4 and then 2 workers
    await page.goto(`${SKETCH_07}?example=workers`);
    await expect(page.locator('[data-example="workers"]')).toHaveAttribute('aria-pressed', 'true');
    await expect.poll(() => frame(page), { timeout: 60_000 }).toBeGreaterThanOrEqual(2);
    await expect(stats(page)).toHaveText(/· 4 workers$/);

    const box = page.getByLabel('workers (1–8)');
    await box.fill('9');
    await box.press('Enter');
    await expect(page.locator('[data-message="workers"]')).toHaveText(/workers must be a whole number from 1 to 8, got "9"; still using 4/);
    await box.fill('2');
    await box.press('Enter');
    await expect(page.locator('[data-message="workers"]')).toBeHidden();
    await expect(stats(page)).toHaveText(/· 2 workers$/, { timeout: 60_000 });
    const before = await frame(page);
    await expect.poll(() => frame(page), { timeout: 60_000 }).toBeGreaterThan(before + 1); // frames from 2 workers

    await page.locator('[data-pause]').click();
    await waitForDone(page);
    await expect(page.locator('.about')).toHaveText(/the same, byte for byte ✓/);
    expect(await canvasVersusRender(page, 'workers')).toEqual({ differ: 0, length: 320 * 240 * 4 });
    await selectPixel(page, 10, 230);
    await expect(page.locator('[data-inspector] [data-field="hex"]')).toHaveText(await canvasHex(page, 10, 230));
  });

  test('a bad ?example= says so and shows the still scene', async ({ page }) => {
    await page.goto(`${SKETCH_07}?example=movie`);
    await waitForDone(page);
    await expect(page.locator('[data-message="example"]')).toHaveText('example must be still, original, animated, workers; got "movie", so here is the still scene.');
    await expect(page.locator('[data-example="still"]')).toHaveAttribute('aria-pressed', 'true');
    await page.locator('[data-example="animated"]').click();
    await expect(page.locator('[data-message="example"]')).toBeHidden();
  });
});
