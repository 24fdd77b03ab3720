// The picture for a student who cannot see it: rows of pixels in the answer's
// coordinates, the next pixel of a colour, a map's words, and where the 3D view
// looks from.
import { describe, it, expect } from 'vitest';
import { pixelNames, pixelRows, nextPixelNamed, COLOR_NAMES } from '../../lib/lesson/describe.js';
import { mapSummary, mapValue } from '../../lib/p5/tracer/map-words.js';
import { orbitWords } from '../../lib/p5/scene-view/words.js';
import { Camera, Scene, Sphere, PointLight, classScene, render, inspectPixel, colorName } from '../../lib/index.js';

/** A 4 × 2 picture: row 0 white, white, pink, pink; row 1 pink, white, white, white. */
function tiny() {
  const white = [255, 255, 255], pink = [255, 81, 96];
  const pixels = [white, white, pink, pink, pink, white, white, white];
  const rgba = new Uint8ClampedArray(pixels.length * 4);
  pixels.forEach((c, i) => rgba.set([...c, 255], i * 4));
  return rgba;
}

describe('pixelRows', () => {
  it('reads every row of pixels, runs named with their columns, from 0 as in the answer line', () => {
    expect(pixelRows(pixelNames(tiny(), 4, 2), 4, 2)).toEqual(['Row 0: 0–1 white, 2–3 pink', 'Row 1: 0 pink, 1–3 white']);
  });

  it('has one line per row of the picture, at its own resolution', () => {
    const camera = new Camera({ width: 32, height: 24, fov: 30 });
    const rows = pixelRows(pixelNames(render(classScene(), camera), 32, 24), 32, 24);
    expect(rows).toHaveLength(24);
    expect(rows.some((r) => /\bpink\b/.test(r))).toBe(true);
  });
});

describe('nextPixelNamed', () => {
  const names = pixelNames(tiny(), 4, 2);
  it('finds the next pixel of a colour row by row, wrapping round, and the one before', () => {
    expect(nextPixelNamed(names, 4, 'pink', null)).toEqual({ x: 2, y: 0 });
    expect(nextPixelNamed(names, 4, 'pink', { x: 2, y: 0 })).toEqual({ x: 3, y: 0 });
    expect(nextPixelNamed(names, 4, 'pink', { x: 3, y: 0 })).toEqual({ x: 0, y: 1 });
    expect(nextPixelNamed(names, 4, 'pink', { x: 0, y: 1 })).toEqual({ x: 2, y: 0 });
    expect(nextPixelNamed(names, 4, 'pink', { x: 2, y: 0 }, -1)).toEqual({ x: 0, y: 1 });
    expect(nextPixelNamed(names, 4, 'green', null)).toBeNull();
  });

  it('lands on pixels whose colour is that name in the class scene (every pink one is a right answer)', () => {
    const camera = new Camera({ width: 32, height: 24, fov: 30 });
    const all = pixelNames(render(classScene(), camera), 32, 24);
    let at = null;
    for (let i = 0; i < 5; i++) {
      at = nextPixelNamed(all, 32, 'pink', at);
      expect(colorName(inspectPixel(classScene(), camera, at.x, at.y).color)).toBe('pink');
    }
  });

  it('knows every name colorName gives', () => {
    for (const rgb of [[0, 0, 0], [255, 255, 255], [128, 128, 128], [255, 0, 0], [0, 0, 255], [120, 60, 10]]) expect(COLOR_NAMES).toContain(colorName(rgb));
  });
});

describe('map words', () => {
  const scene = new Scene().add(new Sphere([0, 0, -20], 4, { color: 'pink' })).add(new PointLight([-10, 10, 10]));
  const camera = new Camera({ width: 64, height: 48 });

  it('says the value a pixel of a map stands for', () => {
    expect(mapValue('discriminant', scene, camera, 32, 24)).toMatch(/^Discriminant \d[\d.]*, positive: two roots: the ray goes through\.$/);
    expect(mapValue('discriminant', scene, camera, 0, 0)).toMatch(/^Discriminant -[\d.]+, negative: no hit\.$/);
    expect(mapValue('roots', scene, camera, 32, 24)).toBe('2 roots: the ray goes through.');
    expect(mapValue('h', scene, camera, 63, 24)).toMatch(/^H \d+\.\d°\.$/);
    expect(mapValue('depth', scene, camera, 0, 0)).toBe('No hit: black.');
    expect(mapValue('shaded', scene, camera, 0, 0)).toBe('');
  });

  it('describes a map as the map: where its values are', () => {
    expect(mapSummary('discriminant', scene, camera)).toMatch(/^Discriminant map: positive \(two hits\) on pixels x \d+–\d+, y \d+–\d+; .*negative \(no hit\) everywhere else\.$/);
    expect(mapSummary('h', scene, camera)).toMatch(/^H angle map: from -\d+\.\d° at the left to \d+\.\d° at the right/);
    expect(mapSummary('shaded', scene, camera)).toBe('');
  });
});

describe('orbitWords', () => {
  it('says where the 3D view looks from', () => {
    expect(orbitWords({ yaw: 0, pitch: 0 })).toBe('from behind the eye, at the eye\'s height');
    expect(orbitWords({ yaw: -35, pitch: 20 })).toBe('from behind the eye and to its right, from above');
    expect(orbitWords({ yaw: 90, pitch: -20 })).toBe('from the eye\'s left, from below');
    expect(orbitWords({ yaw: 180, pitch: 70 })).toBe('from in front, facing the eye, from high above');
    expect(orbitWords({ yaw: -25, pitch: 20 })).not.toBe(orbitWords({ yaw: -95, pitch: 20 }));
  });
});
