/**
 * The lesson's poll (poll.html): "Do you feel positive about math?" Served
 * by `npm run class`, the answer goes to the teacher's class board, where
 * only the counts show; elsewhere it stays on the page.
 */
import { joinClassBoard, sendToClassBoard } from '../lib/p5/page/class-board.js';
import { useStyle } from '../lib/p5/dom.js';

const WORDS = { 1: 'negative', 2: 'neutral', 3: 'positive' };
const form = /** @type {HTMLFormElement} */ (document.querySelector('[data-poll-form]'));
const result = /** @type {HTMLElement} */ (document.querySelector('[data-poll-result]'));
const inClass = joinClassBoard() !== null;

useStyle();
/** @type {HTMLElement} */ (document.querySelector('[data-poll-where]')).textContent = inClass
  ? 'Your teacher sees how many chose each answer; you may change yours: the last one counts.'
  : 'This page is not connected to a class board (npm run class): your answer stays here, nothing is sent.';

form.addEventListener('submit', (event) => {
  event.preventDefault();
  const value = Number(new FormData(form).get('feeling'));
  if (!WORDS[value]) {
    result.textContent = 'Choose one of the three answers first.';
    return;
  }
  result.textContent = `Your answer: ${value} · ${WORDS[value]}.`;
  sendToClassBoard({ kind: 'poll', value }, form);
});
