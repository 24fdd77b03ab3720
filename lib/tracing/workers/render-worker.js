/**
 * A Web Worker that renders the rows it is given (see split.js's workerHandler).
 * Started by ParallelRenderer as a module worker.
 */
import { workerHandler } from './split.js';

const handle = workerHandler();
self.onmessage = (event) => handle(event.data, (message, transfer) => self.postMessage(message, { transfer }));
self.postMessage({ ready: true }); // loaded: ParallelRenderer now counts this worker's silences by timeoutMs, not startTimeoutMs
