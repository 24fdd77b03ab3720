/**
 * The homework pages' self-check: a "Check my scene" button under the
 * picture and the result of a check (lib/lesson/homework.js) as a list, ✓, ✗ or –
 * per check, in the student's words. Its hints name the library's classes as
 * the page does: `new RT.Sphere(…)` in a global-mode sketch of the one-file
 * build, `new Sphere(…)` in a module. Each check sends an `rt-check` event
 * (bubbling) with `detail: { passed, toFix }` (on a page served by
 * `npm run class` the teacher's board gets it).
 *
 *   p.createHomeworkCheck({ view, check: checkTrafficSignal, parent: 'check', problem });
 */
import { element, resolveParent, sketchNode, useStyle } from '../dom.js';
import { createAnnouncer } from '../page/announce.js';
import { checkOptions } from '../../text/check.js';
import { joinClassBoard } from '../page/class-board.js';

/**
 * @param {import('p5').default} p the sketch
 * @param {object} options
 * @param {import('../tracer/view.js').TracerView} options.view whose scene and camera are checked
 * @param {(scene: object, camera: object, options: { prefix: string }) => { passed: boolean, checks: object[] }} options.check e.g. checkTrafficSignal
 * @param {HTMLElement|string|{elt: HTMLElement}} [options.parent] where the button and the result go; default the sketch's node
 * @param {string|null} [options.problem] a warning shown above the result (e.g. a bad ?solution= value), as plain text
 * @returns {{ button: HTMLButtonElement, results: HTMLElement, run: () => void, destroy: () => void }} `destroy()` (p.remove() calls it) takes them off the page
 * @example
 * const view = p.createTracerView({ scene: makeScene(), camera: makeCamera() });
 * p.createHomeworkCheck({ view, check: checkTrafficSignal }); // a "Check my scene" button and its verdict
 */
export function createHomeworkCheck(p, options) {
  const { view, check, parent, problem = null } = checkOptions(options, ['view', 'check', 'parent', 'problem'], 'createHomeworkCheck');
  return homeworkCheck({ view, check, parent: resolveParent(parent, sketchNode(p)), problem, prefix: libraryPrefix(p) });
}

/**
 * The self-check without a sketch: the button and the verdict in `parent`,
 * checking `view.scene` and `view.camera` as they are at each press (a page
 * whose picture runs in a sandboxed frame checks the scene it read from it).
 * @param {{ view: { scene: object, camera: object }, check: Function, parent: HTMLElement, problem?: string|null, prefix?: string }} options
 * @returns {{ button: HTMLButtonElement, results: HTMLElement, run: () => void, destroy: () => void }}
 */
export function homeworkCheck({ view, check, parent, problem = null, prefix = '' }) {
  useStyle(); // the list's marks and colours are in the kit's stylesheet (inside the one-file build too)
  const button = element('button', { type: 'button', class: 'rt-button' }, 'Check my scene');
  const results = element('div', { 'data-check-results': '' }, 'Press the button to check your scene against the task.');
  const warning = problem ? element('p', { class: 'hw-warning', role: 'alert' }, problem) : null;
  const announcer = createAnnouncer({ name: 'check' }); // the verdict is said; the list is read on demand
  const box = element('div', { class: 'rt-check' }, button, results, announcer.element, warning); // a block of its own, whatever the page around it
  parent.append(box);
  const run = () => {
    const result = check(view.scene, view.camera, { prefix });
    announcer.say(showCheck(results, result));
    // The page's tasks (task-list.js) hear of each check.
    const toFix = result.checks.filter((c) => !c.passed && !c.skipped && !c.bonus).length;
    results.dispatchEvent(new CustomEvent('rt-check', { bubbles: true, detail: { passed: result.passed, toFix } }));
  };
  joinClassBoard();
  button.addEventListener('click', run);
  return { button, results, run, destroy: () => { announcer.destroy(); box.remove(); } };
}

/** 'RT.' in a global-mode sketch that has the one-file build's RT, else ''. */
function libraryPrefix(p) {
  return /** @type {any} */ (p)._isGlobal && typeof (/** @type {any} */ (globalThis).RT?.Sphere) === 'function' ? 'RT.' : '';
}

/**
 * Shows a check's result in `target` (a DOM element): a headline ("Passed!"
 * or "Not yet: n checks to fix") and one line per check, ✓, ✗ or – (waiting),
 * with its message. The element gets `data-check="passed"|"not-yet"`; each
 * line `data-check-item="passed"|"failed"|"skipped"`, and says in words (for a
 * screen reader; the marks are hidden from it) "passed", "to fix" or "waiting".
 * Returns the verdict in one line: the headline and the checks to fix.
 */
export function showCheck(target, { passed, checks }) {
  const toFix = checks.filter((c) => !c.passed && !c.skipped && !c.bonus).length;
  const headline = passed ? 'Passed! Your scene does what the task asks.'
    : `Not yet: ${toFix} ${toFix === 1 ? 'check' : 'checks'} to fix.`;
  const list = element('ul', { class: 'hw-checks' });
  for (const c of checks) {
    const state = c.passed ? 'passed' : c.skipped ? 'skipped' : 'failed';
    const item = element('li', { 'data-check-item': state, class: `hw-${state}${c.bonus ? ' hw-bonus' : ''}` });
    item.append(element('span', { class: 'hw-mark', 'aria-hidden': 'true' }, c.passed ? '✓' : c.skipped ? '–' : '✗'),
      element('b', {}, element('span', { class: 'rt-visually-hidden' }, `${STATE_WORDS[state]}: `), c.label), element('span', { class: 'hw-detail' }, ' ', c.detail));
    list.append(item);
  }
  target.dataset.check = passed ? 'passed' : 'not-yet';
  target.replaceChildren(element('p', { class: 'hw-headline' }, headline), list);
  const labels = checks.filter((c) => !c.passed && !c.skipped && !c.bonus).map((c) => c.label);
  return labels.length ? `${headline} To fix: ${labels.join('; ')}.` : headline;
}

/** Each check's state in words. */
const STATE_WORDS = { passed: 'Passed', failed: 'To fix', skipped: 'Waiting' };
