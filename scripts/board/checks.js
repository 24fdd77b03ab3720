/**
 * What a student's page sends to the class board, checked field by field
 * before anything is stored: every field known, every text capped, every
 * number in its range, the answer line read by the lesson's own reader
 * (lib/lesson/activity.js) and judged again on the server (./judge.js): the page's
 * verdict is kept only as what the page said.
 */
import { readAnswerLine, ANSWER_LINE_MAX } from '../../lib/lesson/activity.js';
import { LESSONS, lessonOf } from '../../lib/lesson/tasks.js';
import { judgeAnswer } from './judge.js';

/** A nickname's most characters (as the page's box allows). */
export const NICKNAME_MAX = 40;
/** The largest body a student's page sends, in bytes: a submission is about 300. */
export const BODY_MAX_BYTES = 4096;
/** The homework pages whose self-check the board counts. */
export const HOMEWORK_PAGES = ['08', '09'];
/** The lesson's poll: "Do you feel positive about math?" */
export const POLL = { question: 'Do you feel positive about math?', options: { 1: 'negative', 2: 'neutral', 3: 'positive' } };
/** The largest picture an answer may name (a side, in pixels). */
const SCREEN_SIDE_MAX = 4096;

/** A submission the board refuses: its message names the field. */
export class BadSubmission extends Error {}

const ID = /^[A-Za-z0-9_-]{1,64}$/;
const LAPTOP = /^[A-Za-z0-9_-]{8,64}$/;
// What a name may not hold: control characters, format characters (the marks that turn text around,
// invisible joiners but the two that emoji and some scripts need), line and paragraph separators, lone surrogates.
const UNSAFE = /[\p{Cc}\p{Zl}\p{Zp}\p{Cs}]|(?![\u200C\u200D])\p{Cf}/u;
// What shows nothing on the board: whitespace, default-ignorable characters (zero-width ones,
// the Hangul fillers U+3164, U+115F, U+1160, U+FFA0) and the blank braille pattern.
const INVISIBLE = /[\p{White_Space}\p{Default_Ignorable_Code_Point}\u2800]/gu;
const SEEN = /[\p{L}\p{N}\p{S}\p{P}]/u;
// Letters of other scripts drawn like the Latin ones of "student" (and a few more): a name's key reads them as Latin.
const LOOKALIKES = new Map(Object.entries({
  а: 'a', е: 'e', о: 'o', р: 'p', с: 'c', у: 'y', х: 'x', ѕ: 's', і: 'i', ј: 'j', ԁ: 'd', ո: 'n', ս: 'u',
  ο: 'o', ν: 'v', τ: 't', υ: 'u', ι: 'i', κ: 'k', ρ: 'p', ı: 'i',
}));
/** How the board names a student without a name (store.js nameOf): a name that reads the same is refused. */
const ANONYMOUS = /^student\p{Nd}+$/u;

const FIELDS = {
  hello: ['laptop', 'nickname'],
  answer: ['line', 'width', 'height', 'fov', 'verdict', 'color'],
  task: ['page', 'task'],
  check: ['page', 'passed', 'toFix'],
  poll: ['value'],
};
const COMMON = ['laptop', 'nickname', 'id', 'kind'];

/**
 * The submission as the store keeps it, or a BadSubmission naming the field.
 * @param {unknown} body the parsed JSON
 * @returns {object}
 */
export function checkSubmission(body) {
  const sent = plainObject(body, 'the submission');
  const kind = sent.kind;
  if (typeof kind !== 'string' || !Object.hasOwn(FIELDS, kind) || kind === 'hello') {
    throw new BadSubmission(`kind must be one of answer, task, check, poll, got ${shortly(kind)}`);
  }
  knownFields(sent, [...COMMON, ...FIELDS[kind]]);
  const who = checkHello({ laptop: sent.laptop, nickname: sent.nickname });
  if (typeof sent.id !== 'string' || !ID.test(sent.id)) throw new BadSubmission('id must be 1–64 letters, digits, - or _');
  return { ...who, id: sent.id, kind, ...PARTS[kind](sent) };
}

/** A laptop saying hello (its id and nickname): `{ laptop, nickname? }`. */
export function checkHello(body) {
  const sent = plainObject(body, 'the hello');
  knownFields(sent, FIELDS.hello);
  return { laptop: checkLaptop(sent.laptop), nickname: checkNickname(sent.nickname) };
}

/** A hello's laptop id, and its nickname as sent: checked apart (checkNickname), as a refused name does not refuse the hello. */
export function readHello(body) {
  const sent = plainObject(body, 'the hello');
  knownFields(sent, FIELDS.hello);
  return { laptop: checkLaptop(sent.laptop), nickname: sent.nickname };
}

/** A laptop's id: 8–64 letters, digits, - or _. */
export function checkLaptop(laptop) {
  if (typeof laptop !== 'string' || !LAPTOP.test(laptop)) throw new BadSubmission('laptop must be 8–64 letters, digits, - or _');
  return laptop;
}

/**
 * A nickname as the board shows it: NFC, trimmed, at most 40 characters;
 * undefined when none. Refused (the message names the field, `name`) when it
 * holds control, format or direction characters or lone surrogates, when
 * nothing of it shows once its invisible characters are removed, or when it
 * reads like another student's anonymous label ("student 3").
 * Whether another laptop has it is the store's to say (nameKey).
 */
export function checkNickname(nickname) {
  if (nickname === undefined || nickname === null) return undefined;
  if (typeof nickname !== 'string') throw new BadSubmission(`name must be text, got ${shortly(nickname)}`);
  if (!nickname.isWellFormed()) throw new BadSubmission('name must not hold lone surrogates (half of a character)');
  const name = nickname.normalize('NFC').replace(/^\p{White_Space}+|\p{White_Space}+$/gu, '');
  if (name === '') return undefined;
  if ([...name].length > NICKNAME_MAX) throw new BadSubmission(`name is too long: at most ${NICKNAME_MAX} characters`);
  if (!SEEN.test(name.replace(INVISIBLE, ''))) throw new BadSubmission('name is blank once its invisible characters are removed: type a name with letters or digits');
  const unsafe = UNSAFE.exec(name);
  if (unsafe) throw new BadSubmission(`name must not hold control, format or direction characters (it holds U+${unsafe[0].codePointAt(0).toString(16).toUpperCase().padStart(4, '0')})`);
  if (ANONYMOUS.test(nameKey(name).replace(/[\p{P}\p{S}]/gu, ''))) throw new BadSubmission('name reads like the board\'s label of a student without a name ("student 3"): choose another');
  return name;
}

/**
 * What two names that look the same have in common: compatibility forms
 * (NFKC: "ＡＮＮＡ" is "ANNA"), any letter case, no invisible characters nor
 * spaces, lookalike letters of other scripts read as Latin.
 * @param {string} name
 */
export function nameKey(name) {
  const folded = name.normalize('NFKC').replace(INVISIBLE, '').toUpperCase().toLowerCase().normalize('NFKC');
  return [...folded].map((c) => LOOKALIKES.get(c) ?? c).join('');
}

const PARTS = {
  answer(sent) {
    if (typeof sent.line !== 'string' || sent.line.length > ANSWER_LINE_MAX) throw new BadSubmission(`line must be text of at most ${ANSWER_LINE_MAX} characters`);
    const boxes = readAnswerLine(sent.line);
    if (!boxes) throw new BadSubmission('line must read like "Pixel: 10,12; H: 30; V: -82"');
    const width = wholeNumber(sent.width, 'width', 1, SCREEN_SIDE_MAX);
    const height = wholeNumber(sent.height, 'height', 1, SCREEN_SIDE_MAX);
    const fov = number(sent.fov, 'fov', 1, 179);
    const x = wholeNumber(Number(boxes.x), 'the pixel\'s x', 0, width - 1);
    const y = wholeNumber(Number(boxes.y), 'the pixel\'s y', 0, height - 1);
    const h = number(Number(boxes.h), 'H', -180, 180);
    const v = number(Number(boxes.v), 'V', -90, 90);
    if (sent.verdict !== undefined && sent.verdict !== 'right' && sent.verdict !== 'wrong') throw new BadSubmission('verdict must be "right" or "wrong"');
    if (sent.color !== undefined && !(typeof sent.color === 'string' && /^#[0-9a-f]{6}$/i.test(sent.color))) throw new BadSubmission('color must be like "#ff5160"');
    const judged = judgeAnswer({ x, y, h, v, width, height, fov });
    return { x, y, h, v, width, height, fov, line: judged.line, verdict: judged.verdict, color: judged.color, colorName: judged.colorName,
      pageSaid: sent.verdict === undefined ? null : `${sent.verdict}${sent.color ? ` ${sent.color}` : ''}` };
  },
  task(sent) {
    const lesson = typeof sent.page === 'string' ? lessonOf(sent.page) : undefined;
    if (!lesson) throw new BadSubmission(`page must be one of ${LESSONS.map((l) => l.page).join(', ')}`);
    if (typeof sent.task !== 'string' || !lesson.tasks.some((t) => t.id === sent.task)) throw new BadSubmission(`task must be one of page ${lesson.page}'s: ${lesson.tasks.map((t) => t.id).join(', ')}`);
    return { page: lesson.page, task: sent.task };
  },
  check(sent) {
    if (!HOMEWORK_PAGES.includes(/** @type {string} */ (sent.page))) throw new BadSubmission(`page must be ${HOMEWORK_PAGES.join(' or ')}`);
    if (typeof sent.passed !== 'boolean') throw new BadSubmission('passed must be true or false');
    return { page: sent.page, passed: sent.passed ? 1 : 0, toFix: wholeNumber(sent.toFix, 'toFix', 0, 100) };
  },
  poll(sent) {
    return { value: wholeNumber(sent.value, 'value', 1, 3) };
  },
};

function plainObject(body, what) {
  if (body === null || typeof body !== 'object' || Array.isArray(body)) throw new BadSubmission(`${what} must be a JSON object`);
  return /** @type {Record<string, unknown>} */ (body);
}

function knownFields(sent, known) {
  for (const key of Object.keys(sent)) {
    if (!known.includes(key)) throw new BadSubmission(`unknown field ${shortly(key)}`);
  }
}

function number(value, field, min, max) {
  if (typeof value !== 'number' || !Number.isFinite(value) || value < min || value > max) throw new BadSubmission(`${field} must be a number from ${min} to ${max}, got ${shortly(value)}`);
  return value;
}

function wholeNumber(value, field, min, max) {
  if (!Number.isInteger(value) || value < min || value > max) throw new BadSubmission(`${field} must be a whole number from ${min} to ${max}, got ${shortly(value)}`);
  return /** @type {number} */ (value);
}

/** A value echoed in a message: JSON, at most 40 characters. */
function shortly(value) {
  let text;
  try { text = JSON.stringify(value) ?? String(value); } catch { text = typeof value; }
  return text.length > 40 ? `${text.slice(0, 39)}…` : text;
}
