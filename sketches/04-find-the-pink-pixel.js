/**
 * 04 · Find the pink pixel (slide "Activity": what pixel, horizontal angle
 * and vertical angle render a PINK pixel? Pixel: #,#; H: #; V: #).
 *
 * Type a pixel and the camera's H (turn right) and V (look up), press Check:
 * the pixel's ray is traced and the page says whether it is pink, and if not,
 * what colour it is and what the ray hit. The answer line gives the RAY's own
 * H and V for that pixel — the camera's angles plus the pixel's offset from
 * the middle of the picture — as the inspector shows them. Tick the box to
 * see every pink pixel at once: each one is a right answer.
 */
import p5 from 'p5';
import { Camera, classScene, inspectPixel, colorName, toHex } from '../lib/index.js';
import { createTracerView, createInspector, answerLine } from '../lib/p5/index.js';
import { valueBox } from '../lib/p5/scene-form.js';
import { element } from '../lib/p5/dom.js';

// The screen and where the camera starts: change them and find pink again.
const WIDTH = 32;
const HEIGHT = 24;
const FOV = 30; // vertical field of view, degrees
const START = { x: 10, y: 12, h: 0, v: 0 };

const cameraFor = (h, v) => new Camera({ width: WIDTH, height: HEIGHT, fov: FOV, yaw: h, pitch: v });

new p5((p) => {
  let view, boxes, result, answer, showPink, pinkCount, pink = null;

  p.setup = () => {
    view = createTracerView(p, { scene: classScene(), camera: cameraFor(START.h, START.v), parent: 'picture', grid: true, label: `The class scene: ${WIDTH} × ${HEIGHT} pixels` });
    // This sketch's canvas lies over the picture and marks the pink pixels; the traced canvas stays as traced.
    p.createCanvas(WIDTH, HEIGHT).parent(view.canvas.parentElement).class('pink-marks').attribute('data-pink-marks', '').attribute('data-overlay', '');
    p.pixelDensity(1);

    boxes = {
      x: valueBox({ label: 'Pixel x', name: 'x', value: START.x, rule: { min: 0, max: WIDTH - 1, integer: true } }),
      y: valueBox({ label: 'Pixel y', name: 'y', value: START.y, rule: { min: 0, max: HEIGHT - 1, integer: true } }),
      h: valueBox({ label: 'Camera H', name: 'h', value: START.h, rule: { min: -180, max: 180 } }),
      v: valueBox({ label: 'Camera V', name: 'v', value: START.v, rule: { min: -90, max: 90 } }),
    };
    const checkButton = element('button', { type: 'submit', class: 'rt-button', 'data-check': '' }, 'Check');
    const form = element('form', { class: 'boxes', novalidate: '' }, ...Object.values(boxes).map((b) => b.element), checkButton);
    form.addEventListener('submit', (event) => { event.preventDefault(); check(); });
    for (const b of [boxes.h, boxes.v]) b.input.addEventListener('change', turnCamera);

    result = element('p', { class: 'result', 'data-result': '', role: 'status' });
    answer = element('code', { class: 'answer', 'data-answer-line': '' });
    const copyButton = element('button', { type: 'button', class: 'rt-button' }, 'Copy answer');
    copyButton.addEventListener('click', () => navigator.clipboard?.writeText(answer.textContent).catch(() => {}));
    const note = element('p', { class: 'note' }, 'Camera H turns the camera right (negative: left) and camera V tilts it up (negative: down), in degrees: they say where the MIDDLE of the picture points. Each pixel\'s ray points a little to the side of that, so the H and V in your answer are the ray\'s own angles for that pixel (the camera\'s angles plus the pixel\'s offset) — the numbers the inspector shows when you click the pixel. The eye stays put, so a ray\'s H and V alone say where it goes.');
    showPink = element('input', { type: 'checkbox', 'data-show-pink': '' });
    pinkCount = element('span', { 'data-pink-count': '' });
    const toggle = element('div', { class: 'controls' }, element('label', {}, showPink, 'Highlight every pink pixel (the reverse question)'), pinkCount);
    document.getElementById('activity').append(element('section', { class: 'task' },
      element('h2', {}, 'Your answer'), form, result, element('div', { class: 'answer-row' }, answer, copyButton), note));
    view.figure.after(toggle);

    createInspector({ view, parent: 'activity' });
    view.onSelect((s) => s && explain(s)); // clicks, arrow keys and Check all end here
    check();
  };

  // Reads the four boxes; a bad one keeps its message and the picture stays as it was.
  function check() {
    const [x, y, h, v] = [boxes.x, boxes.y, boxes.h, boxes.v].map((b) => b.read());
    if ([x, y, h, v].includes(undefined)) {
      result.replaceChildren('Fix the box marked in red, then Check again.');
      result.dataset.result = 'error';
      return;
    }
    if (h !== view.camera.yaw || v !== view.camera.pitch) view.setCamera(cameraFor(h, v));
    pink = null;
    view.select(x, y);
  }

  function turnCamera() {
    const h = boxes.h.read(), v = boxes.v.read();
    if (h === undefined || v === undefined || (h === view.camera.yaw && v === view.camera.pitch)) return;
    pink = null;
    view.setCamera(cameraFor(h, v)); // the selected pixel is explained again through the new camera
  }

  // Is this pixel pink? If not: its colour, and what its ray hit.
  function explain({ x, y }) {
    boxes.x.input.value = x; boxes.y.input.value = y;
    boxes.x.clear(); boxes.y.clear();
    const record = inspectPixel(view.scene, view.camera, x, y);
    const name = colorName(record.color);
    const swatch = element('span', { class: 'rt-swatch', style: `background: ${toHex(record.color)}` });
    const object = record.hit?.object.name;
    const why = name === 'pink' ? `Pink! Pixel ${x},${y} shows the pink sphere.`
      : object === 'pink' ? `That pixel is ${name}: it is on the pink sphere, but too dark there to look pink.`
        : `That pixel is ${name}: ${object ? whatIs(object) : 'the ray hits nothing, so it gets the background'}.`;
    result.replaceChildren(swatch, (name === 'pink' ? '✔ ' : '✘ ') + why);
    result.dataset.result = name === 'pink' ? 'pink' : 'not-pink';
    result.dataset.colorName = name;
    answer.textContent = answerLine(record);
  }

  const whatIs = (name) => (name === 'ground' ? 'the ground' : name.startsWith('light') ? `${name}, a light` : `the ${name} sphere`);

  // Every pixel the renderer made pink, read from the finished picture.
  function findPink() {
    const rgba = view.renderer.buffer, found = [];
    for (let y = 0; y < HEIGHT; y++) {
      for (let x = 0; x < WIDTH; x++) {
        const i = 4 * (y * WIDTH + x);
        if (colorName([rgba[i], rgba[i + 1], rgba[i + 2]]) === 'pink') found.push({ x, y });
      }
    }
    pinkCount.textContent = `${found.length} of ${WIDTH * HEIGHT} pixels are pink: each one is a right answer for this camera.`;
    pinkCount.dataset.pinkCount = String(found.length);
    return found;
  }

  p.draw = () => {
    const k = view.scale; // screen pixels per traced pixel: the marks canvas covers the picture exactly
    if (p.width !== WIDTH * k || p.height !== HEIGHT * k) p.resizeCanvas(WIDTH * k, HEIGHT * k);
    p.clear();
    if (!showPink.checked) { pink = null; pinkCount.textContent = ''; return; }
    if (!view.done) return;
    pink ??= findPink();
    p.stroke(0);
    p.strokeWeight(2);
    p.fill(255);
    for (const { x, y } of pink) p.circle((x + 0.5) * k, (y + 0.5) * k, k * 0.4);
  };
}, document.getElementById('sketch'));
