/**
 * The page contract: `document.body.dataset.render` is "rendering" while any
 * tracer view on the page is still tracing and "done" once every one has
 * finished. Tests (and screenshot tools) wait for "done".
 */

/** Every registered view → is it still tracing? */
const views = new Map();

/**
 * Registers a view (any object used as a key) with the page; it counts as
 * rendering until told otherwise.
 * @returns {{ rendering: Function, done: Function, unregister: Function }}
 */
export function registerView(view) {
  views.set(view, true);
  update();
  return {
    /** The view started (or restarted) tracing. */
    rendering: () => set(view, true),
    /** The view has finished its picture. */
    done: () => set(view, false),
    /** The view left the page: it no longer holds the page in "rendering". */
    unregister: () => { views.delete(view); update(); },
  };
}

/** The registered views, in the order they were made. */
export function pageViews() {
  return [...views.keys()];
}

/**
 * "rendering", "done", or null when no view is registered.
 * @example
 * pageRenderState(); // 'rendering' while a view traces, 'done' when all have finished (body[data-render] says the same)
 */
export function pageRenderState() {
  if (views.size === 0) return null;
  for (const rendering of views.values()) if (rendering) return 'rendering';
  return 'done';
}

function set(view, rendering) {
  if (!views.has(view) || views.get(view) === rendering) return;
  views.set(view, rendering);
  update();
}

function update() {
  const state = pageRenderState();
  if (typeof document === 'undefined' || !document.body || state === null) return;
  // Write only on change: observers of the attribute see each transition once.
  if (document.body.dataset.render !== state) document.body.dataset.render = state;
}
