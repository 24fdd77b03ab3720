/**
 * A student's page and the class board (`npm run class`): what the student
 * submits goes to the class server, which shows it on the teacher's board.
 *
 *   sketch 04's Check        an `rt-answer` event whose detail has `submitted` and `send` (lib/p5/controls/answer-form.js)
 *   a task done              an `rt-task` event (lib/p5/controls/task-list.js)
 *   a homework self-check    an `rt-check` event (lib/p5/controls/homework-check.js)
 *   the lesson's poll        sendToClassBoard({ kind: 'poll', value }) (site/poll.js)
 *
 * Only a page the class server served sends anything: it carries
 * `<meta name="rt-class-board" content="/class/">` (scripts/board/plugin.js).
 * The static site and `npm start` have no such tag: nothing is sent there,
 * and nothing of this module shows.
 *
 * Each submission goes into an outbox (localStorage) with an id of its own
 * and leaves it only when the server answered that it is stored; until then
 * it is sent again (after a pause, when the network is back, on the next
 * page), and the server stores an id once. The line beside what was sent
 * says where it is; once stored it has `data-received`.
 *
 * The first hello gives the laptop a secret, kept beside its id; every
 * request proves it (X-RT-Laptop-Secret). A page whose laptop the server does
 * not know (a new class, a lost secret) says hello again, and what waited in
 * its outbox goes after.
 */
import { element, useStyle } from '../dom.js';

const OUTBOX = 'rt-class-outbox';
const LAPTOP = 'rt-class-laptop';
const NICKNAME = 'rt-class-nickname';
const SECRET = 'rt-class-secret';
/** The most submissions kept waiting on one laptop (the oldest go first past it). */
const OUTBOX_MAX = 200;
const RETRY_MS = [1000, 2000, 5000, 10_000, 30_000];

/** Where this page sends (the class server's route), or null: not served by `npm run class`. */
export function classBoardRoute() {
  if (typeof document === 'undefined') return null;
  const meta = /** @type {HTMLMetaElement|null} */ (document.querySelector('meta[name="rt-class-board"]'));
  return meta?.content ? new URL(meta.content, location.href).href : null;
}

let joined = null;

/**
 * Joins the class board once per page (any number of calls): listens for
 * what the page's controls report, shows the student's name on the board
 * with a box to change it, and sends what an earlier page left in the
 * outbox. Does nothing on a page not served by the class server.
 * @returns {?{ send: (submission: object, near?: Element) => void }}
 */
export function joinClassBoard() {
  if (joined !== null) return joined || null;
  const route = classBoardRoute();
  if (!route) {
    joined = false;
    return null;
  }
  const outbox = new Outbox(route);
  const bar = nameBar(outbox);
  /** @param {string} type @param {(detail: any, target: Element) => void} handle */
  const on = (type, handle) => document.addEventListener(type, (event) => handle(/** @type {CustomEvent} */ (event).detail ?? {}, /** @type {Element} */ (event.target)));
  on('rt-answer', (detail, target) => {
    if (detail.submitted && detail.send) outbox.add({ kind: 'answer', ...detail.send }, target);
  });
  on('rt-task', (detail, target) => {
    for (const task of detail.tasks ?? []) outbox.add({ kind: 'task', page: detail.page, task }, target);
  });
  on('rt-check', (detail, target) => {
    const page = /\/(\d\d)-[^/]*$/.exec(location.pathname)?.[1];
    if (page) outbox.add({ kind: 'check', page, passed: Boolean(detail.passed), toFix: detail.toFix ?? 0 }, target);
  });
  addEventListener('online', () => outbox.flush());
  outbox.hello(bar);
  outbox.flush(); // after the hello is answered
  joined = { send: (submission, near) => outbox.add(submission, near) };
  return joined;
}

/** Sends a submission to the class board (when the page is served by it); `near`: where its line goes. */
export function sendToClassBoard(submission, near) {
  const board = joinClassBoard();
  board?.send(submission, near);
  return board !== null;
}

/** localStorage, or null where it is refused (a sandbox, privacy settings). */
function storage() {
  try { return globalThis.localStorage ?? null; } catch { return null; }
}

/** 32 random hex digits (crypto.randomUUID needs https; a class server is plain http). */
function randomId() {
  return [...crypto.getRandomValues(new Uint8Array(16))].map((b) => b.toString(16).padStart(2, '0')).join('');
}

/** This laptop's id, made once and kept. */
function laptopId() {
  const store = storage();
  let id = store ? store.getItem(LAPTOP) : remembered.laptop;
  if (!id || !/^[\w-]{8,64}$/.test(id)) {
    id = randomId();
    remembered.laptop = id;
    store?.setItem(LAPTOP, id);
  }
  return id;
}

const nickname = () => storage()?.getItem(NICKNAME) || undefined;

/** What the server knows this laptop by: its id and the secret it gave at hello (in memory too, where storage is refused). */
const remembered = { laptop: '', secret: '' };
function laptopSecret() {
  return storage()?.getItem(SECRET) ?? remembered.secret;
}
/** Keeps the id and secret a hello gave (a new laptop's, or another id when the server would not hand this one over). */
function keepLaptop(laptop, secret) {
  if (typeof laptop !== 'string' || !/^[\w-]{8,64}$/.test(laptop) || typeof secret !== 'string') return;
  remembered.laptop = laptop;
  remembered.secret = secret;
  storage()?.setItem(LAPTOP, laptop);
  storage()?.setItem(SECRET, secret);
}

/** A JSON POST to the class server, naming this laptop and proving it. */
function post(url, body) {
  const headers = { 'Content-Type': 'application/json', 'X-RT-Laptop': laptopId() };
  const secret = laptopSecret();
  if (secret) headers['X-RT-Laptop-Secret'] = secret;
  return fetch(url, { method: 'POST', headers, body: JSON.stringify(body) });
}

/** What waits to be sent, kept in localStorage; each item's line on the page, while the page is open. */
class Outbox {
  #route; #lines = new Map(); #timer = 0; #tries = 0; #sending = false; #bar = null; #helloedFor = new Set();
  /** The hello under way (or done): nothing is sent before it is answered. */
  #said = Promise.resolve();

  constructor(route) { this.#route = route; }

  #read() {
    try { return JSON.parse(storage()?.getItem(OUTBOX) ?? '[]'); } catch { return []; }
  }

  #write(items) {
    try { storage()?.setItem(OUTBOX, JSON.stringify(items.slice(-OUTBOX_MAX))); } catch { /* full: it is sent from memory this time */ }
  }

  /** Keeps a submission and sends it; its line goes at the end of `near`'s section. */
  add(submission, near) {
    const item = { id: randomId(), ...submission };
    this.#write([...this.#read(), item]);
    if (near) {
      const line = lineNear(near);
      line.dataset.item = item.id; // the line tells of the newest submission sent from there
      this.#lines.set(item.id, line);
    }
    this.#say(item.id, 'Sending to the class board…', 'sending');
    this.flush();
  }

  /** Sends what waits, oldest first, one at a time; stops at the first that cannot go now, and tries again later. */
  async flush() {
    if (this.#sending) return;
    this.#sending = true;
    clearTimeout(this.#timer);
    try {
      await this.#said;
      for (let item = this.#read()[0]; item; item = this.#read()[0]) {
        const wait = await this.#send(item);
        if (wait !== 0) {
          this.#timer = setTimeout(() => this.flush(), wait);
          return;
        }
      }
      this.#tries = 0;
    } finally {
      this.#sending = false;
    }
  }

  /** One item: 0 when it is done with (stored, or refused for good), else the pause before trying again (ms). */
  async #send(item) {
    let answer, body;
    try {
      answer = await post(new URL('send', this.#route), { ...item, laptop: laptopId() });
      body = await answer.json().catch(() => ({}));
    } catch {
      return this.#later('Not sent yet: the class server cannot be reached. It is kept, and sent when it can be.');
    }
    if (answer.ok) {
      this.#drop(item);
      this.#say(item.id, `✓ Received by the class board (as ${body.name}).`, 'received');
      return 0;
    }
    if (answer.status === 429) {
      const seconds = Number(body.retryAfter) || 5;
      this.#sayWaiting(`Not sent yet: too many sends from this laptop. The next goes in ${seconds} s.`);
      return seconds * 1000;
    }
    if (answer.status === 403 && body.hello && !this.#helloedFor.has(item.id)) {
      // The server does not know this laptop (a new class, a lost secret): hello again, then this item once more.
      this.#helloedFor.add(item.id);
      await this.hello();
      return 0;
    }
    if (answer.status >= 500 && answer.status !== 507) return this.#later(`Not sent yet: ${body.error ?? `the class server answered ${answer.status}`}. It is sent again soon.`);
    this.#drop(item); // refused for good: sending it again would be refused again
    this.#say(item.id, `Not received: ${body.error ?? `the class server answered ${answer.status}`}.`, 'refused');
    return 0;
  }

  #later(message) {
    this.#sayWaiting(message);
    return RETRY_MS[Math.min(this.#tries++, RETRY_MS.length - 1)];
  }

  #drop(item) { this.#write(this.#read().filter((i) => i.id !== item.id)); }

  /** The line of item `id` (if it was sent from this page): its words and state; `data-received` once stored. */
  #say(id, text, state) {
    const line = this.#lines.get(id);
    if (!line || line.dataset.item !== id) return;
    line.dataset.classSent = state;
    line.toggleAttribute('data-received', state === 'received');
    line.textContent = text;
  }

  /** Every line whose submission still waits (behind the one refused for now, they wait too): why. */
  #sayWaiting(text) {
    for (const { id } of this.#read()) this.#say(id, text, 'waiting');
  }

  /**
   * Says hello to the board, with the name to take (else the one kept): the
   * bar shows the name the teacher sees, or why the name was refused (the
   * old name stays).
   * @param {?{ show: (name: ?string, trouble?: string, refused?: boolean) => void }} [bar]
   * @param {string} [name]
   */
  hello(bar = this.#bar, name = nickname()) {
    this.#bar = bar;
    this.#said = this.#hello(name);
    return this.#said;
  }

  async #hello(name) {
    let answer, body;
    try {
      answer = await post(new URL('hello', this.#route), { laptop: laptopId(), nickname: name });
      body = await answer.json();
    } catch {
      return this.#bar?.show(null, 'the class server cannot be reached now; what you do is kept and sent when it can be');
    }
    keepLaptop(body.laptop, body.secret);
    if (answer.ok) {
      if (name) storage()?.setItem(NICKNAME, name);
      return this.#bar?.show(body.name, '');
    }
    this.#bar?.show(body.name ?? null, body.field === 'name' ? `Not saved: ${body.error}` : (body.error ?? `the class server answered ${answer.status}`), body.field === 'name');
  }
}

/** The status line of the section (or box) an event came from, made at its end the first time. */
function lineNear(target) {
  const host = target.closest('section, .rt-check, form') ?? target;
  let line = /** @type {HTMLElement|null} */ (host.querySelector(':scope > [data-class-sent]'));
  if (!line) {
    line = element('p', { class: 'rt-class-sent', role: 'status', 'data-class-sent': '' });
    host.append(line);
  }
  return line;
}

/** The strip under the page's header: the student's name on the board, and a box to choose it. */
function nameBar(outbox) {
  useStyle();
  const shown = element('b', { 'data-class-name': '' }, '…');
  const input = element('input', { type: 'text', id: 'rt-class-nickname', maxlength: '40', autocomplete: 'nickname', value: nickname() ?? '', 'aria-describedby': 'rt-class-problem' });
  // The server's word on the name, next to the box: read out when it comes.
  const problem = element('span', { class: 'rt-class-problem', id: 'rt-class-problem', role: 'alert', 'data-class-problem': '' });
  const form = element('form', { class: 'rt-class-name' },
    element('label', { for: 'rt-class-nickname' }, 'Your name on the board'), input,
    element('button', { type: 'submit', class: 'rt-button' }, 'Save name'), problem);
  const poll = /\/poll\.html$/.test(location.pathname) ? null : element('a', { href: new URL('/poll.html', location.href).href }, 'The lesson\'s poll');
  const bar = element('aside', { class: 'rt-class-bar', 'aria-label': 'Class board', 'data-class-bar': '' },
    element('span', {}, 'Class board: the teacher sees you as ', shown, '.'), form, poll);
  form.addEventListener('submit', (event) => {
    event.preventDefault();
    const name = input.value.trim().slice(0, 40);
    if (!name) storage()?.removeItem(NICKNAME);
    outbox.hello(api, name || undefined);
  });
  const header = document.querySelector('body > header');
  if (header) header.after(bar);
  else document.body.prepend(bar);
  const api = {
    show(name, trouble, refused = false) {
      if (name) shown.textContent = name;
      problem.textContent = trouble ? (refused ? trouble : `(${trouble})`) : '';
      input.setAttribute('aria-invalid', String(refused));
    },
  };
  return api;
}
