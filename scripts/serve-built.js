/**
 * The built site for the browser tests that do not test the dev server
 * (Playwright's project `built`): the shared build of scripts/built-site-cache.js,
 * made first if a source changed, then `vite preview` of it on the port given.
 * A bundled page loads several times faster than the dev server's page of many
 * modules transformed on request.
 *   node scripts/serve-built.js --port 5200
 */
import { spawn } from 'node:child_process';
import { BUILT_SITE, buildSiteOnce } from './built-site-cache.js';

const port = process.argv[process.argv.indexOf('--port') + 1];
if (!/^\d+$/.test(port ?? '')) {
  console.error('serve-built: give the port, as --port 5200');
  process.exit(2);
}

const status = buildSiteOnce();
if (status !== 0) process.exit(status);
const preview = spawn(process.execPath, ['node_modules/vite/bin/vite.js', 'preview', '--outDir', BUILT_SITE, '--port', port, '--strictPort'], { stdio: 'inherit' });
for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, () => preview.kill(signal));
preview.on('exit', (code) => process.exit(code ?? 0));
