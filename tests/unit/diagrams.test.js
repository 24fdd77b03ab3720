// The diagrams' labels: the placer's rules, and the side and top views drawn
// into a recording stand-in for p5 for pixels all over the class scene and
// sketch 01's scene, where no label may land on another or leave the view.
import { describe, it, expect } from 'vitest';
import { drawSideView, drawTopView } from '../../lib/p5/diagrams/index.js';
import { labelPlacer, ON_THICK } from '../../lib/p5/diagrams/labels.js';
import { classScene, Camera, Scene, Sphere, PointLight, inspectPixel } from '../../lib/index.js';

const sizeOf = (font) => Number(/([\d.]+)px/.exec(font)[1]);
const widthOf = (text, font) => text.length * sizeOf(font) * 0.56;

/**
 * A p5 sketch that draws nothing and records every text written on its
 * canvas context, with the box it covers (its width by the stand-in's
 * measure, one em high, centred on y as the diagrams' labels are).
 */
function recordingSketch() {
  const texts = [];
  const ctx = {
    font: '10px sans-serif', textAlign: 'start', saved: [],
    save() { this.saved.push([this.font, this.textAlign]); },
    restore() { [this.font, this.textAlign] = this.saved.pop(); },
    measureText(text) { return { width: widthOf(text, this.font) }; },
    fillText(text, x, y) {
      const w = widthOf(text, this.font), h = sizeOf(this.font);
      const left = this.textAlign === 'left' ? x : this.textAlign === 'right' ? x - w : x - w / 2;
      texts.push({ text, x: left, y: y - h / 2, w, h });
    },
  };
  const context = new Proxy(ctx, { get: (o, k) => (k in o ? o[k] : () => ({ addColorStop() {} })) });
  let size = 12;
  const sketch = { drawingContext: context, textSize: (s) => { size = s; }, textWidth: (t) => t.length * size * 0.56, color: () => ({}) };
  const p = new Proxy(sketch, { get: (o, k) => (k in o ? o[k] : typeof k === 'string' && /^[A-Z]+$/.test(k) ? k : () => {}) });
  return { p, texts };
}

const overlap = (a, b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;

/** What is wrong with the labels of one view drawn in the box { x, y, w, h }: overlaps and labels out of it. */
function labelFaults(draw, options) {
  const { p, texts } = recordingSketch();
  draw(p, options);
  const { x, y, w, h } = options;
  const area = { x: x + 4, y: y + 30, w: w - 8, h: h - 34 - 26 }; // under the title, above the line key
  const faults = [];
  texts.forEach((a, i) => {
    if (a.x < area.x || a.y < area.y || a.x + a.w > area.x + area.w || a.y + a.h > area.y + area.h) faults.push(`"${a.text}" leaves the view`);
    for (const b of texts.slice(i + 1)) if (overlap(a, b)) faults.push(`"${a.text}" on "${b.text}"`);
  });
  return faults;
}

/** Every `step`-th pixel of a camera, both views: the faults, each with its pixel and view. */
function sweep(scene, camera, box, step) {
  const faults = [];
  for (let py = 0; py < camera.height; py += step) {
    for (let px = 0; px < camera.width; px += step) {
      const record = inspectPixel(scene, camera, px, py);
      for (const [name, draw] of [['side', drawSideView], ['top', drawTopView]]) {
        for (const f of labelFaults(draw, { scene, camera, record, ...box })) faults.push(`${name} ${px},${py}: ${f}`);
      }
    }
  }
  return faults;
}

/** Sketch 01's scene (sketches/01-rays-through-pixels.js). */
function sketch01Scene() {
  const scene = new Scene({ background: [0.85, 0.92, 1], ambient: 0.2 });
  const spheres = [
    ['pink', [0, 0, -20], 4, [1, 0.32, 0.36]], ['blue', [7, 1, -30], 3, [0.45, 0.6, 0.95]],
    ['ground', [0, -10004, -20], 10000, [0.55, 0.55, 0.55]],
  ];
  for (const [name, center, radius, color] of spheres) scene.add(Object.assign(new Sphere(center, radius, { color }), { name }));
  return scene.add(new PointLight([-10, 20, 8]));
}

describe('labelPlacer', () => {
  // on the stand-in, a character is 0.56 em wide
  const placer = (options) => labelPlacer(recordingSketch().p, { x: 0, y: 0, w: 400, h: 300 }, options);

  it('takes the first free place, and never one on a label put before', () => {
    const labels = placer();
    const first = labels.put('first', [[100, 100], [100, 200]]);
    expect(first).toMatchObject({ y: 100 - 8.75 });
    const second = labels.put('second', [[100, 100], [100, 150], [100, 200]]);
    expect(second).toMatchObject({ y: 150 - 8.75 });
    expect(overlap(first, second)).toBe(false);
  });

  it('puts a label of rows as one block, its rows one under the other', () => {
    const { p, texts } = recordingSketch();
    const labels = labelPlacer(p, { x: 0, y: 0, w: 400, h: 300 });
    const box = labels.put([['image plane, 48 px', {}], ['row 15', { bold: true }]], [[100, 50, 'left', 'top']], { size: 13 });
    expect(box).toMatchObject({ x: 97, y: 50, h: 2 * 13 * 1.25 });
    expect(texts.map((t) => t.text)).toEqual(['image plane, 48 px', 'row 15']);
    expect(texts[1].y - texts[0].y).toBeCloseTo(13 * 1.25);
  });

  it('goes further down its list to keep off a thick line, but not for a thin one', () => {
    const labels = placer();
    labels.keepClearLine(0, 100, 400, 100, ON_THICK);
    labels.keepClearLine(0, 200, 400, 200, 1);
    expect(labels.put('ray', [[100, 100], [100, 200], [100, 250]])).toMatchObject({ y: 200 - 8.75 });
  });

  it('never leaves the area while a place inside is there, and leaves out an optional label with no free place', () => {
    const labels = placer();
    expect(labels.put('edge', [[399, 100, 'left'], [390, 100, 'right']])).toMatchObject({ x: 390 + 3 - (4 * 14 * 0.56 + 6) });
    labels.keepClear(0, 0, 400, 300);
    expect(labels.put('crowded', [[100, 100], [200, 200]], {}, { optional: true })).toBeNull();
  });

  it('keeps `spacing` px between labels side by side, so they never read as one', () => {
    const labels = placer({ spacing: 8 });
    const a = labels.put('ground', [[100, 100, 'left']]);
    const b = labels.put('plane', [[a.x + a.w + 2, 100, 'left'], [a.x + a.w + 12, 100, 'left']]); // a box starts 3 px left of its anchor
    expect(b.x - (a.x + a.w)).toBeGreaterThanOrEqual(8);
  });
});

describe('side and top views: labels', () => {
  it('the class scene, every 4th pixel, in the diagram tests\' 440 × 330 box: no label on another or out of the view', () => {
    const camera = new Camera({ width: 64, height: 48, fov: 30 });
    expect(sweep(classScene(), camera, { x: 0, y: 0, w: 440, h: 330 }, 4)).toEqual([]);
  });

  it('the class scene from inside the pink sphere, and before any click', () => {
    const scene = classScene();
    const inside = new Camera({ width: 64, height: 48, fov: 30, position: [0, 0, -17], yaw: 60 });
    expect(sweep(scene, inside, { x: 0, y: 0, w: 440, h: 330 }, 8)).toEqual([]);
    for (const draw of [drawSideView, drawTopView]) expect(labelFaults(draw, { scene, camera: inside, record: null, x: 0, y: 0, w: 440, h: 330 })).toEqual([]);
  });

  it('sketch 01\'s scene, every 2nd pixel, in its 600 × 315 boxes: no label on another or out of the view', () => {
    const camera = new Camera({ width: 32, height: 24, fov: 30 });
    expect(sweep(sketch01Scene(), camera, { x: 0, y: 325, w: 600, h: 315 }, 2)).toEqual([]);
  });
});
