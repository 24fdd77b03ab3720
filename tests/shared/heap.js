/**
 * Bytes allocated on the JS heap while `work` runs: what the heap grew by,
 * plus what every garbage collection meanwhile freed. For the allocation
 * test and the benchmarks that report allocation (Node only).
 */
import { GCProfiler, getHeapStatistics } from 'node:v8';

export function bytesAllocatedBy(work) {
  const profiler = new GCProfiler();
  profiler.start();
  const before = getHeapStatistics().used_heap_size;
  work();
  const after = getHeapStatistics().used_heap_size;
  const freed = profiler.stop().statistics
    .reduce((sum, gc) => sum + gc.beforeGC.heapStatistics.usedHeapSize - gc.afterGC.heapStatistics.usedHeapSize, 0);
  return after - before + freed;
}
