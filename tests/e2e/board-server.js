/**
 * `npm run class -- --port N --data DIR` for the class board's tests: started
 * in a process group of its own (scripts/class.js and the Vite it starts), so
 * that a test can crash both at once (kill -9) as a power cut or a killed
 * terminal would, or stop them.
 */
import { spawn } from 'node:child_process';
import { freePort } from './class-server.js';

/**
 * Starts the class server; resolves once it printed the board's address.
 * @param {{ data: string, port?: number }} options
 * @returns {Promise<{ url: string, board: string, key: string, port: number, output: () => string, crash: () => Promise<void>, close: () => Promise<void> }>}
 */
export async function startBoardServer({ data, port }) {
  port ??= await freePort();
  const child = spawn(process.execPath, ['scripts/class.js', '--port', String(port), '--data', data], { stdio: ['ignore', 'pipe', 'pipe'], detached: true });
  let output = '';
  const board = await new Promise((ready, fail) => {
    const timer = setTimeout(() => fail(new Error(`no board address in 90 s:\n${output}`)), 90_000);
    const read = (d) => {
      output += d;
      const m = /(http:\/\/\S+\/board\?key=[\w-]+)/.exec(output);
      if (m) { clearTimeout(timer); ready(m[1]); }
      const off = /^ {2}(the class board is off: .*)$/m.exec(output);
      if (off) { clearTimeout(timer); fail(new Error(off[1])); } // better-sqlite3 not built here: say why, at once
    };
    child.stdout.on('data', read);
    child.stderr.on('data', read);
    child.on('exit', (code) => { clearTimeout(timer); fail(new Error(`the class server ended (${code}):\n${output}`)); });
  });
  child.removeAllListeners('exit');
  const ended = new Promise((done) => child.once('exit', done));
  const stop = (signal) => {
    try { process.kill(-child.pid, signal); } catch { /* already gone */ }
    return ended.then(() => waitForPortFree(port));
  };
  const local = `http://127.0.0.1:${port}/`;
  return {
    url: local,
    board: board.replace(/^http:\/\/[^/]+\//, local),
    key: new URL(board).searchParams.get('key'),
    port,
    output: () => output,
    crash: () => stop('SIGKILL'),
    close: () => stop('SIGTERM'),
  };
}

/** Resolves once nothing answers on `port` (the Vite child too has ended). */
async function waitForPortFree(port) {
  for (let i = 0; i < 100; i++) {
    try {
      await fetch(`http://127.0.0.1:${port}/`, { signal: AbortSignal.timeout(500) });
    } catch {
      return;
    }
    await new Promise((r) => setTimeout(r, 100));
  }
}
