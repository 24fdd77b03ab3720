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
 * when setup() is done, the render state, the selected pixel, the frame's
 * height, and what the code built (its first tracer view's scene and camera,
 * as the library's JSON), from which the page itself judges the tasks and
 * the homework. The kit's own mistake panel is off in the frame (the page
 * shows them, at the editor's lines), and so are its task list and
 * self-check: the page keeps them, outside the frame.
 *
 * The page may send new values of the scene's or the camera's fields (a
 * number scrubbed in the editor): the frame sets them in a copy of its
 * view's scene, as JSON, and traces again, coarse to fine, with no new run.
 */
import p5 from 'p5';
import { pageViews } from '../lib/p5/page/page-state.js';
import { errorMessage } from '../lib/p5/page/error-panel.js';
import { sceneToJSON, cameraToJSON } from '../lib/scene/json.js';
import { withValues } from './scene-values.js';
import { codePlace, readValues } from './frame-protocol.js';

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

  const scene = sceneTeller(tell);
  new MutationObserver(() => {
    const state = document.body.dataset.render;
    if (state === 'done') scene.now(); // the page judges a finished picture by the scene it was traced from
    if (state) tell({ type: 'render', state });
  }).observe(document.body, { attributes: true, attributeFilter: ['data-render'] });

  new ResizeObserver(() => tell({ type: 'size', height: document.documentElement.scrollHeight })).observe(document.documentElement);

  let told = false;
  p5.registerAddon((_p5, fn, lifecycles) => {
    // The page's own task list and self-check judge what the code built: none in the frame.
    fn.createTaskList = () => ({ tasks: [], startAgain() {}, destroy() {} });
    fn.createHomeworkCheck = () => ({ button: null, results: null, run() {}, destroy() {} });
    lifecycles.postsetup = function () {
      if (told) return; // the first sketch's setup; a second p5 instance of the same code says nothing new
      told = true;
      const view = pageViews().find((v) => typeof v.select === 'function' && typeof v.on === 'function');
      if (view && selected && selected.x < view.width && selected.y < view.height) view.select(selected.x, selected.y);
      view?.on('select', (pixel) => {
        scene.now(); // a pixel of the scene the page has
        tell({ type: 'select', x: pixel?.x ?? null, y: pixel?.y ?? null });
      });
      tell({ type: 'setup' });
      if (view) {
        scene.follow(view);
        view.on('restart', () => scene.soon());
        addEventListener('message', (event) => {
          const changes = event.source === parent ? readValues(event.data) : null;
          if (changes) setValues(view, changes, mistake);
        });
      }
    };
  });
}

/** The page's new values in the view's scene and camera, traced again; a bad value is a mistake naming its field, and the last good picture stays. */
function setValues(view, changes, mistake) {
  try {
    const { scene, camera } = withValues(view.scene, view.camera, changes);
    if (scene) view.setScene(scene);
    if (camera) view.setCamera(camera);
  } catch (error) {
    mistake(error, null);
  }
}

/** How often at most the scene goes to the page while it keeps changing (an animation, a camera that orbits), in ms. */
const SCENE_EVERY_MS = 400;

/** Tells the page the view's scene and camera: at once, or soon (at most every SCENE_EVERY_MS), and only when changed. */
function sceneTeller(tell) {
  let view = null, timer = 0, last = '';
  const now = () => {
    clearTimeout(timer);
    timer = 0;
    if (!view) return;
    let message;
    try {
      message = { type: 'scene', scene: JSON.stringify(sceneToJSON(view.scene)), camera: JSON.stringify(cameraToJSON(view.camera)), mode: view.mode, order: view.order };
    } catch (error) {
      message = { type: 'scene', scene: null, camera: null, problem: String(error?.message ?? error) };
    }
    const key = `${message.scene}\n${message.camera}\n${message.mode}\n${message.order}`;
    if (key === last) return;
    last = key;
    tell(message);
  };
  return {
    follow(v) { view = v; now(); },
    now,
    soon() { if (!timer) timer = setTimeout(now, SCENE_EVERY_MS); },
  };
}
