/**
 * `npm run class`: the gallery served to the classroom's network, so that
 * students reach the teacher's dev server from their own laptops. Starts
 * Vite with --host (every network interface) and prints the address to
 * type, big, with a QR code for phones and tablets.
 *
 *   npm run class                          port 5173
 *   npm run class -- --port 8080           another port
 *   npm run class -- --allow-host NAME     a name of this computer students may type
 *                                          (its own host name and NAME.local are always let in)
 *   npm run class -- --data DIR            the class board's folder (scripts/board/setup.js)
 *
 * Students' laptops must be on the same network (Wi-Fi) as the teacher's, and
 * the teacher's firewall must let the port in. Ctrl+C stops the server.
 */
import { spawn } from 'node:child_process';
import { networkInterfaces, hostname } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { allowedHostsFrom, computerNames } from './class-gate.js';
import { folderFrom, boardKey, boardLines, loadDatabase, FOLDER_VARIABLE } from './board/setup.js';

const ROOT = resolve(import.meta.dirname, '..');

/**
 * The addresses students can type: `http://IP:port/` for every IPv4 address
 * of a network interface that is not the machine's own loopback, private
 * networks (192.168…, 10…, 172.16–31…) first.
 * @param {ReturnType<typeof networkInterfaces>} interfaces
 * @param {number} port
 * @returns {string[]}
 */
export function classroomAddresses(interfaces, port) {
  const found = [];
  for (const list of Object.values(interfaces)) {
    for (const entry of list ?? []) {
      const v4 = entry.family === 'IPv4' || entry.family === 4;
      if (v4 && !entry.internal && !entry.address.startsWith('169.254.')) found.push(entry.address);
    }
  }
  const isPrivate = (ip) => /^(192\.168\.|10\.|172\.(1[6-9]|2\d|3[01])\.)/.test(ip);
  return [...new Set(found)]
    .sort((a, b) => Number(isPrivate(b)) - Number(isPrivate(a)))
    .map((ip) => `http://${ip}:${port}/`);
}

/** The port asked for with --port N (a whole number 1–65535), else 5173. */
export function portFrom(argv) {
  const i = argv.indexOf('--port');
  if (i < 0) return 5173;
  const n = Number(argv[i + 1]);
  if (!Number.isInteger(n) || n < 1 || n > 65535) throw new RangeError(`--port must be a whole number from 1 to 65535, got ${JSON.stringify(argv[i + 1])}`);
  return n;
}

async function main() {
  let port, names, folder;
  try {
    port = portFrom(process.argv);
    names = computerNames(hostname(), allowedHostsFrom(process.argv));
    folder = folderFrom(process.argv); // the class board's (scripts/board/)
  } catch (error) {
    console.error(error.message);
    process.exit(2);
  }
  const env = { ...process.env, SKETCHBOOK_CLASS_HOSTS: JSON.stringify(names), [FOLDER_VARIABLE]: folder };
  const vite = spawn(join(ROOT, 'node_modules/.bin/vite'), ['--host', '--mode', 'class', '--port', String(port), '--strictPort'], { cwd: ROOT, env, stdio: ['inherit', 'pipe', 'inherit'] });
  let said = false;
  vite.stdout.on('data', async (chunk) => {
    process.stdout.write(chunk);
    if (said || !/ready in/i.test(String(chunk))) return;
    said = true;
    setTimeout(() => sayWhereToGo(port, names).then(() => sayWhereTheBoardIs(folder, port)), 200); // after Vite's own list of addresses
  });
  for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, () => vite.kill(signal));
  vite.on('exit', (code) => process.exit(code ?? 0));
}

async function sayWhereToGo(port, names) {
  const addresses = classroomAddresses(networkInterfaces(), port);
  if (addresses.length === 0) {
    console.log('\nNo network found: connect this computer to the classroom\'s Wi-Fi, then run npm run class again.\n');
    return;
  }
  console.log('\n  Students type this address in their browser (same Wi-Fi as this computer):\n');
  console.log(`      ${addresses[0]}\n`);
  if (addresses.length > 1) console.log(`  (or, on another network of this computer: ${addresses.slice(1).join('  ')})\n`);
  console.log(`  By name it answers to: ${names.map((name) => `http://${name}:${port}/`).join('  ')}`);
  console.log('  (another name: npm run class -- --allow-host NAME)\n');
  try {
    const { renderUnicodeCompact } = await import('uqr');
    console.log(renderUnicodeCompact(addresses[0]).split('\n').map((row) => `      ${row}`).join('\n'));
    console.log('\n  (a phone\'s camera opens it from the code above)\n');
  } catch {
    // No QR code without the uqr package (npm install): the address is enough.
  }
  console.log('  If a laptop cannot reach it: the firewall of this computer must let port ' +
    `${port} in (the computer may ask the first time). Ctrl+C stops the server.\n`);
}

async function sayWhereTheBoardIs(folder, port) {
  const { problem } = await loadDatabase();
  console.log(problem ? `  ${problem}\n` : `${boardLines(folder, boardKey(folder), port)}\n`);
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) main();
