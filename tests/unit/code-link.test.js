import { describe, it, expect } from 'vitest';
import { deflateRawSync } from 'node:zlib';
import { codeLinkURL, codeTextInLink, decodeCodeLink, encodeCodeLink, MAX_CODE_BYTES } from '../../editor/code-link.js';

const CODE = "import p5 from 'p5';\n// a sphere: ✓ ünïcode\nconst WIDTH = 64;\n".repeat(20);

describe('code in a link', () => {
  it('round-trips through the fragment, compressed, the rest of the address kept', async () => {
    const link = await codeLinkURL('http://class.test:5173/sketches/10-playground.html?lng=en#old', CODE);
    expect(link).toMatch(/^http:\/\/class\.test:5173\/sketches\/10-playground\.html\?lng=en#code=z\.[\w-]+$/);
    expect(link.length).toBeLessThan(CODE.length / 3);
    expect(await decodeCodeLink(codeTextInLink(link))).toBe(CODE);
    expect(codeTextInLink('http://x/a.html#scene=z.abc')).toBeNull();
  });

  it('refuses damaged, foreign or too large text with a message saying what is wrong', async () => {
    await expect(decodeCodeLink('plain text')).rejects.toThrow(/not z\. and base64url/);
    await expect(decodeCodeLink('z.@@@')).rejects.toThrow(/not z\. and base64url/);
    const encoded = await encodeCodeLink(CODE);
    await expect(decodeCodeLink(encoded.slice(0, 20))).rejects.toThrow(/cut short or damaged/);
    const bomb = `z.${deflateRawSync(Buffer.alloc(MAX_CODE_BYTES + 1, 32)).toString('base64url')}`;
    expect(bomb.length).toBeLessThan(2_000);
    await expect(decodeCodeLink(bomb)).rejects.toThrow(RangeError);
    const notText = `z.${deflateRawSync(Buffer.from([0xff, 0xfe, 0x00])).toString('base64url')}`;
    await expect(decodeCodeLink(notText)).rejects.toThrow(/not UTF-8/);
  });
});
