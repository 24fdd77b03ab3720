/**
 * The packed layout render()'s fast kernel (lib/tracing/kernel.js) reads shapes in,
 * in a module of its own below both the kernel and the shapes: each shape
 * class writes its own numbers and does its own numbers-only hit and normal,
 * and neither imports the other.
 *
 * A shape class that the kernel can run has a static `packed`:
 * `{ pack(shape, shapes, at, tables), hit(shapes, at, ox, oy, oz, dx, dy, dz, tMin), normal(shapes, at, surface) }`:
 * `pack` writes at most KIND numbers from `shapes[at]`; `hit` is its `hit`
 * in numbers (the same t, bit for bit); `normal` reads the point at
 * `surface[P…]` and writes its `normalAt` into `surface[N…]`.
 *
 * A shape that needs more than six numbers (a triangle's corner, edges and
 * normal; a mesh's tree) pushes what it needs onto the scene's side `tables`
 * (a list, one per packed scene) and writes its index among its own numbers.
 * Its `hit` and `normal` find that list in `sideTables.current`: the kernel
 * sets it once per primary ray (one store; the hit tests of spheres, planes
 * and boxes never read it), rather than pass one more argument to every hit
 * test of every shape.
 */

/** Numbers per shape in the kernel's `shapes` array: up to six of the shape's own, then its kind. */
export const SHAPE = 7;

/** Where among a shape's numbers its kind lies: the kernel's index of its class's `packed`. */
export const KIND = 6;

/** The side tables of the scene the kernel is tracing now (see above). */
export const sideTables = { current: [] };

/** Where the hit point P and the unit normal N lie in the kernel's `surface` record. */
export const P = 0, N = 3;

/**
 * Checks a module's literal copies of layout offsets against the module that
 * owns them, and throws at load when one differs, naming it. The hot loops
 * (lib/tracing/kernel.js, a shape's numbers-only hit and normal) keep copies because
 * V8 folds a module's own literal constant into them but reads an imported
 * one from its module at every use: render() of the class scene ran 6–7 %
 * slower on imported offsets (docs/performance.md).
 * @param {Record<string, number>} copies the copies, by their owner's names
 * @param {Record<string, any>} owner what the owning module exports
 * @param {string} where the owning module, for the message
 */
export function checkCopies(copies, owner, where) {
  for (const [name, value] of Object.entries(copies)) {
    if (owner[name] !== value) throw new Error(`${name} is ${value} in a copy of ${where}'s layout, which says ${owner[name]}: change the copy`);
  }
}

/**
 * Every number the kernel writes per pixel lives in one buffer of its own,
 * `GUARD` empty bytes from either end. Workers are threads of one process,
 * and in Chromium two workers' small buffers could lie side by side on one
 * cache line: each write by one then stalled the other (false sharing), and
 * two workers ran at half speed (docs/performance.md).
 */
const GUARD = 256; // more than a cache line and the neighbour the CPU fetches with it
const scratch = new ArrayBuffer(4096);
let scratchUsed = GUARD;

/** `count` numbers of the kernel's scratch buffer. */
export function scratchNumbers(count) {
  const numbers = new Float64Array(scratch, scratchUsed, count);
  scratchUsed += count * Float64Array.BYTES_PER_ELEMENT;
  if (scratchUsed > scratch.byteLength - GUARD) throw new Error('lib/shapes/packed.js: the scratch buffer is too small');
  return numbers;
}
