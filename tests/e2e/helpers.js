/**
 * Shared steps of the browser tests: console-error capture, waiting for
 * the page contract's body[data-render="done"], clicking a traced pixel and
 * screenshots of a canvas.
 */
import { test, expect } from '@playwright/test';
import { existsSync, readFileSync } from 'node:fs';
import { PNG } from 'pngjs';

/**
 * Collects console errors, warnings and logs (p5's friendly errors are logs)
 * and page errors; call before page.goto. A quiet console is part of the
 * page contract. Chromium's hint about repeated getImageData is left out:
 * the tests' own pixel reads cause it, not the page; so is the software GL
 * driver's "GPU stall due to ReadPixels", which headless Chromium logs for any
 * WebGL canvas it composites (a 3D view), whatever the page does.
 */
export function watchConsole(page) {
  const errors = [];
  page.on('console', (msg) => {
    if (!['error', 'warning', 'log'].includes(msg.type()) || msg.text().startsWith('Canvas2D: Multiple readback operations') || /GL Driver Message .*GPU stall due to ReadPixels/.test(msg.text())) return;
    errors.push(`${msg.type()}: ${msg.text()}`);
  });
  page.on('pageerror', (err) => errors.push(String(err)));
  return errors;
}

/** Waits until every tracer view on the page has finished tracing. */
export async function waitForDone(page, timeout = 30_000) {
  await expect(page.locator('body')).toHaveAttribute('data-render', 'done', { timeout });
}

/** Every test of the calling file must leave the console quiet (see watchConsole). */
export function expectQuietConsole(test) {
  let errors;
  test.beforeEach(({ page }) => { errors = watchConsole(page); });
  test.afterEach(() => { expect(errors, 'console errors').toEqual([]); });
}

/**
 * One page for all the tests of the calling describe block, run in order: for
 * tests that each open a page and only read it, the pages then share one
 * browser context and its cache (the page's scripts are not fetched and
 * compiled again). Made with the project's baseURL, viewport and scale; its
 * console must stay quiet, checked after each test. Use `shared.page`.
 */
export function sharedPage(test) {
  const shared = { page: null, errors: [] };
  test.describe.configure({ mode: 'serial' });
  test.beforeAll(async ({ browser }, info) => {
    const { baseURL, viewport, deviceScaleFactor } = info.project.use;
    shared.page = await (await browser.newContext({ baseURL, viewport, deviceScaleFactor })).newPage();
    shared.errors = watchConsole(shared.page);
  });
  test.afterEach(() => { expect(shared.errors.splice(0), 'console errors').toEqual([]); });
  test.afterAll(() => shared.page?.context().close());
  return shared;
}

/**
 * Clicks the centre of traced pixel (x, y) of a tracer canvas, whatever its
 * on-screen scale. Through the locator, so Playwright first waits until the
 * canvas is visible, still and the one that receives the click.
 */
export async function clickPixel(canvas, x, y) {
  await settled(canvas); // a late font or stylesheet would move the canvas under the pointer
  const box = await canvas.boundingBox();
  const width = Number(await canvas.getAttribute('data-width'));
  const height = Number(await canvas.getAttribute('data-height'));
  await canvas.click({ position: { x: ((x + 0.5) * box.width) / width, y: ((y + 0.5) * box.height) / height } });
}

/**
 * Matches a canvas against its reference screenshot, capturing exactly the
 * screen pixels the canvas covers, then checks that the reference holds the
 * canvas's own pixels and nothing else. Use it for every canvas screenshot.
 *
 * Why not expect(canvas).toHaveScreenshot: Chromium paints a canvas at its
 * rounded position, but an element screenshot rounds its clip outwards, so a
 * canvas at a fractional y (text of fractional height above it) would gain a
 * row of the frame around it. Snapping the clip here holds wherever the page
 * puts the canvas; the check makes any capture that is not the canvas fail.
 */
export async function expectCanvasScreenshot(canvas, name) {
  const page = canvas.page();
  await canvas.scrollIntoViewIfNeeded();
  const { clip, cssWidth, cssHeight } = await settled(canvas); // measured where it stays
  const referencePath = test.info().snapshotPath(name, { kind: 'screenshot' });
  const isNew = !existsSync(referencePath);
  await expect(page).toHaveScreenshot(name, { clip });
  // A missing reference fails the test without throwing ("writing actual"): say what to do next.
  if (isNew && test.info().errors.length) throw new Error(firstPictureHelp(page.url(), name));
  const reference = PNG.sync.read(readFileSync(referencePath));
  expect([reference.width, reference.height], `${name} is the canvas's CSS size`).toEqual([cssWidth, cssHeight]);
  const own = PNG.sync.read(Buffer.from((await canvas.evaluate((c) => c.toDataURL('image/png'))).split(',')[1], 'base64'));
  expect(firstForeignRow(reference, own), `${name}: first row that is not the canvas's pixels`).toBe(-1);
}

/** What to do when a picture had no reference: look at the one just written; for a sketch, the script that makes its alone. */
export function firstPictureHelp(url, name) {
  const sketch = /\/sketches\/(\d\d-[\w-]+\.html)/.exec(new URL(url).pathname)?.[1];
  const look = `${name} had no reference picture: the picture just seen was written as one. Look at it; commit it if it is right.`;
  return sketch
    ? `${look}\nIf not, delete it, fix the sketch, and make this new sketch's reference alone (checked on a second run) with\n` +
      `  npm run test:new-picture -- sketches/${sketch}\n(docs/DEVELOPERS.md: "How the first reference picture is made").`
    : `${look} (docs/DEVELOPERS.md: "How the first reference picture is made").`;
}

/** In the page: the screen pixels the canvas is painted on (its edges rounded, as Chromium paints it). */
/**
 * Waits until the page has its fonts and stylesheets (the tracer view links
 * its own at run time) and the canvas stands still for two frames, and returns
 * where it is painted: a late reflow would otherwise move or resize the canvas
 * between measuring it and clicking or capturing it.
 */
async function settled(canvas) {
  // A live sketch's save can reload the page once more while we wait: wait for that page instead.
  for (let attempt = 0; ; attempt++) {
    try {
      return await settledOnce(canvas);
    } catch (error) {
      if (attempt >= 3 || !/Execution context was destroyed|navigat/i.test(error.message)) throw error;
      await canvas.page().waitForLoadState('load');
    }
  }
}

async function settledOnce(canvas) {
  await canvas.page().evaluate(async () => {
    await document.fonts.ready;
    const pending = [...document.querySelectorAll('link[rel="stylesheet"]')].filter((link) => !link.sheet);
    await Promise.all(pending.map((link) => new Promise((done) => {
      link.addEventListener('load', done, { once: true });
      link.addEventListener('error', done, { once: true });
    })));
  });
  let last = null;
  for (let tries = 0; tries < 20; tries++) {
    const now = await canvas.evaluate((c) => new Promise((done) => {
      requestAnimationFrame(() => requestAnimationFrame(() => done(c.getBoundingClientRect().toJSON())));
    }));
    if (last && ['x', 'y', 'width', 'height'].every((k) => now[k] === last[k])) break;
    last = now;
  }
  return canvas.evaluate(paintedClip);
}

function paintedClip(canvas) {
  const r = canvas.getBoundingClientRect();
  const x = Math.round(r.left), y = Math.round(r.top);
  return { clip: { x, y, width: Math.round(r.right) - x, height: Math.round(r.bottom) - y }, cssWidth: r.width, cssHeight: r.height };
}

/**
 * The first row of a screenshot that differs from the canvas's own pixels
 * (each a scale × scale block on screen), or -1 when every row matches.
 */
function firstForeignRow(shot, own) {
  const scale = shot.width / own.width;
  expect(Number.isInteger(scale) && shot.height === own.height * scale, 'a whole number of screen pixels per canvas pixel').toBe(true);
  for (let y = 0; y < shot.height; y++) {
    for (let x = 0; x < shot.width; x++) {
      const s = (y * shot.width + x) * 4, o = (Math.floor(y / scale) * own.width + Math.floor(x / scale)) * 4;
      for (let k = 0; k < 4; k++) if (shot.data[s + k] !== own.data[o + k]) return y;
    }
  }
  return -1;
}
