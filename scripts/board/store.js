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
 */
import { mkdirSync } from 'node:fs';
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
CREATE TABLE IF NOT EXISTS sent (
  class INTEGER NOT NULL, laptop TEXT NOT NULL, id TEXT NOT NULL, kind TEXT NOT NULL, at TEXT NOT NULL,
  page TEXT, task TEXT, line TEXT, x INTEGER, y INTEGER, h REAL, v REAL, width INTEGER, height INTEGER, fov REAL,
  verdict TEXT, color TEXT, color_name TEXT, page_said TEXT, passed INTEGER, to_fix INTEGER, value INTEGER,
  PRIMARY KEY (class, laptop, id));
CREATE INDEX IF NOT EXISTS sent_by_kind ON sent (class, kind);
`;

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
      laptop: q('SELECT number, nickname FROM laptops WHERE class = ? AND laptop = ?'),
      nextNumber: q('SELECT COALESCE(MAX(number), 0) + 1 AS n FROM laptops WHERE class = ?'),
      addLaptop: q('INSERT INTO laptops (class, laptop, number, nickname, seen) VALUES (?, ?, ?, ?, ?)'),
      renameLaptop: q('UPDATE laptops SET nickname = ?, seen = ? WHERE class = ? AND laptop = ?'),
      add: q(`INSERT OR IGNORE INTO sent (class, laptop, id, kind, at, page, task, line, x, y, h, v, width, height, fov,
        verdict, color, color_name, page_said, passed, to_fix, value)
        VALUES (@class, @laptop, @id, @kind, @at, @page, @task, @line, @x, @y, @h, @v, @width, @height, @fov,
        @verdict, @color, @colorName, @pageSaid, @passed, @toFix, @value)`),
      students: q('SELECT number, nickname FROM laptops WHERE class = ? ORDER BY number'),
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
   * A laptop's name on the board (its nickname, else "student N"), made
   * known to the class on its first visit; a new nickname replaces the old.
   * @returns {{ number: number, name: string }}
   */
  hello(laptop, nickname) {
    return this.#write(() => this.#laptop(laptop, nickname, new Date().toISOString()));
  }

  #laptop(laptop, nickname, at) {
    const cls = this.#class.id;
    const found = this.#q.laptop.get(cls, laptop);
    if (!found) {
      const number = this.#q.nextNumber.get(cls).n;
      this.#q.addLaptop.run(cls, laptop, number, nickname ?? null, at);
      return { number, name: nameOf(number, nickname) };
    }
    if (nickname && nickname !== found.nickname) this.#q.renameLaptop.run(nickname, at, cls, laptop);
    return { number: found.number, name: nameOf(found.number, nickname ?? found.nickname) };
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
      const who = this.#laptop(submission.laptop, submission.nickname, at);
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

/** A student's name on the board: the nickname, else "student N". */
export const nameOf = (number, nickname) => (nickname ? nickname : `student ${number}`);

const EMPTY_ROW = {
  page: null, task: null, line: null, x: null, y: null, h: null, v: null, width: null, height: null, fov: null,
  verdict: null, color: null, colorName: null, pageSaid: null, passed: null, toFix: null, value: null,
};
