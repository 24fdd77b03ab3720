// The read-only text boxes of CSV and code: a CR shows as ␍ (a text box turns
// it into a LF), and a text longer than the box can lay out quickly is cut at
// a line's end, with a note.
import { describe, it, expect } from 'vitest';
import { showInBox, BOX_CHARS } from '../../lib/p5/controls/text-box.js';

/** What a textarea does to its value: every CR and CRLF becomes a LF. */
function textarea() {
  let value = '';
  return { get value() { return value; }, set value(v) { value = String(v).replace(/\r\n?/g, '\n'); } };
}

describe('showInBox', () => {
  it('shows a CR in a name as ␍, so the row stays one line', () => {
    const box = textarea();
    const csv = 'sphere,t\n"two\rrows",1\n';
    expect(showInBox(box, csv)).toBe('');
    expect(box.value).toBe('sphere,t\n"two␍rows",1\n');
    expect(box.value.split('\n')).toHaveLength(3);
  });

  it('cuts a long text at a line end and says how much it shows', () => {
    const box = textarea();
    const line = `${'x'.repeat(99)}\n`;
    const text = line.repeat(10_000); // 1 MB
    const note = showInBox(box, text);
    expect(box.value.length).toBeLessThanOrEqual(BOX_CHARS);
    expect(box.value.length).toBeGreaterThan(BOX_CHARS - line.length);
    expect(box.value.endsWith('\n')).toBe(true);
    expect(text.startsWith(box.value)).toBe(true);
    expect(note).toBe(`The box shows the first ${(box.value.length / 100).toLocaleString('en')} of 10,000 lines; copying or downloading gives them all.`);
  });

  it('cuts a text of one long line at the limit', () => {
    const box = textarea();
    expect(showInBox(box, 'y'.repeat(3 * BOX_CHARS))).toMatch(/^The box shows the first 1 of 1 lines/);
    expect(box.value).toBe('y'.repeat(BOX_CHARS));
  });
});
