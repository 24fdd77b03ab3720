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
 * lib/tracing/workers/parallel.js starts its worker from a file beside it; in one file
 * there is none, so the worker's code (bundled, a classic script) goes inside
 * the file and starts from a Blob URL: `?worker&inline` is Vite's own way.
 */
export function inlineRenderWorker() {
  return {
    name: 'inline-render-worker',
    enforce: 'pre',
    transform(code, id) {
      if (!id.endsWith('/lib/tracing/workers/parallel.js')) return null;
      if (!code.includes(WORKER_START)) this.error(`lib/tracing/workers/parallel.js no longer starts its worker with ${WORKER_START}: update vite.onefile.config.js`);
      return `import InlineRenderWorker from './render-worker.js?worker&inline';\n${code.replace(WORKER_START, INLINE_START)}`;
    },
  };
}

/** Where lib/p5/dom.js finds the kit's stylesheet, and where it is in one file. */
const STYLE_AT = "new URL('./style.css', import.meta.url).href";
const STYLE_INSIDE = "'data:text/css;charset=utf-8,' + encodeURIComponent(inlineStyle)";

/** lib/p5/dom.js links style.css from beside it; in one file the link's URL is the stylesheet itself. */
export function inlineStyle() {
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
 * Both files start with a `// noprotect` line: the p5 web editor rewrites every
 * .js file of a sketch without one so that each loop breaks out after 100 ms,
 * and the tracer's loops (a whole frame, the homework check's picture) run
 * longer on purpose: cut short, a picture would stop part-way without a word.
 */
const NOPROTECT = `// noprotect: the p5 web editor would otherwise rewrite every loop of this file to break out after 100 ms,
// leaving pictures traced part-way. Keep this line.
`;

/**
 * The classic script then checks for p5 (2.x, or 1.11 and later 1.x):
 * without it, the page would only say "p5 is not defined"; this says what to
 * change, in the console and on the page, in the mistake panel's style
 * (inline: the kit's stylesheet is not loaded yet).
 */
function needP5() {
  const check = `(function () { // a function of its own: the page gets no new global
if (typeof p5 !== 'function' || (typeof p5.registerAddon !== 'function' && !/^1\\.(1[1-9]|[2-9]\\d)\\./.test(p5.VERSION))) {
  var needP5 = 'raytracing-sketchbook.js needs p5.js 1.11 or 2.x loaded before it: put p5\\'s own <script> first' +
    (typeof p5 === 'function' ? ' (this page has p5 ' + p5.VERSION + ')' : ' (this page has no p5)');
  document.addEventListener('DOMContentLoaded', function () {
    var panel = document.createElement('div');
    panel.setAttribute('data-error', '');
    panel.setAttribute('role', 'alert');
    panel.style.cssText = 'position:fixed;left:1rem;right:1rem;bottom:1rem;z-index:10000;padding:0.8rem 1.1rem;background:#fff5f3;color:#1b1f24;border:3px solid #c4321b;border-radius:8px;font:600 1.3rem system-ui,sans-serif';
    panel.textContent = needP5;
    document.body.append(panel);
  });
  throw new Error(needP5);
}
})();
`;
  return {
    name: 'need-p5',
    renderChunk(code, chunk, options) {
      return { code: NOPROTECT + (options.format === 'iife' ? check : '') + code, map: null };
    },
  };
}

export default defineConfig({
  plugins: [inlineRenderWorker(), inlineStyle(), needP5()],
  worker: { format: 'iife', rolldownOptions: { checks: { bundlerTimings: false } } },
  build: {
    target: 'es2022',
    outDir: process.env.SKETCHBOOK_WITH_SOLUTIONS === '1' ? 'dist-teacher' : 'dist', // beside the site (vite.config.js)
    emptyOutDir: false, // the site is already there
    copyPublicDir: false,
    minify: false, // a file a teacher can read
    lib: {
      entry: 'lib/global.js',
      name: 'RT',
      formats: ['iife', 'es'],
      fileName: (format) => (format === 'es' ? 'raytracing-sketchbook.mjs' : 'raytracing-sketchbook.js'),
    },
    rolldownOptions: {
      external: ['p5'],
      // One file each: the panel's lazily loaded "did you mean" (lib/p5/page/mistake-hints.js) goes inside, not beside.
      output: { globals: { p5: 'p5' }, codeSplitting: false },
      checks: { bundlerTimings: false }, // inlining the render worker is the work of this build, not a slow plugin
    },
  },
});
