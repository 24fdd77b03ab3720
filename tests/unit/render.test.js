import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, Box, PointLight, Camera, classScene, render, inspectPixel } from '../../lib/index.js';
import { renderPixel, writePixel } from '../../lib/tracing/render.js';

function planeBoxScene() {
  const scene = new Scene({ background: 'skyblue', ambient: 0.1 });
  scene.add(new Plane([0, -2, 0], [0, 1, 0], { color: [0.8, 0.8, 0.8], reflection: 0.2 }));
  scene.add(new Box([-3, -2, -16], [0, 1, -12], { color: '#ff5160' }));
  scene.add(new Sphere([2.5, -0.5, -13], 1.5, { color: 'white', transparency: 0.7, reflection: 0.2, specular: 0.5 }));
  scene.add(new PointLight([-6, 8, -4]));
  scene.add(new Sphere([4, 6, -20], 1, { emission: [0.5, 0.4, 0.2] }));
  return scene;
}

const scenes = [
  ['class scene 64×48', () => classScene(), { width: 64, height: 48 }],
  ['full class scene (mirrors and glass) 64×48', () => classScene({ full: true }), { width: 64, height: 48 }],
  ['plane + box + glass + point light 48×36', planeBoxScene, { width: 48, height: 36, fov: 45, position: [0, 1, 0], pitch: -8 }],
  ['class scene turned: yaw and pitch, 33×25', () => classScene({ full: true }), { width: 33, height: 25, fov: 50, position: [-4, 6, 2], yaw: 12, pitch: -15 }],
];

describe('render', () => {
  it('returns width × height RGBA bytes, opaque', () => {
    const pixels = render(classScene(), new Camera({ width: 16, height: 12 }));
    expect(pixels).toBeInstanceOf(Uint8ClampedArray);
    expect(pixels).toHaveLength(16 * 12 * 4);
    for (let i = 3; i < pixels.length; i += 4) expect(pixels[i]).toBe(255);
  });

  it('an empty scene is the background everywhere', () => {
    const pixels = render(new Scene({ background: [1, 0.5, 0] }), new Camera({ width: 4, height: 3 }));
    for (let i = 0; i < pixels.length; i += 4) expect([...pixels.subarray(i, i + 4)]).toEqual([255, 128, 0, 255]);
  });

  it('renders into a given target and returns it', () => {
    const target = new Uint8ClampedArray(8 * 6 * 4);
    const camera = new Camera({ width: 8, height: 6 });
    expect(render(classScene(), camera, target)).toBe(target);
    expect(target).toEqual(render(classScene(), camera));
  });

  it('is deterministic: the same scene twice gives the same bytes', () => {
    const camera = new Camera({ width: 32, height: 24 });
    expect(render(classScene({ full: true }), camera)).toEqual(render(classScene({ full: true }), camera));
  });

  it('rows go from the top: the sky is at the top, the ground at the bottom', () => {
    const camera = new Camera({ width: 9, height: 9, fov: 90 });
    const pixels = render(classScene(), camera);
    const at = (x, y) => [...pixels.subarray((y * 9 + x) * 4, (y * 9 + x) * 4 + 3)];
    expect(at(0, 0)).toEqual([255, 255, 255]); // background [2, 2, 2], clamped
    expect(at(4, 8)).not.toEqual([255, 255, 255]);
  });

  it('renderPixel writes only its own pixel, the same bytes as render', () => {
    const scene = classScene(), camera = new Camera({ width: 20, height: 10 });
    const full = render(scene, camera);
    const target = new Uint8ClampedArray(20 * 10 * 4);
    renderPixel(scene, camera, 13, 7, target);
    const i = (7 * 20 + 13) * 4;
    expect([...target.subarray(i, i + 4)]).toEqual([...full.subarray(i, i + 4)]);
    expect(target.reduce((n, b) => n + (b !== 0), 0)).toBeLessThanOrEqual(4);
  });

  it('writePixel clamps to 0–255 and rounds', () => {
    const t = new Uint8ClampedArray(8);
    writePixel(t, 4, [2, -1, 0.5]);
    expect([...t]).toEqual([0, 0, 0, 0, 255, 0, 128, 255]);
    writePixel(t, 0, [1 / 255, 0.4 / 255, 0.6 / 255]);
    expect([...t.subarray(0, 4)]).toEqual([1, 0, 1, 255]);
  });
});

describe('render == inspectPixel, for every pixel of whole images', () => {
  for (const [name, makeScene, cameraOptions] of scenes) {
    it(name, () => {
      const scene = makeScene();
      const camera = new Camera(cameraOptions);
      const pixels = render(scene, camera);
      const { width, height } = camera;
      let differing = 0;
      const colours = new Set();
      for (let y = 0; y < height; y++) {
        for (let x = 0; x < width; x++) {
          const i = (y * width + x) * 4;
          const rendered = [pixels[i], pixels[i + 1], pixels[i + 2]];
          const inspected = inspectPixel(scene, camera, x, y).color;
          if (rendered.some((c, k) => c !== inspected[k])) {
            differing++;
            if (differing === 1) expect(inspected, `pixel ${x},${y}`).toEqual(rendered);
          }
          colours.add(rendered.join());
        }
      }
      expect(differing).toBe(0);
      expect(colours.size).toBeGreaterThan(20); // a real picture, not a blank one
    });
  }

  it('inspecting first does not change what render then draws (no leftover state)', () => {
    const scene = classScene({ full: true }), camera = new Camera({ width: 24, height: 18 });
    const before = render(scene, camera);
    for (let y = 0; y < 18; y += 5) for (let x = 0; x < 24; x += 5) inspectPixel(scene, camera, x, y);
    expect(render(scene, camera)).toEqual(before);
  });
});
