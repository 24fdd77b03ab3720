/**
 * Heap bytes per ray of Mesh#hit on the bunny, in a fresh process (bench/bvh.js runs it several
 * times): the goal is none. V8 compiles the traversal on a background thread and does not always
 * make the same code: some runs box numbers (~150–700 bytes a ray). A unit test of this was
 * flaky for that reason, so the bench reports it, over runs, instead.
 */
import { GCProfiler, getHeapStatistics } from 'node:v8';
import bunny from 'bunny';
import { Mesh } from '../lib/shapes/mesh.js';
import { Ray } from '../lib/math/ray.js';

const mesh = new Mesh(bunny);
let seed = 5; const rnd = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
const b = mesh.bounds(); const rays = [];
for (let i = 0; i < 2000; i++) { const o = [b.min.x + (b.max.x - b.min.x) * rnd(), b.min.y + (b.max.y - b.min.y) * rnd(), 20]; rays.push(new Ray(o, [rnd() - 0.5, rnd() - 0.5, -1])); }
const run = () => { for (const ray of rays) mesh.hit(ray); };
for (let i = 0; i < 20; i++) run();
const profiler = new GCProfiler(); profiler.start();
const before = getHeapStatistics().used_heap_size; for (let i = 0; i < 10; i++) run(); const after = getHeapStatistics().used_heap_size;
const freed = profiler.stop().statistics.reduce((s, gc) => s + gc.beforeGC.heapStatistics.usedHeapSize - gc.afterGC.heapStatistics.usedHeapSize, 0);
console.log(((after - before + freed) / 20000).toFixed(2));
