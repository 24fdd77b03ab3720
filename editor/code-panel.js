/**
 * The editor of a page's sketch (opened by code-in-page.js): the sketch's own
 * file in a CodeMirror editor beside its picture. Run, or a pause in typing,
 * runs the edited code in a sandboxed frame (frame-host.js) that takes the
 * picture's place; the student's code is kept in this browser, per sketch;
 * Download, Reset to the starter and a share link that carries the code
 * (code-link.js).
 *
 * Code that came in a link waits for the student's Run, and runs only in
 * the frame, which cannot read this page, its storage or the class's board.
 * From the first run the page's tasks and self-check are the page's own,
 * under the frame (page-judge.js): judged from what the code built, kept
 * through every run, sent to the class's board from the page.
 * The sketch's own script still runs in the page at first, as the teacher's
 * file: a save of the file swaps it in place, as on every page, and sets the
 * editor's text too while the student has not changed it.
 */
import { showMistake, clearMistakes } from '../lib/p5/page/error-panel.js';
import { pageViews } from '../lib/p5/page/page-state.js';
import { element, copyText } from '../lib/p5/dom.js';
import { downloadText } from '../lib/p5/controls/text-box.js';
import { createCodeEditor } from './code-editor.js';
import './code-in-page.css';
import { SketchFrames } from './frame-host.js';
import { openPageJudge, boardLines } from './page-judge.js';
import { codeTextInLink, decodeCodeLink, codeLinkURL, CODE_LINK_WARN_LENGTH } from './code-link.js';
import { keptCode, keepCode } from './kept-code.js';

/** The pause in typing after which the code runs again, as a save would (ms). */
export const PAUSE_MS = 800;

/**
 * Opens the editor under the page's sketch.
 * @param {object} options
 * @param {string} options.name the sketch's name, `NN-name`
 * @param {HTMLElement} options.main the sketch's `<main>`
 * @param {string} options.markup its HTML before the sketch filled it (the frame's page)
 * @param {Set<any>} options.instances the page's own p5 instances, stopped when the editor's code first runs
 * @returns {{ panel: HTMLElement, heading: HTMLElement }}
 */
export function openCodePanel({ name, main, markup, instances }) {
  const file = `${name}.js`;
  const help = 'code-help';
  const status = element('p', { class: 'code-status', role: 'status', 'data-code-status': '' });
  const buttons = {
    run: element('button', { type: 'button', class: 'rt-button', 'data-code-run': '' }, 'Run'),
    download: element('button', { type: 'button', class: 'rt-button' }, 'Download'),
    reset: element('button', { type: 'button', class: 'rt-button' }, 'Reset to the starter'),
    share: element('button', { type: 'button', class: 'rt-button' }, 'Copy share link'),
  };
  const linkBox = element('input', { type: 'text', readonly: '', class: 'code-link', 'aria-label': 'Share link', hidden: '' });
  const editorBox = element('div', { class: 'code-editor-box' });
  const heading = element('h2', { id: 'code-title', tabindex: '-1' }, 'The sketch\'s code');
  const panel = element('section', { class: 'card code-panel', 'data-code-panel': '', 'aria-labelledby': 'code-title' },
    heading,
    element('p', { id: help, class: 'code-help' },
      'Edit the code here: when you stop typing it runs again (or press Run). Tab indents; to leave the editor press Esc, then Tab.'),
    element('div', { class: 'code-toolbar' }, buttons.run, buttons.download, buttons.reset, buttons.share),
    status, linkBox, editorBox);
  const frames = element('div', { class: 'code-frames', 'data-code-frames': '', hidden: '' });
  const judged = element('div', { class: 'code-judged', 'data-code-judged': '', hidden: '' }); // the page's tasks and self-check, once the code runs
  const area = element('div', { class: 'code-in-page' }, element('div', { class: 'code-picture' }, frames, judged), panel); // on a wide screen, once the code runs: the frame beside the editor
  main.after(area);

  let starter = null, editor = null, timer = 0, linkWaiting = false, selected = null, runs = 0, quiet = false, judge = null;
  const say = (text) => { status.textContent = text; };
  const keep = (code) => keepCode(name, code, starter);

  let runtime = null;
  /** p5 and the kit for the frame, fetched once (2 MB: when the student first comes to the editor, or at the first run). */
  const theRuntime = () => (runtime ??= fetch(new URL('../sketch-runtime.js', location.href), { cache: 'no-cache' }).then((r) => {
    if (!r.ok) throw new Error(`sketch-runtime.js: ${r.status}`);
    return r.text();
  }).catch((error) => { runtime = null; throw error; }));
  for (const [target, type] of [[editorBox, 'focusin'], [buttons.run, 'pointerenter'], [buttons.run, 'focus']]) {
    target.addEventListener(type, () => theRuntime().catch(() => {}), { once: true });
  }
  const host = new SketchFrames({
    box: frames,
    runtime: theRuntime,
    page: {
      base: location.origin + location.pathname,
      title: 'Your sketch, running apart from this page',
      css: pageStyles,
      markup,
      bodyClass: document.body.className,
      imports: ['../lib/index.js', '../lib/p5/index.js'].map((path) => new URL(path, location.href).href),
      sourceURL: file,
    },
    onMessage: heard,
  });

  /** Runs the editor's code in a new frame (stopping the page's own sketch the first time). */
  async function run() {
    clearTimeout(timer);
    linkWaiting = false;
    const code = editor.code();
    keep(code);
    runs += 1;
    clearMistakes();
    if (!host.showing) {
      selected ??= pageViews().find((v) => typeof v.select === 'function')?.selected ?? null;
      const lines = boardLines(); // what the page's own parts sent stays said, under the page's judge
      for (const p of [...instances]) p.remove();
      judge ??= openPageJudge({ page: name.slice(0, 2), box: judged, lines });
      judged.hidden = false;
      const was = panel.getBoundingClientRect().top;
      main.hidden = true;
      main.style.display = 'none'; // its layout's own display would keep showing an empty box
      frames.hidden = false;
      area.classList.add('running');
      // The code stays where the student was looking, and on a wide screen the frame beside it is in view
      // (a frame out of view gets no rendering: no picture, no size).
      scrollBy(0, panel.getBoundingClientRect().top - was);
    }
    document.body.dataset.render = 'rendering';
    say(`Running your code (run ${runs})…`);
    try {
      await host.run(code, selected);
    } catch (error) {
      say(`Your code could not run: the kit for the frame did not load (${error.message}). Reload the page to try again.`);
    }
  }

  /** The page's mistakes panel, its hint said for the editor (not "save"). */
  function mistake(text, where = null) {
    showMistake(text, where)?.querySelector('.rt-error-hint')?.replaceChildren('Fix it in the editor: when your code runs again, the panel goes.');
  }

  function heard(message, current) {
    judge?.heard(message);
    switch (message.type) {
      case 'setup': say(`Your code ran (run ${runs}).`); break;
      case 'render': document.body.dataset.render = message.state; break;
      case 'select': selected = message.x === null ? null : { x: message.x, y: message.y }; break;
      case 'stuck': // the frames are gone (frame-host.js): the picture too
        mistake(`Your code did not answer for ${message.seconds} s: is there a loop that never ends (while (true), a step that goes the wrong way)? It was stopped.`);
        say('Your code was stopped: fix the loop and it runs again.');
        document.body.dataset.render = 'error';
        break;
      case 'error': {
        const line = message.line === null ? undefined : editor.line(message.line);
        mistake(message.message, message.line === null ? null : {
          file: `${file} (the editor)`, line: message.line, column: message.column ?? 1, exact: message.exact, source: line ?? '',
          url: URL.createObjectURL(new Blob([editor.code()], { type: 'text/javascript' })),
        });
        if (!current) {
          say(`Your code stopped at a mistake${message.line ? ` on line ${message.line}` : ''}: the picture is the last one that ran.`);
          if (document.body.dataset.render !== 'done') document.body.dataset.render = 'error';
        }
        break;
      }
    }
  }

  const changed = (code) => {
    if (quiet || linkWaiting) return; // a link's code is not kept, nor run, until the student presses Run
    keep(code);
    clearTimeout(timer);
    timer = setTimeout(run, PAUSE_MS);
  };

  /** The code in the page's link, null when it has none or it cannot be read (then the status says why). */
  async function codeFromLink() {
    const inLink = codeTextInLink(location.href);
    if (inLink === null) return null;
    try {
      return await decodeCodeLink(inLink);
    } catch (error) {
      say(`The code in this link cannot be read: ${error.message}. The editor has the code it had.`);
      return null;
    }
  }

  /** A link's code is in the editor: it is not kept, nor run, until the student presses Run. */
  function waitForRun() {
    linkWaiting = true;
    say('This code came in a link: read it first, then press Run. It runs apart from this page and cannot read what the page keeps.');
  }

  /** The editor's text set by the page, not typed: not run again on a pause. */
  const setQuietly = (text) => {
    quiet = true;
    try { editor.setCode(text); } finally { quiet = false; }
  };

  buttons.run.addEventListener('click', () => run());
  buttons.download.addEventListener('click', () => downloadText(editor.code(), file, 'text/javascript'));
  buttons.reset.addEventListener('click', () => {
    linkWaiting = false;
    setQuietly(starter); // one change: Ctrl+Z in the editor brings the student's code back
    run();
    say('Back to the starter (Ctrl+Z in the editor brings your code back).');
  });
  buttons.share.addEventListener('click', async () => {
    const link = await codeLinkURL(location.href, editor.code());
    linkBox.value = link;
    linkBox.hidden = false;
    const copied = await copyText(link);
    const long = link.length > CODE_LINK_WARN_LENGTH ? ` It is ${link.length.toLocaleString('en')} characters long: a chat may cut it.` : '';
    if (copied) say(`Link copied: whoever opens it sees your code and runs it with Run.${long}`);
    else {
      linkBox.select();
      say(`This browser did not let the page copy: the link is selected in the box, press Ctrl+C (⌘C on a Mac).${long}`);
    }
  });

  fetch(new URL(`../sketch-code/${file}`, location.href), { cache: 'no-cache' })
    .then((r) => (r.ok ? r.text() : Promise.reject(new Error(String(r.status)))))
    .then(async (text) => {
      starter = text;
      const fromLink = await codeFromLink();
      const own = keptCode(name);
      const code = fromLink ?? (own !== null && own !== starter ? own : starter);
      editor = createCodeEditor({ parent: editorBox, code, label: `Code of the sketch, ${file}`, describedBy: help, onChange: changed });
      if (fromLink !== null) waitForRun();
      else if (code !== starter) run(); // the student's own code, kept from the last visit
      followTheFile();
      // A link pasted into this tab changes only the fragment: its code comes in as at a visit.
      addEventListener('hashchange', async () => {
        const code = await codeFromLink();
        if (code === null) return;
        clearTimeout(timer);
        setQuietly(code);
        waitForRun();
      });
    }, () => say(`The code of ${file} could not be loaded here: open this page from the gallery on the server (npm start or npm run class).`));
  return { panel, heading };

  /** On the teacher's dev server, a save of the sketch's file reaches the editor too, while its text is still the starter. */
  function followTheFile() {
    import.meta.hot?.on('vite:afterUpdate', async (payload) => {
      if (!payload.updates.some((u) => u.path.endsWith(`/sketches/${file}`))) return;
      const text = await fetch(new URL(`../sketch-code/${file}`, location.href), { cache: 'no-cache' }).then((r) => r.text());
      const untouched = editor.code() === starter;
      starter = text;
      if (!untouched) return;
      setQuietly(text);
      if (host.showing) run();
    });
  }
}

/**
 * The page's own stylesheets (sketch.css, homework.css, the page's `<style>`), as text for the frame;
 * not the kit's (the frame's runtime brings it) nor those the dev server adds for modules.
 */
function pageStyles() {
  const own = (node) => (node instanceof HTMLLinkElement && !node.hasAttribute('data-sketchbook'))
    || (node instanceof HTMLStyleElement && !node.hasAttribute('data-vite-dev-id'));
  const sheets = [...document.styleSheets].filter((s) => own(s.ownerNode));
  return sheets.map((sheet) => {
    try { return [...sheet.cssRules].map((rule) => rule.cssText).join('\n'); } catch { return ''; }
  }).join('\n');
}
