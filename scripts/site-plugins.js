/**
 * Vite plugins of the site (vite.config.js), the same in `npm start` and in
 * `npm run build`:
 * - includeText: a page shows a file of the repository as text
 *   (`<!-- text of examples/web-editor/sketch.js -->`), escaped, so what the
 *   page tells a teacher to paste is the file the browser tests run;
 * - oneFileInDev: the dev server answers /raytracing-sketchbook.js and .mjs
 *   with the one-file builds, and the web editor's ready folder as its .zip
 *   (npm run build writes them into dist/);
 * - apiReference: /api/ is the API reference, generated from the JSDoc
 *   (made once and kept, made again after a change to lib/);
 * - apiLine: under each lesson page, "API:" and the names its sketch uses,
 *   linked into the reference;
 * - fromFileNotice: a lesson page opened from a file (a built page
 *   double-clicked) says why its picture is missing and what to run; the
 *   gallery's own notice gets the same inline style.
 */
import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { resolve, sep } from 'node:path';
import { build } from 'vite';
import { apiReferenceHTML, namesUsedBy, apiLineHTML } from './api-reference.js';
import { ZIP_NAME, readyFolderZip } from './ready-folder.js';

const escapeHTML = (text) => text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

export function includeText() {
  return {
    name: 'include-text',
    transformIndexHtml(html) {
      return html.replace(/<!-- text of ([\w./-]+) -->/g, (_, file) => escapeHTML(readFileSync(resolve(file), 'utf8')));
    },
  };
}

/** The one-file builds, made in memory once and again after a change to lib/. */
export function oneFileInDev() {
  let made = null;
  const make = () => (made ??= build({ configFile: resolve('vite.onefile.config.js'), logLevel: 'warn', build: { write: false } })
    .then((outputs) => new Map(outputs.flatMap((o) => o.output).map((chunk) => [chunk.fileName, chunk.code ?? chunk.source]))));
  return {
    name: 'one-file-in-dev',
    apply: 'serve',
    configureServer(server) {
      server.watcher.on('change', (file) => { if (file.includes('/lib/')) made = null; });
      server.middlewares.use(async (req, res, next) => {
        const name = req.url.split('?')[0].replace(/^\//, '');
        if (name !== 'raytracing-sketchbook.js' && name !== 'raytracing-sketchbook.mjs' && name !== ZIP_NAME) return next();
        try {
          const files = await make();
          if (name === ZIP_NAME) {
            res.setHeader('Content-Type', 'application/zip');
            return res.end(readyFolderZip(files.get('raytracing-sketchbook.js')));
          }
          res.setHeader('Content-Type', 'text/javascript; charset=utf-8');
          res.end(files.get(name));
        } catch (error) {
          made = null;
          next(error);
        }
      });
    },
  };
}

/**
 * The API reference at /api/ (a page of its own in dist/api/index.html).
 * Making it reads every file of lib/ (about 200 ms): the server makes it
 * once, again after a change to lib/ or package.json, and answers from
 * memory, so a class opening it at once does not hold up anyone's sketch.
 * @param {() => string} [make] the page (apiReferenceHTML; a test counts its calls)
 */
export function apiReference(make = apiReferenceHTML) {
  let page = null;
  const current = () => {
    if (page) return page;
    const html = make();
    return (page = { html, etag: `W/"${createHash('sha1').update(html).digest('base64url')}"` });
  };
  return {
    name: 'api-reference',
    configureServer(server) {
      const root = server.config.root.split(sep).join('/');
      const madeFrom = (file) => file.split(sep).join('/').startsWith(`${root}/lib/`) || file.split(sep).join('/') === `${root}/package.json`;
      for (const event of ['add', 'change', 'unlink']) server.watcher.on(event, (file) => { if (madeFrom(file)) page = null; });
      server.middlewares.use((req, res, next) => {
        const path = req.url.split('?')[0];
        if (path !== '/api/' && path !== '/api/index.html' && path !== '/api') return next();
        if (path === '/api') { res.statusCode = 301; res.setHeader('Location', '/api/'); return res.end(); }
        const { html, etag } = current();
        res.setHeader('ETag', etag);
        res.setHeader('Cache-Control', 'no-cache');
        if (req.headers['if-none-match'] === etag) { res.statusCode = 304; return res.end(); }
        res.setHeader('Content-Type', 'text/html; charset=utf-8');
        res.end(html);
      });
    },
    generateBundle() {
      this.emitFile({ type: 'asset', fileName: 'api/index.html', source: make() });
    },
  };
}

/** The "API:" line of a lesson page, put before its sketch's <script>. */
export function apiLine() {
  return {
    name: 'api-line',
    // before Vite's build rewrites the page's <script> (the line goes before it)
    transformIndexHtml: { order: 'pre', handler: apiLineInto },
  };
}

function apiLineInto(html, { filename }) {
  const script = /<script type="module" src="\.\/(\d\d-[\w-]+\.js)"><\/script>/.exec(html);
  if (!script || !/[\\/]sketches[\\/]\d\d-[\w-]+\.html$/.test(filename)) return html;
  const line = apiLineHTML(namesUsedBy(readFileSync(resolve('sketches', script[1]), 'utf8')));
  return html.replace(script[0], `${line}\n  ${script[0]}`);
}

/**
 * A built page opened from a file runs none of its scripts and gets none of
 * its stylesheets (the browser refuses both to a file: page), so the notice
 * and what shows it are inline: the page's own <style> and <script> still run.
 */
export const FROM_FILE_HEAD = `<script>if (location.protocol === 'file:') document.documentElement.classList.add('file-protocol');</script>
  <style>.from-file { display: none; } .file-protocol .from-file { display: block; max-width: 48rem; padding: 0.8rem 1rem; border: 2px solid #d6336c; border-radius: 8px; background: #fff; font-family: system-ui, sans-serif; }</style>`;

export const FROM_FILE_NOTICE = `<p class="from-file" role="alert">
    This page was opened from a file, and browsers run a site's scripts only when a server
    sends them: the picture cannot trace here. In the sketchbook's folder run
    <code>npm run preview</code> and open the address it prints, or serve the <code>dist</code>
    folder with any static server (<code>python3 -m http.server</code>), then open this page
    there.
  </p>`;

export function fromFileNotice() {
  return {
    name: 'from-file-notice',
    transformIndexHtml: { order: 'pre', handler: fromFileNoticeInto },
  };
}

const LESSON_PAGE = /[\\/]sketches[\\/]\d\d-[\w-]+\.html$/;

/**
 * A lesson page with the notice under its header; a page with a notice of
 * its own (the gallery) with what shows it; any other page as it is.
 */
export function fromFileNoticeInto(html, { filename }) {
  const lesson = LESSON_PAGE.test(filename) && html.includes('</header>');
  if (!lesson && !html.includes('class="from-file"')) return html;
  const withHead = html.replace('</head>', `  ${FROM_FILE_HEAD}\n</head>`);
  return lesson ? withHead.replace('</header>', `</header>\n  ${FROM_FILE_NOTICE}`) : withHead;
}
