// The class activity's verdict on one pixel: pink, or its colour and what its ray hit.
import { describe, it, expect } from 'vitest';
import { Camera, classScene, inspectPixel, pinkPixelVerdict } from '../../lib/index.js';

const camera = new Camera({ width: 32, height: 24, fov: 30 }); // sketch 04's screen
const verdictAt = (x, y) => pinkPixelVerdict(inspectPixel(classScene(), camera, x, y));
const record = (color, name) => ({ x: 3, y: 4, color, hit: name === undefined ? null : { object: { name } } });

describe('pinkPixelVerdict', () => {
  it('says pink for a lit pixel of the pink sphere', () => {
    expect(verdictAt(16, 12)).toEqual({ pink: true, colorName: 'pink', message: 'Pink! Pixel 16,12 shows the pink sphere.' });
  });

  it('names the colour and what the ray hit: a sphere, the ground, nothing', () => {
    const yellow = verdictAt(27, 16);
    expect(yellow).toMatchObject({ pink: false });
    expect(yellow.message).toBe(`That pixel is ${yellow.colorName}: the yellow sphere.`);
    expect(verdictAt(16, 23).message).toMatch(/^That pixel is \w+: the ground\.$/);
    expect(verdictAt(0, 0).message).toMatch(/^That pixel is \w+: the ray hits nothing, so it gets the background\.$/);
  });

  it('tells a dark pixel of the pink sphere from a miss, and names a light as a light', () => {
    expect(pinkPixelVerdict(record([90, 20, 25], 'pink')).message).toMatch(/^That pixel is \w+: it is on the pink sphere, but too dark there to look pink\.$/);
    expect(pinkPixelVerdict(record([255, 255, 255], 'light 1')).message).toBe('That pixel is white: light 1, a light.');
  });
});
