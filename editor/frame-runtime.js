/**
 * What runs inside the sandboxed frame of a page's code editor, bundled into
 * one module with p5 and the whole kit (scripts/sketch-runtime.js serves and
 * builds it as `sketch-runtime.js`). The frame's import map points the code's
 * `import p5 from 'p5'` and `import … from '../lib/index.js'` (and
 * '../lib/p5/index.js') at this module, so the code in the editor is the
 * sketch's own file as it stands, imports and all (sketch 13's bunny too).
 *
 * startFrame() tells the page, by postMessage (frame-protocol.js), what the
 * page shows around the frame: the code's mistakes at the editor's lines,
 * when setup() is done, the render state, the selected pixel, the homework
 * check's verdict and the frame's height. The kit's own mistake panel is off
 * in the frame (the page shows them, at the editor's lines).
 */
import p5 from 'p5';
import { pageViews } from '../lib/p5/page-state.js';
import { errorMessage } from '../lib/p5/error-panel.js';
import { codePlace } from './frame-protocol.js';

export * from '../lib/index.js';
export * from '../lib/p5/index.js';
export { p5 };
// Sketch 13's bunny, as its file reads it (`import bunnyFile from 'bunny/index.js?raw'`): 110 kB of the runtime's 2 MB.
export { default as bunnyFile } from 'bunny/index.js?raw';

/**
 * Starts telling the page about the code that is about to run.
 * @param {{ sourceURL: string, selected: { x: number, y: number }|null }} run
 * @param {(message: object) => void} tell posts a message to the page
 */
export function startFrame({ sourceURL, selected }, tell) {
  const mistake = (error, event) => {
    const place = codePlace(typeof error?.stack === 'string' ? error.stack : '', event, sourceURL);
    // A syntax error of the code's script comes from the append that ran it: its own words are the student's.
    const message = errorMessage(error ?? event?.message ?? 'an error').replace(/Failed to execute 'append' on '\w+': /, '');
    tell({ type: 'error', message, line: place?.line ?? null, column: place?.column ?? null,
      exact: error?.name === 'SyntaxError' });
  };
  addEventListener('error', (event) => mistake(event.error, event));
  addEventListener('unhandledrejection', (event) => mistake(event.reason, null));

  new MutationObserver(() => {
    const state = document.body.dataset.render;
    if (state) tell({ type: 'render', state });
  }).observe(document.body, { attributes: true, attributeFilter: ['data-render'] });

  document.addEventListener('rt-check', (event) => tell({ type: 'check', passed: /** @type {CustomEvent} */ (event).detail?.passed === true }));
  new ResizeObserver(() => tell({ type: 'size', height: document.documentElement.scrollHeight })).observe(document.documentElement);

  let told = false;
  p5.registerAddon((_p5, _fn, lifecycles) => {
    lifecycles.postsetup = function () {
      if (told) return; // the first sketch's setup; a second p5 instance of the same code says nothing new
      told = true;
      const view = pageViews().find((v) => typeof v.select === 'function' && typeof v.on === 'function');
      if (view && selected && selected.x < view.width && selected.y < view.height) view.select(selected.x, selected.y);
      view?.on('select', (pixel) => tell({ type: 'select', x: pixel?.x ?? null, y: pixel?.y ?? null }));
      tell({ type: 'setup' });
    };
  });
}
