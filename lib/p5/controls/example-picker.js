/**
 * Buttons for a page of examples that share one picture, as in sketch 07
 * (still, animated, workers): the chosen one is pressed. An example that
 * plays a SceneAnimation shows a row with Pause / Play (and, on the workers, how
 * many), and under the picture the frame counter and a note on what is shown.
 *
 *   const picker = p.createExamplePicker({ parent: column, examples: EXAMPLES, onChoose }); // EXAMPLES: { name: { note, label?, thread? } }
 *   const view = p.createTracerView({ …, parent: column });      // the picture goes under the buttons
 *   picker.attach(p.createAnimation({ view, sceneAt, camera }));
 *   picker.choose(exampleInLink(location.search, EXAMPLES).name);
 *
 * exampleInLink needs no page.
 */
import { element, resolveParent, sketchNode } from '../dom.js';
import { workerCountBox } from './animation.js';
import { checkOptions, show } from '../../text/check.js';

/**
 * The example a link asks for with `?example=…`: when it names none of the
 * examples, the first one, and a `problem` saying why.
 * @param {string} search the link's query, e.g. `location.search`
 * @param {Record<string, object>} examples by name, in order
 * @returns {{ name: string, problem: string }}
 * @example
 * exampleInLink('?example=animated', { still: {}, animated: {} }); // { name: 'animated', problem: '' }
 */
export function exampleInLink(search, examples) {
  const names = Object.keys(examples);
  const asked = new URLSearchParams(search).get('example');
  if (asked === null || names.includes(asked)) return { name: asked ?? names[0], problem: '' };
  return { name: names[0], problem: `example must be ${names.join(', ')}; got ${show(asked)}, so here is the ${names[0]} scene.` };
}

/**
 * @param {import('p5').default} p the sketch
 * @param {object} options
 * @param {HTMLElement|{elt: HTMLElement}|string} [options.parent] where the buttons go; default the sketch's node
 * @param {Record<string, { note: string, label?: string, thread?: 'main'|'workers' }>} options.examples by name, in order:
 *   the note under the picture, the button's text (default the name), and for an animated one the thread its frames are traced on
 * @param {(name: string, example: object) => void} options.onChoose shows the chosen example
 * @returns {{ attach: Function, choose: Function, say: Function }}
 * @example
 * p.createExamplePicker({
 *   examples: { still: { note: 'One frame, traced once.' }, animated: { note: 'A frame per draw().', thread: 'main' } },
 *   onChoose: (name) => view.setScene(name === 'still' ? classScene() : classSceneAt(0)),
 * });
 */
export function createExamplePicker(p, options) {
  const { parent, examples, onChoose } = checkOptions(options, ['parent', 'examples', 'onChoose'], 'createExamplePicker');
  const host = resolveParent(parent, sketchNode(p));
  const buttons = Object.entries(examples).map(([name, { label = name }]) => element('button', { class: 'rt-button', 'data-example': name }, label));
  const pause = element('button', { class: 'rt-button', 'data-pause': '' }, 'Pause');
  const row = element('div', { class: 'controls' }, pause);
  const error = element('p', { class: 'error', role: 'alert', 'data-message': 'example' });
  const stats = element('p', { class: 'stats', 'data-stats': '' });
  const note = element('p', { class: 'about' });
  host.append(element('div', { class: 'tabs' }, ...buttons), row, error);
  let chosen, workers;

  const picker = {
    /**
     * Hands the controls to an animation (sets its stats, onPlay, onPause and
     * onError): Pause plays and pauses it, the box sets its worker count.
     * Call once the picture is under the buttons: the stats and the note go under it.
     */
    attach(animation) {
      Object.assign(animation, {
        stats,
        onPlay: (on) => {
          pause.textContent = on ? 'Pause' : 'Play';
          if (on) note.textContent = examples[chosen].note;
        },
        onPause: ({ same }) => {
          note.textContent = same === undefined ? 'Paused: click a pixel of this frame to see its story.'
            : `Paused. Traced again on one thread, this frame is ${same ? 'the same, byte for byte ✓' : 'DIFFERENT ✗'}`;
        },
        onError: (problem) => picker.say(String(problem.message ?? problem)),
      });
      pause.addEventListener('click', () => animation.play(!animation.playing));
      const box = workerCountBox(animation); // "workers (1–8)", a message when the count is bad
      row.append(box.label, box.message);
      workers = box.label;
      host.append(stats, note);
    },

    /** Shows example `name`: its button pressed, an animation's controls only for an animation, its note. */
    choose(name) {
      chosen = name;
      const { thread, note: words } = examples[name];
      for (const button of buttons) button.setAttribute('aria-pressed', String(button.dataset.example === name));
      row.style.display = thread ? '' : 'none';
      if (workers) workers.style.display = thread === 'workers' ? '' : 'none';
      stats.style.display = thread ? '' : 'none';
      picker.say('');
      onChoose(name, examples[name]);
      note.textContent = words;
    },

    /** Writes a message in the error line as plain text (it may quote what someone typed); '' hides it. */
    say(message) {
      error.textContent = message;
    },
  };
  for (const button of buttons) button.addEventListener('click', () => picker.choose(button.dataset.example));
  return picker;
}
