// The tracer view and the inspector panel on the class scene at 64×48:
// clicks land on the right traced pixel whatever the on-screen scale, the
// panel shows exactly what inspectPixel computes, arrow keys move the
// selection, body[data-render] follows every (re)render, and the canvas
// holds the traced picture only.
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, expectQuietConsole, waitForDone } from './helpers.js';

const PAGE = '/tests/e2e/pages/inspector.html';
const WIDTH = 64, HEIGHT = 48;
const ANSWER = /^Pixel: \d+,\d+; H: -?\d+\.\d; V: -?\d+\.\d$/;

expectQuietConsole(test);

/** Opens the test page (optionally with ?query) and waits for the picture. */
async function open(page, query = '') {
  await page.goto(PAGE + query);
  await waitForDone(page);
}

/** The lesson's answer line for a record, computed here independently of the panel's code. */
function expectedAnswer({ x, y, h, v }) {
  const angle = (a) => (Math.abs(a) < 0.05 ? 0 : a).toFixed(1);
  return `Pixel: ${x},${y}; H: ${angle(h)}; V: ${angle(v)}`;
}

/** inspectPixel for (x, y) in the page, reduced to plain numbers the panel should show. */
function inspectInPage(page, x, y) {
  return page.evaluate(([x, y]) => {
    const r = window.lib.inspectPixel(window.view.scene, window.view.camera, x, y);
    return {
      x: r.x, y: r.y, h: r.h, v: r.v, color: r.color,
      hit: r.hit && { t: r.hit.t, incidence: r.hit.incidence, name: r.hit.object.name },
      tests: r.tests.map(({ quadratic: q, geometric: g }) => ({
        quadratic: { A: q.A, B: q.B, C: q.C, discriminant: q.discriminant, t0: q.t0, t1: q.t1, roots: q.roots },
        geometric: { tca: g.tca, d2: g.d2, thc: g.thc, t0: g.t0, t1: g.t1, L: [g.L.x, g.L.y, g.L.z] },
      })),
    };
  }, [x, y]);
}

/** Every value the panel shows, by its data attributes, as full-precision strings. */
function panelValues(page) {
  return page.locator('[data-inspector]').evaluate((panel) => {
    const values = {};
    for (const el of panel.querySelectorAll('[data-field]')) {
      const key = [el.dataset.route, el.dataset.sphere, el.dataset.light, el.dataset.field].filter((k) => k !== undefined).join('.');
      values[key] = el.dataset.value;
    }
    return values;
  });
}

/** The panel must hold inspectPixel's numbers exactly (full precision in data-value). */
async function expectPanelMatches(page, x, y) {
  const r = await inspectInPage(page, x, y);
  await expect(page.locator('[data-answer]')).toHaveText(expectedAnswer(r));
  const values = await panelValues(page);
  const str = (n) => (n === null ? '' : String(n));
  expect(values.h).toBe(String(r.h));
  expect(values.v).toBe(String(r.v));
  r.tests.forEach(({ quadratic: q, geometric: g }, i) => {
    for (const f of ['A', 'B', 'C', 'discriminant', 't0', 't1']) expect(values[`quadratic.${i}.${f}`], `sphere ${i} ${f}`).toBe(str(q[f]));
    expect(values[`quadratic.${i}.meaning`]).toBe(String(q.roots));
    for (const f of ['tca', 'd2', 'thc', 't0', 't1']) expect(values[`geometric.${i}.${f}`], `sphere ${i} ${f}`).toBe(str(g[f]));
    expect(values[`geometric.${i}.L`]).toBe(g.L.join(','));
    expect(values[`geometric.${i}.agree`]).toBe('true'); // the class scene's rays are never tangent
  });
  expect(values['hit-object']).toBe(r.hit ? r.hit.name : '');
  if (r.hit) {
    expect(values['hit-t']).toBe(String(r.hit.t));
    expect(values.incidence).toBe(String(r.hit.incidence));
  }
  const hex = '#' + r.color.map((c) => c.toString(16).padStart(2, '0')).join('');
  expect(values.hex).toBe(hex);
  expect(await page.locator('[data-field="swatch"]').evaluate((el) => getComputedStyle(el).backgroundColor)).toBe(`rgb(${r.color.join(', ')})`);
  return r;
}

test('body[data-render] goes rendering → done, and the canvas states its traced size', async ({ page }) => {
  await page.addInitScript(() => {
    window.renderStates = [];
    new MutationObserver(() => {
      const state = document.body?.dataset.render;
      if (state && state !== window.renderStates.at(-1)) window.renderStates.push(state);
    }).observe(document, { attributes: true, attributeFilter: ['data-render'], subtree: true });
  });
  await open(page);
  expect(await page.evaluate(() => window.renderStates)).toEqual(['rendering', 'done']);
  const canvas = page.locator('canvas[data-tracer]');
  await expect(canvas).toHaveAttribute('data-width', String(WIDTH));
  await expect(canvas).toHaveAttribute('data-height', String(HEIGHT));
  expect(await canvas.evaluate((c) => [c.width, c.height, getComputedStyle(c).imageRendering])).toEqual([WIDTH, HEIGHT, 'pixelated']);
  await expect(page.locator('[data-progress-text]')).toHaveText(/^100% · [\d.]+[kM]? rays\/s$/);
});

for (const scale of [5, 9.5]) {
  test(`clicks select the right pixel at ${scale} screen px per pixel, and the panel equals inspectPixel`, async ({ page }) => {
    await open(page, `?scale=${scale}`);
    const box = await page.locator('[data-tracer]').boundingBox();
    expect(box.width).toBeCloseTo(WIDTH * scale, 0);
    for (const [x, y] of [[10, 12], [32, 20], [0, 0], [63, 47], [50, 33]]) {
      await clickPixel(page.locator('[data-tracer]'), x, y);
      expect(await page.evaluate(() => window.view.selected)).toEqual({ x, y });
      await expect(page.locator('[data-answer]')).toHaveText(ANSWER);
      await expectPanelMatches(page, x, y);
    }
  });
}

test('changing the scale keeps clicks on the right pixel (auto, then a fixed scale)', async ({ page }) => {
  await open(page);
  for (const scale of ['auto', 3, 12]) {
    await page.evaluate((s) => window.view.setScale(s), scale);
    await clickPixel(page.locator('[data-tracer]'), 21, 17);
    expect(await page.evaluate(() => window.view.selected)).toEqual({ x: 21, y: 17 });
    await page.evaluate(() => window.view.select(null));
  }
  // A click near a pixel's corner still belongs to that pixel.
  const canvas = page.locator('[data-tracer]');
  const k = (await canvas.boundingBox()).width / WIDTH;
  await canvas.click({ position: { x: 7 * k + 1, y: 9 * k + 1 } });
  expect(await page.evaluate(() => window.view.selected)).toEqual({ x: 7, y: 9 });
  await canvas.click({ position: { x: 8 * k - 1, y: 10 * k - 1 } });
  expect(await page.evaluate(() => window.view.selected)).toEqual({ x: 7, y: 9 });
});

test('arrow keys move the selected pixel and the panel follows', async ({ page }) => {
  await open(page, '?scale=6');
  await clickPixel(page.locator('[data-tracer]'), 10, 12);
  const moves = [['ArrowRight', 11, 12], ['ArrowDown', 11, 13], ['ArrowLeft', 10, 13], ['ArrowUp', 10, 12], ['Shift+ArrowRight', 20, 12]];
  for (const [key, x, y] of moves) {
    await page.keyboard.press(key);
    expect(await page.evaluate(() => window.view.selected)).toEqual({ x, y });
    await expectPanelMatches(page, x, y);
  }
  // The edge stops the selection; it never leaves the picture.
  await page.evaluate(() => window.view.select(0, 0));
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('ArrowUp');
  expect(await page.evaluate(() => window.view.selected)).toEqual({ x: 0, y: 0 });
  await expect(page.locator('[data-answer]')).toHaveText(ANSWER);
});

test('the panel explains a pink pixel: hit, lights, colour name and both routes', async ({ page }) => {
  await open(page, '?scale=6');
  await clickPixel(page.locator('[data-tracer]'), 32, 20); // the middle of the big pink sphere
  const panel = page.locator('[data-inspector]');
  await expect(panel.locator('[data-field="color-name"]')).toHaveText('pink');
  await expect(panel.locator('[data-field="hit-object"]')).toHaveText('pink');
  await expect(panel.locator('[data-route="quadratic"][data-sphere="1"][data-field="meaning"]')).toHaveText('two hits');
  await expect(panel.locator('[data-route="quadratic"][data-sphere="2"][data-field="meaning"]')).toHaveText('no hit');
  await expect(panel.locator('[data-route="quadratic"][data-sphere="2"][data-field="t0"]')).toHaveText('—');
  await expect(panel.locator('[data-field="agree"]')).toHaveText(Array(7).fill('✓'));
  // One row per light, each saying whether its shadow ray was blocked.
  expect(await panel.locator('[data-field="in-shadow"]').count()).toBe(2);
  // Numbers are short: at most 4 significant digits after the point.
  for (const text of await panel.locator('[data-field="discriminant"]').allTextContents()) expect(text).toMatch(/^-?\d+(\.\d{1,4})?(e-?\d+)?$/);
});

test('a new scene restarts the render without a reload, ends done, and the panel follows', async ({ page }) => {
  await open(page, '?scale=6');
  await clickPixel(page.locator('[data-tracer]'), 32, 20);
  await page.evaluate(() => { window.notReloaded = true; });
  const state = await page.evaluate(() => {
    const { Scene, Sphere } = window.lib;
    const scene = new Scene({ background: [0, 0, 0.2] });
    const sphere = new Sphere([0, 0, -10], 2, { color: [0, 1, 0] });
    sphere.name = 'green';
    scene.add(sphere);
    window.view.setScene(scene);
    return document.body.dataset.render;
  });
  expect(state).toBe('rendering');
  await waitForDone(page);
  expect(await page.evaluate(() => window.notReloaded)).toBe(true);
  await expect(page.locator('[data-field="hit-object"]')).toHaveText('green');
  await expectPanelMatches(page, 32, 20);
  // The picture is the new scene's: the canvas equals render() of it, byte for byte.
  expect(await page.evaluate(canvasEqualsRender)).toBe(true);

  // A new camera of another size: the traced resolution changes, the selection stays inside.
  await page.evaluate(() => window.view.setCamera(new window.lib.Camera({ width: 16, height: 12 })));
  await waitForDone(page);
  await expect(page.locator('[data-tracer]')).toHaveAttribute('data-width', '16');
  expect(await page.evaluate(() => window.view.selected)).toEqual({ x: 15, y: 11 });
});

test('a light that fades with distance says by how much on its row; one that does not, nothing', async ({ page }) => {
  await open(page, '?scale=6');
  const expected = await page.evaluate(() => {
    const { Scene, Sphere, PointLight, inspectPixel } = window.lib;
    const scene = new Scene().add(new Sphere([0, 0, -10], 3, { color: [1, 0.5, 0.5] }))
      .add(new PointLight([2, 3, 0], { attenuation: 0.04 })).add(new PointLight([-2, 3, 0]));
    window.view.setScene(scene);
    const light = inspectPixel(scene, window.view.camera, 32, 24).hit.lights[0];
    return { falloff: String(light.falloff), factor: light.falloff };
  });
  await waitForDone(page);
  await clickPixel(page.locator('[data-tracer]'), 32, 24);
  const panel = page.locator('[data-inspector]');
  const fading = panel.locator('[data-field="falloff"]');
  await expect(fading).toHaveCount(1); // the second light does not fade: no words for it
  await expect(fading).toHaveAttribute('data-light', '0');
  await expect(fading).toHaveAttribute('data-value', expected.falloff);
  await expect(fading).toHaveText(/^falloff ×0\.\d+ at distance \d+(\.\d+)?$/);
  expect(expected.factor).toBeGreaterThan(0);
  expect(expected.factor).toBeLessThan(1);
});

test('the traced canvas is render()\'s picture exactly, and exports as a PNG at traced size', async ({ page }) => {
  await open(page, '?scale=6&grid=1');
  await clickPixel(page.locator('[data-tracer]'), 5, 5); // a crosshair and the grid are drawn: not into the picture
  expect(await page.evaluate(canvasEqualsRender)).toBe(true);
  const size = await page.evaluate(() => new Promise((resolve) => {
    const img = new Image();
    img.onload = () => resolve([img.naturalWidth, img.naturalHeight]);
    img.src = window.view.toPNG();
  }));
  expect(size).toEqual([WIDTH, HEIGHT]);
});

test('Copy CSV puts the pixel\'s table in the panel (header + one row per sphere)', async ({ page }) => {
  await open(page, '?scale=6');
  await clickPixel(page.locator('[data-tracer]'), 32, 20);
  await page.locator('[data-copy-csv]').click();
  await expect(page.locator('[data-copy-status]')).not.toHaveText('');
  const lines = (await page.locator('[data-csv]').inputValue()).trim().split('\n');
  expect(lines).toHaveLength(1 + 7);
  expect(lines[0]).toMatch(/^x,y,H,V,sphere,A,B,C,discriminant,roots,meaning,t0,t1,/);
  expect(lines[2]).toMatch(/^32,20,-?\d+\.\d,-?\d+\.\d,pink,1,/);
  expect(lines[2]).toContain(',two hits,');
});

test('the traced canvas screenshot holds the picture only (no grid, no crosshair)', async ({ page }) => {
  await open(page, '?scale=8');
  const canvas = page.locator('canvas[data-tracer]');
  await expectCanvasScreenshot(canvas, 'class-scene-64x48.png');
  // With the grid and a selection the overlay draws on top; hidden, the picture beneath is unchanged.
  await page.evaluate(() => { window.view.setGrid(true); window.view.select(40, 30); });
  await page.addStyleTag({ content: '[data-overlay] { visibility: hidden !important; }' });
  await expectCanvasScreenshot(canvas, 'class-scene-64x48.png');
});

/** In the page: does the data-tracer canvas hold exactly render(scene, camera)? */
function canvasEqualsRender() {
  const { view } = window;
  const c = document.querySelector('canvas[data-tracer]');
  const got = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  const want = window.lib.render(view.scene, view.camera);
  return got.length === want.length && got.every((b, i) => b === want[i]);
}
