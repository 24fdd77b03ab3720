/**
 * A long table that keeps only the rows in view in the page: the inspector's
 * "Show all 10,000 spheres" made 20,000 rows, 5 s to build and seconds of
 * layout at every frame after. The rows sit in a box that scrolls (at most
 * VIRTUAL_HEIGHT high); two spacer rows stand for the rows above and below
 * the view, and each row says its place (aria-rowindex, the table its
 * aria-rowcount) for screen readers.
 */
import { element } from '../dom.js';

/** Tables with more rows than this keep only the rows in view. */
export const VIRTUAL_FROM = 2000;
/** Rows made beyond each edge of the view, so a small scroll shows no gap. */
const OVERSCAN = 10;
/** Rows made before the box is laid out (its height not known yet), and the row height guessed until one is measured. */
const FIRST_ROWS = 40;
const GUESSED_ROW_PX = 24;

/**
 * Fills `body` with the rows of `count` that `box` shows (rowAt(k) makes
 * row k, each time it comes into view), and again as `box` scrolls.
 * @param {HTMLElement} box the scrolling box around the table
 * @param {HTMLTableSectionElement} body the table's tbody
 * @param {number} count
 * @param {(k: number) => HTMLTableRowElement} rowAt
 * @param {number} columns how many columns a row has (the spacers span them)
 */
export function virtualRows(box, body, count, rowAt, columns) {
  box.classList.add('rt-virtual');
  body.parentElement?.setAttribute('aria-rowcount', String(count + 1));
  const top = spacer(columns), bottom = spacer(columns);
  let rowPx = 0, first = -1, last = -1, frame = 0;
  const show = () => {
    frame = 0;
    const px = rowPx || GUESSED_ROW_PX;
    const from = Math.max(0, Math.min(count - 1, Math.floor(box.scrollTop / px) - OVERSCAN));
    const to = Math.min(count, from + (box.clientHeight ? Math.ceil(box.clientHeight / px) + 2 * OVERSCAN : FIRST_ROWS));
    if (from === first && to === last) return;
    first = from;
    last = to;
    const rows = [];
    for (let k = from; k < to; k++) {
      const row = rowAt(k);
      row.setAttribute('aria-rowindex', String(k + 2)); // the head is row 1
      rows.push(row);
    }
    top.firstChild.style.height = `${from * px}px`;
    bottom.firstChild.style.height = `${(count - to) * px}px`;
    body.replaceChildren(top, ...rows, bottom);
  };
  const later = () => { if (!frame) frame = requestAnimationFrame(measureAndShow); };
  const measureAndShow = () => {
    if (!rowPx && last > first && box.isConnected) {
      const rows = body.children, a = rows[1].getBoundingClientRect(), b = rows[rows.length - 2].getBoundingClientRect();
      rowPx = (b.bottom - a.top) / (last - first) || 0;
      first = last = -1; // made again at the measured height
    }
    show();
  };
  box.addEventListener('scroll', later, { passive: true });
  show();
  later(); // once laid out: the true row height and the box's own
}

function spacer(columns) {
  return element('tr', { class: 'rt-spacer', 'aria-hidden': 'true' }, element('td', { colspan: String(columns) }));
}
