/**
 * The picture in words, for a screen reader: what a scene shows through a
 * camera ("a pink sphere in the middle, a white sphere on the left, …, a gray
 * floor, on a white background; two lights") and the traced picture itself
 * as rows of colour names (what p5's gridOutput() does for shapes).
 *
 * Where things are is measured the way the camera sees them: a coarse grid
 * of the camera's own rays (and one ray toward each sphere's centre, so a small
 * one is not missed between them). What each ray meets first is seen; what it
 * meets behind that is "behind" it.
 */
import { colorName } from '../math/color.js';
import { ballOf, middleOf, kindOf as shapeKind, shapeClasses } from '../shapes/index.js';

/** The coarse grid of rays, at most this many a side (fewer for a smaller picture). */
const SAMPLE_COLUMNS = 24;
const SAMPLE_ROWS = 18;
/** Objects named one by one, the largest on screen first; the rest are counted. */
const NAMED = 8;
/** The share of a shape's rays another shape must meet first for it to be "behind" that one. */
const HIDDEN_SHARE = 0.25;
/**
 * Hit tests (rays × shapes) a description may cost: a ray toward each of
 * 10,000 spheres' centres made 10⁸ of them, 1.6 s at every change. Past it,
 * the centre rays go to a spread of the spheres in view (the others are
 * counted), and past that the grid of rays has fewer rays.
 */
const MAX_HIT_TESTS = 500_000;
const NUMBER_WORDS = ['no', 'one', 'two', 'three', 'four', 'five', 'six', 'seven', 'eight', 'nine', 'ten'];

/**
 * One sentence saying what the scene shows through the camera: each shape's
 * colour name and kind, where it is in the picture (left, middle, right; at
 * the top, at the bottom; behind another), the floor, the background and the lights.
 * @param {import('../scene/scene.js').Scene} scene
 * @param {import('../math/camera.js').Camera} camera
 * @returns {string}
 * @example
 * describeScene(classScene(), new Camera({ width: 64, height: 48 }));
 * // 'A pink sphere in the middle; a white sphere on the left; …; and a gray floor, on a white background. Two lights.'
 */
export function describeScene(scene, camera) {
  const { seen, unsampled } = sample(scene, camera);
  const flat = [], round = [];
  for (const s of seen) (s.surface ? flat : round).push(s);
  round.sort((a, b) => b.first - a.first);
  const parts = round.slice(0, NAMED).map((s) => objectPhrase(s, seen));
  const more = round.length - NAMED + unsampled;
  if (more > 0) parts.push(`${count(more)} more ${more === 1 ? 'shape' : 'shapes'}`);
  parts.push(...flat.map(surfacePhrase));
  const things = parts.length ? list(parts) : 'nothing';
  const background = `on a ${colorWord(scene.background)} background`;
  const hidden = scene.objects.filter((o) => !o.material.isEmissive).length - seen.filter((s) => !s.object.material.isEmissive).length - unsampled;
  const outOfView = hidden > 0 ? ` ${capital(count(hidden))} ${hidden === 1 ? 'shape is' : 'shapes are'} out of view.` : '';
  const lights = scene.lights.length;
  return `${capital(things)}, ${background}.${outOfView} ${capital(count(lights))} ${lights === 1 ? 'light' : 'lights'}.`;
}

/**
 * What each shape looks like from the camera: `{ object, first, any, x, y, behind }`
 * for every shape at least one ray meets (first: how many rays meet it first;
 * x, y: where on the picture, 0–1; behind: the shape in front of it most often).
 */
export function sampleScene(scene, camera) {
  return sample(scene, camera).seen;
}

/** sampleScene's shapes (`seen`), and how many spheres in view got no ray of their own and were met by none (`unsampled`). */
function sample(scene, camera) {
  const objects = scene.objects;
  const seen = objects.map((object) => ({ object, first: 0, any: 0, sx: 0, sy: 0, fx: 0, fy: 0, covers: new Map(), surface: surfaceKind(object, camera) }));
  const ray = { origin: camera.position, direction: { x: 0, y: 0, z: -1 } };
  const ts = new Float64Array(objects.length);
  const balls = boundingBalls(objects);
  const o = camera.position, d = ray.direction;
  const cast = (px, py) => {
    camera.directionAt(px, py, d);
    let nearest = -1;
    for (let i = 0; i < objects.length; i++) {
      ts[i] = passesBy(balls, i, o, d) ? Infinity : objects[i].hit(ray);
      if (ts[i] !== Infinity && (nearest < 0 || ts[i] < ts[nearest])) nearest = i;
    }
    if (nearest < 0) return;
    const u = (px + 0.5) / camera.width, v = (py + 0.5) / camera.height;
    for (let i = 0; i < objects.length; i++) {
      if (ts[i] === Infinity) continue;
      const s = seen[i];
      s.any++; s.sx += u; s.sy += v;
      if (i === nearest) { s.first++; s.fx += u; s.fy += v; } else s.covers.set(nearest, (s.covers.get(nearest) ?? 0) + 1);
    }
  };
  const affordable = Math.floor(MAX_HIT_TESTS / Math.max(1, objects.length));
  const shrink = Math.min(1, Math.sqrt(affordable / (SAMPLE_COLUMNS * SAMPLE_ROWS)));
  const columns = Math.max(1, Math.min(Math.floor(SAMPLE_COLUMNS * shrink), camera.width));
  const rows = Math.max(1, Math.min(Math.floor(SAMPLE_ROWS * shrink), camera.height));
  for (let j = 0; j < rows; j++) {
    for (let i = 0; i < columns; i++) cast(((i + 0.5) * camera.width) / columns - 0.5, ((j + 0.5) * camera.height) / rows - 0.5);
  }
  const inView = [];
  for (let i = 0; i < objects.length; i++) {
    const ball = ballOf(objects[i]); // a ray at each ball's centre too: a small one falls between the samples
    if (!ball) continue;
    const p = camera.project(ball.center);
    if (p.depth > 0 && p.x >= -0.5 && p.x <= camera.width - 0.5 && p.y >= -0.5 && p.y <= camera.height - 0.5) inView.push([i, p]);
  }
  // One ray toward each sphere's centre, or toward an even spread of them when that would cost too many hit tests.
  const rays = Math.min(inView.length, Math.max(0, affordable - columns * rows));
  const skipped = new Set(inView.map(([i]) => i));
  for (let j = 0; j < rays; j++) {
    const [i, p] = inView[Math.floor((j * inView.length) / rays)];
    skipped.delete(i);
    cast(p.x, p.y);
  }
  return { seen: summary(seen), unsampled: [...skipped].filter((i) => seen[i].any === 0).length };
}

/** The shapes some ray met, with where they are and what is in front of them. */
function summary(seen) {
  return seen.filter((s) => s.any > 0).map((s) => {
    const n = s.first || s.any;
    const x = (s.first ? s.fx : s.sx) / n, y = (s.first ? s.fy : s.sy) / n;
    let behind = null, most = 0;
    for (const [i, k] of s.covers) if (k > most && !seen[i].surface) { most = k; behind = seen[i].object; }
    // "behind" only when a good part of it is hidden, not for a ray or two along an edge
    if (most < Math.max(2, s.any * HIDDEN_SHARE)) behind = null;
    return { object: s.object, first: s.first, any: s.any, x, y, behind, surface: s.surface };
  });
}

/**
 * Each shape's bounding ball from its bounds, 4 numbers (x, y, z, r²; r² = −1 when
 * unbounded): a ray that passes a ball by misses its shape, a test far cheaper
 * than a cylinder's or a mesh's own (10,000 cylinders' hit tests were a task of a second).
 */
function boundingBalls(objects) {
  const balls = new Float64Array(4 * objects.length);
  objects.forEach((shape, i) => {
    const b = typeof shape.bounds === 'function' ? shape.bounds() : null;
    if (!b) { balls[4 * i + 3] = -1; return; }
    const hx = (b.max.x - b.min.x) / 2, hy = (b.max.y - b.min.y) / 2, hz = (b.max.z - b.min.z) / 2;
    balls.set([b.min.x + hx, b.min.y + hy, b.min.z + hz, (hx * hx + hy * hy + hz * hz) * (1 + 1e-9)], 4 * i);
  });
  return balls;
}

/** Does the ray from o along unit d pass ball i by (the lesson's geometric test: d² > r², or the ball behind the eye)? */
function passesBy(balls, i, o, d) {
  const r2 = balls[4 * i + 3];
  if (!(r2 >= 0)) return false;
  const lx = balls[4 * i] - o.x, ly = balls[4 * i + 1] - o.y, lz = balls[4 * i + 2] - o.z;
  const tca = lx * d.x + ly * d.y + lz * d.z, ll = lx * lx + ly * ly + lz * lz;
  return ll - tca * tca > r2 || (tca < 0 && ll > r2);
}

/**
 * 'floor', 'ceiling' or 'wall' for an unbounded shape (a plane), or a ball so big the camera sees
 * it as one (the class scene's ground); null for an ordinary shape.
 */
function surfaceKind(o, camera) {
  let normal, below;
  if (typeof o.bounds === 'function' && o.bounds() === null) { // unbounded: a plane
    const point = middleOf(o);
    normal = o.normalAt(point);
    below = camera.position.y > point.y;
  } else if (ballOf(o)?.radius >= 100) {
    const { center: c, radius } = ballOf(o), e = camera.position;
    const dx = e.x - c.x, dy = e.y - c.y, dz = e.z - c.z, d = Math.hypot(dx, dy, dz);
    if (d - radius > radius / 10 || d < radius) return null; // far off, or the camera is inside it
    normal = { y: dy / d };
    below = dy > 0;
  } else {
    return null;
  }
  if (Math.abs(normal.y) < 0.7) return 'wall';
  return below ? 'floor' : 'ceiling';
}

/** "a white sphere on the left", "a blue sphere on the right, behind the yellow sphere". */
function objectPhrase(s, seen) {
  const where = [horizontal(s.x), vertical(s.y)].filter(Boolean).join(' ');
  const front = s.behind && seen.find((t) => t.object === s.behind);
  const behind = front ? `, behind the ${colorOf(front.object)} ${kindOf(front.object)}` : '';
  return `${article(nounPhrase(s.object))} ${where}${behind}`.trim();
}

/** "a gray floor". */
function surfacePhrase(s) {
  return article(`${colorOf(s.object)} ${s.surface}`);
}

/** "pink sphere", "white mirror sphere", "glowing yellow sphere (a light)", "orange sphere called sun". */
function nounPhrase(o) {
  const m = o.material, color = colorOf(o), kind = kindOf(o);
  if (m.isEmissive) return `glowing ${color} ${kind} (a light)`;
  const words = [color, m.reflection >= 0.5 && 'mirror', m.transparency >= 0.5 && 'glass', kind].filter(Boolean).join(' ');
  const name = typeof o.name === 'string' ? o.name.trim() : '';
  const said = name && (words.split(' ').includes(name.toLowerCase()) || isKindName(name));
  return name && !said ? `${words} called ${name.slice(0, 40)}` : words;
}

/** "sphere", "Box 2": a name that only says the kind, as shapeName makes them. */
function isKindName(name) {
  const kinds = shapeClasses().map((Shape) => Shape.type.replace(/[^A-Za-z]/g, '')).join('|');
  return new RegExp(`^(${kinds})\\s*\\d*$`, 'i').test(name);
}

/** The word for a shape's kind: 'sphere', 'box', …; 'shape' for one of a sketch's own. */
function kindOf(o) {
  const kind = shapeKind(o);
  return kind === 'object' ? 'shape' : kind;
}

/**
 * A shape's colour name: the colour it is named by, when the sketch named it so (the class's
 * "yellow" sphere, whose surface is nearest orange, is yellow in the description as in the
 * inspector and the verdict: one name a sphere); else its glow for a light, else its surface colour.
 */
function colorOf(o) {
  const name = typeof o.name === 'string' ? o.name.trim().toLowerCase().replace(/^grey$/, 'gray') : '';
  if (COLOR_NAMES.includes(name)) return name;
  const m = o.material;
  return colorWord(m.isEmissive ? m.emission : m.color);
}

/** The nearest simple colour's name for a 0–1 colour (brighter than 1 counts as 1). */
export function colorWord(rgb) {
  return colorName(rgb.map((c) => Math.min(1, c) * 255));
}

function horizontal(x) {
  if (x < 1 / 3) return 'on the left';
  if (x > 2 / 3) return 'on the right';
  return 'in the middle';
}

function vertical(y) {
  if (y < 1 / 4) return 'at the top';
  if (y > 3 / 4) return 'at the bottom';
  return '';
}

function article(phrase) {
  return (/^[aeiou]/i.test(phrase) ? 'an ' : 'a ') + phrase;
}

function count(n) {
  return NUMBER_WORDS[n] ?? n.toLocaleString('en');
}

function capital(text) {
  return text.charAt(0).toUpperCase() + text.slice(1);
}

function list(parts) {
  if (parts.length < 3) return parts.join(' and ');
  return `${parts.slice(0, -1).join('; ')}; and ${parts.at(-1)}`; // semicolons: a part may hold a comma
}

/**
 * The traced picture as rows of colour names, top to bottom: at most `rows`
 * rows of at most `columns` cells, each cell the commonest colour name of the
 * pixels it covers (a few of them, evenly spread), runs of one colour counted:
 * `'Row 1 of 12: 16 white'`, `'Row 6 of 12: 5 white, 2 gray, 6 pink, 3 white'`.
 * @param {Uint8ClampedArray} rgba the picture, width × height × 4 bytes
 * @returns {string[]}
 */
export function pictureRows(rgba, width, height, { columns = 16, rows = 12 } = {}) {
  const cols = Math.min(columns, width), rowCount = Math.min(rows, height);
  const lines = [];
  for (let j = 0; j < rowCount; j++) {
    const names = [];
    for (let i = 0; i < cols; i++) names.push(cellName(rgba, width, i * width / cols, (i + 1) * width / cols, j * height / rowCount, (j + 1) * height / rowCount));
    lines.push(`Row ${j + 1} of ${rowCount}: ${runs(names)}`);
  }
  return lines;
}

/** The commonest colour name among up to 4 × 4 pixels spread over the cell [x0, x1) × [y0, y1). */
function cellName(rgba, width, x0, x1, y0, y1) {
  const tally = new Map();
  let best = '', most = 0;
  const nx = Math.min(4, Math.ceil(x1 - x0)), ny = Math.min(4, Math.ceil(y1 - y0));
  for (let b = 0; b < ny; b++) {
    const y = Math.floor(y0 + ((b + 0.5) * (y1 - y0)) / ny);
    for (let a = 0; a < nx; a++) {
      const x = Math.floor(x0 + ((a + 0.5) * (x1 - x0)) / nx), i = 4 * (y * width + x);
      const name = colorName([rgba[i], rgba[i + 1], rgba[i + 2]]);
      const k = (tally.get(name) ?? 0) + 1;
      tally.set(name, k);
      if (k > most) { most = k; best = name; }
    }
  }
  return best;
}

/** ['white', 'white', 'pink'] → '2 white, 1 pink'. */
function runs(names) {
  const out = [];
  for (let i = 0; i < names.length;) {
    let j = i;
    while (j < names.length && names[j] === names[i]) j++;
    out.push(`${j - i} ${names[i]}`);
    i = j;
  }
  return out.join(', ');
}

/** The names every colour of a picture may have (lib/math/color.js colorName), for a search by first letters. */
export const COLOR_NAMES = ['pink', 'red', 'orange', 'yellow', 'green', 'cyan', 'blue', 'purple', 'white', 'gray', 'black', 'brown'];

/**
 * Each pixel's colour name as an index into COLOR_NAMES, row by row: what the
 * rows in words and the search for "the next pink pixel" read.
 * @param {Uint8ClampedArray} rgba the picture, width × height × 4 bytes
 * @returns {Uint8Array}
 */
export function pixelNames(rgba, width, height) {
  const names = new Uint8Array(width * height);
  const rgb = [0, 0, 0];
  for (let i = 0; i < names.length; i++) {
    rgb[0] = rgba[4 * i]; rgb[1] = rgba[4 * i + 1]; rgb[2] = rgba[4 * i + 2];
    names[i] = COLOR_NAMES.indexOf(colorName(rgb));
  }
  return names;
}

/**
 * The traced picture at its own resolution, one line per row of pixels, the
 * runs of one colour named with their columns, in the coordinates of the
 * answer line (`Pixel: x,y`, both from 0): `'Row 12: 0–9 white, 10–21 pink, 22–31 white'`.
 * @param {Uint8Array} names pixelNames' result
 * @returns {string[]}
 */
export function pixelRows(names, width, height) {
  const lines = [];
  for (let y = 0; y < height; y++) {
    const runs = [];
    for (let x = 0; x < width;) {
      const name = names[y * width + x];
      let end = x;
      while (end + 1 < width && names[y * width + end + 1] === name) end++;
      runs.push(`${x === end ? x : `${x}–${end}`} ${COLOR_NAMES[name]}`);
      x = end + 1;
    }
    lines.push(`Row ${y}: ${runs.join(', ')}`);
  }
  return lines;
}

/**
 * The next pixel after `from` (row by row, wrapping round) whose colour name is
 * `name`: `{ x, y }`, or null when the picture has none. From null: the first.
 * @param {Uint8Array} names pixelNames' result
 * @param {string} name a colour name
 * @param {{x: number, y: number}|null} from
 * @param {number} [step=1] 1: the next one; -1: the one before
 */
export function nextPixelNamed(names, width, name, from, step = 1) {
  const wanted = COLOR_NAMES.indexOf(name), n = names.length;
  const start = from ? from.y * width + from.x : step > 0 ? -1 : n;
  for (let k = 1; k <= n; k++) {
    const i = (((start + step * k) % n) + n) % n;
    if (names[i] === wanted) return { x: i % width, y: Math.floor(i / width) };
  }
  return null;
}
