// Hostile scene JSON: deep nesting, huge arrays, huge keys. Each gives a
// TypeError/RangeError that names the path, in a message of a few lines.
import { describe, it, expect } from 'vitest';
import { sceneFromJSON, cameraFromJSON, MAX_JSON_DEPTH } from '../../lib/scene/json.js';
import { decodeScene } from '../../lib/scene/codec.js';
import { show, SHOW_MAX } from '../../lib/text/check.js';

const SHORT = 400; // no message longer than this

/** Runs `make`, returns the error it throws (fails when none). */
function errorOf(make) {
  try { make(); } catch (error) { return error; }
  throw new Error('expected an error');
}

const nested = (levels, inner = '1') => `${'['.repeat(levels)}${inner}${']'.repeat(levels)}`;

describe('deep nesting', () => {
  for (const levels of [MAX_JSON_DEPTH + 1, 10_000, 100_000]) {
    it(`${levels} levels in a colour: a RangeError naming the path`, () => {
      const error = errorOf(() => sceneFromJSON(`{"objects":[{"type":"sphere","center":[0,0,-5],"radius":1,"material":{"color":${nested(levels)}}}]}`));
      expect(error).toBeInstanceOf(RangeError);
      expect(error.message).toMatch(/^scene is nested more than 32 levels deep, at objects\[0\]\.material\.color\[0\]\[0\]/);
      expect(error.message).not.toMatch(/call stack/);
      expect(error.message.length).toBeLessThan(SHORT);
    });
  }

  it('a deep object (not arrays) too, and through a link', () => {
    let text = '1';
    for (let i = 0; i < 10_000; i++) text = `{"a":${text}}`;
    const error = errorOf(() => decodeScene(`{"objects":[{"type":"sphere","center":[0,0,-5],"radius":1,"material":${text}}]}`));
    expect(error).toBeInstanceOf(RangeError);
    expect(error.message).toMatch(/objects\[0\]\.material\.a\.a\.a/);
    expect(error.message.length).toBeLessThan(SHORT);
  });

  it('a camera too', () => {
    expect(() => cameraFromJSON(`{"width":${nested(10_000)}}`)).toThrow(/camera is nested more than 32 levels deep, at width\[0\]/);
  });

  it('is refused while reading the text, before JSON.parse builds the levels: deep text that is cut short is refused for its depth', () => {
    const cut = `{"objects":[{"type":"sphere","material":{"color":${'['.repeat(3_500_000)}`; // 3.5 million levels, never closed
    const error = errorOf(() => sceneFromJSON(cut));
    expect(error).toBeInstanceOf(RangeError);
    expect(error.message).toMatch(/^scene is nested more than 32 levels deep, at objects\[0\]\.material\.color\[0\]\[0\]/);
  });

  it('the reading before JSON.parse names the same path as the walk after it, brackets and quotes in text passed over', async () => {
    const { tooDeepAt } = await import('../../lib/scene/json-depth.js');
    const text = `{"q[":[1,"[[{\\"[",{"b":2,"c":[0,0,${nested(40)}]}]}`; // a bracket in a key, brackets and an escaped quote in a string
    expect(tooDeepAt(text, 32)).toBe(`q[[2].c[2]${'[0]'.repeat(28)}`);
    expect(errorOf(() => sceneFromJSON(JSON.parse(text))).message).toBe(`scene is nested more than 32 levels deep, at ${tooDeepAt(text, 32)}`);
    expect(tooDeepAt(nested(32), 32)).toBeNull();
    expect(tooDeepAt(nested(33), 32)).toBe('[0]'.repeat(32));
  });

  it('an ordinary scene is far from the limit', () => {
    expect(sceneFromJSON('{"objects":[{"type":"sphere","center":[0,0,-5],"radius":1,"material":{"color":[1,0,0]}}]}').objects).toHaveLength(1);
  });
});

describe('huge values are not echoed whole', () => {
  it('a 1,000,000-number centre: the field named, the message short', () => {
    const error = errorOf(() => sceneFromJSON({ objects: [{ type: 'sphere', center: new Array(1_000_000).fill(1), radius: 1 }] }));
    expect(error.message).toMatch(/^objects\[0\]\.center/);
    expect(error.message.length).toBeLessThan(SHORT);
  });

  it('a 1 MB field name', () => {
    const key = 'k'.repeat(1_000_000);
    const error = errorOf(() => sceneFromJSON({ objects: [{ type: 'sphere', center: [0, 0, -5], radius: 1, [key]: 1 }] }));
    expect(error).toBeInstanceOf(TypeError);
    expect(error.message).toMatch(/^objects\[0\] has no field "kkk/);
    expect(error.message.length).toBeLessThan(SHORT);
  });

  it('a 1 MB string as a radius', () => {
    const error = errorOf(() => sceneFromJSON({ objects: [{ type: 'sphere', center: [0, 0, -5], radius: 'r'.repeat(1_000_000) }] }));
    expect(error.message).toMatch(/^objects\[0\]\.radius/);
    expect(error.message.length).toBeLessThan(SHORT);
  });

  it('broken JSON text of a megabyte', () => {
    const error = errorOf(() => sceneFromJSON(`{"objects":[${'1,'.repeat(500_000)}`));
    expect(error.message).toMatch(/^scene is not valid JSON/);
    expect(error.message.length).toBeLessThan(SHORT);
  });
});

describe('show', () => {
  it('is short for anything', () => {
    const deep = JSON.parse(nested(10_000));
    const odd = [deep, new Array(1e6).fill(0), 'x'.repeat(1e6), Object.create(null), new Proxy({}, { ownKeys() { throw new Error('no'); } }), () => 1, Symbol('s')];
    for (const value of odd) expect(show(value).length).toBeLessThanOrEqual(SHOW_MAX);
  });

  it('reads as before for small values', () => {
    expect(show('abc')).toBe('"abc"');
    expect(show([1, 'a', null])).toBe('[1, "a", null]');
    expect(show({ x: 1, y: 'b' })).toBe('{"x":1,"y":"b"}');
    expect(show(undefined)).toBe('undefined');
    expect(show(Object)).toBe('function Object');
  });
});
