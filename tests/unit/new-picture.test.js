// npm run test:new-picture: which sketch, which of its pictures exist, and only its test.
import { describe, it, expect } from 'vitest';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { sketchPage, referencesOf, testTitle } from '../../scripts/new-picture.js';

describe('npm run test:new-picture', () => {
  it('takes a sketch page by its path or its name, and says what to type otherwise', () => {
    expect(sketchPage('sketches/04-find-the-pink-pixel.html')).toBe('04-find-the-pink-pixel.html');
    expect(sketchPage('10-playground.html')).toBe('10-playground.html');
    expect(() => sketchPage(undefined)).toThrow(/which sketch\? usage: npm run test:new-picture -- sketches\/NN-name\.html/);
    expect(() => sketchPage('sketches/sketch.css')).toThrow(/named like sketches\/11-my-sketch\.html, got "sketches\/sketch\.css"/);
    expect(() => sketchPage('sketches/99-none.html')).toThrow(/there is no sketches\/99-none\.html/);
  });

  it('finds the reference pictures of that page\'s views only', () => {
    const dir = mkdtempSync(join(tmpdir(), 'shots-'));
    for (const f of ['11-a-view0.png', '11-a-view1.png', '11-ab-view0.png', '11-a-view0-actual.txt']) writeFileSync(join(dir, f), '');
    expect(referencesOf('11-a.html', dir)).toEqual(['11-a-view0.png', '11-a-view1.png']);
    expect(referencesOf('12-b.html', dir)).toEqual([]);
    expect(referencesOf('11-a.html', join(dir, 'none'))).toEqual([]);
  });

  it('selects only that page\'s screenshot test', () => {
    const title = new RegExp(testTitle('04-find-the-pink-pixel.html'));
    expect(title.test('04-find-the-pink-pixel.html renders, with no console errors')).toBe(true);
    expect(title.test('04-find-the-pink-pixelxhtml renders, with no console errors')).toBe(false);
    expect(title.test('05-value-boxes.html renders, with no console errors')).toBe(false);
  });
});
