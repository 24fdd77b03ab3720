/**
 * The teacher's class board (/board?key=…): what the students' pages sent,
 * live. The class server pushes the whole state (Server-Sent Events,
 * scripts/board/routes.js) after each burst of submits; the board draws it.
 * Every name and answer is set as text, never parsed as HTML.
 */
import { classScene, Camera, render } from '../../../lib/index.js';
import { showMarks } from './board-marks.js';
import { showSpread, showPoll, showHomework, showTasks, showRefused } from './board-parts.js';

const key = new URLSearchParams(location.search).get('key') ?? '';
const withKey = (path) => `${path}?key=${encodeURIComponent(key)}`;
const $ = (selector) => /** @type {HTMLElement} */ (document.querySelector(selector));

/** Sketch 04's picture at its first camera (H 0, V 0): the marks go on it. */
function drawPicture() {
  const canvas = /** @type {HTMLCanvasElement} */ ($('.picture canvas'));
  const camera = new Camera({ width: canvas.width, height: canvas.height, fov: 30 });
  const pixels = render(classScene(), camera);
  canvas.getContext('2d').putImageData(new ImageData(pixels, canvas.width, canvas.height), 0, 0);
}

/** Everything on the board, from one state of the class. */
function show(state) {
  const names = new Map(state.students.map((s) => [s.number, s.name]));
  const answers = state.answers.map((a) => ({ ...a, name: names.get(a.student) ?? `student ${a.student}` }));
  $('[data-board-answers]').textContent = String(answers.length);
  $('[data-answers-word]').textContent = answers.length === 1 ? 'answer' : 'answers';
  const right = new Set(answers.filter((a) => a.verdict === 'right').map((a) => a.student));
  const answered = new Set(answers.map((a) => a.student));
  $('[data-count="right"]').textContent = String(right.size);
  $('[data-count="wrong"]').textContent = String(answered.size - right.size);
  // Students are the laptops that sent something kept: those without an answer sent other work.
  $('[data-count="not-yet"]').textContent = String(state.students.length - answered.size);
  showMarks($('[data-marks]'), answers, state.class.id);
  showLatest(answers);
  showSpread($('[data-spread]'), answers, state.class.id);
  const n = state.students.length;
  whenChanged('poll', state.poll, () => showPoll($('[data-poll]'), state.poll));
  whenChanged('homework', [state.homework, n], () => showHomework($('[data-homework]'), state.homework, n));
  whenChanged('tasks', [state.tasks, n], () => showTasks($('[data-tasks]'), state.tasks, n));
  whenChanged('refused', state.refused, () => showRefused($('[data-refused]'), state.refused ?? []));
  $('[data-refused-count]').textContent = String(state.refusedCount ?? 0);
}

/** Draws a part again only when what it shows changed (a burst of answers leaves the others as they are). */
const drawn = new Map();
function whenChanged(part, value, draw) {
  const text = JSON.stringify(value);
  if (drawn.get(part) === text) return;
  drawn.set(part, text);
  draw();
}

/** The ten newest answers, newest first, in words. */
function showLatest(answers) {
  const list = $('[data-latest]');
  const items = answers.slice(-10).reverse().map((a) => {
    const li = document.createElement('li');
    const who = document.createElement('b');
    who.textContent = a.name;
    const line = document.createElement('code');
    line.textContent = a.line;
    li.append(who, ' ', line, ` ${a.verdict === 'right' ? '✔ right, pink' : `✘ wrong, ${a.colorName}`}`);
    li.className = a.verdict;
    return li;
  });
  list.replaceChildren(...items);
  if (items.length === 0) list.replaceChildren(Object.assign(document.createElement('li'), { textContent: 'No answer yet.' }));
}

/** The live stream: each event is the whole state; the browser reconnects by itself. */
function connect() {
  const status = $('[data-live]');
  const say = (state, text) => { status.dataset.live = state; status.textContent = text; };
  const events = new EventSource(withKey('/board/events'));
  let newest = null; // states that come faster than frames: only the newest is drawn
  events.addEventListener('state', (e) => {
    const waiting = newest !== null;
    newest = /** @type {MessageEvent} */ (e).data;
    if (waiting) return;
    requestAnimationFrame(() => {
      const text = newest;
      newest = null;
      show(JSON.parse(text));
      say('live', `Live: updated ${new Date().toLocaleTimeString()}`);
    });
  });
  events.addEventListener('error', () => say('reconnecting', 'Reconnecting to the class server…'));
}

/** Clear the board: asked first, in a dialog; the class is archived by the server. */
function clearing() {
  const dialog = /** @type {HTMLDialogElement} */ ($('[data-clear-dialog]'));
  $('[data-board-clear]').addEventListener('click', () => dialog.showModal());
  dialog.addEventListener('close', async () => {
    if (dialog.returnValue !== 'clear') return;
    const answer = await fetch(withKey('/board/clear'), { method: 'POST' });
    $('[data-live]').textContent = answer.ok ? 'The board was cleared: a new class starts.' : `The board could not be cleared (${answer.status}).`;
  });
}

/** @type {HTMLAnchorElement} */ ($('[data-board-csv]')).href = withKey('/board/class.csv');
drawPicture();
clearing();
connect();
