import { describe, it, expect } from 'vitest';
import { bytesAllocatedBy } from '../shared/heap.js';
import { execFileSync } from 'node:child_process';
import { Camera, classScene, render } from '../../lib/index.js';

describe('tracing allocates nothing per pixel', () => {
  it('even when the page holds an { x, y, z } literal with non-numbers in it (importing p5 2.3 is enough)', () => {
    // V8 shares one hidden class among all such literals: were vectors literals
    // too, their coordinates would now be stored boxed, one allocation per write.
    globalThis.someSketchsPoint = { x: 'left', y: null, z: undefined };
    const scene = classScene(), camera = new Camera({ width: 160, height: 120 });
    const target = new Uint8ClampedArray(160 * 120 * 4);
    for (let i = 0; i < 60; i++) render(scene, camera, target); // warm up: the optimised code is the one that allocates nothing
    const frames = 10, pixels = frames * 160 * 120;
    const bytes = bytesAllocatedBy(() => { for (let i = 0; i < frames; i++) render(scene, camera, target); });
    // Boxed coordinates cost some 350 bytes a pixel; a frame's tile lists, about 1.
    expect(bytes / pixels).toBeLessThan(100);
  });
});

describe('path tracing allocates nothing per sample', () => {
  it('in a room of a plane, a box, balls, a fuzzy mirror, glass and a lamp, after another scene has run', () => {
    // V8 decides per process what it inlines and when the optimised code comes in; on a busy machine some
    // processes keep a call that boxes every number it passes (over 100 bytes a path) whatever the warm-up.
    // Each try is a fresh process (tests/shared/path-allocation.js); the least of them is the code's own.
    let least = Infinity;
    for (let attempt = 0; attempt < 5 && least >= 4; attempt++) { // stops at the first try under 4
      const printed = execFileSync(process.execPath, ['tests/shared/path-allocation.js'], { encoding: 'utf8' });
      least = Math.min(least, Number(printed));
    }
    // A boxed number per hit test or bounce costs hundreds of bytes a path; the frame itself (its bytes,
    // packed scene) some 30 kB in all, about 1 byte a path of this small frame.
    expect(least, `bytes a path, the least of the tries`).toBeLessThan(4);
  }, 120_000);
});
