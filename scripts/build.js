/**
 * npm run build: the static site in dist/ (the gallery, the web editor's
 * steps, every sketch, the API reference in dist/api/), the one-file builds
 * beside it (dist/raytracing-sketchbook.js, a classic script defining RT, and
 * dist/raytracing-sketchbook.mjs), the web editor's ready folder made of
 * them (dist/web-editor/, and as dist/raytracing-sketchbook-web-editor.zip)
 * and the package's types (types/).
 * The homework's reference solutions are left out (vite.config.js);
 * `npm run build -- --with-solutions` writes a private copy with them into
 * dist-teacher/ instead, so dist/ is always the one to publish.
 */
import { spawnSync } from 'node:child_process';

if (process.argv.includes('--with-solutions')) process.env.SKETCHBOOK_WITH_SOLUTIONS = '1';

const steps = [
  ['the site', ['node_modules/vite/bin/vite.js', 'build']],
  ['the one-file builds', ['node_modules/vite/bin/vite.js', 'build', '-c', 'vite.onefile.config.js']],
  ['the web editor\'s ready folder', ['scripts/ready-folder.js']],
  ['the types', ['scripts/types.js']],
];
for (const [what, args] of steps) {
  console.log(`\n— ${what}`);
  const { status } = spawnSync(process.execPath, args, { stdio: 'inherit' });
  if (status !== 0) {
    console.error(`npm run build: ${what} failed`);
    process.exit(status ?? 1);
  }
}
