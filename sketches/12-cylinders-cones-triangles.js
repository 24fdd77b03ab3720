/**
 * 12 · Cylinders, cones and triangles: the quadratic again, with new A, B, C.
 *
 * Cylinder (axis along y through its centre): (Xo + Xd·t − Xc)² + (Zo + Zd·t − Zc)² = r²,
 *   A = Xd² + Zd², B = 2[(Xo − Xc)Xd + (Zo − Zc)Zd], C = (Xo − Xc)² + (Zo − Zc)² − r²,
 *   then only the roots within its height count, and its caps are two discs.
 * Cone: the radius shrinks from r at the bottom to 0 at the tip, so y comes back in.
 * Triangle: Möller–Trumbore, e1 = B − A, e2 = C − A, P = Rd × e2, det = e1·P (0: parallel).
 * Click a pixel: the inspector shows each shape's own record for its ray.
 */
import p5 from 'p5';
import { Scene, Plane, Cylinder, Cone, Triangle, PointLight, Camera } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …

const WIDTH = 64, HEIGHT = 48;

function makeScene() {
  const scene = new Scene({ background: [0.85, 0.92, 1], ambient: 0.12 });
  scene.add(new Plane([0, -4, 0], [0, 1, 0], { color: [0.75, 0.75, 0.75], name: 'floor' }));
  scene.add(new Cylinder([-6, -1, -24], 2.5, 6, { color: [1, 0.32, 0.36], name: 'pink cylinder' })); // center, radius, height
  scene.add(new Cone([1, -1, -26], 3, 6, { color: [1, 0.8, 0.2], name: 'yellow cone' }));
  scene.add(new Triangle([5, -4, -22], [10, -4, -24], [7.5, 3, -23], { color: [0.3, 0.75, 0.4], name: 'green triangle' }));
  scene.add(new PointLight([-10, 20, 0]));
  return scene;
}

new p5((p) => {
  p.setup = () => {
    p.noCanvas(); // the tracer view brings its own canvas
    const eye = new Camera({ width: WIDTH, height: HEIGHT, fov: 35, position: [0, 2, 0], pitch: -8 });
    const view = p.createTracerView({ scene: makeScene(), camera: eye, grid: true });
    p.createInspector({ view });
    view.select(8, 20); // on the cylinder, in its light
    p.createTaskList({ page: '12', view }); // the page's tasks, ticked off as they are done
  };
}, 'sketch');
