/**
 * 10 · Playground: live coding (the whole lesson, one edit at a time).
 *
 * Edit this code in the page's editor and press Run (or stop typing): the
 * picture is traced again.
 * Try a second sphere, another colour, a mirror (reflection: 0.8), glass
 * (transparency: 0.9), a light you can see (a sphere with an emission),
 * or move the camera. Click a pixel to see its ray, A, B, C and the
 * discriminant.
 */
import p5 from 'p5';
import { Scene, Sphere, PointLight, Camera } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …

const WIDTH = 64, HEIGHT = 48; // traced pixels: try 32 × 24 or 160 × 120

function makeScene() {
  const scene = new Scene({ background: [0.85, 0.92, 1], ambient: 0.1 });
  scene.add(new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] })); // center, radius, material
  scene.add(new PointLight([-10, 20, 0]));                            // position
  return scene;
}

new p5((p) => {
  p.setup = () => {
    p.noCanvas(); // the tracer view brings its own canvas
    const eye = new Camera({ width: WIDTH, height: HEIGHT, fov: 30, position: [0, 0, 0] }); // looks toward −z
    const view = p.createTracerView({ scene: makeScene(), camera: eye, grid: true });
    p.createInspector({ view });
    p.createTaskList({ page: '10', view }); // the page's tasks, ticked off as they are done
  };
}, 'sketch');
