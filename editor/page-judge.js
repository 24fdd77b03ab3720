/**
 * The page's judge of the code that runs in its sandboxed frame. The frame
 * only reports what the student's code built: its first tracer view's scene
 * and camera as the library's JSON text, and the pixel selected there
 * (frame-protocol.js). The page reads that JSON again with the library's
 * checked reader (lib/scene/json.js, within the limits of a scene from a
 * link), and with the scene it read it ticks the page's tasks
 * (lib/p5/controls/task-list.js) and runs the homework's self-check
 * (lib/lesson/homework.js) itself. Both live here, in the page under the
 * frame, for the whole visit: every Run keeps them, their progress is kept
 * in the page's own storage, and their `rt-task` and `rt-check` events reach
 * the class board as on every other page. Whatever the frame claims beyond
 * what it built (a verdict, a task, progress) is no message the page reads.
 */
import { sceneFromJSON, cameraFromJSON } from '../lib/scene/json.js';
import { MAX_SCENE_OBJECTS } from '../lib/scene/codec.js';
import { lessonOf } from '../lib/lesson/tasks.js';
import { HOMEWORK_CHECKS } from '../lib/lesson/homework.js';
import { TaskList } from '../lib/p5/controls/task-list.js';
import { homeworkCheck } from '../lib/p5/controls/homework-check.js';
import { element } from '../lib/p5/dom.js';

/**
 * What the frame's code built, as the page read it: the view the page's
 * tasks and self-check look at (a tracer view's `scene`, `camera`, `mode`,
 * `order`, `selected` and `onSelect`, without a picture of its own).
 */
export class FrameView {
  /** @type {import('../lib/scene/scene.js').Scene|null} */ scene = null;
  /** @type {import('../lib/math/camera.js').Camera|null} */ camera = null;
  mode = 'shaded';
  order = 'coarse';
  /** @type {{ x: number, y: number }|null} */ selected = null;
  /** Why the last scene could not be read (null: it was, or none came yet). */
  problem = null;
  /** No canvas of its own: the picture is in the frame. */
  canvas = null;
  #listeners = new Set();

  get width() { return this.camera?.width ?? 0; }
  get height() { return this.camera?.height ?? 0; }

  /** @param {(pixel: { x: number, y: number }|null) => void} fn @returns {() => void} removes it */
  onSelect(fn) {
    this.#listeners.add(fn);
    return () => this.#listeners.delete(fn);
  }

  /** A new run set up, or the frames are gone: nothing read from it yet. */
  clear() {
    this.scene = this.camera = this.selected = this.problem = null;
  }

  /**
   * Reads a checked scene message (frame-protocol.js): the scene and camera
   * the page judges from now on, or, when they cannot be read, none and the
   * reason in `problem`, naming the field.
   * @param {{ scene: string|null, camera: string|null, mode: string, order: string, problem: string|null }} message
   */
  read({ scene, camera, mode, order, problem }) {
    this.clear();
    if (scene === null) {
      this.problem = `The scene your code built could not be sent to the page: ${problem}`;
      return;
    }
    try {
      const read = { scene: sceneFromJSON(scene, { maxObjects: MAX_SCENE_OBJECTS, limitWork: true }), camera: cameraFromJSON(camera) };
      Object.assign(this, read, { mode, order });
    } catch (error) {
      this.problem = `The scene your code built could not be read: ${error.message}`;
    }
  }

  /** The frame's view selected pixel (x, y) (x null: none): its listeners hear it when it is a pixel of the camera read. */
  select(x, y) {
    const inside = x !== null && this.camera !== null && x < this.camera.width && y < this.camera.height;
    this.selected = inside ? { x, y } : null;
    for (const fn of this.#listeners) fn(this.selected);
  }
}

/** A self-check's result when there is no scene to check: one check to fix, saying why. */
function noScene(problem) {
  return { passed: false, checks: [{ label: 'Your scene reached the page', passed: false,
    detail: problem ?? 'Your code has not built a scene yet: press Run, and check again once its picture shows.' }] };
}

/**
 * Opens the page's judge in `box` (the page's, outside the frame): a line
 * for a scene that cannot be read, the self-check of a homework page, the
 * page's tasks. `lines` are the class board's lines the page's own parts
 * had (lib/p5/page/class-board.js): they move here, and go on saying where each
 * submission is.
 * @param {{ page: string, box: HTMLElement, lines?: { tasks?: Element|null, check?: Element|null } }} options
 * @returns {{ view: FrameView, heard: (message: { type: string }) => void, tasks: TaskList|null }}
 */
export function openPageJudge({ page, box, lines = {} }) {
  const view = new FrameView();
  const status = element('p', { class: 'code-judge-status', role: 'status', 'data-judge-status': '' });
  box.append(status);
  const check = HOMEWORK_CHECKS[page];
  if (check) {
    const section = element('section', { class: 'card hw-panel', 'aria-label': 'Self-check', 'data-page-check': '' });
    box.append(section);
    const part = homeworkCheck({ view, parent: section,
      check: (scene, camera, options) => (scene && camera ? check(scene, camera, options) : noScene(view.problem)) });
    if (lines.check) part.button.parentElement.append(lines.check);
  }
  const tasks = lessonOf(page) ? new TaskList({ page, view, parent: box }) : null;
  if (tasks && lines.tasks) tasks.element.append(lines.tasks);

  const heard = (message) => {
    if (message.type === 'setup' || message.type === 'stuck') view.clear();
    else if (message.type === 'scene') view.read(/** @type {any} */ (message));
    else if (message.type === 'select') view.select(/** @type {any} */ (message).x, /** @type {any} */ (message).y);
    else return;
    status.textContent = view.problem ?? '';
  };
  return { view, heard, tasks };
}

/** The class board's lines of the page's own task list and self-check (lib/p5/page/class-board.js), to keep when they go. */
export function boardLines() {
  return {
    tasks: document.querySelector('[data-tasks] > [data-class-sent]'),
    check: document.querySelector('.rt-check > [data-class-sent]'),
  };
}
