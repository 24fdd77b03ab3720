// Every visual mode of the tracer view, on the class scene: a reference
// screenshot of the traced canvas, its legend shown, and no console errors.
import { test, expect } from '@playwright/test';
import { expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';
import { MODES } from '../../lib/tracing/modes.js';

for (const { name } of MODES) {
  test(`visual mode "${name}"`, async ({ page }) => {
    const errors = watchConsole(page);
    await page.goto(`/tests/e2e/pages/inspector.html?mode=${name}&scale=6`);
    await waitForDone(page);
    const canvas = page.locator('[data-tracer]');
    await expect(canvas).toHaveAttribute('data-width', '64');
    if (name !== 'shaded') await expect(page.locator('.rt-legend')).toBeVisible();
    await expectCanvasScreenshot(canvas, `mode-${name}.png`);
    expect(errors).toEqual([]);
  });
}
