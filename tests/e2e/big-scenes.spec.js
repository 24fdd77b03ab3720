// Big scenes (1,000 spheres) in sketch 05: a click on a pixel and the value
// boxes stay responsive. The inspector shows the rows that matter (the hit,
// the nearest misses) with the rest on demand; the form shows a page of rows
// and adds a sphere as one new row. Long tasks are measured in the page
// (PerformanceObserver 'longtask'); the structural checks (row counts) are
// the ones that fail first, the time limit has room for a loaded machine.
import { test, expect } from '@playwright/test';
import { watchConsole, waitForDone, clickPixel } from './helpers.js';
import { Scene, Sphere } from '../../lib/index.js';
import { sceneToJSON } from '../../lib/serialize.js';
import { encodeSceneLink } from '../../lib/p5/scene-link.js';
import { SPHERE_ROWS } from '../../lib/p5/inspector.js';
import { FORM_ROWS } from '../../lib/p5/scene-form.js';

const SPHERES = 1000;
// ms, the median step. Not the speed goal (50 ms: measured and reported in the
// annotation, docs/security.md), which a busy two-core machine cannot promise: a
// guard against the page building the whole scene or every table again, which
// took seconds a step.
const LONG_TASK_LIMIT = 1000;
const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];

/** 1,000 spheres: 999 small ones in a wall in front of the camera, and a light sphere above (an emissive sphere is a light). */
function wall() {
  const scene = new Scene({ background: [0.9, 0.9, 1] });
  for (let i = 0; i < SPHERES - 1; i++) {
    const col = i % 40, row = Math.floor(i / 40);
    scene.add(Object.assign(new Sphere([(col - 19.5) * 0.6, (row - 12) * 0.6, -45], 0.25, { color: [col / 40, row / 25, 0.5] }), { name: `ball ${i}` }));
  }
  scene.add(Object.assign(new Sphere([0, 30, -20], 1, { color: [0, 0, 0], emission: 1 }), { name: 'sun' }));
  return sceneToJSON(scene);
}

/** Longest task since the last call (the observer starts with the page), once the page has painted and settled. */
async function longestTaskSince(page) {
  return page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(() => {
    const t = window.longestTask;
    window.longestTask = 0;
    resolve(Math.round(t));
  }, 200)))));
}

test.describe('1,000 spheres in sketch 05', () => {
  test.beforeEach(async ({ page }) => {
    await page.addInitScript(() => {
      window.longestTask = 0;
      new PerformanceObserver((list) => {
        for (const e of list.getEntries()) window.longestTask = Math.max(window.longestTask, e.duration);
      }).observe({ type: 'longtask', buffered: true });
    });
  });

  test('a click shows the rows that matter, the rest on demand; the form a page of rows', async ({ page }) => {
    test.setTimeout(180_000); // tracing 1,000 spheres, and every row on demand, on a busy machine
    const errors = watchConsole(page);
    await page.goto(`/sketches/05-value-boxes.html#scene=${await encodeSceneLink(wall())}`);
    await waitForDone(page, 60_000);
    const loading = await longestTaskSince(page);

    // The form: a page of rows, and more on demand.
    const rows = page.locator('[data-table="sphere"] tbody tr');
    await expect(rows).toHaveCount(FORM_ROWS);
    await page.locator('[data-show-more="sphere"]').click();
    await expect(rows).toHaveCount(2 * FORM_ROWS);
    await expect(page.locator('[data-show-more="sphere"]')).toHaveText(`Show ${FORM_ROWS} more (${SPHERES - 2 * FORM_ROWS} not shown)`);

    // A click: the hit and the nearest misses, not 1,000 rows.
    await longestTaskSince(page);
    const canvas = page.locator('[data-tracer]');
    await clickPixel(canvas, 80, 60);
    const panel = page.locator('[data-inspector]');
    await expect(panel).toHaveAttribute('data-x', '80');
    const quadraticRows = panel.locator('[data-route="quadratic"][data-field="meaning"]');
    await expect(quadraticRows).toHaveCount(SPHERE_ROWS);
    const click = await longestTaskSince(page);
    const hit = await panel.locator('[data-field="hit-object"]').textContent();
    expect(hit).toMatch(/^ball \d+$/);
    await expect(panel.locator('.rt-hit-row')).toHaveCount(2); // the hit sphere's row, in both tables
    await expect(panel.locator('.rt-hit-row').first().locator('th')).toHaveText(hit);

    // Arrow keys move along: the longest task of each step, and their median (one slow step on a busy machine is no verdict).
    await canvas.focus();
    const steps = [];
    for (let i = 1; i <= 5; i++) {
      await page.keyboard.press('ArrowRight');
      await expect(panel).toHaveAttribute('data-x', String(80 + i));
      steps.push(await longestTaskSince(page));
    }
    const arrows = median(steps);

    // Adding a sphere: a row when its table shows all its rows, else the page of rows again; the scene is not checked and built whole again.
    // (Located by its data-add, not by role: finding a button by role walks the whole page's accessibility tree, in the page's time.)
    const firstRow = await rows.first().elementHandle();
    const adds = [];
    for (let i = 1; i <= 3; i++) {
      await longestTaskSince(page);
      await page.locator('[data-add="Add sphere"]').click();
      await expect(page.locator('[data-show-more="sphere"]')).toHaveText(`Show ${FORM_ROWS} more (${SPHERES + i - 2 * FORM_ROWS} not shown)`);
      adds.push(await longestTaskSince(page));
    }
    await expect(rows).toHaveCount(2 * FORM_ROWS); // the new rows are among those not shown yet…
    expect(await firstRow.evaluate((row) => row.isConnected)).toBe(true); // …and the shown rows were not built again

    // Typing a value into one box (Enter): the picture is traced again with it.
    const typed = [];
    for (const value of ['0.3', '0.35', '0.4']) {
      const radius = page.locator('input[name="objects[5].radius"]');
      await radius.fill(value);
      await longestTaskSince(page);
      await radius.press('Enter');
      await waitForDone(page, 60_000);
      typed.push(await longestTaskSince(page));
    }
    await expect(page.locator('[data-message-for="objects[5].radius"]')).toBeEmpty();

    // On demand: every sphere.
    await panel.locator('[data-show-all-spheres]').first().click();
    await expect(quadraticRows).toHaveCount(SPHERES + 3);
    const all = await longestTaskSince(page);

    test.info().annotations.push({ type: 'longest task (ms)', description: `loading ${loading}, click ${click}, arrow steps ${steps.join('/')} (median ${arrows}), Add sphere ${adds.join('/')} (median ${median(adds)}), a typed value ${typed.join('/')} (median ${median(typed)}), every row on demand ${all}` });
    expect(arrows).toBeLessThan(LONG_TASK_LIMIT);
    expect(median(adds)).toBeLessThan(LONG_TASK_LIMIT);
    expect(median(typed)).toBeLessThan(LONG_TASK_LIMIT);
    expect(errors).toEqual([]);
  });

  test('a sphere added to a table that shows all its rows is one new row', async ({ page }) => {
    await page.goto('/sketches/05-value-boxes.html');
    await waitForDone(page);
    const rows = page.locator('[data-table="sphere"] tbody tr');
    const before = await rows.count();
    const first = await rows.first().elementHandle();
    await page.getByRole('button', { name: 'Add sphere' }).click();
    await expect(rows).toHaveCount(before + 1);
    expect(await first.evaluate((row) => row.isConnected)).toBe(true); // the old rows were kept, not built again
    await expect(rows.last().locator('input').first()).toHaveAttribute('name', /^objects\[\d+\]\.center\.0$/);
  });
});
