// The one line a screen reader hears for a selected pixel names the shape as the panel does:
// its own name, else its kind and its number counted from 1 ("sphere 1"), never the index from 0.
import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, PointLight, Camera, inspectPixel } from '../../lib/index.js';
import { pixelAnnouncement } from '../../lib/p5/inspector.js';

const camera = new Camera({ width: 32, height: 24 });

describe('pixelAnnouncement', () => {
  it('says "the sphere 1" for the first unnamed sphere, as the panel and its CSV name it', () => {
    const scene = new Scene().add(new Sphere([0, 0, -20], 4, { color: 'pink' })).add(new PointLight([-10, 20, 0]));
    const r = inspectPixel(scene, camera, 16, 12);
    expect(r.hit.name).toBe('sphere 1');
    expect(pixelAnnouncement(r)).toMatch(/, the sphere 1\.$/);
  });

  it('counts per kind: an unnamed sphere after an unnamed plane is still "sphere 1"', () => {
    const scene = new Scene().add(new Plane([0, -30, 0], [0, 1, 0])).add(new Sphere([0, 0, -20], 4)).add(new PointLight([-10, 20, 0]));
    expect(pixelAnnouncement(inspectPixel(scene, camera, 16, 12))).toMatch(/, the sphere 1\.$/);
  });

  it('keeps a shape\'s own name, and a colour name before its kind', () => {
    const named = (name) => new Scene().add(new Sphere([0, 0, -20], 4, { name })).add(new PointLight([-10, 20, 0]));
    expect(pixelAnnouncement(inspectPixel(named('pink'), camera, 16, 12))).toMatch(/, the pink sphere\.$/);
    expect(pixelAnnouncement(inspectPixel(named('moon'), camera, 16, 12))).toMatch(/, the moon\.$/);
  });
});
