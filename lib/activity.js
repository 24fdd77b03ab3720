/**
 * The class activity (slide "Activity", sketch 04): what pixel, horizontal
 * angle and vertical angle render a PINK pixel? Given the record of one pixel
 * (inspectPixel), the verdict says whether it is pink, and if not, what colour
 * it is and what its ray hit.
 */
import { colorName } from './color.js';

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

const NUMBER = String.raw`[+\-−]?(?:\d+(?:\.\d*)?|\.\d+)`;
const ANSWER_LINE = new RegExp(String.raw`^\s*pixel\s*:?\s*(${NUMBER})\s*,\s*(${NUMBER})\s*[;,]?\s*h\s*[:=]?\s*(${NUMBER})\s*°?\s*[;,]?\s*v\s*[:=]?\s*(${NUMBER})\s*°?\s*;?\s*$`, 'i');

/**
 * Reads an answer line (`Pixel: 10,12; H: 30; V: -82`, any case and spacing,
 * a typographic minus too) into the text of its four boxes, `{ x, y, h, v }`;
 * null when the text is not an answer line. The boxes check the values.
 * @param {string} text
 * @example
 * readAnswerLine('pixel 10, 12; h 30; v -82'); // { x: '10', y: '12', h: '30', v: '-82' }
 * readAnswerLine('pink!');                     // null
 */
export function readAnswerLine(text) {
  const m = ANSWER_LINE.exec(String(text ?? ''));
  if (!m) return null;
  const [x, y, h, v] = m.slice(1).map((s) => s.replace('−', '-'));
  return { x, y, h, v };
}
