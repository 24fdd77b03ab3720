/**
 * Every part of a link that a page reads: the query parameters (`?name=`) and
 * the fragment's parameters (`#name=`), page by page. The hostile-link test
 * tries an HTML payload in each; a unit test (tests/unit/html-sinks.test.js)
 * fails when the code reads a parameter this list lacks.
 */
import { readdirSync } from 'node:fs';

/** Read on every page: p5's language detector looks at `?lng=`. */
export const EVERY_PAGE = ['lng'];

/** A sketch's code shared as a link (`#code=z.…`, editor/code-link.js): read on every sketch page, whose code panel opens with it. */
const CODE = { name: 'code', where: 'fragment' };
const SKETCH_PAGES = readdirSync('sketches').filter((f) => /^\d\d-.*\.html$/.test(f)).map((f) => `sketches/${f}`);

/** Parameters of one page: `where` is 'query' or 'fragment'. */
export const PAGE_PARAMETERS = {
  ...Object.fromEntries(SKETCH_PAGES.map((path) => [path, [CODE]])),
  'sketches/05-value-boxes.html': [{ name: 'scene', where: 'query' }, { name: 'scene', where: 'fragment' }, CODE],
  'sketches/07-original-examples.html': [{ name: 'example', where: 'query' }, CODE],
  'sketches/08-homework-traffic-signal.html': [{ name: 'solution', where: 'query' }, CODE],
  'sketches/09-homework-rear-lights.html': [{ name: 'solution', where: 'query' }, CODE],
  // The teacher's page of progress codes: a code in its link is read as one pasted line (site/teacher.js).
  'teacher.html': [CODE],
};

/** The names the project's own code reads (p5's `lng` aside). */
export const OWN_NAMES = [...new Set(Object.values(PAGE_PARAMETERS).flat().map((p) => p.name))].sort();
