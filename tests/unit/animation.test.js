// The animation's pure parts: the FPS counter, the stats line, the worker-count box's reading, comparing frames.
import { describe, it, expect } from 'vitest';
import { framesPerSecond, FrameCounter, statsLine, readWorkerCount, sameBytes } from '../../lib/p5/controls/animation.js';

describe('framesPerSecond', () => {
  it('is 0 with fewer than two frames', () => {
    expect(framesPerSecond([])).toBe(0);
    expect(framesPerSecond([100])).toBe(0);
    expect(framesPerSecond([100, 100])).toBe(0);
  });

  it('counts the gaps between frames over the time they span', () => {
    expect(framesPerSecond([0, 100, 200, 300])).toBeCloseTo(10);
    expect(framesPerSecond([1000, 1500])).toBeCloseTo(2);
  });
});

describe('FrameCounter', () => {
  it('counts every frame and keeps only the last second for the FPS', () => {
    const counter = new FrameCounter();
    for (let t = 0; t <= 2000; t += 50) counter.tick(t);
    expect(counter.frames).toBe(41);
    expect(counter.stamps[0]).toBe(1050); // older than a second before 2000: forgotten
    expect(counter.fps).toBeCloseTo(20);
  });

  it('starts again from nothing', () => {
    const counter = new FrameCounter();
    counter.tick(0);
    counter.tick(10);
    counter.reset();
    expect(counter.frames).toBe(0);
    expect(counter.fps).toBe(0);
  });
});

describe('statsLine', () => {
  it('says which thread made the frames', () => {
    expect(statsLine({ frame: 3, fps: 9.46, time: 1.234 })).toBe('frame 3 · 9.5 FPS · t = 1.23 s · main thread');
    expect(statsLine({ frame: 7, fps: 12, time: 2, workers: 1 })).toBe('frame 7 · 12.0 FPS · t = 2.00 s · 1 worker');
    expect(statsLine({ frame: 7, fps: 12, time: 2, workers: 4 })).toMatch(/· 4 workers$/);
  });
});

describe('readWorkerCount', () => {
  it('reads a whole number in range', () => {
    expect(readWorkerCount('4')).toBe(4);
    expect(readWorkerCount(' 8 ')).toBe(8);
    expect(readWorkerCount('1')).toBe(1);
    expect(readWorkerCount('12', { max: 16 })).toBe(12);
  });

  it('says what was typed when it is not a worker count', () => {
    expect(() => readWorkerCount('9')).toThrow('workers must be a whole number from 1 to 8, got "9"');
    expect(() => readWorkerCount('0')).toThrow(RangeError);
    expect(() => readWorkerCount('2.5')).toThrow(/got "2.5"/);
    expect(() => readWorkerCount('two')).toThrow(/got "two"/);
    expect(() => readWorkerCount('  ')).toThrow(/got nothing$/);
  });
});

describe('sameBytes', () => {
  it('is true only for the same bytes, in the same number', () => {
    const a = new Uint8ClampedArray([1, 2, 3, 255]);
    expect(sameBytes(a, new Uint8ClampedArray([1, 2, 3, 255]))).toBe(true);
    expect(sameBytes(a, new Uint8ClampedArray([1, 2, 4, 255]))).toBe(false);
    expect(sameBytes(a, new Uint8ClampedArray([1, 2, 3]))).toBe(false);
  });
});
