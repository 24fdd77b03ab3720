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
