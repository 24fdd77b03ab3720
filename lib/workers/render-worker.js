/**
 * A Web Worker that renders the rows it is given (see split.js's runJob).
 * Started by ParallelRenderer as a module worker.
 */
import { runJob } from './split.js';

self.onmessage = (event) => runJob(event.data, (message, transfer) => self.postMessage(message, transfer));
