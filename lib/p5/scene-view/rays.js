/**
 * The rays the 3D view shows for pixels, read from inspectPixel's record (so
 * the rays and the traced colour always agree, see lib/lesson/rays3d.js raySegments):
 * the selected pixel's whole story, the primary rays of its row or column
 * (keys h / v), and the story of a pixel Shoot sends flying. Lengths scale
 * with the scene's radius `r`: a missing ray goes 2.5 r out, a normal is short.
 */
import { inspectPixel } from '../../lesson/inspect.js';
import { raySegments, sampleSegments, primarySegment } from '../../lesson/rays3d.js';

/**
 * The story of a pixel (its inspectPixel record) as segments: primary ray,
 * normal, shadow rays (one per point of an area light), bounces, and last,
 * with several rays per pixel, its n × n sub-pixel rays (kind 'sample').
 */
export function pixelStory(scene, record, r) {
  const story = raySegments(scene, record, { missLength: r * 2.5, normalLength: r * 0.08 });
  for (const s of sampleSegments(record, { missLength: r * 2.5 })) story.push(s);
  return story;
}

/** The story of a pixel in Shoot's flight (a shorter normal: many fly at once). */
export function shotStory(scene, camera, x, y, r) {
  return raySegments(scene, inspectPixel(scene, camera, x, y), { missLength: r * 2.5, normalLength: r * 0.06 });
}

/**
 * The primary rays of the selected pixel's row ('row') or column ('column'),
 * each to its hit (or out to the background), leaving out the selected
 * pixel's own (drawn in full); [] for no fan or no selection.
 * @param {{ scene: object, camera: { width: number, height: number } }} view
 * @param {{x: number, y: number}|null} selected
 * @param {'row'|'column'|null} kind
 */
export function fanRays({ scene, camera }, selected, kind, r) {
  const s = selected;
  if (!kind || !s) return [];
  const out = [];
  const n = kind === 'row' ? camera.width : camera.height;
  for (let i = 0; i < n; i++) {
    const x = kind === 'row' ? i : s.x, y = kind === 'row' ? s.y : i;
    if (x === s.x && y === s.y) continue;
    out.push(primarySegment(scene, camera, x, y, { missLength: r * 2.5 }));
  }
  return out;
}
