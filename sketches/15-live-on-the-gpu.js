/**
 * 15 · Live on the GPU.
 *
 * The class scene with mirrors and glass, traced whole on every animation
 * frame by the graphics card: a WebGL2 fragment shader runs the CPU kernel's
 * steps (nearest hit, the surface, the lights with their shadow rays, the
 * mirror and glass rays) for every pixel at once, reading the same packed
 * scene. Drag the picture to orbit the camera, or use the arrow keys (with no
 * pixel selected; Escape lets a pixel go), + and − to come closer or go back.
 *
 * Click a pixel: the inspector tells its story, computed again on the CPU
 * (float64) by the same formulas; where the GPU's byte (float32) differs from
 * it, the inspector says by how much. Switch to the CPU to compare the speed:
 * "Turn by itself" asks for a new picture as soon as the last one is whole.
 */
import p5 from 'p5';
import { classScene, Camera } from '../lib/index.js';
import { orbit } from '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …

const WIDTH = 160, HEIGHT = 120, SCALE = 4;

new p5((p) => {
  let view, counted = 0, since = 0;
  /** Frames so far: drawn by the GPU, or pictures the CPU finished. */
  const frames = () => view.picturesDone;

  p.setup = () => {
    p.noCanvas(); // the tracer view brings its own canvas
    const camera = new Camera({ width: WIDTH, height: HEIGHT, fov: 40, position: [0, 3, 6], pitch: -8 });
    view = p.createTracerView({ scene: classScene({ full: true }), camera, engine: 'gpu', scale: SCALE, parent: 'views', label: 'The class scene, mirrors and glass' });
    view.orbitDistance = 26; // orbit about the pink glass sphere
    p.createInspector({ view, parent: 'sketch' });
    for (const input of document.querySelectorAll('input[name="engine"]')) {
      input.checked = input.value === view.engine; // the CPU, when the GPU could not be had
      input.addEventListener('change', () => { view.setEngine(input.value); counted = frames(); });
    }
  };

  // "Turn by itself": a new camera as soon as the last picture is whole; frames per second, counted over each half second.
  p.draw = () => {
    if (document.getElementById('turn').checked && view.done) orbit(view, 1, 0, 1);
    const now = p.millis();
    if (now - since < 500) return;
    const fps = ((frames() - counted) * 1000) / (now - since);
    document.getElementById('fps').textContent = `${fps.toFixed(1)} frames per second on the ${view.engine.toUpperCase()}`;
    counted = frames(); since = now;
  };
}, document.getElementById('sketch'));
