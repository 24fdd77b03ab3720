/**
 * The page's side of the sandboxed frame that runs the editor's code.
 *
 * Each run is a new `<iframe sandbox="allow-scripts allow-downloads">` (no
 * `allow-same-origin`: the frame has an opaque origin, so it cannot read
 * the kit's storage, its pages or anything of the class server's in the
 * page's name) whose document is written here (`srcdoc`): the sketch's own
 * markup and stylesheets, and a small script that waits for the code.
 * The page then sends it the runtime (p5 and the kit, one module: see
 * scripts/sketch-runtime.js) and the code; the frame runs the runtime from a
 * Blob URL of its own, behind an import map, and the code as a module.
 *
 * The new frame stays hidden until its setup() is done; then it takes the old
 * one's place. A run that fails before that leaves the old frame, the last
 * good picture, where it was.
 *
 * A frame says it is alive every second. One silent for SILENCE_MS while the
 * page is in view is stuck in a loop that never ends (`while (true)`, a loop
 * whose step goes the wrong way): the frames are removed, which stops it and
 * frees the student's processor, and the page hears `{ type: 'stuck' }`.
 */
import { readFrameMessage, frameHeight } from './frame-protocol.js';

/** The frame's bootstrap, written into its document as text: it runs in the frame, not here. */
function frameBootstrap() {
  const tell = (message) => parent.postMessage(message, '*');
  // Storage of its own, in memory: a sandboxed frame's own throws. Nothing in it reaches the page.
  const memory = () => {
    const items = new Map();
    return {
      getItem: (key) => (items.has(String(key)) ? items.get(String(key)) : null),
      setItem: (key, value) => { items.set(String(key), String(value)); },
      removeItem: (key) => { items.delete(String(key)); },
      clear: () => items.clear(),
      key: (i) => [...items.keys()][i] ?? null,
      get length() { return items.size; },
    };
  };
  /** @type {any} */ (window).__sketchbookErrorPanel = true; // the page shows the mistakes, at the editor's lines
  // p5 listens for the device's motion; a frame of another origin may not (the browser would log a refusal).
  const listenFor = EventTarget.prototype.addEventListener;
  window.addEventListener = function (type, ...rest) {
    if (type !== 'deviceorientation' && type !== 'devicemotion') listenFor.call(this, type, ...rest);
  };
  const listen = (event) => {
    const run = event.data;
    if (event.source !== parent || !run || run.type !== 'run') return;
    removeEventListener('message', listen);
    Object.defineProperty(window, 'localStorage', { value: memory(), configurable: true });
    Object.defineProperty(window, 'sessionStorage', { value: memory(), configurable: true });
    const blob = (code) => URL.createObjectURL(new Blob([code], { type: 'text/javascript' }));
    const runtime = blob(run.runtime);
    const imports = { p5: blob(`export { p5 as default } from ${JSON.stringify(runtime)};`) };
    for (const name of run.imports) imports[name] = runtime;
    imports['bunny/index.js?raw'] = blob(`export { bunnyFile as default } from ${JSON.stringify(runtime)};`);
    const map = document.createElement('script');
    map.type = 'importmap';
    map.textContent = JSON.stringify({ imports });
    document.head.append(map);
    // A module script of its own imports the runtime (an import() here would be rewritten by the dev server).
    const w = /** @type {any} */ (window);
    w.__sketchbookStart = (kit) => {
      kit.startFrame(run, tell);
      const script = document.createElement('script');
      script.type = 'module';
      script.textContent = `${run.code}\n//# sourceURL=${run.sourceURL}`;
      document.body.append(script);
    };
    const start = document.createElement('script');
    start.type = 'module';
    start.textContent = `import * as kit from ${JSON.stringify(runtime)};\nwindow.__sketchbookStart(kit);`;
    start.addEventListener('error', () => tell({ type: 'error', message: 'The kit did not load in the frame.', line: null, column: null }));
    document.head.append(start);
  };
  addEventListener('message', listen);
  setInterval(() => tell({ type: 'alive' }), 1000); // silent for long: a loop that never ends (SILENCE_MS)
  tell({ type: 'ready' }); // the page sends the run now: a load event may be the frame's first, empty document's
}

/** How long a frame may be silent before it is taken for stuck (ms): timers of a frame out of view run once a second. */
export const SILENCE_MS = 8_000;

/**
 * In the frame, the page's margins are the page's own, around the frame; the
 * page shows the tasks and the self-check outside it, so their empty place goes.
 */
const FRAME_CSS = 'body.in-frame { margin: 0; padding: 0.25rem 0 0; min-height: 0; }\nbody.in-frame .hw-panel:empty { display: none; }';

const escapeText = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

/**
 * The frame's document: `markup` (the sketch's `<main>`, from the page's own
 * HTML) and `css` (the page's own stylesheets), the base URL of the page.
 */
export function frameDocument({ base, title, css, markup, bodyClass }) {
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><base href="${escapeText(base)}">`
    + `<title>${escapeText(title)}</title><style>${css.replace(/<\//g, '<\\/')}\n${FRAME_CSS}</style>`
    + `<script>(${frameBootstrap})();</script></head><body class="${escapeText(bodyClass)} in-frame">${markup}</body></html>`;
}

export class SketchFrames {
  #box; #runtime; #page; #onMessage; #current = null; #pending = null; #title; #watch = 0;
  /** When each frame was last heard of (performance.now()). */
  #heardAt = new WeakMap();
  /** Each frame's run, sent once when its document says it is ready. */
  #runs = new WeakMap();

  /**
   * @param {object} options
   * @param {HTMLElement} options.box where the frames go
   * @param {() => Promise<string>} options.runtime the runtime's code (fetched once by the caller)
   * @param {{ base: string, title: string, css: () => string, markup: string, bodyClass: string, imports: string[], sourceURL: string }} options.page
   * @param {(message: object, current: boolean) => void} options.onMessage each checked message of a frame still on the page
   */
  constructor({ box, runtime, page, onMessage }) {
    this.#box = box;
    this.#runtime = runtime;
    this.#page = page;
    this.#onMessage = onMessage;
    this.#title = page.title;
    addEventListener('message', (event) => this.#heard(event));
  }

  /** Whether a frame is showing. */
  get showing() { return this.#current !== null; }

  /** Sends the frame on show a message of the page's (new values: frame-protocol.js); false when none is showing. */
  send(message) {
    const frame = this.#current;
    if (!frame?.contentWindow) return false;
    frame.contentWindow.postMessage(message, '*');
    return true;
  }

  /**
   * Runs `code` in a new frame, the pixel `selected` selected once it is set up.
   * @param {string} code
   * @param {{ x: number, y: number }|null} selected
   */
  async run(code, selected) {
    const runtime = await this.#runtime();
    this.#pending?.remove();
    const frame = document.createElement('iframe');
    frame.setAttribute('sandbox', 'allow-scripts allow-downloads');
    frame.title = this.#title;
    frame.className = 'code-frame';
    frame.dataset.codeFrame = 'starting';
    if (this.#current) frame.classList.add('code-frame-pending');
    if (this.#current) frame.setAttribute('aria-hidden', 'true');
    if (this.#current) frame.inert = true;
    frame.style.height = this.#current ? this.#current.style.height : '';
    const page = this.#page;
    frame.srcdoc = frameDocument({ base: page.base, title: page.title, css: page.css(), markup: page.markup, bodyClass: page.bodyClass });
    this.#runs.set(frame, { type: 'run', runtime, code, sourceURL: page.sourceURL, imports: page.imports, selected });
    this.#pending = frame;
    this.#heardAt.set(frame, performance.now());
    this.#watchForLoops();
    if (!this.#current) this.#showPending();
    else this.#box.append(frame);
  }

  /** The pending frame takes the current one's place. */
  #showPending() {
    const frame = this.#pending;
    this.#pending = null;
    frame.classList.remove('code-frame-pending');
    frame.removeAttribute('aria-hidden');
    frame.inert = false;
    frame.dataset.codeFrame = 'running';
    if (this.#current) this.#current.remove();
    if (!frame.isConnected) this.#box.append(frame);
    this.#current = frame;
  }

  /** Every second: a frame silent for SILENCE_MS is stopped. Not while the page is hidden or was itself held up. */
  #watchForLoops() {
    if (this.#watch) return;
    let last = performance.now();
    this.#watch = setInterval(() => {
      const now = performance.now();
      const excused = now - last > 2_000 || document.visibilityState !== 'visible';
      last = now;
      for (const frame of [this.#pending, this.#current]) {
        if (!frame) continue;
        if (excused) this.#heardAt.set(frame, now);
        else if (now - this.#heardAt.get(frame) > SILENCE_MS) {
          this.#stop();
          break;
        }
      }
    }, 1_000);
  }

  /**
   * Removes the frames: a loop ends only with its process, and Chromium runs
   * the new frame and the old one in one process (one thread), so a stuck new
   * frame holds up the old one, and would hold up the next run's too.
   */
  #stop() {
    const current = this.#pending === null;
    for (const frame of [this.#pending, this.#current]) frame?.remove();
    this.#pending = this.#current = null;
    this.#onMessage({ type: 'stuck', seconds: SILENCE_MS / 1000 }, current);
  }

  #heard(event) {
    const from = [this.#current, this.#pending].find((f) => f && f.contentWindow === event.source);
    if (!from || event.origin !== 'null') return; // only our frames, and only while sandboxed
    const message = readFrameMessage(event.data);
    if (!message) return;
    this.#heardAt.set(from, performance.now());
    if (message.type === 'alive') return;
    if (message.type === 'ready') {
      const run = this.#runs.get(from);
      this.#runs.delete(from);
      if (run) from.contentWindow.postMessage(run, '*');
      return;
    }
    if (message.type === 'size') {
      from.style.height = `${frameHeight(message.height, innerHeight)}px`;
      return;
    }
    if (from === this.#pending) {
      if (message.type === 'setup') this.#showPending();
      else if (message.type === 'error') { // it failed before its picture: the last good one stays
        from.remove();
        this.#pending = null;
        this.#onMessage(message, false);
        return;
      } else return;
    }
    this.#onMessage(message, true);
  }
}
