// "Edit this sketch" (editor/code-in-page.js): every sketch page other than
// 08, 09 and 10 offers its own code in the page. The editor loads when the
// student opens it; the page's code runs unchanged in the sandboxed frame;
// a link's code opens the editor by itself and waits for Run; it all works
// by keyboard.
import { readFileSync, readdirSync } from 'node:fs';
import { test, expect } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { waitForDone, watchConsole } from './helpers.js';
import { setCode, editorText, waitForRun, sketchFrame, codeLink } from './code-editor.js';

const OPEN_AT_ONCE = ['08', '09', '10'];
const OFFERED = readdirSync('sketches').filter((f) => /^\d\d-.*\.html$/.test(f) && !OPEN_AT_ONCE.includes(f.slice(0, 2)));
// Each run starts a frame with p5 and the kit in it: seconds on a busy machine.
test.describe.configure({ timeout: 180_000 });

test('every sketch page but 08, 09 and 10 offers "Edit this sketch"; the editor is not loaded before', async ({ page }) => {
  expect(OFFERED.length).toBeGreaterThanOrEqual(13);
  for (const file of OFFERED) {
    const asked = [];
    page.on('request', (request) => asked.push(request.url()));
    await page.goto(`/sketches/${file}`);
    await expect(page.locator('header [data-edit-sketch]'), file).toHaveText('Edit this sketch');
    await expect(page.locator('[data-editor]'), file).toHaveCount(0);
    expect(asked.filter((url) => /codemirror|code-panel|sketch-runtime|sketch-code/.test(url)), file).toEqual([]);
    page.removeAllListeners('request');
  }
});

// The pages whose code needs the most of the frame: the activity and its task list (04), render workers (07),
// a mesh from a package and its BVH panel (13), the GPU (15).
for (const name of ['04-find-the-pink-pixel', '07-original-examples', '13-meshes-and-a-bvh', '15-live-on-the-gpu']) {
  test(`${name}: "Edit this sketch" opens its own file, and the code runs as it is in the sandboxed frame`, async ({ page }) => {
    const errors = watchConsole(page);
    await page.goto(`/sketches/${name}.html`);
    await waitForDone(page);
    await page.locator('[data-edit-sketch]').click();
    // The editor's modules load now, on the first click: seconds on a busy machine.
    await expect(page.locator('[data-editor]')).toHaveAttribute('aria-label', `Code of the sketch, ${name}.js`, { timeout: 30_000 });
    await expect(page.locator('[data-edit-sketch]')).toHaveCount(0);
    await expect(page.locator('#code-title')).toBeFocused();
    expect(await editorText(page)).toBe(readFileSync(`sketches/${name}.js`, 'utf8'));
    await page.getByRole('button', { name: 'Run' }).click();
    await waitForRun(page, 1, 120_000);
    expect((await page.locator('iframe[data-code-frame="running"]').getAttribute('sandbox')).split(/\s+/)).not.toContain('allow-same-origin');
    await expect(sketchFrame(page).locator('[data-tracer]').first()).toBeVisible();
    await expect(page.locator('main#sketch')).toBeHidden(); // the page's own sketch made way
    await expect(page.locator('[data-error]')).toHaveCount(0);
    expect(errors).toEqual([]);
  });
}

test('by keyboard alone: Edit this sketch, the panel\'s title, Run, the editor (Tab indents, Esc then Tab leaves); axe is content', async ({ page }) => {
  const name = '12-cylinders-cones-triangles';
  const starter = readFileSync(`sketches/${name}.js`, 'utf8');
  await page.goto(`/sketches/${name}.html`);
  await waitForDone(page);
  await page.locator('[data-edit-sketch]').focus();
  await page.keyboard.press('Enter');
  await expect(page.locator('#code-title')).toBeFocused({ timeout: 30_000 });
  await page.keyboard.press('Tab');
  await expect(page.getByRole('button', { name: 'Run' })).toBeFocused();
  for (let i = 0; i < 4; i += 1) await page.keyboard.press('Tab'); // Download, Reset, Copy share link, the editor
  await expect(page.locator('[data-editor]')).toBeFocused();
  await page.keyboard.press('ControlOrMeta+Home');
  await page.keyboard.press('Tab');
  await expect(page.locator('[data-editor]')).toBeFocused(); // Tab indents
  expect(await editorText(page)).toBe(`  ${starter}`);
  await page.keyboard.press('Escape');
  await page.keyboard.press('Tab');
  await expect(page.locator('[data-editor]')).not.toBeFocused();
  await waitForRun(page, 1, 120_000); // the pause after typing ran it
  const { violations } = await new AxeBuilder({ page }).withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa']).analyze();
  expect(violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.id}: ${v.nodes[0].target.join(' ')}`)).toEqual([]);
});

test('a link\'s code opens the editor by itself and waits for Run; the student\'s version is kept and said on the button', async ({ page }) => {
  const name = '06-lights-shadows-reflections';
  const starter = readFileSync(`sketches/${name}.js`, 'utf8');
  const shared = starter.replace(/\n$/, '\n// shared with me\n');
  await page.goto(codeLink(`/sketches/${name}.html`, shared));
  await expect(page.locator('[data-code-status]')).toContainText('This code came in a link: read it first, then press Run.', { timeout: 30_000 });
  expect(await editorText(page)).toBe(shared);
  await expect(page.locator('[data-edit-sketch]')).toHaveCount(0);
  await page.waitForTimeout(1_500); // more than the pause after which typed code runs
  await expect(page.locator('iframe')).toHaveCount(0);

  await page.goto(`/sketches/${name}.html`);
  await page.locator('[data-edit-sketch]').click();
  await expect(page.locator('[data-editor]')).toBeVisible({ timeout: 30_000 });
  await setCode(page, starter.replace(/\n$/, '\n// mine\n'));
  await waitForRun(page, 1, 120_000);
  await page.reload();
  await expect(page.locator('[data-edit-sketch]')).toHaveText('Edit this sketch (your version is kept)');
  await page.locator('[data-edit-sketch]').click();
  await waitForRun(page, 1, 120_000); // the student's own code runs at once when the editor opens
  expect(await editorText(page)).toContain('// mine');
});
