/**
 * A visual mode's picture in words: what the map shows (not the scene it is
 * a map of), and the value one pixel of it stands for, so that a student who
 * cannot see the colours hears the discriminant, the roots, H or V, the
 * normal or the depth t of the pixel they select.
 */
import { Ray } from '../../math/ray.js';
import { copy, scaleAndAdd, Vec3 } from '../../math/vec3.js';
import { sphereFocus } from '../../tracing/modes.js';
import { nearestHit } from '../../tracing/trace.js';
import { horizontalAngle, verticalAngle } from '../../math/camera.js';
import { formatNumber, formatVector, formatAngle } from '../../text/format.js';

/** The grid of rays a map's summary looks at, at most this many a side. */
const SUMMARY_SIDE = 64;

const _ray = new Ray();
const _focus = { index: -1, discriminant: 0, roots: 0 };
const _hit = { object: null, t: Infinity };
const _point = new Vec3();
const _normal = new Vec3();

function primaryRay(camera, x, y) {
  copy(_ray.origin, camera.position);
  camera.directionAt(x, y, _ray.direction);
  return _ray;
}

/** What the roots of a quadratic mean for the ray. */
const ROOTS_MEANING = ['no hit', 'one root: the ray grazes the sphere', 'two roots: the ray goes through'];

/**
 * What pixel (x, y) of a `mode` map stands for, in a few words:
 * `'Discriminant −12.3, negative: no hit.'`, `'H 3.2°.'`; '' for the shaded picture.
 * @param {string} mode a visual mode's name (lib/tracing/modes.js)
 */
export function mapValue(mode, scene, camera, x, y) {
  const ray = primaryRay(camera, x, y);
  switch (mode) {
    case 'discriminant':
    case 'roots': {
      if (sphereFocus(scene.objects, ray, _focus) < 0) return 'No sphere for the quadratic.';
      const meaning = ROOTS_MEANING[_focus.roots];
      if (mode === 'roots') return `${_focus.roots} ${_focus.roots === 1 ? 'root' : 'roots'}: ${meaning.replace(/^[^:]*: /, '')}.`;
      const sign = _focus.roots === 0 ? 'negative' : _focus.roots === 1 ? 'about 0' : 'positive';
      return `Discriminant ${formatNumber(_focus.discriminant)}, ${sign}: ${meaning}.`;
    }
    case 'h': return `H ${formatAngle(horizontalAngle(ray.direction))}°.`;
    case 'v': return `V ${formatAngle(verticalAngle(ray.direction))}°.`;
    case 'normals':
    case 'depth': {
      if (!nearestHit(scene.objects, ray, _hit)) return 'No hit: black.';
      if (mode === 'depth') return `Depth t ${formatNumber(_hit.t)}.`;
      scaleAndAdd(_point, ray.origin, ray.direction, _hit.t);
      _hit.object.normalAt(_point, _normal);
      return `Normal ${formatVector(_normal)}.`;
    }
    default: return '';
  }
}

/**
 * What a `mode` map shows, as the map: where its values are, over a grid of the
 * camera's rays (at most SUMMARY_SIDE a side). '' for the shaded picture.
 * @example
 * mapSummary('discriminant', scene, camera);
 * // 'Discriminant map: positive (two hits) on pixels x 14–49, y 6–41; negative (no hit) everywhere else.'
 */
export function mapSummary(mode, scene, camera) {
  const { width, height } = camera;
  if (mode === 'h' || mode === 'v') {
    const first = mode === 'h' ? [0, (height - 1) >> 1] : [(width - 1) >> 1, 0];
    const last = mode === 'h' ? [width - 1, (height - 1) >> 1] : [(width - 1) >> 1, height - 1];
    const angle = mode === 'h' ? horizontalAngle : verticalAngle;
    const a = angle(primaryRay(camera, ...first).direction), b = angle(primaryRay(camera, ...last).direction);
    return mode === 'h' ? `H angle map: from ${formatAngle(a)}° at the left to ${formatAngle(b)}° at the right (purple negative, orange positive).`
      : `V angle map: from ${formatAngle(a)}° at the top to ${formatAngle(b)}° at the bottom (orange positive, purple negative).`;
  }
  if (mode === 'normals') return 'Normals map: which way each surface faces where the ray hits it (x red, y green, z blue); black where it hits nothing.';
  if (mode === 'depth') return 'Depth map: how far each ray goes before it hits, near bright, far dark; black where it hits nothing.';
  if (mode !== 'discriminant' && mode !== 'roots') return '';
  // where each number of roots is: its count and the box of pixels it covers
  const stepX = Math.max(1, width / SUMMARY_SIDE), stepY = Math.max(1, height / SUMMARY_SIDE);
  const boxes = [null, null, null];
  for (let gy = 0; gy < height; gy += stepY) {
    for (let gx = 0; gx < width; gx += stepX) {
      const x = Math.floor(gx), y = Math.floor(gy);
      if (sphereFocus(scene.objects, primaryRay(camera, x, y), _focus) < 0) continue;
      const b = boxes[_focus.roots] ??= { x0: x, x1: x, y0: y, y1: y };
      b.x0 = Math.min(b.x0, x); b.x1 = Math.max(b.x1, x); b.y0 = Math.min(b.y0, y); b.y1 = Math.max(b.y1, y);
    }
  }
  const name = mode === 'roots' ? 'Roots map' : 'Discriminant map';
  const words = mode === 'roots' ? ['0 roots (no hit)', '1 root (a graze)', '2 roots (two hits)']
    : ['negative (no hit)', 'about 0 (a graze)', 'positive (two hits)'];
  if (!boxes[0] && !boxes[1] && !boxes[2]) return `${name}: no sphere, black everywhere.`;
  const inner = boxes[2] ? 2 : boxes[1] ? 1 : 0;
  const box = boxes[inner];
  const parts = [`${words[inner]} on pixels x ${box.x0}–${box.x1}, y ${box.y0}–${box.y1}`];
  if (inner === 2 && boxes[1]) parts.push(`${words[1]} at its edge`);
  if (inner !== 0 && boxes[0]) parts.push(`${words[0]} everywhere else`);
  return `${name}: ${parts.join('; ')}.`;
}
