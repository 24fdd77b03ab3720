/**
 * A lesson page's tasks (lib/lesson/tasks.js) as a list under the page, each
 * ticked off by what the student does there: a pixel selected, a value
 * changed, a picture traced again, the activity's verdict, a self-check. What
 * is done is kept in the browser (localStorage, lib/lesson/progress.js), shown as a
 * strip in the page's header, and announced in one polite status line.
 *
 *   p.createTaskList({ page: '01', view });                      // after the page's own setup
 *   p.createTaskList({ page: '00', view, parts: { photons, sceneView } });
 *
 * Controls report what they judged with DOM events on their own element:
 * `rt-answer` (the answer form's verdict) and `rt-check` (a homework self-check).
 * The list reports tasks newly done with an `rt-task` event, `detail: { page, tasks }`
 * (the ids): on a page served by `npm run class` they go to the teacher's board.
 */
import { recordOf } from '../pixel/record.js';
import { lessonOf, LESSONS } from '../../lesson/tasks.js';
import { markDone, clearProgress, pageProgress, progressText } from '../../lesson/progress.js';
import { loadProgress, saveProgress } from './progress-store.js';
import { checkOptions, show } from '../../text/check.js';
import { element, resolveParent, useStyle } from '../dom.js';
import { joinClassBoard } from '../page/class-board.js';
import { createAnnouncer } from '../page/announce.js';

const OPTIONS = ['page', 'view', 'parent', 'parts', 'hintAfterMs', 'hintAfterTries'];
/** What the student does that may finish a task whose state it changes (a box, a switch, a drag in 3D). */
const INPUT_EVENTS = ['input', 'change', 'click', 'pointerup', 'keyup'];

/**
 * @param {import('p5').default} p the sketch
 * @param {object} options
 * @param {string} options.page the lesson page, '00'–'14'
 * @param {import('../tracer/view.js').TracerView} options.view the picture whose selected pixel the tasks look at (or what stands for it: `scene`, `camera`, `onSelect`)
 * @param {HTMLElement|string|{elt: HTMLElement}} [options.parent] where the list goes; default right after the page's `<main>`
 * @param {object} [options.parts] the page's other parts the tasks look at: `photons`, `sceneView`, `animation`
 * @param {number} [options.hintAfterMs=60000] a task's hint shows after this long on the page,
 * @param {number} [options.hintAfterTries=6] or after this many pixels selected or self-checks run, whichever comes first
 * @returns {TaskList}
 * @example
 * const view = p.createTracerView({ scene, camera });
 * p.createTaskList({ page: '01', view }); // "Select any pixel", … ticked off as the student does them
 */
export function createTaskList(p, options) {
  return new TaskList(checkOptions(options, OPTIONS, 'createTaskList'));
}

/** A task's words up to its first colon, without its asides: "Select any pixel" of "Select any pixel: click it, …". */
function shortText(text) {
  const colon = text.indexOf(': ');
  return (colon > 0 ? text.slice(0, colon) : text).replace(/ \([^()]*\)/g, '').replace(/\.$/, '');
}

/** The task list of one page, what `p.createTaskList({ … })` returns. */
export class TaskList {
  #lesson; #view; #parts; #progress; #memory = {}; #items = new Map();
  #last = null; #tries = 0; #hintAfterTries; #timer = 0; #pending = 0; #cleanups = [];
  #voice = createAnnouncer({ name: 'task', order: 2 }); // after the pixel and the verdict that did it

  constructor({ page, view, parent, parts = {}, hintAfterMs = 60_000, hintAfterTries = 6 }) {
    this.#lesson = lessonOf(page);
    if (!this.#lesson) throw new RangeError(`page must be one of ${LESSONS.map((l) => `'${l.page}'`).join(', ')}, got ${show(page)}`);
    if (!view || typeof view.onSelect !== 'function') throw new TypeError(`createTaskList needs { view }: a tracer view, got ${show(view)}`);
    this.#view = view;
    this.#parts = parts;
    this.#hintAfterTries = hintAfterTries;
    this.#progress = loadProgress();
    useStyle();
    this.#build(parent);
    this.#listen(hintAfterMs);
    this.#show();
    joinClassBoard();
  }

  /** The lesson page's tasks `{ id, text, done }`, done as kept in this browser. */
  get tasks() {
    const done = this.#progress[this.#lesson.page] ?? [];
    return this.#lesson.tasks.map((t) => ({ id: t.id, text: t.text, done: done.includes(t.id) }));
  }

  /** Forgets this page's progress ("Start again"): every task to do again. */
  startAgain() {
    this.#progress = clearProgress(loadProgress(), this.#lesson.page);
    this.#memory = {};
    saveProgress(this.#progress);
    this.#say('Started again: every task of this page is to do.');
    this.#show();
  }

  /** Takes the list and its strip off the page and stops listening. */
  destroy() {
    for (const cleanup of this.#cleanups) cleanup();
    clearTimeout(this.#timer);
    clearTimeout(this.#pending);
    this.#voice.destroy();
    this.element.remove();
    this.strip?.remove();
  }

  /* ---------------- what happens on the page ---------------- */

  #listen(hintAfterMs) {
    const view = this.#view;
    this.#cleanups.push(view.onSelect((s) => {
      const moved = s && (s.x !== this.#last?.x || s.y !== this.#last?.y);
      this.#last = s;
      if (!moved) return this.#later();
      this.#tries++;
      this.#judge({ type: 'select', record: recordOf(view, s) });
    }));
    const on = (target, type, handler) => {
      target.addEventListener(type, handler);
      this.#cleanups.push(() => target.removeEventListener(type, handler));
    };
    // An answer comes with its pixel's selection, already counted as a try.
    on(document, 'rt-answer', (/** @type {CustomEvent} */ e) => this.#judge({ type: 'answer', ...e.detail }));
    on(document, 'rt-check', (/** @type {CustomEvent} */ e) => { this.#tries++; this.#judge({ type: 'check', ...e.detail }); });
    for (const type of INPUT_EVENTS) on(document, type, () => this.#later());
    // A picture traced again (or the photons all sent): the scene may be new.
    const traced = new MutationObserver(() => { if (document.body.dataset.render === 'done') this.#later(); });
    traced.observe(document.body, { attributes: true, attributeFilter: ['data-render'] });
    this.#cleanups.push(() => traced.disconnect());
    this.#timer = setTimeout(() => this.#showHints(), hintAfterMs);
  }

  /** A look at the page's state once the handlers of what just happened have run. */
  #later() {
    if (this.#pending) return;
    this.#pending = setTimeout(() => { this.#pending = 0; this.#judge({ type: 'state' }); });
  }

  /** Asks each task not yet done whether `happened` did it. */
  #judge(happened) {
    const view = this.#view;
    if (!view.scene) return; // a picture that runs in a sandboxed frame, before its scene came (editor/page-judge.js)
    const event = { scene: view.scene, camera: view.camera, mode: view.mode, order: view.order, renderMode: view.order, parts: this.#parts, ...happened };
    const before = loadProgress(); // another tab of the same browser may have done tasks too
    let progress = { ...before, [this.#lesson.page]: [...new Set([...(before[this.#lesson.page] ?? []), ...(this.#progress[this.#lesson.page] ?? [])])] };
    const newly = [];
    for (const task of this.#lesson.tasks) {
      if (progress[this.#lesson.page].includes(task.id)) continue;
      if (task.done(event, (this.#memory[task.id] ??= {}))) {
        progress = markDone(progress, this.#lesson, task.id);
        newly.push(task);
      }
    }
    if (newly.length === 0) {
      if (this.#tries >= this.#hintAfterTries) this.#showHints();
      return;
    }
    this.#progress = progress;
    saveProgress(progress);
    this.#show();
    this.#announce(newly);
    this.element.dispatchEvent(new CustomEvent('rt-task', { bubbles: true, detail: { page: this.#lesson.page, tasks: newly.map((t) => t.id) } }));
  }

  /* ---------------- on the page ---------------- */

  /** Names every task just done (one press may do two), each by its words up to the first colon. */
  #announce(newly) {
    const { done, total, finished } = pageProgress(this.#progress, this.#lesson);
    const names = newly.map((t) => shortText(t.text)).join('; ');
    this.#say(`${newly.length > 1 ? 'Tasks' : 'Task'} done (${done} of ${total}): ${names}.${finished ? ' That was every task of this page. Well done!' : ''}`);
  }

  /** On the page, and said by the page's voice with the pixel and verdict that did it. */
  #say(text) {
    this.status.textContent = text;
    this.#voice.say(text);
  }

  #showHints() {
    for (const [id, { hint }] of this.#items) if (!this.tasks.find((t) => t.id === id)?.done) hint.hidden = false;
  }

  /** Every task's tick, the count, the strip. */
  #show() {
    for (const task of this.tasks) {
      const { item, mark, state } = this.#items.get(task.id);
      item.dataset.done = String(task.done);
      mark.textContent = task.done ? '✓' : '';
      state.textContent = task.done ? 'Done: ' : ''; // the ✓ in words: the list reads differently once a task is done
      item.classList.toggle('rt-task-done', task.done);
    }
    const progress = pageProgress(this.#progress, this.#lesson);
    const text = `${progressText(progress)} done${progress.finished ? ': page finished ★' : ''}`;
    this.count.textContent = text;
    if (this.strip) this.strip.textContent = `Tasks: ${text}`;
    this.element.dataset.finished = String(progress.finished);
  }

  #build(parent) {
    const list = element('ol', { class: 'rt-task-items' });
    for (const task of this.#lesson.tasks) {
      const mark = element('span', { class: 'rt-task-mark', 'aria-hidden': 'true' });
      const state = element('span', { class: 'rt-visually-hidden', 'data-task-state': '' });
      const hint = element('p', { class: 'rt-task-hint', 'data-hint': '', hidden: '' }, `Hint: ${task.hint}`);
      const item = element('li', { 'data-task': task.id, 'data-done': 'false' }, mark, state, element('span', { class: 'rt-task-text' }, task.text), hint);
      list.append(item);
      this.#items.set(task.id, { item, mark, state, hint });
    }
    this.count = element('span', { class: 'rt-task-count', 'data-task-count': '' });
    // not a live region: the page's voice says it (announce.js), with what did it
    this.status = element('p', { class: 'rt-task-status', 'data-task-status': '' });
    const again = element('button', { type: 'button', class: 'rt-button', 'data-tasks-again': '' }, 'Start again');
    again.addEventListener('click', () => this.startAgain());
    // back from the list to the picture in one key, not 16 Shift+Tabs past every control
    const canvas = this.#view.canvas;
    const back = canvas?.id ? element('a', { href: `#${canvas.id}`, class: 'rt-back-to-picture', 'data-back-to-picture': '' }, 'Back to the picture') : null;
    const heading = element('h2', { id: 'tasks-heading' }, 'Tasks ', this.count);
    this.element = element('section', { class: 'rt-tasks card', id: 'tasks', 'data-tasks': this.#lesson.page, 'aria-labelledby': 'tasks-heading' },
      heading, element('p', { class: 'rt-task-about' }, 'Each ticks itself off when done, kept in this browser; the gallery gives a code for your teacher.'),
      list, this.status, ...[again, back].filter(Boolean));
    const main = document.querySelector('main');
    if (parent != null) resolveParent(parent, main).append(this.element);
    else if (main) main.after(this.element);
    else document.body.append(this.element);

    const header = document.querySelector('body > header');
    if (header) {
      this.strip = element('a', { class: 'rt-task-strip', href: '#tasks', 'data-task-strip': '' });
      header.append(this.strip);
    }
  }
}
