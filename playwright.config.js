import { defineConfig } from '@playwright/test';
import { availableParallelism } from 'node:os';
import { findBrowser } from './scripts/find-browser.js';

// PW_PORT lets several test runs share a machine without sharing a server.
const PORT = Number(process.env.PW_PORT ?? 5199);
// The built site (scripts/serve-built.js) on the next port: pages that tests only read load faster from it.
const BUILT_PORT = Number(process.env.PW_BUILT_PORT ?? PORT + 1);
const executablePath = findBrowser() ?? undefined;
// Specs that only read pages, run on the built site (the dev server's own ways, hot swap and
// the mistakes panel, stay with the dev server).
const BUILT_SPECS = ['**/layout.spec.js', '**/access.spec.js', '**/projector.spec.js', '**/gallery.spec.js', '**/hostile-links.spec.js', '**/blind-walk.spec.js'];
// npm run test:quick (RT_QUICK=1): one smoke page of each kind, on the dev server, no build: the
// axe test of the gallery, a lesson, a homework, the web editor and the teacher's page; the API
// reference (axe takes a minute on its long page) by its narrow-window test.
const QUICK = Boolean(process.env.RT_QUICK);
const QUICK_PAGES = /axe: .* on (\/|\/sketches\/01-rays-through-pixels\.html|\/sketches\/08-homework-traffic-signal\.html|\/web-editor\.html|\/teacher\.html)(;|$)|at 320 CSS px wide \/api\/ does not scroll sideways$/;
const LIVE_SPECS = ['**/mistakes.spec.js', '**/saves.spec.js', '**/swaps.spec.js', '**/class-server.spec.js', '**/class-board.spec.js', '**/code-in-page-class.spec.js'];

// Screenshots are of traced canvases only, at a pinned viewport, headless.
export default defineConfig({
  testDir: 'tests/e2e',
  testMatch: '**/*.spec.js',
  snapshotPathTemplate: '{testDir}/__screenshots__/{testFilePath}/{arg}{ext}',
  fullyParallel: true,
  // Both cores of a 2-core machine (Playwright's default is half of them): each browser waits on
  // its page's frames and the server part of the time.
  workers: process.env.CI ? 2 : Math.max(2, Math.floor(availableParallelism() / 2)),
  retries: 0,
  forbidOnly: true,
  // npm run test:timing reads the JSON report; the expect counter shows a faster suite proves as much.
  reporter: [['list'], ['json', { outputFile: 'test-results/e2e.json' }], ['./scripts/expect-counter.js']],
  timeout: 60_000,
  expect: { toHaveScreenshot: { maxDiffPixels: 0, animations: 'disabled', caret: 'hide', stylePath: 'tests/e2e/screenshot.css' } },
  use: {
    baseURL: `http://localhost:${PORT}`,
    viewport: { width: 1280, height: 900 },
    deviceScaleFactor: 1,
    browserName: 'chromium',
    headless: true,
    launchOptions: { executablePath },
  },
  // Live-coding tests write sketch files the dev server watches; the reloads
  // those saves cause must not reach other tests' pages: they run last, alone.
  projects: QUICK ? [{ name: 'quick', testMatch: ['**/access.spec.js', '**/layout.spec.js'], grep: QUICK_PAGES }] : [
    { name: 'built', testMatch: BUILT_SPECS, use: { baseURL: `http://localhost:${BUILT_PORT}` } },
    { name: 'pages', testIgnore: [...LIVE_SPECS, ...BUILT_SPECS] },
    { name: 'live', testMatch: LIVE_SPECS, dependencies: ['pages', 'built'], workers: 1, fullyParallel: false },
  ],
  webServer: [{
    command: `node_modules/.bin/vite --port ${PORT} --strictPort`,
    url: `http://localhost:${PORT}/`,
    reuseExistingServer: !process.env.CI,
    timeout: 60_000,
  }, ...QUICK || process.env.PW_NO_BUILD ? [] : [{ // PW_NO_BUILD=1: a dev-server spec run alone, without the build
    command: `node scripts/serve-built.js --port ${BUILT_PORT}`,
    url: `http://localhost:${BUILT_PORT}/`,
    reuseExistingServer: !process.env.CI,
    timeout: 300_000, // a build first: a minute and a half on a busy 2-core machine
  }]],
});
