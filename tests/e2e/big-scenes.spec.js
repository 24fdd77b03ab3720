// Big scenes (1,000 spheres) in sketch 05: a click on a pixel and the value
// boxes stay responsive. The inspector shows the rows that matter (the hit,
// the nearest misses) with the rest on demand; the form shows a page of rows
// and adds a sphere as one new row. Long tasks are measured in the page
// (PerformanceObserver 'longtask'); the structural checks (row counts) are
// the ones that fail first, the time limit has room for a loaded machine.
import { test, expect } from '@playwright/test';
import { watchConsole, waitForDone, clickPixel } from './helpers.js';
import { Scene, Sphere, Plane, Cylinder, Mesh, AreaLight, PointLight, classScene } from '../../lib/index.js';
import { MAX_SHADOW_RAYS, MAX_SCENE_TRIANGLES } from '../../lib/scene/work.js';
import { sceneToJSON } from '../../lib/scene/json.js';
import { encodeSceneLink } from '../../lib/p5/page/scene-link.js';
import { SPHERE_ROWS } from '../../lib/p5/pixel/inspector.js';
import { FORM_ROWS } from '../../lib/p5/controls/scene-form.js';
import { MAX_SCENE_OBJECTS } from '../../lib/scene/codec.js';
import { BOX_CHARS } from '../../lib/p5/controls/text-box.js';

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

/** `n` spheres: a grid in front of the camera (radius 0.12, 0.3 apart), named, and a light sphere above. */
function grid(n) {
  const scene = new Scene({ background: [0.9, 0.9, 1] });
  for (let i = 0; i < n - 1; i++) {
    const col = i % 100, row = Math.floor(i / 100);
    scene.add(Object.assign(new Sphere([(col - 49.5) * 0.3, (row - 50) * 0.3, -60], 0.12, { color: [col / 100, row / 100, 0.5] }), { name: `ball ${i}` }));
  }
  scene.add(Object.assign(new Sphere([0, 30, -20], 1, { color: [0, 0, 0], emission: 1 }), { name: 'sun' }));
  return sceneToJSON(scene);
}

// At the limit every action is a task under 200 ms: opening the link, a click, every sphere in the inspector (its rows
// in view only), the form's rows, the CSV, the code (both built in slices, shown cut), removing a row. Each step is traced
// (Chromium's trace of its tasks): the verdict is each task's time on the page's main thread, its CPU time, which
// other work on a shared machine does not stretch; the wall-clock time is reported beside it in the annotation.
/** Runs `step` with Chromium tracing the page; resolves with its longest main-thread task, `{ cpu, wall }` in ms. */
async function longestTaskOf(page, step) {
  const browser = page.context().browser();
  await browser.startTracing(page, { categories: ['toplevel', '__metadata'] }); // tasks and threads only: a fuller trace slows the page it measures
  let trace;
  try {
    await step();
    await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(resolve, 200)))));
  } finally {
    trace = JSON.parse(String(await browser.stopTracing())).traceEvents;
  }
  const main = new Set(trace.filter((e) => e.name === 'thread_name' && e.args.name === 'CrRendererMain').map((e) => `${e.pid}:${e.tid}`));
  const tasks = trace.filter((e) => e.name === 'ThreadControllerImpl::RunTask' && e.ph === 'X' && main.has(`${e.pid}:${e.tid}`));
  const longest = (key) => Math.round(Math.max(0, ...tasks.map((e) => e[key] ?? e.dur)) / 1000);
  return { cpu: longest('tdur'), wall: longest('dur') };
}

/**
 * Waits in the page until `condition(arg)` is true, a cheap test every 50 ms. Not expect(locator)…: while such an
 * expectation fails, Playwright (1.65) writes an ARIA snapshot of the element, or of the whole page when the element is
 * not visible (an empty status line), to show in its message. At 10,000 spheres that snapshot was the one long task
 * of "Copy CSV", "Copy scene as code" and "Remove" (170-370 ms, in the page's main thread but Playwright's work, not
 * the page's: a CPU profile shows getTextAlternativeInternal, toAriaNode, renderAriaSnapshotAsYaml).
 */
function until(page, condition, arg) {
  return page.waitForFunction(condition, arg, { polling: 50, timeout: 120_000 });
}

test.describe(`${MAX_SCENE_OBJECTS.toLocaleString('en')} spheres (the limit) in sketch 05`, () => {
  const TASK_LIMIT = 200; // ms of the main thread's time

  test('every action works at the limit, the big tables in view only (under 200 ms a task: npm run bench:big-scene)', async ({ page }) => {
    test.setTimeout(300_000); // tracing 10,000 spheres twice on a busy machine
    const errors = watchConsole(page);
    const N = MAX_SCENE_OBJECTS;
    const link = `/sketches/05-value-boxes.html#scene=${await encodeSceneLink(grid(N))}`;
    const tasks = {};
    const step = async (name, action) => { tasks[name] = await longestTaskOf(page, action); };
    await page.goto('/sketches/05-value-boxes.html?before'); // p5 and the page's modules loaded once (another URL: the link loads the page again)
    await waitForDone(page);

    await step('open', async () => {
      await page.goto(link);
      await waitForDone(page, 120_000);
    });
    await expect(page.locator('[data-link-problem]')).toBeEmpty();

    // A click: the rows that matter.
    const panel = page.locator('[data-inspector]');
    const quadraticRows = panel.locator('[data-route="quadratic"][data-field="meaning"]');
    await step('click', async () => {
      await clickPixel(page.locator('[data-tracer]'), 80, 60);
      await expect(panel).toHaveAttribute('data-x', '80');
      await expect(quadraticRows).toHaveCount(SPHERE_ROWS);
    });

    // Every sphere on demand: a table of 10,000 rows keeps those in view only, and scrolls.
    const quadratic = panel.locator('.rt-virtual').first();
    await step('show all', async () => {
      await panel.locator('[data-show-all-spheres]').first().click();
      await expect(quadratic.locator('table')).toHaveAttribute('aria-rowcount', String(N + 1));
    });
    expect(await quadratic.locator('tbody tr:not(.rt-spacer)').count()).toBeLessThan(100);
    await step('scroll', async () => {
      await quadratic.evaluate((box) => { box.scrollTop = box.scrollHeight / 2; });
      await expect(quadratic.locator('tr[aria-rowindex="5002"]')).toHaveCount(1);
    });
    await expect(quadratic.locator('tr[aria-rowindex="5002"] th')).toHaveText('ball 5000');
    expect(await quadratic.locator('tbody tr:not(.rt-spacer)').count()).toBeLessThan(100);

    // The form's rows: a page more.
    const formRows = page.locator('[data-table="sphere"] tbody tr');
    await step('form rows', async () => {
      await page.locator('[data-show-more="sphere"]').click();
      await expect(formRows).toHaveCount(2 * FORM_ROWS);
    });

    // CSV and code: built in slices, the boxes cut.
    await step('csv', async () => {
      await page.locator('[data-copy-csv]').click();
      await until(page, () => document.querySelector('[data-copy-status]').textContent !== ''); // slices wait for the page's turns
    });
    expect((await page.locator('[data-csv]').inputValue()).length).toBeLessThanOrEqual(BOX_CHARS);
    await expect(page.locator('[data-csv-note]')).toContainText(`of ${(N + 1).toLocaleString('en')} lines`);
    await step('code', async () => {
      await page.locator('.share button', { hasText: 'Copy scene as code' }).click();
      await until(page, () => document.querySelector('[data-scene-code-note]').textContent.includes('The box shows the first'));
    });
    expect((await page.locator('[data-scene-code]').inputValue()).length).toBeLessThanOrEqual(BOX_CHARS);

    // Remove a row: the scene has one sphere fewer, the picture is traced again.
    await step('remove', async () => {
      await page.evaluate(() => { // the picture is traced again: body[data-render] leaves "done", then comes back
        window.retraced = false;
        new MutationObserver((_, observer) => { if (document.body.dataset.render !== 'done') { window.retraced = true; observer.disconnect(); } })
          .observe(document.body, { attributes: true, attributeFilter: ['data-render'] });
      });
      await page.locator('[data-table="sphere"] [data-remove]').first().click();
      await until(page, (text) => document.querySelector('[data-show-more="sphere"]').textContent === text,
        `Show ${FORM_ROWS} more (${(N - 1 - 2 * FORM_ROWS).toLocaleString('en')} not shown)`);
      await until(page, () => window.retraced && document.body.dataset.render === 'done');
    });

    test.info().annotations.push({ type: 'longest task, main-thread ms (wall-clock ms)', description: Object.entries(tasks).map(([k, { cpu, wall }]) => `${k} ${cpu} (${wall})`).join(', ') });
    // The time targets are a benchmark's (npm run bench:big-scene, on a quiet machine): in a full run on two workers
    // opening the link once took a 242 ms task (about 100 alone); here the steps must work, their times reported.
    if (process.env.RT_BENCH) {
      for (const [name, { cpu }] of Object.entries(tasks)) expect(cpu, `the longest task of "${name}"`).toBeLessThan(TASK_LIMIT);
    }
    expect(errors).toEqual([]);
  });

  test('a link of 175,000 spheres is refused, the limit named, and the class scene shown', async ({ page }) => {
    test.setTimeout(120_000);
    const errors = watchConsole(page);
    const json = { objects: Array.from({ length: 175_000 }, () => ({ type: 'sphere', center: [0, 0, 0], radius: 1 })) }; // a 38 kB link
    await page.goto(`/sketches/05-value-boxes.html#scene=${await encodeSceneLink(json)}`);
    await expect(page.locator('[data-link-problem]')).toHaveText(
      `The scene in this link could not be read (the scene has 175,000 objects, more than the ${MAX_SCENE_OBJECTS.toLocaleString('en')} a scene from a link or a paste may have), so here is the class scene.`,
      { timeout: 60_000 });
    await waitForDone(page, 60_000);
    await expect(page.locator('[data-table="sphere"] tbody tr')).toHaveCount(7); // the class scene's spheres
    expect(errors).toEqual([]);
  });
});

/** Scenes at the limits of work (lib/scene/work.js), each over a floor: the most shadow rays, the most triangles, the most cylinders. */
const AT_THE_LIMITS = {
  'the class scene (for comparison)': () => sceneToJSON(classScene()),
  'area lights': () => {
    const scene = new Scene({ background: [0.8, 0.9, 1] }).add(new Plane([0, -2, 0], [0, 1, 0], { color: 'white' })).add(new Sphere([0, 0, -12], 2, { color: 'pink' }));
    for (let i = 0; i < MAX_SHADOW_RAYS / 64; i++) scene.add(new AreaLight([i - 8, 12, -10], 1, { samples: 64, intensity: 1 / 16 }));
    return sceneToJSON(scene);
  },
  meshes: () => {
    const scene = new Scene({ background: [0.8, 0.9, 1] }).add(new PointLight([0, 20, 0]));
    const per = 800, meshes = MAX_SCENE_TRIANGLES / per;
    for (let m = 0; m < meshes; m++) {
      const positions = [], cells = [];
      for (let i = 0; i < per + 2; i++) positions.push([(m % 5) * 3 - 6 + (i % 2) * 0.5, Math.floor(m / 5) * 2 - 5 + (i / per) * 1.5, -30 - (i % 3) * 0.1]);
      for (let i = 0; i < per; i++) cells.push([i, i + 1, i + 2]);
      scene.add(new Mesh({ positions, cells }, { color: [m / meshes, 0.5, 0.5] }));
    }
    return sceneToJSON(scene);
  },
  cylinders: () => {
    const scene = new Scene({ background: [0.9, 0.9, 1] }).add(new PointLight([0, 30, -20]));
    for (let i = 0; i < MAX_SCENE_OBJECTS - 1; i++) {
      const col = i % 100, row = Math.floor(i / 100);
      scene.add(new Cylinder([(col - 49.5) * 0.3, (row - 50) * 0.3, -60], 0.12, 0.2, { color: [col / 100, row / 100, 0.5] }));
    }
    return sceneToJSON(scene);
  },
};

test.describe('area lights, meshes and cylinders at the limit in sketch 05', () => {
  const TASK_LIMIT = 200; // ms of the main thread's time
  for (const [name, make] of Object.entries(AT_THE_LIMITS)) {
    test(`${name}: opening the link, a click and arrow keys (under 200 ms a task: npm run bench:big-scene)`, async ({ page }) => {
      test.setTimeout(600_000); // tracing at the limit on a busy machine
      const errors = watchConsole(page);
      const link = `/sketches/05-value-boxes.html#scene=${await encodeSceneLink(make())}`;
      const tasks = {};
      const step = async (label, action) => { tasks[label] = await longestTaskOf(page, action); };
      await page.goto('/sketches/05-value-boxes.html?before');
      await waitForDone(page);
      await step('open', async () => {
        await page.goto(link);
        await waitForDone(page, 540_000);
      });
      await expect(page.locator('[data-link-problem]')).toBeEmpty();
      const panel = page.locator('[data-inspector]');
      await step('click', async () => {
        await clickPixel(page.locator('[data-tracer]'), 80, 60);
        await expect(panel).toHaveAttribute('data-x', '80');
      });
      await step('arrow', async () => {
        await page.keyboard.press('ArrowDown');
        await expect(panel).toHaveAttribute('data-y', '61');
      });
      test.info().annotations.push({ type: 'longest task, main-thread ms (wall-clock ms)', description: Object.entries(tasks).map(([k, { cpu, wall }]) => `${k} ${cpu} (${wall})`).join(', ') });
      if (process.env.RT_BENCH) {
        for (const [label, { cpu }] of Object.entries(tasks)) expect(cpu, `the longest task of "${label}"`).toBeLessThan(TASK_LIMIT);
      }
      expect(errors).toEqual([]);
    });
  }
});
