import { describe, it, expect } from 'vitest';
import { readFrameMessage, codePlace, frameHeight, MAX_MESSAGE, MAX_HEIGHT, MIN_HEIGHT, MAX_SCENE_TEXT } from '../../editor/frame-protocol.js';

describe('readFrameMessage: what the sandboxed frame says, checked field by field', () => {
  it('keeps the known fields of each known message, in a new object', () => {
    const sent = { type: 'error', message: 'ReferenceError: Sphre is not defined', line: 19, column: 13, exact: false, extra: '<img src=x>' };
    const read = readFrameMessage(sent);
    expect(read).toEqual({ type: 'error', message: 'ReferenceError: Sphre is not defined', line: 19, column: 13, exact: false });
    expect(read).not.toBe(sent);
    expect(readFrameMessage({ type: 'render', state: 'done' })).toEqual({ type: 'render', state: 'done' });
    expect(readFrameMessage({ type: 'select', x: 20, y: 10 })).toEqual({ type: 'select', x: 20, y: 10 });
    expect(readFrameMessage({ type: 'select', x: null, y: null })).toEqual({ type: 'select', x: null, y: null });
    expect(readFrameMessage({ type: 'ready' })).toEqual({ type: 'ready' });
    expect(readFrameMessage({ type: 'alive', at: 'x' })).toEqual({ type: 'alive' });
    expect(readFrameMessage({ type: 'setup', more: 1 })).toEqual({ type: 'setup' });
  });

  it('refuses what is not a message it knows, or a field of the wrong type or size', () => {
    for (const bad of [null, 'setup', 42, [], { type: 'eval', code: 'x' }, { type: 'render', state: 'finished' },
      { type: 'select', x: -1, y: 0 }, { type: 'select', x: 1.5, y: 0 }, { type: 'select', x: '3', y: 4 }, { type: 'select', x: 1e9, y: 0 },
      { type: 'error', message: 42 }, { type: 'size', height: Infinity }, { type: 'size', height: -3 }, { type: 'size', height: '900' },
      { type: 'scene', scene: 42, camera: '{}' }, { type: 'scene', scene: '{}', camera: null }, { type: 'scene', scene: '{}' },
      { type: 'scene', scene: 'x'.repeat(MAX_SCENE_TEXT + 1), camera: '{}' }, { type: '__proto__' }]) {
      expect(readFrameMessage(bad)).toBeNull();
    }
  });

  it('knows no message that claims a verdict, a task or progress: the frame reports, the page judges', () => {
    for (const claim of [{ type: 'check', passed: true }, { type: 'check', passed: true, toFix: 0 }, { type: 'task', page: '08', tasks: ['pass'] },
      { type: 'progress', text: '{"v":1,"pages":{"08":["check","light","pass"]}}' }]) {
      expect(readFrameMessage(claim), claim.type).toBeNull();
    }
  });

  it('reads what the code built as text for the page to read again, and only the known render orders', () => {
    const sent = { type: 'scene', scene: '{"objects":[]}', camera: '{"width":4,"height":3}', mode: 'normals', order: 'slow', extra: 1 };
    expect(readFrameMessage(sent)).toEqual({ type: 'scene', scene: '{"objects":[]}', camera: '{"width":4,"height":3}', mode: 'normals', order: 'slow', problem: null });
    expect(readFrameMessage({ ...sent, mode: '<b>', order: 'sideways' })).toMatchObject({ mode: 'shaded', order: 'coarse' });
    expect(readFrameMessage({ type: 'scene', scene: null, camera: null, problem: 'scene objects must be spheres…' }))
      .toMatchObject({ scene: null, problem: 'scene objects must be spheres…' });
  });

  it('cuts a long message and drops a bad line number', () => {
    const read = readFrameMessage({ type: 'error', message: 'x'.repeat(10 * MAX_MESSAGE), line: 0, column: 3 });
    expect(read.message).toHaveLength(MAX_MESSAGE);
    expect(read.line).toBeNull();
    expect(read.column).toBeNull();
  });

  it('makes a frame no shorter than MIN_HEIGHT and no taller than MAX_HEIGHT or the window, whatever it asks', () => {
    expect(frameHeight(readFrameMessage({ type: 'size', height: 20_000 }).height, 900)).toBe(MAX_HEIGHT);
    expect(frameHeight(1e9, 3_000)).toBe(3_000);
    expect(frameHeight(0, 900)).toBe(MIN_HEIGHT);
    expect(frameHeight(640.2, 900)).toBe(641);
    expect(frameHeight(5_000, NaN)).toBe(MAX_HEIGHT);
  });
});

describe('codePlace: the editor\'s line of a mistake', () => {
  const NAME = '10-playground.js';
  it('reads the first frame in the code\'s own script from the stack, past the kit\'s frames', () => {
    const stack = `ReferenceError: Sphre is not defined\n    at makeScene (${NAME}:19:13)\n    at blob:null/1234:1:99`;
    expect(codePlace(stack, null, NAME)).toEqual({ line: 19, column: 13 });
    const kitFirst = `TypeError: radius must be > 0\n    at new Sphere (blob:null/1234:1:5000)\n    at ${NAME}:20:15`;
    expect(codePlace(kitFirst, null, NAME)).toEqual({ line: 20, column: 15 });
  });

  it('takes the browser\'s place for a syntax error or a missing export in the code\'s script, and nothing elsewhere', () => {
    expect(codePlace('', { filename: 'about:srcdoc', lineno: 2, colno: 11 }, NAME)).toEqual({ line: 2, column: 11 });
    expect(codePlace('', { filename: NAME, lineno: 4, colno: 0 }, NAME)).toEqual({ line: 4, column: 1 });
    expect(codePlace('', { filename: 'blob:null/1234', lineno: 1, colno: 4000 }, NAME)).toBeNull();
    expect(codePlace('at other-10-playground.jsx:3:4', null, NAME)).toBeNull();
  });
});
