/**
 * The gallery's share of the lesson's tasks: each lesson card says how many
 * of its tasks this browser has done ("2 of 5", `[data-progress]`), and a
 * section under the cards lists the achievements, the progress code to give
 * the teacher (teacher.html reads it) and "Start again" for every page.
 */
import { LESSONS } from '../lib/lesson/tasks.js';
import { achievements, pageProgress, progressText, progressCode } from '../lib/lesson/progress.js';
import { loadProgress, saveProgress } from '../lib/p5/controls/progress-store.js';
import { element, copyText } from '../lib/p5/dom.js';

/** Adds the progress to the cards of `list` (links to sketches/NN-…) and the progress section after it. */
export function showProgress(list) {
  const counts = [];
  for (const link of list.querySelectorAll('a[href^="sketches/"]')) {
    const lesson = LESSONS.find((l) => link.getAttribute('href').startsWith(`sketches/${l.page}-`));
    if (!lesson) continue;
    const count = element('span', { 'data-progress': lesson.page });
    link.append(element('p', { class: 'card-progress' }, 'Tasks done: ', count));
    counts.push([lesson, count]);
  }

  const awards = element('ul', { class: 'achievements', 'data-achievements': '' });
  const code = element('code', { 'data-progress-code': '' });
  const status = element('span', { class: 'status', role: 'status' });
  const copy = (text, said) => async () => {
    status.textContent = (await copyText(text())) ? said : 'Select the code and press Ctrl+C (⌘C).';
  };
  const teacherLink = () => new URL(`teacher.html#code=${code.textContent}`, location.href).href;
  const again = button('Start again: every page', () => {
    saveProgress({});
    update();
    status.textContent = 'Started again: every task of every page is to do.';
  });
  const section = element('section', { class: 'progress', id: 'progress', 'aria-labelledby': 'progress-heading' },
    element('h2', { id: 'progress-heading' }, 'Your progress'),
    element('p', {}, 'Each lesson page has tasks that tick themselves off as you do them. This browser keeps what you did.'),
    awards,
    element('p', { class: 'code-row' }, 'Your progress code: ', code, ' ',
      button('Copy code', copy(() => code.textContent, 'Code copied: send it to your teacher.')),
      button('Copy link for the teacher', copy(teacherLink, 'Link copied: send it to your teacher.')), ' ', status),
    element('p', {}, again, ' Teachers: ', element('a', { href: './teacher.html' }, 'read your students\' progress codes'), '.'));
  list.after(section);

  function update() {
    const progress = loadProgress();
    for (const [lesson, count] of counts) count.textContent = progressText(pageProgress(progress, lesson));
    const earned = achievements(progress, LESSONS);
    awards.replaceChildren(...(earned.length ? earned.map((a) => element('li', { 'data-achievement': a.id }, `★ ${a.text}`))
      : [element('li', {}, 'No achievement yet: finish every task of a page for the first.')]));
    code.textContent = progressCode(progress, LESSONS);
  }
  update();
  window.addEventListener('pageshow', update); // back from a sketch: its tasks count now
}

function button(label, onClick) {
  const b = element('button', { type: 'button' }, label);
  b.addEventListener('click', onClick);
  return b;
}
