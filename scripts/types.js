/**
 * npm run types: the package's TypeScript declarations (types/), generated
 * from the library's JSDoc by tsc, so editors autocomplete `new Sphere(` and
 * `createTracerView({`. Run by npm run build and before npm pack.
 */
import { rmSync } from 'node:fs';
import { spawnSync } from 'node:child_process';

rmSync('types', { recursive: true, force: true }); // no declarations of deleted modules
const { status } = spawnSync(process.execPath, ['node_modules/typescript/bin/tsc', '-p', 'tsconfig.types.json'], { stdio: 'inherit' });
if (status !== 0) process.exit(status ?? 1);
console.log('types/ written');
