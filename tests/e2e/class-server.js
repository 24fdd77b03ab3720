/**
 * `npm run class` for tests and measurements: started on a port of its own
 * (`port`, else CLASS_PORT, else one the system gives), stopped by its PID.
 */
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

/** A port nobody listens on. */
export function freePort() {
  return new Promise((done, fail) => {
    const probe = createServer();
    probe.on('error', fail);
    probe.listen(0, '127.0.0.1', () => { const { port } = probe.address(); probe.close(() => done(port)); });
  });
}

/**
 * Starts the class server; resolves with { url, close } once Vite is ready.
 * @param {number} [port]
 * @param {string[]} [args] more of `npm run class`'s arguments (`--allow-host NAME`)
 */
export async function startClassServer(port = Number(process.env.CLASS_PORT) || undefined, args = []) {
  port ??= await freePort();
  const data = mkdtempSync(join(tmpdir(), 'class-server-')); // the class board's folder: not the teacher's
  const child = spawn(process.execPath, ['scripts/class.js', '--port', String(port), '--data', data, ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
  let output = '';
  await new Promise((ready, fail) => {
    const timer = setTimeout(() => fail(new Error(`the class server was not ready in 60 s:\n${output}`)), 60_000);
    const read = (d) => {
      output += d;
      if (/ready in/i.test(output)) { clearTimeout(timer); ready(); }
    };
    child.stdout.on('data', read);
    child.stderr.on('data', read);
    child.on('exit', (code) => { clearTimeout(timer); fail(new Error(`the class server ended (${code}):\n${output}`)); });
  });
  return {
    url: `http://127.0.0.1:${port}/`,
    port,
    output: () => output,
    close: () => new Promise((done) => {
      if (child.exitCode !== null) return done();
      child.once('exit', () => done());
      child.kill('SIGTERM');
    }),
  };
}
