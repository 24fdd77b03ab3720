/**
 * A pixel's inspectPixel record as CSV, for worksheets (the inspector's "Copy
 * CSV" and "Download CSV"): a header and one row per sphere, cells a
 * spreadsheet would run as formulas written as text.
 */
import { toHex, colorName } from '../../math/color.js';
import { formatNumber, formatAngle } from '../../text/format.js';
import { csvCell } from '../../text/csv.js';

export { csvCell }; // one CSV cell, as the class board's export writes them too

/** Relative tolerance within which the two intersection routes "agree". */
export const AGREE_TOLERANCE = 1e-9;

/** What a number of roots means for the ray. */
export function rootsMeaning(roots) {
  return ['no hit', 'tangent', 'two hits'][roots];
}

/** True when both routes found the same number of roots and the same t0, t1 (relative 1e-9). */
export function routesAgree(quadratic, geometric) {
  return quadratic.roots === geometric.roots && close(quadratic.t0, geometric.t0) && close(quadratic.t1, geometric.t1);
}

function close(a, b) {
  if (a === null || b === null) return a === b;
  return Math.abs(a - b) <= AGREE_TOLERANCE * Math.max(1, Math.abs(a), Math.abs(b));
}

const CSV_HEAD = ['x', 'y', 'H', 'V', 'sphere', 'A', 'B', 'C', 'discriminant', 'roots', 'meaning', 't0', 't1',
  'L_x', 'L_y', 'L_z', 'tca', 'd2', 'thc', 'geometric_t0', 'geometric_t1', 'routes_agree',
  'hit_object', 'hit_t', 'color_hex', 'color_name'];

/**
 * One pixel's record as CSV for worksheets: a header and one row per sphere
 * (the pixel's own columns repeated on each), numbers as the panel shows
 * them, empty cells for "no value".
 */
export function pixelCSV(r) {
  return [...pixelCSVLines(r)].join('');
}

/** pixelCSV's text a line at a time (each with its LF), a sphere's row made when it is read: built in slices for 10,000 spheres. */
export function* pixelCSVLines(r) {
  const n = (x) => (x === null || x === undefined ? '' : formatNumber(x));
  const line = (row) => `${row.map(csvCell).join(',')}\n`;
  const hitName = r.hit ? r.hit.name : '';
  const pixel = [r.x, r.y, formatAngle(r.h), formatAngle(r.v)];
  const after = [hitName, r.hit ? n(r.hit.t) : '', toHex(r.color), colorName(r.color)];
  yield line(CSV_HEAD);
  for (const test of r.tests) {
    const q = test.quadratic, g = test.geometric;
    yield line([...pixel, test.name, n(q.A), n(q.B), n(q.C), n(q.discriminant), q.roots, rootsMeaning(q.roots),
      n(q.t0), n(q.t1), n(g.L.x), n(g.L.y), n(g.L.z), n(g.tca), n(g.d2), n(g.thc), n(g.t0), n(g.t1),
      routesAgree(q, g), ...after]);
  }
  if (r.tests.length === 0) yield line([...pixel, ...CSV_HEAD.slice(4, -4).map(() => ''), ...after]);
}
