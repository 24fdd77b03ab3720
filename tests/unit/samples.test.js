import { describe, it, expect } from 'vitest';
import { Camera, render, inspectPixel, classScene, ProgressiveRenderer } from '../../lib/index.js';
import { sampleOffsets } from '../../lib/math/camera.js';
import { cameraToJSON, cameraFromJSON } from '../../lib/scene/json.js';

const W = 32, H = 24;
const camera = (options = {}) => new Camera({ width: W, height: H, ...options });

describe('Camera samples: several rays per pixel', () => {
  it('is 1 unless told, and takes 4, 9 or 16', () => {
    expect(camera().samples).toBe(1);
    for (const n of [1, 4, 9, 16]) expect(camera({ samples: n }).samples).toBe(n);
  });

  it.each([0, 2, 3, 5, 8, 25, -4, 4.5, NaN, '4', null])('refuses samples = %s, naming the field', (samples) => {
    expect(() => camera({ samples })).toThrow(/samples must be 1, 4, 9 or 16/);
  });

  it('puts one ray at the centre of each cell of an n × n grid over the pixel', () => {
    expect([...sampleOffsets(1)]).toEqual([0, 0]);
    expect([...sampleOffsets(4)]).toEqual([-0.25, -0.25, 0.25, -0.25, -0.25, 0.25, 0.25, 0.25]);
    for (const n of [9, 16]) {
      const offsets = sampleOffsets(n), side = Math.sqrt(n);
      const cells = new Set();
      for (let s = 0; s < offsets.length; s += 2) {
        const dx = offsets[s], dy = offsets[s + 1];
        expect(Math.abs(dx)).toBeLessThan(0.5);
        expect(Math.abs(dy)).toBeLessThan(0.5);
        cells.add(`${Math.floor((dx + 0.5) * side)},${Math.floor((dy + 0.5) * side)}`);
      }
      expect(cells.size).toBe(n); // one ray in every cell: stratified
    }
    expect(sampleOffsets(9)).toBe(sampleOffsets(9)); // made once
  });

  it('with one ray per pixel, gives the very bytes it always gave', () => {
    expect(render(classScene(), camera({ samples: 1 }))).toEqual(render(classScene(), camera()));
  });

  it('gives what a picture twice as wide and high gives, averaged over each 2 × 2 block', () => {
    // Independent of the sub-pixel code: the ray through cell (i, j) of pixel (x, y) is the
    // ray through pixel (2x + i, 2y + j) of a camera twice the size (same field of view).
    const smooth = render(classScene(), camera({ samples: 4 }));
    const big = render(classScene(), new Camera({ width: 2 * W, height: 2 * H }));
    let worst = 0, edges = 0;
    for (let y = 0; y < H; y++) {
      for (let x = 0; x < W; x++) {
        for (let c = 0; c < 3; c++) {
          const at = (bx, by) => big[((2 * y + by) * 2 * W + 2 * x + bx) * 4 + c];
          const cells = [at(0, 0), at(1, 0), at(0, 1), at(1, 1)];
          if (Math.max(...cells) - Math.min(...cells) > 8) edges++;
          worst = Math.max(worst, Math.abs(smooth[(y * W + x) * 4 + c] - cells.reduce((a, b) => a + b) / 4));
        }
      }
    }
    expect(edges).toBeGreaterThan(20); // the test sees edges, where the average matters
    expect(worst).toBeLessThanOrEqual(1); // bytes rounded once vs four times
  });

  it('is the same picture every run, and differs from one ray per pixel on edges only', () => {
    const a = render(classScene(), camera({ samples: 9 })), b = render(classScene(), camera({ samples: 9 }));
    expect(a).toEqual(b);
    const jagged = render(classScene(), camera());
    let changed = 0;
    for (let i = 0; i < a.length; i++) if (a[i] !== jagged[i]) changed++;
    expect(changed).toBeGreaterThan(0);
    expect(changed).toBeLessThan(a.length / 2);
  });

  it('inspectPixel lists the sub-pixel rays, and its colour is their average, the bytes render() gives', () => {
    const cam = camera({ samples: 4 }), picture = render(classScene(), cam);
    for (let y = 0; y < H; y += 3) {
      for (let x = 0; x < W; x += 3) {
        const record = inspectPixel(classScene(), cam, x, y);
        expect(record.samples).toHaveLength(4);
        expect(record.color).toEqual([...picture.slice((y * W + x) * 4, (y * W + x) * 4 + 3)]);
      }
    }
    const { samples } = inspectPixel(classScene(), cam, 5, 7);
    expect(samples.map((s) => [s.dx, s.dy])).toEqual([[-0.25, -0.25], [0.25, -0.25], [-0.25, 0.25], [0.25, 0.25]]);
    const sub = samples[3];
    expect(sub.ray.direction).toEqual(cam.primaryRay(5.25, 7.25).ray.direction);
    expect(inspectPixel(classScene(), camera(), 5, 7).samples).toBeUndefined();
  });

  it('the progressive renderer ends on render()\'s picture', () => {
    const cam = camera({ samples: 4 });
    const p = new ProgressiveRenderer({ scene: classScene(), camera: cam, budgetMs: 1e9 });
    while (!p.done) p.step();
    expect(p.buffer).toEqual(render(classScene(), cam));
  });

  it('is kept in JSON only when it is not 1, and read back checked', () => {
    expect(cameraToJSON(camera())).not.toHaveProperty('samples');
    expect(cameraToJSON(camera({ samples: 16 })).samples).toBe(16);
    expect(cameraFromJSON(cameraToJSON(camera({ samples: 9 }))).samples).toBe(9);
    expect(() => cameraFromJSON({ width: 8, height: 8, samples: 3 })).toThrow(/samples must be 1, 4, 9 or 16/);
  });

  it('a restart checks a samples changed in place', () => {
    const cam = camera();
    const p = new ProgressiveRenderer({ scene: classScene(), camera: cam });
    cam.samples = 3;
    expect(() => p.restart()).toThrow(/camera\.samples must be 1, 4, 9 or 16/);
  });
});
