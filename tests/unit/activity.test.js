// The class activity's verdict on one pixel: pink, or its colour and what its ray hit.
import { describe, it, expect } from 'vitest';
import { Camera, classScene, inspectPixel } from '../../lib/index.js';
import { pinkPixelVerdict, answerText, readAnswerLine } from '../../lib/lesson/activity.js';

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

describe('the answer line', () => {
  it('repeats the values given, in the slide\'s format', () => {
    expect(answerText({ x: 10, y: 12, h: 30, v: -82 })).toBe('Pixel: 10,12; H: 30; V: -82');
    expect(answerText({ x: 0, y: 3, h: -0, v: 7.5 })).toBe('Pixel: 0,3; H: 0; V: 7.5');
  });

  it('reads an answer line back into the four boxes, whatever the spacing and minus sign', () => {
    expect(readAnswerLine('Pixel: 10,12; H: 30; V: -82')).toEqual({ x: '10', y: '12', h: '30', v: '-82' });
    expect(readAnswerLine('  pixel 3 , 4 ;h:-1.9;v: 3.2 ')).toEqual({ x: '3', y: '4', h: '-1.9', v: '3.2' });
    expect(readAnswerLine('Pixel: 14,9; H: −1.9°; V: 3.2°')).toEqual({ x: '14', y: '9', h: '-1.9', v: '3.2' });
  });

  it('round-trips: what answerText writes, readAnswerLine reads', () => {
    const answer = { x: 31, y: 0, h: -179.5, v: 90 };
    expect(Object.values(readAnswerLine(answerText(answer))).map(Number)).toEqual(Object.values(answer));
  });

  it('is null for text that is not a whole answer line', () => {
    for (const text of ['10', 'Pixel: 10,12', 'Pixel: 10,12; H: 30', 'H: 30; V: -82', 'Pixel: a,b; H: 1; V: 2', '', undefined]) {
      expect(readAnswerLine(text), String(text)).toBeNull();
    }
  });
});

describe('readAnswerLine on long pasted text', () => {
  it('reads a line in time proportional to its length, whatever its spacing', async () => {
    const { answerLineBoxes } = await import('../../lib/lesson/activity.js');
    const { timeRatio } = await import('./linear-time.js');
    const spaces = timeRatio(answerLineBoxes, (n) => `pixel 1,1 h 1 v 1${' '.repeat(n)}x`);
    const pad = (n) => ' '.repeat(n / 4);
    const tokens = timeRatio(answerLineBoxes, (n) => `pixel${pad(n)}1,${pad(n)}2 h${pad(n)}3 v${pad(n)}4 x`);
    expect(spaces).toBeLessThan(400); // the old regular expression: cubic, 26 s on 1,600 spaces
    expect(tokens).toBeLessThan(400);
  });

  it('still reads a line with long runs of spaces up to the cap, and is null past it (an ordinary paste)', async () => {
    const { ANSWER_LINE_MAX } = await import('../../lib/lesson/activity.js');
    const wide = `pixel 1,2${' '.repeat(150)}h 3 v 4`;
    expect(wide.length).toBeLessThanOrEqual(ANSWER_LINE_MAX);
    expect(readAnswerLine(wide)).toEqual({ x: '1', y: '2', h: '3', v: '4' });
    expect(readAnswerLine(`   ${wide}   `)).toEqual({ x: '1', y: '2', h: '3', v: '4' }); // trimmed first
    expect(readAnswerLine(`pixel 1,2${' '.repeat(ANSWER_LINE_MAX)}h 3 v 4`)).toBeNull();
    expect(readAnswerLine(`pixel 1,1 h 1 v 1${' '.repeat(1e5)}x`)).toBeNull();
  });

  it('is null for near misses the tokens allow but the line does not', () => {
    for (const text of ['pixels 1,2; h 3; v 4', 'pixel 1,2; h 3; v 4; v 5', 'pixel 1,2,3; h 3; v 4', 'pixel 1,2; h - 3; v 4', 'pixel 1,2; h 3; v 4 x', 'pixel 1;2; h 3; v 4']) {
      expect(readAnswerLine(text), text).toBeNull();
    }
    expect(readAnswerLine('PIXEL10,12H30V-82')).toEqual({ x: '10', y: '12', h: '30', v: '-82' });
  });
});
