/**
 * The class activity (slide "Activity", sketch 04): what pixel, horizontal
 * angle and vertical angle render a PINK pixel? Given the record of one pixel
 * (inspectPixel), the verdict says whether it is pink, and if not, what colour
 * it is and what its ray hit.
 */
import { colorName } from '../math/color.js';

/**
 * Is this pixel pink? If not: its colour, and what its ray hit.
 * @param {{ x: number, y: number, color: number[], hit: ?{ object: { name?: string } } }} record from inspectPixel
 * @returns {{ pink: boolean, colorName: string, message: string }}
 * @example
 * const camera = new Camera({ width: 64, height: 48 });
 * pinkPixelVerdict(inspectPixel(classScene(), camera, 10, 12)).message; // 'That pixel is white: the white sphere.'
 */
export function pinkPixelVerdict({ x, y, color, hit }) {
  const name = colorName(color);
  const object = hit?.object.name;
  const message = name === 'pink' ? `Pink! Pixel ${x},${y} shows the pink sphere.`
    : object === 'pink' ? `That pixel is ${name}: it is on the pink sphere, but too dark there to look pink.`
      : `That pixel is ${name}: ${object ? whatIs(object) : 'the ray hits nothing, so it gets the background'}.`;
  return { pink: name === 'pink', colorName: name, message };
}

/** What the ray hit, by the object's name: the ground, a light, or a coloured sphere. */
const whatIs = (name) => (name === 'ground' ? 'the ground' : name.startsWith('light') ? `${name}, a light` : `the ${name} sphere`);

/**
 * The slide's answer format with the values the student gave (the pixel and
 * the camera's H and V): `Pixel: 10,12; H: 30; V: -82`.
 * @param {{ x: number, y: number, h: number, v: number }} answer
 * @example
 * answerText({ x: 10, y: 12, h: 30, v: -82 }); // 'Pixel: 10,12; H: 30; V: -82'
 */
export function answerText({ x, y, h, v }) {
  return `Pixel: ${x},${y}; H: ${plain(h)}; V: ${plain(v)}`;
}

/** A number as typed: 30, -82, 7.5 (never "-0"). */
const plain = (n) => String(n === 0 ? 0 : n);

/** The longest answer line read (after trimming): the slide's line is ~30 characters. */
export const ANSWER_LINE_MAX = 200;

/**
 * One token at a time, from where the last one ended (sticky): a word, a
 * number or a separator after optional spaces. Each alternative starts with a
 * different kind of character and nothing repeats inside a repeat, so reading
 * a line takes time in proportion to its length, however it is spaced.
 */
const TOKEN = /\s*(?:([a-z]+)|([+\-−]?(?:\d+(?:\.\d*)?|\.\d+))|([:;,=°]))/iy;

/**
 * The answer line's shape, token by token: a word (lower case), '#' for a
 * number, a separator; `?` after a separator makes it optional.
 */
const SHAPE = ['pixel', ':?', '#', ',', '#', ';,?', 'h', ':=?', '#', '°?', ';,?', 'v', ':=?', '#', '°?', ';?'];

/**
 * Reads an answer line (`Pixel: 10,12; H: 30; V: -82`, any case and spacing,
 * a typographic minus too) into the text of its four boxes, `{ x, y, h, v }`;
 * null when the text is not an answer line, or is longer than ANSWER_LINE_MAX
 * (then it is an ordinary paste, and the box it lands in says what is wrong).
 * The boxes check the values.
 * @param {string} text
 * @example
 * readAnswerLine('pixel 10, 12; h 30; v -82'); // { x: '10', y: '12', h: '30', v: '-82' }
 * readAnswerLine('pink!');                     // null
 */
export function readAnswerLine(text) {
  const line = String(text ?? '').trim();
  return line.length > ANSWER_LINE_MAX ? null : answerLineBoxes(line);
}

/**
 * readAnswerLine without the length cap (exported for the test that times it
 * on long lines): the boxes' texts, or null.
 * @param {string} line trimmed
 */
export function answerLineBoxes(line) {
  const tokens = tokenize(line);
  if (!tokens) return null;
  const numbers = [];
  let i = 0;
  for (const want of SHAPE) {
    const token = tokens[i];
    const optional = want.length > 1 && want.endsWith('?');
    const matches = want === '#' ? token?.number !== undefined
      : optional ? token?.mark !== undefined && want.slice(0, -1).includes(token.mark)
        : token !== undefined && (token.word === want || token.mark === want);
    if (matches) {
      if (want === '#') numbers.push(token.number.replace('−', '-'));
      i++;
    } else if (!optional) return null;
  }
  if (i !== tokens.length) return null;
  const [x, y, h, v] = numbers;
  return { x, y, h, v };
}

/**
 * The line's tokens, `{ word }`, `{ number }` or `{ mark }`; null at a
 * character that starts none, or past the most an answer line has.
 */
function tokenize(line) {
  const tokens = [];
  TOKEN.lastIndex = 0;
  while (TOKEN.lastIndex < line.length) {
    if (tokens.length === SHAPE.length) return null;
    const m = TOKEN.exec(line);
    if (!m) return null;
    tokens.push(m[1] !== undefined ? { word: m[1].toLowerCase() } : m[2] !== undefined ? { number: m[2] } : { mark: m[3] });
  }
  return tokens;
}
