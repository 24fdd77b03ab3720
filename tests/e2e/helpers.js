/**
 * Shared steps of the browser tests: console-error capture and waiting for
 * the page contract's body[data-render="done"].
 */
import { expect } from '@playwright/test';

/**
 * Collects console errors, warnings and logs (p5's friendly errors are logs)
 * and page errors; call before page.goto. A quiet console is part of the
 * page contract. Chromium's hint about repeated getImageData is left out:
 * the tests' own pixel reads cause it, not the page.
 */
export function watchConsole(page) {
  const errors = [];
  page.on('console', (msg) => {
    if (!['error', 'warning', 'log'].includes(msg.type()) || msg.text().startsWith('Canvas2D: Multiple readback operations')) return;
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
 * Clicks the centre of traced pixel (x, y) of a tracer canvas, whatever its
 * on-screen scale. Through the locator, so Playwright first waits until the
 * canvas is visible, still and the one that receives the click.
 */
export async function clickPixel(canvas, x, y) {
  const box = await canvas.boundingBox();
  const width = Number(await canvas.getAttribute('data-width'));
  const height = Number(await canvas.getAttribute('data-height'));
  await canvas.click({ position: { x: ((x + 0.5) * box.width) / width, y: ((y + 0.5) * box.height) / height } });
}
