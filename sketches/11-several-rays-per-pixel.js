/**
 * 11 · Several rays per pixel (anti-aliasing by supersampling).
 *
 * A camera with `samples: 4` traces 4 rays through each pixel, one through
 * the centre of each cell of a 2 × 2 grid, and averages their colours (9 is
 * 3 × 3, 16 is 4 × 4). The grid is fixed, not random: the picture is the same
 * every time. Left: one ray per pixel, jagged. Right: the rays you choose.
 * Both pictures share the selected pixel; the panel shows that pixel's rays.
 */
import p5 from 'p5';
import { Camera, classScene } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …

const WIDTH = 64, HEIGHT = 48, SCALE = 6;
const CHOICES = [1, 4, 9, 16];
const START = 4;

const camera = (samples) => new Camera({ width: WIDTH, height: HEIGHT, samples });

new p5((p) => {
  p.setup = () => {
    p.noCanvas(); // the tracer views bring their own canvases
    const scene = classScene();
    const jagged = p.createTracerView({ scene, camera: camera(1), scale: SCALE, parent: 'views', label: 'One ray per pixel' });
    const smooth = p.createTracerView({ scene, camera: camera(START), scale: SCALE, parent: 'views', label: `${START} rays per pixel` });
    const views = [jagged, smooth];
    for (const view of views) view.onSelect((s) => { // one selected pixel for both pictures
      for (const other of views) if (other.selected?.x !== s?.x || other.selected?.y !== s?.y) other.select(s ? s.x : null, s?.y);
    });
    addChoices(smooth);
    p.createSampleRays({ view: smooth, parent: 'sketch' });
    p.createInspector({ view: smooth, parent: 'sketch' });
    smooth.select(24, 7); // on the pink sphere's top edge: two rays hit it, two miss
    p.createTaskList({ page: '11', view: smooth }); // the page's tasks, ticked off as they are done
  };

  /** The radio buttons 1, 4, 9, 16: the right-hand picture is traced again with that many rays. */
  function addChoices(view) {
    const box = document.getElementById('samples');
    for (const n of CHOICES) {
      const input = Object.assign(document.createElement('input'), { type: 'radio', name: 'samples', value: String(n), checked: n === START });
      input.addEventListener('change', () => {
        view.setCamera(camera(n));
        view.figure.querySelector('figcaption.rt-label')?.replaceChildren(`${n} ray${n === 1 ? '' : 's'} per pixel`);
      });
      const label = document.createElement('label');
      label.append(input, ` ${n}`);
      box.append(label);
    }
  }
}, document.getElementById('sketch'));
