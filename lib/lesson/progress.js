/**
 * Tasks and progress, without a page: which tasks of which lesson page a
 * student has done, as the text the browser keeps (localStorage) and as a
 * short progress code a teacher can read. Both are read strictly: anything
 * corrupt, foreign or of another version reads as "nothing done yet", never
 * as an error, and never as more than a set of known task ids.
 *
 * A lesson is `{ page: '01', title, tasks: [{ id, text, … }] }` (lib/lesson/tasks.js
 * has the kit's); progress is `{ '01': ['select', 'miss'], … }`: per page, the
 * ids of the tasks done, in the lesson's order.
 */

/** The localStorage key: a new layout of the stored text gets a new version here. */
export const PROGRESS_KEY = 'raytracing-sketchbook:tasks:v1';
const STORE_VERSION = 1;
/** Stored text longer than this is not read at all (the kit's own is a few hundred characters). */
const MAX_STORED = 20_000;
const PAGE = /^\d\d$/;
const TASK_ID = /^[a-z0-9-]{1,32}$/;

/** Nothing done yet. */
export const emptyProgress = () => ({});

/**
 * The progress kept in `text` (localStorage's value, or null): only pages and
 * task ids the lessons know, in the lessons' order; anything else reads as
 * nothing done.
 * @param {string|null} text
 * @param {{ page: string, tasks: { id: string }[] }[]} lessons
 * @example
 * parseProgress('{"v":1,"pages":{"01":["select"]}}', LESSONS); // { '01': ['select'] }
 * parseProgress('not json', LESSONS);                          // {}
 */
export function parseProgress(text, lessons) {
  if (typeof text !== 'string' || text.length > MAX_STORED) return emptyProgress();
  let data;
  try { data = JSON.parse(text); } catch { return emptyProgress(); }
  if (!isPlainObject(data) || data.v !== STORE_VERSION || !isPlainObject(data.pages)) return emptyProgress();
  const progress = emptyProgress();
  for (const lesson of lessons) {
    const ids = data.pages[lesson.page];
    if (!Array.isArray(ids)) continue;
    const done = lesson.tasks.map((t) => t.id).filter((id) => ids.includes(id));
    if (done.length) progress[lesson.page] = done;
  }
  return progress;
}

/** The text to keep for `progress` (what parseProgress reads). */
export function serializeProgress(progress) {
  const pages = {};
  for (const [page, ids] of Object.entries(progress)) {
    if (PAGE.test(page) && Array.isArray(ids) && ids.length) pages[page] = ids.filter((id) => TASK_ID.test(id));
  }
  return JSON.stringify({ v: STORE_VERSION, pages });
}

/** `progress` with task `id` of `page` done (a new object; the same one when it was done already). */
export function markDone(progress, lesson, id) {
  const done = progress[lesson.page] ?? [];
  if (done.includes(id) || !lesson.tasks.some((t) => t.id === id)) return progress;
  const ids = lesson.tasks.map((t) => t.id).filter((t) => t === id || done.includes(t));
  return { ...progress, [lesson.page]: ids };
}

/** `progress` without page `page` ("Start again" on that page), or with nothing at all when `page` is left out. */
export function clearProgress(progress, page) {
  if (page === undefined) return emptyProgress();
  return Object.fromEntries(Object.entries(progress).filter(([p]) => p !== page));
}

/** How far a page is: `{ done, total, finished }`. */
export function pageProgress(progress, lesson) {
  const done = (progress[lesson.page] ?? []).length, total = lesson.tasks.length;
  return { done, total, finished: total > 0 && done === total };
}

/** "2 of 5", as the gallery and each page's strip say it. */
export function progressText({ done, total }) {
  return `${done} of ${total}`;
}

/**
 * The achievements earned: one per finished page, then "every page" and
 * "the homework" (the pages whose lesson says `homework: true`).
 * @returns {{ id: string, text: string }[]}
 */
export function achievements(progress, lessons) {
  const finished = lessons.filter((l) => pageProgress(progress, l).finished);
  const list = finished.map((l) => ({ id: `page-${l.page}`, text: `Finished ${l.page} · ${l.title}` }));
  const homework = lessons.filter((l) => l.homework);
  if (homework.length && homework.every((l) => finished.includes(l))) list.push({ id: 'homework', text: 'The homework: both self-checks passed' });
  if (lessons.length && finished.length === lessons.length) list.push({ id: 'all', text: 'Every lesson page finished' });
  return list;
}

/* ---------------- the progress code ---------------- */

/** The code's version: its first part. A code of another version is refused, not guessed at. */
const CODE_PREFIX = 'RT1';
/** The pages the first codes held (00–09): a code that short is still read. */
const FIRST_CODE_PAGES = 10;
/** Longer input than this is no code. */
const MAX_CODE = 80;

/**
 * A short code for `progress`, to copy to a teacher: `RT1-` then, per
 * lesson page in order, the tasks done as bits in two hex digits, then a
 * two-digit check sum, in groups of four: `RT1-0103-0000-…-7A`.
 * @example
 * progressCode({ '01': ['select'] }, LESSONS); // 'RT1-0001-0000-0000-0000-0000-3D' (say)
 */
export function progressCode(progress, lessons) {
  const hex = lessons.map((lesson) => {
    const done = progress[lesson.page] ?? [];
    const bits = lesson.tasks.reduce((sum, t, i) => sum | (done.includes(t.id) ? 1 << i : 0), 0);
    return bits.toString(16).toUpperCase().padStart(2, '0');
  }).join('');
  return [CODE_PREFIX, ...hex.match(/.{1,4}/g), checksum(hex)].join('-');
}

/**
 * The progress a code stands for, checked: `{ progress }`, or `{ problem }`
 * saying in words why it is no code of this kit (never an exception). Only
 * task ids of `lessons` come out of it.
 * @param {string} text what was pasted
 */
export function readProgressCode(text, lessons) {
  if (typeof text !== 'string') return { problem: 'no code given' };
  const code = text.trim().toUpperCase();
  if (code.length === 0) return { problem: 'no code given' };
  if (code.length > MAX_CODE) return { problem: `too long for a progress code (${code.length} characters)` };
  const parts = code.split('-');
  if (parts[0] !== CODE_PREFIX) return { problem: `a progress code starts with ${CODE_PREFIX}-` };
  const hex = parts.slice(1, -1).join(''), sum = parts[parts.length - 1];
  const pages = hex.length / 2; // a code made before the later pages had tasks holds fewer: those read as nothing done
  if (!/^[0-9A-F]*$/.test(hex + sum) || !Number.isInteger(pages) || pages > lessons.length || pages < Math.min(FIRST_CODE_PAGES, lessons.length) || sum.length !== 2) {
    return { problem: 'not the shape of a progress code (RT1- and groups of four hex digits)' };
  }
  if (checksum(hex) !== sum) return { problem: 'a character is wrong or missing (the check sum does not match)' };
  const progress = emptyProgress();
  for (const [i, lesson] of lessons.slice(0, pages).entries()) {
    const bits = parseInt(hex.slice(2 * i, 2 * i + 2), 16);
    if (bits >> lesson.tasks.length) return { problem: `page ${lesson.page} has no task ${Math.floor(Math.log2(bits)) + 1}` };
    const ids = lesson.tasks.filter((_, k) => bits & (1 << k)).map((t) => t.id);
    if (ids.length) progress[lesson.page] = ids;
  }
  return { progress };
}

/** Where a code starts in a line: its prefix, in any case, found in the line as typed (upper-casing changes lengths: ß, ﬁ). */
const CODE_START = new RegExp(`${CODE_PREFIX}-`, 'gi');

/**
 * A line a teacher pasted, `Ana RT1-0103-…`: the name before the code (up to
 * `maxName` characters, without the colon or spaces between) and what
 * readProgressCode makes of the code. With no `RT1-` in it, the line's first
 * word is read as the code, so the problem says what a code starts with.
 * @param {string} line one line, trimmed
 */
export function readProgressLine(line, lessons, maxName = 40) {
  let at = -1;
  for (const match of line.matchAll(CODE_START)) at = match.index;
  const code = at < 0 ? line : line.slice(at);
  let end = Math.max(at, 0); // the name ends before the colon and spaces (a loop: a pattern would retry each run of spaces)
  while (end > 0 && /[:\s]/.test(line[end - 1])) end--;
  const name = line.slice(0, Math.min(end, maxName));
  return { name, ...readProgressCode(code.split(/\s/)[0], lessons) };
}

/** Two hex digits that change when any one digit of `hex` does, or two change places. */
function checksum(hex) {
  let sum = 0;
  for (const [i, ch] of [...hex].entries()) sum = (sum + (i + 1) * parseInt(ch, 16)) % 251;
  return sum.toString(16).toUpperCase().padStart(2, '0');
}

function isPlainObject(value) {
  return value !== null && typeof value === 'object' && !Array.isArray(value);
}
