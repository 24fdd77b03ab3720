// Picture tests in Node: each scene of tests/pictures/pictures.js is rendered and
// compared, pixel for pixel, with its checked-in reference PNG. The renderer is
// deterministic, so not one pixel may differ. A missing or different reference is
// a failure, never silently rewritten: run `npm run test:update` only when the
// change of picture is intended.
import { describe, it, expect } from 'vitest';
import fs from 'node:fs';
import path from 'node:path';
import os from 'node:os';
import {
  pictures, renderPicture, referencePath, readPng, writePng, comparePictures, DIFF_DIR,
} from '../pictures/pictures.js';

const UPDATE_HINT = 'run `npm run test:update` only if this change of picture is intended';

describe('reference pictures', () => {
  it('has at least the four pictures of the library', () => {
    expect(pictures.map((p) => p.name)).toEqual(
      expect.arrayContaining(['class-scene', 'class-scene-full', 'plane-box-point-light', 'class-scene-yaw-pitch']),
    );
  });

  for (const picture of pictures) {
    it(`${picture.name}: ${picture.about}`, () => {
      const file = referencePath(picture.name);
      const rel = path.relative(process.cwd(), file);
      const actual = renderPicture(picture);
      if (!fs.existsSync(file)) {
        writePng(path.join(DIFF_DIR, `${picture.name}.actual.png`), actual);
        expect.fail(`reference picture ${rel} is missing (the rendered one is in ${path.relative(process.cwd(), DIFF_DIR)}); ${UPDATE_HINT}`);
      }
      const expected = readPng(file);
      const { differing, diff, sizeMismatch } = comparePictures(actual, expected);
      if (differing > 0) {
        writePng(path.join(DIFF_DIR, `${picture.name}.actual.png`), actual);
        if (diff) writePng(path.join(DIFF_DIR, `${picture.name}.diff.png`), { ...actual, data: diff });
        const what = sizeMismatch
          ? `is ${actual.width}×${actual.height}, the reference ${expected.width}×${expected.height}`
          : `differs from the reference in ${differing} pixels`;
        expect.fail(`${picture.name} ${what} (see ${path.relative(process.cwd(), DIFF_DIR)}/${picture.name}.actual.png and .diff.png); ${UPDATE_HINT}`);
      }
      // pixelmatch found nothing; the bytes are identical too.
      expect(Buffer.from(actual.data).equals(Buffer.from(expected.data))).toBe(true);
    });
  }
});

describe('the picture comparison itself', () => {
  const picture = pictures[0];

  it('counts a single changed pixel, even by one step of one channel', () => {
    const a = renderPicture(picture);
    const b = { ...a, data: a.data.slice() };
    b.data[4 * 1234 + 1] += b.data[4 * 1234 + 1] < 255 ? 1 : -1;
    expect(comparePictures(a, a).differing).toBe(0);
    expect(comparePictures(a, b).differing).toBe(1);
  });

  it('treats a different size as a mismatch', () => {
    const a = renderPicture(picture);
    const small = { width: 2, height: 2, data: new Uint8ClampedArray(16) };
    expect(comparePictures(a, small)).toMatchObject({ sizeMismatch: true });
    expect(comparePictures(a, small).differing).toBeGreaterThan(0);
  });

  it('reads back exactly the bytes it writes', () => {
    const a = renderPicture(picture);
    const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'pictures-')), 'roundtrip.png');
    writePng(file, a);
    const back = readPng(file);
    fs.rmSync(file);
    expect([back.width, back.height]).toEqual([a.width, a.height]);
    expect(Buffer.from(back.data).equals(Buffer.from(a.data))).toBe(true);
  });
});
