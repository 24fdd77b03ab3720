/**
 * Heap bytes per ray of Mesh#hit on the bunny, in a fresh process (bench/bvh.js runs it several
 * times): the goal is none. V8 compiles the traversal on a background thread and does not always
 * make the same code: some runs box numbers (~150–700 bytes a ray). A unit test of this was
 * flaky for that reason, so the bench reports it, over runs, instead.
 */
import { bytesAllocatedBy } from '../tests/shared/heap.js';
import bunny from 'bunny';
import { Mesh } from '../lib/shapes/mesh.js';
import { Ray } from '../lib/math/ray.js';

const mesh = new Mesh(bunny);
let seed = 5; const rnd = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
const b = mesh.bounds(); const rays = [];
for (let i = 0; i < 2000; i++) { const o = [b.min.x + (b.max.x - b.min.x) * rnd(), b.min.y + (b.max.y - b.min.y) * rnd(), 20]; rays.push(new Ray(o, [rnd() - 0.5, rnd() - 0.5, -1])); }
const run = () => { for (const ray of rays) mesh.hit(ray); };
for (let i = 0; i < 20; i++) run();
const bytes = bytesAllocatedBy(() => { for (let i = 0; i < 10; i++) run(); });
console.log((bytes / 20000).toFixed(2));
