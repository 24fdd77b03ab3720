import { defineConfig } from 'vite';
import { readdirSync } from 'node:fs';
import { resolve } from 'node:path';
import { includeText, oneFileInDev, apiReference, apiLine, fromFileNotice } from './scripts/site-plugins.js';
import { p5OfflineI18n } from './scripts/p5-offline-i18n.js';
import { teachersAnswers, classroom } from './scripts/classroom.js';
import { classBoard } from './scripts/board/plugin.js';
import { BOARD_ROUTES } from './scripts/board/routes.js';
import { reloadItsPagesOnly, swapSketchesInPlace, syntaxErrorsWhereTheyAre } from './scripts/vite-live-coding.js';
import { longLinks } from './scripts/long-links.js';
import { everySaveArrives } from './scripts/every-save-arrives.js';
import { sketchRuntime } from './scripts/sketch-runtime.js';

// Every page is an entry of the static build: the gallery, the web editor's
// steps, the teacher's page of progress codes and each sketch (the API reference is made by a plugin).
const sketchPages = readdirSync('sketches')
  .filter((file) => file.endsWith('.html'))
  .map((file) => resolve('sketches', file));

// Cross-origin isolation: a page may then share one frame with its render
// workers (SharedArrayBuffer) instead of copying rows between threads. Every
// page loads only its own origin's files, so nothing it uses is refused.
const isolation = { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' };

// The homework's reference solutions: served by the teacher's own `npm start`;
// not by `npm run class` (mode "class") nor in `npm run build`, unless
// `npm run build -- --with-solutions` (a private copy, into dist-teacher/).
const withSolutions = process.env.SKETCHBOOK_WITH_SOLUTIONS === '1';

// The browser tests run two dev servers at once (playwright.config.js): the live-coding tests' own,
// and one for the other tests, which must not watch the files the live tests save (a save or a
// syntax error there reaches no page of theirs). Each keeps its own optimized dependencies.
const testServer = process.env.SKETCHBOOK_TEST_SERVER; // 'pages' or 'live', set by playwright.config.js
const liveTestFiles = testServer === 'pages' ? ['**/tests/e2e/pages/live-*', '**/bench/live/**'] : [];
// The live tests' pages are written once as a test begins and removed as it ends; only their scripts
// are saved. Vite keeps a full reload sent while no page is connected and hands it to the next page
// that connects: the reload for a page just written reached that very page half a second after it
// loaded, in the middle of the test's first save (a swap seen as a reload).
const unwatched = testServer === 'live' ? ['**/tests/e2e/pages/live-*.html'] : liveTestFiles;

export default defineConfig(({ command, mode }) => ({
  base: './',
  ...(testServer ? { cacheDir: `node_modules/.vite-${testServer}` } : {}),
  // p5's translations from node_modules, not a CDN (scripts/p5-offline-i18n.js): in the build and the dev server's bundle of p5.
  // A saved sketch is swapped in place, or reloads only the pages running it; a syntax error is shown at its line (scripts/vite-live-coding.js).
  // A save that reaches the disk in two steps is taken as it ends, not half-way (scripts/every-save-arrives.js).
  // The web editor's page, its one-file build, the API reference and each lesson's
  // "API:" line, and the notice a lesson page shows when opened from a file: scripts/site-plugins.js.
  // The answers and the class server's ways (compressed, revalidated, p5 minified): scripts/classroom.js.
  // The class board (what students send, the teacher's /board): scripts/board/; its routes pass the class gate by name (BOARD_ROUTES).
  // A link too long for the server gets a page saying so (scripts/long-links.js).
  // The code editor's frame: p5 and the kit in one module, and each sketch's file as text (scripts/sketch-runtime.js).
  plugins: [teachersAnswers({ served: command === 'serve' ? mode !== 'class' : withSolutions }), ...(mode === 'class' ? [classroom({ isolation, routes: BOARD_ROUTES }), classBoard()] : []), longLinks(),
    p5OfflineI18n(), everySaveArrives(), reloadItsPagesOnly(), swapSketchesInPlace(), syntaxErrorsWhereTheyAre(), includeText(), oneFileInDev(), apiReference(), apiLine(), fromFileNotice(), sketchRuntime()],
  optimizeDeps: { rolldownOptions: { plugins: [p5OfflineI18n()] } },
  build: {
    target: 'es2022',
    outDir: withSolutions ? 'dist-teacher' : 'dist',
    chunkSizeWarningLimit: 1500, // p5 itself is 1.3 MB: one library, loaded once per page
    rolldownOptions: {
      input: [resolve('index.html'), resolve('web-editor.html'), resolve('teacher.html'), resolve('poll.html'), ...sketchPages],
      // Generating the API reference and bundling the render workers is this build's own work, not a slow plugin
      // to report: the reference parses the kit's files only (scripts/api-reference.js), the rest is Vite's.
      // The error panel is imported lazily by lib/p5/page/scene-holds.js so that the view, imported in Node or
      // before a page has one, touches no page (and no module circle forms); that it is in the page's chunk
      // anyway is no news for a teacher building the site.
      checks: { bundlerTimings: false, ineffectiveDynamicImport: false },
    },
  },
  worker: { format: 'es', rolldownOptions: { checks: { bundlerTimings: false } } },
  preview: { headers: isolation },
  server: {
    // The class server sends them itself, to loopback only (scripts/class-gate.js): browsers
    // ignore them on a student's plain-http address and say so in red on every page.
    headers: mode === 'class' ? {} : isolation,
    // The class server answers no other origin: no CORS headers, and its gate refuses their writes and preflights.
    ...(mode === 'class' ? { cors: false } : {}),
    // Test output must not reload pages under test.
    watch: { ignored: ['**/test-results/**', '**/playwright-report/**', '**/__screenshots__/**', '**/tests/pictures/**', ...unwatched] },
  },
}));
