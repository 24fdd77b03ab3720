/**
 * `apart(fn, a, b, c, d, e)` calls fn(a, b, c, d, e) from one call site that has
 * seen many functions (five no-ops, when the module loads), so V8 inlines
 * none of the functions called through it: each is compiled on its own,
 * with the small functions it calls inlined in it.
 *
 * Why: V8 inlines a function's callees only up to a budget (920 bytes of
 * bytecode). The path tracer's loop calls more than that per bounce (the hit
 * tests of each kind of shape, the glass lobe with Snell and Schlick); what
 * falls past the budget stays a real call, and V8 boxes every number passed
 * to or returned from a real call: hundreds of bytes a sample, in some runs
 * and not others. Called through here, with objects and whole numbers only
 * as arguments, the heavy steps cost a call and allocate nothing.
 */
export function apart(fn, a, b, c, d, e) {
  fn(a, b, c, d, e);
}

const NO_OPS = [() => {}, () => {}, () => {}, () => {}, () => {}];
for (let round = 0; round < 32; round++) for (const fn of NO_OPS) apart(fn);
