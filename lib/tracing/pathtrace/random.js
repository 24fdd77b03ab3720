/**
 * The path tracer's random numbers: a sequence seeded by (seed, x, y, s)
 * alone, so sample s of pixel (x, y) draws the same numbers on any thread,
 * in any order, on any split of the frame over workers.
 *
 * The seed is a chain of PCG hashes (Jarzynski and Olano, "Hash Functions for
 * GPU Rendering", 2020: one step of a 32-bit linear congruential generator,
 * then PCG's output permutation); each draw steps the generator once more and
 * permutes its state. 32-bit integer arithmetic only (Math.imul, >>>), the
 * same in a WebGL2 shader, and no allocation: the state lives in a typed array.
 */

const MULTIPLIER = 747796405, INCREMENT = 2891336453;
const PERMUTE = 277803737;
const TWO_TO_32 = 4294967296;

/** PCG's output permutation of a 32-bit state (random-xorshift, multiply, xorshift). */
function permute(state) {
  const word = Math.imul((state >>> ((state >>> 28) + 4)) ^ state, PERMUTE);
  return ((word >>> 22) ^ word) >>> 0;
}

/**
 * pcg_hash: a well-mixed 32-bit number from any 32-bit input.
 * @param {number} input a whole number (taken modulo 2³²)
 * @returns {number} 0 … 2³² − 1
 * @example
 * pcgHash(0) !== pcgHash(1); // true: neighbouring inputs land far apart
 */
export function pcgHash(input) {
  return permute((Math.imul(input >>> 0, MULTIPLIER) + INCREMENT) >>> 0);
}

/** One generator, reseeded for every sample; `next()` draws from it. */
export class PathRandom {
  #state = new Uint32Array(1);

  /**
   * Starts the sequence of sample `s` of pixel (x, y) under `seed`.
   * @returns {PathRandom} this
   */
  start(seed, x, y, s) {
    this.#state[0] = pcgHash(seed ^ pcgHash(x ^ pcgHash(y ^ pcgHash(s))));
    return this;
  }

  /**
   * The next number of the sequence, uniform in [0, 1).
   * @returns {number}
   */
  next() {
    const state = this.#state;
    state[0] = Math.imul(state[0], MULTIPLIER) + INCREMENT; // the typed array keeps it modulo 2³²
    return permute(state[0]) / TWO_TO_32;
  }

  /**
   * The next `count` numbers of the sequence into `out[0 …]`: the tracer's
   * way, since a number returned from a call V8 does not inline is boxed.
   */
  draw(out, count) {
    const state = this.#state;
    for (let i = 0; i < count; i++) {
      state[0] = Math.imul(state[0], MULTIPLIER) + INCREMENT;
      out[i] = permute(state[0]) / TWO_TO_32;
    }
  }
}
