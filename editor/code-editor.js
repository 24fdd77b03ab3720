/**
 * The code editor of a page (CodeMirror 6, from node_modules): JavaScript
 * highlighting, line numbers, undo, search. Tab indents; Esc then Tab leaves
 * the editor (CodeMirror's own escape, said in the hint beside it). Numbers
 * can be scrubbed: Alt+↑/↓ or Alt+drag (number-scrub.js). The
 * editable element carries `data-editor` (the page contract) and a label.
 */
import { EditorView, basicSetup } from 'codemirror';
import { javascript } from '@codemirror/lang-javascript';
import { keymap } from '@codemirror/view';
import { indentWithTab } from '@codemirror/commands';
import { numberScrubbing, scrubbed } from './number-scrub.js';

/**
 * @param {object} options
 * @param {HTMLElement} options.parent
 * @param {string} options.code the text it starts with
 * @param {string} options.label its name for screen readers
 * @param {string} options.describedBy the id of the hint under it
 * @param {(code: string, scrub: object|undefined) => void} options.onChange called after each change of the text,
 *   with the scrub that made it, if one did (number-scrub.js's `scrubbed`)
 * @returns {{ view: EditorView, code: () => string, setCode: (code: string) => void, line: (n: number) => string|undefined, focusLine: (n: number) => void }}
 */
export function createCodeEditor({ parent, code, label, describedBy, onChange }) {
  const view = new EditorView({
    doc: code,
    parent,
    extensions: [
      basicSetup,
      numberScrubbing(),
      keymap.of([indentWithTab]),
      javascript(),
      EditorView.lineWrapping, // no sideways scrolling, at 320 px too; the editor grows with its code (no scroll region of its own)
      EditorView.contentAttributes.of({ 'data-editor': '', 'aria-label': label, 'aria-describedby': describedBy }),
      EditorView.updateListener.of((update) => {
        if (update.docChanged) onChange(update.state.doc.toString(), update.transactions.map((t) => t.annotation(scrubbed)).find(Boolean));
      }),
    ],
  });
  return {
    view,
    code: () => view.state.doc.toString(),
    /** Replaces the whole text as one change (Ctrl+Z brings the old text back). */
    setCode: (text) => view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: text } }),
    line: (n) => (n >= 1 && n <= view.state.doc.lines ? view.state.doc.line(n).text : undefined),
    focusLine: (n) => {
      const line = view.state.doc.line(Math.max(1, Math.min(n, view.state.doc.lines)));
      view.dispatch({ selection: { anchor: line.from }, scrollIntoView: true });
      view.focus();
    },
  };
}
