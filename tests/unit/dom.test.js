// The clipboard helper every Copy button uses: true when the browser took the text, false otherwise (never a throw).
import { describe, it, expect, vi, afterEach } from 'vitest';
import { copyText, shownName, nameTitle, NAME_SHOWN } from '../../lib/p5/dom.js';

afterEach(() => vi.unstubAllGlobals());

describe('copyText', () => {
  it('hands the text to the clipboard and says it did', async () => {
    const writeText = vi.fn(async () => {});
    vi.stubGlobal('navigator', { clipboard: { writeText } });
    expect(await copyText('Pixel: 10,12; H: 30; V: -82')).toBe(true);
    expect(writeText).toHaveBeenCalledWith('Pixel: 10,12; H: 30; V: -82');
  });

  it('says false when the browser refuses, or has no clipboard', async () => {
    vi.stubGlobal('navigator', { clipboard: { writeText: async () => { throw new DOMException('denied', 'NotAllowedError'); } } });
    expect(await copyText('x')).toBe(false);
    vi.stubGlobal('navigator', {});
    expect(await copyText('x')).toBe(false);
  });
});

describe('shownName', () => {
  it('keeps a short name, cuts a long one to NAME_SHOWN characters with an ellipsis, never half of a character', () => {
    expect(shownName('pink')).toBe('pink');
    expect(shownName('x'.repeat(NAME_SHOWN))).toBe('x'.repeat(NAME_SHOWN));
    expect(shownName('x'.repeat(100_000))).toBe(`${'x'.repeat(NAME_SHOWN - 1)}…`);
    expect(shownName(`${'x'.repeat(NAME_SHOWN - 2)}😀😀`)).toBe(`${'x'.repeat(NAME_SHOWN - 2)}…`); // the emoji's first half alone is no character
    expect(nameTitle('pink')).toEqual({});
    expect(nameTitle('y'.repeat(50))).toEqual({ title: 'y'.repeat(50) });
  });
});
