// The ready folder's .zip: entries any unzip tool reads, the same bytes every build.
import { describe, it, expect } from 'vitest';
import { zip, crc32 } from '../../scripts/zip.js';
import { readStoredZip } from '../e2e/static-folder.js';

describe('zip', () => {
  it('CRC-32 gives the standard check value and the empty input\'s', () => {
    expect(crc32(Buffer.from('123456789')).toString(16)).toBe('cbf43926');
    expect(crc32(Buffer.alloc(0))).toBe(0);
  });

  it('holds each file, under its path, with its CRC-32: read back byte for byte', () => {
    const files = [
      { name: 'folder/index.html', data: Buffer.from('<!doctype html>\n') },
      { name: 'folder/ré.js', data: Buffer.from([0, 1, 2, 255]) },
      { name: 'folder/empty.txt', data: Buffer.alloc(0) },
    ];
    const back = readStoredZip(zip(files));
    expect(back.map((f) => f.name)).toEqual(files.map((f) => f.name));
    back.forEach((f, i) => {
      expect(Buffer.compare(f.data, files[i].data), f.name).toBe(0);
      expect(f.crc, f.name).toBe(crc32(files[i].data));
    });
  });

  it('gives the same bytes for the same files (a fixed date)', () => {
    const files = [{ name: 'a.txt', data: Buffer.from('a') }];
    expect(Buffer.compare(zip(files), zip(files))).toBe(0);
  });
});
