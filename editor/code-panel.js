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
 *
 * A number scrubbed in the editor (Alt+↑/↓, Alt+drag: number-scrub.js) that
 * is a field of the scene goes to the frame as a value, and the picture
 * follows without a new run (live-numbers.js); the page finds the number in
 * its own parse of the code, and nothing the frame says becomes code.
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
import { liveNumbers } from './live-numbers.js';

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
  const parts = panelParts(file);
  main.after(parts.area);
  /** The panel's state, shared by its parts below. */
  const page = {
    name, file, main, instances, parts,
    starter: null, editor: null, timer: 0, linkWaiting: false, selected: null, runs: 0, quiet: false, judge: null,
    say: (text) => { parts.status.textContent = text; },
  };
  const runtime = runtimeLoader([[parts.editorBox, 'focusin'], [parts.buttons.run, 'pointerenter'], [parts.buttons.run, 'focus']]);
  page.host = new SketchFrames({ box: parts.frames, runtime, page: framePage(file, markup), onMessage: (message, current) => heard(page, message, current) });
  page.live = liveNumbers(page.host);
  wireButtons(page);
  loadEditor(page);
  return { panel: parts.panel, heading: parts.heading };
}

/** The panel's elements: heading, hint, buttons, status, share box, editor box; the frames and the page's judge beside it. */
function panelParts(file) {
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
      'Edit the code here: when you stop typing it runs again (or press Run). Tab indents; to leave the editor press Esc, then Tab. '
      + 'With the caret in a number, Alt+↑ and Alt+↓ change it (Shift: ten steps), and the picture follows; Alt+drag on a number does too.'),
    element('div', { class: 'code-toolbar' }, buttons.run, buttons.download, buttons.reset, buttons.share),
    status, linkBox, editorBox);
  const frames = element('div', { class: 'code-frames', 'data-code-frames': '', hidden: '' });
  const judged = element('div', { class: 'code-judged', 'data-code-judged': '', hidden: '' }); // the page's tasks and self-check, once the code runs
  const area = element('div', { class: 'code-in-page' }, element('div', { class: 'code-picture' }, frames, judged), panel); // on a wide screen, once the code runs: the frame beside the editor
  return { help, file, status, buttons, linkBox, editorBox, heading, panel, frames, judged, area };
}

/**
 * p5 and the kit for the frame, fetched once (2 MB): when the student first
 * comes to the editor (one of `nearby`'s events), or at the first run.
 * @param {[EventTarget, string][]} nearby
 * @returns {() => Promise<string>}
 */
function runtimeLoader(nearby) {
  let runtime = null;
  const theRuntime = () => (runtime ??= fetch(new URL('../sketch-runtime.js', location.href), { cache: 'no-cache' }).then((r) => {
    if (!r.ok) throw new Error(`sketch-runtime.js: ${r.status}`);
    return r.text();
  }).catch((error) => { runtime = null; throw error; }));
  for (const [target, type] of nearby) target.addEventListener(type, () => theRuntime().catch(() => {}), { once: true });
  return theRuntime;
}

/** What the frame's document is made of: this page's address, styles, the sketch's markup, the kit's modules. */
function framePage(file, markup) {
  return {
    base: location.origin + location.pathname,
    title: 'Your sketch, running apart from this page',
    css: pageStyles,
    markup,
    bodyClass: document.body.className,
    imports: ['../lib/index.js', '../lib/p5/index.js'].map((path) => new URL(path, location.href).href),
    sourceURL: file,
  };
}

/** Runs the editor's code in a new frame (stopping the page's own sketch the first time). */
async function run(page) {
  if (!page.editor) return page.say('The code is still loading: press Run again in a moment.');
  clearTimeout(page.timer);
  page.linkWaiting = false;
  const code = page.editor.code();
  keepCode(page.name, code, page.starter);
  page.runs += 1;
  page.live.ran(code);
  clearMistakes();
  if (!page.host.showing) showFrames(page);
  document.body.dataset.render = 'rendering';
  page.say(`Running your code (run ${page.runs})…`);
  try {
    await page.host.run(code, page.selected);
  } catch (error) {
    page.say(`Your code could not run: the kit for the frame did not load (${error.message}). Reload the page to try again.`);
  }
}

/** The first run: the page's own sketch stops, its tasks go under the page's judge, the frames take its place. */
function showFrames(page) {
  const { parts, main } = page;
  page.selected ??= pageViews().find((v) => typeof v.select === 'function')?.selected ?? null;
  const lines = boardLines(); // what the page's own parts sent stays said, under the page's judge
  for (const p of [...page.instances]) p.remove();
  page.judge ??= openPageJudge({ page: page.name.slice(0, 2), box: parts.judged, lines });
  parts.judged.hidden = false;
  const was = parts.panel.getBoundingClientRect().top;
  main.hidden = true;
  main.style.display = 'none'; // its layout's own display would keep showing an empty box
  parts.frames.hidden = false;
  parts.area.classList.add('running');
  // The code stays where the student was looking, and on a wide screen the frame beside it is in view
  // (a frame out of view gets no rendering: no picture, no size).
  scrollBy(0, parts.panel.getBoundingClientRect().top - was);
}

/** The page's mistakes panel, its hint said for the editor (not "save"). */
function mistake(text, where = null) {
  showMistake(text, where)?.querySelector('.rt-error-hint')?.replaceChildren('Fix it in the editor: when your code runs again, the panel goes.');
}

/** A checked message of a frame still on the page (`current`: the one on show). */
function heard(page, message, current) {
  page.judge?.heard(message);
  switch (message.type) {
    case 'setup':
      page.live.setUp();
      page.say(`Your code ran (run ${page.runs}).`);
      break;
    case 'scene':
      if (page.live.scene(message)) changed(page, page.editor.code()); // a literal's fields are known: its latest value goes too
      break;
    case 'render': document.body.dataset.render = message.state; break;
    case 'select': page.selected = message.x === null ? null : { x: message.x, y: message.y }; break;
    case 'stuck': // the frames are gone (frame-host.js): the picture too
      page.live.gone();
      mistake(`Your code did not answer for ${message.seconds} s: is there a loop that never ends (while (true), a step that goes the wrong way)? It was stopped.`);
      page.say('Your code was stopped: fix the loop and it runs again.');
      document.body.dataset.render = 'error';
      break;
    case 'error': heardMistake(page, message, current); break;
  }
}

/** A mistake of the code, shown at the editor's line; one before the new picture leaves the last good one. */
function heardMistake(page, message, current) {
  const { editor, file } = page;
  const line = message.line === null ? undefined : editor.line(message.line);
  mistake(message.message, message.line === null ? null : {
    file: `${file} (the editor)`, line: message.line, column: message.column ?? 1, exact: message.exact, source: line ?? '',
    url: URL.createObjectURL(new Blob([editor.code()], { type: 'text/javascript' })),
  });
  if (!current) {
    page.live.failed();
    page.say(`Your code stopped at a mistake${message.line ? ` on line ${message.line}` : ''}: the picture is the last one that ran.`);
    if (document.body.dataset.render !== 'done') document.body.dataset.render = 'error';
  }
}

/**
 * The editor's text changed (by a scrub of a number, if `scrub`): a number of
 * the scene goes to the frame as a value; other changes run the code after a
 * pause in typing (a scrub's first step at once).
 */
function changed(page, code, scrub) {
  if (page.quiet || page.linkWaiting || scrub?.passing) return; // a link's code is not kept, nor run, until the student presses Run
  keepCode(page.name, code, page.starter);
  clearTimeout(page.timer);
  const next = page.live.changed(code, scrub);
  if (next.words) page.say(next.words);
  if (next.run === null && next.words) clearMistakes(); // a value went to the picture: an earlier value's mistake is past
  if (next.run === 'now') run(page);
  else if (next.run === 'later') page.timer = setTimeout(() => run(page), PAUSE_MS);
}

/** The code in the page's link, null when it has none or it cannot be read (then the status says why). */
async function codeFromLink(page) {
  const inLink = codeTextInLink(location.href);
  if (inLink === null) return null;
  try {
    return await decodeCodeLink(inLink);
  } catch (error) {
    page.say(`The code in this link cannot be read: ${error.message}. The editor has the code it had.`);
    return null;
  }
}

/** A link's code is in the editor: it is not kept, nor run, until the student presses Run. */
function waitForRun(page) {
  page.linkWaiting = true;
  page.say('This code came in a link: read it first, then press Run. It runs apart from this page and cannot read what the page keeps.');
}

/** The editor's text set by the page, not typed: not run again on a pause. */
function setQuietly(page, text) {
  page.quiet = true;
  try { page.editor.setCode(text); } finally { page.quiet = false; }
}

/** Run, Download, Reset to the starter, Copy share link. */
function wireButtons(page) {
  const { buttons } = page.parts;
  buttons.run.addEventListener('click', () => run(page));
  buttons.download.addEventListener('click', () => downloadText(page.editor.code(), page.file, 'text/javascript'));
  buttons.reset.addEventListener('click', () => {
    page.linkWaiting = false;
    setQuietly(page, page.starter); // one change: Ctrl+Z in the editor brings the student's code back
    run(page);
    page.say('Back to the starter (Ctrl+Z in the editor brings your code back).');
  });
  buttons.share.addEventListener('click', () => shareLink(page));
}

/** A link that carries the code: copied, or selected in its box when the browser does not let the page copy. */
async function shareLink(page) {
  const { linkBox } = page.parts;
  const link = await codeLinkURL(location.href, page.editor.code());
  linkBox.value = link;
  linkBox.hidden = false;
  const copied = await copyText(link);
  const long = link.length > CODE_LINK_WARN_LENGTH ? ` It is ${link.length.toLocaleString('en')} characters long: a chat may cut it.` : '';
  if (copied) page.say(`Link copied: whoever opens it sees your code and runs it with Run.${long}`);
  else {
    linkBox.select();
    page.say(`This browser did not let the page copy: the link is selected in the box, press Ctrl+C (⌘C on a Mac).${long}`);
  }
}

/** The sketch's file as the starter; the editor opens with the link's code, the student's kept code, or the starter. */
function loadEditor(page) {
  const { file, parts } = page;
  fetch(new URL(`../sketch-code/${file}`, location.href), { cache: 'no-cache' })
    .then((r) => (r.ok ? r.text() : Promise.reject(new Error(String(r.status)))))
    .then(async (text) => {
      page.starter = text;
      const fromLink = await codeFromLink(page);
      const own = keptCode(page.name);
      const code = fromLink ?? (own !== null && own !== text ? own : text);
      page.editor = createCodeEditor({ parent: parts.editorBox, code, label: `Code of the sketch, ${file}`, describedBy: parts.help,
        onChange: (changedCode, scrub) => changed(page, changedCode, scrub) });
      if (fromLink !== null) waitForRun(page);
      else if (code !== text) run(page); // the student's own code, kept from the last visit
      followTheFile(page);
      // A link pasted into this tab changes only the fragment: its code comes in as at a visit.
      addEventListener('hashchange', async () => {
        const linked = await codeFromLink(page);
        if (linked === null) return;
        clearTimeout(page.timer);
        setQuietly(page, linked);
        waitForRun(page);
      });
    }, () => page.say(`The code of ${file} could not be loaded here: open this page from the gallery on the server (npm start or npm run class).`));
}

/** On the teacher's dev server, a save of the sketch's file reaches the editor too, while its text is still the starter. */
function followTheFile(page) {
  import.meta.hot?.on('vite:afterUpdate', async (payload) => {
    if (!payload.updates.some((u) => u.path.endsWith(`/sketches/${page.file}`))) return;
    const text = await fetch(new URL(`../sketch-code/${page.file}`, location.href), { cache: 'no-cache' }).then((r) => r.text());
    const untouched = page.editor.code() === page.starter;
    page.starter = text;
    if (!untouched) return;
    setQuietly(page, text);
    if (page.host.showing) run(page);
  });
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
