/**
 * Where the class board keeps its database and its key, and the lines the
 * terminal shows about it (`npm run class`, scripts/class.js). The folder is
 * `--data DIR`, else one in the teacher's home folder; the key is made once
 * and kept in that folder, so the board's address stays the same from one
 * lesson (or restart) to the next.
 */
import { randomBytes } from 'node:crypto';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { homedir } from 'node:os';
import { join, resolve } from 'node:path';
import { DATABASE_FILE } from './store.js';

/** The folder of the board when `--data` is not given. */
export const DEFAULT_FOLDER = join(homedir(), 'raytracing-sketchbook-board');
/** The file of the board's key, in its folder. */
export const KEY_FILE = 'board-key';
/** How scripts/class.js tells the class server (Vite, a child process) the folder. */
export const FOLDER_VARIABLE = 'SKETCHBOOK_BOARD_DATA';

/** The folder asked for with `--data DIR`, else the board's own folder in the home folder. */
export function folderFrom(argv, env = process.env) {
  const i = argv.indexOf('--data');
  if (i >= 0) {
    const dir = argv[i + 1];
    if (!dir || dir.startsWith('--')) throw new RangeError('--data needs a folder: npm run class -- --data FOLDER');
    return resolve(dir);
  }
  return env[FOLDER_VARIABLE] ? resolve(env[FOLDER_VARIABLE]) : DEFAULT_FOLDER;
}

/** The board's key, made on the first run (24 random bytes) and kept, readable by the teacher only. */
export function boardKey(folder) {
  mkdirSync(folder, { recursive: true });
  const file = join(folder, KEY_FILE);
  try {
    const kept = readFileSync(file, 'utf8').trim();
    if (/^[A-Za-z0-9_-]{20,}$/.test(kept)) return kept;
  } catch { /* none yet */ }
  const key = randomBytes(24).toString('base64url');
  writeFileSync(file, `${key}\n`, { mode: 0o600 });
  return key;
}

/**
 * better-sqlite3's Database class, or why it cannot be used. It is an
 * optional dependency, a native module built (or downloaded) for this Node at
 * `npm install`; where that fails, npm leaves it out without a word, and the
 * class board is off. It loads its binary at the first database opened: one
 * is opened here, in memory, so that a missing or foreign binary says so now.
 * @returns {Promise<{ Database?: any, problem?: string }>}
 */
export async function loadDatabase() {
  try {
    const Database = (await import('better-sqlite3')).default;
    new Database(':memory:').close();
    return { Database };
  } catch (error) {
    return { problem: `the class board is off: better-sqlite3 could not be loaded (${String(error?.message ?? error).split('\n')[0]}). ${HOW_TO_BUILD}` };
  }
}

/** What a teacher does where better-sqlite3 could not be built. */
export const HOW_TO_BUILD = 'To build it: install a C++ compiler, make and Python (Debian, Ubuntu: sudo apt install build-essential python3; a Mac: xcode-select --install; Windows: the "Desktop development with C++" tools), then npm install; see docs/class-board.md.';

/** What the terminal says about the board: its address (with the key) and its folder. */
export function boardLines(folder, key, port) {
  return [
    '  The class board (for you, the teacher: keep this address to yourself, do not project it):',
    '',
    `      http://localhost:${port}/board?key=${key}`,
    '',
    `  What students send is kept in ${join(folder, DATABASE_FILE)}`,
    `  (another folder: npm run class -- --data FOLDER).`,
  ].join('\n');
}
