// For tests that a reader of typed text takes time in proportion to its length:
// the ratio of its times on two lengths, not an absolute time (the machine is noisy).

/**
 * Milliseconds per call of `read(makeText(n))`, the median of several batches
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
  return times.sort((a, b) => a - b)[3];
}

/**
 * How much longer `read` takes on 10⁵ characters than on 10³: about 100 when
 * linear, 10,000 when quadratic. A warm-up first, so the JIT is not timed.
 */
export function timeRatio(read, makeText) {
  perCall(read, makeText, 1e3);
  return perCall(read, makeText, 1e5) / perCall(read, makeText, 1e3);
}

/** Runs `read`, swallowing what it throws (a refusal is a result too). */
export const quietly = (read) => (text) => { try { read(text); } catch { /* timed all the same */ } };
