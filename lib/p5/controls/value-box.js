/**
 * A value box: a labelled text box with a message beside it, read by
 * lib/scene/values.js (a number by default), for any form of the kit: the scene
 * form's cells, the answer form's boxes. Its look is in style.css (`.sf-…`).
 */
import { readNumber } from '../../scene/values.js';
import { useStyle, element } from '../dom.js';

/**
 * A labelled text box with a message beside it. `read()` returns the value
 * (via `parse(text, label)`) or, when it throws, shows the message and
 * returns undefined. Good values clear the message.
 * @param {object} options
 * @param {string} options.label also the name used in messages
 * @param {string|number} [options.value]
 * @param {(text: string, label: string) => any} [options.parse] default readNumber with `rule`
 * @param {object} [options.rule] for readNumber
 * @param {string} [options.name] the box's `name` (for tests and labels)
 * @param {string} [options.size='6'] width in characters
 */
export function valueBox({ label, value = '', parse, rule, name, size = '6' }) {
  useStyle();
  const read = parse ?? ((text, l) => readNumber(text, l, rule));
  const input = element('input', { type: 'text', inputmode: 'decimal', name, size, spellcheck: 'false', autocomplete: 'off', 'aria-label': label });
  input.value = String(value);
  const message = element('span', { class: 'sf-message', role: 'alert', 'data-message-for': name ?? label });
  const box = {
    element: element('label', { class: 'sf-box' }, element('span', { class: 'sf-label' }, label), element('span', { class: 'sf-field' }, input), message),
    input,
    message,
    read() {
      try {
        const v = read(input.value, label);
        box.clear();
        return v;
      } catch (error) {
        box.fail(error.message);
        return undefined;
      }
    },
    fail(text) {
      message.textContent = text;
      input.setAttribute('aria-invalid', 'true');
    },
    clear() {
      message.textContent = '';
      input.removeAttribute('aria-invalid');
    },
  };
  return box;
}
