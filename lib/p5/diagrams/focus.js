/** Which sphere a pixel's diagrams explain: the discriminant mode's choice, by the same function. */
import { sphereFocus } from '../../tracing/modes.js';

/**
 * The sphere test of a record (inspectPixel) worth explaining: the one
 * `sphereFocus` (lib/tracing/modes.js) picks for the record's ray — the nearest sphere
 * the ray hits, even behind a plane or box, else its closest miss. Null when
 * the record has no sphere tests.
 */
export function focusTest(record) {
  const tests = record?.tests ?? [];
  if (!tests.length) return null;
  return tests[sphereFocus(tests.map((t) => t.sphere), record.ray)] ?? null;
}
