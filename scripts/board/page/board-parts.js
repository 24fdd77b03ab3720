/**
 * The board's other parts, each drawn again from the state: the spread of the
 * answers' H and V, the poll's histogram, the homework's self-checks and the
 * tasks done page by page. Bars are plain elements with their numbers
 * written beside them, so a screen reader reads the numbers.
 */
import { LESSONS } from '../../../lib/lesson/tasks.js';

const POLL = [[1, 'negative'], [2, 'neutral'], [3, 'positive']];

/** A new element with text and a class. */
function make(tag, text = '', className = '') {
  const el = document.createElement(tag);
  if (text) el.textContent = text;
  if (className) el.className = className;
  return el;
}

/** A bar of `share` (0–1) of its row's width, hidden from screen readers: the number beside it says it. */
function bar(share, className = '') {
  const outer = make('span', '', `bar ${className}`);
  outer.ariaHidden = 'true';
  const inner = make('span');
  inner.style.width = `${Math.round(Math.max(0, Math.min(1, share)) * 100)}%`;
  outer.append(inner);
  return outer;
}

const median = (sorted) => (sorted.length % 2 ? sorted[(sorted.length - 1) / 2] : (sorted[sorted.length / 2 - 1] + sorted[sorted.length / 2]) / 2);
const angle = (n) => `${Math.round(n * 10) / 10}°`;

/** The rows of the spread, made once: the words and a strip of dots each; dots are added, not drawn again. */
const spread = { rows: null, dots: 0, classId: null };

/** H and V of the answers: range and median of each, for all and for the right ones, and a dot strip of each. */
export function showSpread(host, answers, classId) {
  if (!spread.rows || spread.classId !== classId) {
    spread.classId = classId;
    spread.dots = 0;
    spread.rows = [['H', 'h', -180, 180], ['V', 'v', -90, 90]].map(([label, field, min, max]) => {
      const words = make('span');
      const strip = make('span', '', 'strip');
      strip.ariaHidden = 'true';
      const row = make('p', '', 'spread-row');
      row.append(make('b', String(label)), words, strip);
      return { field, min, max, words, strip, row };
    });
    host.replaceChildren(...spread.rows.map((r) => r.row));
  }
  for (const { field, min, max, words, strip } of spread.rows) {
    const all = answers.map((a) => a[field]).sort((a, b) => a - b);
    const right = answers.filter((a) => a.verdict === 'right').map((a) => a[field]).sort((a, b) => a - b);
    const say = (list) => (list.length ? `${angle(list[0])} to ${angle(list[list.length - 1])}, median ${angle(median(list))}` : 'none yet');
    words.textContent = answers.length ? ` all ${say(all)}; right ${say(right)}` : ' no answer yet';
    for (const a of answers.slice(spread.dots)) {
      const dot = make('span', '', `dot ${a.verdict}`);
      dot.style.left = `${((a[field] - min) / (max - min)) * 100}%`;
      strip.append(dot);
    }
  }
  spread.dots = answers.length;
}

/** The poll's histogram: each option's count and bar. */
export function showPoll(host, poll) {
  const counts = new Map(poll.map((p) => [p.value, p.students]));
  const total = poll.reduce((sum, p) => sum + p.students, 0);
  const list = make('ul', '', 'bars');
  for (const [value, word] of POLL) {
    const n = counts.get(value) ?? 0;
    const item = make('li', '', 'bar-row');
    item.dataset.poll = String(value);
    item.append(make('span', `${value} ${word}`, 'bar-label'), bar(total ? n / total : 0, `poll-${value}`), make('b', String(n), 'bar-count'));
    list.append(item);
  }
  host.replaceChildren(list, make('p', `${total} ${total === 1 ? 'student has' : 'students have'} answered.`, 'note'));
}

/** Per homework page: how many students' last check passed, and how many checks were run. */
export function showHomework(host, homework, students) {
  if (homework.length === 0) return void host.replaceChildren(make('p', 'No self-check run yet (pages 08 and 09).'));
  const list = make('ul', '', 'bars');
  for (const h of homework) {
    const lesson = LESSONS.find((l) => l.page === h.page);
    const item = make('li', '', 'bar-row');
    item.dataset.homework = h.page;
    item.append(make('span', `${h.page} ${lesson?.title ?? ''}`, 'bar-label'), bar(students ? h.passed / students : 0, 'passed'),
      make('b', `${h.passed} passed`, 'bar-count'), make('span', ` of ${h.students} who checked (${h.checks} checks run)`));
    list.append(item);
  }
  host.replaceChildren(list);
}

/** Per lesson page with any task done: each task's text and how many students did it. */
export function showTasks(host, tasks, students) {
  const done = new Map(tasks.map((t) => [`${t.page} ${t.task}`, t.students]));
  const pages = LESSONS.filter((l) => l.tasks.some((t) => done.has(`${l.page} ${t.id}`)));
  if (pages.length === 0) return void host.replaceChildren(make('p', 'No task done yet.'));
  host.replaceChildren(...pages.map((lesson) => {
    const block = make('div', '', 'task-page');
    block.dataset.page = lesson.page;
    const list = make('ul', '', 'bars');
    for (const task of lesson.tasks) {
      const n = done.get(`${lesson.page} ${task.id}`) ?? 0;
      const item = make('li', '', 'bar-row');
      item.dataset.task = task.id;
      item.append(make('span', task.text, 'bar-label'), bar(students ? n / students : 0), make('b', `${n} of ${students}`, 'bar-count'));
      list.append(item);
    }
    block.append(make('h3', `${lesson.page} · ${lesson.title}`), list);
    return block;
  }));
}

/** What the server refused, newest first: who, when, what and why, each as text. */
export function showRefused(host, refused) {
  if (refused.length === 0) return void host.replaceChildren(make('li', 'Nothing refused.'));
  host.replaceChildren(...refused.map((r) => {
    const item = make('li');
    item.dataset.refusedWhat = r.what;
    const time = make('time', new Date(r.at).toLocaleTimeString());
    time.dateTime = r.at;
    item.append(make('b', r.name), ' ', time, ` ${r.what}: `, make('span', r.reason, 'reason'));
    return item;
  }));
}
