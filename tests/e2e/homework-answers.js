/**
 * What a student must not get: the homework pages, their solution files, and
 * the solutions' own numbers as a minifier writes them (`[1,.1,.05]`), to
 * look for in what is built or served.
 */
import { readFileSync } from 'node:fs';

export { ELSEWHERE } from '../../scripts/classroom.js';

export const HOMEWORK = [
  { page: '08-homework-traffic-signal.html', script: 'sketches/08-homework-traffic-signal.js', solution: 'sketches/solutions/08-traffic-signal.js', ownLabel: 'Your traffic signal' },
  { page: '09-homework-rear-lights.html', script: 'sketches/09-homework-rear-lights.js', solution: 'sketches/solutions/09-rear-lights.js', ownLabel: 'Your car, seen from behind' },
];

const numberArrays = (text) => [...text.matchAll(/\[\s*-?[\d.]+(\s*,\s*-?[\d.]+)+\s*\]/g)].map((m) => m[0]);
const minified = (array) => `[${JSON.parse(array).map((n) => String(n).replace(/^(-?)0\./, '$1.')).join(',')}]`;

/** The number arrays of a solution that its starter does not have, minified. */
export function answerFingerprints(solution) {
  const starter = new Set(HOMEWORK.flatMap((hw) => numberArrays(readFileSync(hw.script, 'utf8'))).map(minified));
  return [...new Set(numberArrays(readFileSync(solution, 'utf8')).map(minified))].filter((a) => !starter.has(a));
}
