/**
 * A bounding volume hierarchy: boxes within boxes around a list of items
 * (a mesh's triangles), so that a ray tests the items of the few boxes it
 * passes through instead of every item: about log₂(n) boxes deep, not n.
 *
 * Built once by the surface area heuristic over BINS bins per node: a box
 * is split where the children's (surface area × item count) is smallest,
 * the odds of a random ray entering a box going with its area. Kept in typed
 * arrays: `boxes` (Float64Array, 6 numbers a node: min x y z, max x y z),
 * `nodes` (Int32Array, 2 a node: for a leaf its first item in `order` and
 * its count; for an inner node its first child, the second next to it, and 0).
 * Traversal is a loop over a stack preallocated to the tree's depth: no
 * allocation per ray.
 */

import { triangleHit } from './triangle.js';

/** Bins per split along an axis. */
const BINS = 12;
/** A leaf holds at most this many items (unless they cannot be told apart). */
const MAX_LEAF = 8;
/** The cost of testing a box, against 1 for testing an item. */
const BOX_COST = 1;
/**
 * A box is grown by this much of its size on every side: a hit found by
 * an item's test exactly on the box's face is never lost to rounding in the slab test.
 */
const PAD = 1e-9;

export class BVH {
  /**
   * @param {Float64Array} itemBoxes 6 numbers per item: its box, min x y z then max x y z
   */
  constructor(itemBoxes) {
    const count = itemBoxes.length / 6;
    if (!(count >= 1) || !Number.isInteger(count)) throw new RangeError('a BVH needs at least one item, 6 numbers each');
    this.itemBoxes = itemBoxes;
    this.count = count;
    this.order = new Int32Array(count).map((_, i) => i);
    this.boxes = new Float64Array(6 * (2 * count - 1));
    this.nodes = new Int32Array(2 * (2 * count - 1));
    this.nodeCount = 1;
    this.depth = build(this);
    this.stack = new Int32Array(this.depth + 2);
    this.stackT = new Float64Array(this.depth + 2);
    this.state = new Float64Array(9); // the ray (origin, direction, tMin), then the best t and item so far
    this.t = Infinity;
  }

  /**
   * The nearest triangle hit past tMin, the items being triangles: `corners`
   * holds 9 numbers for each, in the tree's order (item order[k] at 9k):
   * corner a, edges e1 and e2 (see triangleHit). Returns the item's index
   * (−1 when none) and leaves its t in `this.t` (Infinity when none): a
   * number returned from a call the engine does not inline costs an
   * allocation, an index does not. `stats`, when given, counts `boxTests`,
   * `boxesEntered` (and lists them in `entered`) and `itemTests`; a tie goes
   * to the lowest item index, as in a loop over every item.
   */
  nearest(ray, tMin, corners, stats = null) {
    const o = ray.origin, d = ray.direction, state = this.state;
    state[0] = o.x; state[1] = o.y; state[2] = o.z; state[3] = d.x; state[4] = d.y; state[5] = d.z; state[6] = tMin;
    return this.walk(corners, stats);
  }

  /** `nearest` for the ray from (ox, oy, oz) along (dx, dy, dz), in numbers (render()'s kernel calls it so). */
  nearestAlong(ox, oy, oz, dx, dy, dz, tMin, corners) {
    const state = this.state;
    state[0] = ox; state[1] = oy; state[2] = oz; state[3] = dx; state[4] = dy; state[5] = dz; state[6] = tMin;
    return this.walk(corners, null);
  }

  /** `nearest` for the ray in state[0…6]: its numbers pass in a Float64Array, never boxed. */
  walk(corners, stats) {
    const { boxes, nodes, order, stack, stackT, state } = this;
    const ox = state[0], oy = state[1], oz = state[2], ix = 1 / state[3], iy = 1 / state[4], iz = 1 / state[5];
    state[7] = Infinity; state[8] = -1;
    const tLo = state[6]; // tMin as a float64 from here on (a tagged argument mixed into the slab tests' numbers would box them)
    let top = 0;
    const rootT = enterBox(boxes, 0, ox, oy, oz, ix, iy, iz, tLo, Infinity);
    if (stats) stats.boxTests++;
    if (rootT !== Infinity) { stack[0] = 0; stackT[0] = rootT; top = 1; }
    while (top > 0) {
      top--;
      if (stackT[top] > state[7]) continue; // a hit nearer than this box was found meanwhile
      const node = stack[top], first = nodes[2 * node], n = nodes[2 * node + 1];
      if (stats) { stats.boxesEntered++; stats.entered.push(node); }
      if (n > 0) {
        hitLeaf(corners, order, first, n, state);
        if (stats) stats.itemTests += n;
        continue;
      }
      const best = state[7];
      const tLeft = enterBox(boxes, first, ox, oy, oz, ix, iy, iz, tLo, best);
      const tRight = enterBox(boxes, first + 1, ox, oy, oz, ix, iy, iz, tLo, best);
      if (stats) stats.boxTests += 2;
      // the nearer child goes on top, so it is entered first
      const nearFirst = tLeft <= tRight;
      const far = nearFirst ? first + 1 : first, tFar = nearFirst ? tRight : tLeft;
      const near = nearFirst ? first : first + 1, tNear = nearFirst ? tLeft : tRight;
      if (tFar !== Infinity) { stack[top] = far; stackT[top] = tFar; top++; }
      if (tNear !== Infinity) { stack[top] = near; stackT[top] = tNear; top++; }
    }
    this.t = state[7];
    return state[8];
  }

  /** Node `i`'s box as `{ min, max }` (the inspector draws the boxes a ray entered). */
  box(i) {
    const b = this.boxes, j = 6 * i;
    return { min: { x: b[j], y: b[j + 1], z: b[j + 2] }, max: { x: b[j + 3], y: b[j + 4], z: b[j + 5] } };
  }
}

/**
 * Tests the triangles of a leaf, items first…first+n−1; a nearer hit
 * (or as near, of a lower index) goes into state[7] (t) and state[8] (item).
 * Numbers travel in `state`, a Float64Array: none is boxed on the way.
 */
function hitLeaf(corners, order, first, n, state) {
  const ox = state[0], oy = state[1], oz = state[2], dx = state[3], dy = state[4], dz = state[5], tMin = state[6];
  for (let k = first; k < first + n; k++) {
    const j = 9 * k;
    const t = triangleHit(corners[j], corners[j + 1], corners[j + 2], corners[j + 3], corners[j + 4], corners[j + 5],
      corners[j + 6], corners[j + 7], corners[j + 8], ox, oy, oz, dx, dy, dz, tMin);
    if (t < state[7] || (t === state[7] && t !== Infinity && order[k] < state[8])) { state[7] = t; state[8] = order[k]; }
  }
}

/**
 * The slab test (as for a Box) on node `i`'s box: where the ray enters it
 * (tMin if it starts inside), or Infinity when it misses the box, leaves it
 * before tMin or enters it beyond `best`. A zero direction component gives
 * an infinite 1/d; where that meets a box face exactly (0·∞ = NaN) the
 * comparisons below ignore that axis, keeping the box: never a hit lost.
 */
function enterBox(boxes, i, ox, oy, oz, ix, iy, iz, tMin, best) {
  const j = 6 * i;
  let tNear = tMin, tFar = best;
  let lo = (boxes[j] - ox) * ix, hi = (boxes[j + 3] - ox) * ix;
  if (lo > hi) { const s = lo; lo = hi; hi = s; }
  if (lo > tNear) tNear = lo;
  if (hi < tFar) tFar = hi;
  lo = (boxes[j + 1] - oy) * iy; hi = (boxes[j + 4] - oy) * iy;
  if (lo > hi) { const s = lo; lo = hi; hi = s; }
  if (lo > tNear) tNear = lo;
  if (hi < tFar) tFar = hi;
  lo = (boxes[j + 2] - oz) * iz; hi = (boxes[j + 5] - oz) * iz;
  if (lo > hi) { const s = lo; lo = hi; hi = s; }
  if (lo > tNear) tNear = lo;
  if (hi < tFar) tFar = hi;
  return tNear <= tFar ? tNear : Infinity;
}

/** Builds the tree into `bvh` (root: node 0, every item); returns its depth. */
function build(bvh) {
  const work = [[0, 0, bvh.count, 1]]; // node, first item, end, depth
  const scratch = {
    counts: new Int32Array(BINS), bins: new Float64Array(6 * BINS), left: new Float64Array(BINS), right: new Float64Array(BINS),
    centres: new Float64Array(6), box: new Float64Array(6),
  };
  let depth = 1;
  while (work.length) {
    const [node, start, end, level] = work.pop();
    depth = Math.max(depth, level);
    boundItems(bvh, start, end, bvh.boxes, 6 * node, true);
    const mid = end - start > 1 ? split(bvh, node, start, end, scratch) : -1;
    if (mid < 0) {
      bvh.nodes[2 * node] = start;
      bvh.nodes[2 * node + 1] = end - start;
      continue;
    }
    const left = bvh.nodeCount;
    bvh.nodeCount += 2;
    bvh.nodes[2 * node] = left;
    bvh.nodes[2 * node + 1] = 0;
    work.push([left, start, mid, level + 1], [left + 1, mid, end, level + 1]);
  }
  return depth;
}

/**
 * Where to split items start…end of `node` (reordering `order` so the left
 * child's come first): the index of the first right item, or −1 for a leaf.
 */
function split(bvh, node, start, end, { counts, bins, left, right, centres: c, box }) {
  const { order, itemBoxes } = bvh, n = end - start;
  // c: the box around the items' centres
  boundItems(bvh, start, end, c, 0, false);
  const extents = [c[3] - c[0], c[4] - c[1], c[5] - c[2]];
  const axis = extents.indexOf(Math.max(...extents));
  const lo = c[axis], size = extents[axis];
  if (!(size > 0)) return n > MAX_LEAF ? start + (n >> 1) : -1; // all centres in one spot: halve a big list anyhow
  const binOf = (item) => Math.min(BINS - 1, Math.floor((BINS * (centre(itemBoxes, item, axis) - lo)) / size));
  counts.fill(0);
  for (let b = 0; b < BINS; b++) emptyBox(bins, 6 * b);
  for (let k = start; k < end; k++) {
    const b = binOf(order[k]);
    counts[b]++;
    growBox(bins, 6 * b, itemBoxes, 6 * order[k]);
  }
  sweep(bins, counts, left, 1, box);
  sweep(bins, counts, right, -1, box);
  let bestCost = Infinity, bestBin = -1;
  for (let b = 0, nLeft = 0; b < BINS - 1; b++) {
    nLeft += counts[b];
    const cost = left[b] + right[b + 1];
    if (nLeft > 0 && nLeft < n && cost < bestCost) { bestCost = cost; bestBin = b; }
  }
  const leafCost = n * area(bvh.boxes, 6 * node);
  if (bestBin < 0 || (n <= MAX_LEAF && leafCost <= BOX_COST * area(bvh.boxes, 6 * node) + bestCost)) {
    return n > MAX_LEAF ? start + (n >> 1) : -1;
  }
  let mid = start; // partition: the bins up to bestBin to the left
  for (let k = start; k < end; k++) {
    if (binOf(order[k]) <= bestBin) { const s = order[k]; order[k] = order[mid]; order[mid] = s; mid++; }
  }
  return mid;
}

/**
 * `out[b]` = (surface area × item count) of the box around bins 0…b
 * (`direction` 1) or b…BINS−1 (`direction` −1); `box` is scratch.
 */
function sweep(bins, counts, out, direction, box) {
  emptyBox(box, 0);
  let n = 0;
  for (let i = 0; i < BINS; i++) {
    const b = direction > 0 ? i : BINS - 1 - i;
    if (counts[b]) { growBox(box, 0, bins, 6 * b); n += counts[b]; }
    out[b] = n ? area(box, 0) * n : 0;
  }
}

/** The box around items start…end (their boxes, or their centres), padded, into out[at…at+5]. */
function boundItems(bvh, start, end, out, at, padded) {
  const { order, itemBoxes } = bvh;
  emptyBox(out, at);
  for (let k = start; k < end; k++) {
    const j = 6 * order[k];
    for (let a = 0; a < 3; a++) {
      const lo = padded ? itemBoxes[j + a] : centre(itemBoxes, order[k], a);
      const hi = padded ? itemBoxes[j + 3 + a] : lo;
      if (lo < out[at + a]) out[at + a] = lo;
      if (hi > out[at + 3 + a]) out[at + 3 + a] = hi;
    }
  }
  if (!padded) return;
  let size = 0; // one pad for every axis, from the box's largest size: a flat box gets one too
  for (let a = 0; a < 6; a++) size = Math.max(size, Math.abs(out[at + a]), a < 3 ? out[at + 3 + a] - out[at + a] : 0);
  for (let a = 0; a < 3; a++) {
    out[at + a] -= PAD * size;
    out[at + 3 + a] += PAD * size;
  }
}

function centre(itemBoxes, item, axis) {
  return (itemBoxes[6 * item + axis] + itemBoxes[6 * item + 3 + axis]) / 2;
}

function emptyBox(box, at) {
  for (let a = 0; a < 3; a++) { box[at + a] = Infinity; box[at + 3 + a] = -Infinity; }
}

function growBox(box, at, from, j) {
  for (let a = 0; a < 3; a++) {
    if (from[j + a] < box[at + a]) box[at + a] = from[j + a];
    if (from[j + 3 + a] > box[at + 3 + a]) box[at + 3 + a] = from[j + 3 + a];
  }
}

/** Half the surface area of a box (the heuristic only compares areas). */
function area(box, at) {
  const x = box[at + 3] - box[at], y = box[at + 4] - box[at + 1], z = box[at + 5] - box[at + 2];
  return x * y + y * z + z * x;
}
