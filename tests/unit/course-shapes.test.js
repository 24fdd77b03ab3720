// The course's shapes (Cylinder, Cone, Triangle, Mesh) through the whole kit, by the shape
// protocol alone: added to a scene, rendered, inspected, culled, written as JSON and as
// code and read back, checked again on a restart.
import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, PointLight, Camera, Cylinder, Cone, Triangle, Mesh, render, inspectPixel, sceneToJSON, sceneFromJSON, sceneToCode, ProgressiveRenderer } from '../../lib/index.js';
import * as lib from '../../lib/index.js';

const tetra = { positions: [[-2, -2, -22], [2, -2, -22], [0, -2, -18], [0, 2, -20]], cells: [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]] };
const SHAPES = {
  cylinder: () => new Cylinder([0, 0, -20], 2, 4, { color: 'pink', name: 'can' }),
  'open cone': () => new Cone([0, 0, -20], 2, 4, { color: 'yellow', capped: false }),
  triangle: () => new Triangle([-3, -2, -20], [3, -2, -20], [0, 3, -20], { color: 'green' }),
  mesh: () => new Mesh(tetra, { color: [0.6, 0.7, 0.9], reflection: 0.2 }),
};
const camera = new Camera({ width: 32, height: 24 });
const sceneWith = (shape) => new Scene({ background: [0.9, 0.95, 1] })
  .add(new Plane([0, -5, 0], [0, 1, 0], { color: [0.5, 0.5, 0.5] })).add(new Sphere([5, 0, -25], 2)).add(shape).add(new PointLight([-10, 20, 0]));
const middle = (rgba) => [...rgba.slice((12 * 32 + 16) * 4, (12 * 32 + 16) * 4 + 3)];

for (const [what, make] of Object.entries(SHAPES)) {
  describe(`a ${what}`, () => {
    it('renders: the middle pixel is the shape, and render() agrees with the inspector', () => {
      const scene = sceneWith(make()), picture = render(scene, camera);
      const record = inspectPixel(scene, camera, 16, 12);
      expect(record.hit.object).toBe(scene.objects[2]);
      expect(record.color).toEqual(middle(picture));
      const entry = record.records.find((e) => e.object === scene.objects[2]);
      expect(entry.rows.at(-1)[1]).toBeCloseTo(record.hit.t, 9); // its own record's t is the hit's
    });

    it('round-trips through scene JSON and through code, to the same picture', async () => {
      const scene = sceneWith(make()), picture = render(scene, camera);
      const json = sceneToJSON(scene);
      expect(render(sceneFromJSON(JSON.parse(JSON.stringify(json))), camera)).toEqual(picture);
      const code = sceneToCode(scene, { importFrom: 'lib' });
      const body = code.replace(/^import .*$/m, '') + '\nreturn scene;';
      const built = new Function(...Object.keys(lib), body)(...Object.values(lib));
      expect(render(built, camera)).toEqual(picture);
    });

    it('is checked again on a restart: a bad field changed in place is named', () => {
      const scene = sceneWith(make()), p = new ProgressiveRenderer({ scene, camera });
      const shape = scene.objects[2];
      if ('radius' in shape) shape.radius = -1; else if ('a' in shape) shape.a = null; else shape.positions = [[0, 0]];
      expect(() => p.restart()).toThrow(/objects\[2\]/);
    });
  });
}

it('a cone that is open keeps capped: false through JSON and code', () => {
  const scene = sceneWith(SHAPES['open cone']());
  expect(sceneToJSON(scene).objects[2].capped).toBe(false);
  expect(sceneToCode(scene)).toContain('capped: false');
  expect(sceneFromJSON(sceneToJSON(scene)).objects[2].capped).toBe(false);
});
