/**
 * 01 · Rays through pixels (slide "Background: Ray Tracing", Appel 1968).
 *
 * One ray leaves the eye through the centre of each pixel of the screen; the
 * first thing it hits gives the pixel its colour. The picture is traced the
 * way Appel described it: scanline by scanline, left to right, top to bottom.
 * Point at (or click) a pixel to see its ray in the side view (its row, its
 * vertical angle V) and the top view (its column, its horizontal angle H).
 * Tick "slow motion" to watch one ray at a time, or Shoot in the 3D view to
 * watch each ray fly from the eye through its pixel to what it hits.
 */
import p5 from 'p5';
import { Camera, Scene, Sphere, PointLight } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …

// Try other numbers: the screen's size in pixels, how wide the eye sees, the spheres.
const WIDTH = 32;
const HEIGHT = 24;
const FOV = 30; // vertical field of view, degrees
const SPHERES = [
  { name: 'pink', center: [0, 0, -20], radius: 4, color: [1, 0.32, 0.36] },
  { name: 'blue', center: [7, 1, -30], radius: 3, color: [0.45, 0.6, 0.95] },
  { name: 'ground', center: [0, -10004, -20], radius: 10000, color: [0.55, 0.55, 0.55] },
];
const LIGHT = [-10, 20, 8];
const SLOW_RAYS_PER_FRAME = 2;

function makeScene() {
  const scene = new Scene({ background: [0.85, 0.92, 1], ambient: 0.2 });
  for (const s of SPHERES) scene.add(new Sphere(s.center, s.radius, { color: s.color, name: s.name }));
  return scene.add(new PointLight(LIGHT));
}

new p5((p) => {
  let view, hovered = null, shown = '';

  p.setup = () => {
    p.createCanvas(600, 640).parent('diagram');
    p.pixelDensity(1);
    const eye = new Camera({ width: WIDTH, height: HEIGHT, fov: FOV });
    view = p.createTracerView({ scene: makeScene(), camera: eye, parent: 'picture', scale: 16, grid: true, order: 'scanline', label: `The screen: ${WIDTH} × ${HEIGHT} pixels` });
    view.slowRaysPerStep = SLOW_RAYS_PER_FRAME; // slow motion: rays traced per frame
    p.createInspector({ view, parent: 'picture' });
    p.createSceneView({ view, parent: 'diagram', width: 600, height: 420, label: 'The same rays in 3D: drag to turn, h / v for a whole row / column' });

    const slow = p.createCheckbox(' Slow motion: one ray at a time', false);
    const again = p.createButton('Trace again');
    again.class('rt-button');
    const controls = p.createDiv().class('controls').parent('picture');
    slow.parent(controls); again.parent(controls);
    view.figure.after(controls.elt);
    slow.changed(() => view.setOrder(slow.checked() ? 'slow' : 'scanline'));
    again.elt.addEventListener('click', () => view.restart()); // a click, Enter or Space (p5's mousePressed is the mouse only)

    // Pointing at a pixel shows its ray; leaving the picture shows the selected one again.
    view.canvas.addEventListener('pointermove', (e) => { hovered = view.pixelAt(e.clientX, e.clientY); });
    view.canvas.addEventListener('pointerleave', () => { hovered = null; });
    p.createTaskList({ page: '01', view }); // the page's tasks, ticked off as they are done
  };

  p.draw = () => {
    // Which ray to draw: the one being traced (slow motion), else the pixel pointed at, else the selected one.
    const tracing = view.order === 'slow' && !view.done ? view.current : null;
    const pixel = tracing ?? hovered ?? view.selected;
    const shownKey = pixel ? `${pixel.x},${pixel.y}` : 'none';
    if (shownKey === shown) return; // nothing new to draw
    shown = shownKey;
    const record = pixel ? view.recordAt(pixel.x, pixel.y) : null; // the selected pixel's record is the view's own, shared with the inspector
    p.background('#f6f7f9');
    p.drawSideView({ scene: view.scene, camera: view.camera, record, x: 0, y: 0, w: 600, h: 315 });
    p.drawTopView({ scene: view.scene, camera: view.camera, record, x: 0, y: 325, w: 600, h: 315 });
  };
}, document.getElementById('sketch'));
