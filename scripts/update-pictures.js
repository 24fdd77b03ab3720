#!/usr/bin/env node
/**
 * Rewrites the library's reference pictures (tests/pictures/*.png) from the
 * current renderer. Run it only when a picture change is intended
 * (`npm run test:update`), then look at the new PNGs before committing them.
 */
import fs from 'node:fs';
import path from 'node:path';
import { pictures, renderPicture, referencePath, readPng, writePng, comparePictures, DIFF_DIR } from '../tests/pictures/pictures.js';

let changed = 0;
for (const picture of pictures) {
  const file = referencePath(picture.name);
  const actual = renderPicture(picture);
  let status = 'new';
  if (fs.existsSync(file)) {
    const { differing } = comparePictures(actual, readPng(file));
    status = differing === 0 ? 'unchanged' : `updated (${differing} pixels differed)`;
  }
  if (status !== 'unchanged') {
    writePng(file, actual);
    changed++;
  }
  console.log(`${path.relative(process.cwd(), file)}: ${status}`);
}
fs.rmSync(DIFF_DIR, { recursive: true, force: true });
console.log(`${changed} of ${pictures.length} reference pictures written.`);
