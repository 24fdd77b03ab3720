// A scene or camera changed in place after a ProgressiveRenderer was made is
// checked again by restart(), with the constructors' own messages; a refused
// restart leaves the last picture as it was.
import { describe, it, expect, vi } from 'vitest';
import { ProgressiveRenderer } from '../../lib/tracing/frames.js';
import { render, Camera, Scene, Sphere, Plane, Box, Mesh, PointLight, SpotLight, AreaLight, classScene } from '../../lib/index.js';
import * as sceneCheck from '../../lib/scene/check.js';

const camera = () => new Camera({ width: 16, height: 12 });

function finished(scene, cam = camera()) {
  const r = new ProgressiveRenderer({ scene, camera: cam, budgetMs: 1e9 });
  while (!r.done) r.step();
  return r;
}

describe('restart() after the scene changed in place', () => {
  const cases = [
    ['a sphere\'s centre set to null', (s) => { s.objects[1].center = null; }, TypeError, 'objects[1].center must be [x, y, z] or {x, y, z}, got null'],
    ['a sphere\'s radius made negative', (s) => { s.objects[1].radius = -1; }, RangeError, 'objects[1].radius must be greater than 0, got -1'],
    ['a material set to null', (s) => { s.objects[1].material = null; }, TypeError, 'objects[1].material must be a Material, got null'],
    ['a colour made three numbers too many', (s) => { s.objects[1].material.color = [1, 2, 3, 4]; }, TypeError, 'objects[1].material.color must have 3 numbers [r, g, b], got [1, 2, 3, 4]'],
    ['a colour name misspelt', (s) => { s.objects[1].material.color = 'redd'; }, TypeError, /^objects\[1\]\.material\.color/],
    ['a reflection over 1', (s) => { s.objects[1].material.reflection = 2; }, RangeError, 'objects[1].material.reflection must be between 0 and 1, got 2'],
    ['a shape replaced by null', (s) => { s.objects[0] = null; }, TypeError, 'objects[0] must be a shape (a Sphere, Plane, Box, … with hit, normalAt, intersect and bounds), got null'],
    ['the ambient term made text', (s) => { s.ambient = '0.5'; }, TypeError, 'scene.ambient must be a finite number, got "0.5"'],
  ];
  for (const [what, change, Kind, message] of cases) {
    it(`${what}: a ${Kind.name} naming the field, and the picture stays`, () => {
      const scene = classScene();
      const r = finished(scene);
      const before = r.buffer.slice();
      change(scene);
      expect(() => r.restart()).toThrow(Kind);
      expect(() => r.restart()).toThrow(message);
      expect(r.buffer).toEqual(before);
      expect(r.done).toBe(true);
    });
  }

  it('a colour given as text is read as the Material constructor reads it', () => {
    const scene = classScene();
    const r = finished(scene);
    scene.objects[1].material.color = 'red';
    r.restart();
    expect(scene.objects[1].material.color).toEqual([1, 0, 0]);
    while (!r.done) r.step();
    const made = classScene();
    made.objects[1].material.color = [1, 0, 0];
    expect(r.buffer).toEqual(render(made, camera()));
  });

  it('checks planes, boxes and point lights too', () => {
    const scene = new Scene().add(new Plane([0, -1, 0], [0, 1, 0])).add(new Box([-1, -1, -6], [1, 1, -4])).add(new PointLight([0, 5, 0]));
    const r = finished(scene);
    scene.objects[0].normal = [0, 0, 0];
    expect(() => r.restart()).toThrow(/^objects\[0\]\.normal/);
    scene.objects[0].normal = [0, 1, 0];
    scene.objects[1].max = { x: 1, y: NaN, z: 0 };
    expect(() => r.restart()).toThrow('objects[1].max.y must be a finite number, got NaN');
    scene.objects[1].max = [1, 1, -4];
    scene.lights[0].source.intensity = -1;
    expect(() => r.restart()).toThrow('lights[0].intensity must not be negative, got -1');
    scene.lights[0].source.intensity = 1;
    scene.lights[0].source.attenuation = '0.1';
    expect(() => r.restart()).toThrow('lights[0].attenuation must be a finite number, got "0.1"');
  });
});

describe('restart() and a mesh', () => {
  const square = () => new Mesh({ positions: [[-1, -1, -5], [1, -1, -5], [1, 1, -5], [-1, 1, -5]], cells: [[0, 1, 2], [0, 2, 3]] });

  it('builds no BVH again while the mesh is as it was built', () => {
    const scene = new Scene().add(square()).add(new PointLight([0, 5, 0]));
    const r = finished(scene);
    const { bvh } = scene.objects[0];
    const build = vi.spyOn(Mesh, 'build');
    r.restart();
    r.restart();
    expect(build).not.toHaveBeenCalled();
    expect(scene.objects[0].bvh).toBe(bvh);
    build.mockRestore();
  });

  it('checks one changed in place, and traces its new triangles', () => {
    const scene = new Scene({ background: [0, 0, 1] }).add(square()).add(new PointLight([0, 5, 0]));
    const r = finished(scene);
    const mesh = scene.objects[0];
    mesh.positions[0][0] = NaN;
    expect(() => r.restart()).toThrow(/^objects\[0\]\.positions\[0\]\.x must be a finite number/);
    mesh.positions[0][0] = -1;
    for (const p of mesh.positions) p[2] = -500; // far away: a speck
    r.restart();
    while (!r.done) r.step(1000);
    const moved = new Scene({ background: [0, 0, 1] }).add(new Mesh({ positions: mesh.positions, cells: mesh.cells })).add(new PointLight([0, 5, 0]));
    expect(r.buffer).toEqual(render(moved, camera()));
  });
});

describe('restart() after a spot or area light changed in place', () => {
  it('checks them as it checks point lights, naming the light and the field', () => {
    const scene = new Scene().add(new Sphere([0, 0, -5], 1)).add(new SpotLight([0, 5, -5], [0, 0, -5], { angle: 20 })).add(new AreaLight([0, 5, -5], 1));
    const r = finished(scene);
    const spot = scene.lights[0].source, area = scene.lights[1].source;
    spot.angle = 120;
    expect(() => r.restart()).toThrow('lights[0].angle must be between 0 and 90 degrees (not included), got 120');
    spot.angle = 20;
    spot.target = [0, 5, -5];
    expect(() => r.restart()).toThrow(/^lights\[0\]\.target must not be the light's own position/);
    spot.target = [0, 0, -5];
    spot.intensity = -1;
    expect(() => r.restart()).toThrow('lights[0].intensity must not be negative, got -1');
    spot.intensity = 1;
    area.samples = 1e6;
    expect(() => r.restart()).toThrow(/^lights\[1\]\.samples must be a square number of shadow rays/);
    area.samples = 16;
    area.radius = null;
    expect(() => r.restart()).toThrow('lights[1].radius must be a finite number, got null');
    area.radius = 1;
    expect(() => r.restart()).not.toThrow();
  });
});

describe('restart() after the camera changed in place', () => {
  it('says the size limit, as the Camera constructor does, instead of "Invalid typed array length"', () => {
    const cam = camera();
    const r = finished(classScene(), cam);
    cam.width = cam.height = 50000;
    expect(() => r.restart()).toThrow(new RangeError('camera.width must be at most 16384 pixels, got 50000'));
    cam.width = cam.height = 8000;
    expect(() => r.restart()).toThrow(/^camera\.width × height must be at most 16,777,216 pixels/);
    cam.width = 16; cam.height = 12; cam.fov = 0;
    expect(() => r.restart()).toThrow(/^camera\.fov must be between 0 and 180/);
    cam.fov = 30; cam.position = null;
    expect(() => r.restart()).toThrow('camera.position must be [x, y, z] or {x, y, z}, got null');
    expect(r.width).toBe(16);
  });

  it('a new camera or scene given to restart is checked the same way', () => {
    const r = finished(classScene());
    const big = camera();
    big.height = 1.5;
    expect(() => r.restart({ camera: big })).toThrow('camera.height must be a positive whole number, got 1.5');
    const scene = classScene();
    scene.objects[2].center = [0, 0];
    expect(() => r.restart({ scene })).toThrow('objects[2].center must have 3 numbers [x, y, z], got [0, 0]');
  });

  it('checks once per restart, never per pixel', () => {
    let checks = 0;
    const scene = classScene();
    const r = new ProgressiveRenderer({ scene, camera: camera(), budgetMs: 1e9 });
    const spy = new Proxy(scene.objects, { get: (t, k) => { if (k === 'forEach') checks++; return Reflect.get(t, k); } });
    scene.objects = spy;
    r.restart();
    const afterRestart = checks;
    while (!r.done) r.step();
    expect(afterRestart).toBeGreaterThan(0);
    expect(checks).toBe(afterRestart);
  });
});

it('a good scene and camera pass, the same array kept for colours already [r, g, b]', () => {
  const scene = classScene();
  const color = scene.objects[1].material.color;
  sceneCheck.checkScene(scene);
  sceneCheck.checkCamera(camera());
  expect(scene.objects[1].material.color).toBe(color);
  expect(new Sphere([0, 0, 0], 1).material.color).toEqual([1, 1, 1]);
});
