/**
 * The gallery: every sketches/*.html page in lesson order (by its number),
 * found at build time, so a new sketch shows up without editing a list. Its
 * title and one line come from the page's <title> and description; its
 * thumbnail is the picture the screenshot tests check for that sketch.
 */
import { showProgress } from './gallery-progress.js';

const pages = import.meta.glob('../sketches/*.html', { query: '?raw', import: 'default', eager: true });
const thumbnails = import.meta.glob('../tests/e2e/__screenshots__/gallery.spec.js/*-view0.png', {
  query: '?url', import: 'default', eager: true,
});

const list = document.getElementById('sketches');
for (const path of Object.keys(pages).sort()) {
  list.append(card(path, describe(pages[path])));
}
showProgress(list); // each lesson's tasks done in this browser, and the code for the teacher

/** Title, one line and number of a sketch page, read from its HTML. */
function describe(html) {
  const doc = new DOMParser().parseFromString(html, 'text/html');
  const title = doc.title.replace(/^\d+\s*·\s*/, '');
  const line = doc.querySelector('meta[name="description"]')?.content ?? '';
  return { title, line };
}

function card(path, { title, line }) {
  const file = path.split('/').pop();
  const slug = file.replace(/\.html$/, '');
  const number = slug.match(/^\d+/)?.[0] ?? '';
  const thumb = thumbnails[`../tests/e2e/__screenshots__/gallery.spec.js/${slug}-view0.png`];

  const link = document.createElement('a');
  link.href = `sketches/${file}`;
  const picture = thumb ? Object.assign(document.createElement('img'), { src: thumb, alt: '', loading: 'lazy' })
    : Object.assign(document.createElement('div'), { className: 'no-thumb', textContent: number });
  picture.classList.add('thumb');
  const heading = document.createElement('h2');
  heading.append(Object.assign(document.createElement('span'), { className: 'number', textContent: number }), ' ', title);
  const text = document.createElement('p');
  text.textContent = line;
  link.append(picture, heading, text);

  const item = document.createElement('li');
  item.append(link);
  return item;
}
