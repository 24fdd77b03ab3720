/**
 * Vite plugins for live coding in class.
 *
 * syntaxErrorsWhereTheyAre: a syntax error in a sketch is reported at its
 * own line and column. Vite's import analysis (es-module-lexer) fails on
 * some syntax errors (an unclosed string or bracket) without a position, so
 * its overlay pointed at 1:0; others (`1 +* 2`) it let through, and the page
 * died in the browser with nothing on it, its modules never run. This
 * plugin parses each of the project's scripts first (Vite's own parseAst,
 * Oxc) and reports the first error with its position: a page's own script
 * shows it in the kit's error panel on that page (file, line, the line
 * itself), any other module in Vite's overlay (file, line, column, code).
 * A page's script that imports from the kit a name it does not export, or a
 * kit file that is not there (kit-imports.js), is shown the same way, with
 * the nearest name; and every page gets a small classic script that shows
 * any other module the browser refuses to load, in the same panel.
 *
 * reloadItsPagesOnly: a saved sketch file reloads the pages that run it, not
 * every page open on the dev server. Vite's default for a module with no HMR
 * boundary is a reload of every page, so one save by the teacher would reload
 * every student's page on the classroom network (and every page under test).
 * The plugin walks the module graph up from the saved file to the scripts
 * pages load (modules nothing imports) and reloads each one's page: the
 * `.html` of the same name beside it (sketches/10-playground.js →
 * sketches/10-playground.html), or the page itself for an inline script.
 * When a root has no such page (a worker), it leaves the update to Vite.
 *
 * swapSketchesInPlace: a save of a page's own script swaps it in place (no
 * reload, so the first preview comes within 100 ms): the script is served
 * with Vite's HMR hooks, which hand the swap to lib/p5/page/hot-swap.js. Only a
 * script that imports nothing but p5 and the kit's lib/, and that calls
 * nothing outside p5 it cannot undo (timers, workers, the camera…: see
 * OUTSIDE_P5), is served so; a save of any other
 * script, or of a module it imports, reloads its pages as before.
 */
import { existsSync } from 'node:fs';
import { relative, resolve } from 'node:path';
import { parseAst } from 'vite';
import { badKitImport } from './kit-imports.js';

/** Each page script served with the swap hooks (absolute path → true), for reloadItsPagesOnly. */
const swappable = new Map();

export function syntaxErrorsWhereTheyAre() {
  let root = process.cwd();
  return {
    name: 'sketchbook:syntax-errors-where-they-are',
    apply: 'serve',
    enforce: 'pre',
    configResolved(config) { root = config.root; },
    transform(code, id) {
      const [file, query = ''] = id.split('?');
      if (!/\.m?js$/.test(file) || file.includes('/node_modules/') || id.startsWith('\0') || /(^|&)(raw|url|inline)\b/.test(query)) return null;
      const isPageScript = existsSync(file.replace(/\.m?js$/, '.html'));
      let program;
      try {
        program = parseAst(code, undefined, file);
      } catch (error) {
        if (typeof error?.pos !== 'number') throw error;
        // "Parse failed with 1 error:\nUnterminated string\n2: …": the line that names it.
        const message = String(error.message).split('\n')[1]?.trim() || 'invalid JavaScript';
        if (!isPageScript) this.error(`Syntax error: ${message}`, error.pos); // Vite's overlay
        return mistakeModule(root, file, code, error.pos, `SyntaxError: ${message}`);
      }
      // A page's script importing what the kit does not have: the browser would refuse every module of the page.
      const bad = isPageScript ? badKitImport(program, file, resolve(import.meta.dirname, '../lib')) : null;
      return bad ? mistakeModule(root, file, code, bad.pos, bad.message, bad.suggestion) : null;
    },
    // Before any module: a module the page cannot load (a mistake the checks above miss) is shown in the panel too.
    transformIndexHtml: () => [{ tag: 'script', children: failedModuleScript(root), injectTo: 'head-prepend' }],
  };
}

/**
 * A classic script for every page the dev server serves. When the browser
 * refuses a page's module graph (an import the page's script cannot have),
 * none of its modules runs, the kit's panel included; this script, run
 * first, hears the error and loads the panel by itself to show it (the
 * module and line the browser names; the nearest export the module has).
 * Once the kit's panel is installed, it leaves every error to it. It also
 * marks the page as the dev server's (lib/p5/page/last-picture.js: a page that
 * a save reloads keeps its last good picture for after the reload).
 */
function failedModuleScript(root) {
  const panel = '/' + relative(root, resolve(import.meta.dirname, '../lib/p5/page/error-panel.js')).split('\\').join('/');
  return `window.__sketchbookDevServer = true;
addEventListener('error', function (event) {
  if (window.__sketchbookErrorPanel || !(event.error instanceof SyntaxError || event.target instanceof HTMLScriptElement)) return;
  var script = event.target instanceof HTMLScriptElement ? event.target.src : '';
  import(${JSON.stringify(panel)}).then(function (m) { m.showModuleFailure(event, script); });
}, true);`;
}

/**
 * A page's script with a syntax error (or an import the kit cannot give) is
 * served as a module that shows the mistake on that page alone, in the kit's own panel (lib/p5/page/error-panel.js),
 * and in the console: Vite's overlay would appear on every page open on the
 * server, each student's included.
 */
function mistakeModule(root, file, code, pos, text, suggestion = null) {
  const before = code.slice(0, pos).split('\n');
  const line = before.length, column = before.at(-1).length + 1;
  const where = { file: relative(root, file).split('\\').join('/'), line, column, source: code.split('\n')[line - 1], exact: true, ...(suggestion && { suggestion }) };
  const panel = '/' + relative(root, resolve(import.meta.dirname, '../lib/p5/page/error-panel.js')).split('\\').join('/');
  return [
    `import { showMistake } from ${JSON.stringify(panel)};`,
    `console.error(${JSON.stringify(`${text}${suggestion ? ` (${suggestion})` : ''} (${where.file}:${line}:${column})`)});`,
    `showMistake(${JSON.stringify(text)}, ${JSON.stringify(where)});`,
  ].join('\n');
}

export function reloadItsPagesOnly() {
  return {
    name: 'sketchbook:reload-its-pages-only',
    apply: 'serve',
    hotUpdate({ file, modules, server }) {
      if (this.environment.name !== 'client' || modules.length === 0 || !/\.[cm]?js$/.test(file)) return undefined;
      // A page's own script served with the swap hooks: Vite sends the update, and only pages that run it have it.
      if (modules.every((mod) => mod.isSelfAccepting && swappable.get(mod.file))) return undefined;
      const pages = pagesOf(modules, server.config.root);
      if (!pages) return undefined;
      for (const page of pages) {
        this.environment.hot.send({ type: 'full-reload', path: `/${page}`, triggeredBy: file });
      }
      return []; // handled: no reload of every page
    },
  };
}

/** The pages (paths from the root) whose scripts import `modules`, or null when one root is not a page's script. */
function pagesOf(modules, root) {
  const pages = new Set(), seen = new Set(), stack = [...modules];
  while (stack.length > 0) {
    const mod = stack.pop();
    if (seen.has(mod)) continue;
    seen.add(mod);
    if (mod.isSelfAccepting && !swappable.get(mod.file)) return null; // it can swap itself: Vite's own HMR
    if (mod.importers.size > 0) {
      stack.push(...mod.importers);
      continue;
    }
    if (mod.file?.endsWith('.html')) { // a page's inline script
      pages.add(relative(root, mod.file).split('\\').join('/'));
      continue;
    }
    const html = mod.file?.replace(/\.[cm]?js$/, '.html');
    if (!html || html === mod.file || !existsSync(html)) return null;
    pages.add(relative(root, html).split('\\').join('/'));
  }
  return pages;
}

/**
 * Names that reach outside p5 in a way a swap could not undo: a timer would
 * go on calling the old sketch, a worker or the camera would go on running.
 * A script that holds any of them reloads its page on a save. (Listeners
 * are watched on the page instead, by lib/p5/page/hot-swap.js: one on an element
 * the swap removes goes with it.)
 */
const OUTSIDE_P5 = new Set([
  'setTimeout', 'setInterval', 'requestAnimationFrame', 'requestIdleCallback',
  'Worker', 'SharedWorker', 'WebSocket', 'EventSource', 'BroadcastChannel', 'AudioContext', 'webkitAudioContext',
  'MutationObserver', 'ResizeObserver', 'IntersectionObserver', 'PerformanceObserver',
  'createCapture', 'createAudio', 'createVideo', 'getUserMedia',
]);

export function swapSketchesInPlace() {
  let root = process.cwd();
  return {
    name: 'sketchbook:swap-sketches-in-place',
    apply: 'serve',
    configResolved(config) { root = config.root; },
    transform(code, id) {
      const file = id.split('?')[0];
      if (id.includes('?') || !/\.m?js$/.test(file) || file.includes('/node_modules/') || id.startsWith('\0')) return null;
      if (!existsSync(file.replace(/\.m?js$/, '.html'))) return null;
      const hooks = swapHooks(root, file, code);
      swappable.set(file, hooks !== null);
      return hooks;
    },
  };
}

/**
 * The script with the swap hooks, or null when it cannot be swapped. The
 * hooks go on its first line (as Vite's own do) and an import after its last,
 * so every line keeps its number for the mistake panel.
 */
export function swapHooks(root, file, code) {
  let program;
  try { program = parseAst(code, undefined, file); } catch { return null; }
  const lib = resolve(import.meta.dirname, '../lib');
  for (const node of program.body) {
    if (node.type !== 'ImportDeclaration' && !(node.type.startsWith('Export') && node.source)) continue;
    const from = node.source.value;
    if (from === 'p5') continue;
    if (!from.startsWith('.') && !from.startsWith('/')) return null;
    const path = from.startsWith('/') ? resolve(root, `.${from}`) : resolve(file, '..', from);
    if (!path.startsWith(lib + '/')) return null; // the sketch's own module: its saves reload the page
  }
  if (reachesOutsideP5(program)) return null;
  const swap = '/' + relative(root, resolve(lib, 'p5/page/hot-swap.js')).split('\\').join('/');
  return `if (import.meta.hot) { import.meta.hot.accept(__sketchbookSwap.swappedIn); import.meta.hot.dispose(__sketchbookSwap.swapOut); } ${code}\nimport * as __sketchbookSwap from ${JSON.stringify(swap)};\n`;
}

/** Does the program name a function of OUTSIDE_P5, or set a handler (`window.onresize = …`)? */
function reachesOutsideP5(node) {
  if (Array.isArray(node)) return node.some(reachesOutsideP5);
  if (node === null || typeof node !== 'object') return false;
  if (node.type === 'Identifier' && OUTSIDE_P5.has(node.name)) return true;
  if (node.type === 'AssignmentExpression' && node.left.type === 'MemberExpression' && /^on[a-z]+$/.test(node.left.property?.name ?? '')) return true;
  for (const key in node) {
    if (key !== 'type' && key !== 'start' && key !== 'end' && reachesOutsideP5(node[key])) return true;
  }
  return false;
}
