import { describe, it, expect } from 'vitest';
import { EditorState } from '@codemirror/state';
import { javascript } from '@codemirror/lang-javascript';
import { literalAt, stepped, written, decimalsOf } from '../../editor/number-literal.js';
import { fieldsOfLiteral, valueInPlace, fieldWords } from '../../editor/live-values.js';
import { liveNumbers } from '../../editor/live-numbers.js';
import { readValues, readFrameMessage } from '../../editor/frame-protocol.js';

const stateOf = (doc) => EditorState.create({ doc, extensions: [javascript()] });

describe('number literals, found in the page\'s own parse of the code', () => {
  const code = 'scene.add(new Sphere([0, -20.5, 1e3], .5, { n: 0x1f, k: 10n }), x-1); // 42';
  const at = (text, offset = 0) => literalAt(stateOf(code), code.indexOf(text) + offset);

  it('finds a decimal literal under the caret, at either end, its minus sign included', () => {
    expect(at('0,')).toEqual({ from: code.indexOf('0,'), to: code.indexOf('0,') + 1, text: '0' });
    expect(at('-20.5', 3)).toEqual({ from: code.indexOf('-20.5'), to: code.indexOf('-20.5') + 5, text: '-20.5' });
    expect(at('-20.5', 5)?.text).toBe('-20.5'); // the caret just after it
    expect(at(' .5,', 1)?.text).toBe('.5');
    expect(at('1)')?.text).toBe('1'); // x-1: a subtraction, not a negative literal
  });

  it('leaves what it cannot step: exponents, hex, BigInt, names, comments', () => {
    expect(at('1e3', 1)).toBeNull();
    expect(at('0x1f', 2)).toBeNull();
    expect(at('10n', 1)).toBeNull();
    expect(at('Sphere', 2)).toBeNull();
    expect(at('42', 1)).toBeNull();
  });
});

describe('a step of the last decimal place', () => {
  it('steps by one unit of the last decimal, the decimals kept, with no binary drift', () => {
    expect(stepped('4', 1)).toBe('5');
    expect(stepped('0.5', 1)).toBe('0.6');
    expect(stepped('0.29', 1)).toBe('0.30');
    expect(stepped('1.25', -10)).toBe('1.15');
    expect(stepped('.5', -1)).toBe('0.4');
    expect(stepped('-20', 1)).toBe('-19');
    expect(stepped('0', -1)).toBe('-1');
    expect(stepped('0.1', -2)).toBe('-0.1');
    expect(decimalsOf('4.')).toBe(0);
  });

  it('writes a negative number after a minus or plus sign with a space between', () => {
    expect(written('-', '-1')).toBe(' -1');
    expect(written('+', '-1')).toBe(' -1');
    expect(written(' ', '-1')).toBe('-1');
    expect(written('-', '1')).toBe('1');
  });
});

const report = (radius, x = 0, width = 64) => ({
  scene: { background: [1, 1, 1], objects: [{ type: 'sphere', center: [x, 0, -20], radius }, { type: 'point-light', position: [-10, 20, 0] }] },
  camera: { width, height: 48, fov: 30, position: [0, 0, 0] },
});

describe('which fields of the scene a literal writes, by comparing two runs', () => {
  it('names the fields that held the old value and hold the new one', () => {
    expect(fieldsOfLiteral(report(4), report(5), 4, 5)).toEqual([['scene', 'objects', '0', 'radius']]);
    expect(fieldsOfLiteral(report(4, 0), report(4, 0.1), 0, 0.1)).toEqual([['scene', 'objects', '0', 'center', '0']]);
  });

  it('refuses any other difference: a canvas size, a computed value, another shape, no change at all', () => {
    expect(fieldsOfLiteral(report(4, 0, 64), report(4, 0, 65), 64, 65)).toBeNull();
    expect(fieldsOfLiteral(report(4), report(10), 4, 5)).toBeNull(); // radius = 2 × the literal
    const more = report(4);
    more.scene.objects.push({ type: 'sphere', center: [1, 1, 1], radius: 1 });
    expect(fieldsOfLiteral(report(4), more, 3, 4)).toBeNull();
    expect(fieldsOfLiteral(report(4), report(4), 3, 4)).toBeNull();
    expect(fieldsOfLiteral(report(4), report(5), 5, 5)).toBeNull();
  });

  it('reads the literal\'s value in place only while the code around it is unchanged', () => {
    const binding = { prefix: 'new Sphere([0, 0, -20], ', suffix: ', red)' };
    expect(valueInPlace(binding, 'new Sphere([0, 0, -20], 4.5, red)')).toBe(4.5);
    expect(valueInPlace(binding, 'new Sphere([0, 0, -20],  -1, red)')).toBe(-1);
    expect(valueInPlace(binding, 'new Sphere([0, 0, -20], 4.5, blue)')).toBeNull();
    expect(valueInPlace(binding, 'new Sphere([0, 0, -20], x, red)')).toBeNull();
    expect(valueInPlace(binding, 'new Sphere([0, 0, -20], 1e3, red)')).toBeNull();
  });

  it('says a field as a student reads it', () => {
    expect(fieldWords(['scene', 'objects', '0', 'radius'])).toBe('radius');
    expect(fieldWords(['scene', 'objects', '0', 'center', '2'])).toBe('center z');
    expect(fieldWords(['scene', 'objects', '1', 'color', '1'])).toBe('color g');
    expect(fieldWords(['camera', 'fov'])).toBe('fov');
  });
});

describe('liveNumbers: a scrubbed number goes to the frame as a value once its fields are known', () => {
  const A = 'scene.add(new Sphere([0, 0, -20], 4, red));';
  const at = A.indexOf('4,');
  const withRadius = (r) => A.replace('4,', `${r},`);
  const sceneMessage = (data) => ({ type: 'scene', scene: JSON.stringify(data.scene), camera: JSON.stringify(data.camera) });

  function started() {
    const sent = [];
    const live = liveNumbers({ send: (m) => { sent.push(m); return true; } });
    live.ran(A);
    live.setUp();
    live.scene(sceneMessage(report(4)));
    return { live, sent };
  }

  it('runs the first step at once, learns the fields from its report, then sends the later steps as values', () => {
    const { live, sent } = started();
    expect(live.changed(withRadius(5), { from: at, to: at + 1, was: '4', now: '5' })).toEqual({ run: 'now', words: null });
    live.ran(withRadius(5));
    expect(live.changed(withRadius(6), { from: at, to: at + 1, was: '5', now: '6' })).toEqual({ run: null, words: null }); // waits for the first step's report
    live.setUp();
    expect(live.scene(sceneMessage(report(5)))).toBe(true);
    expect(live.changed(withRadius(6), { from: at, to: at + 1, was: '5', now: '6' })).toEqual({ run: null, words: 'radius 6' });
    expect(sent).toEqual([{ type: 'values', changes: [{ path: ['scene', 'objects', '0', 'radius'], value: 6 }] }]);
    expect(live.changed(withRadius(4), undefined)).toEqual({ run: null, words: 'radius 4' }); // Undo: the same literal, back
    expect(live.changed(A.replace('red', 'blue'), undefined)).toEqual({ run: 'later', words: null }); // typed elsewhere: the code runs again
  });

  it('runs the code again, after the pause, when the literal is not simply a field of the scene', () => {
    const { live, sent } = started();
    live.changed(withRadius(5), { from: at, to: at + 1, was: '4', now: '5' });
    live.ran(withRadius(5));
    live.setUp();
    live.scene(sceneMessage(report(10))); // the radius is computed from it
    expect(live.changed(withRadius(6), { from: at, to: at + 1, was: '5', now: '6' })).toEqual({ run: 'later', words: '6: your code runs again' });
    expect(sent).toEqual([]);
  });

  it('once the frames are gone (a loop that never ends), the same code as before runs again', () => {
    const { live } = started();
    expect(live.changed(A, undefined)).toEqual({ run: null, words: null }); // the picture on show is this code's
    live.gone();
    expect(live.changed(A, undefined)).toEqual({ run: 'later', words: null });
  });

  it('a report that is not JSON teaches nothing and throws nothing', () => {
    const { live, sent } = started();
    live.changed(withRadius(5), { from: at, to: at + 1, was: '4', now: '5' });
    live.ran(withRadius(5));
    live.setUp();
    expect(live.scene({ type: 'scene', scene: '{"objects": [', camera: '{}' })).toBe(true);
    expect(live.changed(withRadius(6), { from: at, to: at + 1, was: '5', now: '6' })).toEqual({ run: 'later', words: '6: your code runs again' });
    expect(sent).toEqual([]);
  });

  it('a forged message is no message: the page knows none that carries code', () => {
    for (const forged of [{ type: 'values', changes: [] }, { type: 'code', code: 'x' }, { type: 'edit', from: 0, to: 3, insert: 'evil' }]) {
      expect(readFrameMessage(forged)).toBeNull();
    }
  });
});

describe('readValues: the page\'s values, checked in the frame', () => {
  it('keeps paths of field names and indices with finite numbers', () => {
    expect(readValues({ type: 'values', changes: [{ path: ['scene', 'objects', '0', 'radius'], value: 4.5 }] }))
      .toEqual([{ path: ['scene', 'objects', '0', 'radius'], value: 4.5 }]);
  });

  it('refuses anything else', () => {
    for (const bad of [null, { type: 'values' }, { type: 'values', changes: [{ path: ['window', 'x'], value: 1 }] },
      { type: 'values', changes: [{ path: ['scene', '__proto__', 'x'], value: 1 }] }, { type: 'values', changes: [{ path: ['scene', 'objects'], value: NaN }] },
      { type: 'values', changes: [{ path: ['scene', 'objects', '0', 'radius'], value: '4' }] }]) {
      expect(readValues(bad)).toBeNull();
    }
  });
});
