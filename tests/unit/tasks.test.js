// Progress without a page: the stored text, read strictly, and the progress code for the teacher.
import { describe, it, expect } from 'vitest';
import { PROGRESS_KEY, parseProgress, serializeProgress, markDone, clearProgress, pageProgress, progressText, achievements, progressCode, readProgressCode, readProgressLine } from '../../lib/lesson/progress.js';
import { LESSONS, lessonOf } from '../../lib/lesson/tasks.js';

const all = Object.fromEntries(LESSONS.map((l) => [l.page, l.tasks.map((t) => t.id)]));

describe('the stored progress', () => {
  it('has a versioned key and reads back what it wrote, in the lessons\' order', () => {
    expect(PROGRESS_KEY).toMatch(/:v1$/);
    let progress = markDone({}, lessonOf('01'), 'miss');
    progress = markDone(progress, lessonOf('01'), 'select');
    expect(progress).toEqual({ '01': ['select', 'miss'] });
    expect(parseProgress(serializeProgress(progress), LESSONS)).toEqual(progress);
  });

  it('reads corrupt, foreign or other-version text as nothing done, without an error', () => {
    for (const text of [null, '', 'not json', '[]', 'null', '{"v":2,"pages":{"01":["select"]}}', '{"pages":{"01":["select"]}}',
      '{"v":1,"pages":[]}', '{"v":1,"pages":{"01":"select"}}', JSON.stringify({ v: 1, pages: { '01': ['select'] }, pad: 'x'.repeat(30_000) })]) {
      expect(parseProgress(text, LESSONS), String(text).slice(0, 40)).toEqual({});
    }
  });

  it('keeps only the pages and task ids the lessons know', () => {
    const text = JSON.stringify({ v: 1, pages: { '01': ['select', '<script>', 'nope'], 99: ['select'], __proto__: ['x'], '02': [1, {}, 'zero'] } });
    expect(parseProgress(text, LESSONS)).toEqual({ '01': ['select'], '02': ['zero'] });
  });

  it('marks a task once, refuses unknown ids, and clears one page or all', () => {
    const one = markDone({}, lessonOf('03'), 'inside');
    expect(markDone(one, lessonOf('03'), 'inside')).toBe(one);
    expect(markDone(one, lessonOf('03'), 'no-such-task')).toBe(one);
    const two = markDone(one, lessonOf('01'), 'select');
    expect(clearProgress(two, '03')).toEqual({ '01': ['select'] });
    expect(clearProgress(two)).toEqual({});
  });

  it('counts a page as "2 of 5"', () => {
    const progress = { '02': ['negative', 'zero'] };
    expect(pageProgress(progress, lessonOf('02'))).toEqual({ done: 2, total: 5, finished: false });
    expect(progressText(pageProgress(progress, lessonOf('02')))).toBe('2 of 5');
    expect(pageProgress({ '02': all['02'] }, lessonOf('02')).finished).toBe(true);
  });
});

describe('achievements', () => {
  it('one per finished page, the homework when 08 and 09 are finished, every page last', () => {
    expect(achievements({ '01': ['select'] }, LESSONS)).toEqual([]);
    expect(achievements({ '01': all['01'] }, LESSONS).map((a) => a.id)).toEqual(['page-01']);
    expect(achievements({ '08': all['08'] }, LESSONS).map((a) => a.id)).toEqual(['page-08']);
    expect(achievements({ '08': all['08'], '09': all['09'] }, LESSONS).map((a) => a.id)).toEqual(['page-08', 'page-09', 'homework']);
    const ids = achievements(all, LESSONS).map((a) => a.id);
    expect(ids).toHaveLength(LESSONS.length + 2);
    expect(ids.slice(-2)).toEqual(['homework', 'all']);
  });
});

describe('the progress code', () => {
  const progress = { '00': ['select'], '01': ['select', 'miss', 'slow'], '07': all['07'], '09': ['pass'] };

  it('is short, and reads back as the same progress', () => {
    const code = progressCode(progress, LESSONS);
    expect(code).toMatch(/^RT1(-[0-9A-F]{4}){8}-[0-9A-F]{2}-[0-9A-F]{2}$/); // 17 pages, two hex digits each, in fours
    expect(readProgressCode(code, LESSONS)).toEqual({ progress });
    expect(readProgressCode(`  ${code.toLowerCase()} `, LESSONS)).toEqual({ progress }); // as typed
    expect(readProgressCode(progressCode({}, LESSONS), LESSONS)).toEqual({ progress: {} });
  });

  it('refuses a code with a digit changed, two digits swapped, or one missing, and says why', () => {
    const code = progressCode(progress, LESSONS);
    const flip = (i) => code.slice(0, i) + (code[i] === '0' ? '1' : '0') + code.slice(i + 1);
    for (let i = 4; i < code.length; i++) {
      if (code[i] === '-') continue;
      expect(readProgressCode(flip(i), LESSONS).problem, `digit ${i}`).toBeTruthy();
    }
    const swapped = code.replace(/-([0-9A-F])([0-9A-F])/, (m, a, b) => (a === b ? m : `-${b}${a}`));
    if (swapped !== code) expect(readProgressCode(swapped, LESSONS).problem).toMatch(/check sum/);
    expect(readProgressCode(code.slice(0, -4) + code.slice(-3), LESSONS).problem).toMatch(/shape/);
  });

  it('refuses what is no code, never throwing', () => {
    expect(readProgressCode('', LESSONS).problem).toBe('no code given');
    expect(readProgressCode(undefined, LESSONS).problem).toBe('no code given');
    expect(readProgressCode('RT2-0000-0000-0000-0000-0000-00', LESSONS).problem).toMatch(/starts with RT1-/);
    expect(readProgressCode('<img src=x onerror=alert(1)>', LESSONS).problem).toMatch(/starts with RT1-/);
    expect(readProgressCode(`RT1-${'0'.repeat(200)}`, LESSONS).problem).toMatch(/too long/);
    expect(readProgressCode('RT1-00G0-0000-0000-0000-0000-00', LESSONS).problem).toMatch(/shape/);
  });

  it('still reads a code made when only pages 00–09 had tasks: the later pages as nothing done', () => {
    const first10 = LESSONS.slice(0, 10);
    const old = progressCode(progress, first10);
    expect(old).toMatch(/^RT1(-[0-9A-F]{4}){5}-[0-9A-F]{2}$/);
    expect(readProgressCode(old, LESSONS)).toEqual({ progress });
    expect(readProgressCode(progressCode(progress, LESSONS.slice(0, 9)), LESSONS).problem).toMatch(/shape/); // shorter still: no code of this kit
  });

  it('still reads the codes made before pages 16 and 17 had tasks: 15 pages (00–14) and 16 (00–14, 16)', () => {
    const fifteen = progressCode(progress, LESSONS.slice(0, 15)), sixteen = progressCode(progress, LESSONS.slice(0, 16));
    expect(fifteen).toMatch(/^RT1(-[0-9A-F]{4}){7}-[0-9A-F]{2}-[0-9A-F]{2}$/); // 30 hex digits
    expect(sixteen).toMatch(/^RT1(-[0-9A-F]{4}){8}-[0-9A-F]{2}$/); // 32
    expect(readProgressCode(fifteen, LESSONS)).toEqual({ progress });
    expect(readProgressCode(sixteen, LESSONS)).toEqual({ progress });
  });

  it('refuses bits for tasks a page does not have, even with a good check sum', () => {
    // Page 08 has 3 tasks: bit 3 (value 8) is none of them. Build the code with its check sum.
    const hex = `${'00'.repeat(8)}08${'00'.repeat(LESSONS.length - 9)}`;
    let sum = 0;
    for (const [i, ch] of [...hex].entries()) sum = (sum + (i + 1) * parseInt(ch, 16)) % 251;
    const code = ['RT1', ...hex.match(/.{1,4}/g), sum.toString(16).toUpperCase().padStart(2, '0')].join('-');
    expect(readProgressCode(code, LESSONS).problem).toBe('page 08 has no task 4');
  });
});

describe('a line the teacher pasted', () => {
  const code = progressCode({ '01': ['select'] }, LESSONS);

  it('finds the code after any name, in the line as typed (ß, ﬁ and İ change length when upper-cased; "started" holds RT)', () => {
    for (const name of ['Weiß', 'ﬁona', 'Ana (started)', 'İpek', 'Straße ﬁﬁ', 'ART-Bart']) {
      for (const line of [`${name} ${code}`, `${name}: ${code}`, `${name}:${code}`, `${name} ${code.toLowerCase()}`]) {
        const read = readProgressLine(line, LESSONS);
        expect(read.name, line).toBe(name);
        expect(read.progress, line).toEqual({ '01': ['select'] });
      }
    }
    expect(readProgressLine(code, LESSONS)).toEqual({ name: '', progress: { '01': ['select'] } });
  });

  it('says why a line holds no code, and cuts the name', () => {
    expect(readProgressLine('Ana 0100-0000', LESSONS)).toEqual({ name: '', problem: 'a progress code starts with RT1-' });
    expect(readProgressLine(`${'x'.repeat(100)} ${code}`, LESSONS, 40).name).toBe('x'.repeat(40));
  });

  it('reads a line in time proportional to its length', async () => {
    const { timeRatio } = await import('./linear-time.js');
    expect(timeRatio((line) => readProgressLine(line, LESSONS), (n) => `a${' '.repeat(n)}b ${code}`)).toBeLessThan(400);
    expect(timeRatio((line) => readProgressLine(line, LESSONS), (n) => `${'rt1-'.repeat(n / 4)}`)).toBeLessThan(400);
    expect(timeRatio((line) => readProgressLine(line, LESSONS), (n) => `${':'.repeat(n)}x ${code}`)).toBeLessThan(400);
  });
});
