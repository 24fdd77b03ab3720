/**
 * A Playwright reporter that counts the expect calls each test reaches and
 * writes them to test-results/expects.json, so that a change to the suite
 * (merged tests, shared pages) can show it proves as much as before.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, relative } from 'node:path';

export default class ExpectCounter {
  constructor(options = {}) {
    this.outputFile = options.outputFile ?? 'test-results/expects.json';
    this.tests = new Map();
  }

  onStepEnd(test, result, step) {
    if (step.category !== 'expect' || step.parent?.category === 'expect') return;
    const entry = this.entryFor(test);
    entry.expects += 1;
  }

  onTestEnd(test, result) {
    const entry = this.entryFor(test);
    entry.status = result.status;
    entry.duration = result.duration;
  }

  entryFor(test) {
    let entry = this.tests.get(test.id);
    if (!entry) {
      entry = {
        project: test.parent.project()?.name ?? '',
        file: relative(process.cwd(), test.location.file),
        title: test.titlePath().slice(3).join(' › '),
        expects: 0,
      };
      this.tests.set(test.id, entry);
    }
    return entry;
  }

  onEnd() {
    const tests = [...this.tests.values()];
    const total = tests.reduce((sum, t) => sum + t.expects, 0);
    mkdirSync(dirname(this.outputFile), { recursive: true });
    writeFileSync(this.outputFile, JSON.stringify({ total, tests }, null, 1));
  }

  printsToStdio() { return false; }
}
