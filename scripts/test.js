/**
 * npm test: the linter and format check (ESLint), the unit tests (Vitest),
 * then the browser tests (Playwright), then one closing line with the totals.
 * npm run test:quick (--quick): the unit tests and one smoke page of each kind
 * (Playwright's project `quick`, playwright.config.js), in a few minutes.
 */
import { spawnSync } from 'node:child_process';
import { readFileSync, mkdirSync } from 'node:fs';
import { findBrowser, HOW_TO_GET_ONE } from './find-browser.js';

mkdirSync('test-results', { recursive: true });
const run = (cmd, args) => spawnSync(cmd, args, { stdio: 'inherit', shell: false }).status;
const bin = (name) => `node_modules/.bin/${name}`;

const quick = process.argv.includes('--quick');
if (quick) process.env.RT_QUICK = '1';
const lintStatus = quick ? 0 : run(bin('eslint'), ['.']);
if (lintStatus !== 0) console.error('\nESLint found problems (above): `npm run lint` lists them, `npx eslint --fix .` mends the format ones.\n');
const unitStatus = run(bin('vitest'), ['run', '--reporter=default', '--reporter=json', '--outputFile=test-results/unit.json']);
const unit = readJSON('test-results/unit.json');
const counts = {
  passed: unit?.numPassedTests ?? 0,
  failed: (unit ? unit.numFailedTests : 1) + (lintStatus === 0 ? 0 : 1),
};

let e2eStatus = 1;
if (findBrowser() === null) {
  console.error(HOW_TO_GET_ONE);
  counts.failed += 1;
} else {
  e2eStatus = run(bin('playwright'), ['test']);
  const stats = readJSON('test-results/e2e.json')?.stats;
  counts.passed += stats?.expected ?? 0;
  counts.failed += stats ? stats.unexpected + stats.flaky : 1;
}

const ok = lintStatus === 0 && unitStatus === 0 && e2eStatus === 0 && counts.failed === 0;
console.log(`\ntotal: ${counts.passed} passed, ${counts.failed} failed`);
console.log(quick
  ? 'the quick check only: npm test runs every test'
  : 'where the time went: npm run test:timing (from test-results/e2e.json and unit.json)');
process.exit(ok ? 0 : 1);

function readJSON(path) {
  try { return JSON.parse(readFileSync(path, 'utf8')); } catch { return null; }
}
