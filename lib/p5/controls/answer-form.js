/**
 * An answer form for an activity: checked value boxes and a Check button
 * (Enter in any box checks too), the answer in the lesson's format with the
 * verdict beside it (a colour swatch, ✔/✘ and a message), a line of detail,
 * a Copy button, and a note. Pasting a whole answer line into any box fills
 * every box (`parse`).
 *
 *   const form = p.createAnswerForm({ parent: 'activity', boxes: { x: { label: 'Pixel x', rule } }, onCheck, parse: readAnswerLine });
 *   const values = form.read();   // { x: 10 }, or undefined after marking the bad box in red
 *   form.show({ ok: true, message: 'Pink!', color, answer: 'Pixel: 10,12; H: 30; V: -82' });
 */
import { valueBox } from './value-box.js';
import { element, resolveParent, sketchNode, copyText } from '../dom.js';
import { checkOptions } from '../../text/check.js';
import { joinClassBoard } from '../page/class-board.js';
import { createAnnouncer } from '../page/announce.js';

/**
 * Reads every box (each bad one shows its message): `{ name: value }`, or
 * undefined when any box is bad.
 * @param {Record<string, { read: () => any }>} boxes
 */
export function readBoxes(boxes) {
  const values = Object.fromEntries(Object.entries(boxes).map(([name, box]) => [name, box.read()]));
  return Object.values(values).includes(undefined) ? undefined : values;
}

/**
 * @param {import('p5').default} p the sketch
 * @param {object} options
 * @param {string|HTMLElement} [options.parent] where the form goes (an id or an element); default the sketch's node
 * @param {Record<string, { label: string, value?: number|string, rule?: object }>} options.boxes by name, in order
 * @param {() => void} options.onCheck Check was pressed (or Enter)
 * @param {string} [options.title='Your answer'] the heading
 * @param {(text: string) => ?Record<string, string>} [options.parse] reads a pasted answer line into box texts by name, or null
 * @param {string|Node} [options.note] under the answer
 * @example
 * const form = p.createAnswerForm({
 *   boxes: { x: { label: 'Pixel x' }, y: { label: 'Pixel y' } },
 *   onCheck: () => console.log(form.read()), // { x, y } as numbers; undefined while a box is wrong (it says why)
 * });
 */
export function createAnswerForm(p, options) {
  const { parent, boxes: specs, onCheck, title = 'Your answer', parse, note } = checkOptions(options, ['parent', 'boxes', 'onCheck', 'title', 'parse', 'note'], 'createAnswerForm');
  const boxes = Object.fromEntries(Object.entries(specs).map(([name, spec]) => [name, valueBox({ name, ...spec })]));
  const entry = answerEntry(boxes, { onCheck, parse, onLine: fillFromLine });
  joinClassBoard(); // served by npm run class: a Check's answer goes to the teacher's board
  const row = answerRow();
  const { answer, result, detail, verdict } = row;
  const section = element('section', { class: 'task' },
    element('h2', {}, title), entry.form, row.element, detail, verdict.element, row.copyVoice.element,
    note && (note instanceof Node ? note : element('p', { class: 'note' }, note)));
  resolveParent(parent, sketchNode(p)).append(section);

  /** Puts values in boxes (clearing their messages). */
  function fill(values) {
    for (const [name, value] of Object.entries(values)) {
      boxes[name].input.value = value;
      boxes[name].clear();
    }
  }

  /** A whole answer line, pasted or typed: every box gets its value, and the last verdict goes (it judged another answer). */
  function fillFromLine(values) {
    fill(values);
    row.unchecked();
  }

  return {
    boxes, result, answer, detail, element: section, fill,
    /** Every box's value by name, or undefined (the bad boxes say why, and so does the result line). */
    read() {
      const values = readBoxes(boxes);
      if (!values) {
        // names the boxes in words, not only by their red mark
        const bad = Object.values(boxes).filter((b) => b.message.textContent).map((b) => b.input.getAttribute('aria-label'));
        result.replaceChildren(`Fix ${bad.length === 1 ? 'the box' : 'the boxes'} ${bad.join(', ')} (marked in red, the reason beside it), then Check again.`);
        result.dataset.result = 'error';
        verdict.say(result.textContent);
      }
      return values;
    },
    /**
     * The verdict: ✔ or ✘, a swatch of `color` (CSS, e.g. '#ff5160'), the
     * message, `data` on the result's dataset, the answer line and a line of detail.
     * The form's element then sends an `rt-answer` event (bubbling) with `detail: { ok, answer, submitted, send }`:
     * `submitted` when the student pressed Check, `send` what the class board gets of it (lib/p5/page/class-board.js).
     */
    show({ ok, message, color, data = {}, answer: line, detail: more, send }) {
      row.show({ ok, message, color, data, line, more });
      // The page's tasks (task-list.js) hear of each verdict.
      section.dispatchEvent(new CustomEvent('rt-answer', { bubbles: true, detail: { ok: Boolean(ok), answer: answer.textContent, submitted: entry.byStudent(), send } }));
    },
  };
}

/**
 * The boxes in a form with its Check button: Check (or Enter) runs `onCheck`;
 * with `parse`, a whole answer line pasted or typed into any box is handed to
 * `onLine`, which fills every box. `byStudent()`: a Check of the student's own
 * is running (what the class board gets).
 */
function answerEntry(boxes, { onCheck, parse, onLine }) {
  const checkButton = element('button', { type: 'submit', class: 'rt-button', 'data-check': '' }, 'Check');
  const form = element('form', { class: 'boxes', novalidate: '' }, ...Object.values(boxes).map((b) => b.element), checkButton);
  let byStudent = false; // a verdict shown while the student's own Check (or Enter) runs: what the class board gets
  /** The slide's whole line typed into one box, as a paste would bring it: fills every box. */
  const takeTypedLine = () => {
    const values = parse && Object.values(boxes).map((box) => parse(box.input.value)).find(Boolean);
    if (values) onLine(values);
  };
  form.addEventListener('submit', (event) => {
    event.preventDefault();
    byStudent = true;
    takeTypedLine();
    try { onCheck(); } finally { byStudent = false; }
  });
  if (parse) {
    form.addEventListener('paste', (event) => {
      const values = parse(event.clipboardData?.getData('text/plain') ?? '');
      if (!values) return; // an ordinary paste into one box
      event.preventDefault();
      onLine(values);
    });
    // Capture: before a box's own change handler reads the line as a bad number.
    form.addEventListener('change', takeTypedLine, true);
  }
  return { form, byStudent: () => byStudent };
}

/**
 * The answer's row: the answer line, the verdict beside it, Copy answer and
 * what it did; the line of detail under it; and the voices that say the
 * verdict and the copy.
 */
function answerRow() {
  const answer = element('code', { class: 'answer', 'data-answer-line': '' });
  const result = element('span', { class: 'result', 'data-result': '' });
  const detail = element('p', { class: 'detail', 'data-answer-detail': '' });
  // The verdict is said with the answer line, as the line to type: it speaks for the
  // selected pixel too (the inspector's line gives the ray's own angles, not an answer).
  const verdict = createAnnouncer({ name: 'verdict', order: 1, speaksFor: 'pixel' });
  // What Copy answer did shows beside it and is said by the page's one voice (not a status of its own).
  const copyVoice = createAnnouncer({ name: 'copy', order: 3 });
  const copied = element('span', { class: 'copied', 'data-copied': '' });
  const copyButton = element('button', { type: 'button', class: 'rt-button', 'data-copy-answer': '' }, 'Copy answer');
  const tellCopy = (text) => { copied.textContent = text; copyVoice.say(text); };
  copyButton.addEventListener('click', async () => {
    const line = answer.textContent;
    if (!line) return tellCopy('Check an answer first: nothing to copy yet.');
    tellCopy(await copyText(line) ? `Copied: ${line}. Paste it in the class chat.` : `Select the answer and press Ctrl+C (⌘C): ${line}`);
  });
  return {
    answer, result, detail, verdict, copyVoice,
    element: element('div', { class: 'answer-row' }, answer, result, copyButton, copied),
    /** No verdict: the answer changed since the last Check. */
    unchecked() {
      for (const key of Object.keys(result.dataset)) delete result.dataset[key];
      result.dataset.result = 'unchecked';
      result.replaceChildren('Not checked yet: press Check.');
      answer.textContent = '';
      detail.textContent = '';
    },
    /** ✔ or ✘, a swatch, the message, `data` on the result's dataset, the answer line and the detail, said with the line first. */
    show({ ok, message, color, data, line, more }) {
      const swatch = color && element('span', { class: 'rt-swatch', style: `background: ${color}` });
      result.replaceChildren(...[swatch, (ok ? '✔ ' : '✘ ') + message].filter(Boolean));
      Object.assign(result.dataset, data);
      if (line !== undefined) answer.textContent = line;
      copied.textContent = '';
      if (more !== undefined) detail.textContent = more;
      // words, not ✔ / ✘ (read as "heavy check mark"); the line first: it is the one to type
      verdict.say(`${answer.textContent ? `${answer.textContent}. ` : ''}${ok ? 'Right' : 'Wrong'}: ${message}`);
    },
  };
}
