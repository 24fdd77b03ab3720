import { describe, it, expect } from 'vitest';
import { ProgressiveRenderer, CHECK_EVERY, COARSE_PASSES } from '../../lib/tracing/frames.js';
import { render, Camera, Scene, Sphere, Plane, Box, PointLight, classScene } from '../../lib/index.js';
import { renderPixel } from '../../lib/tracing/render.js';

const ORDERS = ['coarse', 'scanline', 'slow'];

function floorScene() {
  const scene = new Scene({ background: [0.2, 0.3, 0.5], ambient: 0.1 });
  scene.add(new Plane([0, -2, 0], [0, 1, 0], { color: [0.8, 0.8, 0.8], reflection: 0.3 }));
  scene.add(new Box([-3, -2, -14], [-1, 0, -12], { color: 'orange' }));
  scene.add(new Sphere([1.5, -0.5, -12], 1.5, { color: 'pink', specular: 0.6, transparency: 0.4 }));
  scene.add(new PointLight([5, 8, 0], [1, 1, 0.9], 1.2));
  return scene;
}

const SCENES = { class: classScene(), 'class, full shading': classScene({ full: true }), 'plane, box, point light': floorScene() };
const SIZES = [[37, 23], [16, 16], [1, 1], [40, 30], [5, 70], [33, 17]];

/** A clock that moves only when told to: no test here depends on real time. */
function fakeClock() {
  const clock = { t: 0, reads: 0, now: () => { clock.reads++; return clock.t; } };
  return clock;
}

/** Runs a renderer to the end, checking the step contract on the way. */
function finish(p, budgetMs) {
  let guard = 0;
  while (!p.done) {
    const { changed, done } = p.step(budgetMs);
    expect(changed).toBe(true);
    expect(done).toBe(p.done);
    if (++guard > 1e6) throw new Error('never finished');
  }
  return p.buffer;
}

describe('ProgressiveRenderer: the finished picture is render()\'s, byte for byte', () => {
  for (const [name, scene] of Object.entries(SCENES)) {
    for (const [width, height] of SIZES) {
      it(`${name} at ${width}×${height} in every mode`, () => {
        const camera = new Camera({ width, height, fov: 40, position: [0, 1, 0], pitch: -5 });
        const expected = render(scene, camera);
        for (const mode of ORDERS) {
          const clock = fakeClock();
          // The shader advances the clock, so budgets end after a known number of pixels.
          const shader = (...args) => { clock.t += 0.25; renderPixel(...args); };
          const p = new ProgressiveRenderer({ scene, camera, mode, shader, now: clock.now, slowRaysPerStep: 5 });
          expect(finish(p, 3)).toEqual(expected);
        }
      });
    }
  }
});

describe('with the default shader, each primary ray meets only its tile\'s candidate shapes, as in render()', () => {
  /** Counts every ray–shape test the scene's shapes make. */
  function countTests(scene) {
    const counter = { tests: 0 };
    for (const object of scene.objects) {
      const hit = object.hit;
      object.hit = function (...args) { counter.tests++; return hit.apply(this, args); };
    }
    return counter;
  }

  it('finishes with render()\'s picture, byte for byte, in every mode', () => {
    for (const scene of Object.values(SCENES)) {
      for (const [width, height] of [...SIZES, [64, 48]]) {
        const camera = new Camera({ width, height, fov: 50, position: [-1, 2, 1], yaw: 8, pitch: -10 });
        const expected = render(scene, camera);
        for (const mode of ORDERS) {
          const p = new ProgressiveRenderer({ scene, camera, mode, slowRaysPerStep: 7 });
          expect(finish(p, 0)).toEqual(expected);
        }
      }
    }
  });

  it('makes exactly the ray–shape tests render() makes; another shader tests every shape', () => {
    const scene = classScene(), camera = new Camera({ width: 64, height: 48, pitch: -3 });
    const counter = countTests(scene);
    render(scene, camera);
    const byRender = counter.tests;
    for (const mode of ORDERS) {
      counter.tests = 0;
      finish(new ProgressiveRenderer({ scene, camera, mode, slowRaysPerStep: 100 }), 1e9);
      expect(counter.tests).toBe(byRender);
    }
    counter.tests = 0;
    const shader = (...args) => renderPixel(...args); // the same colours, but not the default shader
    finish(new ProgressiveRenderer({ scene, camera, shader }), 1e9);
    expect(counter.tests).toBeGreaterThan(byRender + 64 * 48);
  });

  it('a scene changed in place traces anew on restart(), with its new shapes', () => {
    const scene = classScene(), camera = new Camera({ width: 40, height: 30 });
    const p = new ProgressiveRenderer({ scene, camera });
    finish(p, 0);
    scene.add(new Sphere([-2, 2, -12], 1, { color: 'orange' }));
    scene.objects[1].center.x = 3; // the pink sphere moves right
    p.restart();
    expect(finish(p, 0)).toEqual(render(scene, camera));
  });
});

describe('coarse passes', () => {
  const scene = classScene();

  it('traces each pixel once, in the first pass whose block size divides both x and y', () => {
    const camera = new Camera({ width: 37, height: 23 });
    const passOf = new Map();
    let p;
    const shader = (s, c, x, y, target) => {
      const key = `${x},${y}`;
      expect(passOf.has(key)).toBe(false);
      passOf.set(key, p.blockSize);
      renderPixel(s, c, x, y, target);
    };
    p = new ProgressiveRenderer({ scene, camera, shader });
    finish(p);
    expect(passOf.size).toBe(37 * 23);
    for (let y = 0; y < 23; y++) {
      for (let x = 0; x < 37; x++) {
        const first = COARSE_PASSES.find((s) => x % s === 0 && y % s === 0);
        expect(passOf.get(`${x},${y}`)).toBe(first);
      }
    }
  });

  it('after the 16 px pass every pixel shows the colour of its block\'s traced corner', () => {
    const camera = new Camera({ width: 37, height: 23 });
    const expected = render(scene, camera);
    let p, preview = null;
    const shader = (s, c, x, y, target) => {
      // The buffer as the 16 px pass left it, caught as the 8 px pass begins.
      if (p.blockSize === 8 && !preview) preview = target.slice();
      renderPixel(s, c, x, y, target);
    };
    p = new ProgressiveRenderer({ scene, camera, shader });
    finish(p, 1e9);
    expect(preview).not.toBe(null);
    for (let y = 0; y < 23; y++) {
      for (let x = 0; x < 37; x++) {
        const corner = ((y - (y % 16)) * 37 + (x - (x % 16))) * 4;
        const i = (y * 37 + x) * 4;
        expect([...preview.subarray(i, i + 4)]).toEqual([...expected.subarray(corner, corner + 4)]);
      }
    }
  });

  it('has current null and blockSize counting down 16, 8, 4, 2, 1 (pass, its old name, too)', () => {
    const p = new ProgressiveRenderer({ scene, camera: new Camera({ width: 40, height: 30 }) });
    const seen = [p.blockSize];
    while (!p.step(0).done) {
      expect(p.current).toBe(null);
      expect(p.pass).toBe(p.blockSize);
      if (seen.at(-1) !== p.blockSize) seen.push(p.blockSize);
    }
    expect(seen).toEqual([16, 8, 4, 2, 1]);
  });
});

describe('scanline and slow modes', () => {
  const scene = classScene();
  const camera = new Camera({ width: 37, height: 23 });

  it('scanline traces row by row, left to right, and leaves the rest transparent', () => {
    const order = [];
    const shader = (s, c, x, y, t) => { order.push(y * 37 + x); renderPixel(s, c, x, y, t); };
    const p = new ProgressiveRenderer({ scene, camera, mode: 'scanline', shader });
    p.step(0);
    const n = order.length;
    expect(order).toEqual([...Array(n).keys()]);
    expect(p.current).toEqual({ x: (n - 1) % 37, y: Math.floor((n - 1) / 37) });
    expect(p.row).toBe(Math.floor(n / 37));
    expect(p.blockSize).toBe(1); // one pixel at a time, in rows
    expect(p.pass).toBe(p.row); // the old name: the row, in this order
    for (let i = 0; i < 37 * 23; i++) expect(p.buffer[i * 4 + 3]).toBe(i < n ? 255 : 0);
  });

  it('slow traces exactly slowRaysPerStep pixels per step, whatever the budget and the clock', () => {
    for (const perStep of [1, 3, 50]) {
      const clock = fakeClock();
      let traced = 0;
      const shader = (...args) => { traced++; clock.t += 1000; renderPixel(...args); };
      const p = new ProgressiveRenderer({ scene, camera, mode: 'slow', shader, slowRaysPerStep: perStep, now: clock.now });
      let before = 0, k = 0;
      while (!p.done) {
        p.step(k++ % 2 ? 0 : 1e6);
        expect(traced - before).toBe(Math.min(perStep, 37 * 23 - before));
        expect(p.current).toEqual({ x: (traced - 1) % 37, y: Math.floor((traced - 1) / 37) });
        before = traced;
      }
      expect(traced).toBe(37 * 23);
    }
  });

  it('slowRaysPerStep can change on restart', () => {
    const p = new ProgressiveRenderer({ scene, camera, mode: 'slow' });
    p.step();
    expect(p.traced).toBe(1);
    p.restart({ slowRaysPerStep: 4 });
    p.step();
    expect(p.traced).toBe(4);
  });

  it('with slowRaysPerSecond, slow traces the rays owed by the clock: fewer than one a step, and the same picture', () => {
    const clock = fakeClock();
    const p = new ProgressiveRenderer({ scene, camera, mode: 'slow', now: clock.now });
    p.slowRaysPerSecond = 4; // one ray every 250 ms
    expect(p.step()).toEqual({ changed: true, done: false }); // the first ray at once
    expect(p.traced).toBe(1);
    clock.t += 100;
    expect(p.step().changed).toBe(false);
    clock.t += 100;
    p.step();
    expect(p.traced).toBe(1);
    clock.t += 60;
    p.step();
    expect(p.traced).toBe(2);
    clock.t += 60_000; // a long pause (a hidden tab) does not become a burst
    p.step();
    expect(p.traced).toBe(3);
    while (!p.done) { clock.t += 250; p.step(); }
    expect(p.buffer).toEqual(render(scene, camera));
  });
});

describe('progress and restarts', () => {
  const scene = classScene();

  it('progress goes from 0 to 1 without going back, in every mode', () => {
    for (const mode of ORDERS) {
      const p = new ProgressiveRenderer({ scene, camera: new Camera({ width: 37, height: 23 }), mode, slowRaysPerStep: 20 });
      expect(p.progress).toBe(0);
      expect(p.done).toBe(false);
      let last = 0;
      while (!p.step(0).done) {
        expect(p.progress).toBeGreaterThan(last);
        expect(p.progress).toBeLessThan(1);
        last = p.progress;
      }
      expect(p.progress).toBe(1);
      expect(p.step()).toEqual({ changed: false, done: true });
    }
  });

  it('a restart in the middle starts over and still ends with render()\'s picture', () => {
    for (const mode of ORDERS) {
      const camera = new Camera({ width: 37, height: 23 });
      const p = new ProgressiveRenderer({ scene, camera, mode, slowRaysPerStep: 40 });
      for (let i = 0; i < 5; i++) p.step(0);
      p.restart();
      expect(p.progress).toBe(0);
      expect(p.current).toBe(null);
      expect(p.buffer.every((b) => b === 0)).toBe(true);
      expect(finish(p, 0)).toEqual(render(scene, camera));
    }
  });

  it('a new camera size mid-render gives a new buffer of the new size and the new picture', () => {
    const p = new ProgressiveRenderer({ scene, camera: new Camera({ width: 37, height: 23 }) });
    p.step(0); p.step(0);
    const old = p.buffer;
    const camera = new Camera({ width: 20, height: 45, yaw: 10 });
    p.restart({ camera });
    expect(p.buffer).not.toBe(old);
    expect(p.buffer.length).toBe(20 * 45 * 4);
    expect([p.width, p.height]).toEqual([20, 45]);
    expect(finish(p, 0)).toEqual(render(scene, camera));
  });

  it('the same size keeps the buffer; a new scene, mode or shader restarts with it', () => {
    const camera = new Camera({ width: 24, height: 18 });
    const p = new ProgressiveRenderer({ scene, camera, mode: 'scanline' });
    const buffer = p.buffer;
    p.step(0);
    p.restart({ camera: new Camera({ width: 24, height: 18, yaw: 20 }), mode: 'coarse' });
    expect(p.buffer).toBe(buffer);
    expect(p.mode).toBe('coarse');
    p.step(0);
    const other = floorScene();
    p.restart({ scene: other });
    expect(p.progress).toBe(0);
    const c2 = new Camera({ width: 24, height: 18, yaw: 20 });
    expect(finish(p, 0)).toEqual(render(other, c2));

    const red = (s, c, x, y, target) => target.set([255, 0, 0, 255], (y * c.width + x) * 4);
    p.restart({ shader: red });
    finish(p, 0);
    expect(p.buffer.every((b, i) => b === [255, 0, 0, 255][i % 4])).toBe(true);
  });

  it('takes the render order as order, or as mode (its older name), never both', () => {
    const camera = new Camera({ width: 8, height: 6 });
    const p = new ProgressiveRenderer({ scene, camera, order: 'scanline' });
    expect([p.order, p.mode]).toEqual(['scanline', 'scanline']);
    expect(new ProgressiveRenderer({ scene, camera, mode: 'slow' }).order).toBe('slow');
    expect(new ProgressiveRenderer({ scene, camera }).order).toBe('coarse');
    p.restart({ order: 'coarse' });
    expect(p.order).toBe('coarse');
    expect(() => p.restart({ order: 'fast' })).toThrow(/^order must be one of 'coarse', 'scanline', 'slow', got "fast"$/);
    expect(() => p.restart({ order: 'slow', mode: 'slow' })).toThrow(/order or as mode \(its older name\), not both/);
    expect(p.order).toBe('coarse');
  });

  it('a bad change throws naming the field and leaves the render as it was', () => {
    const camera = new Camera({ width: 37, height: 23 });
    const p = new ProgressiveRenderer({ scene, camera });
    p.step(0);
    const progress = p.progress;
    expect(() => p.restart({ mode: 'fast' })).toThrow(/mode must be one of 'coarse', 'scanline', 'slow', got "fast"/);
    expect(() => p.restart({ shader: 3 })).toThrow(TypeError);
    expect(() => p.restart({ camera: { width: 3 } })).toThrow(/camera must be a Camera/);
    expect(() => p.restart({ slowRaysPerStep: 0 })).toThrow(/slowRaysPerStep/);
    expect(() => p.restart(null)).toThrow(/changes must be an object/);
    expect(p.mode).toBe('coarse');
    expect(p.progress).toBe(progress);
    expect(finish(p, 0)).toEqual(render(scene, camera));
  });

  it('checks its options', () => {
    const camera = new Camera({ width: 4, height: 4 });
    expect(() => new ProgressiveRenderer({ camera })).toThrow(/scene must be a Scene/);
    expect(() => new ProgressiveRenderer({ scene })).toThrow(/camera must be a Camera/);
    expect(() => new ProgressiveRenderer({ scene, camera, budgetMs: -1 })).toThrow(RangeError);
    expect(() => new ProgressiveRenderer({ scene, camera, budgetMs: NaN })).toThrow(/budgetMs must be a finite number/);
    expect(() => new ProgressiveRenderer({ scene, camera, slowRaysPerStep: 1.5 })).toThrow(/slowRaysPerStep must be a positive whole number/);
    expect(() => new ProgressiveRenderer({ scene, camera }).step('x')).toThrow(/budgetMs/);
  });
});

describe('the time budget (a fake clock)', () => {
  const scene = classScene();
  const camera = new Camera({ width: 64, height: 48 });

  /** A renderer whose every pixel takes exactly `msPerPixel` on a fake clock. */
  function timed(mode, msPerPixel) {
    const clock = fakeClock();
    const shader = (...args) => { clock.t += msPerPixel; renderPixel(...args); };
    return { clock, p: new ProgressiveRenderer({ scene, camera, mode, shader, now: clock.now }) };
  }

  it('stops at the first clock check after the budget is spent', () => {
    for (const mode of ['coarse', 'scanline']) {
      for (const budgetMs of [0, 1, 8, 16, 17, 40]) {
        const { p } = timed(mode, 1);
        p.step(0); // past the small first coarse pass
        const before = p.traced;
        p.step(budgetMs);
        // a pixel of 1 ms is dearer than budget / CHECK_EVERY for a budget under 16 ms: then one pixel between looks
        const traced = p.traced - before;
        if (budgetMs < CHECK_EVERY) expect(traced, `${mode}, ${budgetMs} ms`).toBe(Math.max(1, budgetMs));
        expect(traced).toBeGreaterThanOrEqual(budgetMs);
        expect(traced).toBeLessThan(budgetMs + CHECK_EVERY);
      }
    }
  });

  it('uses the default budget of 8 ms, or the one given at construction', () => {
    const { p } = timed('scanline', 0.5);
    p.step();
    expect(p.traced).toBe(17); // 1 pixel (a render's pace unknown), then 16 × 0.5 ms: 8.5 ms, past 8 at the second check
    const clock = fakeClock();
    const q = new ProgressiveRenderer({ scene, camera, mode: 'scanline', budgetMs: 20, now: clock.now,
      shader: (...a) => { clock.t += 0.5; renderPixel(...a); } });
    q.step();
    expect(q.traced * 0.5).toBeGreaterThanOrEqual(20);
    expect(q.traced * 0.5).toBeLessThan(20 + CHECK_EVERY * 0.5);
  });

  /**
   * Steps a 320×240 render to the end on a fake clock, pixel (x, y) costing
   * `cost(x, y)` ms, the clock as `read` shows it; returns each step's time
   * on the true clock and its number of clock reads.
   */
  function steps(mode, budgetMs, cost, read = (t) => t) {
    const camera = new Camera({ width: 320, height: 240 });
    const clock = { t: 0, reads: 0 };
    const shader = (s, c, x, y, target) => { clock.t += cost(x, y); renderPixel(s, c, x, y, target); };
    const now = () => { clock.reads++; return read(clock.t); };
    const p = new ProgressiveRenderer({ scene, camera, mode, shader, now });
    const seen = [];
    while (!p.done) {
      const t0 = clock.t, reads = clock.reads;
      p.step(budgetMs);
      if (!p.done) seen.push({ ms: clock.t - t0, reads: clock.reads - reads });
    }
    return seen;
  }

  it('reads the clock a few dozen times a step, not every few pixels, and stops within CHECK_EVERY pixels of the budget', () => {
    for (const mode of ['coarse', 'scanline']) {
      const seen = steps(mode, 8, () => 0.001); // 8,000 pixels a step
      expect(seen.length).toBeGreaterThan(5);
      for (const { ms, reads } of seen) {
        expect(ms).toBeGreaterThanOrEqual(8);
        expect(ms).toBeLessThanOrEqual(8 + CHECK_EVERY * 0.001 + 1e-9);
        expect(reads).toBeLessThan(40);
      }
    }
  });

  it('stays within its budget when the pixels get four times dearer in the middle of a step', () => {
    for (const mode of ['coarse', 'scanline']) {
      // The lower half of the picture costs four times the upper half, per pixel.
      const seen = steps(mode, 8, (x, y) => (y < 120 ? 0.001 : 0.004));
      for (const { ms } of seen) expect(ms).toBeLessThanOrEqual(8 + CHECK_EVERY * 0.004 + 1e-9);
    }
  });

  it('holds its budget when one pixel costs more than the whole budget: one pixel a step, from the first step on', () => {
    for (const mode of ['coarse', 'scanline']) {
      const seen = steps(mode, 8, (x, y) => (y < 120 ? 0.001 : 250)); // 250 ms a pixel: 10,000 shadow rays each
      const dear = seen.filter(({ ms }) => ms >= 250);
      expect(dear.length).toBeGreaterThan(10);
      // One dear pixel a step, not 16 (4 s a step); once a run sized by the cheap pixels meets the first dear ones, it may overrun.
      expect(dear.filter(({ ms }) => ms > 250 + 8 + 1e-6).length, mode).toBeLessThanOrEqual(1);
    }
    const camera = new Camera({ width: 8, height: 8 });
    const clock = fakeClock();
    const p = new ProgressiveRenderer({ scene, camera, mode: 'scanline', now: clock.now, shader: (...a) => { clock.t += 250; renderPixel(...a); } });
    p.step(8);
    expect(p.traced).toBe(1); // the first step of a render too
  });

  it('stays near its budget when the pixels get a hundred times dearer (a lit sphere among 10,000, after the background)', () => {
    for (const mode of ['coarse', 'scanline']) {
      const seen = steps(mode, 8, (x, y) => (y < 120 ? 0.001 : 0.1));
      const longest = Math.max(...seen.map(({ ms }) => ms));
      expect(longest).toBeLessThanOrEqual(4 * 8); // once, where they start; runs sized by the background's pace took 190 ms
    }
  });

  it('copes with a clock that moves only every 0.1 ms, as a browser\'s may', () => {
    const tick = 0.1;
    for (const mode of ['coarse', 'scanline']) {
      const seen = steps(mode, 8, () => 0.001, (t) => Math.floor(t / tick) * tick);
      for (const { ms, reads } of seen) {
        expect(ms).toBeGreaterThanOrEqual(8 - tick);
        expect(ms).toBeLessThanOrEqual(8 + tick + CHECK_EVERY * 0.001);
        expect(reads).toBeLessThan(40);
      }
    }
  });

  it('measures rays per second over the time spent tracing', () => {
    const { p } = timed('coarse', 0.5);
    expect(p.raysPerSecond).toBe(0);
    p.step(4); p.step(4);
    expect(p.raysPerSecond).toBeCloseTo(2000, 6);
    p.restart();
    expect(p.raysPerSecond).toBe(0);
  });
});
