// tsc --checkJs over lib/ (tsconfig.json): the JSDoc says what the code does.
// The package's types are generated from that JSDoc, so a wrong @param is a
// wrong type in a teacher's editor.
import { it, expect } from 'vitest';
import { spawnSync } from 'node:child_process';

it('lib/ type-checks against its own JSDoc (tsc -p tsconfig.json)', () => {
  const { status, stdout, stderr } = spawnSync(process.execPath, ['node_modules/typescript/bin/tsc', '-p', 'tsconfig.json'], { encoding: 'utf8' });
  const errors = `${stdout}${stderr}`.split('\n').filter((line) => / error TS\d+/.test(line));
  expect(errors, 'tsc errors').toEqual([]);
  expect(status).toBe(0);
}, 120_000);
