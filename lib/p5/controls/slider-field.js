/**
 * A number a student can drag or type, as in sketch 02: a label, a slider and
 * a text box side by side (cells of the parent's grid), then a line for a bad
 * number; the picture keeps the last good value.
 *
 *   createSliderField(p, panel, { name: 'r', label: 'Radius r', min: 0.5, max: 12, step: 0.5, value: 4,
 *     use: (r) => view.setScene(sceneWith(r)) }); // use() throws for a value it cannot take
 *
 * The text box is read by readNumber, as every value box of the sketchbook
 * is; fieldMessage needs no page.
 */
import { readNumber } from '../../scene/values.js';
import { withText } from '../dom.js';
import { checkOptions } from '../../text/check.js';

/**
 * The line under a field with a bad value: its label, what is wrong, and that
 * the picture stays. readNumber's messages start with the label already; the
 * library's start with the field's own name ("radius must be …"): the label
 * says it better, so the name goes.
 */
export function fieldMessage(label, error) {
  const what = error.message.startsWith(label) ? error.message : `${label}: ${error.message.replace(/^\S+ (?=must )/, '')}`;
  return `${what}. The picture keeps the last good value.`;
}

/**
 * @param {import('p5').default} p the sketch (its DOM functions make the parts)
 * @param {object} field
 * @param {import('p5').default.Element|HTMLElement|string} field.parent the grid the label, slider, text box and message go into
 * @param {string} field.name the text box's id is `field-<name>`, the message's `data-message-for` is `<name>`
 * @param {string} field.label what the field is called
 * @param {number} field.min the slider's range…
 * @param {number} field.max
 * @param {number} field.step
 * @param {number} field.value …and its value at first
 * @param {(value: number) => void} field.use puts a number to use, or throws an Error saying why it cannot
 * @example
 * p.createSliderField({
 *   parent: 'controls', name: 'radius', label: 'r', min: 1, max: 8, step: 0.5, value: 4,
 *   use: (r) => view.setScene(makeScene(r)), // a bad value throws: the message shows, the picture stays
 * });
 */
export function createSliderField(p, options) {
  const { parent, name, label, min, max, step, value, use } = checkOptions(options, ['parent', 'name', 'label', 'min', 'max', 'step', 'value', 'use'], 'createSliderField');
  const id = `field-${name}`;
  withText(p.createElement('label'), label).attribute('for', id).parent(parent);
  const slider = p.createSlider(min, max, value, step).parent(parent).attribute('aria-label', `${label} slider`);
  const textBox = p.createInput(String(value)).parent(parent).id(id).attribute('inputmode', 'decimal');
  const message = p.createDiv().class('message').parent(parent).attribute('role', 'alert').attribute('data-message-for', name);

  /** Uses the number in `text`: the number, or undefined after saying why not. */
  const tryUse = (text) => {
    try {
      const number = readNumber(text, label);
      use(number);
      message.elt.textContent = '';
      textBox.attribute('aria-invalid', 'false');
      return number;
    } catch (error) {
      message.elt.textContent = fieldMessage(label, error);
      textBox.attribute('aria-invalid', 'true');
      return undefined;
    }
  };
  slider.input(() => {
    textBox.value(String(slider.value()));
    tryUse(String(slider.value()));
  });
  textBox.input(() => {
    const number = tryUse(textBox.value());
    if (number !== undefined) slider.value(number);
  });
}
