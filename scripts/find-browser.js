/**
 * Which Chromium Playwright should drive: its own when installed, else a
 * system one (CHROMIUM_PATH, /usr/bin/chromium, …). With --check, exits
 * non-zero with the exact command to run when there is none.
 */
import { existsSync } from 'node:fs';
import { chromium } from '@playwright/test';
import { fileURLToPath } from 'node:url';

const SYSTEM_CHROMIUMS = [
  '/usr/bin/chromium', '/usr/bin/chromium-browser', '/snap/bin/chromium',
  '/usr/bin/google-chrome', '/usr/bin/google-chrome-stable',
  '/Applications/Google Chrome.app/Contents/MacOS/Google Chrome',
];

/** Path of a Chromium to launch, or undefined for Playwright's own; null when none exists. */
export function findBrowser() {
  if (process.env.CHROMIUM_PATH) {
    return existsSync(process.env.CHROMIUM_PATH) ? process.env.CHROMIUM_PATH : null;
  }
  try {
    if (existsSync(chromium.executablePath())) return undefined; // Playwright's own browser
  } catch { /* not installed */ }
  return SYSTEM_CHROMIUMS.find((path) => existsSync(path)) ?? null;
}

export const HOW_TO_GET_ONE = [
  'No Chromium found for the browser tests. Install one, then run npm test again:',
  '  npx playwright install chromium            (where downloads are allowed)',
  '  sudo apt-get install -y chromium           (Debian/Ubuntu; gives /usr/bin/chromium)',
  '  or set CHROMIUM_PATH=/path/to/chrome',
].join('\n');

if (process.argv[1] === fileURLToPath(import.meta.url) && process.argv.includes('--check')) {
  const found = findBrowser();
  if (found === null) {
    console.error(HOW_TO_GET_ONE);
    process.exit(1);
  }
  console.log(`Browser: ${found ?? "Playwright's own Chromium"}`);
}
