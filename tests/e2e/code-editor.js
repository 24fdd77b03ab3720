/**
 * Helpers for the pages that edit their code in the page (editor/): the
 * editor's text, a run's end, the frame's page, a link carrying code.
 */
import { deflateRawSync } from 'node:zlib';
import { readFile } from 'node:fs/promises';
import { expect } from '@playwright/test';

/** The editor's whole text replaced by `code`, as typed (one paste). */
export async function setCode(page, code) {
  const editor = page.locator('[data-editor]');
  await editor.focus(); // not a click: the frame above it may grow (the inspector's story) and move it
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.insertText(code);
}

/**
 * The editor's whole text, as the student saves it (Download): CodeMirror
 * draws only the lines near the window, so its elements do not hold it all.
 */
export async function editorText(page) {
  const download = page.waitForEvent('download');
  await page.getByRole('button', { name: 'Download', exact: true }).click();
  return readFile(await (await download).path(), 'utf8');
}

/** Waits until run `n` of the editor's code has set up and its picture is traced. */
export async function waitForRun(page, n, timeout = 60_000) {
  await expect(page.locator('[data-code-status]')).toHaveText(`Your code ran (run ${n}).`, { timeout });
  // A frame out of view gets no animation frames (Chromium's throttling): look at it, as the student does.
  await page.locator('iframe[data-code-frame="running"]').scrollIntoViewIfNeeded();
  await expect(page.locator('body')).toHaveAttribute('data-render', 'done', { timeout });
}

/** The running frame, as a frame locator. */
export const sketchFrame = (page) => page.frameLocator('iframe[data-code-frame="running"]');

/** `path#code=z.…`: the link a student's Copy share link makes for `code`. */
export function codeLink(path, code) {
  return `${path}#code=z.${deflateRawSync(Buffer.from(code, 'utf8')).toString('base64url')}`;
}
