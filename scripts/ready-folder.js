/**
 * The web editor's ready folder (npm run build, after the one-file builds):
 * examples/web-editor/'s index.html and sketch.js, p5's own p5.min.js and
 * raytracing-sketchbook.js, the four files a page needs to run from a
 * double-click, written into dist/web-editor/ and as one .zip beside the
 * web-editor page (dist/raytracing-sketchbook-web-editor.zip).
 *
 *   node scripts/ready-folder.js [dist]
 */
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { zip } from './zip.js';

export const FOLDER = 'web-editor';
export const ZIP_NAME = 'raytracing-sketchbook-web-editor.zip';
/** The folder's name once unzipped. */
const ZIPPED_FOLDER = 'raytracing-sketchbook';

/** The four files, `{ name, data }`; `bundle` is raytracing-sketchbook.js's text or bytes. */
export function readyFolderFiles(bundle) {
  return [
    { name: 'index.html', data: readFileSync(resolve('examples/web-editor/index.html')) },
    { name: 'sketch.js', data: readFileSync(resolve('examples/web-editor/sketch.js')) },
    { name: 'p5.min.js', data: readFileSync(resolve('node_modules/p5/lib/p5.min.js')) },
    { name: 'raytracing-sketchbook.js', data: Buffer.from(bundle) },
  ];
}

/** The same files as one .zip, inside a folder of their own. */
export function readyFolderZip(bundle) {
  return zip(readyFolderFiles(bundle).map(({ name, data }) => ({ name: `${ZIPPED_FOLDER}/${name}`, data })));
}

/** Writes `dist`/web-editor/ and the .zip, from `dist`/raytracing-sketchbook.js; returns what it wrote, in words. */
export function writeReadyFolder(dist = 'dist') {
  const bundle = readFileSync(join(dist, 'raytracing-sketchbook.js'));
  mkdirSync(join(dist, FOLDER), { recursive: true });
  for (const { name, data } of readyFolderFiles(bundle)) writeFileSync(join(dist, FOLDER, name), data);
  writeFileSync(join(dist, ZIP_NAME), readyFolderZip(bundle));
  return `${join(dist, FOLDER)}/ (index.html, sketch.js, p5.min.js, raytracing-sketchbook.js) and ${join(dist, ZIP_NAME)}`;
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) console.log(writeReadyFolder(process.argv[2]));
