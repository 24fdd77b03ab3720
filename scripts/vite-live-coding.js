/**
 * Vite plugins for live coding in class.
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
 */
import { existsSync } from 'node:fs';
import { relative } from 'node:path';

export function reloadItsPagesOnly() {
  return {
    name: 'sketchbook:reload-its-pages-only',
    apply: 'serve',
    hotUpdate({ file, modules, server }) {
      if (this.environment.name !== 'client' || modules.length === 0 || !/\.[cm]?js$/.test(file)) return undefined;
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
    if (mod.isSelfAccepting) return null; // it can swap itself: Vite's own HMR
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
