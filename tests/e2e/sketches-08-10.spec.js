// The homework pages (08, 09) and the playground (10): the self-check says
// "not yet" on the starter, listing what fails, and "passed" on the reference
// solution (?solution=1); the playground traces and its inspector answers.
import { test, expect } from '@playwright/test';
import { clickPixel, expectCanvasScreenshot, watchConsole, waitForDone } from './helpers.js';

const HOMEWORK = [
  {
    page: '08-homework-traffic-signal.html',
    label: 'Your traffic signal',
    solutionLabel: /^The reference solution/,
    firstCheck: 'Three lights',
    checks: 6,
  },
  {
    page: '09-homework-rear-lights.html',
    label: 'Your car, seen from behind',
    solutionLabel: /^The reference solution/,
    firstCheck: 'Two red lights',
    checks: 5,
  },
];

/** Presses "Check my scene" and returns the results element. */
async function checkMyScene(page) {
  await page.getByRole('button', { name: 'Check my scene' }).click();
  const results = page.locator('[data-check-results]');
  await expect(results).toHaveAttribute('data-check', /passed|not-yet/);
  return results;
}

for (const hw of HOMEWORK) {
  test.describe(hw.page, () => {
    test('the starter: the self-check says "not yet" and lists the failing check', async ({ page }) => {
      const errors = watchConsole(page);
      await page.goto(`/sketches/${hw.page}`);
      await waitForDone(page);
      await expect(page.locator('.rt-label')).toHaveText(hw.label);
      const results = await checkMyScene(page);
      await expect(results).toHaveAttribute('data-check', 'not-yet');
      await expect(results.locator('.hw-headline')).toHaveText('Not yet: 1 check to fix.');
      const failed = results.locator('[data-check-item="failed"]');
      await expect(failed).toHaveCount(1);
      await expect(failed).toContainText(hw.firstCheck);
      await expect(failed).toContainText('No lights yet');
      await expect(results.locator('[data-check-item="skipped"]')).toHaveCount(hw.checks - 1);
      await expect(results.locator('[data-check-item="passed"]')).toHaveCount(0);
      expect(errors).toEqual([]);
    });

    test('the reference solution (?solution=1): the self-check passes every check', { tag: '@dev-server' }, async ({ page }) => {
      const errors = watchConsole(page);
      await page.goto(`/sketches/${hw.page}?solution=1`);
      await waitForDone(page);
      await expect(page.locator('.rt-label')).toHaveText(hw.solutionLabel);
      const results = await checkMyScene(page);
      await expect(results).toHaveAttribute('data-check', 'passed');
      await expect(results.locator('.hw-headline')).toHaveText(/^Passed!/);
      await expect(results.locator('[data-check-item="passed"]')).toHaveCount(hw.checks);
      await expect(results.locator('[data-check-item]:not([data-check-item="passed"])')).toHaveCount(0);
      await expectCanvasScreenshot(page.locator('[data-tracer]'), `${hw.page.replace('.html', '')}-solution.png`);
      expect(errors).toEqual([]);
    });

    test('?solution=0 shows the student\'s own scene; a bad value says what the parameter takes', async ({ page }) => {
      const errors = watchConsole(page);
      await page.goto(`/sketches/${hw.page}?solution=0`);
      await waitForDone(page);
      await expect(page.locator('.rt-label')).toHaveText(hw.label);
      await expect(page.locator('.hw-warning')).toHaveCount(0);
      await page.goto(`/sketches/${hw.page}?solution=yes`);
      await waitForDone(page);
      await expect(page.locator('.rt-label')).toHaveText(hw.label);
      await expect(page.locator('.hw-warning')).toHaveText(/^\?solution= takes 1 \(show the reference solution\) or 0 \(your scene\), got .*yes/);
      expect(errors).toEqual([]);
    });
  });
}

test('the traffic-signal solution: a click on a light says its colour', { tag: '@dev-server' }, async ({ page }) => {
  await page.goto('/sketches/08-homework-traffic-signal.html?solution=1');
  await waitForDone(page);
  const panel = page.locator('[data-inspector]');
  // Column 80 is the signal's middle; rows 25, 38 and 52 are the centres of its three lights.
  for (const [y, name] of [[25, 'red'], [38, 'yellow'], [52, 'green']]) {
    await clickPixel(page.locator('[data-tracer]'), 80, y);
    await expect(panel.locator('[data-answer]')).toHaveText(new RegExp(`^Pixel: 80,${y}; H: -?\\d+\\.\\d; V: -?\\d+\\.\\d$`));
    await expect(panel.locator('.rt-color-name')).toHaveText(name);
  }
});

test('the playground traces, and its inspector answers a click and the arrow keys', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/sketches/10-playground.html');
  await waitForDone(page);
  const canvas = page.locator('[data-tracer]');
  await expect(canvas).toHaveAttribute('data-width', '64');
  await expect(canvas).toHaveAttribute('data-height', '48');
  const panel = page.locator('[data-inspector]');
  await clickPixel(page.locator('[data-tracer]'), 32, 24);
  await expect(panel.locator('[data-answer]')).toHaveText('Pixel: 32,24; H: 0.3; V: -0.3');
  await expect(panel).toContainText('two hits'); // the centre ray meets the sphere twice
  await page.keyboard.press('ArrowRight');
  await expect(panel.locator('[data-answer]')).toHaveText(/^Pixel: 33,24; H: /);
  await clickPixel(page.locator('[data-tracer]'), 0, 0);
  await expect(panel.locator('[data-answer]')).toHaveText(/^Pixel: 0,0; H: -\d+\.\d; V: \d+\.\d$/);
  expect(errors).toEqual([]);
});
