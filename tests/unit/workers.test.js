import { describe, it, expect } from 'vitest';
import { ParallelRenderer, splitRows, bandHeight, claimHeight } from '../../lib/tracing/workers/parallel.js';
import { workerHandler, REPORT_MS } from '../../lib/tracing/workers/split.js';
import { fakeWorkers, silentWorker, neverLoadedWorker } from './fake-workers.js';
import { sceneToJSON, cameraToJSON } from '../../lib/scene/json.js';
import { render, Camera, Scene, Sphere, Plane, Box, PointLight, Material, classScene, classSceneAt } from '../../lib/index.js';

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

  it('bandHeight: half a tile (8 rows) on tall frames, fewer so that every worker gets 16 bands or one-row bands', () => {
    expect(bandHeight(480, 2)).toBe(8);
    expect(bandHeight(240, 4)).toBe(3);
    expect(bandHeight(23, 3)).toBe(1);
    for (const [height, parts] of [[480, 2], [240, 4], [120, 8], [1000, 3], [240, 2]]) {
      const rows = bandHeight(height, parts);
      expect(rows === 1 || splitRows(height, parts, rows).every((bands) => bands.length >= 16), `${height} rows, ${parts} workers`).toBe(true);
    }
  });

  it('claimHeight: bands taken from a counter are thinner still (4 rows at most, 32 a worker or one-row bands)', () => {
    expect(claimHeight(480, 2)).toBe(4);
    expect(claimHeight(240, 2)).toBe(3);
    expect(claimHeight(23, 3)).toBe(1);
    expect(claimHeight(4000, 1)).toBe(4);
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

describe('ParallelRenderer', () => {
  it('is not available in Node, and falls back to render() on the main thread', async () => {
    expect(ParallelRenderer.available).toBe(false);
    const scene = classScene(), camera = new Camera({ width: 37, height: 23 });
    const calls = [];
    const parallel = new ParallelRenderer({ workers: 3 });
    expect(parallel.usingWorkers).toBe(false);
    const buffer = await parallel.render(scene, camera, { onRows: (y0, y1) => calls.push([y0, y1]) });
    expect(buffer).toEqual(render(scene, camera));
    expect(calls).toEqual([[0, 23]]);
    parallel.terminate();
  });

  for (const shared of [false, true]) {
    for (const workers of [1, 2, 3, 7]) {
      for (const [width, height] of [[37, 23], [16, 5], [20, 41]]) {
        it(`${workers} worker(s) at ${width}×${height}, ${shared ? 'one shared frame' : 'rows transferred'}: render()'s picture, byte for byte, every row arriving once`, async () => {
          const fake = fakeWorkers();
          const parallel = new ParallelRenderer({ workers, rowsPerBand: 3, shared, createWorker: fake.create });
          expect(parallel.shared).toBe(shared);
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
            expect(buffer.buffer).toBeInstanceOf(ArrayBuffer); // never the shared frame itself: ImageData takes only this
            expect(arrived.every((n) => n === 1)).toBe(true);
          }
          // Workers are started once and reused; none is started without rows to render.
          expect(fake.started.length).toBe(Math.min(workers, Math.ceil(height / 3)));
          expect(parallel.problem).toBe(null);
          parallel.terminate();
          expect(fake.started.every((w) => w.terminated)).toBe(true);
        });
      }
    }
  }

  it('sends the scene and camera once per change, and each worker answers a short frame in one message', async () => {
    const fake = fakeWorkers({ now: () => 0 }); // a clock that stands still: every frame is "short"
    const parallel = new ParallelRenderer({ workers: 2, createWorker: fake.create });
    const camera = new Camera({ width: 64, height: 480 });
    const answers = [];
    await parallel.render(classScene(), camera, { onRows: () => answers.push(1) });
    await parallel.render(classScene(), camera); // the same scene, built again: nothing new to send
    await parallel.render(classSceneAt(1), camera); // a change
    const withScene = fake.received.map((m) => m.scene !== undefined);
    expect(withScene).toEqual([true, true, false, false, true, true]);
    expect(fake.received.every((m) => m.bands.length === 30)).toBe(true); // 480 rows in 8-row bands, dealt in turn
    expect(answers.length).toBe(60); // onRows: once per band
    expect(fake.answers.length).toBe(3 * 2); // but a worker answers a frame in one message
    expect(await parallel.render(classSceneAt(1), camera)).toEqual(render(classSceneAt(1), camera));
  });

  it('a shared frame: every worker gets the same job, and the bands are taken from one counter, each once', async () => {
    const fake = fakeWorkers({ now: () => 0 });
    const parallel = new ParallelRenderer({ workers: 3, shared: true, createWorker: fake.create });
    const camera = new Camera({ width: 48, height: 100 });
    const arrived = new Array(100).fill(0);
    for (const scene of [classScene(), classSceneAt(3)]) {
      arrived.fill(0);
      expect(await parallel.render(scene, camera, { onRows: (y0, y1) => { for (let y = y0; y < y1; y++) arrived[y]++; } })).toEqual(render(scene, camera));
      expect(arrived.every((n) => n === 1)).toBe(true);
    }
    const jobs = fake.received.map(({ id, rowsPerBand, shared, next, bands }) => ({ id, rowsPerBand, shared: shared instanceof SharedArrayBuffer, next: next instanceof SharedArrayBuffer, bands }));
    expect(jobs).toEqual([1, 1, 1, 2, 2, 2].map((id) => ({ id, rowsPerBand: claimHeight(100, 3), shared: true, next: true, bands: undefined })));
    // The frames are reused: the second render wrote into the first one's shared frame, its counter set back to 0.
    expect(fake.received[3].shared).toBe(fake.received[0].shared);
    // The fake workers run one after the other: the first takes every band, the others find none left.
    expect(fake.answers.map((m) => m.bands.length)).toEqual([100, 0, 0, 100, 0, 0]); // one-row bands: 100 rows over 3 workers
  });

  it('two renders at once each get their own picture, shared or transferred', async () => {
    for (const shared of [false, true]) {
      const fake = fakeWorkers();
      const parallel = new ParallelRenderer({ workers: 2, shared, createWorker: fake.create });
      const a = new Camera({ width: 24, height: 17 }), b = new Camera({ width: 19, height: 30, yaw: 20 });
      const [pa, pb] = await Promise.all([parallel.render(classScene(), a), parallel.render(roomScene(), b)]);
      expect(pa).toEqual(render(classScene(), a));
      expect(pb).toEqual(render(roomScene(), b));
    }
  });

  it('rejects a scene that cannot travel as JSON, before any worker starts', async () => {
    const fake = fakeWorkers();
    const parallel = new ParallelRenderer({ workers: 2, createWorker: fake.create });
    const scene = classScene();
    scene.objects.push({ hit: () => Infinity, material: new Material() }); // a shape of the sketch's own: it traces, but has no JSON
    await expect(parallel.render(scene, new Camera({ width: 4, height: 4 }))).rejects.toThrow(/spheres, planes, boxes or point lights/);
    await expect(parallel.render(classScene(), { width: 4, height: 4 })).rejects.toThrow(/camera must be a Camera/);
    expect(fake.started.length).toBe(0);
  });

  describe('a failing worker: the main thread renders instead, the same bytes, and says why', () => {
    const camera = new Camera({ width: 31, height: 40, yaw: -4 });
    const expected = render(classScene(), camera);

    it('a worker that never answers is given up on after timeoutMs', async () => {
      const problems = [], workers = [];
      const parallel = new ParallelRenderer({
        workers: 2, timeoutMs: 40, onProblem: (e) => problems.push(e.message),
        createWorker: () => { const w = silentWorker(); workers.push(w); return w; },
      });
      const arrived = new Array(40).fill(0);
      const started = performance.now();
      const buffer = await parallel.render(classScene(), camera, { onRows: (y0, y1) => { for (let y = y0; y < y1; y++) arrived[y]++; } });
      expect(performance.now() - started).toBeGreaterThanOrEqual(39);
      expect(buffer).toEqual(expected);
      expect(arrived.every((n) => n === 1)).toBe(true);
      expect(problems).toEqual(['render worker 1 did not answer within 0.04 s; rendering on the main thread instead']);
      expect(parallel.problem).toBe(problems[0]);
      expect(workers.every((w) => w.terminated)).toBe(true);
      // From then on every frame is the main thread's, at once, with no new worker and no new message.
      expect(await parallel.render(classScene(), camera)).toEqual(expected);
      expect(workers.length).toBe(2);
      expect(problems.length).toBe(1);
    });

    it('a worker still loading its code has startTimeoutMs, not timeoutMs: its rows are its own once it has loaded', async () => {
      const problems = [];
      const slow = fakeWorkers(undefined, { loadMs: 150 });
      const parallel = new ParallelRenderer({ workers: 2, timeoutMs: 40, startTimeoutMs: 2000, createWorker: slow.create, onProblem: (e) => problems.push(e.message) });
      const started = performance.now();
      expect(await parallel.render(classScene(), camera)).toEqual(expected);
      expect(performance.now() - started).toBeGreaterThanOrEqual(149); // longer than timeoutMs: waited for, not given up on
      expect(problems).toEqual([]);
      expect(slow.answers.length).toBeGreaterThan(0); // the workers traced it
      // Loaded now: a silence in a frame counts by timeoutMs again.
      expect(await parallel.render(classScene(), new Camera({ width: 31, height: 40, yaw: 3 }))).toEqual(render(classScene(), new Camera({ width: 31, height: 40, yaw: 3 })));
      expect(parallel.usingWorkers).toBe(true);
    });

    it('a worker whose code never loads is given up on after startTimeoutMs, and says so', async () => {
      const problems = [];
      const parallel = new ParallelRenderer({ workers: 2, timeoutMs: 20, startTimeoutMs: 80, createWorker: neverLoadedWorker, onProblem: (e) => problems.push(e.message) });
      const started = performance.now();
      expect(await parallel.render(classScene(), camera)).toEqual(expected);
      expect(performance.now() - started).toBeGreaterThanOrEqual(79);
      expect(problems).toEqual(['render worker 1 did not start within 0.08 s; rendering on the main thread instead']);
      expect(() => new ParallelRenderer({ startTimeoutMs: -1 })).toThrow(/startTimeoutMs must be a positive whole number, got -1/);
    });

    it('one silent worker among answering ones: the rows it owed are rendered here, the others kept', async () => {
      const fake = fakeWorkers();
      let n = 0;
      const parallel = new ParallelRenderer({ workers: 3, rowsPerBand: 2, timeoutMs: 60, createWorker: () => (n++ === 1 ? silentWorker() : fake.create()) });
      expect(await parallel.render(classScene(), camera)).toEqual(expected);
      expect(parallel.problem).toMatch(/^render worker 2 did not answer/);
    });

    it('a shared frame: a worker that stops after taking bands from the counter: the bands it took are rendered here', async () => {
      const fake = fakeWorkers();
      let t = 0;
      const dying = {
        onmessage: null, onerror: null, terminated: false,
        postMessage(job) {
          // Takes a band, renders it, takes another, and dies at its first report: two bands taken, none reported.
          const handle = workerHandler({ now: () => (t += REPORT_MS) });
          setTimeout(() => { try { handle(job, () => { throw new Error('gone'); }); } catch { /* it died */ } });
        },
        terminate() { dying.terminated = true; },
      };
      setTimeout(() => dying.onmessage?.({ data: { ready: true } })); // it loaded, as render-worker.js says
      let n = 0;
      const parallel = new ParallelRenderer({ workers: 2, shared: true, timeoutMs: 60, createWorker: () => (n++ === 0 ? dying : fake.create()) });
      const arrived = new Array(40).fill(0);
      expect(await parallel.render(classScene(), camera, { onRows: (y0, y1) => { for (let y = y0; y < y1; y++) arrived[y]++; } })).toEqual(expected);
      expect(arrived.every((k) => k === 1)).toBe(true);
      expect(parallel.problem).toMatch(/^render worker 1 did not answer within 0.06 s/);
      expect(dying.terminated).toBe(true);
    });

    it('a worker that cannot start (its script fails to load)', async () => {
      const problems = [];
      const crashing = () => {
        const w = { terminate() {}, postMessage() { setTimeout(() => w.onerror({ message: '' })); } };
        return w;
      };
      const parallel = new ParallelRenderer({ workers: 2, createWorker: crashing, onProblem: (e) => problems.push(e.message) });
      expect(await parallel.render(classScene(), camera)).toEqual(expected);
      expect(problems).toEqual(['render worker 1 failed (it could not start); rendering on the main thread instead']);
    });

    it('a Worker constructor that throws (no workers from file://, say)', async () => {
      const parallel = new ParallelRenderer({ workers: 2, createWorker: () => { throw new DOMException('Script at file:///x.js cannot be accessed', 'SecurityError'); } });
      expect(await parallel.render(classScene(), camera)).toEqual(expected);
      expect(parallel.problem).toBe('render workers could not start (Script at file:///x.js cannot be accessed); rendering on the main thread instead');
      expect(parallel.warm().usingWorkers).toBe(false);
    });

    it('a worker that reports an error', async () => {
      const broken = {
        onmessage: null, onerror: null, terminated: false,
        postMessage(data) { setTimeout(() => broken.onmessage({ data: { id: data.id, error: 'RangeError: out of memory' } })); },
        terminate() { broken.terminated = true; },
      };
      const parallel = new ParallelRenderer({ workers: 1, createWorker: () => broken });
      expect(await parallel.render(classScene(), camera)).toEqual(expected);
      expect(parallel.problem).toBe('render worker 1 reported RangeError: out of memory; rendering on the main thread instead');
      expect(broken.terminated).toBe(true);
    });
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
    expect(() => new ParallelRenderer({ timeoutMs: 0 })).toThrow(/timeoutMs must be a positive whole number/);
    expect(() => new ParallelRenderer({ shared: 'yes' })).toThrow(/shared must be 'auto', true or false, got "yes"/);
    expect(() => new ParallelRenderer({ onProblem: 'alert' })).toThrow(/onProblem must be a function/);
    expect(() => new ParallelRenderer({ createWorker: 'render-worker.js' })).toThrow(/createWorker must be a function/);
    expect(new ParallelRenderer().shared).toBe(false); // Node is not a cross-origin isolated page
  });
});

describe('workerHandler (what a worker does)', () => {
  const scene = classScene(), camera = new Camera({ width: 13, height: 11 });
  const expected = render(scene, camera);
  const job = (more) => ({ id: 5, version: 1, scene: sceneToJSON(scene), camera: cameraToJSON(camera), ...more });

  it(`reports its finished bands at most once per REPORT_MS (${REPORT_MS}) of work, the last with done; put together they are render()'s rows`, () => {
    const messages = [];
    let t = 0;
    const bands = [[0, 1], [2, 3], [4, 5], [6, 7], [8, 9], [10, 11]];
    workerHandler({ now: () => (t += REPORT_MS * 0.6) })(job({ bands }), (m, transfer) => messages.push({ m, transfer }));
    expect(messages.map(({ m }) => [m.id, m.bands, m.done])).toEqual([
      [5, [[0, 1], [2, 3]], false], [5, [[4, 5], [6, 7]], false], [5, [[8, 9], [10, 11]], true],
    ]);
    for (const { m, transfer } of messages) {
      expect(transfer).toEqual([m.pixels]);
      const rows = m.bands.map(([y0, y1]) => [...expected.slice(y0 * 13 * 4, y1 * 13 * 4)]).flat();
      expect([...new Uint8ClampedArray(m.pixels)]).toEqual(rows);
    }
  });

  it('answers a short frame in one message', () => {
    const messages = [];
    workerHandler({ now: () => 0 })(job({ bands: [[0, 3], [6, 9]] }), (m) => messages.push(m));
    expect(messages.map((m) => [m.bands, m.done])).toEqual([[[[0, 3], [6, 9]], true]]);
  });

  it('with a shared frame and no counter, writes its bands there and posts no pixels', () => {
    const shared = new SharedArrayBuffer(13 * 11 * 4), messages = [];
    workerHandler({ now: () => 0 })(job({ bands: [[0, 4], [8, 11]], shared }), (m) => messages.push(m));
    expect(messages).toEqual([{ id: 5, bands: [[0, 4], [8, 11]], done: true }]);
    const frame = new Uint8ClampedArray(shared);
    expect(frame.slice(0, 4 * 52)).toEqual(expected.slice(0, 4 * 52));
    expect(frame.slice(8 * 52)).toEqual(expected.slice(8 * 52));
    expect(frame.slice(4 * 52, 8 * 52).every((b) => b === 0)).toBe(true);
  });

  it('with a counter, takes bands from it until the frame runs out, sharing them with the other workers', () => {
    const shared = new SharedArrayBuffer(13 * 11 * 4), next = new SharedArrayBuffer(4);
    const a = [], b = [];
    let t = 0;
    const clock = () => (t += REPORT_MS); // every band "takes" REPORT_MS: a reports each band before taking the next
    const handleB = workerHandler({ now: clock });
    // Worker b starts while worker a is at its first report: b takes all that is left, a finds nothing more.
    workerHandler({ now: clock })(job({ shared, next, rowsPerBand: 3 }), (m) => {
      a.push(m);
      if (a.length === 1) handleB(job({ shared, next, rowsPerBand: 3 }), (mb) => b.push(mb));
    });
    expect(a).toEqual([{ id: 5, bands: [[0, 3]], done: false }, { id: 5, bands: [[3, 6]], done: true }]);
    expect(b.map((m) => [m.bands, m.done])).toEqual([[[[6, 9]], false], [[[9, 11]], true]]);
    expect(new Uint8ClampedArray(shared)).toEqual(expected);
    expect(new Int32Array(next)[0]).toBeGreaterThanOrEqual(4); // every band taken (each worker's last take found none)
  });

  it('keeps the scene between jobs, and says so when a job names a version it never got', () => {
    const handle = workerHandler(), messages = [];
    handle(job({ bands: [[0, 11]] }), (m) => messages.push(m));
    handle({ id: 6, version: 1, bands: [[0, 11]] }, (m) => messages.push(m));
    expect(new Uint8ClampedArray(messages.at(-1).pixels)).toEqual(expected);
    handle({ id: 7, version: 2, bands: [[0, 1]] }, (m) => messages.push(m));
    expect(messages[2]).toEqual({ id: 7, error: 'Error: scene version 2 never arrived (have 1)' });
  });

  it('posts an error naming the bad field instead of throwing', () => {
    const messages = [];
    const bad = { objects: [{ type: 'sphere', center: [0, 0, 0], radius: 0 }] };
    workerHandler()({ id: 1, version: 1, scene: bad, camera: { width: 2, height: 2 }, bands: [[0, 2]] }, (m) => messages.push(m));
    expect(messages).toEqual([{ id: 1, error: 'RangeError: objects[0].radius must be greater than 0, got 0' }]);
  });
});
