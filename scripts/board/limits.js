/**
 * How much one laptop may send: a bucket of `burst` sends that fills again at
 * `perSecond`. A student sends a few a minute; a page in a loop, or a
 * script, empties its bucket and is told when to send again (the page says
 * so and sends it then). Buckets are kept per laptop id and per network
 * address (a script may make up ids, not addresses).
 */

/** A laptop: 30 at once, then one a second. */
export const LAPTOP_LIMIT = { burst: 30, perSecond: 1 };
/** One network address (a classroom's laptops each have one; a NAT shares one): 600 at once, then 30 a second. */
export const ADDRESS_LIMIT = { burst: 600, perSecond: 30 };

export class RateLimit {
  #buckets = new Map();

  /** @param {{ burst: number, perSecond: number, now?: () => number }} options */
  constructor({ burst, perSecond, now = () => performance.now() }) {
    this.burst = burst;
    this.perSecond = perSecond;
    this.now = now;
  }

  /**
   * Takes one send from `key`'s bucket.
   * @returns {number} 0 when allowed, else the seconds to wait (rounded up)
   */
  take(key) {
    const t = this.now();
    const bucket = this.#buckets.get(key) ?? { tokens: this.burst, at: t };
    bucket.tokens = Math.min(this.burst, bucket.tokens + ((t - bucket.at) / 1000) * this.perSecond);
    bucket.at = t;
    this.#buckets.delete(key); // re-inserted: the map stays in order of last use
    this.#buckets.set(key, bucket);
    if (this.#buckets.size > 10_000) this.#buckets.delete(this.#buckets.keys().next().value); // the least recently used
    if (bucket.tokens >= 1) {
      bucket.tokens -= 1;
      return 0;
    }
    return Math.ceil((1 - bucket.tokens) / this.perSecond);
  }
}
