/** Stand-ins for Web Workers in Node: the real worker code, run on structured clones of the messages. */
import { workerHandler } from '../../lib/tracing/workers/split.js';

/**
 * A stand-in for a Web Worker: runs the real worker code (workerHandler)
 * later, on structured clones of the messages, as a worker would (a
 * SharedArrayBuffer clones to the same memory, as between threads). It says
 * `{ ready: true }` once "loaded", as render-worker.js does: after `loadMs`
 * (a slow network, a busy machine), and takes no job before.
 * `handlerOptions` go to workerHandler (a clock, say).
 */
export function fakeWorkers(handlerOptions, { loadMs = 0 } = {}) {
  const started = [], received = [], answers = [];
  const create = () => {
    const handle = workerHandler(handlerOptions);
    const loaded = new Promise((resolve) => setTimeout(resolve, loadMs));
    const worker = {
      onmessage: null, onerror: null, terminated: false, jobs: 0,
      postMessage(data) {
        worker.jobs++;
        received.push(data);
        const job = structuredClone(data);
        loaded.then(() => setTimeout(() => handle(job, (message, transfer) => {
          const copy = structuredClone(message, { transfer });
          answers.push(copy);
          setTimeout(() => { if (!worker.terminated) worker.onmessage({ data: copy }); });
        })));
      },
      terminate() { worker.terminated = true; },
    };
    loaded.then(() => { if (!worker.terminated) worker.onmessage?.({ data: { ready: true } }); });
    started.push(worker);
    return worker;
  };
  return { create, started, received, answers };
}

/** A worker that loads (says it is ready), takes its jobs and never answers. */
export function silentWorker() {
  const w = neverLoadedWorker();
  setTimeout(() => { if (!w.terminated) w.onmessage?.({ data: { ready: true } }); });
  return w;
}

/** A worker whose code never loads: it says nothing at all (a script that never arrives). */
export function neverLoadedWorker() {
  const w = { onmessage: null, onerror: null, terminated: false, jobs: 0, postMessage() { w.jobs++; }, terminate() { w.terminated = true; } };
  return w;
}
