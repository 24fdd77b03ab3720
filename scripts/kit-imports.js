/**
 * Imports from the kit that cannot work, found by the dev server before the
 * browser does: a name the module does not export (`import { createTracerVeiw }
 * from '../lib/p5/index.js'`, typical after copying from an older page), or a
 * kit file that is not there. The browser refuses the whole module graph for
 * either, so no script of the page runs and the page stays blank; the dev
 * server (vite-live-coding.js) shows the mistake on the page instead, with the
 * nearest name the module does export.
 */
import { existsSync, readFileSync, readdirSync, statSync } from 'node:fs';
import { basename, dirname, relative, resolve } from 'node:path';
import { parseAst } from 'vite';
import { closestName } from '../lib/text/check.js';

/** Export names of each module read so far: path → { mtime, names }. */
const cache = new Map();

/**
 * The names a module exports, `export * from` followed (a module that cannot
 * be read or parsed exports nothing we know of: null).
 * @param {string} file an absolute path
 * @returns {Set<string>|null}
 */
export function exportsOf(file, seen = new Set()) {
  if (seen.has(file)) return new Set(); // a circle of `export *`: its names come from elsewhere
  seen.add(file);
  let mtime;
  try { mtime = statSync(file).mtimeMs; } catch { return null; }
  const known = cache.get(file);
  if (known?.mtime === mtime && known.names) return known.names;
  let program;
  try { program = parseAst(readFileSync(file, 'utf8'), undefined, file); } catch { return null; }
  const names = new Set();
  for (const node of program.body) {
    if (node.type === 'ExportDefaultDeclaration') names.add('default');
    if (node.type === 'ExportAllDeclaration') {
      if (node.exported) names.add(nameOf(node.exported));
      else for (const name of exportsOf(resolve(dirname(file), node.source.value), seen) ?? []) if (name !== 'default') names.add(name);
    }
    if (node.type !== 'ExportNamedDeclaration') continue;
    for (const s of node.specifiers ?? []) names.add(nameOf(s.exported));
    const d = node.declaration;
    if (d?.id) names.add(d.id.name);
    for (const v of d?.declarations ?? []) if (v.id.type === 'Identifier') names.add(v.id.name);
  }
  cache.set(file, { mtime, names });
  return names;
}

/**
 * The first import of `program` (the parsed script `file`) from the kit's
 * `lib` folder that the browser would refuse, or null.
 * @returns {{ pos: number, from: string, message: string, suggestion: string|null }|null}
 */
export function badKitImport(program, file, lib) {
  for (const node of program.body) {
    if (node.type !== 'ImportDeclaration' && !(node.type.startsWith('Export') && node.source)) continue;
    const from = node.source.value;
    if (!from.startsWith('.')) continue; // p5, another package, a path from the root: Vite's to resolve
    const path = resolve(dirname(file), from);
    if (!path.startsWith(lib + '/')) continue;
    if (!existsSync(path)) return missingFile(node, from, path, lib);
    const names = exportsOf(path);
    if (!names) continue;
    const methods = path === resolve(lib, 'p5/index.js') ? addonMethods(lib) : new Set();
    for (const s of node.specifiers ?? []) {
      const name = s.type === 'ImportSpecifier' ? nameOf(s.imported) : s.type === 'ImportDefaultSpecifier' ? 'default' : s.type === 'ExportSpecifier' ? nameOf(s.local) : null;
      if (name === null || names.has(name)) continue;
      return {
        pos: (s.imported ?? s.local ?? s).start,
        from,
        message: `SyntaxError: The requested module '${from}' does not provide an export named '${name}'`,
        suggestion: suggestion(name, names, methods, from),
      };
    }
  }
  return null;
}

/**
 * What the import meant: the nearest export, or a method of the p5 addon
 * (createTracerView is no export: importing lib/p5 gives every sketch `p.createTracerView`).
 */
function suggestion(name, names, methods, from) {
  if (name === 'default') return `it has named exports only: import { … } from '${from}'`;
  const meant = closestName(name, [...names, ...methods]);
  if (meant === null) return null;
  if (!methods.has(meant) || names.has(meant)) return `did you mean ${meant}?`;
  const method = `is a method of p, not an export: write p.${meant}({ … })`;
  return meant === name ? `${meant} ${method}` : `did you mean ${meant}? It ${method}`;
}

/** The names of the p5 addon's methods: the keys of FACTORIES in lib/p5/addon.js. */
function addonMethods(lib) {
  const file = resolve(lib, 'p5/addon.js');
  try {
    for (const node of parseAst(readFileSync(file, 'utf8'), undefined, file).body) {
      const factories = node.declaration?.declarations?.find((d) => d.id.name === 'FACTORIES');
      if (factories?.init?.type === 'ObjectExpression') return new Set(factories.init.properties.filter((p) => p.key).map((p) => nameOf(p.key)));
    }
  } catch { /* no such list to read: no method to suggest */ }
  return new Set();
}

/** An import of a kit file that is not there, with the nearest file of its folder. */
function missingFile(node, from, path, lib) {
  let siblings = [];
  try { siblings = readdirSync(dirname(path)).filter((f) => /\.m?js$/.test(f)); } catch { /* no such folder either */ }
  const meant = closestName(basename(path), siblings);
  const fixed = meant ? from.slice(0, from.length - basename(path).length) + meant : null;
  return {
    pos: node.source.start,
    from,
    message: `TypeError: Failed to fetch the module '${from}': there is no ${relative(dirname(lib), path).split('\\').join('/')}`,
    suggestion: fixed ? `did you mean '${fixed}'?` : null,
  };
}

/** An export or import name: an identifier, or a string (`import { "a b" as c }`). */
function nameOf(node) {
  return node.type === 'Identifier' ? node.name : String(node.value);
}
