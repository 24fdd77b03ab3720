/**
 * 13 · Meshes and a BVH: the Stanford bunny (npm package bunny, 3,674 triangles).
 *
 * A loop over every triangle tests 3,674 of them for each ray. The bounding
 * volume hierarchy (lib/shapes/bvh.js) tests the ray against a box first: a miss skips
 * every triangle inside. mesh.walk(ray) says which boxes the ray entered, how
 * many box and triangle tests it made and which triangle it hit.
 * The picture is traced on Web Workers (the mesh goes to them as scene JSON).
 */
import p5 from 'p5';
// The npm package bunny is one CommonJS file, exports.positions=[…]; exports.cells=[…]: read as
// text, its two arrays are JSON (no bundling step between the package and the page).
import bunnyFile from 'bunny/index.js?raw';
import { Scene, Plane, Mesh, PointLight, Camera } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …

const WIDTH = 384, HEIGHT = 288; // 110,592 pixels: enough for the render workers

/** The bunny's { positions, cells } from its package's file. */
function readBunny(text) {
  const [, positions, cells] = /exports\.positions\s*=\s*(\[[^;]*\])\s*;?\s*exports\.cells\s*=\s*(\[[^;]*\])/.exec(text);
  return { positions: JSON.parse(positions), cells: JSON.parse(cells) };
}

new p5((p) => {
  p.setup = () => {
    p.noCanvas(); // the tracer view brings its own canvas
    const mesh = new Mesh(readBunny(bunnyFile), { color: [0.92, 0.84, 0.72], name: 'bunny' });
    const scene = new Scene({ background: [0.85, 0.92, 1], ambient: 0.15 })
      .add(new Plane([0, 0, 0], [0, 1, 0], { color: [0.6, 0.65, 0.7], name: 'floor' }))
      .add(mesh)
      .add(new PointLight([-12, 24, 20]));
    const eye = new Camera({ width: WIDTH, height: HEIGHT, fov: 30, position: [0, 6, 26], pitch: -6 });
    const view = p.createTracerView({ scene, camera: eye });
    p.createInspector({ view });
    p.createBvhView({ view, mesh, parent: 'sketch' });
    view.select(200, 150); // on the bunny's side
    p.createTaskList({ page: '13', view }); // the page's tasks, ticked off as they are done
  };
}, 'sketch');
