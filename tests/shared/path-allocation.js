/**
 * Bytes a path that the path tracer allocates, measured in this process and
 * printed as a number: the room of tests/unit/allocation.test.js (a plane, a
 * box, balls, a fuzzy mirror, glass and a lamp), after another scene has run.
 * Run as `node tests/shared/path-allocation.js`: each run is a fresh V8.
 */
import { bytesAllocatedBy } from './heap.js';
import { Camera, classScene, pathTrace, Scene, Sphere, Plane, Box } from '../../lib/index.js';

globalThis.someSketchsPoint = { x: 'left', y: null, z: undefined }; // as a page with p5 2.3 has: { x, y, z } literals with non-numbers
pathTrace(classScene(), new Camera({ width: 32, height: 24 }), { samples: 64 }); // another scene first: the loops' feedback holds several kinds
const scene = new Scene({ background: [0.2, 0.25, 0.35] })
  .add(new Plane([0, -2, 0], [0, 1, 0], { color: [0.75, 0.75, 0.7] }))
  .add(new Box([-4, -2, -14], [-1.5, 1, -11], { color: [0.8, 0.2, 0.2] }))
  .add(new Sphere([1.5, -1, -11], 1, { color: [0.9, 0.9, 0.9], reflection: 1, fuzz: 0.2 }))
  .add(new Sphere([3.5, -1, -12], 1, { transparency: 1, ior: 1.5 }))
  .add(new Sphere([0, 5, -12], 1.5, { color: [0, 0, 0], emission: [4, 4, 3.6] }));
const camera = new Camera({ width: 24, height: 18, fov: 40, position: [0, 1, 0], pitch: -5 });
const samples = 64, paths = samples * camera.width * camera.height;
let least = Infinity;
for (let attempt = 0; attempt < 6 && least >= 4; attempt++) { // stops at the first try under 4
  for (let i = 0; i < 20; i++) pathTrace(scene, camera, { samples: 16 }); // warm up
  least = Math.min(least, bytesAllocatedBy(() => pathTrace(scene, camera, { samples })) / paths);
}
console.log(least);
