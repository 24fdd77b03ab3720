/**
 * The code editor's frame (editor/): what a sandboxed frame needs, served
 * from the site itself.
 *
 * - `sketch-runtime.js`: p5 and the whole kit in one ES module
 *   (editor/frame-runtime.js bundled, p5's translations inside). A frame
 *   without `allow-same-origin` has an opaque origin: a module it fetched
 *   from the site would need CORS headers, which a static host may not send,
 *   and cross-origin isolation headers it may not get. So the page fetches
 *   this one file (same origin) and hands its text to the frame, which runs
 *   it from a Blob URL of its own.
 * - `sketch-code/NN-name.js`: each sketch's own file as text, the editor's
 *   starter (the page's bundled script is not the file the student reads).
 *
 * The dev server (and `npm run class`) makes the runtime once, again after a
 * change to lib/ or editor/, and reads the sketches' files as they are; the
 * build writes both into the site.
 */
import { createHash } from 'node:crypto';
import { readFileSync, readdirSync } from 'node:fs';
import { resolve } from 'node:path';
import { build } from 'vite';
import { p5OfflineI18n } from './p5-offline-i18n.js';
import { inlineRenderWorker, inlineStyle } from '../vite.onefile.config.js';

export const RUNTIME_FILE = 'sketch-runtime.js';
export const CODE_FOLDER = 'sketch-code';

/** A sketch's own script: `NN-name.js` in sketches/ (never a solution: those are in a folder of their own). */
export const isSketchFile = (name) => /^\d\d-[a-z0-9-]+\.js$/.test(name);

/** The runtime's code, bundled in memory. */
export async function buildRuntime(root = process.cwd()) {
  const outputs = await build({
    configFile: false,
    root,
    logLevel: 'warn',
    mode: 'production',
    plugins: [p5OfflineI18n(), inlineRenderWorker(), inlineStyle()],
    // Inlining the render worker and p5 is this build's own work, not a slow plugin to report (as vite.onefile.config.js).
    worker: { format: 'iife', rolldownOptions: { checks: { bundlerTimings: false } } },
    build: {
      write: false,
      target: 'es2022',
      minify: true,
      lib: { entry: resolve(root, 'editor/frame-runtime.js'), formats: ['es'], fileName: () => RUNTIME_FILE },
      rolldownOptions: { output: { codeSplitting: false }, checks: { bundlerTimings: false } }, // one file: the panel's lazy parts inside
    },
  });
  const chunk = [outputs].flat().flatMap((o) => o.output).find((c) => c.fileName === RUNTIME_FILE);
  return chunk.code;
}

function notFound(res, text) {
  res.statusCode = 404;
  res.setHeader('Content-Type', 'text/plain; charset=utf-8');
  res.end(text);
}

export function sketchRuntime() {
  let made = null;
  const runtime = (root) => (made ??= buildRuntime(root).catch((error) => { made = null; throw error; }));
  return {
    name: 'sketch-runtime',
    configureServer(server) {
      const root = server.config.root;
      // Made again after a change to what it bundles: lib/ and the frame's own modules.
      server.watcher.on('change', (file) => { if (/[\\/]lib[\\/]|[\\/]editor[\\/]frame-/.test(file)) made = null; });
      server.middlewares.use(async (req, res, next) => {
        const path = decodeURIComponent((req.url ?? '/').split(/[?#]/)[0]);
        try {
          if (path === `/${RUNTIME_FILE}`) {
            const code = await runtime(root);
            const etag = `"${createHash('sha1').update(code).digest('base64url')}"`; // a page visit asks again, and gets a 304
            res.setHeader('Cache-Control', 'no-cache');
            res.setHeader('ETag', etag);
            if (req.headers['if-none-match'] === etag) { res.statusCode = 304; return void res.end(); }
            res.setHeader('Content-Type', 'text/javascript; charset=utf-8');
            return void res.end(code);
          }
          if (path.startsWith(`/${CODE_FOLDER}/`)) {
            const name = path.slice(CODE_FOLDER.length + 2);
            let code = null;
            if (isSketchFile(name)) try { code = readFileSync(resolve(root, 'sketches', name), 'utf8'); } catch { /* no such sketch */ }
            // Not the gallery's page as a fallback: the editor would take it for the code.
            if (code === null) return void notFound(res, `No sketch ${name} to edit.\n`);
            res.setHeader('Content-Type', 'text/plain; charset=utf-8');
            res.setHeader('Cache-Control', 'no-cache');
            return void res.end(code);
          }
        } catch (error) {
          return next(error);
        }
        return next();
      });
    },
    async generateBundle() {
      this.emitFile({ type: 'asset', fileName: RUNTIME_FILE, source: await buildRuntime(process.cwd()) });
      for (const name of readdirSync('sketches').filter(isSketchFile)) {
        this.emitFile({ type: 'asset', fileName: `${CODE_FOLDER}/${name}`, source: readFileSync(resolve('sketches', name), 'utf8') });
      }
    },
  };
}
