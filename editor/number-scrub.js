/**
 * Number scrubbing in the code editor: with the caret in a number literal,
 * Alt+ArrowUp / Alt+ArrowDown change it by one step of its last decimal
 * place (with Shift, ten steps); elsewhere those keys still move the line,
 * as CodeMirror's own keys do. Alt+drag sideways on a number changes it
 * continuously: while Alt is held, numbers show a sideways cursor and a
 * dotted underline. Each change is an ordinary transaction of the editor,
 * marked with `scrubbed`; a whole drag is one step of the editor's history,
 * so one Undo takes it back.
 */
import { EditorView, ViewPlugin, Decoration, keymap } from '@codemirror/view';
import { Annotation, Prec, Transaction } from '@codemirror/state';
import { syntaxTree } from '@codemirror/language';
import { literalAt, stepped, written } from './number-literal.js';

/**
 * Marks a scrub's transaction: `{ from, to, was, now }`, the literal's place
 * in the code before the change and its old and new text; `{ passing: true }`
 * marks the drag's last, unseen step back to where it began.
 */
export const scrubbed = Annotation.define();

/** Screen pixels of a sideways drag per step of the number. */
export const DRAG_PX_PER_STEP = 6;

/** Writes `text` in place of `literal`, the caret kept as far from its end; returns the new literal. */
function replaceLiteral(view, literal, text, { history = true, passing = false } = {}) {
  const insert = written(view.state.sliceDoc(literal.from - 1, literal.from), text);
  const to = literal.from + insert.length;
  const fromEnd = Math.max(0, literal.to - view.state.selection.main.head);
  view.dispatch({
    changes: { from: literal.from, to: literal.to, insert },
    selection: { anchor: to - Math.min(fromEnd, text.length) },
    annotations: [
      scrubbed.of(passing ? { passing } : { from: literal.from, to: literal.to, was: literal.text, now: text }),
      Transaction.userEvent.of('input.scrub'),
      ...(history ? [] : [Transaction.addToHistory.of(false)]),
    ],
  });
  return { from: to - text.length, to, text };
}

/** One key's steps at the caret; false (the key's usual command runs) when the caret is not in a number. */
const stepBy = (steps) => (view) => {
  const { main } = view.state.selection;
  const literal = literalAt(view.state, main.head);
  if (!literal || main.from < literal.from || main.to > literal.to) return false;
  replaceLiteral(view, literal, stepped(literal.text, steps));
  return true;
};

const keys = Prec.highest(keymap.of([
  { key: 'Alt-ArrowUp', run: stepBy(1), shift: stepBy(10) },
  { key: 'Alt-ArrowDown', run: stepBy(-1), shift: stepBy(-10) },
]));

/** Alt+drag on a number: each DRAG_PX_PER_STEP sideways is one step; on release, the whole drag is one change. */
function startDrag(event, view) {
  if (!event.altKey || event.button !== 0) return false;
  const pos = view.posAtCoords({ x: event.clientX, y: event.clientY }, false);
  const start = literalAt(view.state, pos);
  if (!start) return false;
  event.preventDefault();
  view.dom.classList.add('cm-scrubbing');
  let literal = start, steps = 0;
  const move = (e) => {
    const now = Math.round((e.clientX - event.clientX) / DRAG_PX_PER_STEP);
    if (now === steps) return;
    steps = now;
    literal = replaceLiteral(view, literal, stepped(start.text, steps), { history: false });
  };
  const end = () => {
    removeEventListener('mousemove', move);
    removeEventListener('mouseup', end);
    view.dom.classList.remove('cm-scrubbing');
    if (literal.text === start.text) return;
    const last = literal.text; // back to the start unseen, then the drag's change as one step of the history
    literal = replaceLiteral(view, literal, start.text, { history: false, passing: true });
    replaceLiteral(view, literal, last);
  };
  addEventListener('mousemove', move);
  addEventListener('mouseup', end);
  return true;
}

const numberMark = Decoration.mark({ class: 'cm-scrub-number', attributes: { title: 'Alt+↑ / Alt+↓, or Alt+drag sideways: change this number' } });

/** The numbers in view, marked so that Alt shows they can be dragged. */
const numberMarks = ViewPlugin.fromClass(class {
  constructor(view) { this.decorations = this.marks(view); }
  update(update) {
    if (update.docChanged || update.viewportChanged || syntaxTree(update.startState) !== syntaxTree(update.state)) this.decorations = this.marks(update.view);
  }
  marks(view) {
    const ranges = [];
    for (const { from, to } of view.visibleRanges) {
      syntaxTree(view.state).iterate({ from, to, enter: (node) => {
        if (node.name !== 'Number') return;
        const literal = literalAt(view.state, node.to);
        if (literal) ranges.push(numberMark.range(literal.from, literal.to));
      } });
    }
    return Decoration.set(ranges, true);
  }
}, { decorations: (plugin) => plugin.decorations });

/** Whether Alt is held, as a class on the editor (the cue's CSS: code-in-page.css). */
function altCue(view) {
  const show = (event) => view.dom.classList.toggle('cm-alt-held', event.altKey);
  const off = () => view.dom.classList.remove('cm-alt-held');
  for (const type of ['keydown', 'keyup', 'mousemove']) addEventListener(type, show);
  addEventListener('blur', off);
  return { destroy() { for (const type of ['keydown', 'keyup', 'mousemove']) removeEventListener(type, show); removeEventListener('blur', off); } };
}

/** The editor's extension for number scrubbing. */
export function numberScrubbing() {
  return [keys, numberMarks, ViewPlugin.define(altCue), Prec.highest(EditorView.domEventHandlers({ mousedown: startDrag }))];
}
