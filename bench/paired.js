/**
 * render() of an older commit against the work tree's, in one process:
 * `npm run bench:paired` (and the last part of `npm run bench`).
 *
 * The older commit's lib/ (9e9a563 unless BENCH_OLD names another) is taken
 * out of git with `git archive` into a temporary folder and imported beside
 * the work tree's own lib/. Both render the class scene at 640×480, (a)
 * Lambert and shadows and (b) full shading, frame after frame in turns (old,
 * new, old, new, …) so that both see the machine's same moments; each round's
 * ratio is taken within the round. Each frame is timed by the CPU time the
 * process spent on it (process.cpuUsage, the garbage collector's threads
 * too), not by the clock: on a shared machine the clock also counts the time
 * the process waited for a core, and a load of 20 on 2 cores moved clock
 * ratios by 40 %. It prints the medians and the ratio new / old (below 1: the
 * work tree is faster), and whether the two pictures are the same bytes.
 * Figures are printed, never asserted.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, symlinkSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const ROOT = join(import.meta.dirname, '..');
const ROUNDS = 21, PER_ROUND = 3, WARMUP = 5;

/** Milliseconds of CPU time this process has used. */
const cpuTime = () => {
  const { user, system } = process.cpuUsage();
  return (user + system) / 1000;
};

const median = (values) => {
  const sorted = [...values].sort((a, b) => a - b), mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
};

/** lib/ and package.json of `commit` in a new temporary folder (with the work tree's node_modules beside them); null when git cannot give them. */
function extract(commit, dir) {
  const archive = spawnSync('git', ['-C', ROOT, 'archive', '--format=tar', commit, 'lib', 'package.json'], { maxBuffer: 1 << 28 });
  if (archive.status !== 0) return null;
  const tar = spawnSync('tar', ['-x', '-C', dir], { input: archive.stdout });
  if (tar.status !== 0) return null;
  if (existsSync(join(ROOT, 'node_modules'))) symlinkSync(join(ROOT, 'node_modules'), join(dir, 'node_modules'));
  return join(dir, 'lib', 'index.js');
}

/** A frame of the class scene, 640×480, by one library's own render(). */
function frameOf(lib, full) {
  const camera = new lib.Camera({ width: 640, height: 480, fov: 30, position: [0, 0, 0] });
  const scene = lib.classScene({ full }), target = new Uint8ClampedArray(640 * 480 * 4);
  return { run: () => lib.render(scene, camera, target, undefined, { blocking: true }), target }; // an older render() ignores the fifth argument
}

/** Old and new in turns: per round PER_ROUND frames of each; the medians and the median of the rounds' ratios. */
function pair(old, now) {
  for (let i = 0; i < WARMUP; i++) { old.run(); now.run(); }
  const times = { old: [], now: [] }, ratios = [];
  for (let round = 0; round < ROUNDS; round++) {
    const rounds = { old: [], now: [] };
    for (let i = 0; i < PER_ROUND; i++) {
      for (const [key, c] of round % 2 ? [['now', now], ['old', old]] : [['old', old], ['now', now]]) { // who goes first changes each round
        const start = cpuTime();
        c.run();
        rounds[key].push(cpuTime() - start);
      }
    }
    times.old.push(...rounds.old);
    times.now.push(...rounds.now);
    ratios.push(median(rounds.now) / median(rounds.old));
  }
  return { old: median(times.old), now: median(times.now), ratio: median(ratios) };
}

/** Runs the paired benchmark and prints its lines. */
export async function runPairedBench(commit = process.env.BENCH_OLD ?? '9e9a563') {
  const dir = mkdtempSync(join(tmpdir(), 'rt-bench-old-'));
  try {
    const entry = extract(commit, dir);
    if (!entry) {
      console.log(`\nPaired render() against ${commit}: skipped (git could not give that commit's lib/ here)`);
      return;
    }
    const old = await import(pathToFileURL(entry).href);
    const now = await import(pathToFileURL(join(ROOT, 'lib', 'index.js')).href);
    console.log(`\nrender() of ${commit} (old) against the work tree's (new), the class scene 640×480, ${ROUNDS} rounds of ${PER_ROUND} frames each, in turns, CPU time:`);
    for (const [label, full] of [['(a) Lambert + shadows', false], ['(b) full shading', true]]) {
      const a = frameOf(old, full), b = frameOf(now, full);
      const { old: o, now: n, ratio } = pair(a, b);
      const same = a.target.every((byte, i) => byte === b.target[i]);
      const change = (ratio - 1) * 100;
      console.log(`  ${label.padEnd(24)} old ${o.toFixed(1)} ms, new ${n.toFixed(1)} ms: new/old ${ratio.toFixed(3)} (${change >= 0 ? '+' : ''}${change.toFixed(1)} %, median of the rounds' ratios); pictures ${same ? 'the same bytes' : 'DIFFER'}`);
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) await runPairedBench(process.argv[2]);
