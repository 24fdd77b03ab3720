// For tests that a reader of typed text takes time in proportion to its length:
// the ratio of its times on two lengths, not an absolute time (the machine is noisy).
// A busy machine only ever adds time, so each length is timed by its fastest batch,
// and a ratio that looks too high is measured again: a quadratic reader is ~100 times
// over the tests' caps on every try, a linear one under them on most.

/**
 * Milliseconds per call of `read(makeText(n))`, the fastest of several batches
 * (a batch is long enough for the clock, however short one call is).
 */
function perCall(read, makeText, n) {
  const text = makeText(n);
  const reps = Math.max(1, Math.round(2e5 / n));
  const times = [];
  for (let run = 0; run < 7; run++) {
    const start = performance.now();
    for (let i = 0; i < reps; i++) read(text);
    times.push((performance.now() - start) / reps);
  }
  return Math.min(...times);
}

/** Above this a ratio is measured again (linear is ~100; the tests' caps are 400). */
const LOOKS_HIGH = 200;
const TRIES = 3;

/**
 * How much longer `read` takes on 10⁵ characters than on 10³: about 100 when
 * linear, 10,000 when quadratic; the least of up to three tries. A warm-up
 * first, so the JIT is not timed.
 */
export function timeRatio(read, makeText) {
  perCall(read, makeText, 1e3);
  let least = Infinity;
  for (let attempt = 0; attempt < TRIES && least > LOOKS_HIGH; attempt++) {
    least = Math.min(least, perCall(read, makeText, 1e5) / perCall(read, makeText, 1e3));
  }
  return least;
}

/** Runs `read`, swallowing what it throws (a refusal is a result too). */
export const quietly = (read) => (text) => { try { read(text); } catch { /* timed all the same */ } };
