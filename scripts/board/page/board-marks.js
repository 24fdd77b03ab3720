/**
 * The answers as marks on sketch 04's picture: a pink dot for a right one, a
 * cross for a wrong one, on the answer's pixel; the student's name on hover
 * and focus. One tab stop for all of them (a roving tabindex): the arrow
 * keys move from mark to mark, Home and End to the first and last. Marks are
 * kept from one state to the next, so a focused mark stays focused while
 * answers come in.
 */

/** @type {Map<number, HTMLButtonElement>} */
const shown = new Map();
let shownClass = null;

/**
 * @param {HTMLElement} host the layer over the picture
 * @param {{ id: number, name: string, line: string, x: number, y: number, width: number, height: number, verdict: string, colorName: string }[]} answers
 * @param {number} classId a new class (the board cleared) starts with no marks
 */
export function showMarks(host, answers, classId) {
  if (classId !== shownClass) {
    shownClass = classId;
    shown.clear();
    host.replaceChildren();
  }
  const atPixel = new Map();
  for (const a of answers) {
    const pixel = `${a.x},${a.y}`;
    const nth = atPixel.get(pixel) ?? 0;
    atPixel.set(pixel, nth + 1);
    if (shown.has(a.id)) continue;
    const mark = markOf(a, nth);
    shown.set(a.id, mark);
    host.append(mark);
  }
  const marks = [...shown.values()];
  if (marks.length && !marks.some((m) => m.tabIndex === 0)) marks[0].tabIndex = 0;
  if (!host.dataset.keys) {
    host.dataset.keys = 'on';
    host.addEventListener('keydown', (event) => move(host, event));
  }
}

/** One answer's mark, the nth on its pixel (drawn a little aside, so that each one shows). */
function markOf(a, nth) {
  const mark = document.createElement('button');
  mark.type = 'button';
  mark.className = `mark ${a.verdict}`;
  mark.tabIndex = -1;
  mark.dataset.answer = '';
  mark.dataset.pixel = `${a.x},${a.y}`;
  mark.dataset.verdict = a.verdict;
  mark.setAttribute('aria-label', `${a.name}: ${a.line}, ${a.verdict === 'right' ? 'right, pink' : `wrong, ${a.colorName}`}`);
  if (a.verdict === 'wrong') mark.append(Object.assign(document.createElement('span'), { textContent: '✕', ariaHidden: 'true' }));
  const tip = document.createElement('span');
  tip.className = 'tip';
  tip.ariaHidden = 'true'; // the label says it
  tip.textContent = a.name;
  mark.append(tip);
  const offset = Math.min(nth, 8) * 0.18; // of a pixel
  mark.style.left = `${((a.x + 0.5 + offset) / a.width) * 100}%`;
  mark.style.top = `${((a.y + 0.5 + offset) / a.height) * 100}%`;
  mark.addEventListener('focus', () => {
    for (const other of shown.values()) other.tabIndex = -1;
    mark.tabIndex = 0;
  });
  return mark;
}

const STEPS = { ArrowRight: 1, ArrowDown: 1, ArrowLeft: -1, ArrowUp: -1 };

function move(host, event) {
  const marks = /** @type {HTMLButtonElement[]} */ ([...host.querySelectorAll('[data-answer]')]);
  const at = marks.indexOf(/** @type {HTMLButtonElement} */ (document.activeElement));
  if (at < 0 || marks.length === 0) return;
  const to = event.key === 'Home' ? 0 : event.key === 'End' ? marks.length - 1
    : STEPS[event.key] ? (at + STEPS[event.key] + marks.length) % marks.length : -1;
  if (to < 0) return;
  event.preventDefault();
  marks[to].focus();
}
