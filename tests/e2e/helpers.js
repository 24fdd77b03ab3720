/**
 * Shared steps of the browser tests: console-error capture and waiting for
 * the page contract's body[data-render="done"].
 */
import { expect } from '@playwright/test';

/** Collects console errors and page errors; call before page.goto. */
export function watchConsole(page) {
  const errors = [];
  page.on('console', (msg) => { if (msg.type() === 'error') errors.push(msg.text()); });
  page.on('pageerror', (err) => errors.push(String(err)));
  return errors;
}

/** Waits until every tracer view on the page has finished tracing. */
export async function waitForDone(page, timeout = 30_000) {
  await expect(page.locator('body')).toHaveAttribute('data-render', 'done', { timeout });
}
