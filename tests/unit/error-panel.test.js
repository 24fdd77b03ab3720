import { describe, it, expect } from 'vitest';
import { sketchFrame, errorMessage } from '../../lib/p5/page/error-panel.js';

const ORIGIN = 'http://localhost:5173';

describe('sketchFrame: the first line of the stack in the sketch\'s own files', () => {
  it('skips frames in lib/ and node_modules/ (Chromium stacks), and drops Vite\'s query', () => {
    const stack = [
      'TypeError: radius must be a finite number, got "4"',
      '    at finiteNumber (http://localhost:5173/lib/check.js:8:11)',
      '    at new Sphere (http://localhost:5173/lib/shapes/sphere.js:27:5)',
      '    at p.setup (http://localhost:5173/sketches/11-my-sketch.js?t=1712345678901:14:12)',
      '    at #_setup (http://localhost:5173/node_modules/.vite/deps/p5.js?v=aa5156a9:1290:21)',
      '    at async #_start (http://localhost:5173/node_modules/.vite/deps/p5.js?v=aa5156a9:1266:5)',
    ].join('\n');
    expect(sketchFrame(stack, ORIGIN)).toEqual({
      url: 'http://localhost:5173/sketches/11-my-sketch.js', file: 'sketches/11-my-sketch.js', line: 14, column: 12,
    });
  });

  it('reads Firefox and Safari stacks (name@url:line:col)', () => {
    const stack = 'Sphere@http://localhost:5173/lib/shapes/sphere.js:27:5\nsetup@http://localhost:5173/sketches/10-playground.js:20:7\n';
    expect(sketchFrame(stack, ORIGIN)).toMatchObject({ file: 'sketches/10-playground.js', line: 20, column: 7 });
  });

  it('an anonymous frame (at url:line:col) counts too; a folder named like the file is decoded', () => {
    expect(sketchFrame('    at http://localhost:5173/my%20sketches/a.js:3:1', ORIGIN)).toMatchObject({ file: 'my sketches/a.js', line: 3 });
  });

  it('null when no frame is the sketch\'s: only the library, p5, Vite\'s client, another origin, or no stack', () => {
    expect(sketchFrame('    at f (http://localhost:5173/lib/p5/tracer-view.js:200:3)', ORIGIN)).toBeNull();
    expect(sketchFrame('    at f (http://localhost:5173/@vite/client:10:3)', ORIGIN)).toBeNull();
    expect(sketchFrame('    at f (https://cdn.example.com/sketch.js:10:3)', ORIGIN)).toBeNull();
    expect(sketchFrame('    at f (http://localhost:5173/index.html:10:3)', ORIGIN)).toBeNull(); // not a script file
    expect(sketchFrame('', ORIGIN)).toBeNull();
  });
});

describe('errorMessage', () => {
  it('"Name: message" for an error, the message alone for a plain Error', () => {
    expect(errorMessage(new RangeError('radius must be greater than 0, got -1'))).toBe('RangeError: radius must be greater than 0, got -1');
    expect(errorMessage(new Error('draw broke'))).toBe('draw broke');
  });

  it('anything else thrown, as text', () => {
    expect(errorMessage('oops')).toBe('oops');
    expect(errorMessage({ code: 42 })).toBe('{"code":42}');
    expect(errorMessage(undefined)).toBe('undefined');
  });
});
