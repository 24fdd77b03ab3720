/**
 * npm run test:timing: where the suite's time goes. Reads the reports that
 * npm test writes (test-results/e2e.json from Playwright, unit.json from
 * Vitest, expects.json from scripts/expect-counter.js) and prints the slowest
 * spec files and tests. `node scripts/test-timing.js --top 30` shows more.
 */
import { readFileSync } from 'node:fs';
import { relative } from 'node:path';

const top = Number(process.argv[process.argv.indexOf('--top') + 1]) || 15;
const dir = process.argv.find((arg) => arg.startsWith('--dir='))?.slice(6) ?? 'test-results';

const e2e = readJSON(`${dir}/e2e.json`);
const unit = readJSON(`${dir}/unit.json`);
const expects = readJSON(`${dir}/expects.json`);
if (!e2e && !unit) {
  console.error(`No reports in ${dir}/: run npm test (or playwright test / vitest run) first.`);
  process.exit(1);
}
if (e2e) printBrowserTests(e2e, expects);
if (unit) printUnitTests(unit);

function printBrowserTests(report, counted) {
  const tests = browserTests(report);
  const files = byFile(tests);
  const work = sum(tests.map((t) => t.duration));
  const wall = report.stats?.duration ?? 0;
  const byStatus = {};
  for (const t of tests) byStatus[t.status] = (byStatus[t.status] ?? 0) + 1;
  const statuses = Object.entries(byStatus).map(([status, count]) => `${count} ${status}`).join(', ');
  console.log(`\nBrowser tests: ${tests.length} in ${files.length} files (${statuses}), ${minutes(wall)} wall, ${minutes(work)} of test time` +
    (counted ? `, ${counted.total} expect calls reached` : ''));
  table(`Slowest ${Math.min(top, files.length)} spec files (test time, the file's share, its longest test)`, files.slice(0, top).map((f) => [
    minutes(f.duration), percent(f.duration, work), `${f.count} tests`, `max ${seconds(f.longest)}`, f.file,
  ]));
  table(`Slowest ${Math.min(top, tests.length)} browser tests`, tests.toSorted((a, b) => b.duration - a.duration).slice(0, top).map((t) => [
    seconds(t.duration), `[${t.project}]`, `${t.file}: ${t.title}`,
  ]));
  table('Each project (test time, its tests, when its last test ended)', byProject(tests).map((p) => [
    minutes(p.duration), `${p.count} tests`, `done at ${minutes(p.end)}`, p.project,
  ]));
  const workers = byWorker(tests);
  if (workers.length > 1) {
    table('Busy time of each worker (an idle worker at the end means one file held the run up)', workers.map((w) => [
      `worker ${w.worker}`, minutes(w.busy), `done at ${minutes(w.end)}`,
    ]));
  }
}

function printUnitTests(report) {
  const files = (report.testResults ?? []).map((f) => ({
    file: relative(process.cwd(), f.name),
    duration: (f.endTime ?? 0) - (f.startTime ?? 0),
    count: f.assertionResults?.length ?? 0,
  })).toSorted((a, b) => b.duration - a.duration);
  const work = sum(files.map((f) => f.duration));
  console.log(`\nUnit tests: ${report.numTotalTests} in ${files.length} files, ${minutes(work)} of file time`);
  table(`Slowest ${Math.min(top, files.length)} unit test files`, files.slice(0, top).map((f) => [
    seconds(f.duration), `${f.count} tests`, f.file,
  ]));
}

/** Every test result of a Playwright JSON report, flattened. */
function browserTests(report) {
  const out = [];
  const walk = (suite, titles) => {
    for (const spec of suite.specs ?? []) {
      for (const test of spec.tests ?? []) {
        for (const result of test.results ?? []) {
          out.push({
            file: spec.file, project: test.projectName, title: [...titles, spec.title].join(' › '),
            duration: result.duration, worker: result.parallelIndex ?? result.workerIndex,
            start: Date.parse(result.startTime), status: result.status,
          });
        }
      }
    }
    for (const child of suite.suites ?? []) walk(child, [...titles, child.title]);
  };
  for (const fileSuite of report.suites ?? []) walk(fileSuite, []);
  return out;
}

function byFile(tests) {
  const files = new Map();
  for (const t of tests) {
    const f = files.get(t.file) ?? { file: t.file, duration: 0, count: 0, longest: 0 };
    f.duration += t.duration; f.count += 1; f.longest = Math.max(f.longest, t.duration);
    files.set(t.file, f);
  }
  return [...files.values()].toSorted((a, b) => b.duration - a.duration);
}

/** Per Playwright project: its test time and when its last test ended, from the run's start. */
function byProject(tests) {
  const start = Math.min(...tests.map((t) => t.start).filter(Number.isFinite));
  const projects = new Map();
  for (const t of tests) {
    const p = projects.get(t.project) ?? { project: t.project, duration: 0, count: 0, end: 0 };
    p.duration += t.duration; p.count += 1; p.end = Math.max(p.end, t.start + t.duration - start);
    projects.set(t.project, p);
  }
  return [...projects.values()].toSorted((a, b) => b.duration - a.duration);
}

/** Per parallel slot: its busy time and when its last test ended, from the run's start. */
function byWorker(tests) {
  const start = Math.min(...tests.map((t) => t.start).filter(Number.isFinite));
  const slots = new Map();
  for (const t of tests) {
    const slot = slots.get(t.worker) ?? { worker: t.worker, busy: 0, end: 0 };
    slot.busy += t.duration; slot.end = Math.max(slot.end, t.start + t.duration - start);
    slots.set(t.worker, slot);
  }
  return [...slots.values()].toSorted((a, b) => b.busy - a.busy).slice(0, 8);
}

function table(title, rows) {
  console.log(`\n${title}:`);
  const widths = rows[0]?.map((_, i) => Math.max(...rows.map((r) => String(r[i]).length))) ?? [];
  for (const row of rows) {
    console.log('  ' + row.map((cell, i) => (i === row.length - 1 ? cell : String(cell).padStart(widths[i]))).join('  '));
  }
}

function readJSON(path) {
  try { return JSON.parse(readFileSync(path, 'utf8')); } catch { return null; }
}
function sum(values) { return values.reduce((a, b) => a + b, 0); }
function seconds(ms) { return `${(ms / 1000).toFixed(1)} s`; }
function minutes(ms) { return ms >= 60_000 ? `${(ms / 60_000).toFixed(1)} min` : seconds(ms); }
function percent(part, whole) { return `${whole ? Math.round((100 * part) / whole) : 0}%`; }
