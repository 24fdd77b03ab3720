import { defineConfig } from '@playwright/test';
import { findBrowser } from './scripts/find-browser.js';

// PW_PORT lets several test runs share a machine without sharing a server.
const PORT = Number(process.env.PW_PORT ?? 5199);
const executablePath = findBrowser() ?? undefined;
const LIVE_SPECS = ['**/mistakes.spec.js', '**/saves.spec.js', '**/swaps.spec.js', '**/class-server.spec.js', '**/class-board.spec.js', '**/code-in-page-class.spec.js'];

// Screenshots are of traced canvases only, at a pinned viewport, headless.
export default defineConfig({
  testDir: 'tests/e2e',
  testMatch: '**/*.spec.js',
  snapshotPathTemplate: '{testDir}/__screenshots__/{testFilePath}/{arg}{ext}',
  fullyParallel: true,
  workers: process.env.CI ? 2 : undefined,
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
  projects: [
    { name: 'pages', testIgnore: LIVE_SPECS },
    { name: 'live', testMatch: LIVE_SPECS, dependencies: ['pages'], workers: 1, fullyParallel: false },
  ],
  webServer: {
    command: `node_modules/.bin/vite --port ${PORT} --strictPort`,
    url: `http://localhost:${PORT}/`,
    reuseExistingServer: !process.env.CI,
    timeout: 60_000,
  },
});
