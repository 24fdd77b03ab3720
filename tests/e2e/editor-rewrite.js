/**
 * What the p5 web editor does to every .js file of a sketch before it runs
 * it (its loop protection), for the tests: a file with a `// noprotect`
 * comment passes as it is; any other is parsed (acorn, the latest syntax),
 * every for, while and do-while loop gets a time check as the first line of
 * its body that breaks out of the loop once it has run 100 ms,
 *
 *   var _LP0 = Date.now();            // just before the loop
 *   … { if (Date.now() - _LP0 > 100) { window.loopProtect.hit(line); break; } … }
 *
 * and the file is printed again (escodegen). The editor only declares
 * `_LPn` when the loop sits directly in a block (a loop that is the body of
 * another statement gets the check but no declaration), and so does this.
 *
 *   protectLoops(code)  // → { code, skipped, loops }
 */
import { parse } from 'acorn';
import { ancestor } from 'acorn-walk';
import { generate } from 'escodegen';

/** How long a loop may run before the editor breaks out of it. */
export const LOOP_TIMEOUT_MS = 100;

/** The editor's test for the opt-out: the text `//` then `noprotect`, anywhere in the file. */
export const hasNoProtect = (code) => /\/\/\s*noprotect/.test(code);

/**
 * @param {string} code a file of the sketch
 * @returns {{ code: string, skipped: boolean, loops: number }} `skipped`: left as it was (noprotect, or not parsed); `loops`: how many got a check
 */
export function protectLoops(code) {
  if (hasNoProtect(code)) return { code, skipped: true, loops: 0 };
  const ast = parseEither(code);
  if (!ast) return { code, skipped: true, loops: 0 };
  const loops = [];
  const collect = (loop, _, ancestors) => {
    const block = ancestors.findLast((node) => node !== loop && (node.type === 'BlockStatement' || node.type === 'Program'));
    loops.push({ loop, block });
  };
  ancestor(ast, { ForStatement: collect, WhileStatement: collect, DoWhileStatement: collect });
  if (loops.length === 0) return { code, skipped: false, loops: 0 };
  loops.forEach(({ loop, block }, i) => {
    const name = `_LP${i}`;
    const check = timeCheck(name, loop.loc.start.line);
    loop.body = loop.body.type === 'BlockStatement' ? { ...loop.body, body: [check, ...loop.body.body] } : { type: 'BlockStatement', body: [check, loop.body] };
    const at = block?.body.indexOf(loop) ?? -1;
    if (at !== -1) block.body.splice(at, 0, startTime(name));
  });
  return { code: generate(ast), skipped: false, loops: loops.length };
}

/** A classic script first, a module if that fails, null if neither (the editor then runs the file as it is). */
function parseEither(code) {
  for (const sourceType of ['script', 'module']) {
    try {
      return parse(code, { ecmaVersion: 'latest', sourceType, locations: true });
    } catch { /* try the next */ }
  }
  return null;
}

const id = (name) => ({ type: 'Identifier', name });
const member = (object, property) => ({ type: 'MemberExpression', object, property: id(property), computed: false });
const now = () => ({ type: 'CallExpression', callee: member(id('Date'), 'now'), arguments: [] });
const literal = (value) => ({ type: 'Literal', value, raw: String(value) });

/** `var name = Date.now();` */
function startTime(name) {
  return { type: 'VariableDeclaration', kind: 'var', declarations: [{ type: 'VariableDeclarator', id: id(name), init: now() }] };
}

/** `if (Date.now() - name > 100) { window.loopProtect.hit(line); break; }` */
function timeCheck(name, line) {
  const elapsed = { type: 'BinaryExpression', operator: '-', left: now(), right: id(name) };
  const hit = { type: 'CallExpression', callee: member(member(id('window'), 'loopProtect'), 'hit'), arguments: [literal(line)] };
  return {
    type: 'IfStatement',
    test: { type: 'BinaryExpression', operator: '>', left: elapsed, right: literal(LOOP_TIMEOUT_MS) },
    consequent: { type: 'BlockStatement', body: [{ type: 'ExpressionStatement', expression: hit }, { type: 'BreakStatement', label: null }] },
    alternate: null,
  };
}
