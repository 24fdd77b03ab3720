/**
 * 04 · Find the pink pixel (slide "Activity": what pixel, horizontal angle
 * and vertical angle render a PINK pixel? Pixel: #,#; H: #; V: #).
 *
 * Type a pixel and the camera's H (turn right) and V (look up), press Check:
 * the pixel's ray is traced and the page says whether it is pink, and if not,
 * what colour it is and what the ray hit. The answer line repeats what was
 * typed, in the slide's format; pasting such a line fills all four boxes.
 * Tick the box to see every pink pixel at once: each one is a right answer.
 */
import p5 from 'p5';
import { Camera, classScene, inspectPixel, colorName, toHex, pinkPixelVerdict, answerText, readAnswerLine } from '../lib/index.js';
import { formatAngle } from '../lib/p5/index.js'; // and the sketchbook's p5 addon: p.createTracerView, …

// The screen and where the camera starts: change them and find pink again.
const WIDTH = 32;
const HEIGHT = 24;
const FOV = 30; // vertical field of view, degrees
const START = { h: 0, v: 0 }; // the pixel boxes start empty: the first answer is the student's

const cameraFor = (h, v) => new Camera({ width: WIDTH, height: HEIGHT, fov: FOV, yaw: h, pitch: v });

new p5((p) => {
  let view, form, pinkOnes;

  p.setup = () => {
    view = p.createTracerView({ scene: classScene(), camera: cameraFor(START.h, START.v), parent: 'picture', grid: true, label: `The class scene: ${WIDTH} × ${HEIGHT} pixels` });
    // The reverse question: every pink pixel, marked on this sketch's canvas laid over the picture.
    pinkOnes = p.createPixelHighlight({
      view,
      name: 'pink',
      label: 'Highlight every pink pixel (the reverse question)',
      test: (rgb) => colorName(rgb) === 'pink',
      describe: (count, total) => `${count} of ${total} pixels are pink: each one is a right answer for this camera.`,
    });

    form = p.createAnswerForm({
      parent: 'activity',
      boxes: {
        x: { label: 'Pixel x', rule: { min: 0, max: WIDTH - 1, integer: true } },
        y: { label: 'Pixel y', rule: { min: 0, max: HEIGHT - 1, integer: true } },
        h: { label: 'Camera H', value: START.h, rule: { min: -180, max: 180 } },
        v: { label: 'Camera V', value: START.v, rule: { min: -90, max: 90 } },
      },
      onCheck: check,
      parse: readAnswerLine, // paste a whole answer line into any box
      note: document.getElementById('h-and-v'), // the page's picture of H and V
    });
    for (const b of [form.boxes.h, form.boxes.v]) b.input.addEventListener('change', turnCamera);

    p.createInspector({ view, parent: 'activity', title: 'The selected pixel\'s ray, with its own H and V' });
    // A click or an arrow key picks a new pixel: it goes into the boxes and is checked.
    // A new camera re-announces the same pixel: the boxes keep what was typed.
    view.onSelect((s) => {
      if (!s || (judged && s.x === judged.x && s.y === judged.y)) return;
      form.fill({ x: s.x, y: s.y });
      check();
    });
    p.createTaskList({ page: '04', view }); // the page's tasks, ticked off as they are done
  };

  p.draw = () => pinkOnes.draw();

  let judged = null; // the pixel of the last answer checked

  // Reads the four boxes; a bad one keeps its message and the picture stays as it was.
  function check() {
    const values = form.read();
    if (!values) return;
    judged = values;
    view.select(values.x, values.y); // before the camera turns, so that the view announces the pixel typed
    if (values.h !== view.camera.yaw || values.v !== view.camera.pitch) view.setCamera(cameraFor(values.h, values.v));
    explain(values);
  }

  // Leaving the H or V box turns the camera at once, to look around; only Check judges.
  function turnCamera() {
    const h = form.boxes.h.read(), v = form.boxes.v.read();
    if (h === undefined || v === undefined || (h === view.camera.yaw && v === view.camera.pitch)) return;
    view.setCamera(cameraFor(h, v));
  }

  // Is this pixel pink? If not: its colour, and what its ray hit.
  function explain(answer) {
    const record = inspectPixel(view.scene, view.camera, answer.x, answer.y);
    const { pink, colorName: name, message } = pinkPixelVerdict(record);
    form.show({
      ok: pink, message, color: toHex(record.color), data: { result: pink ? 'pink' : 'not-pink', colorName: name },
      answer: answerText(answer), // what the student gave, in the slide's format
      // Served by npm run class, a Check sends this to the teacher's board, which judges it again.
      send: { line: answerText(answer), width: WIDTH, height: HEIGHT, fov: FOV, verdict: pink ? 'right' : 'wrong', color: toHex(record.color) },
      detail: `The ray through that pixel: H ${formatAngle(record.h)}, V ${formatAngle(record.v)} (the camera's angles plus the pixel's offset from the middle).`,
    });
  }
}, document.getElementById('sketch'));
