// Path tracing: tests only a right path tracer passes. The white furnace, a
// diffuse plane under a uniform sky, light trapped in a closed room (the sum
// of a geometric series), the cosine sampler's distribution by chi-square,
// Russian roulette unbiased, and the same bytes however the frame is split.
import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, Camera, pathTrace, inspectPath, ParallelRenderer } from '../../lib/index.js';
import { PathRandom, pcgHash } from '../../lib/tracing/pathtrace/random.js';
import { cosineHemisphere, cosinePdf } from '../../lib/tracing/pathtrace/sampling.js';
import { readPathOptions, preparePaths, pathTraceRows } from '../../lib/tracing/pathtrace/path-trace.js';
import { PathProgressiveRenderer } from '../../lib/tracing/pathtrace/progressive.js';
import { fakeWorkers } from './fake-workers.js';
import { room } from '../shared/path-room.js';

const L = 0.6; // the sky's light

/** A ball filling the middle of a small picture, under a uniform sky of L. */
function furnace(material) {
  const scene = new Scene({ background: [L, L, L] }).add(new Sphere([0, 0, -10], 3, material));
  return { scene, camera: new Camera({ width: 8, height: 6, fov: 30 }) };
}

/** Pixels of an 8×6 picture whose every point lies on the ball (the jitter covers the whole pixel). */
const ON_BALL = [[3, 2], [4, 2], [3, 3], [4, 3]];

describe('the white furnace', () => {
  it('a white diffuse ball under a uniform sky L is L everywhere, within 1 % at 1,024 samples', () => {
    const { scene, camera } = furnace({ color: [1, 1, 1] });
    for (const [x, y] of ON_BALL) {
      const { mean, bounces } = inspectPath(scene, camera, x, y, { samples: 1024 });
      expect(bounces[0].name).toBe('sphere 1');
      for (const m of mean) expect(Math.abs(m - L)).toBeLessThan(0.01 * L);
    }
    const rgba = pathTrace(scene, camera, { samples: 1024 });
    for (let i = 0; i < rgba.length; i += 4) expect(Math.abs(rgba[i] - L * 255)).toBeLessThanOrEqual(1);
  });

  it('with albedo a and one bounce, a·L; white glass and a white mirror lose no light either', () => {
    const a = [0.7, 0.45, 0.2];
    const { scene, camera } = furnace({ color: a });
    for (const [x, y] of ON_BALL) {
      const { mean } = inspectPath(scene, camera, x, y, { samples: 256, maxBounces: 1 });
      mean.forEach((m, c) => expect(m).toBeCloseTo(a[c] * L, 10));
    }
    for (const material of [{ transparency: 1, ior: 1.5 }, { reflection: 1 }, { reflection: 1, fuzz: 0.3 }, { reflection: 0.5, transparency: 0.5 }]) {
      const ball = furnace(material);
      const { mean } = inspectPath(ball.scene, ball.camera, 4, 3, { samples: 512 });
      for (const m of mean) expect(Math.abs(m - L), JSON.stringify(material)).toBeLessThan(0.01 * L);
    }
  });
});

describe('a diffuse plane under a uniform sky', () => {
  it('is albedo·L: every bounce off it goes to the sky', () => {
    const albedo = [0.8, 0.45, 0.2];
    const scene = new Scene({ background: [L, L, L] }).add(new Plane([0, -1, 0], [0, 1, 0], { color: albedo }));
    const camera = new Camera({ width: 6, height: 4, fov: 20, pitch: -60 });
    const rgba = pathTrace(scene, camera, { samples: 64 });
    for (let i = 0; i < rgba.length; i += 4) {
      for (let c = 0; c < 3; c++) expect(rgba[i + c]).toBe(Math.round(albedo[c] * L * 255));
    }
  });
});

/** The eye inside a closed ball of albedo a that gives off E: every path bounces until it ends, gathering E·(1 + a + a² + …). */
function closedRoom(a, E) {
  const scene = new Scene().add(new Sphere([0, 0, 0], 10, { color: a, emission: E }));
  return { scene, camera: new Camera({ width: 4, height: 4, fov: 60, position: [1, 2, 3] }) };
}

describe('Russian roulette', () => {
  const a = [0.5, 0.7, 0.3], E = [0.2, 0.15, 0.35];
  const expected = a.map((ac, c) => (E[c] * (1 - ac ** 41)) / (1 - ac)); // 40 bounces: 41 hits
  const { scene, camera } = closedRoom(a, E);

  it('without it, 40 bounces gather E·(1 − a⁴¹)/(1 − a), every path alike (bounces alone: a light sample adds its own noise)', () => {
    const { mean, stderr, bounces, end } = inspectPath(scene, camera, 2, 2, { samples: 16, maxBounces: 40, roulette: false, lightSampling: false });
    mean.forEach((m, c) => expect(m).toBeCloseTo(expected[c], 12));
    stderr.forEach((e) => expect(e).toBeLessThan(1e-6)); // (rounding only)
    expect(bounces).toHaveLength(41);
    expect(end).toBe('maxBounces');
  });

  it('with it, paths end early yet the mean agrees within 3 standard errors: the survivors are re-weighted by 1/q', () => {
    const free = inspectPath(scene, camera, 1, 2, { samples: 16, maxBounces: 40, roulette: false });
    const played = inspectPath(scene, camera, 1, 2, { samples: 4096, maxBounces: 40 });
    played.unclamped.forEach((m, c) => {
      expect(played.stderr[c]).toBeGreaterThan(0); // the roulette makes noise...
      expect(Math.abs(m - free.unclamped[c])).toBeLessThan(3 * Math.hypot(played.stderr[c], free.stderr[c])); // ...and no bias
    });
    // A path the roulette ended says where, with the survival probability it drew against.
    const paths = Array.from({ length: 40 }, (_, sample) => inspectPath(scene, camera, 1, 2, { sample, maxBounces: 40 }));
    const ended = paths.find((p) => p.end === 'roulette');
    expect(ended).toBeDefined();
    expect(ended.bounces.length).toBeLessThan(41);
    const last = ended.bounces.at(-1);
    expect(last.survival).toBeGreaterThan(0);
    expect(last.survival).toBeLessThan(1);
    expect(ended.bounces.slice(0, 2).every((b) => b.survival === undefined)).toBe(true); // not before bounce 3
  });
});

describe('the cosine-weighted sampler', () => {
  /** Chi-square of n directions around `normal` over equal-probability cells of cos²θ (10) × φ (8), for cosine-weighted directions. */
  function chiSquare(sample, normal, n = 80_000) {
    const [nx, ny, nz] = normal, cells = new Float64Array(80), out = new Float64Array(4), u = new Float64Array(2), N = Float64Array.from(normal);
    const random = new PathRandom().start(7, 1, 2, 3);
    // A tangent frame of our own to measure φ in (any will do: φ is uniform).
    const t = Math.abs(nx) < 0.9 ? [0, -nz, ny] : [-nz, 0, nx], tl = Math.hypot(...t), T = t.map((v) => v / tl);
    const B = [ny * T[2] - nz * T[1], nz * T[0] - nx * T[2], nx * T[1] - ny * T[0]];
    for (let i = 0; i < n; i++) {
      u[0] = random.next(); u[1] = random.next();
      sample(out, N, u);
      const cos = out[0] * nx + out[1] * ny + out[2] * nz;
      expect(Math.hypot(out[0], out[1], out[2])).toBeCloseTo(1, 12);
      const phi = Math.atan2(out[0] * B[0] + out[1] * B[1] + out[2] * B[2], out[0] * T[0] + out[1] * T[1] + out[2] * T[2]) + Math.PI;
      const row = Math.min(9, Math.floor(cos * cos * 10)), column = Math.min(7, Math.floor((phi / (2 * Math.PI)) * 8));
      cells[row * 8 + column]++;
    }
    const e = n / 80;
    return cells.reduce((sum, o) => sum + ((o - e) ** 2) / e, 0);
  }
  const cosineWeighted = (out, N, u) => cosineHemisphere(out, 0, N, 0, u, 0);
  /** The wrong sampler, uniform over the hemisphere: cos θ uniform. */
  const uniform = (out, N, u) => {
    const cos = u[0], sin = Math.sqrt(1 - cos * cos), n = Array.from(N);
    const t = Math.abs(n[0]) < 0.9 ? [0, -n[2], n[1]] : [-n[2], 0, n[0]], tl = Math.hypot(...t), T = t.map((v) => v / tl);
    const B = [n[1] * T[2] - n[2] * T[1], n[2] * T[0] - n[0] * T[2], n[0] * T[1] - n[1] * T[0]];
    const a = sin * Math.cos(2 * Math.PI * u[1]), b = sin * Math.sin(2 * Math.PI * u[1]);
    for (let c = 0; c < 3; c++) out[c] = a * T[c] + b * B[c] + cos * n[c];
  };
  // 79 degrees of freedom: the 0.1 % critical value is 124.8.
  const CRITICAL = 124.8;
  const normals = [[0, 0, 1], [0, 0, -1], [0, 1, 0], [0.48, -0.6, 0.64]];

  it('draws cos θ / π over the hemisphere: chi-square within the 0.1 % critical value, about any normal', () => {
    for (const normal of normals) expect(chiSquare(cosineWeighted, normal), String(normal)).toBeLessThan(CRITICAL);
  });

  it('the same test rejects a uniform hemisphere sampler, so it can fail', () => {
    expect(chiSquare(uniform, [0.48, -0.6, 0.64])).toBeGreaterThan(10 * CRITICAL);
  });

  it('its density integrates to 1 and it says the cos it drew', () => {
    const out = new Float64Array(4);
    cosineHemisphere(out, 0, Float64Array.of(0, 1, 0), 0, Float64Array.of(0.36, 0.25), 0);
    expect(out[3]).toBeCloseTo(0.8, 12);
    expect(out[1]).toBeCloseTo(0.8, 12);
    // ∫ cos/π dω over the hemisphere = ∫₀^{π/2} cos θ sin θ 2π/π dθ = 1 (midpoint rule)
    let total = 0;
    for (let k = 0; k < 1000; k++) { const theta = ((k + 0.5) / 1000) * (Math.PI / 2); total += cosinePdf(Math.cos(theta)) * Math.sin(theta) * 2 * Math.PI * (Math.PI / 2000); }
    expect(total).toBeCloseTo(1, 5);
    expect(cosinePdf(-0.1)).toBe(0);
  });
});

describe('the same bytes, however the frame is traced', () => {
  const { scene, camera } = room();
  const options = { samples: 8, seed: 3, maxBounces: 6, sky: { top: [0.5, 0.7, 1], bottom: [1, 1, 1] } };

  it('twice alike; another seed, another picture; the sky gradient and the lamp show', () => {
    const a = pathTrace(scene, camera, options), b = pathTrace(scene, camera, options);
    expect(b).toEqual(a);
    expect(pathTrace(scene, camera, { ...options, seed: 4 })).not.toEqual(a);
    expect(new Set(a).size).toBeGreaterThan(40);
  });

  it('by rows in any bands, and sample after sample (the progressive renderer), as pathTrace', () => {
    const whole = pathTrace(scene, camera, options);
    const frame = preparePaths(scene, camera, readPathOptions(options, scene, camera));
    const banded = new Uint8ClampedArray(whole.length);
    for (const [y0, y1] of [[11, 18], [0, 5], [5, 11]]) pathTraceRows(frame, banded, y0, y1);
    expect(banded).toEqual(whole);
    const progressive = new PathProgressiveRenderer({ scene, camera, path: options });
    const seen = [];
    while (!progressive.done) if (progressive.step(1e-9).changed) seen.push(progressive.sample); // a row a step: each pass shown
    expect(seen).toEqual([1, 2, 3, 4, 5, 6, 7, 8]);
    expect(progressive.buffer).toEqual(whole);
    expect(progressive.progressText).toMatch(/^Sample 8 of 8 · /);
    progressive.restart({ path: { samples: 2 } }); // the other options kept
    while (!progressive.done) progressive.step(1);
    expect(progressive.buffer).toEqual(pathTrace(scene, camera, { ...options, samples: 2 }));
  });

  it('on workers (stand-ins running the real worker code), dealt in bands or taken from a shared counter', async () => {
    const whole = pathTrace(scene, camera, options);
    for (const [workers, shared] of [[3, false], [2, true], [5, false]]) {
      const fakes = fakeWorkers();
      const parallel = new ParallelRenderer({ workers, shared, createWorker: fakes.create, rowsPerBand: 2 });
      expect(await parallel.render(scene, camera, { path: options })).toEqual(whole);
      expect(fakes.received.every((m) => m.path.samples === 8)).toBe(true);
      parallel.terminate();
    }
  });

  it('inspectPath\'s mean × 255 is pathTrace\'s byte; its history ends at the mean', () => {
    const whole = pathTrace(scene, camera, options);
    for (const [x, y] of [[12, 9], [3, 15], [20, 2]]) {
      const path = inspectPath(scene, camera, x, y, { ...options, sample: 5 });
      const i = (y * camera.width + x) * 4;
      expect([...Uint8ClampedArray.from(path.mean, (m) => m * 255)]).toEqual([...whole.slice(i, i + 3)]);
      expect(path.history).toHaveLength(8);
      expect(path.history.at(-1)).toEqual(path.mean);
      expect(path.sample).toBe(5);
    }
  });
});

describe('a scene the kernel cannot pack', () => {
  it('is path traced too, with its materials in the same layout: a subclass with its own hit test, lamp and all', () => {
    class OwnHit extends Sphere { hit(ray, tMin) { return super.hit(ray, tMin); } }
    const lamp = new OwnHit([0, 0, -5], 1, { color: [1, 0, 0], emission: [1, 1, 1] });
    const scene = new Scene().add(lamp).add(new Plane([0, -1, 0], [0, 1, 0], { color: [0.5, 0.5, 0.5] }));
    const frame = preparePaths(scene, new Camera({ width: 8, height: 8 }), readPathOptions({ samples: 2 }, scene, new Camera({ width: 8, height: 8 })));
    expect(frame.packed).toBeNull();
    expect(frame.materials[3]).toBe(1); // the lamp's emission at EMISSION, as packScene would place it
    const picture = pathTrace(scene, new Camera({ width: 8, height: 8 }), { samples: 2, blocking: true });
    expect([...picture.subarray((4 * 8 + 4) * 4, (4 * 8 + 4) * 4 + 3)]).toEqual([255, 255, 255]); // the lamp, seen straight
  });
});

describe('the story of one path', () => {
  const { scene, camera } = room();
  it('bounce by bounce: point, normal, direction drawn and its density, throughput, light gathered', () => {
    const path = inspectPath(scene, camera, 5, 10, { sample: 0, samples: 4 }); // the red box
    expect(path.bounces[0].name).toBe('box 1');
    for (const b of path.bounces.slice(0, -1)) {
      expect(Math.hypot(b.normal.x, b.normal.y, b.normal.z)).toBeCloseTo(1, 12);
      if (b.lobe === 'diffuse') {
        const cos = b.direction.x * b.normal.x + b.direction.y * b.normal.y + b.direction.z * b.normal.z;
        expect(b.pdf).toBeCloseTo(cos / Math.PI, 12);
        expect(b.delta).toBe(false);
      }
    }
    const first = path.bounces[0];
    expect(first.lobe).toBe('diffuse');
    expect(first.throughput).toEqual([0.8, 0.2, 0.2]); // the box's colour: cos/π over a pdf of cos/π
    expect(first.emitted).toEqual([0, 0, 0]);
    // The light gathered: what each surface gave off plus the sky, as the sample's radiance.
    const gathered = [0, 1, 2].map((c) => path.bounces.reduce((sum, b) => sum + b.emitted[c] + (b.lightSample?.contribution[c] ?? 0), 0) + path.sky[c]);
    gathered.forEach((g, c) => expect(g).toBeCloseTo(path.radiance[c], 12));
  });

  it('a path that reaches the lamp gathers its light times the throughput (times its MIS weight after a diffuse bounce)', () => {
    for (const lightSampling of [false, true]) {
      const paths = Array.from({ length: 200 }, (_, sample) => inspectPath(scene, camera, 12, 12, { sample, lightSampling }));
      const lit = paths.find((p) => p.bounces.some((b) => b.name === 'sphere 3' && b.emitted[0] > 0));
      expect(lit).toBeDefined();
      const k = lit.bounces.findIndex((b) => b.name === 'sphere 3');
      const before = k === 0 ? [1, 1, 1] : lit.bounces[k - 1].throughput;
      const weight = lit.bounces[k].emissionWeight;
      if (lightSampling && k > 0 && lit.bounces[k - 1].lobe === 'diffuse') expect(weight).toBeLessThan(1);
      else expect(weight).toBe(1);
      expect(lit.bounces[k].emitted).toEqual([4, 4, 3.6].map((e, c) => before[c] * e * weight));
    }
  });
});

describe('the random sequence', () => {
  it('depends on (seed, x, y, s) alone: a change of any gives other numbers', () => {
    const first = (...key) => new PathRandom().start(...key).next();
    const base = first(0, 1, 2, 3);
    expect(first(0, 1, 2, 3)).toBe(base);
    for (const key of [[1, 1, 2, 3], [0, 2, 2, 3], [0, 1, 3, 3], [0, 1, 2, 4], [0, 2, 1, 3]]) expect(first(...key)).not.toBe(base);
    expect(pcgHash(0)).not.toBe(pcgHash(1));
    const r = new PathRandom().start(0, 0, 0, 0);
    let sum = 0;
    for (let i = 0; i < 10000; i++) { const v = r.next(); expect(v >= 0 && v < 1).toBe(true); sum += v; }
    expect(sum / 10000).toBeCloseTo(0.5, 1);
  });
});

describe('bad input is named', () => {
  const { scene, camera } = room();
  it('names the field', () => {
    expect(() => pathTrace(scene, camera)).toThrow(/needs options \{ samples \}/);
    expect(() => pathTrace(scene, camera, {})).toThrow(/samples must be given/);
    expect(() => pathTrace(scene, camera, { samples: 0 })).toThrow(/samples must be a positive whole number/);
    expect(() => pathTrace(scene, camera, { samples: 70000 })).toThrow(/samples must be at most 65536/);
    expect(() => pathTrace(scene, new Camera({ width: 4096, height: 4096 }), { samples: 8 })).toThrow(/samples × width × height must be at most/);
    expect(() => pathTrace(scene, camera, { samples: 1, maxBounces: 1.5 })).toThrow(/maxBounces must be a whole number from 0 to 64/);
    expect(() => pathTrace(scene, camera, { samples: 1, seed: -1 })).toThrow(/seed must be a whole number/);
    expect(() => pathTrace(scene, camera, { samples: 1, sampels: 2 })).toThrow(/unknown pathTrace option "sampels"/);
    expect(() => pathTrace(scene, camera, { samples: 1, sky: 'blu' })).toThrow(/sky/);
    expect(() => pathTrace(scene, camera, { samples: 1, sky: { top: 'white' } })).toThrow(/sky must have both top and bottom/);
    expect(() => inspectPath(scene, camera, 24, 0, { samples: 1 })).toThrow(/x/);
    expect(() => inspectPath(scene, camera, 0, 0, { sample: -1 })).toThrow(/sample must be a whole number/);
    expect(() => pathTrace({}, camera, { samples: 1 })).toThrow(/scene must be a Scene/);
  });
});
