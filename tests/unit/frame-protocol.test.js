import { describe, it, expect } from 'vitest';
import { readFrameMessage, codePlace, MAX_MESSAGE, MAX_HEIGHT } from '../../editor/frame-protocol.js';

describe('readFrameMessage: what the sandboxed frame says, checked field by field', () => {
  it('keeps the known fields of each known message, in a new object', () => {
    const sent = { type: 'error', message: 'ReferenceError: Sphre is not defined', line: 19, column: 13, exact: false, extra: '<img src=x>' };
    const read = readFrameMessage(sent);
    expect(read).toEqual({ type: 'error', message: 'ReferenceError: Sphre is not defined', line: 19, column: 13, exact: false });
    expect(read).not.toBe(sent);
    expect(readFrameMessage({ type: 'render', state: 'done' })).toEqual({ type: 'render', state: 'done' });
    expect(readFrameMessage({ type: 'select', x: 20, y: 10 })).toEqual({ type: 'select', x: 20, y: 10 });
    expect(readFrameMessage({ type: 'select', x: null, y: null })).toEqual({ type: 'select', x: null, y: null });
    expect(readFrameMessage({ type: 'check', passed: true })).toEqual({ type: 'check', passed: true });
    expect(readFrameMessage({ type: 'ready' })).toEqual({ type: 'ready' });
    expect(readFrameMessage({ type: 'alive', at: 'x' })).toEqual({ type: 'alive' });
    expect(readFrameMessage({ type: 'setup', more: 1 })).toEqual({ type: 'setup' });
  });

  it('refuses what is not a message it knows, or a field of the wrong type or size', () => {
    for (const bad of [null, 'setup', 42, [], { type: 'eval', code: 'x' }, { type: 'render', state: 'finished' },
      { type: 'select', x: -1, y: 0 }, { type: 'select', x: 1.5, y: 0 }, { type: 'select', x: '3', y: 4 }, { type: 'select', x: 1e9, y: 0 },
      { type: 'check', passed: 'yes' }, { type: 'error', message: 42 }, { type: 'size', height: Infinity }, { type: 'size', height: -3 },
      { type: 'progress', text: 'x'.repeat(5_000) }, { type: '__proto__' }]) {
      expect(readFrameMessage(bad)).toBeNull();
    }
  });

  it('cuts a long message, drops a bad line number, and caps the height', () => {
    const read = readFrameMessage({ type: 'error', message: 'x'.repeat(10 * MAX_MESSAGE), line: 0, column: 3 });
    expect(read.message).toHaveLength(MAX_MESSAGE);
    expect(read.line).toBeNull();
    expect(read.column).toBeNull();
    expect(readFrameMessage({ type: 'size', height: 1e9 })).toEqual({ type: 'size', height: MAX_HEIGHT });
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
