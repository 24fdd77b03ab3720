// Light sampling (next-event estimation with multiple importance sampling): the same expected picture as
// bounces alone, less noise. Pictures with and without it agree region by region within 4 standard errors
// (a double count of the direct light would not); a one-light scene's direct light matches its closed
// form; the light sampler's densities are the ones the bounces are weighed with; no NaN at the edges.
import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, Box, Camera, pathTrace, inspectPath } from '../../lib/index.js';
import { readPathOptions, preparePaths } from '../../lib/tracing/pathtrace/path-trace.js';
import { tracePath, radiance } from '../../lib/tracing/pathtrace/integrator.js';
import { sampleLight, lightPdf, lightTable, L_PDF, L_POINT, LIGHT_SAMPLE } from '../../lib/tracing/pathtrace/lights.js';
import { packMaterials, scatter, metalDensity, SURFACE, EVENT, LOBE, METAL } from '../../lib/tracing/pathtrace/materials.js';
import { readSky } from '../../lib/tracing/pathtrace/sky.js';
import { PathRandom } from '../../lib/tracing/pathtrace/random.js';
import { PathProgressiveRenderer } from '../../lib/tracing/pathtrace/progressive.js';
import { cornellBox, cornellCamera } from '../shared/cornell-box.js';

/** Each pixel's mean and variance per sample, channel by channel, over `samples` unclamped samples. */
function pixelStats(scene, camera, options, samples) {
  const frame = preparePaths(scene, camera, readPathOptions({ ...options, samples }, scene, camera));
  const n = camera.width * camera.height, mean = new Float64Array(n * 3), variance = new Float64Array(n * 3);
  for (let y = 0; y < camera.height; y++) {
    for (let x = 0; x < camera.width; x++) {
      const sum = [0, 0, 0], squares = [0, 0, 0];
      for (let s = 0; s < samples; s++) {
        tracePath(frame, x, y, s);
        for (let c = 0; c < 3; c++) { expect(Number.isFinite(radiance[c])).toBe(true); sum[c] += radiance[c]; squares[c] += radiance[c] ** 2; }
      }
      for (let c = 0; c < 3; c++) {
        const i = (y * camera.width + x) * 3 + c, m = sum[c] / samples;
        mean[i] = m; variance[i] = Math.max(0, squares[c] - samples * m * m) / (samples - 1);
      }
    }
  }
  return { mean, variance, samples, width: camera.width, height: camera.height };
}

/** Blocks of `size`×`size` pixels: each block's mean colour and its standard error. */
function regions(stats, size) {
  const out = [];
  for (let by = 0; by < stats.height; by += size) {
    for (let bx = 0; bx < stats.width; bx += size) {
      const mean = [0, 0, 0], se2 = [0, 0, 0];
      let count = 0;
      for (let y = by; y < Math.min(stats.height, by + size); y++) {
        for (let x = bx; x < Math.min(stats.width, bx + size); x++, count++) {
          for (let c = 0; c < 3; c++) { const i = (y * stats.width + x) * 3 + c; mean[c] += stats.mean[i]; se2[c] += stats.variance[i] / stats.samples; }
        }
      }
      out.push({ mean: mean.map((m) => m / count), stderr: se2.map((v) => Math.sqrt(v) / count) });
    }
  }
  return out;
}

/** The regions of two renders, channel by channel: the difference and 4 standard errors of it. */
function compare(a, b) {
  return a.flatMap((r, k) => [0, 1, 2].map((c) => ({ k, c, difference: Math.abs(r.mean[c] - b[k].mean[c]), bound: 4 * Math.hypot(r.stderr[c], b[k].stderr[c]) })));
}

/** A closed room (a box seen from inside) with one small, bright lamp: 1/16 of the Cornell lamp's area, the same power. */
function smallLamp() {
  const scene = cornellBox(8);
  const at = scene.objects.findIndex((o) => o.name === 'lamp');
  scene.objects[at] = new Box([-0.625, 9.8, -15.125], [0.625, 9.99, -13.875], { color: [0, 0, 0], emission: [128, 128, 115.2], name: 'lamp' });
  return scene;
}

/** A glass ball on a floor under a lamp ball, a dark sky. */
function glassUnderLamp() {
  return new Scene({ background: [0.02, 0.02, 0.03] })
    .add(new Plane([0, -1, 0], [0, 1, 0], { color: [0.7, 0.7, 0.7], name: 'floor' }))
    .add(new Sphere([0, 0, -8], 1, { transparency: 1, ior: 1.5, name: 'glass' }))
    .add(new Sphere([1, 4, -8], 0.5, { color: [0, 0, 0], emission: [12, 12, 10], name: 'lamp' }));
}

/** Balls on a floor under a gradient sky (the sky sampled by its brightness), a diffuse ball and a box. */
function gradientSky() {
  return new Scene()
    .add(new Plane([0, -1, 0], [0, 1, 0], { color: [0.6, 0.6, 0.55] }))
    .add(new Sphere([-1.2, 0, -7], 1, { color: [0.8, 0.3, 0.2] }))
    .add(new Box([0.5, -1, -8], [2, 0.5, -6.5], { color: [0.3, 0.5, 0.8] }));
}

/** A fuzzy metal ball and a mirror ball under a small bright lamp ball, a grey floor, a dark sky. */
function metalsUnderLamp() {
  return new Scene({ background: [0.02, 0.02, 0.03] })
    .add(new Plane([0, -1, 0], [0, 1, 0], { color: [0.6, 0.6, 0.6], name: 'floor' }))
    .add(new Sphere([-1.1, 0, -8], 1, { color: [0.9, 0.8, 0.7], reflection: 1, fuzz: 0.3, name: 'brushed' }))
    .add(new Sphere([1.1, 0, -8], 1, { color: [0.8, 0.8, 0.9], reflection: 0.6, fuzz: 0.05, name: 'half mirror' }))
    .add(new Sphere([0, 3.5, -7], 0.3, { color: [0, 0, 0], emission: [40, 40, 36], name: 'lamp' }));
}

describe('with and without light sampling, the same picture', () => {
  const cases = [
    ['the Cornell box', () => cornellBox(8), () => cornellCamera(8, 8), {}],
    ['a small bright lamp', smallLamp, () => cornellCamera(8, 8), {}],
    ['fuzzy metal balls under a small lamp', metalsUnderLamp, () => new Camera({ width: 8, height: 8, fov: 30, position: [0, 1, 0], pitch: -10 }), {}],
    ['a glass ball under a lamp', glassUnderLamp, () => new Camera({ width: 8, height: 8, fov: 30, position: [0, 1, 0], pitch: -10 }), {}],
    ['a gradient sky', gradientSky, () => new Camera({ width: 8, height: 8, fov: 40, position: [0, 1, 0], pitch: -10 }), { sky: { top: [0.3, 0.5, 1], bottom: [1.2, 1, 0.8] } }],
  ];
  for (const [name, makeScene, makeCamera, options] of cases) {
    it(`${name}: each 4×4 region's mean within 4 standard errors${name === 'the Cornell box' ? ', a double count of the direct light not' : ''}`, () => {
      const scene = makeScene(), camera = makeCamera();
      const on = regions(pixelStats(scene, camera, { ...options, seed: 1 }, 256), 4);
      const off = regions(pixelStats(scene, camera, { ...options, seed: 2, lightSampling: false }, 256), 4);
      for (const { k, c, difference, bound } of compare(on, off)) expect(difference, `region ${k}, channel ${c}`).toBeLessThanOrEqual(bound);
      if (name !== 'the Cornell box') return;
      // The bound is tight: the light that bounced once (direct light) counted twice breaks it.
      const direct = regions(pixelStats(scene, camera, { seed: 3, maxBounces: 1 }, 64), 4), seen = regions(pixelStats(scene, camera, { seed: 3, maxBounces: 0 }, 64), 4);
      const twice = on.map((r, k) => ({ mean: r.mean.map((m, c) => m + direct[k].mean[c] - seen[k].mean[c]), stderr: r.stderr }));
      const broken = compare(twice, off).filter(({ difference, bound }) => difference > bound);
      expect(broken.length).toBeGreaterThan(compare(twice, off).length / 2);
    }, 180_000);
  }
});

describe('a diffuse plane under one small lamp ball, direct light alone', () => {
  // Seen from x on the plane, a ball of radius r whose centre is d away, at θ from the normal, wholly above
  // the horizon, gives irradiance π·L·(r/d)²·cos θ; the plane of albedo a sends a/π of it: a·L·(r/d)²·cos θ.
  const a = 0.7, L = 40, r = 0.3, centre = [1.5, 3, -0.5];
  const scene = new Scene({ background: [0, 0, 0] })
    .add(new Plane([0, 0, 0], [0, 1, 0], { color: [a, a, a] }))
    .add(new Sphere(centre, r, { color: [0, 0, 0], emission: [L, L, L] }));
  const camera = new Camera({ width: 3, height: 3, fov: 0.01, position: [0, 4, 0], pitch: -90 }); // the middle pixel: the point under the eye
  const d = Math.hypot(...centre), expected = a * L * (r / d) ** 2 * (centre[1] / d);

  it('matches a·L·(r/d)²·cos θ, within 4 standard errors, and the error is under 1 %', () => {
    const { unclamped, stderr } = inspectPath(scene, camera, 1, 1, { samples: 4096, maxBounces: 1 });
    expect(stderr[0]).toBeGreaterThan(0);
    expect(Math.abs(unclamped[0] - expected)).toBeLessThanOrEqual(4 * stderr[0]);
    expect(Math.abs(unclamped[0] - expected)).toBeLessThan(0.01 * expected);
  });

  it('bounces alone agree, with far more noise', () => {
    const on = inspectPath(scene, camera, 1, 1, { samples: 4096, maxBounces: 1 });
    const off = inspectPath(scene, camera, 1, 1, { samples: 4096, maxBounces: 1, lightSampling: false });
    expect(Math.abs(off.unclamped[0] - expected)).toBeLessThanOrEqual(4 * off.stderr[0]);
    expect(off.stderr[0]).toBeGreaterThan(10 * on.stderr[0]);
  });
});

describe('the light sampler', () => {
  /** A table of one light (or the sky), and the densities sampleLight gives and lightPdf says, for the same direction. */
  function densities(objects, sky, from, draws = 200) {
    const lights = lightTable(objects, packMaterials(objects), readSky(sky, [0, 0, 0]), { x: 0, y: 0, z: 0 });
    const random = new PathRandom().start(5, 0, 0, 0), u = new Float64Array(4), out = new Float64Array(LIGHT_SAMPLE);
    const ray = new Float64Array(6), hit = new Float64Array(6), pdf = new Float64Array(1), pairs = [];
    ray.set(from);
    for (let i = 0; i < draws; i++) {
      random.draw(u, 4);
      sampleLight(lights, ray, u, out);
      if (!(out[L_PDF] > 0)) continue;
      ray.set(out.subarray(0, 3), 3);
      const p = out.subarray(L_POINT, L_POINT + 3), o = objects[0];
      hit.set(p);
      if (o instanceof Sphere) hit.set([p[0] - o.center.x, p[1] - o.center.y, p[2] - o.center.z].map((v) => v / o.radius), 3);
      else if (o) {
        const axis = [0, 1, 2].find((k) => Math.abs(p[k] - ['x', 'y', 'z'].map((w) => o.min[w])[k]) < 1e-9 || Math.abs(p[k] - ['x', 'y', 'z'].map((w) => o.max[w])[k]) < 1e-9);
        hit.set([0, 1, 2].map((k) => (k === axis ? 1 : 0)), 3);
      }
      lightPdf(lights, 0, ray, hit, pdf);
      pairs.push([out[L_PDF], pdf[0], Float64Array.from(out)]);
    }
    return { lights, pairs };
  }

  it('draws the same density it weighs a bounce by: a ball from outside and from inside, a box from outside and inside, the sky', () => {
    const ball = new Sphere([0, 3, -4], 1.5, { emission: [2, 2, 2] }), box = new Box([-1, 2, -6], [2, 2.5, -3], { emission: [1, 2, 3] });
    for (const [objects, sky, from] of [[[ball], undefined, [0.3, -1, 0.2]], [[ball], undefined, [0.2, 3.5, -4.3]], [[box], undefined, [0.5, 0, 0]], [[box], undefined, [0, 2.2, -5]], [[], { top: [1, 1, 1], bottom: [0.1, 0.1, 0.1] }, [0, 0, 0]]]) {
      const { pairs } = densities(objects, sky, from);
      expect(pairs.length).toBeGreaterThan(150);
      for (const [drawn, said] of pairs) expect(said / drawn).toBeCloseTo(1, 9);
    }
  });

  it('a ball from outside: every direction lies in the cone it subtends, and the point on its near side', () => {
    const ball = new Sphere([0, 3, -4], 1.5, { emission: [2, 2, 2] }), from = [0.3, -1, 0.2];
    const { pairs } = densities([ball], undefined, from);
    const d = Math.hypot(0 - 0.3, 3 + 1, -4 - 0.2), cosMax = Math.sqrt(1 - (1.5 / d) ** 2);
    for (const [pdf, , out] of pairs) {
      const cos = (out[0] * -0.3 + out[1] * 4 + out[2] * -4.2) / d;
      expect(cos).toBeGreaterThanOrEqual(cosMax - 1e-12);
      expect(pdf).toBeCloseTo(1 / (2 * Math.PI * (1 - cosMax)), 9);
      expect(Math.hypot(out[L_POINT], out[L_POINT + 1] - 3, out[L_POINT + 2] + 4)).toBeCloseTo(1.5, 9);
    }
  });

  it('the sky by its brightness: dy\'s histogram follows the gradient (chi-square), not a uniform sky\'s', () => {
    const { pairs } = densities([], { top: [1, 1, 1], bottom: [0.1, 0.1, 0.1] }, [0, 0, 0], 20000);
    const cells = new Float64Array(10);
    for (const [, , out] of pairs) cells[Math.min(9, Math.floor((out[1] + 1) * 5))]++;
    // density of t = (dy + 1)/2 ∝ 0.1·(1 − t) + t: each cell's share its integral over the cell
    const share = (t0, t1) => (0.1 * (t1 - t0) + 0.45 * (t1 * t1 - t0 * t0)) / 0.55;
    const chi = (expectedShare) => cells.reduce((sum, o, k) => sum + (o - 20000 * expectedShare(k)) ** 2 / (20000 * expectedShare(k)), 0);
    expect(chi((k) => share(k / 10, (k + 1) / 10))).toBeLessThan(27.9); // 9 degrees of freedom, 0.1 %
    expect(chi(() => 0.1)).toBeGreaterThan(10 * 27.9);
  });

  it('lists emissive balls and boxes by power, a gradient sky; not a plane, a ball of no light, a uniform sky', () => {
    const objects = [new Sphere([0, 5, 0], 1, { emission: [1, 1, 1] }), new Box([0, 0, 0], [1, 1, 1], { emission: [3, 3, 3] }),
      new Plane([0, 9, 0], [0, -1, 0], { emission: [5, 5, 5] }), new Sphere([4, 5, 0], 1, { emission: [0, 0, 0] })];
    const lights = lightTable(objects, packMaterials(objects), readSky({ top: [1, 1, 1], bottom: [0, 0, 0] }, [0, 0, 0]), { x: 0, y: 0, z: 0 });
    expect(lights.count).toBe(3);
    expect([...lights.of]).toEqual([0, 1, -1, -1]);
    expect(lights.sky).toBe(2);
    const picks = [0, 1, 2].map((k) => lights.table[k * 10 + 2]);
    expect(picks[0] / picks[1]).toBeCloseTo((4 * Math.PI) / (3 * 6), 12); // emission × area
    expect(picks.reduce((s, p) => s + p, 0)).toBeCloseTo(1, 12);
    expect(lightTable(objects, packMaterials(objects), readSky([0.5, 0.5, 0.5], [0, 0, 0]), { x: 0, y: 0, z: 0 }).sky).toBe(-1);
  });
});

describe('a fuzzy metal\'s density', () => {
  // The metal draws the mirror direction r plus fuzz × a point in the unit ball; light sampling weighs a
  // direction by the density of that draw, which depends on the angle to r alone.
  const fuzz = 0.4, materials = packMaterials([new Sphere([0, 0, 0], 1, { color: [1, 1, 1], reflection: 1, fuzz })]);
  const surface = new Float64Array(SURFACE), dir = new Float64Array(3), out = new Float64Array(1);
  surface.set([0, 0, 0, 0, 1, 0, Math.SQRT1_2, -Math.SQRT1_2, 0]); // a ray coming down at 45°: r = (√½, √½, 0)
  const density = (b) => { // the density of a direction at cos b to r
    dir.set([b * Math.SQRT1_2 - Math.sqrt(1 - b * b) * Math.SQRT1_2, b * Math.SQRT1_2 + Math.sqrt(1 - b * b) * Math.SQRT1_2, 0]);
    metalDensity(materials, 0, surface, dir, out);
    return out[0];
  };
  /** The chance of a direction within cos ≥ c of r: 2π ∫ density db from c to 1 (midpoint rule). */
  const capChance = (c, steps = 20000) => {
    let sum = 0;
    for (let i = 0; i < steps; i++) sum += density(c + ((i + 0.5) * (1 - c)) / steps);
    return 2 * Math.PI * sum * (1 - c) / steps;
  };

  it('sums to one over all directions, and is 0 outside the cone the fuzz ball subtends', () => {
    expect(capChance(-1, 200000)).toBeCloseTo(1, 4);
    expect(density(Math.sqrt(1 - fuzz * fuzz) - 1e-6)).toBe(0);
  });

  it('a lamp\'s blurred highlight on a brushed ball: the same with and without light sampling, less noisy, not counted twice', () => {
    const scene = new Scene({ background: [0, 0, 0] })
      .add(new Plane([0, -1.5, 0], [0, 1, 0], { color: [0.3, 0.3, 0.3] }))
      .add(new Sphere([0, 0, -6], 1.5, { color: [0.9, 0.9, 0.9], reflection: 1, fuzz: 0.3, name: 'brushed' }))
      .add(new Sphere([0, 4, -2], 0.4, { color: [0, 0, 0], emission: [30, 30, 30], name: 'lamp' }));
    const camera = new Camera({ width: 8, height: 8, fov: 30 });
    for (const [x, y] of [[3, 2], [4, 1]]) { // in the highlight
      const on = inspectPath(scene, camera, x, y, { samples: 2048, maxBounces: 2 });
      const off = inspectPath(scene, camera, x, y, { samples: 2048, maxBounces: 2, lightSampling: false, seed: 1 });
      expect(on.bounces[0].lightSample.light).toBe('lamp');
      expect(Math.abs(on.unclamped[0] - off.unclamped[0]), `pixel ${x},${y}`).toBeLessThanOrEqual(4 * Math.hypot(on.stderr[0], off.stderr[0]));
      expect(on.stderr[0]).toBeLessThan(off.stderr[0]);
    }
  });

  it('matches where scatter\'s metal directions fall (cos to r, five caps)', () => {
    const random = new PathRandom().start(9, 0, 0, 0), event = new Float64Array(EVENT), draws = 40000, cosines = [];
    let metal = 0;
    for (let i = 0; i < draws; i++) {
      scatter(materials, 0, random, surface, event);
      if (event[LOBE] === METAL) metal++;
      cosines.push((event[0] + event[1]) * Math.SQRT1_2);
    }
    expect(metal).toBe(draws); // the cone lies wholly above the surface: none absorbed
    for (const c of [0.95, 0.97, 0.98, 0.99, 0.995]) {
      const expected = capChance(c), seen = cosines.filter((b) => b >= c).length / draws;
      expect(Math.abs(seen - expected), `cap cos ≥ ${c}`).toBeLessThan(4 * Math.sqrt(expected * (1 - expected) / draws));
    }
  });
});

describe('no NaN, and the same picture, at the edges', () => {
  it('with no light at all, a light of no power, a tiny light, a light inside a closed box', () => {
    const camera = new Camera({ width: 6, height: 6, fov: 60, position: [0, 1, 0], pitch: -20 });
    const dark = new Scene({ background: [0, 0, 0] }).add(new Plane([0, 0, 0], [0, 1, 0], { color: [0.5, 0.5, 0.5] }));
    expect(pathTrace(dark, camera, { samples: 4 }).every((v, i) => (i % 4 === 3 ? v === 255 : v === 0))).toBe(true);
    const noPower = new Scene({ background: [0.3, 0.3, 0.3] }).add(new Plane([0, 0, 0], [0, 1, 0], { color: [0.5, 0.5, 0.5] }))
      .add(new Sphere([0, 2, -3], 0.5, { emission: [0, 0, 0] })).add(new Box([1, 0, -4], [2, 1, -3], { emission: [1e-300, 0, 0] }));
    const tiny = new Scene({ background: [0, 0, 0] }).add(new Plane([0, 0, 0], [0, 1, 0], { color: [0.5, 0.5, 0.5] }))
      .add(new Sphere([0, 2, -3], 1e-9, { emission: [1e6, 1e6, 1e6] }));
    const boxed = new Scene({ background: [1, 1, 1] })
      .add(new Box([-3, -0.5, -6], [3, 3, 2], { color: [0.6, 0.6, 0.6], name: 'room' }))
      .add(new Sphere([0, 2, -3], 0.4, { color: [0, 0, 0], emission: [6, 6, 6], name: 'lamp' }));
    for (const scene of [noPower, tiny, boxed]) {
      for (const lightSampling of [true, false]) {
        const stats = pixelStats(scene, camera, { lightSampling, seed: 4 }, 16); // asserts every sample finite
        expect(stats.mean.every(Number.isFinite)).toBe(true);
      }
    }
    const on = regions(pixelStats(boxed, camera, { seed: 1 }, 256), 3), off = regions(pixelStats(boxed, camera, { seed: 2, lightSampling: false }, 256), 3); // four regions of 3×3
    for (const { k, c, difference, bound } of compare(on, off)) expect(difference, `closed box, region ${k}, channel ${c}`).toBeLessThanOrEqual(bound);
  }, 120_000);
});

describe('less noise', () => {
  it('the Cornell box: the per-pixel variance at least 3× smaller on average (8× at the median pixel)', () => {
    const scene = cornellBox(8), camera = cornellCamera(32, 32);
    const per = (options) => {
      const { variance } = pixelStats(scene, camera, options, 12), pixels = [];
      for (let i = 0; i < variance.length; i += 3) pixels.push((variance[i] + variance[i + 1] + variance[i + 2]) / 3);
      pixels.sort((p, q) => p - q);
      return { mean: pixels.reduce((s, v) => s + v, 0) / pixels.length, median: pixels[pixels.length >> 1] };
    };
    const on = per({ seed: 1 }), off = per({ seed: 1, lightSampling: false });
    expect(off.mean / on.mean).toBeGreaterThan(3);
    expect(off.median / on.median).toBeGreaterThan(8);
  }, 120_000);
});

describe('the noise a page shows', () => {
  /** A progressive renderer's noise after `samples` passes. */
  const noiseAfter = (scene, camera, path) => {
    const tracer = new PathProgressiveRenderer({ scene, camera, path, now: () => 0 }); // a clock that never moves: a step traces until the frame is done
    const seen = [tracer.noise];
    while (!tracer.done) { tracer.step(); seen.push(tracer.noise); }
    return seen;
  };

  it('is each pixel\'s standard error averaged (none before two samples, 0 for a sky alone), and lower with light sampling at the same samples', () => {
    const camera = cornellCamera(16, 16);
    const on = noiseAfter(cornellBox(8), camera, { samples: 12, seed: 3 }), off = noiseAfter(cornellBox(8), camera, { samples: 12, seed: 3, lightSampling: false });
    expect(on[0]).toBeNull();
    expect(on.at(-1)).toBeGreaterThan(0);
    expect(on.at(-1)).toBeLessThan(0.6 * off.at(-1));
    const scene = cornellBox(8), frame = preparePaths(scene, camera, readPathOptions({ samples: 12, seed: 3 }, scene, camera));
    let total = 0; // the same number from the samples themselves: each pixel's brightness, its spread over √12
    for (let y = 0; y < 16; y++) {
      for (let x = 0; x < 16; x++) {
        const values = Array.from({ length: 12 }, (_, s) => { tracePath(frame, x, y, s); return (radiance[0] + radiance[1] + radiance[2]) / 3; });
        const mean = values.reduce((a, v) => a + v, 0) / 12;
        total += Math.sqrt(values.reduce((a, v) => a + (v - mean) ** 2, 0) / 11 / 12);
      }
    }
    expect(on.at(-1)).toBeCloseTo(total / 256, 9);
    expect(noiseAfter(new Scene({ background: [0.4, 0.5, 0.6] }), camera, { samples: 3 }).at(-1)).toBe(0);
  });
});

describe('inspectPath tells each diffuse bounce\'s light sample', () => {
  const scene = new Scene({ background: [0.05, 0.05, 0.05] })
    .add(new Plane([0, -2, 0], [0, 1, 0], { color: [0.75, 0.75, 0.7], name: 'floor' }))
    .add(new Sphere([1.5, -1, -11], 1, { color: [0.9, 0.9, 0.9], reflection: 1, fuzz: 0.2, name: 'mirror' }))
    .add(new Box([-2, -2, -12], [-1, 0.5, -11], { color: [0.8, 0.2, 0.2], name: 'block' }))
    .add(new Sphere([0, 5, -12], 1.5, { color: [0, 0, 0], emission: [4, 4, 3.6], name: 'lamp' }));
  const camera = new Camera({ width: 24, height: 18, fov: 40, position: [0, 1, 0], pitch: -5 });

  it('light, point, direction, blocked, pdf, weight, contribution; skipped on metal and when off', () => {
    const paths = Array.from({ length: 60 }, (_, sample) => inspectPath(scene, camera, 12, 14, { sample, maxBounces: 4 }));
    const diffuse = paths.flatMap((p) => p.bounces).filter((b) => b.lobe === 'diffuse');
    expect(diffuse.length).toBeGreaterThan(20);
    let lit = 0, blocked = 0;
    for (const b of diffuse) {
      const s = b.lightSample;
      expect(s.light).toBe('lamp');
      expect(Math.hypot(s.direction.x, s.direction.y, s.direction.z)).toBeCloseTo(1, 12);
      expect(Math.hypot(s.point.x, s.point.y - 5, s.point.z + 12)).toBeCloseTo(1.5, 9); // on the lamp
      expect(s.pdf).toBeGreaterThan(0);
      if (s.below) { expect(s.contribution).toEqual([0, 0, 0]); continue; }
      if (s.blocked !== null) {
        blocked++;
        expect(['floor', 'mirror', 'block']).toContain(s.blocked);
        expect(s.contribution).toEqual([0, 0, 0]);
      } else {
        lit++;
        expect(s.weight).toBeGreaterThan(0);
        expect(s.weight).toBeLessThanOrEqual(1);
        expect(s.contribution[0]).toBeGreaterThan(0);
      }
    }
    expect(lit).toBeGreaterThan(5);
    expect(blocked).toBeGreaterThan(0);
    const metal = paths.flatMap((p) => p.bounces).find((b) => b.lobe === 'metal');
    expect(metal.lightSample.light).toBe('lamp'); // a fuzzy metal aims at the lights too
    expect(metal.lightSkipped).toBeUndefined();
    const mirrorScene = new Scene({ background: [0.05, 0.05, 0.05] }).add(scene.objects[3])
      .add(new Sphere([0, 1, -8], 1.5, { color: [0.9, 0.9, 0.9], reflection: 1, name: 'mirror' }));
    const mirror = inspectPath(mirrorScene, camera, 12, 9, { maxBounces: 2 }).bounces[0];
    expect(mirror.lobe).toBe('metal');
    expect(mirror.lightSample).toBeUndefined();
    expect(mirror.lightSkipped).toMatch(/mirror/);
    const off = inspectPath(scene, camera, 12, 14, { sample: 0, lightSampling: false });
    expect(off.bounces.every((b) => b.lightSample === undefined && b.lightSkipped === undefined)).toBe(true);
    const none = inspectPath(new Scene({ background: [0.5, 0.5, 0.5] }).add(new Plane([0, -2, 0], [0, 1, 0])), camera, 12, 14);
    expect(none.bounces[0].lightSkipped).toMatch(/no light/);
  });

  it('bad lightSampling is named', () => {
    expect(() => pathTrace(scene, camera, { samples: 1, lightSampling: 'yes' })).toThrow(/lightSampling/);
  });
});
