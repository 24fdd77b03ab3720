/**
 * A panel of switches, one per idea, each with a line saying what it does, as
 * in sketch 06: tick boxes, a choice and a slider that shows its value.
 *
 *   const panel = p.createSwitches({ parent: column, legend: 'One switch per idea' });
 *   const shadows = panel.toggle('shadows', 'a shadow ray from each hit point to each light…');
 *   const offset = panel.choice('shadow-ray offset', [['0.0001 (a small ε)', 1e-4], ['0 (none)', 0]], '…');
 *   const bounces = panel.slider('mirror bounces', { min: 0, max: 5, value: 5 }, '…');
 *   panel.onChange(() => { scene.shadows = shadows.checked(); …; view.restart(); });
 *
 * Each switch is returned as the p5.Element it is: `checked()`, `value()`.
 * Every text is set as text, never parsed as HTML.
 */
import { element, withText } from '../dom.js';
import { checkOptions } from '../../text/check.js';

/**
 * @param {import('p5').default} p the sketch (its DOM functions make the parts)
 * @param {object} options
 * @param {import('p5').default.Element|HTMLElement|string} options.parent where the panel goes
 * @param {string} options.legend the panel's title
 * @example
 * const panel = p.createSwitches({ parent: 'controls', legend: 'Lighting' });
 * const shadows = panel.toggle('Shadows', 'one shadow ray per light');
 * panel.onChange(() => view.setScene(makeScene({ shadows: shadows.checked() })));
 */
export function createSwitches(p, options) {
  const { parent, legend } = checkOptions(options, ['parent', 'legend'], 'createSwitches');
  const panel = p.createElement('fieldset').addClass('switches').parent(parent);
  panel.child(withText(p.createElement('legend'), legend));
  const inputs = []; // [switch, the p5 event it changes on]

  /** One switch in the panel: its control, then the line saying what it does. */
  const add = (control, why) => {
    const item = p.createDiv().addClass('switch');
    item.child(control);
    item.child(withText(p.createP(), why).addClass('why'));
    panel.child(item);
  };

  return {
    /** A tick box called `name`, on at first (it has `data-switch="<name>"`). */
    toggle(name, why) {
      const checkbox = p.createCheckbox('', true);
      checkbox.elt.querySelector('label').append(element('span', {}, ` ${name}`));
      checkbox.attribute('data-switch', name);
      add(checkbox, why);
      inputs.push([checkbox, 'changed']);
      return checkbox;
    },

    /** A drop-down inside its label; `options` are `[words, value]`, the first one chosen; value() is a string. */
    choice(label, options, why) {
      const select = /** @type {any} */ (p.createSelect()); // p5's types give a plain p5.Element, without option()
      for (const [words, value] of options) select.option(words, String(value));
      const labelled = withText(p.createElement('label'), `${label} `);
      labelled.child(select);
      add(labelled, why);
      inputs.push([select, 'changed']);
      return select;
    },

    /** A slider inside a label that shows its value: "mirror bounces: 5". */
    slider(label, { min, max, value, step = 1 }, why) {
      const slider = p.createSlider(min, max, value, step);
      const labelled = withText(p.createElement('label'), `${label}: ${value} `);
      labelled.child(slider);
      add(labelled, why);
      // A listener of its own: p5's slider.input() keeps one function per event, and onChange takes that one.
      slider.elt.addEventListener('input', () => { labelled.elt.firstChild.textContent = `${label}: ${slider.value()} `; });
      inputs.push([slider, 'input']);
      return slider;
    },

    /** Calls `retrace` whenever a switch changes. */
    onChange(retrace) {
      for (const [input, event] of inputs) input[event](retrace);
    },
  };
}
