/**
 * 16 · Light that bounces: path tracing.
 *
 * Whitted's tracer (left) lights a point only from the lights it can see:
 * the lamp in the ceiling. Real light bounces off everything: the red wall
 * tints the floor beside it, the ceiling is lit by the floor. A path tracer
 * (right) follows a ray from the eye through a random point of the pixel,
 * and at each surface lets it bounce in a random direction (a cosine-weighted
 * one off paint, the mirror direction off the ball), multiplying its
 * throughput by the surface's colour, until it reaches the lamp, leaves the
 * box, or Russian roulette ends it. A pixel is the average of many such
 * paths: the picture starts noisy and settles, its noise falling as 1/√N.
 * "1 bounce" keeps only paths that reached the lamp straight from their first
 * surface: direct light, where the colour bleeding disappears.
 * "Light sampling" (on at first) also aims a shadow ray at the lamp from every
 * bounce, weighed against the bounce's own chance of finding it: the same
 * picture on average; the noise, measured under the buttons, falls.
 * Switch it off and compare the number at the same sample.
 * Click a pixel: the panel lists one of its paths, bounce by bounce, and the
 * 3D view draws it.
 */
import p5 from 'p5';
import { Scene, Plane, Box, Sphere, Camera } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createPathPanel, …

const SIZE = 64, SAMPLES = 128, MANY = 16;
const WHITE = [0.73, 0.73, 0.73], RED = [0.65, 0.05, 0.05], GREEN = [0.12, 0.45, 0.15];

/**
 * The Cornell box, closed behind the eye: white floor, ceiling, back and front, a red wall left,
 * a green one right, a lamp under the ceiling, a tall block and a mirror ball. `lamp` is the
 * lamp's emission: Whitted's tracer takes it as a point light's colour at the lamp's middle
 * (1: white), the path tracer as light given off by each point of its face (8: bright enough
 * to light a room by bounces).
 */
function cornellBox(lamp) {
  const scene = new Scene({ background: [0, 0, 0], ambient: 0.05 });
  scene.add(new Plane([0, 0, 0], [0, 1, 0], { color: WHITE, name: 'floor' }));
  scene.add(new Plane([0, 10, 0], [0, -1, 0], { color: WHITE, name: 'ceiling' }));
  scene.add(new Plane([0, 0, -20], [0, 0, 1], { color: WHITE, name: 'back wall' }));
  scene.add(new Plane([0, 0, 5], [0, 0, -1], { color: WHITE, name: 'front wall' })); // behind the eye
  scene.add(new Plane([-5, 0, 0], [1, 0, 0], { color: RED, name: 'red wall' }));
  scene.add(new Plane([5, 0, 0], [-1, 0, 0], { color: GREEN, name: 'green wall' }));
  scene.add(new Box([-2.5, 9.8, -17], [2.5, 9.99, -12], { color: [0, 0, 0], emission: [lamp, lamp, 0.9 * lamp], name: 'lamp' }));
  scene.add(new Box([-3.6, 0, -18], [-0.8, 6, -15], { color: WHITE, name: 'tall block' }));
  scene.add(new Sphere([2.2, 1.8, -13], 1.8, { color: [0.9, 0.9, 0.9], reflection: 1, fuzz: 0.05, name: 'mirror ball' }));
  return scene;
}

new p5((p) => {
  p.setup = () => {
    p.noCanvas(); // the tracer views bring their own canvases
    const camera = new Camera({ width: SIZE, height: SIZE, fov: 40, position: [0, 5, 3.7] });
    const whitted = p.createTracerView({ scene: cornellBox(1), camera, parent: 'views', label: 'Whitted: light straight from the lamp' });
    const paths = p.createTracerView({ scene: cornellBox(8), camera, parent: 'views', label: 'Path tracing: light that bounces', path: { samples: SAMPLES, maxBounces: MANY } });
    for (const view of [whitted, paths]) view.onSelect((s) => { // one selected pixel for both pictures
      for (const other of [whitted, paths]) if (other.selected?.x !== s?.x || other.selected?.y !== s?.y) other.select(s ? s.x : null, s?.y);
    });
    for (const input of document.querySelectorAll('#bounces input')) {
      input.addEventListener('change', () => paths.setPath({ maxBounces: Number(input.value) }));
    }
    const lightSampling = document.getElementById('light-sampling'), noise = document.getElementById('noise');
    lightSampling.addEventListener('click', () => { // a toggle: pressed is on
      const on = lightSampling.getAttribute('aria-pressed') !== 'true';
      lightSampling.setAttribute('aria-pressed', String(on));
      paths.setPath({ lightSampling: on });
    });
    paths.on('restart', () => { noise.textContent = 'Noise left: measured from the second sample on.'; delete noise.dataset.value; });
    paths.on('progress', () => { // the noise left: each pixel's standard error, averaged over the picture
      const { sample, noise: left, options } = paths.pathState;
      if (left === null) return;
      noise.textContent = `Noise left: ${left.toFixed(4)} after ${sample} samples (light sampling ${options.lightSampling === false ? 'off' : 'on'})`;
      noise.dataset.value = String(left);
    });
    const sceneView = p.createSceneView({ view: paths, parent: 'sketch', orbit: { yaw: 10, pitch: 25, distance: 6 }, planeDistance: 1, // inside the room, behind the eye
      label: 'In 3D: the path, each segment coloured by the throughput it carries' });
    const panel = p.createPathPanel({ view: paths, parent: 'sketch', sceneView });
    p.createInspector({ view: whitted, parent: 'sketch' });
    p.createTaskList({ page: '16', view: whitted, parts: { paths, pathPanel: panel } }); // the page's tasks, ticked off as they are done
    whitted.select(12, 58); // the floor by the red wall: redder in the path-traced picture
  };
}, document.getElementById('sketch'));
