/**
 * Number literals of the editor's code, found in the page's own parse of it
 * (CodeMirror's syntax tree), never in anything the sketch's frame says; and
 * a literal's text one step up or down: a step is one unit of its last
 * decimal place ("4" steps by 1, "0.25" by 0.01), the decimals kept.
 */
import { syntaxTree, ensureSyntaxTree } from '@codemirror/language';

/** A decimal literal we can step: digits, an optional point and decimals (not 1e3, 0x1f, 10n or 1_000). */
const DECIMAL = /^-?(\d+\.?\d*|\.\d+)$/;

/**
 * The number literal at `pos` in `state` (its minus sign included when it is
 * written as `-20`), or null when the caret is not on one we can step.
 * @param {import('@codemirror/state').EditorState} state
 * @param {number} pos
 * @returns {{ from: number, to: number, text: string }|null}
 */
export function literalAt(state, pos) {
  const tree = ensureSyntaxTree(state, pos + 1, 100) ?? syntaxTree(state); // parsed up to the caret, even on a busy machine
  for (const side of [-1, 1]) {
    const node = tree.resolveInner(pos, side);
    if (node.name !== 'Number') continue;
    let from = node.from;
    const parent = node.parent;
    if (parent?.name === 'UnaryExpression' && parent.to === node.to && state.sliceDoc(parent.from, node.from) === '-') from = parent.from;
    const text = state.sliceDoc(from, node.to);
    if (DECIMAL.test(text)) return { from, to: node.to, text };
  }
  return null;
}

/** Whether `text` is a decimal literal the page can step and read back. */
export const isDecimal = (text) => DECIMAL.test(text);

/** How many decimals a literal's text has ("0.25": 2, "4": 0, "4.": 0). */
export function decimalsOf(text) {
  const point = text.indexOf('.');
  return point < 0 ? 0 : text.length - point - 1;
}

/**
 * The literal's text `steps` steps of its last decimal place away, as many
 * decimals kept: stepped('0.5', 1) is '0.6', stepped('4', -10) is '-6'.
 * @param {string} text a decimal literal (isDecimal)
 * @param {number} steps whole steps, up (positive) or down
 */
export function stepped(text, steps) {
  const decimals = decimalsOf(text);
  const units = Math.round(Number(text) * 10 ** decimals) + steps; // whole units: no 0.1 + 0.2 drift
  const written = (Math.abs(units) / 10 ** decimals).toFixed(decimals);
  return units < 0 ? `-${written}` : written;
}

/**
 * The text to write for a new literal where the old one stood: a negative
 * number right after a `-` or `+` gets a space (`x - -1`, not `x--1`).
 * @param {string} before the character before the literal ('' at the start)
 * @param {string} text the new literal
 */
export function written(before, text) {
  return text.startsWith('-') && (before === '-' || before === '+') ? ` ${text}` : text;
}
