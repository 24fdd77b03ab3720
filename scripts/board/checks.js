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
// Control characters, and the marks that reverse text around them (a name cannot turn the board's lines around).
const UNSAFE = /[\p{Cc}\u202A-\u202E\u2066-\u2069\u2028\u2029]/u;

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
  if (typeof sent.laptop !== 'string' || !LAPTOP.test(sent.laptop)) throw new BadSubmission('laptop must be 8–64 letters, digits, - or _');
  return { laptop: sent.laptop, nickname: checkNickname(sent.nickname) };
}

/** A nickname: text of 1–40 characters, no control characters; undefined when none. */
export function checkNickname(nickname) {
  if (nickname === undefined || nickname === null) return undefined;
  if (typeof nickname !== 'string') throw new BadSubmission(`nickname must be text, got ${shortly(nickname)}`);
  const name = nickname.trim();
  if ([...name].length > NICKNAME_MAX) throw new BadSubmission(`nickname is too long: at most ${NICKNAME_MAX} characters`);
  if (UNSAFE.test(name)) throw new BadSubmission('nickname must not hold control characters');
  return name === '' ? undefined : name;
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
