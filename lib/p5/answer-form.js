/**
 * An answer form for an activity: checked value boxes and a Check button
 * (Enter in any box checks too), a result line with a colour swatch and ✔/✘,
 * the answer in the lesson's format with a Copy button, and a note.
 *
 *   const form = createAnswerForm({ parent: 'activity', boxes: { x: { label: 'Pixel x', rule } }, onCheck });
 *   const values = form.read();   // { x: 10 }, or undefined after marking the bad box in red
 *   form.show({ ok: true, message: 'Pink!', color, answer: 'Pixel: 10,12; H: 1.2; V: 0.3' });
 */
import { valueBox } from './scene-form.js';
import { element } from './dom.js';

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
 * @param {object} options
 * @param {string|HTMLElement} options.parent where the form goes (an id or an element)
 * @param {Record<string, { label: string, value?: number|string, rule?: object }>} options.boxes by name, in order
 * @param {() => void} options.onCheck Check was pressed (or Enter)
 * @param {string} [options.title='Your answer'] the heading
 * @param {string} [options.note] a paragraph under the answer
 */
export function createAnswerForm({ parent, boxes: specs, onCheck, title = 'Your answer', note }) {
  const boxes = Object.fromEntries(Object.entries(specs).map(([name, spec]) => [name, valueBox({ name, ...spec })]));
  const checkButton = element('button', { type: 'submit', class: 'rt-button', 'data-check': '' }, 'Check');
  const form = element('form', { class: 'boxes', novalidate: '' }, ...Object.values(boxes).map((b) => b.element), checkButton);
  form.addEventListener('submit', (event) => { event.preventDefault(); onCheck(); });

  const result = element('p', { class: 'result', 'data-result': '', role: 'status' });
  const answer = element('code', { class: 'answer', 'data-answer-line': '' });
  const copyButton = element('button', { type: 'button', class: 'rt-button' }, 'Copy answer');
  copyButton.addEventListener('click', () => navigator.clipboard?.writeText(answer.textContent).catch(() => {}));
  const section = element('section', { class: 'task' },
    element('h2', {}, title), form, result, element('div', { class: 'answer-row' }, answer, copyButton),
    note && element('p', { class: 'note' }, note));
  (typeof parent === 'string' ? document.getElementById(parent) : parent).append(section);

  return {
    boxes, result, answer, element: section,
    /** Every box's value by name, or undefined (the bad boxes say why, and so does the result line). */
    read() {
      const values = readBoxes(boxes);
      if (!values) {
        result.replaceChildren('Fix the box marked in red, then Check again.');
        result.dataset.result = 'error';
      }
      return values;
    },
    /** Puts values in boxes (clearing their messages). */
    fill(values) {
      for (const [name, value] of Object.entries(values)) {
        boxes[name].input.value = value;
        boxes[name].clear();
      }
    },
    /**
     * The verdict: ✔ or ✘, a swatch of `color` (CSS, e.g. '#ff5160'), the
     * message, `data` on the result line's dataset, and the answer line.
     */
    show({ ok, message, color, data = {}, answer: line }) {
      const swatch = color && element('span', { class: 'rt-swatch', style: `background: ${color}` });
      result.replaceChildren(...[swatch, (ok ? '✔ ' : '✘ ') + message].filter(Boolean));
      Object.assign(result.dataset, data);
      if (line !== undefined) answer.textContent = line;
    },
  };
}
