// Every lesson page gets the notice it shows when opened from a file (a built
// page double-clicked): inline, since such a page loads no stylesheet and no
// script of its own files; the gallery's notice gets the same style.
import { describe, it, expect } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { fromFileNoticeInto, FROM_FILE_HEAD, FROM_FILE_NOTICE } from '../../scripts/site-plugins.js';

const lessons = readdirSync('sketches').filter((f) => /^\d\d-.*\.html$/.test(f));

describe('fromFileNoticeInto', () => {
  it.each(lessons)('%s: the notice under its header, what shows it in its head', (file) => {
    const filename = resolve('sketches', file);
    const html = fromFileNoticeInto(readFileSync(filename, 'utf8'), { filename });
    expect(html).toContain(`</header>\n  ${FROM_FILE_NOTICE}`);
    expect(html.indexOf(FROM_FILE_HEAD)).toBeGreaterThan(-1);
    expect(html.indexOf(FROM_FILE_HEAD)).toBeLessThan(html.indexOf('</head>'));
  });

  it('gives the gallery\'s own notice the same inline style, and leaves other pages alone', () => {
    const gallery = readFileSync('index.html', 'utf8');
    const built = fromFileNoticeInto(gallery, { filename: resolve('index.html') });
    expect(built.indexOf(FROM_FILE_HEAD)).toBeLessThan(built.indexOf('</head>'));
    expect(built.split('class="from-file"').length).toBe(2); // its own notice, not a second one
    const editor = readFileSync('web-editor.html', 'utf8');
    expect(fromFileNoticeInto(editor, { filename: resolve('web-editor.html') })).toBe(editor);
  });
});
