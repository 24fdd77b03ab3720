import { describe, it, expect } from 'vitest';
import { ParallelRenderer, splitRows } from '../../lib/workers/parallel.js';
import { runJob } from '../../lib/workers/split.js';
import { sceneToJSON, cameraToJSON } from '../../lib/serialize.js';
import { render, Camera, Scene, Sphere, Plane, Box, PointLight, classScene } from '../../lib/index.js';

describe('splitRows', () => {
  it('puts every row in exactly one band, for many heights, worker counts and band sizes', () => {
    const wrong = []; // every case that fails, listed, so a failure says which
    for (let height = 1; height <= 70; height++) {
      for (let parts = 1; parts <= 9; parts++) {
        for (const rowsPerBand of [1, 2, 3, 4, 16]) {
          const shares = splitRows(height, parts, rowsPerBand);
          const seen = new Array(height).fill(0);
          let badBand = false;
          for (const [y0, y1] of shares.flat()) {
            if (!(y1 > y0 && y1 - y0 <= rowsPerBand)) badBand = true;
            for (let y = y0; y < y1; y++) seen[y]++;
          }
          if (shares.length !== parts || badBand || seen.some((n) => n !== 1)) wrong.push({ height, parts, rowsPerBand });
        }
      }
    }
    expect(wrong).toEqual([]);
  });

  it('deals bands out in turn, so the shares differ by at most one band', () => {
    expect(splitRows(7, 3)).toEqual([[[0, 1], [3, 4], [6, 7]], [[1, 2], [4, 5]], [[2, 3], [5, 6]]]);
    expect(splitRows(10, 2, 4)).toEqual([[[0, 4], [8, 10]], [[4, 8]]]);
    expect(splitRows(2, 4)).toEqual([[[0, 1]], [[1, 2]], [], []]);
    const sizes = splitRows(101, 6, 3).map((bands) => bands.length);
    expect(Math.max(...sizes) - Math.min(...sizes)).toBeLessThanOrEqual(1);
  });

  it('checks its arguments', () => {
    expect(() => splitRows(0, 2)).toThrow(/height must be a positive whole number/);
    expect(() => splitRows(10, 1.5)).toThrow(/parts must be a positive whole number/);
    expect(() => splitRows(10, 2, 0)).toThrow(/rowsPerBand/);
  });
});

function roomScene() {
  const scene = new Scene({ background: [0.3, 0.4, 0.6], ambient: 0.05 });
  scene.add(new Plane([0, -2, 0], [0, 1, 0], { color: [0.7, 0.7, 0.7], reflection: 0.2 }));
  scene.add(new Box([-3, -2, -14], [-1, 0, -12], { color: 'orange' }));
  scene.add(new Sphere([1.5, -0.5, -12], 1.5, { color: 'pink', transparency: 0.5, specular: 0.5 }));
  scene.add(new PointLight([4, 6, -2], [1, 1, 1], 1.1));
  return scene;
}

/**
 * A stand-in for a Web Worker: runs the real worker job (runJob) later, on
 * structured clones of the messages, as a worker would.
 */
function fakeWorkers() {
  const started = [];
  const create = () => {
    const worker = {
      onmessage: null, onerror: null, terminated: false, jobs: 0,
      postMessage(data) {
        worker.jobs++;
        const job = structuredClone(data);
        setTimeout(() => runJob(job, (message, transfer) => {
          const copy = structuredClone(message, { transfer });
          setTimeout(() => { if (!worker.terminated) worker.onmessage({ data: copy }); });
        }));
      },
      terminate() { worker.terminated = true; },
    };
    started.push(worker);
    return worker;
  };
  return { create, started };
}

describe('ParallelRenderer', () => {
  it('is not available in Node, and falls back to render() on the main thread', async () => {
    expect(ParallelRenderer.available).toBe(false);
    const scene = classScene(), camera = new Camera({ width: 37, height: 23 });
    const calls = [];
    const parallel = new ParallelRenderer({ workers: 3 });
    const buffer = await parallel.render(scene, camera, { onRows: (y0, y1) => calls.push([y0, y1]) });
    expect(buffer).toEqual(render(scene, camera));
    expect(calls).toEqual([[0, 23]]);
    parallel.terminate();
  });

  for (const workers of [1, 2, 3, 7]) {
    for (const [width, height] of [[37, 23], [16, 5], [20, 41]]) {
      it(`${workers} worker(s) at ${width}×${height}: render()'s picture, byte for byte, every row arriving once`, async () => {
        const fake = fakeWorkers();
        const parallel = new ParallelRenderer({ workers, rowsPerBand: 3, createWorker: fake.create });
        for (const scene of [classScene({ full: true }), roomScene()]) {
          const camera = new Camera({ width, height, fov: 40, yaw: 3 });
          const arrived = new Array(height).fill(0);
          const buffer = await parallel.render(scene, camera, {
            onRows: (y0, y1, frame) => {
              for (let y = y0; y < y1; y++) arrived[y]++;
              expect(frame.length).toBe(width * height * 4);
            },
          });
          expect(buffer).toEqual(render(scene, camera));
          expect(arrived.every((n) => n === 1)).toBe(true);
        }
        // Workers are started once and reused; none is started without rows to render.
        expect(fake.started.length).toBe(Math.min(workers, Math.ceil(height / 3)));
        parallel.terminate();
        expect(fake.started.every((w) => w.terminated)).toBe(true);
      });
    }
  }

  it('two renders at once each get their own picture', async () => {
    const fake = fakeWorkers();
    const parallel = new ParallelRenderer({ workers: 2, createWorker: fake.create });
    const a = new Camera({ width: 24, height: 17 }), b = new Camera({ width: 19, height: 30, yaw: 20 });
    const [pa, pb] = await Promise.all([parallel.render(classScene(), a), parallel.render(roomScene(), b)]);
    expect(pa).toEqual(render(classScene(), a));
    expect(pb).toEqual(render(roomScene(), b));
  });

  it('rejects a scene that cannot travel as JSON, before any worker starts', async () => {
    const fake = fakeWorkers();
    const parallel = new ParallelRenderer({ workers: 2, createWorker: fake.create });
    const scene = classScene();
    scene.objects.push({ hit: () => Infinity, material: { isEmissive: false } });
    await expect(parallel.render(scene, new Camera({ width: 4, height: 4 }))).rejects.toThrow(/spheres, planes, boxes or point lights/);
    await expect(parallel.render(classScene(), { width: 4, height: 4 })).rejects.toThrow(/camera must be a Camera/);
    expect(fake.started.length).toBe(0);
  });

  it('rejects when a worker reports an error or fails, and starts a new worker next time', async () => {
    const broken = {
      onmessage: null, onerror: null, terminated: false,
      postMessage(data) { setTimeout(() => broken.onmessage({ data: { id: data.id, error: 'RangeError: out of memory' } })); },
      terminate() { broken.terminated = true; },
    };
    const parallel = new ParallelRenderer({ workers: 1, createWorker: () => broken });
    const camera = new Camera({ width: 8, height: 6 });
    await expect(parallel.render(classScene(), camera)).rejects.toThrow('render worker: RangeError: out of memory');

    let starts = 0;
    const crashing = () => {
      starts++;
      const w = { terminate() {}, postMessage() { setTimeout(() => w.onerror({ message: 'SyntaxError in worker' })); } };
      return w;
    };
    const p2 = new ParallelRenderer({ workers: 1, createWorker: crashing });
    await expect(p2.render(classScene(), camera)).rejects.toThrow('render worker failed: SyntaxError in worker');
    await expect(p2.render(classScene(), camera)).rejects.toThrow('render worker failed');
    expect(starts).toBe(2);
  });

  it('terminate() rejects a render under way', async () => {
    const fake = fakeWorkers();
    const parallel = new ParallelRenderer({ workers: 2, createWorker: fake.create });
    const pending = parallel.render(classScene(), new Camera({ width: 30, height: 20 }));
    await Promise.resolve(); // let render() post its jobs
    parallel.terminate();
    await expect(pending).rejects.toThrow('terminated');
  });

  it('checks its options', () => {
    expect(() => new ParallelRenderer({ workers: 0 })).toThrow(/workers must be a positive whole number, got 0/);
    expect(() => new ParallelRenderer({ rowsPerBand: -1 })).toThrow(/rowsPerBand/);
    expect(() => new ParallelRenderer({ createWorker: 'render-worker.js' })).toThrow(/createWorker must be a function/);
  });
});

describe('runJob (what a worker does)', () => {
  it('posts each band of rows, then done; the bands put together are render()\'s rows', () => {
    const scene = classScene(), camera = new Camera({ width: 13, height: 11 });
    const expected = render(scene, camera);
    const messages = [];
    runJob({ id: 5, scene: sceneToJSON(scene), camera: cameraToJSON(camera), bands: [[0, 2], [6, 11]] }, (m, transfer) => messages.push({ m, transfer }));
    expect(messages.map(({ m }) => [m.id, m.y0, m.y1, m.done])).toEqual([[5, 0, 2, undefined], [5, 6, 11, undefined], [5, undefined, undefined, true]]);
    for (const { m, transfer } of messages.slice(0, 2)) {
      expect(transfer).toEqual([m.pixels]);
      expect(new Uint8ClampedArray(m.pixels)).toEqual(expected.slice(m.y0 * 13 * 4, m.y1 * 13 * 4));
    }
  });

  it('posts an error naming the bad field instead of throwing', () => {
    const messages = [];
    const scene = { objects: [{ type: 'sphere', center: [0, 0, 0], radius: 0 }] };
    runJob({ id: 1, scene, camera: { width: 2, height: 2 }, bands: [[0, 2]] }, (m) => messages.push(m));
    expect(messages).toEqual([{ id: 1, error: 'RangeError: objects[0].radius must be greater than 0, got 0' }]);
  });
});
