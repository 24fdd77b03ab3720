/**
 * The path tracer's per-sample numbers in one buffer of their own, with empty
 * guard bytes at either end (as lib/shapes/packed.js does for the kernel):
 * two workers' small arrays on one cache line would stall each other.
 */
const GUARD = 256;
const buffer = new ArrayBuffer(2048);
let used = GUARD;

/** `count` numbers of the path tracer's scratch buffer. */
export function pathNumbers(count) {
  const numbers = new Float64Array(buffer, used, count);
  used += count * Float64Array.BYTES_PER_ELEMENT;
  if (used > buffer.byteLength - GUARD) throw new Error('lib/tracing/pathtrace/scratch.js: the scratch buffer is too small');
  return numbers;
}
