/**
 * Every part of a link that a page reads: the query parameters (`?name=`) and
 * the fragment's parameters (`#name=`), page by page. The hostile-link test
 * tries an HTML payload in each; a unit test (tests/unit/html-sinks.test.js)
 * fails when the code reads a parameter this list lacks.
 */

/** Read on every page: p5's language detector looks at `?lng=`. */
export const EVERY_PAGE = ['lng'];

/** Parameters of one page: `where` is 'query' or 'fragment'. */
export const PAGE_PARAMETERS = {
  'sketches/05-value-boxes.html': [{ name: 'scene', where: 'query' }, { name: 'scene', where: 'fragment' }],
  'sketches/07-original-examples.html': [{ name: 'example', where: 'query' }],
  'sketches/08-homework-traffic-signal.html': [{ name: 'solution', where: 'query' }],
  'sketches/09-homework-rear-lights.html': [{ name: 'solution', where: 'query' }],
};

/** The names the project's own code reads (p5's `lng` aside). */
export const OWN_NAMES = [...new Set(Object.values(PAGE_PARAMETERS).flat().map((p) => p.name))].sort();
