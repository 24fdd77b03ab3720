// The library's looser corners, checked: camera size, render's and
// inspectPixel's arguments, colour names from Object.prototype, and lights so
// bright that colour × intensity could overflow to NaN.
import { describe, it, expect } from 'vitest';
import { Scene, Sphere, PointLight, Camera, Material, render, inspectPixel } from '../../lib/index.js';
import { MAX_CAMERA_SIDE, MAX_CAMERA_PIXELS } from '../../lib/math/camera.js';
import { MAX_COLOR, toColor } from '../../lib/math/color.js';

const camera = new Camera({ width: 8, height: 6 });
const scene = new Scene().add(new Sphere([0, 0, -10], 2)).add(new PointLight([5, 5, 0]));

describe('camera size limit', () => {
  it('names the side or the total it breaks', () => {
    expect(() => new Camera({ width: 1e6, height: 1e6 })).toThrow(new RangeError(`width must be at most ${MAX_CAMERA_SIDE} pixels, got 1000000`));
    expect(() => new Camera({ width: 10, height: 20_000 })).toThrow(/^height must be at most 16384 pixels/);
    expect(() => new Camera({ width: 16384, height: 16384 })).toThrow(/^width × height must be at most 16,777,216 pixels \(4096 × 4096\), got 16384 × 16384$/);
  });

  it('the largest allowed sizes are cameras', () => {
    expect(new Camera({ width: 4096, height: 4096 }).width).toBe(4096);
    expect(new Camera({ width: MAX_CAMERA_SIDE, height: MAX_CAMERA_PIXELS / MAX_CAMERA_SIDE }).height).toBe(1024);
  });
});

describe('render and inspectPixel arguments', () => {
  it('a scene and a camera, by name', () => {
    for (const bad of [{}, null, undefined, 'scene', { objects: [] }]) {
      expect(() => render(bad, camera)).toThrow(TypeError);
      expect(() => render(bad, camera)).toThrow(/^scene must be a Scene/);
      expect(() => inspectPixel(bad, camera, 0, 0)).toThrow(/^scene must be a Scene/);
      expect(() => render(scene, bad)).toThrow(/^camera must be a Camera/);
      expect(() => inspectPixel(scene, bad, 0, 0)).toThrow(/^camera must be a Camera/);
    }
  });

  it('a target big enough, of bytes', () => {
    expect(() => render(scene, camera, new Uint8ClampedArray(10))).toThrow(new RangeError('target must hold width × height × 4 = 192 bytes, got 10'));
    expect(() => render(scene, camera, new Float32Array(192))).toThrow(/^target must be a Uint8ClampedArray/);
    expect(() => render(scene, camera, [])).toThrow(TypeError);
    const roomy = new Uint8ClampedArray(200);
    expect(render(scene, camera, roomy)).toBe(roomy);
  });

  it('rows inside the picture, in order', () => {
    expect(() => render(scene, camera, undefined, { y0: 0, y1: 7 })).toThrow(/^rows\.y1 must be a whole number from 0 to 6/);
    expect(() => render(scene, camera, undefined, { y0: -1, y1: 2 })).toThrow(/^rows\.y0/);
    expect(() => render(scene, camera, undefined, { y0: 4, y1: 2 })).toThrow(/^rows\.y1 must not be less than rows\.y0/);
    expect(() => render(scene, camera, undefined, { y0: 1.5, y1: 2 })).toThrow(RangeError);
    expect(() => render(scene, camera, undefined, 3)).toThrow(/^rows must be \{ y0, y1 \}/);
    const band = render(scene, camera, undefined, { y0: 2, y1: 4 });
    const whole = render(scene, camera);
    expect(band.slice(2 * 8 * 4, 4 * 8 * 4)).toEqual(whole.slice(2 * 8 * 4, 4 * 8 * 4));
  });

  it('new Scene(null) says what a scene takes', () => {
    expect(() => new Scene(null)).toThrow(/^scene options must be an object/);
  });
});

describe('colour text', () => {
  it('names from Object.prototype are no colours', () => {
    for (const name of ['constructor', '__proto__', 'toString', 'hasOwnProperty', 'valueOf']) {
      expect(() => toColor(name)).toThrow(TypeError);
      expect(() => toColor(name)).toThrow(`color must be a colour like '#ff5160', 'rgb(255, 81, 96)' or 'pink', got "${name.toLowerCase()}"`);
      expect(() => new Material({ color: name })).toThrow(/^color must be a colour like/);
    }
  });
});

describe('very bright lights', () => {
  it('colour channels and intensities past MAX_COLOR are refused, by name', () => {
    expect(() => new PointLight([0, 0, 0], [1e308, 1, 1], 10)).toThrow(/^color\[0\] must be at most 1000000/);
    expect(() => new PointLight([0, 0, 0], [1, 1, 1], 1e308)).toThrow(/^intensity must be at most 1000000/);
    expect(() => new Material({ emission: 1e300 })).toThrow(/^emission\[0\] must be at most/);
  });

  it('the brightest allowed lights give white, never NaN (black)', () => {
    const bright = new Scene({ ambient: 1, background: [MAX_COLOR, 0, MAX_COLOR] })
      .add(new Sphere([0, 0, -10], 2, { color: [MAX_COLOR, MAX_COLOR, 0], specular: 1, reflection: 1 }))
      .add(new Sphere([3, 0, -10], 1, { color: [0, 0, 0], emission: MAX_COLOR }))
      .add(new PointLight([5, 5, 0], [MAX_COLOR, MAX_COLOR, MAX_COLOR], MAX_COLOR));
    const record = inspectPixel(bright, camera, 4, 3);
    for (const c of record.tracedColor) expect(Number.isNaN(c)).toBe(false);
    expect(record.hit).not.toBeNull();
    expect(Math.max(...record.color)).toBe(255); // bright, not NaN-black
    const rgba = render(bright, camera);
    for (let y = 0; y < camera.height; y++) {
      for (let x = 0; x < camera.width; x++) {
        const { light } = inspectPixel(bright, camera, x, y);
        expect(light.some(Number.isNaN), `pixel ${x},${y}`).toBe(false);
        expect(rgba[(y * camera.width + x) * 4 + 3]).toBe(255);
      }
    }
  });
});
