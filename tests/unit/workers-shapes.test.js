// Cylinders, cones, triangles and meshes travel to the workers as scene JSON
// and are packed there for render()'s kernel: the workers' picture is
// render()'s, byte for byte, shared frame or rows transferred.
import { describe, it, expect } from 'vitest';
import { ParallelRenderer } from '../../lib/tracing/workers/parallel.js';
import { sceneToJSON, sceneFromJSON } from '../../lib/scene/json.js';
import { prepareFrame } from '../../lib/tracing/render.js';
import { fakeWorkers } from './fake-workers.js';
import { render, Camera, Scene, Plane, Sphere, Cylinder, Cone, Triangle, Mesh, PointLight } from '../../lib/index.js';

/** A mirror floor, a can, an open pipe, a glass cone, a sail and a tetrahedron mesh, lit from above. */
function shapesScene() {
  return new Scene({ background: [0.3, 0.4, 0.6], ambient: 0.05, maxDepth: 3 })
    .add(new Plane([0, -2, 0], [0, 1, 0], { color: [0.7, 0.7, 0.7], reflection: 0.3 }))
    .add(new Cylinder([-3, -1, -12], 1, 2, { color: 'orange', specular: 0.4 }))
    .add(new Cylinder([3.5, -0.5, -13], 0.8, 3, { color: 'teal', capped: false }))
    .add(new Cone([0, -0.5, -10], 1.2, 3, { color: 'pink', transparency: 0.6, ior: 1.4 }))
    .add(new Triangle([-5, -2, -16], [5, -2, -16], [0, 4, -17], { color: 'white', reflection: 0.5 }))
    .add(new Mesh({ positions: [[1, -2, -8], [2.5, -2, -8], [1.5, 0, -8.5], [1.6, -2, -6.8]], cells: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] }, { color: 'gold' }))
    .add(new Sphere([-1.5, 1.5, -14], 1, { color: 'silver', reflection: 0.8 }))
    .add(new PointLight([4, 6, -2], [1, 1, 1], 1.1));
}

describe('workers and the course\'s other shapes', () => {
  it('the scene is packed for the kernel on either side of the JSON', () => {
    const camera = new Camera({ width: 16, height: 16 });
    expect(prepareFrame(shapesScene(), camera).packed).not.toBeNull();
    expect(prepareFrame(sceneFromJSON(sceneToJSON(shapesScene())), camera).packed).not.toBeNull();
  });

  for (const shared of [false, true]) {
    for (const workers of [1, 3]) {
      it(`${workers} worker(s), ${shared ? 'one shared frame' : 'rows transferred'}: render()'s picture, byte for byte`, async () => {
        const fake = fakeWorkers();
        const parallel = new ParallelRenderer({ workers, rowsPerBand: 3, shared, createWorker: fake.create });
        const scene = shapesScene(), camera = new Camera({ width: 41, height: 29, fov: 50 });
        const buffer = await parallel.render(scene, camera);
        const expected = render(scene, camera);
        expect(buffer).toEqual(expected);
        expect(new Set(expected.filter((_, i) => i % 4 === 0)).size).toBeGreaterThan(20); // a picture, not a flat background
        expect(parallel.problem).toBe(null);
        parallel.terminate();
      });
    }
  }
});
