// Every reader of text from outside (OBJ files, scene JSON and links, progress
// codes, colours, link parameters) takes time in proportion to the text: the
// ratio of its times on 10⁵ and 10³ characters is about 100 when linear,
// 10,000 when quadratic (tests/unit/linear-time.js). Each shape of text is one
// that makes a careless pattern retry: long runs of digits, of spaces, of one
// letter, with the character that makes it fail at the very end.
import { describe, it, expect } from 'vitest';
import { timeRatio, quietly } from './linear-time.js';
import { parseOBJ } from '../../lib/shapes/obj.js';
import { sceneFromJSON, cameraFromJSON } from '../../lib/scene/json.js';
import { decodeScene } from '../../lib/scene/codec.js';
import { toColor } from '../../lib/math/color.js';
import { readProgressCode, readProgressLine, parseProgress } from '../../lib/lesson/progress.js';
import { LESSONS } from '../../lib/lesson/tasks.js';
import { readNumber, readColor } from '../../lib/scene/values.js';
import { answerLineBoxes } from '../../lib/lesson/activity.js';
import { solutionParameter } from '../../lib/lesson/homework.js';
import { exampleInLink } from '../../lib/p5/controls/example-picker.js';

const LINEAR = 400; // × for 100 × the text: linear is ~100, quadratic ~10,000
const pad = (n, s) => s.repeat(Math.max(1, Math.floor(n / s.length)));

/** Each reader with the texts that test it. */
const READERS = {
  'the OBJ reader': [parseOBJ, [
    (n) => `v ${pad(n, '1')}x 0 0\n`, // digits, then a letter (40,000 took 2 s)
    (n) => `v 1.${pad(n, '1')}x 0 0\n`,
    (n) => `v 1e${pad(n, '1')}x 0 0\n`,
    (n) => `v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1${pad(n, ' ')}2 3 x\n`,
    (n) => `v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/${pad(n, '1')}/x 2 3\n`,
    (n) => `${pad(n, '#')}\nv`,
    (n) => pad(n, 'v 0 0 0\n'),
    (n) => pad(n, '\r'),
  ]],
  'scene JSON': [sceneFromJSON, [
    (n) => `{"objects":[{"type":"sphere","center":[0,0,-5],"radius":${pad(n, '1')}x}]}`,
    (n) => `{"objects":[{"type":"sphere","name":"${pad(n, 'a')}","center":[0,0,-5],"radius":1}]}`,
    (n) => `{"objects":[{"type":"${pad(n, 'sphere')}"}]}`,
    (n) => `{"${pad(n, 'k')}":1}`,
    (n) => `${pad(n / 2, '[')}${pad(n / 2, ']')}`,
    (n) => `{"background":"${pad(n, ' ')}x"}`,
  ]],
  'a camera\'s JSON': [cameraFromJSON, [(n) => `{"width":${pad(n, '9')}}`, (n) => `{"${pad(n, 'w')}":1}`]],
  'a scene link': [decodeScene, [(n) => pad(n, 'A'), (n) => `${pad(n, 'A')}!`, (n) => `{"objects":${pad(n, ' ')}[]}`]],
  'a CSS colour': [(text) => toColor(text, 'color'), [
    (n) => `rgb(${pad(n, ' ')}1, 2, 3x)`, (n) => `rgb(${pad(n, '1')}, 2, 3x)`, (n) => `#${pad(n, 'f')}`, (n) => pad(n, 'p'), (n) => `${pad(n, ' ')}x`,
  ]],
  'a progress code': [(text) => readProgressCode(text, LESSONS), [(n) => `RT1-${pad(n, '0')}`, (n) => `RT1${pad(n, '-')}`, (n) => pad(n, ' ')]],
  'a teacher\'s line': [(text) => readProgressLine(text, LESSONS), [(n) => `a${pad(n, ' ')}b RT1-0`, (n) => pad(n, 'rt1-'), (n) => `${pad(n, ':')}x RT1-0`]],
  'stored progress': [(text) => parseProgress(text, LESSONS), [(n) => `{"v":1,"pages":{"01":[${pad(n, '"select",')}"x"]}}`, (n) => pad(n, '{')]],
  'a typed number or colour': [(text) => { readNumber(text.slice(0, 100), 'x'); readColor(text.slice(0, 100), 'c'); }, [(n) => `${pad(n, '1')}x`]],
  'an answer line': [answerLineBoxes, [(n) => `pixel 1,1 h 1 v 1${pad(n, ' ')}x`]],
  'link parameters': [(text) => { solutionParameter(text); exampleInLink(text, { still: {}, animated: {} }); }, [
    (n) => `?solution=${pad(n, '%20')}`, (n) => `?example=${pad(n, 'x')}`, (n) => pad(n, '&'),
  ]],
};

describe('readers of outside text take time in proportion to it', () => {
  for (const [reader, [read, texts]] of Object.entries(READERS)) {
    it(reader, () => {
      for (const [i, makeText] of texts.entries()) {
        expect(timeRatio(quietly(read), makeText), `${reader}, text ${i}: ${makeText(12)}`).toBeLessThan(LINEAR);
      }
    });
  }
});
