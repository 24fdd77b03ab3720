/**
 * everySaveArrives: the dev server's pages get a file as it was last saved,
 * once, not half-way.
 *
 * An editor's save may reach the disk in two steps: the file emptied, then
 * written (or written, then written again by a formatter). Two things went
 * wrong between the steps:
 * - a page that asked for the module then got the empty half, and swapped in
 *   a sketch with nothing in it; so an emptied module is read again once its
 *   save has ended (at most SAVE_ENDS_MS later) before it is served;
 * - Vite's file watcher (chokidar) passes on at most one change of a file per
 *   50 ms and drops the rest, so the second step never reached the page; so
 *   each change is looked at again just after that window, and when what the
 *   pages were served since differs from the file now, the change is
 *   announced once more.
 * And the other way round: a second change the watcher does pass on, of a
 * save every page already has whole (each asked after its last step), sends
 * no second update: no second swap, no picture traced twice; and a reload
 * made while no page is open reaches only a page that was loading as it was
 * made, not one opened later (keepReloadsForLoadingPagesOnly).
 */
import { readFileSync, statSync } from 'node:fs';

/** Chokidar's window (its `_throttle('change', path, 50)`), and a little after. */
const LOOK_AGAIN_MS = 60;
/** How long an emptied file is waited for before it is served empty (a sketch really deleted to nothing). */
const SAVE_ENDS_MS = 200;
/** How long a change waits for a page to ask for the file before it lets it be. */
const ASKED_WITHIN_MS = 3000;

const wait = (ms) => new Promise((done) => setTimeout(done, ms));

/** The file's text, or null when it cannot be read (gone). */
function textOf(file) {
  try {
    return readFileSync(file, 'utf8');
  } catch {
    return null;
  }
}

/** The size of the file, or -1 when it is gone. */
function sizeOf(file) {
  try {
    return statSync(file).size;
  } catch {
    return -1;
  }
}

export function everySaveArrives() {
  /** For each file saved while the server runs: the texts pages were served since its last update went out. */
  const served = new Map();
  let server = null;

  /** After chokidar's window: a page served a text the file no longer holds gets the change it dropped. */
  const lookAgain = (file, waited = 0) => setTimeout(() => {
    const texts = served.get(file);
    if (!texts) return;
    if (texts.size === 0) { // no page has asked yet: one that asks later reads the file as it is then
      if (waited < ASKED_WITHIN_MS) lookAgain(file, waited + LOOK_AGAIN_MS);
      return;
    }
    const now = textOf(file);
    if (now !== null && [...texts].some((text) => text !== now)) server?.watcher.emit('change', file);
  }, LOOK_AGAIN_MS).unref();

  return {
    name: 'sketchbook:every-save-arrives',
    apply: 'serve',
    enforce: 'pre',
    configureServer(devServer) {
      server = devServer;
      keepReloadsForLoadingPagesOnly(devServer);
    },
    async load(id) {
      const file = id.split('?')[0];
      if (!served.has(file) || sizeOf(file) !== 0) return null; // only a file saved while the server runs can be half-saved
      for (let waited = 0; waited < SAVE_ENDS_MS && sizeOf(file) === 0; waited += 20) await wait(20);
      return textOf(file) ?? null;
    },
    transform(code, id) {
      served.get(id.split('?')[0])?.add(code); // the text as read, before any other plugin changes it
      return null;
    },
    async hotUpdate({ type, file }) {
      if (this.environment.name !== 'client' || type === 'delete' || !/\.[cm]?js$/.test(file)) return undefined;
      // Read as it is now, never thrown: a file deleted since the event is Vite's to handle (its read() would throw,
      // and Vite would show the error on every page, kept for the next page to open when none is).
      const now = textOf(file);
      if (now === null) return undefined;
      const texts = served.get(file);
      // Every page that asked since the last update got this very text (it asked after the save's last step): nothing to send.
      if (texts && texts.size > 0 && [...texts].every((text) => text === now)) return [];
      served.set(file, new Set());
      lookAgain(file);
      return undefined;
    },
  };
}

/**
 * A reload (or an error) sent while no page is connected: Vite keeps it and hands it to the
 * next page that connects, whenever that is. For a page that was loading as the file changed,
 * that is right: it may hold the old version. But a page asked for after the change already
 * loads the new files, and the kept reload only loaded it twice; a test's page, opened just
 * after the last test's files were removed, was reloaded in the middle of its first save. So
 * the message is kept here instead, and let go when the page it is for is asked for again.
 */
function keepReloadsForLoadingPagesOnly(server) {
  const send = server.ws.send;
  let kept = null;
  server.ws.send = (...args) => {
    const [payload] = args;
    if (payload?.type !== 'full-reload' && payload?.type !== 'error') return send(...args);
    if (server.ws.clients.size > 0) return send(...args);
    kept = payload;
    return undefined;
  };
  server.ws.on('vite:client:connect', (_data, client) => {
    if (kept) client.send(kept);
    kept = null;
  });
  server.middlewares.use((req, _res, next) => {
    const page = (req.url ?? '').split('?')[0];
    const isPage = req.headers.accept?.includes('text/html') && !page.startsWith('/@');
    if (kept && isPage && (kept.type === 'error' || !kept.path?.endsWith('.html') || kept.path === page)) kept = null; // it loads as the files are now
    next();
  });
}
