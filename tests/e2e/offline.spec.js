// An offline classroom: in any browser language (and with ?lng=es) no page
// requests anything outside its own origin, and the console stays quiet.
// p5's translations are bundled from node_modules (scripts/p5-offline-i18n.js).
import { test, expect } from '@playwright/test';
import { readdirSync } from 'node:fs';
import { watchConsole } from './helpers.js';

const PAGES = ['index.html', ...readdirSync('sketches').filter((f) => f.endsWith('.html')).map((f) => `sketches/${f}`)];
const LOCALES = ['es-ES', 'ja-JP', 'ko-KR', 'zh-CN', 'hi-IN'];
// Every page loads p5 and its translations the same way: one language opens every page, the
// others the gallery and one sketch (each language is its own set of translations).
const EVERY_PAGE_LOCALE = 'ko-KR';
const SOME_PAGES = ['index.html', 'sketches/04-find-the-pink-pixel.html'];

/** Opens `pages` (every page) in `context`, each with `query`; returns the requests that left the origin. */
async function openEveryPage(context, baseURL, query = '', pages = PAGES) {
  const origin = new URL(baseURL).origin;
  const outside = [];
  const page = await context.newPage();
  page.on('request', (r) => { if (!r.url().startsWith(`${origin}/`) && !/^(data|blob):/.test(r.url())) outside.push(r.url()); });
  const errors = watchConsole(page);
  for (const path of pages) {
    await page.goto(`/${path}${query}`);
    await page.waitForLoadState('load');
    // p5 reads its translations before setup, and setup marks the page as rendering.
    if (path.startsWith('sketches/')) await expect(page.locator('body')).toHaveAttribute('data-render', /rendering|done/);
    await page.evaluate(() => new Promise((r) => setTimeout(r, 100)));
    expect(errors.splice(0), `console on ${path}${query}`).toEqual([]);
  }
  await page.close();
  return outside;
}

for (const locale of LOCALES) {
  const every = locale === EVERY_PAGE_LOCALE;
  test(`browser language ${locale}: ${every ? 'every page stays' : 'the gallery and sketch 04 stay'} on its origin`, async ({ browser, baseURL }) => {
    if (every) test.setTimeout(180_000); // 19 pages, each until it traces: a minute on a busy machine
    const context = await browser.newContext({ locale, baseURL });
    expect(await openEveryPage(context, baseURL, '', every ? PAGES : SOME_PAGES)).toEqual([]);
    await context.close();
  });
}

test('?lng=es on every page stays on its origin', async ({ browser, baseURL }) => {
  test.setTimeout(180_000);
  const context = await browser.newContext({ baseURL });
  expect(await openEveryPage(context, baseURL, '?lng=es')).toEqual([]);
  await context.close();
});

test('a Spanish browser sees a whole picture, as an English one does', async ({ browser, baseURL }) => {
  const context = await browser.newContext({ locale: 'es-ES', baseURL });
  const page = await context.newPage();
  await page.goto('/sketches/04-find-the-pink-pixel.html');
  await expect(page.locator('body')).toHaveAttribute('data-render', 'done', { timeout: 30_000 });
  expect(await page.evaluate(() => navigator.language)).toBe('es-ES');
  await context.close();
});
