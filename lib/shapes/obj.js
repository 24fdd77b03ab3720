/**
 * Wavefront OBJ text → `{ positions, cells }` (a Mesh's data): its `v x y z`
 * lines (vertices) and `f i j k …` lines (faces, counted from 1, or from the
 * end when negative; a face of more than three corners is cut into a fan of
 * triangles). Other statements (normals, texture coordinates, groups,
 * materials) are skipped; a malformed `v` or `f` line is an error naming
 * its line number.
 */
import { show } from '../text/check.js';
import { checkArea } from './triangle.js';

/**
 * A decimal number as OBJ writes one (no hex, no empty field, no "Infinity").
 * One way to match each text: `\d+\.?\d*` let the digits before and after an
 * absent point share a run, retried at every split (40,000 digits: 2 s).
 */
const NUMBER = /^[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?$/;
/** A face corner: a vertex index, maybe followed by /texture and /normal indices. */
const CORNER = /^([+-]?\d+)(\/\d*(\/[+-]?\d*)?)?$/;

/**
 * @param {string} text
 * @returns {{ positions: number[][], cells: number[][], cellLines: number[] }}
 *   `cellLines[i]`: the line number of the face that cells[i] came from
 */
export function parseOBJ(text) {
  if (typeof text !== 'string') throw new TypeError(`OBJ text must be a string, got ${show(text)}`);
  const positions = [], cells = [], cellLines = [];
  let flat = 0, firstFlat = null; // zero-area faces: the Mesh leaves them out, unless every face is one
  const lines = text.replaceAll('\r\n', '\n').replaceAll('\r', '\n').split('\n'); // no pattern: plain text, linear
  for (let i = 0; i < lines.length; i++) {
    const hash = lines[i].indexOf('#');
    const line = (hash < 0 ? lines[i] : lines[i].slice(0, hash)).trim();
    if (!line) continue;
    const [keyword, ...fields] = line.split(/\s+/);
    const where = `OBJ line ${i + 1}`;
    if (keyword === 'v') positions.push(vertex(fields, where, line));
    if (keyword === 'f') {
      const corners = fields.map((field) => corner(field, positions.length, where, line));
      if (corners.length < 3) throw new RangeError(`${where}: a face needs at least 3 vertices "f i j k", got ${show(line)}`);
      for (let k = 1; k + 1 < corners.length; k++) {
        const cell = [corners[0], corners[k], corners[k + 1]];
        try { checkArea(...cell.map((c) => toPoint(positions[c])), `${where}: `); } catch (error) { flat++; firstFlat ??= error; }
        cells.push(cell);
        cellLines.push(i + 1);
      }
    }
  }
  if (!cells.length) throw new RangeError('OBJ text has no faces (lines "f i j k")');
  if (flat === cells.length) throw firstFlat;
  return { positions, cells, cellLines };
}

/** `v x y z [w]`: the three coordinates. */
function vertex(fields, where, line) {
  if ((fields.length !== 3 && fields.length !== 4) || !fields.every((f) => NUMBER.test(f))) {
    throw new RangeError(`${where}: a vertex needs 3 numbers "v x y z", got ${show(line)}`);
  }
  const [x, y, z] = fields.map(Number);
  if (![x, y, z].every(Number.isFinite)) throw new RangeError(`${where}: a vertex's numbers must be finite, got ${show(line)}`);
  return [x, y, z];
}

/** A face corner's vertex, counted from 0 (OBJ counts from 1; −1 is the last vertex so far). */
function corner(field, count, where, line) {
  const match = CORNER.exec(field);
  if (!match) throw new RangeError(`${where}: a face's corners must be vertex numbers like "f 1 2 3", got ${show(line)}`);
  const n = Number(match[1]);
  const index = n < 0 ? count + n : n - 1;
  if (n === 0 || index < 0 || index >= count) {
    throw new RangeError(`${where}: the face refers to vertex ${n}, but ${count === 1 ? 'only 1 vertex is' : `only ${count} vertices are`} defined above it`);
  }
  return index;
}

function toPoint([x, y, z]) {
  return { x, y, z };
}
