import { defineConfig } from 'vite';

// The one-file builds (npm run build, after the site): the library and the p5
// addon in dist/raytracing-sketchbook.js, a classic script defining the global
// RT for a page that loads p5's own <script> first (the p5 web editor's way),
// and in dist/raytracing-sketchbook.mjs, an ES module that imports 'p5'.
// Nothing beside them: the stylesheet and the render worker go inside (below).

/** The worker ParallelRenderer starts, and what starts it inside one file. */
const WORKER_START = "new Worker(new URL('./render-worker.js', import.meta.url), { type: 'module' })";
const INLINE_START = 'new InlineRenderWorker()';

/**
 * lib/workers/parallel.js starts its worker from a file beside it; in one file
 * there is none, so the worker's code (bundled, a classic script) goes inside
 * the file and starts from a Blob URL: `?worker&inline` is Vite's own way.
 */
function inlineRenderWorker() {
  return {
    name: 'inline-render-worker',
    enforce: 'pre',
    transform(code, id) {
      if (!id.endsWith('/lib/workers/parallel.js')) return null;
      if (!code.includes(WORKER_START)) this.error(`lib/workers/parallel.js no longer starts its worker with ${WORKER_START}: update vite.onefile.config.js`);
      return `import InlineRenderWorker from './render-worker.js?worker&inline';\n${code.replace(WORKER_START, INLINE_START)}`;
    },
  };
}

/** Where lib/p5/dom.js finds the kit's stylesheet, and where it is in one file. */
const STYLE_AT = "new URL('./style.css', import.meta.url).href";
const STYLE_INSIDE = "'data:text/css;charset=utf-8,' + encodeURIComponent(inlineStyle)";

/** lib/p5/dom.js links style.css from beside it; in one file the link's URL is the stylesheet itself. */
function inlineStyle() {
  return {
    name: 'inline-style',
    enforce: 'pre',
    transform(code, id) {
      if (!id.endsWith('/lib/p5/dom.js')) return null;
      if (!code.includes(STYLE_AT)) this.error(`lib/p5/dom.js no longer finds its stylesheet with ${STYLE_AT}: update vite.onefile.config.js`);
      return `import inlineStyle from './style.css?inline';\n${code.replace(STYLE_AT, STYLE_INSIDE)}`;
    },
  };
}

/**
 * The classic script starts by checking for p5 2.x: without it, or after p5
 * 1.x, the page would only say "p5 is not defined" or "registerAddon is not a
 * function"; this says what to change.
 */
function needP5Two() {
  const check = `if (typeof p5 !== 'function' || typeof p5.registerAddon !== 'function') {
  throw new Error('raytracing-sketchbook.js needs p5.js 2.x loaded before it: put p5\\'s own <script> first' +
    (typeof p5 === 'function' ? ' (this page has p5 ' + p5.VERSION + ')' : ' (this page has no p5)'));
}
`;
  return {
    name: 'need-p5-two',
    renderChunk(code, chunk, options) {
      return options.format === 'iife' ? { code: check + code, map: null } : null;
    },
  };
}

export default defineConfig({
  plugins: [inlineRenderWorker(), inlineStyle(), needP5Two()],
  worker: { format: 'iife' },
  build: {
    target: 'es2022',
    outDir: 'dist',
    emptyOutDir: false, // the site is already there
    copyPublicDir: false,
    minify: false, // a file a teacher can read
    lib: {
      entry: 'lib/global.js',
      name: 'RT',
      formats: ['iife', 'es'],
      fileName: (format) => (format === 'es' ? 'raytracing-sketchbook.mjs' : 'raytracing-sketchbook.js'),
    },
    rollupOptions: {
      external: ['p5'],
      // One file each: the panel's lazily loaded "did you mean" (lib/p5/mistake-hints.js) goes inside, not beside.
      output: { globals: { p5: 'p5' }, inlineDynamicImports: true },
    },
  },
});
