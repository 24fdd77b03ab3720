/**
 * The mesh benchmark, part of `npm run bench` (alone: `node bench/bvh.js`).
 *
 * (1) The BVH's scaling: the same rays at a sphere tessellated into about
 *     1k and 100k triangles, timed in turns; the per-ray cost ratio should
 *     follow log(n), not n (goal ≤ 4×).
 * (2) A 320×240 frame of the Stanford bunny (the `bunny` package, 3674
 *     triangles) on one thread: primary rays, nearest hit, Lambert shading
 *     from one direction (goal ≤ 250 ms); then the same view as a Scene
 *     through render(), the kernel (lib/tracing/kernel.js) against trace.js (the
 *     mesh's `hit` replaced by itself, which packScene refuses): full
 *     shading with one point light and shadow rays.
 *
 * Timing figures are printed, never asserted: they depend on the machine.
 * The load average printed beside them says how busy it was.
 */
import { performance } from 'node:perf_hooks';
import { loadavg, availableParallelism } from 'node:os';
import { pathToFileURL, fileURLToPath } from 'node:url';
import { execFileSync } from 'node:child_process';
import bunny from 'bunny';
import { Camera } from '../lib/math/camera.js';
import { Ray } from '../lib/math/ray.js';
import { Vec3 } from '../lib/math/vec3.js';
import { Mesh } from '../lib/shapes/mesh.js';
import { Scene } from '../lib/scene/scene.js';
import { PointLight } from '../lib/lights/point-light.js';
import { render } from '../lib/tracing/render.js';
import { packScene } from '../lib/tracing/kernel.js';

const ROUNDS = 15;
const WARMUP = 3;

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}

/** A unit sphere as an n × n latitude–longitude grid: 2n² triangles. */
export function sphereMesh(n) {
  const positions = [], cells = [];
  for (let i = 0; i <= n; i++) {
    for (let j = 0; j < n; j++) {
      const theta = (Math.PI * (i + 0.5)) / (n + 1), phi = (2 * Math.PI * j) / n;
      positions.push([Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)]);
    }
  }
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) {
      const a = i * n + j, b = i * n + ((j + 1) % n), c = a + n, d = b + n;
      cells.push([a, b, c], [b, d, c]);
    }
  }
  return { positions, cells };
}

/** Wall-clock ms of each case's `run`, `rounds` times in turns (after warm-up runs). */
function timeInTurns(cases, rounds) {
  for (const c of cases) for (let i = 0; i < WARMUP; i++) c.run();
  const times = cases.map(() => []);
  for (let r = 0; r < rounds; r++) {
    cases.forEach((c, k) => {
      const start = performance.now();
      c.run();
      times[k].push(performance.now() - start);
    });
  }
  return times;
}

/** The same rays, from a camera 4 units away, at each mesh: hits counted so nothing is optimised away. */
function scalingCase(mesh, label, camera) {
  const ray = new Ray([0, 0, 4]);
  const c = { label, mesh, rays: camera.width * camera.height, hits: 0 };
  c.run = () => {
    let hits = 0;
    for (let y = 0; y < camera.height; y++) {
      for (let x = 0; x < camera.width; x++) {
        camera.directionAt(x, y, ray.direction);
        if (mesh.hit(ray) !== Infinity) hits++;
      }
    }
    c.hits = hits;
  };
  return c;
}

/**
 * One frame of the bunny: for every pixel the primary ray, its nearest hit,
 * and Lambert shading (n·l, the normal turned to face the eye) in grey.
 */
export function bunnyFrame(mesh, camera, target) {
  const ray = new Ray(camera.position), point = new Vec3(), normal = new Vec3();
  const light = new Vec3(0.45, 0.75, 0.48); // toward the light, unit length
  const o = ray.origin, d = ray.direction;
  for (let y = 0; y < camera.height; y++) {
    for (let x = 0; x < camera.width; x++) {
      camera.directionAt(x, y, d);
      const t = mesh.hit(ray);
      let shade = 30; // the background
      if (t !== Infinity) {
        point.x = o.x + d.x * t; point.y = o.y + d.y * t; point.z = o.z + d.z * t;
        mesh.normalAt(point, normal);
        const facing = normal.x * d.x + normal.y * d.y + normal.z * d.z > 0 ? -1 : 1;
        const cos = facing * (normal.x * light.x + normal.y * light.y + normal.z * light.z);
        shade = 40 + 215 * Math.max(0, cos);
      }
      const i = 4 * (y * camera.width + x);
      target[i] = target[i + 1] = target[i + 2] = shade;
      target[i + 3] = 255;
    }
  }
  return target;
}

export function runBvhBench() {
  const startLoad = loadavg()[0];
  console.log(`\nMeshes and their BVH (Node ${process.version}, one thread, ${ROUNDS} rounds after ${WARMUP} warm-up, load average ${startLoad.toFixed(1)} on ${availableParallelism()} cores):`);

  const built = [22, 224].map((n) => {
    const data = sphereMesh(n), start = performance.now();
    const mesh = new Mesh(data);
    return { mesh, buildMs: performance.now() - start };
  });
  const camera = new Camera({ width: 160, height: 120, fov: 30 });
  const cases = built.map(({ mesh }) => scalingCase(mesh, `sphere of ${mesh.triangleCount} triangles`, camera));
  const [small, large] = timeInTurns(cases, ROUNDS).map(median);
  cases.forEach((c, k) => {
    const ms = k ? large : small;
    console.log(`  ${c.label.padEnd(30)} ${(ms * 1e6 / c.rays).toFixed(0).padStart(6)} ns/ray (median), ${c.hits} of ${c.rays} rays hit,` +
      ` BVH ${c.mesh.bvh.nodeCount} nodes deep ${c.mesh.bvh.depth}, built in ${built[k].buildMs.toFixed(0)} ms`);
  });
  const [a, b] = built.map(({ mesh }) => mesh.triangleCount);
  console.log(`  per-ray cost, ${b} over ${a} triangles: ${(large / small).toFixed(2)}× for ${(b / a).toFixed(0)}× the triangles (goal ≤ 4×)`);

  const mesh = new Mesh(bunny);
  const view = new Camera({ width: 320, height: 240, fov: 30, position: [0, 4.8, 28] });
  const target = new Uint8ClampedArray(320 * 240 * 4);
  const frame = { run: () => bunnyFrame(mesh, view, target) };
  const [times] = timeInTurns([frame], ROUNDS);
  let covered = 0;
  for (let i = 0; i < target.length; i += 4) if (target[i] !== 30) covered++;
  console.log(`  bunny, ${mesh.triangleCount} triangles, 320×240, primary rays + Lambert: ${median(times).toFixed(1)} ms/frame median` +
    ` (min ${Math.min(...times).toFixed(1)}, max ${Math.max(...times).toFixed(1)}; goal ≤ 250 ms), the bunny on ${covered} pixels`);
  bunnyRender(view);
  const bytes = [1, 2, 3, 4, 5].map(() => Number(execFileSync(process.execPath, [fileURLToPath(new URL('./bvh-allocation.js', import.meta.url))]).toString()));
  console.log(`  heap bytes per ray, Mesh#hit on the bunny, 5 fresh processes: ${bytes.map((b) => b.toFixed(1)).join(', ')} (goal: 0; median ${median(bytes).toFixed(1)})`);
  console.log(`  load average ${startLoad.toFixed(1)} at the start, ${loadavg()[0].toFixed(1)} at the end`);
}

/** The bunny's frame through render(): the kernel, and trace.js for the same scene, timed in turns; the same bytes checked. */
function bunnyRender(view) {
  const scene = (fast) => {
    const mesh = new Mesh(bunny, { color: [0.9, 0.8, 0.7] });
    if (!fast) mesh.hit = Mesh.prototype.hit.bind(mesh); // the same test, but the kernel's no longer to know: trace.js
    return new Scene({ background: [0.12, 0.12, 0.12], ambient: 0.1 }).add(mesh).add(new PointLight([10, 20, 30]));
  };
  const kernel = scene(true), plain = scene(false);
  if (!packScene(kernel) || packScene(plain)) throw new Error('bench/bvh.js: the kernel should pack the one scene and not the other');
  const fast = new Uint8ClampedArray(320 * 240 * 4), slow = new Uint8ClampedArray(320 * 240 * 4);
  const cases = [{ run: () => render(kernel, view, fast) }, { run: () => render(plain, view, slow) }];
  const [kernelMs, traceMs] = timeInTurns(cases, ROUNDS).map(median);
  const same = fast.every((v, i) => v === slow[i]);
  console.log(`  bunny through render(), 320×240, one light with shadows: kernel ${kernelMs.toFixed(1)} ms/frame median,` +
    ` trace.js ${traceMs.toFixed(1)} ms (${(traceMs / kernelMs).toFixed(2)}×), ${same ? 'the same bytes' : 'DIFFERENT BYTES'}`);
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) runBvhBench();
