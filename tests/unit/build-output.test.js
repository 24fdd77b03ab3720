// The one-file build (vite.onefile.config.js, a step of npm run build) says nothing but what it wrote:
// no deprecated option (inlineDynamicImports), no timings report of its plugins.
import { describe, it, expect, afterAll } from 'vitest';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, readdirSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const folder = mkdtempSync(join(tmpdir(), 'rt-onefile-'));
afterAll(() => rmSync(folder, { recursive: true, force: true }));

describe('the one-file build', () => {
  it('prints no warning, and still makes one file each (the lazily loaded hints inside)', () => {
    const run = spawnSync(process.execPath, ['node_modules/vite/bin/vite.js', 'build', '-c', 'vite.onefile.config.js', '--outDir', folder, '--logLevel', 'info'], { encoding: 'utf8' });
    const output = run.stdout + run.stderr;
    expect(run.status, output).toBe(0);
    expect(output).toMatch(/raytracing-sketchbook\.js/); // the log was read: it names what it wrote
    expect(output).not.toMatch(/WARN|PLUGIN_TIMINGS|BUNDLER_TIMINGS|inlineDynamicImports|deprecated/i);
    expect(readdirSync(folder).sort()).toEqual(['raytracing-sketchbook.js', 'raytracing-sketchbook.mjs']);
    expect(readFileSync(join(folder, 'raytracing-sketchbook.js'), 'utf8')).toMatch(/^\/\/ noprotect/);
  }, 180_000);
});
