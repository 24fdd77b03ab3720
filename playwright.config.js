import { defineConfig } from '@playwright/test';
import { availableParallelism } from 'node:os';
import { findBrowser } from './scripts/find-browser.js';

// PW_PORT lets several test runs share a machine without sharing a server.
const PORT = Number(process.env.PW_PORT ?? 5199);
// The built site (scripts/serve-built.js) on the next port: pages that tests only read load faster from it.
const BUILT_PORT = Number(process.env.PW_BUILT_PORT ?? PORT + 1);
// The live-coding tests' own dev server, on the port after: they run beside the others (vite.config.js).
const LIVE_PORT = Number(process.env.PW_LIVE_PORT ?? PORT + 2);
const executablePath = findBrowser() ?? undefined;
// Specs that do not test live coding or the dev server's own ways run on the built site, as the
// published site is built. A test there that needs the dev server (the teacher's reference solutions,
// the web editor's one-file build served on request) carries the tag @dev-server and runs on it.
// Specs that open the kit's test pages (tests/e2e/pages/) or import lib/ into a page stay on the dev server.
const BUILT_SPECS = ['access', 'answer-lines', 'api-reference', 'big-scenes', 'blind-walk', 'code-in-page-every', 'code-in-page',
  'gallery', 'hostile-links', 'key-line-14', 'layout', 'number-scrub', 'offline', 'projector', 'share-links', 'sketch-00', 'sketch-11',
  'sketch-12', 'sketch-13', 'sketch-14', 'sketch-15', 'sketch-16', 'sketch-17', 'sketches-01-03', 'sketches-04-05', 'sketches-08-10', 'tasks-10-14',
  'tasks', 'web-editor-starters', 'web-editor', 'work-limits'].map((name) => `**/${name}.spec.js`);
const DEV_SERVER = /@dev-server/;
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
  // Three on a 2-core machine (Playwright's default is half the cores, so one): a browser waits on
  // its page's frames, a save's reload and the servers part of the time, and the live-coding
  // tests, one at a time, run beside the others.
  workers: process.env.CI ? 3 : Math.max(3, Math.floor(availableParallelism() / 2) + 1),
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
  // Live-coding tests write sketch files their dev server watches: they have a server of their own
  // (the other dev server does not watch those files) and run one at a time, beside the others.
  // The live project first: Playwright hands out tests in the projects' order, and its one worker must
  // start at once (its tests mostly wait on saves) rather than run alone at the end.
  projects: QUICK ? [{ name: 'quick', testMatch: ['**/access.spec.js', '**/layout.spec.js'], grep: QUICK_PAGES }] : [
    { name: 'live', testMatch: LIVE_SPECS, workers: 1, fullyParallel: false, use: { baseURL: `http://localhost:${LIVE_PORT}` } },
    { name: 'built', testMatch: BUILT_SPECS, grepInvert: DEV_SERVER, use: { baseURL: `http://localhost:${BUILT_PORT}` } },
    { name: 'pages', testIgnore: [...LIVE_SPECS, ...BUILT_SPECS] },
    { name: 'dev-server', testMatch: BUILT_SPECS, grep: DEV_SERVER },
  ],
  webServer: [{
    command: `node_modules/.bin/vite --port ${PORT} --strictPort`,
    env: { SKETCHBOOK_TEST_SERVER: 'pages' },
    url: `http://localhost:${PORT}/`,
    reuseExistingServer: !process.env.CI,
    timeout: 60_000,
  }, ...QUICK ? [] : [{
    command: `node_modules/.bin/vite --port ${LIVE_PORT} --strictPort`,
    env: { SKETCHBOOK_TEST_SERVER: 'live' },
    url: `http://localhost:${LIVE_PORT}/`,
    reuseExistingServer: !process.env.CI,
    timeout: 60_000,
  }], ...QUICK || process.env.PW_NO_BUILD ? [] : [{ // PW_NO_BUILD=1: a dev-server spec run alone, without the build
    command: `node scripts/serve-built.js --port ${BUILT_PORT}`,
    url: `http://localhost:${BUILT_PORT}/`,
    reuseExistingServer: !process.env.CI,
    timeout: 300_000, // a build first: a minute and a half on a busy 2-core machine
  }]],
});
