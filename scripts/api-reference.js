/**
 * The API reference (dist/api/index.html; /api/ in `npm start`), generated
 * from the library's JSDoc: every export of the two entry points, lib/index.js
 * (the library) and lib/p5/index.js (the p5 addon), and every p5 method the
 * addon adds (its FACTORIES table). For each: what it is (the JSDoc's text),
 * how it is called, its options with types and defaults (`@param` lines),
 * what it returns, its methods, and its `@example`.
 *
 * TypeScript's parser finds the exports and their declarations (the same
 * reading of the JSDoc as the package's types); the JSDoc text itself is read
 * here, since TypeScript keeps no `[name=default]` defaults.
 */
import ts from 'typescript';
import { readFileSync } from 'node:fs';
import { resolve, relative } from 'node:path';

/** The entry points: where the names come from, and how a sketch gets them. */
export const ENTRIES = [
  {
    id: 'library',
    file: 'lib/index.js',
    title: 'The library',
    about: 'Scenes, shapes, materials, lights, the camera and the tracer itself. No p5: it runs in Node, in the browser and in Web Workers.',
    imports: [
      "import { Scene, Sphere, Camera, render } from 'raytracing-sketchbook';   // npm package",
      "import { Scene, Sphere, Camera, render } from '../lib/index.js';         // a sketch of this kit",
      'new RT.Scene(), new RT.Sphere(…)                                       // raytracing-sketchbook.js (one file)',
    ],
  },
  {
    id: 'p5',
    file: 'lib/p5/index.js',
    title: 'The p5 addon',
    about: 'Importing it registers the addon with p5 2.x: the sketch gets the methods listed under “p5 methods”, each taking one options object. The module also exports the classes those methods return.',
    imports: [
      "import 'raytracing-sketchbook/p5';   // npm package (p5 2.x installed beside it)",
      "import '../lib/p5/index.js';         // a sketch of this kit",
      '<script src="raytracing-sketchbook.js"></script> after p5\'s own <script>: global mode, createTracerView({ … }) bare',
    ],
  },
];

/**
 * Exports the kit's own pages use (text in slices, the page's render state, links, DOM helpers,
 * number formatting): named in the reference, but apart, after what a teacher's sketch uses.
 */
export const INTERNAL = new Set([
  'joinInSlices', 'nextTask', 'sceneCodeLines', 'solutionParameter', 'registerShape', 'ProgressiveRenderer', 'ParallelRenderer',
  'sketchbookAddon', 'FACTORIES', 'fmt', 'formatLabel', 'exampleInLink', 'pageRenderState',
  'readSceneLink', 'sceneLinkURL', 'linkNotice', 'element', 'copyText', 'showInBox', 'downloadText',
]);

/** `{ entries: [{ …entry, items }], methods }`: everything the reference names, in source order. */
export function collectAPI(root = process.cwd()) {
  const files = ENTRIES.map((e) => resolve(root, e.file));
  const options = { allowJs: true, checkJs: false, noEmit: true, target: ts.ScriptTarget.ES2022, module: ts.ModuleKind.ESNext, moduleResolution: ts.ModuleResolutionKind.Bundler, types: [], noLib: true };
  const program = ts.createProgram(files, options, kitOnlyHost(options));
  const checker = program.getTypeChecker();
  const rel = (node) => relative(root, node.getSourceFile().fileName);

  const entries = ENTRIES.map((entry, i) => {
    const source = program.getSourceFile(files[i]);
    const moduleSymbol = checker.getSymbolAtLocation(source);
    const items = [];
    for (const exported of checker.getExportsOfModule(moduleSymbol)) {
      const symbol = exported.flags & ts.SymbolFlags.Alias ? checker.getAliasedSymbol(exported) : exported;
      const declaration = symbol.valueDeclaration ?? symbol.declarations?.[0];
      if (!declaration) continue;
      items.push(describe(exported.name, symbol, declaration, checker, rel));
    }
    return { ...entry, items };
  });

  // The p5 methods: the addon's FACTORIES table, each factory without its `p`.
  const methods = [];
  const table = entries.find((e) => e.id === 'p5').items.find((item) => item.name === 'FACTORIES');
  if (table?.node && ts.isVariableDeclaration(table.node) && table.node.initializer && ts.isObjectLiteralExpression(table.node.initializer)) {
    for (const property of table.node.initializer.properties) {
      const name = property.name?.getText();
      if (!name) continue;
      let target = property;
      let doc = ownDoc(property);
      const value = ts.isShorthandPropertyAssignment(property) ? property.name : property.initializer;
      const callee = value && (ts.isIdentifier(value) ? value
        : ts.isArrowFunction(value) && ts.isCallExpression(value.body) ? value.body.expression : null);
      if (callee) {
        let symbol = ts.isShorthandPropertyAssignment(property) ? checker.getShorthandAssignmentValueSymbol(property) : checker.getSymbolAtLocation(callee);
        if (symbol && symbol.flags & ts.SymbolFlags.Alias) symbol = checker.getAliasedSymbol(symbol);
        target = symbol?.valueDeclaration ?? target;
        doc = doc ?? ownDoc(target);
      }
      methods.push({ name, kind: 'p5 method', doc: doc ?? emptyDoc(), file: rel(target), factory: true, target });
    }
  }
  // A factory alone in its module: the module's opening comment (what the panel shows, how a sketch uses it) goes first.
  for (const method of methods) {
    const header = methods.filter((m) => m.file === method.file).length === 1 ? moduleDoc(method.target) : null;
    if (header?.text) method.doc = { ...method.doc, text: [header.text, method.doc.text].filter(Boolean).join('\n\n') };
    delete method.target;
  }
  for (const item of entries.flatMap((e) => e.items)) delete item.node;
  return { entries, methods };
}

/**
 * A compiler host that follows the kit's own imports only: the reference names
 * what lib/ exports, and p5's declarations (which lib/p5/ imports) took most of
 * the build's time to parse for nothing.
 */
function kitOnlyHost(options) {
  const host = ts.createCompilerHost(options);
  host.resolveModuleNameLiterals = (literals, containingFile, redirected, compilerOptions) => literals.map((literal) => (literal.text.startsWith('.')
    ? ts.resolveModuleName(literal.text, containingFile, compilerOptions, host, undefined, redirected)
    : { resolvedModule: undefined }));
  return host;
}

/** One export: its kind, its JSDoc, a constructor's or a class's methods. */
function describe(name, symbol, declaration, checker, rel) {
  const item = { name, file: rel(declaration), node: declaration };
  if (ts.isClassDeclaration(declaration)) {
    item.kind = 'class';
    const constructor = declaration.members.find(ts.isConstructorDeclaration);
    const classDoc = ownDoc(declaration) ?? moduleDoc(declaration);
    const constructorDoc = constructor ? ownDoc(constructor) : null;
    item.doc = mergeDocs(classDoc, constructorDoc);
    item.params = constructor ? constructor.parameters.map((p) => paramName(p)) : [];
    item.members = [];
    for (const member of declaration.members) {
      if (ts.isConstructorDeclaration(member) || !member.name || ts.isPrivateIdentifier(member.name)) continue;
      const memberName = member.name.getText();
      if (memberName.startsWith('_') || !(ts.isMethodDeclaration(member) || ts.isGetAccessor(member) || ts.isPropertyDeclaration(member))) continue;
      if (ts.isPropertyDeclaration(member) && !ownDoc(member)) continue;
      const isStatic = member.modifiers?.some((m) => m.kind === ts.SyntaxKind.StaticKeyword) ?? false;
      item.members.push({
        name: memberName,
        static: isStatic,
        kind: ts.isMethodDeclaration(member) ? 'method' : 'property',
        params: ts.isMethodDeclaration(member) ? member.parameters.map((p) => paramName(p)) : null,
        doc: ownDoc(member) ?? emptyDoc(),
      });
    }
  } else if (ts.isFunctionDeclaration(declaration)) {
    item.kind = 'function';
    item.doc = ownDoc(declaration) ?? emptyDoc();
    item.params = declaration.parameters.map((p) => paramName(p));
  } else if (ts.isVariableDeclaration(declaration)) {
    const init = declaration.initializer;
    const isFunction = init && (ts.isArrowFunction(init) || ts.isFunctionExpression(init));
    item.kind = isFunction ? 'function' : 'constant';
    item.doc = ownDoc(declaration) ?? emptyDoc();
    if (isFunction) item.params = init.parameters.map((p) => paramName(p));
    else if (init && init.getText().length <= 40) item.value = init.getText();
  } else if (ts.isSourceFile(declaration) || ts.isModuleDeclaration(declaration)) {
    item.kind = 'namespace';
    const first = declaration.statements?.[0];
    item.doc = first ? (ownDoc(first) ?? emptyDoc()) : emptyDoc();
    item.members = checker.getExportsOfModule(symbol).map((s) => ({ name: s.name, kind: 'function', params: null, doc: emptyDoc() }));
  } else {
    item.kind = 'value';
    item.doc = ownDoc(declaration) ?? emptyDoc();
  }
  return item;
}

/** A parameter's name as the JSDoc would call it: `options` for a destructured one. */
function paramName(parameter) {
  return { name: ts.isIdentifier(parameter.name) ? parameter.name.text : null, optional: Boolean(parameter.initializer || parameter.questionToken || parameter.dotDotDotToken) };
}

/** The JSDoc right above a declaration, parsed; null when it has none. */
function ownDoc(node) {
  const docs = ts.getJSDocCommentsAndTags(node).filter((d) => d.kind === ts.SyntaxKind.JSDoc);
  if (docs.length === 0) return null;
  return parseJSDoc(docs[docs.length - 1].getText());
}

/**
 * A module's opening comment, the one above its imports: where a file of one
 * class (or one panel) says what it is in the lesson. Null when the module
 * opens with no import, since its first comment then belongs to its first declaration.
 */
function moduleDoc(node) {
  const first = node.getSourceFile().statements[0];
  return first && ts.isImportDeclaration(first) ? ownDoc(first) : null;
}

function emptyDoc() {
  return { text: '', params: [], returns: null, examples: [] };
}

/** A class: its own JSDoc's text first, then its constructor's; the constructor's @params. */
function mergeDocs(classDoc, constructorDoc) {
  if (!classDoc) return constructorDoc ?? emptyDoc();
  if (!constructorDoc) return classDoc;
  return {
    text: [classDoc.text, constructorDoc.text].filter(Boolean).join('\n\n'),
    params: constructorDoc.params,
    returns: null,
    examples: [...classDoc.examples, ...constructorDoc.examples],
  };
}

/**
 * `/** text  @param {type} [name=default] what  @returns {type} what  @example code *\/`
 * as `{ text, params: [{ name, type, optional, defaultValue, text }], returns, examples }`.
 */
export function parseJSDoc(raw) {
  const lines = raw.replace(/^\/\*\*/, '').replace(/\*\/$/, '').split('\n').map((line) => line.replace(/^\s*\* ?/, ''));
  const blocks = [{ tag: null, lines: [] }];
  for (const line of lines) {
    const tag = /^@(\w+)\s?(.*)$/.exec(line);
    if (tag) blocks.push({ tag: tag[1], lines: [tag[2]] });
    else blocks[blocks.length - 1].lines.push(line);
  }
  const doc = { text: blocks[0].lines.join('\n').trim(), params: [], returns: null, examples: [] };
  for (const block of blocks.slice(1)) {
    const body = block.lines.join('\n');
    if (block.tag === 'param') doc.params.push(parseParam(body));
    else if (block.tag === 'returns' || block.tag === 'return') {
      const [type, rest] = readBraces(body.trim());
      doc.returns = { type: cleanType(type), text: oneLine(rest) };
    } else if (block.tag === 'example') doc.examples.push(dedent(block.lines).trim());
  }
  return doc;
}

function parseParam(body) {
  const [type, afterType] = readBraces(body.trim());
  let rest = afterType.trimStart();
  let name, optional = false, defaultValue = null;
  if (rest.startsWith('[')) {
    optional = true;
    let depth = 0, end = 0;
    for (; end < rest.length; end++) {
      if (rest[end] === '[') depth++;
      if (rest[end] === ']' && --depth === 0) break;
    }
    const inside = rest.slice(1, end);
    const eq = inside.indexOf('=');
    name = (eq < 0 ? inside : inside.slice(0, eq)).trim();
    defaultValue = eq < 0 ? null : inside.slice(eq + 1).trim();
    rest = rest.slice(end + 1);
  } else {
    const match = /^(\S+)/.exec(rest);
    name = match ? match[1] : '';
    rest = rest.slice(name.length);
  }
  return { name, type: cleanType(type), optional, defaultValue, text: oneLine(rest.replace(/^\s*-\s*/, '')) };
}

/** `{a {b} c} rest` → ['a {b} c', ' rest']; no braces → ['', text]. */
function readBraces(text) {
  if (!text.startsWith('{')) return ['', text];
  let depth = 0;
  for (let i = 0; i < text.length; i++) {
    if (text[i] === '{') depth++;
    if (text[i] === '}' && --depth === 0) return [text.slice(1, i), text.slice(i + 1)];
  }
  return [text.slice(1), ''];
}

/** A JSDoc type as a student reads it: `import('../scene.js').Scene` is `Scene`. */
function cleanType(type) {
  return type.replace(/import\(['"]p5['"]\)\.default/g, 'p5').replace(/import\(['"][^'"]+['"]\)\./g, '').replace(/\s+/g, ' ').trim();
}

const oneLine = (text) => text.replace(/\s+/g, ' ').trim();

function dedent(lines) {
  const body = lines.join('\n').replace(/^\n+/, '');
  const indents = body.split('\n').filter((l) => l.trim()).map((l) => /^ */.exec(l)[0].length);
  const min = indents.length ? Math.min(...indents) : 0;
  return body.split('\n').map((l) => l.slice(min)).join('\n');
}

/* ------------------------------- the page -------------------------------- */

const esc = (text) => String(text).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

/** How an item is called: `new Sphere(center, radius, material?)`, `p.createTracerView({ … })`. */
export function signature(item) {
  const names = callNames(item.params ?? [], item.doc.params);
  if (item.kind === 'class') return `new ${item.name}(${names.join(', ')})`;
  if (item.kind === 'p5 method') {
    const options = item.doc.params.filter((p) => /^\w+\.\w+$/.test(p.name) && !p.name.startsWith('p.')).map((p) => p.name.split('.')[1] + (p.optional ? '?' : ''));
    return options.length ? `p.${item.name}({ ${options.join(', ')} })` : `p.${item.name}(options)`;
  }
  if (item.kind === 'function') return `${item.name}(${names.join(', ')})`;
  if (item.kind === 'constant' && item.value) return `${item.name} = ${item.value}`;
  return item.name;
}

/**
 * The parameters as a call writes them: the code's own names (a destructured
 * one takes its JSDoc name, else `options`), `?` when the JSDoc or a default
 * makes it optional.
 */
function callNames(params, docParams) {
  const top = docParams.filter((p) => !p.name.includes('.'));
  return params.map((p, i) => {
    const name = p.name ?? top[i]?.name ?? 'options';
    const doc = top.find((d) => d.name === name);
    return name + (p.optional || doc?.optional ? '?' : '');
  });
}

/**
 * Turns the text of a JSDoc into paragraphs; `code` stays code, and a
 * paragraph indented as a whole (a comment's code sample or table) stays as written.
 */
function prose(text, name) {
  if (!text) return '';
  return text.split(/\n\s*\n/).map((paragraph) => {
    const lines = paragraph.split('\n').filter((line) => line.trim());
    if (lines.every((line) => /^ {2}/.test(line))) {
      return `<pre class="aside" tabindex="0" role="region" aria-label="${esc(`Code in the description of ${name}`)}"><code>${esc(dedent(lines))}</code></pre>`;
    }
    return `<p>${inlineCode(esc(oneLine(paragraph)))}</p>`;
  }).join('\n');
}

const inlineCode = (html) => html.replace(/`([^`]+)`/g, '<code>$1</code>');

/** A type, with the names the reference documents linked to their entries. */
function typeHTML(type, known) {
  return esc(type).replace(/\b[A-Z]\w*\b/g, (name) => (known.has(name) ? `<a href="#${name}">${name}</a>` : name));
}

function paramsTable(item, known) {
  // A p5 method: its options only (the sketch is `this`, the options object is the one argument).
  const params = item.kind === 'p5 method' ? item.doc.params.slice(1).filter((p, i) => i > 0 || p.name.includes('.') || p.text) : item.doc.params;
  if (params.length === 0) return '';
  const shown = (name) => (item.kind === 'p5 method' ? name.replace(/^\w+\./, '') : name); // the options object is the call's one argument
  const rows = params.map((p) => `<tr><td><code>${esc(shown(p.name))}</code>${p.optional ? '' : ' <span class="required">required</span>'}</td>` +
    `<td><code>${typeHTML(p.type || 'any', known)}</code></td><td>${p.defaultValue === null ? '' : `<code>${esc(p.defaultValue)}</code>`}</td>` +
    `<td>${inlineCode(esc(p.text))}</td></tr>`).join('\n');
  // In its own scroll box (focusable, named) on a narrow screen: the page itself never scrolls sideways.
  return `<div class="params-wrap" tabindex="0" role="region" aria-label="${esc(`${item.name}: ${item.kind === 'p5 method' ? 'options' : 'parameters'}`)}"><table class="params"><thead><tr><th>${item.kind === 'p5 method' ? 'option' : 'parameter'}</th><th>type</th><th>default</th><th></th></tr></thead>\n<tbody>${rows}</tbody></table></div>`;
}

function itemHTML(item, known, where) {
  const parts = [`<section class="item" id="${esc(item.name)}">`,
    `<h3><code>${esc(item.name)}</code> <span class="kind">${esc(item.kind)}</span></h3>`,
    `<pre class="signature"><code>${esc(signature(item))}</code></pre>`,
    prose(item.doc.text, item.name), paramsTable(item, known)];
  if (item.doc.returns) parts.push(`<p class="returns">Returns <code>${typeHTML(item.doc.returns.type, known)}</code>${item.doc.returns.text ? `: ${inlineCode(esc(item.doc.returns.text))}` : ''}</p>`);
  if (item.members?.length) {
    parts.push('<dl class="members">');
    for (const m of item.members) {
      const call = m.params ? `${m.name}(${callNames(m.params, m.doc.params).join(', ')})` : m.name;
      const owner = m.static ? item.name : item.name.charAt(0).toLowerCase() + item.name.slice(1);
      parts.push(`<dt><code>${esc(item.kind === 'namespace' ? `${item.name}.${call}` : `${owner}.${call}`)}</code></dt><dd>${inlineCode(esc(oneLine(m.doc.text.split(/\n\s*\n/)[0] ?? '')))}</dd>`);
    }
    parts.push('</dl>');
  }
  // a box that may scroll sideways takes focus (its arrow keys scroll it) and says what it holds
  item.doc.examples.forEach((example, i) => parts.push(`<pre class="example" tabindex="0" role="region" aria-label="${esc(`Example${item.doc.examples.length > 1 ? ` ${i + 1}` : ''} of ${item.name}`)}"><code>${esc(example)}</code></pre>`));
  parts.push(`<p class="source">${esc(where)} · <code>${esc(item.file)}</code></p>`, '</section>');
  return parts.filter(Boolean).join('\n');
}

/** The whole page: one HTML document, its own style, and the find box's few lines of script. */
export function apiReferenceHTML(root = process.cwd()) {
  const { entries, methods } = collectAPI(root);
  const known = new Set([...entries.flatMap((e) => e.items.map((i) => i.name)), ...methods.map((m) => m.name)]);
  const version = JSON.parse(readFileSync(resolve(root, 'package.json'), 'utf8')).version;
  const toc = [];
  const sections = [];
  const tocLine = (id, title, list) => `<li><a href="#${id}">${esc(title)}</a>: ${list.map((i) => `<a href="#${esc(i.name)}"><code>${esc(i.name)}</code></a>`).join(' ')}</li>`;
  const groupsHTML = (groups) => groups.map(([title, list, where]) => (title ? `<h3 class="group">${esc(title)}</h3>\n` : '') + list.map((i) => itemHTML(i, known, where)).join('\n')).join('\n');
  for (const entry of entries) {
    const items = entry.items.filter((i) => !INTERNAL.has(i.name));
    const groups = entry.id === 'p5' ? [['p5 methods', methods, 'p5 method (the addon)'], ['Exports', items, entry.file]] : [[null, items, entry.file]];
    toc.push(tocLine(entry.id, entry.title, groups.flatMap(([, list]) => list)));
    sections.push(`<section class="entry" id="${entry.id}"><h2>${esc(entry.title)}</h2>\n<p>${esc(entry.about)}</p>\n<pre class="imports" tabindex="0" role="region" aria-label="${esc(`How to import ${entry.title}`)}"><code>${entry.imports.map(esc).join('\n')}</code></pre>\n${groupsHTML(groups)}</section>`);
  }
  const internal = entries.map((entry) => [`From ${entry.file}`, entry.items.filter((i) => INTERNAL.has(i.name)), entry.file]);
  toc.push(tocLine('internal', 'The kit\'s own pages', internal.flatMap(([, list]) => list)));
  sections.push(`<section class="entry" id="internal"><h2>The kit's own pages</h2>\n<p>Exported for the gallery and the lesson pages (text in slices, the page's render state, links, page parts, number formatting). A sketch of your own rarely needs them.</p>\n${groupsHTML(internal)}</section>`);
  return `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<title>API reference · Raytracing Sketchbook</title>
<meta name="description" content="Every name of the Raytracing Sketchbook: the library and the p5 addon, their options and examples.">
<style>
  body { margin: 0 auto; max-width: 60rem; padding: 1.5rem; font: 17px/1.5 system-ui, "Segoe UI", "DejaVu Sans", sans-serif; color: #1b1f24; background: #fafbfc; }
  code, pre { font-family: ui-monospace, "DejaVu Sans Mono", Menlo, monospace; font-size: 0.92em; }
  pre { background: #fff; border: 1px solid #d5dae1; border-radius: 6px; padding: 0.6rem 0.9rem; overflow-x: auto; }
  h2 { margin-top: 2.5rem; border-bottom: 2px solid #d6336c; }
  h3 code { font-size: 1.15rem; }
  .kind { font-size: 0.85rem; font-weight: normal; color: #5b6470; }
  .item { margin: 1.6rem 0; padding-top: 0.4rem; border-top: 1px solid #e3e7ec; }
  .signature { background: #f3f5f8; white-space: pre-wrap; overflow-wrap: anywhere; } /* wraps: no box to scroll */
  pre:focus-visible { outline: 3px solid #1f5fbf; outline-offset: 2px; }
  .example { border-left: 4px solid #d6336c; }
  table.params { border-collapse: collapse; width: 100%; font-size: 0.93rem; }
  .params-wrap { overflow-x: auto; }
  .params-wrap:focus-visible { outline: 3px solid #1f5fbf; outline-offset: 2px; }
  p code, .params code, .members code { overflow-wrap: anywhere; } /* long names, types and calls wrap on a phone */
  .params th, .params td { text-align: left; vertical-align: top; padding: 0.25rem 0.5rem; border-bottom: 1px solid #e3e7ec; }
  .required { font-size: 0.78rem; color: #b01f55; } /* 6.4:1 on the page's background (#d6336c was 4.45:1) */
  .members dt { margin-top: 0.3rem; }
  .members dd { margin-left: 1.5rem; color: #3b434d; }
  .source, .returns { color: #5b6470; font-size: 0.9rem; }
  .toc li { margin-bottom: 0.5rem; }
  .toc code { margin-right: 0.35rem; }
  .find { display: block; position: sticky; top: 0; padding: 0.5rem 0; background: #fafbfc; }
  .find input { font: inherit; padding: 0.2rem 0.4rem; width: min(20rem, 100%); box-sizing: border-box; }
  #found { color: #3b434d; margin-left: 0.5rem; }
</style>
</head>
<body>
<header>
<p><a href="../">← The sketchbook</a> · <a href="../web-editor.html">Use it in the p5 web editor</a></p>
<h1>API reference</h1>
<p>Raytracing Sketchbook ${esc(version)}. Every name a sketch can use, generated from the library's own comments (<code>npm run build</code>). Colours are <code>[r, g, b]</code> in 0–1 or CSS names and hex strings (<code>'pink'</code>, <code>'#ff5160'</code>); points and directions are <code>[x, y, z]</code> or <code>{ x, y, z }</code>. A wrong value or an unknown option throws a <code>TypeError</code> or <code>RangeError</code> naming it.</p>
</header>
<nav aria-label="Every name"><ul class="toc">
${toc.join('\n')}
</ul></nav>
<div class="find" role="search"><label for="find">Find a name or a word</label> <input id="find" type="search" autocomplete="off" spellcheck="false"> <span id="found" role="status"></span></div>
<main>
${sections.join('\n')}
</main>
<script>${FIND_SCRIPT}</script>
</body>
</html>
`;
}

/**
 * The find box: each entry whose name or text holds every word typed stays,
 * the others hide, and so do their links in the list of names; a status says how many.
 */
const FIND_SCRIPT = `
const box = document.getElementById('find'), found = document.getElementById('found');
const items = [...document.querySelectorAll('section.item')];
const texts = new Map(items.map((item) => [item, (item.id + ' ' + item.textContent).toLowerCase()]));
box.addEventListener('input', () => {
  const words = box.value.toLowerCase().split(/\\s+/).filter(Boolean);
  let shown = 0;
  for (const item of items) {
    item.hidden = !words.every((word) => texts.get(item).includes(word));
    if (!item.hidden) shown++;
  }
  for (const a of document.querySelectorAll('.toc a')) {
    const target = document.getElementById(decodeURIComponent(a.hash.slice(1)));
    if (target && target.classList.contains('item')) a.hidden = target.hidden;
  }
  found.textContent = words.length ? shown + ' of ' + items.length + ' names' : '';
});
`;

/**
 * The reference's names a sketch uses: what it imports from the two entry
 * points, and the addon's methods it calls (`p.createTracerView(…)`), in the
 * order they first appear.
 */
export function namesUsedBy(sketchSource, methods = factoryNames()) {
  const names = [];
  const add = (name) => { if (!names.includes(name)) names.push(name); };
  for (const [, list] of sketchSource.matchAll(/import\s*\{([^}]*)\}\s*from\s*['"][./]*lib\/(?:p5\/)?index\.js['"]/g)) {
    for (const part of list.split(',')) {
      const name = part.trim().split(/\s+as\s+/)[0];
      if (name) add(name);
    }
  }
  for (const [, name] of sketchSource.matchAll(/\bp\.(\w+)\s*\(/g)) if (methods.has(name)) add(name);
  return names;
}

/** The addon's method names: the keys of FACTORIES in lib/p5/addon.js (read as text: cheap enough for every page). */
export function factoryNames(root = process.cwd()) {
  let source;
  try {
    source = readFileSync(resolve(root, 'lib/p5/addon.js'), 'utf8');
  } catch {
    return new Set();
  }
  const table = /export const FACTORIES = \{([\s\S]*?)\n\};/.exec(source)?.[1] ?? '';
  return new Set([...table.matchAll(/^\s+(\w+)\s*[,:]/gm)].map((m) => m[1]));
}

/** The line under a lesson page: `API: Scene, Sphere, createTracerView`, each a link into the reference. */
export function apiLineHTML(names, base = '../api/') {
  if (names.length === 0) return '';
  const links = names.map((name) => `<a href="${base}#${esc(name)}"><code>${esc(name)}</code></a>`).join(', ');
  return `<p class="api-line">API: ${links}</p>`;
}

// `node scripts/api-reference.js`: writes the page to stdout (npm run build writes it into dist/api/).
if (import.meta.url === `file://${process.argv[1]}`) process.stdout.write(apiReferenceHTML());
