import { describe, it, expect } from 'vitest';
import { describeScene, pictureRows, sampleScene } from '../../lib/lesson/describe.js';
import { Scene, Sphere, Plane, Box, PointLight, Camera, classScene, render } from '../../lib/index.js';

const camera = new Camera({ width: 64, height: 48 });

describe('describeScene', () => {
  it('names the class scene\'s spheres by colour and place, the floor, the background and the lights', () => {
    const text = describeScene(classScene(), camera);
    expect(text).toMatch(/^A pink sphere in the middle; /);
    expect(text).toContain('a white sphere on the left');
    expect(text).toContain('a blue sphere on the right, behind the pink sphere');
    expect(text).toContain('a yellow sphere on the right'); // named yellow: one colour name a sphere, the inspector's and the verdict's
    expect(text).toContain('a gray floor, on a white background.');
    expect(text).toMatch(/Two lights\.$/);
    expect(text).not.toContain('out of view'); // the emissive spheres count as lights
  });

  it('follows the camera: turned round, the spheres are out of view', () => {
    const text = describeScene(classScene(), new Camera({ width: 32, height: 24, yaw: 180 }));
    expect(text).toBe('A gray floor, on a white background. Four shapes are out of view. Two lights.');
  });

  it('says left, right, top and bottom as the camera sees them', () => {
    const scene = new Scene()
      .add(new Sphere([-6, 0, -20], 1.5, { color: 'red' }))
      .add(new Sphere([6, 0, -20], 1.5, { color: 'blue' }))
      .add(new Sphere([0, 4, -20], 1, { color: 'green' }))
      .add(new Sphere([0, -4, -20], 1, { color: [1, 1, 0] }));
    const text = describeScene(scene, camera);
    expect(text).toMatch(/^A red sphere on the left; /);
    expect(text).toContain('a blue sphere on the right');
    expect(text).toContain('a green sphere in the middle at the top');
    expect(text).toContain('a yellow sphere in the middle at the bottom');
    expect(text).toMatch(/No lights\.$/);
    // turned right, the red one is out of view and the blue one moves to the middle
    const turned = describeScene(scene, new Camera({ width: 64, height: 48, yaw: 17 }));
    expect(turned).toMatch(/^A blue sphere in the middle; /);
    expect(turned).toContain('One shape is out of view.');
    expect(turned).not.toContain('red');
  });

  it('finds a sphere smaller than the grid of rays, and a box and a plane', () => {
    const scene = new Scene()
      .add(new Sphere([0, 0, -200], 0.2, { color: 'pink' }))
      .add(new Box([3, -1, -21], [5, 1, -19], { color: 'green' }))
      .add(new Plane([0, 0, -50], [0, 0, 1], { color: 'white' }))
      .add(new PointLight([0, 10, 0]));
    const text = describeScene(scene, camera);
    expect(text).toContain('a pink sphere in the middle');
    expect(text).toMatch(/^A green box on the right; /); // the largest on screen first
    expect(text).toContain('a white wall');
    expect(text).toMatch(/One light\.$/);
  });

  it('counts what it does not name when there are many shapes', () => {
    const scene = new Scene();
    for (let i = 0; i < 30; i++) scene.add(new Sphere([(i % 6) - 2.5, Math.floor(i / 6) - 2, -30], 0.4, { color: 'blue' }));
    const text = describeScene(scene, camera);
    expect(text.match(/a blue sphere/gi)).toHaveLength(8);
    expect(text).toContain('and 22 more shapes');
  });

  it('10,000 spheres: at most 500,000 hit tests (a ray toward each centre made 10⁸), and every sphere in view counted, none "out of view"', () => {
    const scene = new Scene();
    for (let i = 0; i < 10_000; i++) scene.add(new Sphere([((i % 100) - 49.5) * 0.3, (Math.floor(i / 100) - 49.5) * 0.3, -60], 0.12, { color: 'blue' }));
    let tests = 0;
    for (const o of scene.objects) {
      const hit = o.hit.bind(o);
      o.hit = (ray) => { tests++; return hit(ray); };
    }
    const text = describeScene(scene, new Camera({ width: 160, height: 120, fov: 30 }));
    expect(tests).toBeLessThanOrEqual((8 * 6 + 2) * 10_000); // an 8 × 6 grid of rays and two toward centres: the bound of 500,000 (fewer: a ray past a bounding ball tests no shape)
    expect(text.match(/a blue sphere/gi)).toHaveLength(8);
    expect(text).toContain('and 9,992 more shapes');
    expect(text).not.toContain('out of view');
  });

  it('says so when a scene is empty', () => {
    expect(describeScene(new Scene({ background: 'black' }), camera)).toBe('Nothing, on a black background. No lights.');
  });

  it('a glowing sphere in view is a light', () => {
    const scene = new Scene().add(new Sphere([0, 0, -20], 2, { color: [0, 0, 0], emission: [1, 1, 0.2] }));
    expect(describeScene(scene, camera)).toBe('A glowing yellow sphere (a light) in the middle, on a black background. One light.');
  });

  it('sampleScene says where a sphere is, 0–1 across and down the picture', () => {
    const [s] = sampleScene(new Scene().add(new Sphere([0, 0, -20], 3)), camera);
    expect(s.x).toBeCloseTo(0.5, 1);
    expect(s.y).toBeCloseTo(0.5, 1);
    expect(s.first).toBeGreaterThan(10);
  });
});

describe('pictureRows', () => {
  it('reads a picture row by row as runs of colour names', () => {
    const w = 4, h = 2, rgba = new Uint8ClampedArray(w * h * 4).fill(255);
    rgba.set([255, 0, 0, 255], 4 * 5); // row 2, column 2: red
    expect(pictureRows(rgba, w, h)).toEqual(['Row 1 of 2: 4 white', 'Row 2 of 2: 1 white, 1 red, 2 white']);
  });

  it('groups a large picture into at most columns × rows cells', () => {
    const rows = pictureRows(render(classScene(), camera), 64, 48, { columns: 16, rows: 12 });
    expect(rows).toHaveLength(12);
    for (const line of rows) expect(line.split(': ')[1].split(', ').reduce((n, run) => n + Number(run.split(' ')[0]), 0)).toBe(16);
    expect(rows.join('\n')).toContain('pink');
  });
});

describe('the cost of a description', () => {
  it('tests a shape\'s own hit only for rays that pass through its bounding ball: 10,000 cylinders are not 500,000 cylinder tests', async () => {
    const { Cylinder } = await import('../../lib/index.js');
    const scene = new Scene({ background: [0.9, 0.9, 1] }).add(new PointLight([0, 30, -20]));
    let tests = 0;
    for (let i = 0; i < 10_000; i++) {
      const cylinder = new Cylinder([((i % 100) - 49.5) * 0.3, (Math.floor(i / 100) - 50) * 0.3, -60], 0.12, 0.2, { color: 'teal' });
      const hit = cylinder.hit.bind(cylinder);
      cylinder.hit = (ray) => { tests++; return hit(ray); };
      scene.add(cylinder);
    }
    const text = describeScene(scene, new Camera({ width: 160, height: 120 }));
    expect(text).toMatch(/cyan cylinder/);
    expect(tests).toBeLessThan(5_000); // each of the 50 rays meets a few balls, not all 10,000
  });

  it('says the same as testing every shape: a ray that passes a bounding ball by misses its shape', () => {
    const scene = new Scene().add(new Sphere([0, 0, -10], 2, { color: 'pink' })).add(new Box([2, -1, -12], [4, 1, -10], { color: 'blue' }))
      .add(new Plane([0, -2, 0], [0, 1, 0], { color: 'gray' })).add(new PointLight([0, 10, 0]));
    const unbounded = new Scene();
    for (const o of scene.objects) unbounded.add(Object.assign(Object.create(o), { bounds: () => ({ min: { x: -1e9, y: -1e9, z: -1e9 }, max: { x: 1e9, y: 1e9, z: 1e9 } }) }));
    unbounded.add(new PointLight([0, 10, 0]));
    expect(sampleScene(unbounded, camera).map((s) => [s.first, s.any])).toEqual(sampleScene(scene, camera).map((s) => [s.first, s.any]));
  });
});
