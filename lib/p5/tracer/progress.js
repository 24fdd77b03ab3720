/**
 * What a tracer view says of its work under the picture: the progress bar
 * (percent done and rays per second) and the note shown when its Web Workers
 * failed. Both change only when their words do, so a frame that traced a few
 * more pixels touches nothing on the page.
 */
import { element } from '../dom.js';
import { formatRate } from '../../text/format.js';

/**
 * @returns {{ bar: HTMLElement, note: HTMLElement, show: (renderer: { done: boolean, progress: number, raysPerSecond: number, progressText?: string, problem?: ?string }) => void }}
 *   `bar` the progress bar (`[data-progress]`), `note` the workers' note (`[data-message="view-workers"]`),
 *   `show` brings both up to date with the renderer
 */
export function createTracerProgress() {
  const fill = element('div', { class: 'rt-progress-fill' });
  const text = element('span', { class: 'rt-progress-text', 'data-progress-text': '' });
  const bar = element('div', {
    class: 'rt-progress', 'data-progress': '', role: 'progressbar',
    'aria-valuemin': '0', 'aria-valuemax': '100', 'aria-label': 'Rendering progress',
  }, fill, text);
  const note = element('p', { class: 'rt-note rt-view-note', 'data-message': 'view-workers', role: 'status', hidden: true });
  let shownText = '';
  let shownProblem = null;

  return {
    bar, note,
    show(r) {
      const percent = r.done ? 100 : Math.min(99, Math.floor(r.progress * 100));
      // A path-traced view counts its samples instead ("Sample 37 of 256").
      const words = 'progressText' in r ? r.progressText : `${percent}% · ${formatRate(r.raysPerSecond)} rays/s`;
      if (words !== shownText) {
        shownText = words;
        fill.style.width = `${percent}%`;
        bar.setAttribute('aria-valuenow', String(percent));
        text.textContent = words;
      }
      const problem = r.problem ?? null;
      if (problem !== shownProblem) {
        shownProblem = problem;
        note.hidden = problem === null;
        note.textContent = problem === null ? '' : `Workers unavailable: rendering on the page's thread instead — ${problem}.`;
      }
    },
  };
}
