/**
 * The students' progress kept in this browser (localStorage, under
 * lib/lesson/progress.js's versioned key), for the task lists and the gallery. Storage
 * that is off, full, empty, corrupt or foreign never raises an error: it
 * reads as nothing done, and the page works on without keeping anything.
 */
import { LESSONS } from '../../lesson/tasks.js';
import { PROGRESS_KEY, parseProgress, serializeProgress } from '../../lesson/progress.js';

/** The progress kept in this browser, `{ '01': ['select', …], … }`. */
export function loadProgress(storage = globalThis.localStorage) {
  try {
    return parseProgress(storage?.getItem(PROGRESS_KEY) ?? null, LESSONS);
  } catch {
    return {};
  }
}

/** Keeps `progress` in this browser; false when the browser will not (storage off or full). */
export function saveProgress(progress, storage = globalThis.localStorage) {
  try {
    storage.setItem(PROGRESS_KEY, serializeProgress(progress));
    return true;
  } catch {
    return false;
  }
}
