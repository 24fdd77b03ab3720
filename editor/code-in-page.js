/**
 * Code in the page, on every sketch page: the sketch's own code in an editor
 * beside its picture (code-panel.js). Pages 08, 09 and 10 (`<body
 * data-code-in-page="open">`) open it at once; every other sketch offers it
 * with an "Edit this sketch" button in its header, and opens it by itself for
 * a link that carries code (which still waits for the student's Run). The
 * editor (CodeMirror) is loaded only when it opens.
 *
 * This script comes before the sketch's own in the page: it reads the page's
 * markup before the sketch fills it (the frame's page), and hears of the
 * sketch's p5 instances, stopped when the editor's code first runs.
 */
import p5 from 'p5';
import { element } from '../lib/p5/dom.js';
import { codeTextInLink } from './code-link.js';
import { keptCode } from './kept-code.js';

const name = /([0-9]{2}-[a-z0-9-]+)\.html$/.exec(location.pathname)?.[1] ?? null;
const main = document.getElementById('sketch');
const markup = main?.outerHTML ?? '';
const instances = new Set();
p5.registerAddon((_p5, _fn, lifecycles) => {
  lifecycles.presetup = function () { instances.add(this); };
  lifecycles.remove = function () { instances.delete(this); };
});

if (name && main) offerTheEditor();

function offerTheEditor() {
  let opening = null;
  const open = () => (opening ??= import('./code-panel.js').then(({ openCodePanel }) => openCodePanel({ name, main, markup, instances })));
  const linkHasCode = () => codeTextInLink(location.href) !== null;
  if (document.body.dataset.codeInPage === 'open' || linkHasCode()) {
    open();
    return;
  }
  const header = document.querySelector('body > header');
  const button = element('button', { type: 'button', class: 'rt-button', 'data-edit-sketch': '', title: 'Its code in an editor beside the picture: change it and run it, apart from this page' },
    keptCode(name) === null ? 'Edit this sketch' : 'Edit this sketch (your version is kept)');
  header?.append(button);
  const opened = ({ heading }) => {
    button.remove();
    heading.focus(); // the panel's title: Tab goes on to Run and the editor
    heading.scrollIntoView({ block: 'start' });
  };
  button.addEventListener('click', () => {
    button.disabled = true;
    button.textContent = 'Opening the editor…';
    open().then(opened, () => {
      opening = null;
      button.disabled = false;
      button.textContent = 'Edit this sketch (it did not load: try again)';
    });
  });
  // A link with code pasted into this tab changes only the fragment: the editor opens with its code.
  addEventListener('hashchange', () => { if (linkHasCode()) open().then(() => button.remove(), () => {}); });
}
