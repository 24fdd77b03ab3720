/**
 * The teacher's view of the students' progress, without a server: each line
 * pasted (or the link's #code=…) holds a progress code, maybe after a name.
 * A code is checked, not trusted (lib/lesson/progress.js's readProgressCode): only the
 * kit's own task texts come out of it, and everything is shown as text.
 */
import { LESSONS } from '../lib/lesson/tasks.js';
import { readProgressLine, pageProgress, progressText, achievements } from '../lib/lesson/progress.js';

/** More than this is not read: a class, not a file dump. */
const MAX_LINES = 200;
const MAX_NAME = 40;
/** Cards built in one task: 200 students' cards are about 11,000 elements, a task of their own per batch. */
const CARDS_PER_TASK = 25;
let shown = 0; // which show() is drawing: a new one stops the batches of the last

const form = document.getElementById('codes-form');
const box = /** @type {HTMLTextAreaElement} */ (document.getElementById('codes'));
const summary = document.getElementById('summary');
const students = document.getElementById('students');

const fromLink = new URLSearchParams(location.hash.slice(1)).get('code');
if (fromLink) {
  box.value = fromLink.slice(0, 100);
  show();
}
form.addEventListener('submit', (event) => {
  event.preventDefault();
  show();
});

function show() {
  const lines = box.value.slice(0, 20_000).split('\n').map((l) => l.trim()).filter(Boolean);
  const read = lines.slice(0, MAX_LINES).map((line, i) => ({ line: i + 1, ...readProgressLine(line, LESSONS, MAX_NAME) }));
  const drawing = ++shown;
  students.replaceChildren();
  const batch = (from) => {
    if (drawing !== shown) return;
    students.append(...read.slice(from, from + CARDS_PER_TASK).map(card));
    if (from + CARDS_PER_TASK < read.length) setTimeout(batch, 0, from + CARDS_PER_TASK);
  };
  batch(0);
  const good = read.filter((r) => r.progress).length;
  summary.textContent = lines.length === 0 ? 'Paste at least one code.'
    : `${good} of ${read.length} ${read.length === 1 ? 'code' : 'codes'} read${lines.length > MAX_LINES ? ` (only the first ${MAX_LINES} lines)` : ''}.`;
}

function card({ line, name, progress, problem }) {
  const title = name || `Line ${line}`;
  const article = el('article', { class: 'student', 'data-student': problem ? 'refused' : 'read' }, el('h2', {}, title));
  if (problem) {
    article.append(el('p', { class: 'refused' }, `Not a progress code: ${problem}.`));
    return article;
  }
  const done = LESSONS.reduce((n, l) => n + pageProgress(progress, l).done, 0);
  const total = LESSONS.reduce((n, l) => n + l.tasks.length, 0);
  article.append(el('p', {}, `${done} of ${total} tasks done.`));
  const earned = achievements(progress, LESSONS);
  if (earned.length) article.append(el('p', { class: 'stars' }, earned.map((a) => `★ ${a.text}`).join(' · ')));
  const list = el('ul', { class: 'pages' });
  for (const lesson of LESSONS) {
    const ids = progress[lesson.page] ?? [];
    const item = el('li', { 'data-page': lesson.page }, `${lesson.page} · ${lesson.title}: ${progressText(pageProgress(progress, lesson))}`);
    if (ids.length) item.append(el('ul', {}, ...lesson.tasks.filter((t) => ids.includes(t.id)).map((t) => el('li', {}, `✓ ${t.text}`))));
    list.append(item);
  }
  article.append(list);
  return article;
}

/** An element with attributes and children; text always as text. */
function el(tag, attributes, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) node.setAttribute(name, value);
  node.append(...children);
  return node;
}
