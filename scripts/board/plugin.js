/**
 * The class board on the class server (vite.config.js, mode "class" only):
 * opens the database in the board's folder, adds the board's routes
 * (./routes.js) right after the class gate (which lets in BOARD_ROUTES
 * only: vite.config.js), and marks every page it serves with
 * `<meta name="rt-class-board">`, the sign for a student's page
 * (lib/p5/page/class-board.js) that it may send: without it (the static site,
 * `npm start`) a page sends nothing.
 *
 * Where better-sqlite3 could not be built (no compiler, no prebuilt binary),
 * the board is off: the pages are served without the sign, and the board's
 * routes answer 503 with the reason and what to run.
 */
import { join } from 'node:path';
import { openStore } from './store.js';
import { boardRoutes, boardIsOff, STUDENT_ROUTE } from './routes.js';
import { folderFrom, boardKey, loadDatabase } from './setup.js';

/** @param {{ argv?: string[] }} [options] */
export function classBoard({ argv = process.argv } = {}) {
  const folder = folderFrom(argv);
  let store = null;
  let routes = null;
  return {
    name: 'class-board',
    apply: 'serve',
    enforce: 'pre',
    config() {
      // The database changes at each submit: no reason for the file watcher to look.
      return { server: { watch: { ignored: [`${join(folder, '**')}`] } } };
    },
    async configureServer(server) {
      const { Database, problem } = await loadDatabase();
      if (!Database) {
        server.config.logger.warn(problem);
        return void server.middlewares.use(boardIsOff(problem));
      }
      store = openStore(folder, { Database });
      routes = boardRoutes({ store, key: boardKey(folder) });
      server.middlewares.use(routes);
      server.httpServer?.on('close', () => { routes.close(); store.close(); });
    },
    transformIndexHtml() {
      if (!store) return undefined;
      return [{ tag: 'meta', attrs: { name: 'rt-class-board', content: STUDENT_ROUTE }, injectTo: 'head-prepend' }];
    },
  };
}
