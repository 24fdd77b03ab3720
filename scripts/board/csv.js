/**
 * "Download CSV": every submission of the class, one a row, oldest first.
 * Cells as the kit writes CSV everywhere (csvCell): a nickname that starts
 * like a formula is text in a spreadsheet.
 */
import { csvCell } from '../../lib/text/csv.js';
import { nameOf } from './store.js';
import { POLL } from './checks.js';

const COLUMNS = ['time', 'student', 'name', 'kind', 'page', 'task', 'answer', 'verdict', 'colour', 'page said', 'H', 'V', 'homework', 'checks to fix', 'poll'];

/** @param {object[]} rows from BoardStore.rows() */
export function boardCSV(rows) {
  const line = (cells) => `${cells.map((c) => csvCell(c ?? '')).join(',')}\r\n`;
  return line(COLUMNS) + rows.map((r) => line([
    r.at, r.number, nameOf(r.number, r.nickname), r.kind, r.page, r.task, r.line, r.verdict,
    r.color_name && `${r.color_name} ${r.color}`, r.page_said, r.h, r.v,
    r.passed === null ? '' : r.passed ? 'passed' : 'not yet', r.to_fix,
    r.value === null ? '' : `${r.value} ${POLL.options[r.value]}`,
  ])).join('');
}
