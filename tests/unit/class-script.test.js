import { describe, it, expect } from 'vitest';
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';
import { networkInterfaces, tmpdir } from 'node:os';
import { mkdtempSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { classroomAddresses, portFrom } from '../../scripts/class.js';

describe('npm run class', () => {
  it('offers every outside IPv4 address, private networks first, never the loopback or a link-local one', () => {
    const interfaces = {
      lo: [{ address: '127.0.0.1', family: 'IPv4', internal: true }, { address: '::1', family: 'IPv6', internal: true }],
      docker0: [{ address: '203.0.113.5', family: 'IPv4', internal: false }],
      wlan0: [{ address: '192.168.1.23', family: 'IPv4', internal: false }, { address: 'fe80::1', family: 'IPv6', internal: false }],
      eth1: [{ address: '169.254.3.4', family: 'IPv4', internal: false }],
    };
    expect(classroomAddresses(interfaces, 5173)).toEqual(['http://192.168.1.23:5173/', 'http://203.0.113.5:5173/']);
    expect(classroomAddresses({ lo: interfaces.lo }, 5173)).toEqual([]);
  });

  it('takes --port N, else 5173, and names a bad port', () => {
    expect(portFrom(['node', 'class.js'])).toBe(5173);
    expect(portFrom(['node', 'class.js', '--port', '8080'])).toBe(8080);
    expect(() => portFrom(['node', 'class.js', '--port', 'eighty'])).toThrow(/--port must be a whole number/);
  });

  it('serves the gallery on the network and prints the address students type', async () => {
    const port = await freePort();
    const data = mkdtempSync(join(tmpdir(), 'class-script-')); // the class board's folder: not the teacher's
    const child = spawn(process.execPath, ['scripts/class.js', '--port', String(port), '--data', data], { stdio: ['ignore', 'pipe', 'pipe'] });
    try {
      let output = '';
      const address = await new Promise((resolveAddress, reject) => {
        const timer = setTimeout(() => reject(new Error(`no address printed in 30 s:\n${output}`)), 30_000);
        child.stdout.on('data', (d) => {
          output += d;
          const m = /Students type this address[^\n]*\n\s*\n\s*(http:\/\/\S+)/.exec(output);
          if (m || /No network found/.test(output)) { clearTimeout(timer); resolveAddress(m?.[1] ?? null); }
        });
        child.on('exit', () => reject(new Error(`the script ended:\n${output}`)));
      });
      if (address === null) { // a machine on no network says so, and has no address to offer
        expect(classroomAddresses(networkInterfaces(), port)).toEqual([]);
        return;
      }
      expect(address).toMatch(new RegExp(`^http://\\d+\\.\\d+\\.\\d+\\.\\d+:${port}/$`));
      const page = await (await fetch(address)).text();
      expect(page).toContain('Raytracing Sketchbook');
    } finally {
      child.kill('SIGTERM');
    }
  }, 60_000);
});

describe('npm run class where better-sqlite3 could not be built (npm ci leaves it out without a word)', () => {
  it('serves every page, says in the terminal that the board is off and how to build it, and the board\'s routes say so too', async () => {
    const port = await freePort();
    const data = mkdtempSync(join(tmpdir(), 'class-script-'));
    const without = pathToFileURL(resolve('tests/shared/without-better-sqlite3.js')).href;
    const env = { ...process.env, NODE_OPTIONS: `${process.env.NODE_OPTIONS ?? ''} --import=${without}`.trim() }; // Vite's process too
    const child = spawn(process.execPath, ['scripts/class.js', '--port', String(port), '--data', data], { stdio: ['ignore', 'pipe', 'pipe'], env });
    let output = '';
    try {
      await new Promise((ready, reject) => {
        const timer = setTimeout(() => reject(new Error(`the board's line not printed in 40 s:\n${output}`)), 40_000);
        const read = (d) => {
          output += d;
          if (/^ {2}the class board is off: .*\n/m.test(output)) { clearTimeout(timer); ready(); } // the script's line, after Vite's ready
        };
        child.stdout.on('data', read);
        child.stderr.on('data', read);
        child.on('exit', () => reject(new Error(`the script ended:\n${output}`)));
      });
      expect(output).toContain('better-sqlite3 could not be loaded');
      expect(output).toMatch(/install a C\+\+ compiler, make and Python .*then npm install/);
      expect(output).not.toMatch(/\/board\?key=/); // no address of a board that is not there
      const base = `http://127.0.0.1:${port}/`;
      const sketch = await fetch(`${base}sketches/04-find-the-pink-pixel.html`);
      expect(sketch.status).toBe(200);
      expect(await sketch.text()).not.toContain('rt-class-board'); // the pages send nothing
      expect((await fetch(`${base}poll.html`)).status).toBe(200);
      for (const [method, path] of [['GET', 'board'], ['GET', 'board/state?key=x'], ['POST', 'class/send'], ['POST', 'class/hello']]) {
        const answer = await fetch(base + path, { method, headers: { 'Content-Type': 'application/json' }, body: method === 'POST' ? '{}' : undefined });
        expect([path, answer.status]).toEqual([path, 503]);
        expect(await answer.text()).toMatch(/^The class board is off: better-sqlite3 could not be loaded .*\nThe pages are served as usual; nothing the students do is sent\.\n$/s);
      }
    } finally {
      child.kill('SIGTERM');
    }
  }, 60_000);
});

/** A port nothing listens on now. */
function freePort() {
  return new Promise((resolvePort) => {
    const server = createServer().listen(0, () => {
      const { port } = server.address();
      server.close(() => resolvePort(port));
    });
  });
}
