// The tracer view's PNG export: the file's name, and the download itself (on
// stand-ins for the canvas and the page's link element).
import { describe, it, expect, afterEach } from 'vitest';
import { pngDataURL, pngFilename, download } from '../../lib/p5/tracer/export.js';

describe('PNG export', () => {
  const realDocument = globalThis.document;
  afterEach(() => {
    if (realDocument === undefined) delete globalThis.document;
    else globalThis.document = realDocument;
  });

  it('names the file after the traced resolution and the visual mode', () => {
    expect(pngFilename(64, 48, 'shaded')).toBe('trace-64x48-shaded.png');
    expect(pngFilename(160, 120, 'discriminant')).toBe('trace-160x120-discriminant.png');
  });

  it('asks the canvas for a PNG', () => {
    const asked = [];
    const canvas = { toDataURL: (type) => { asked.push(type); return 'data:image/png;base64,AAAA'; } };
    expect(pngDataURL(canvas)).toBe('data:image/png;base64,AAAA');
    expect(asked).toEqual(['image/png']);
  });

  it('downloads through a link with the file name, clicked once', () => {
    const links = [];
    globalThis.document = /** @type {any} */ ({
      createElement: (tag) => {
        const link = { tag, href: '', download: '', clicks: 0, click() { link.clicks++; } };
        links.push(link);
        return link;
      },
    });
    download('data:image/png;base64,AAAA', 'trace-64x48-shaded.png');
    expect(links).toEqual([expect.objectContaining({ tag: 'a', href: 'data:image/png;base64,AAAA', download: 'trace-64x48-shaded.png', clicks: 1 })]);
  });
});
