/**
 * Saves swapped in place (lib/p5/page/hot-swap.js): no reload, and nothing of the
 * old sketch left behind: no second canvas, no listener, worker, timer or
 * animation frame of the old version still running. What cannot be swapped
 * safely reloads its page, as before.
 */
import { test, expect } from '@playwright/test';
import { writeFileSync, rmSync } from 'node:fs';
import { resolve } from 'node:path';
import { waitForDone, clickPixel } from './helpers.js';
import { liveSketch, sketchSource, saveAndWaitForUpdate } from './live-sketch.js';

const PINK = 'new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] })';
const GREEN = 'new Sphere([0, 0, -20], 5, { color: [0.2, 0.9, 0.3] })';

/** Counts, in the page, live workers and the animation frames asked for (the rest is read through the DevTools protocol). */
function countWorkersAndFrames() {
  const live = new Set();
  window.__liveWorkers = live;
  window.Worker = class extends window.Worker {
    constructor(...args) { super(...args); live.add(this); }
    terminate() { live.delete(this); super.terminate(); }
  };
  const ask = window.requestAnimationFrame.bind(window);
  window.__frameAsks = 0;
  window.requestAnimationFrame = (callback) => { window.__frameAsks += 1; return ask(callback); };
}

/** What the page holds now: canvases, elements, live workers, listeners on window and document, animation frames asked per frame. */
async function holdings(page, cdp) {
  const listeners = [];
  await cdp.send('Runtime.enable');
  for (const expression of ['window', 'document']) {
    const { result } = await cdp.send('Runtime.evaluate', { expression });
    const { listeners: found } = await cdp.send('DOMDebugger.getEventListeners', { objectId: result.objectId });
    listeners.push(...found.map((l) => `${expression}:${l.type}`));
    await cdp.send('Runtime.releaseObject', { objectId: result.objectId });
  }
  await cdp.send('Runtime.disable');
  const counts = await page.evaluate(async () => {
    const frames = 20, asked = window.__frameAsks;
    for (let i = 0; i < frames; i++) await new Promise((r) => window.requestAnimationFrame(r)); // these asks are ours: one a frame
    return {
      canvases: document.querySelectorAll('canvas').length,
      elements: document.querySelectorAll('*').length,
      workers: window.__liveWorkers.size,
      framesAskedPerFrame: Math.round((window.__frameAsks - asked - frames) / frames),
    };
  });
  return { ...counts, listeners: listeners.sort() };
}

// The test's dev server does not watch the live pages (vite.config.js): Vite would keep the reload a
// new page's file makes while no page is connected, and hand it to that page once it connects.
test('a page opened just after its files were written loads once, and stays', async ({ page }) => {
  await page.waitForTimeout(1000); // the last test's page gone: no page of the server open when the files are written
  const sketch = liveSketch('live-swap-new-page', sketchSource());
  try {
    let loads = 0; // navigations, not load events: the kept reload came before the first load had ended
    page.on('framenavigated', (frame) => { if (frame === page.mainFrame()) loads += 1; });
    await page.goto(sketch.url);
    await waitForDone(page);
    await page.waitForTimeout(1500);
    expect(loads).toBe(1);
  } finally {
    sketch.remove();
  }
});

// scripts/every-save-arrives.js: Vite would keep the reload a save makes while no page is connected and
// hand it to the next page that connects, which already loads the saved version.
test('a save that reloads while its page is closed: the page opened next loads once, the saved version', async ({ context }) => {
  const timer = sketchSource({ before: '    setTimeout(() => {}, 0);' }); // reaches outside p5: its saves reload
  const sketch = liveSketch('live-swap-closed', timer);
  try {
    const first = await context.newPage();
    await first.goto(sketch.url);
    await waitForDone(first);
    await first.close();
    await new Promise((done) => setTimeout(done, 500)); // the page's connection gone
    sketch.save(timer.replace('[1, 0.32, 0.36]', '[0.2, 0.9, 0.3]'));
    await new Promise((done) => setTimeout(done, 500)); // the reload sent, to no page
    const page = await context.newPage();
    let loads = 0;
    page.on('framenavigated', (frame) => { if (frame === page.mainFrame()) loads += 1; });
    await page.goto(sketch.url);
    await waitForDone(page);
    await page.waitForTimeout(1500);
    expect(loads).toBe(1);
    const [r, g] = await page.locator('[data-tracer]').evaluate((c) => [...c.getContext('2d').getImageData(32, 24, 1, 1).data]);
    expect(g, 'the saved, green sphere').toBeGreaterThan(r + 40);
  } finally {
    sketch.remove();
  }
});

test('five swaps: no reload, and the page holds what it held after the first load', async ({ page }) => {
  const extra = [
    '    window.view = view;',
    "    p.createButton('Again').id('again');",
    '    p.mousePressed = () => { window.presses = (window.presses ?? 0) + 1; };',
  ].join('\n');
  const source = (sphere) => sketchSource({ sphere, after: extra }).replace('width: 64, height: 48 }), grid: true', 'width: 400, height: 300 }), workers: 2');
  const sketch = liveSketch('live-swap-five', source(PINK));
  try {
    await page.addInitScript(countWorkersAndFrames);
    const cdp = await page.context().newCDPSession(page);
    await page.goto(sketch.url);
    await waitForDone(page);
    await page.evaluate(() => { window.setByThePage = 'still here'; });
    const first = await holdings(page, cdp);
    expect(first.canvases).toBeGreaterThan(0);
    expect(first.workers).toBe(2);
    // Listeners on window and document: the same, but for p5's wait for the page's load (a sketch made after it has none).
    const listeners = first.listeners.filter((l) => l !== 'window:load');

    for (let i = 0; i < 5; i++) {
      expect(await saveAndWaitForUpdate(page, sketch, source(i % 2 ? PINK : GREEN), 300)).toBe('swap');
      await waitForDone(page);
    }
    expect(await page.evaluate(() => [window.setByThePage, window.__sketchbookSwaps])).toEqual(['still here', 5]);
    await expect(page.locator('[data-sketchbook-ghost]')).toHaveCount(0);
    const after = await holdings(page, cdp);
    expect({ ...after, listeners: undefined }).toEqual({ ...first, listeners: undefined });
    expect(after.listeners.filter((l) => l !== 'window:load')).toEqual(listeners);

    // One click: one press heard, by the new sketch alone, and its pixel selected.
    await clickPixel(page.locator('[data-tracer]'), 200, 150);
    expect(await page.evaluate(() => window.presses)).toBe(1);
    await expect(page.locator('[data-inspector] [data-answer]')).toHaveText(/^Pixel: 200,150; /);
    await expect(page.locator('#again')).toHaveCount(1);
  } finally {
    sketch.remove();
  }
});

test('a swap that breaks setup keeps the last good picture under the panel; the fix clears both', async ({ page }) => {
  const sketch = liveSketch('live-swap-mistake', sketchSource());
  try {
    await page.goto(sketch.url);
    await waitForDone(page);
    expect(await saveAndWaitForUpdate(page, sketch, sketchSource({ sphere: 'new Sphere([0, 0, -20], "4")' }))).toBe('swap');
    await expect(page.locator('[data-error-message]')).toContainText('radius must be a finite number, got "4"');
    await expect(page.locator('body')).toHaveAttribute('data-render', 'error');
    const ghost = page.locator('canvas[data-sketchbook-ghost]');
    await expect(ghost).toHaveCount(1);
    const centre = await ghost.evaluate((c) => [...c.getContext('2d').getImageData(32, 24, 1, 1).data]);
    expect(centre[0]).toBeGreaterThan(centre[2] + 40); // the pink sphere of the last good picture
    expect(await ghost.isVisible()).toBe(true);

    expect(await saveAndWaitForUpdate(page, sketch, sketchSource({ sphere: GREEN }))).toBe('swap');
    await waitForDone(page);
    await expect(page.locator('[data-error]')).toHaveCount(0);
    await expect(ghost).toHaveCount(0);
    const now = await page.locator('[data-tracer]').evaluate((c) => [...c.getContext('2d').getImageData(32, 24, 1, 1).data]);
    expect(now[1]).toBeGreaterThan(now[0] + 40); // the new, green sphere
  } finally {
    sketch.remove();
  }
});

test('a sketch that changed the page outside p5 is reloaded, and shows its new version', async ({ page }) => {
  const touch = "    document.querySelector('h1').textContent = 'Changed by the sketch';";
  const sketch = liveSketch('live-swap-outside', sketchSource({ before: touch }));
  try {
    await page.goto(sketch.url);
    await waitForDone(page);
    expect(await saveAndWaitForUpdate(page, sketch, sketchSource({ before: touch, sphere: GREEN }))).toBe('reload');
    await waitForDone(page);
    const centre = await page.locator('[data-tracer]').evaluate((c) => [...c.getContext('2d').getImageData(32, 24, 1, 1).data]);
    expect(centre[1]).toBeGreaterThan(centre[0] + 40);
  } finally {
    sketch.remove();
  }
});

test('a save of a module the sketch imports, or of a sketch that imports one, reloads its page', async ({ page }) => {
  const helper = resolve('tests/e2e/pages/live-swap-helper.js');
  writeFileSync(helper, 'export const RADIUS = 4;\n');
  const withHelper = (sphere) => sketchSource({ sphere }).replace("import p5 from 'p5';", "import p5 from 'p5';\nimport { RADIUS } from './live-swap-helper.js';");
  const sketch = liveSketch('live-swap-imports', withHelper('new Sphere([0, 0, -20], RADIUS, { color: [1, 0.32, 0.36] })'));
  try {
    await page.goto(sketch.url);
    await waitForDone(page);
    expect(await saveAndWaitForUpdate(page, { save: (text) => writeFileSync(helper, text) }, 'export const RADIUS = 6;\n')).toBe('reload');
    await waitForDone(page);
    expect(await saveAndWaitForUpdate(page, sketch, withHelper(GREEN))).toBe('reload');
    await waitForDone(page);
  } finally {
    sketch.remove();
    rmSync(helper, { force: true });
  }
});

test('a sketch in global mode is reloaded', async ({ page }) => {
  const global = (color) => `import p5 from 'p5';
import { Scene, Sphere, Camera } from '../../../lib/index.js';
import '../../../lib/p5/index.js';
window.setup = () => {
  noCanvas();
  createTracerView({ scene: new Scene().add(new Sphere([0, 0, -20], 4, { color: ${color} })), camera: new Camera({ width: 64, height: 48 }) });
};
new p5();
`;
  const sketch = liveSketch('live-swap-global', global('[1, 0.32, 0.36]'));
  try {
    await page.goto(sketch.url);
    await waitForDone(page);
    expect(await saveAndWaitForUpdate(page, sketch, global('[0.2, 0.9, 0.3]'))).toBe('reload');
    await waitForDone(page);
    await expect(page.locator('canvas[data-tracer]')).toHaveCount(1);
  } finally {
    sketch.remove();
  }
});
