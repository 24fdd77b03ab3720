// The rays the 3D view shows for pixels (lib/p5/scene-view/rays.js): read from
// inspectPixel, so they end where the traced pixel's story says.
import { describe, it, expect } from 'vitest';
import { classScene } from '../../lib/scene/examples.js';
import { Camera } from '../../lib/math/camera.js';
import { inspectPixel } from '../../lib/lesson/inspect.js';
import { pixelStory, shotStory, fanRays } from '../../lib/p5/scene-view/rays.js';
import { raySegments, primarySegment } from '../../lib/lesson/rays3d.js';
import { penumbraScene, penumbraCamera, penumbraPixel } from './penumbra-scene.js';

const scene = classScene(), camera = new Camera({ width: 16, height: 12 }), R = 10;

describe('pixelStory and shotStory', () => {
  it('start with the primary ray from the eye to the pixel\'s hit', () => {
    const record = inspectPixel(scene, camera, 8, 7);
    const [primary] = pixelStory(scene, record, R);
    expect(primary.kind).toBe('primary');
    expect(primary.from).toEqual(camera.position);
    expect(primary.to.z).toBeCloseTo(record.hit.point.z, 9);
    expect(shotStory(scene, camera, 8, 7, R)[0].to).toEqual(primary.to);
  });

  it('a shot\'s normal is shorter than the selected pixel\'s (many fly at once)', () => {
    const length = (s) => Math.hypot(s.to.x - s.from.x, s.to.y - s.from.y, s.to.z - s.from.z);
    const normal = (segments) => segments.find((s) => s.kind === 'normal');
    const record = inspectPixel(scene, camera, 8, 7);
    expect(length(normal(pixelStory(scene, record, R)))).toBeCloseTo(R * 0.08, 9);
    expect(length(normal(shotStory(scene, camera, 8, 7, R)))).toBeCloseTo(R * 0.06, 9);
  });
});

describe('pixelStory: an area light and several rays per pixel', () => {
  it('one shadow ray per point of the disc, then the n × n sub-pixel rays last', () => {
    const { scene: lit, lamp } = penumbraScene();
    const camera4 = penumbraCamera(4);
    const { x, y, seen } = penumbraPixel(lit, penumbraCamera(), lamp);
    const story = pixelStory(lit, inspectPixel(lit, camera4, x, y), R);
    const kinds = story.map((s) => s.kind);
    expect(kinds.filter((k) => k === 'shadow')).toHaveLength(16);
    expect(kinds.slice(-4)).toEqual(['sample', 'sample', 'sample', 'sample']);
    expect(kinds.filter((k) => k === 'sample')).toHaveLength(4);
    // the centre ray's point is the one-ray pixel's: the same shadow rays reach the disc
    expect(story.filter((s) => s.kind === 'shadow' && s.lit)).toHaveLength(seen);
  });

  it('no sub-pixel rays with one ray per pixel', () => {
    expect(pixelStory(scene, inspectPixel(scene, camera, 8, 7), R).some((s) => s.kind === 'sample')).toBe(false);
  });
});

describe('fanRays', () => {
  const view = { scene, camera };

  it('a row fan has a primary ray through every other pixel of the row, in order', () => {
    const fan = fanRays(view, { x: 5, y: 3 }, 'row', R);
    expect(fan).toHaveLength(15);
    expect(fan.every((s) => s.kind === 'primary')).toBe(true);
    const first = camera.primaryRay(0, 3).ray.direction, seen = fan[0];
    const d = Math.hypot(seen.to.x - seen.from.x, seen.to.y - seen.from.y, seen.to.z - seen.from.z);
    expect((seen.to.x - seen.from.x) / d).toBeCloseTo(first.x, 9);
  });

  it('a column fan one through every other pixel of the column', () => {
    expect(fanRays(view, { x: 5, y: 3 }, 'column', R)).toHaveLength(11);
  });

  it('none without a kind or a selected pixel', () => {
    expect(fanRays(view, null, 'row', R)).toEqual([]);
    expect(fanRays(view, { x: 5, y: 3 }, null, R)).toEqual([]);
  });
});

describe('a row\'s fan of primary rays', () => {
  it('is each pixel\'s first segment of its story, found without the pixel\'s whole record', () => {
    for (let y = 0; y < camera.height; y++) {
      for (let x = 0; x < camera.width; x++) {
        expect(primarySegment(scene, camera, x, y, { missLength: 7 })).toEqual(raySegments(scene, inspectPixel(scene, camera, x, y), { missLength: 7 })[0]);
      }
    }
  });
});
