/**
 * The class board's database: one SQLite file (better-sqlite3) in the
 * teacher's folder. Write-ahead log with synchronous = NORMAL: a submit is
 * answered only after its transaction is committed to the log file, so a
 * crash of the server (kill -9, a closed terminal) loses nothing a student was
 * told was received. (FULL would also survive a power cut of the teacher's
 * computer, at the price of a flush to the disk per commit: measured here 8 ms
 * median, 27 ms at p95, during which the server answers nobody.)
 *
 * One table of what students sent, each row once: (class, laptop, id) is its
 * key, the id made by the student's page, so a page that sends again what it
 * is not sure arrived is stored once. "Clear the board" archives the class
 * (its rows stay in the file, its CSV too) and starts a new one.
 *
 * Each laptop has a secret, made at its first hello and kept hashed
 * (SHA-256): a later request that does not prove it is not that laptop.
 * What the server refused from a known laptop is kept too, with the reason,
 * for the teacher to see.
 */
import { createHash, randomBytes, timingSafeEqual } from 'node:crypto';
import { mkdirSync } from 'node:fs';
import { BadSubmission, nameKey } from './checks.js';
import { join } from 'node:path';

/** The database file in the board's folder. */
export const DATABASE_FILE = 'board.sqlite';

/** The database's largest size, by default: a class of 30 sends about 100 kB; a flood stops here. */
export const DATABASE_MAX_BYTES = 64 * 1024 * 1024;

const SCHEMA = `
CREATE TABLE IF NOT EXISTS classes (
  id INTEGER PRIMARY KEY, started TEXT NOT NULL, archived TEXT);
CREATE TABLE IF NOT EXISTS laptops (
  class INTEGER NOT NULL, laptop TEXT NOT NULL, number INTEGER NOT NULL, nickname TEXT, seen TEXT NOT NULL,
  PRIMARY KEY (class, laptop));
CREATE TABLE IF NOT EXISTS refused (
  class INTEGER NOT NULL, laptop TEXT NOT NULL, at TEXT NOT NULL, what TEXT NOT NULL, reason TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS sent (
  class INTEGER NOT NULL, laptop TEXT NOT NULL, id TEXT NOT NULL, kind TEXT NOT NULL, at TEXT NOT NULL,
  page TEXT, task TEXT, line TEXT, x INTEGER, y INTEGER, h REAL, v REAL, width INTEGER, height INTEGER, fov REAL,
  verdict TEXT, color TEXT, color_name TEXT, page_said TEXT, passed INTEGER, to_fix INTEGER, value INTEGER,
  PRIMARY KEY (class, laptop, id));
CREATE INDEX IF NOT EXISTS sent_by_kind ON sent (class, kind);
`;
/** Columns added since the first boards: a board made before gets them when it is opened. */
const LAPTOP_COLUMNS = { secret: 'BLOB', name_key: 'TEXT' };
/** The refusals the board shows, newest first. */
const REFUSED_SHOWN = 50;

/** Thrown when the database has reached its size cap. */
export class BoardFullError extends Error {}

/**
 * Opens (or makes) the board's database in `folder`.
 * @param {string} folder
 * @param {{ Database: any, maxBytes?: number }} options Database: better-sqlite3's class
 */
export function openStore(folder, { Database, maxBytes = DATABASE_MAX_BYTES }) {
  mkdirSync(folder, { recursive: true });
  const db = new Database(join(folder, DATABASE_FILE));
  db.pragma('journal_mode = WAL');
  db.pragma('synchronous = NORMAL'); // each commit is in the log file before the student hears "received"
  db.pragma('foreign_keys = ON');
  const pageSize = db.pragma('page_size', { simple: true });
  db.pragma(`max_page_count = ${Math.max(16, Math.floor(maxBytes / pageSize))}`);
  db.exec(SCHEMA);
  const has = new Set(db.pragma('table_info(laptops)').map((c) => c.name));
  for (const [column, type] of Object.entries(LAPTOP_COLUMNS)) if (!has.has(column)) db.exec(`ALTER TABLE laptops ADD COLUMN ${column} ${type}`);
  db.exec('CREATE INDEX IF NOT EXISTS laptops_by_name ON laptops (class, name_key)');
  // Names taken before names had keys: keyed now, so that no other laptop takes them in another spelling.
  const unkeyed = db.prepare('SELECT rowid, nickname FROM laptops WHERE nickname IS NOT NULL AND name_key IS NULL').all();
  const setKey = db.prepare('UPDATE laptops SET name_key = ? WHERE rowid = ?');
  db.transaction(() => { for (const { rowid, nickname } of unkeyed) setKey.run(nameKey(nickname), rowid); })();
  return new BoardStore(db, maxBytes);
}

/** What students sent, kept; the board's numbers read from it. */
export class BoardStore {
  #db; #q; #class;

  constructor(db, maxBytes) {
    this.#db = db;
    this.maxBytes = maxBytes;
    const q = (sql) => db.prepare(sql);
    this.#q = {
      current: q('SELECT id, started FROM classes WHERE archived IS NULL ORDER BY id DESC LIMIT 1'),
      newClass: q('INSERT INTO classes (started) VALUES (?)'),
      archive: q('UPDATE classes SET archived = ? WHERE id = ?'),
      laptop: q('SELECT number, nickname, secret FROM laptops WHERE class = ? AND laptop = ?'),
      nextNumber: q('SELECT COALESCE(MAX(number), 0) + 1 AS n FROM laptops WHERE class = ?'),
      addLaptop: q('INSERT INTO laptops (class, laptop, number, secret, seen) VALUES (?, ?, ?, ?, ?)'),
      renameLaptop: q('UPDATE laptops SET nickname = ?, name_key = ?, seen = ? WHERE class = ? AND laptop = ?'),
      nameTaken: q('SELECT 1 FROM laptops WHERE class = ? AND name_key = ? AND laptop <> ? LIMIT 1'),
      refuse: q('INSERT INTO refused (class, laptop, at, what, reason) VALUES (?, ?, ?, ?, ?)'),
      refused: q(`SELECT r.at, r.what, r.reason, l.number AS student, l.nickname FROM refused r JOIN laptops l ON l.class = r.class AND l.laptop = r.laptop
        WHERE r.class = ? ORDER BY r.rowid DESC LIMIT ${REFUSED_SHOWN}`),
      refusedCount: q('SELECT COUNT(*) AS n FROM refused WHERE class = ?'),
      add: q(`INSERT OR IGNORE INTO sent (class, laptop, id, kind, at, page, task, line, x, y, h, v, width, height, fov,
        verdict, color, color_name, page_said, passed, to_fix, value)
        VALUES (@class, @laptop, @id, @kind, @at, @page, @task, @line, @x, @y, @h, @v, @width, @height, @fov,
        @verdict, @color, @colorName, @pageSaid, @passed, @toFix, @value)`),
      // A student is a laptop that sent something the board kept: a visit alone is not one.
      students: q(`SELECT number, nickname FROM laptops l WHERE class = ?
        AND EXISTS (SELECT 1 FROM sent WHERE class = l.class AND laptop = l.laptop) ORDER BY number`),
      answers: q(`SELECT s.rowid AS id, l.number AS student, s.at, s.line, s.x, s.y, s.h, s.v, s.width, s.height, s.verdict, s.color_name AS colorName
        FROM sent s JOIN laptops l ON l.class = s.class AND l.laptop = s.laptop WHERE s.class = ? AND s.kind = 'answer' ORDER BY s.rowid`),
      tasks: q(`SELECT page, task, COUNT(DISTINCT laptop) AS students FROM sent WHERE class = ? AND kind = 'task' GROUP BY page, task`),
      poll: q(`SELECT value, COUNT(*) AS students FROM (SELECT laptop, value FROM sent s WHERE class = ? AND kind = 'poll'
        AND rowid = (SELECT MAX(rowid) FROM sent WHERE class = s.class AND laptop = s.laptop AND kind = 'poll')) GROUP BY value`),
      homework: q(`SELECT page, SUM(passed) AS passed, COUNT(*) AS students, (SELECT COUNT(*) FROM sent WHERE class = @class AND kind = 'check' AND page = s.page) AS checks
        FROM sent s WHERE class = @class AND kind = 'check'
        AND rowid = (SELECT MAX(rowid) FROM sent WHERE class = s.class AND laptop = s.laptop AND kind = 'check' AND page = s.page) GROUP BY page`),
      everything: q(`SELECT s.rowid AS row, s.*, l.number, l.nickname FROM sent s JOIN laptops l ON l.class = s.class AND l.laptop = s.laptop
        WHERE s.class = ? ORDER BY s.rowid`),
    };
    this.#class = this.#currentClass();
  }

  /** The class being taught: `{ id, started }` (the newest not archived; a first one is made). */
  #currentClass() {
    const found = this.#q.current.get();
    if (found) return found;
    const started = new Date().toISOString();
    return { id: Number(this.#q.newClass.run(started).lastInsertRowid), started };
  }

  get currentClass() { return { ...this.#class }; }

  /**
   * A laptop saying hello: the laptop `laptop` when `secret` is its secret;
   * a laptop new to the class gets a number and a secret; one that exists but
   * whose secret was not given (or not this one) is not handed over: a new
   * laptop, with an id of its own, is made instead.
   * @param {string} laptop
   * @param {string | undefined} secret
   * @returns {{ laptop: string, number: number, name: string, secret?: string }} secret: only to a new laptop
   */
  hello(laptop, secret) {
    return this.#write(() => {
      const at = new Date().toISOString();
      const found = this.#q.laptop.get(this.#class.id, laptop);
      if (found && sameSecret(found.secret, secret)) return { laptop, number: found.number, name: nameOf(found.number, found.nickname) };
      const id = found ? randomBytes(16).toString('hex') : laptop;
      const made = randomBytes(32).toString('base64url');
      const number = this.#add(id, at, hashOf(made)).number;
      return { laptop: id, number, name: nameOf(number, null), secret: made };
    });
  }

  /** Whether `secret` is the secret of the laptop `laptop` of this class (compared in constant time). */
  proves(laptop, secret) {
    const found = this.#q.laptop.get(this.#class.id, laptop);
    return Boolean(found) && sameSecret(found.secret, secret);
  }

  /**
   * A new name for a laptop of the class (checked by checkNickname first): refused
   * when another laptop of the class has one that reads the same (nameKey).
   * @returns {{ number: number, name: string }}
   */
  rename(laptop, nickname) {
    const key = nameKey(nickname);
    return this.#write(() => {
      const cls = this.#class.id;
      const found = this.#q.laptop.get(cls, laptop);
      if (!found) throw new BadSubmission('laptop must say hello before it takes a name');
      if (this.#q.nameTaken.get(cls, key, laptop)) throw new BadSubmission(`name ${JSON.stringify(nickname)} is taken: another laptop of the class has it (or one that reads the same); choose another`);
      if (nickname !== found.nickname) this.#q.renameLaptop.run(nickname, key, new Date().toISOString(), cls, laptop);
      return { number: found.number, name: nameOf(found.number, nickname) };
    });
  }

  /** Keeps what the server refused from a laptop of the class, and why, for the board. */
  refuse(laptop, what, reason) {
    this.#write(() => this.#q.refuse.run(this.#class.id, laptop, new Date().toISOString(), what, reason));
  }

  /** A laptop of the class (made, without a secret, when a submission comes from one it does not know). */
  #laptop(laptop, at) {
    const found = this.#q.laptop.get(this.#class.id, laptop);
    if (found) return { number: found.number, name: nameOf(found.number, found.nickname) };
    return this.#add(laptop, at, null);
  }

  #add(laptop, at, secretHash) {
    const number = this.#q.nextNumber.get(this.#class.id).n;
    this.#q.addLaptop.run(this.#class.id, laptop, number, secretHash, at);
    return { number, name: nameOf(number, null) };
  }

  /**
   * Keeps one checked submission (scripts/board/checks.js), once: sent again
   * with the same id it is not stored twice. Returns when it is on disk.
   * @param {{ laptop: string, nickname?: string, id: string, kind: string }} submission
   * @returns {{ number: number, name: string, stored: boolean }} stored: false when it was already there
   */
  add(submission) {
    return this.addMany([submission])[0];
  }

  /**
   * Keeps several submissions in one transaction: one flush to the disk for
   * all (a class's burst of submits waits for one flush, not for thirty).
   * @returns {{ number: number, name: string, stored: boolean }[]} one per submission, in order
   */
  addMany(submissions) {
    return this.#write(() => submissions.map((submission) => {
      const at = new Date().toISOString();
      const who = this.#laptop(submission.laptop, at);
      const row = { ...EMPTY_ROW, ...submission, class: this.#class.id, at };
      delete row.nickname;
      const { changes } = this.#q.add.run(row);
      return { ...who, stored: changes === 1 };
    }));
  }

  /** One transaction; a full database is a BoardFullError. */
  #write(work) {
    try {
      return this.#db.transaction(work)();
    } catch (error) {
      if (error?.code === 'SQLITE_FULL') throw new BoardFullError(`the class board's database is full (${Math.round(this.maxBytes / 1048576)} MB)`);
      throw error;
    }
  }

  /** The board's numbers for the class being taught (see scripts/board/page/board.js). */
  state() {
    const cls = this.#class.id;
    const students = this.#q.students.all(cls).map((s) => ({ number: s.number, name: nameOf(s.number, s.nickname) }));
    return {
      class: this.currentClass,
      students,
      answers: this.#q.answers.all(cls),
      tasks: this.#q.tasks.all(cls),
      poll: this.#q.poll.all(cls),
      homework: this.#q.homework.all({ class: cls }),
      refused: this.#q.refused.all(cls).map(({ nickname, ...r }) => ({ ...r, name: nameOf(r.student, nickname) })),
      refusedCount: this.#q.refusedCount.get(cls).n,
    };
  }

  /** Every row of the class being taught, oldest first, each with its student's number and nickname. */
  rows() {
    return this.#q.everything.all(this.#class.id);
  }

  /** "Clear the board": the class is archived (kept in the file) and a new one starts. */
  clear() {
    return this.#write(() => {
      this.#q.archive.run(new Date().toISOString(), this.#class.id);
      this.#class = this.#currentClass();
      return this.currentClass;
    });
  }

  close() { this.#db.close(); }
}

const hashOf = (text) => createHash('sha256').update(String(text)).digest();

/** Whether `secret` hashes to `kept` (a laptop without a secret, from an older board, proves nothing). */
function sameSecret(kept, secret) {
  if (!kept || typeof secret !== 'string' || secret.length > 200) return false;
  return timingSafeEqual(hashOf(secret), kept);
}

/** A student's name on the board: the nickname, else "student N". */
export const nameOf = (number, nickname) => (nickname ? nickname : `student ${number}`);

const EMPTY_ROW = {
  page: null, task: null, line: null, x: null, y: null, h: null, v: null, width: null, height: null, fov: null,
  verdict: null, color: null, colorName: null, pageSaid: null, passed: null, toFix: null, value: null,
};
