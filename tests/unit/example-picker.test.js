// Which example a link asks for (?example=…), and what a bad one is told.
import { describe, it, expect } from 'vitest';
import { exampleInLink } from '../../lib/p5/controls/example-picker.js';

const EXAMPLES = { still: {}, animated: { thread: 'main' }, workers: { thread: 'workers' } };

describe('exampleInLink', () => {
  it('is the first example when the link names none', () => {
    expect(exampleInLink('', EXAMPLES)).toEqual({ name: 'still', problem: '' });
    expect(exampleInLink('?scene=abc', EXAMPLES)).toEqual({ name: 'still', problem: '' });
  });

  it('is the example the link names', () => {
    expect(exampleInLink('?example=workers', EXAMPLES)).toEqual({ name: 'workers', problem: '' });
  });

  it('falls back to the first example, saying which names there are and what it got', () => {
    expect(exampleInLink('?example=movie', EXAMPLES)).toEqual({
      name: 'still', problem: 'example must be still, animated, workers; got "movie", so here is the still scene.',
    });
    expect(exampleInLink('?example=', EXAMPLES).problem).toMatch(/got "", so here is the still scene\.$/);
  });

  it('cuts a long name in its message (a 12,000-character link was echoed whole)', () => {
    const { problem } = exampleInLink(`?example=${'x'.repeat(12_000)}`, EXAMPLES);
    expect(problem.length).toBeLessThan(200);
    expect(problem).toMatch(/^example must be still, animated, workers; got "x+…, so here is the still scene\.$/);
  });
});
