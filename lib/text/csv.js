/**
 * CSV cells as the kit writes them everywhere: a pixel's record for
 * worksheets (lib/p5/pixel/csv.js) and the class board's export
 * (scripts/board/csv.js), so a name typed as a formula is text in both.
 */
import { PLAIN_NUMBER } from './format.js';

/**
 * What a cell may start with that a spreadsheet could run as a formula, or
 * skip on its way to one: = + - @ | a tab or CR, a space, a zero-width or
 * bidi mark, a full-width ＝＋－＠, or a quote (as in "=1 or '=1).
 */
const FORMULA_START = /^[=+\-@|\t\r "'\u200B-\u200F\u202A-\u202E\u2060-\u2069\uFEFF＝＋－＠]/;

/**
 * One CSV cell. Text a spreadsheet would run as a formula (FORMULA_START:
 * a name like =HYPERLINK(…) can) gets a leading ' so it shows as text; plain
 * numbers stay numbers. A cell with a quote, a comma, a CR or a LF is quoted.
 */
export function csvCell(cell) {
  let text = String(cell);
  if (FORMULA_START.test(text) && !PLAIN_NUMBER.test(text)) text = `'${text}`;
  return /[",\r\n]/.test(text) ? `"${text.replace(/"/g, '""')}"` : text;
}
