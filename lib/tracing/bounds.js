/**
 * Which pixels can a shape cover? A conservative rectangle on the image, so
 * that `render` tests each primary ray against the few shapes that may be
 * under its pixel instead of against all of them. Being conservative is what
 * keeps the picture identical: a shape left out of a pixel's list is one its
 * ray cannot hit.
 */
import { ballOf } from '../shapes/index.js';
import { clamp } from '../math/numbers.js';

/** Pixels of margin around every rectangle (rounding, the tangent band). */
const MARGIN = 1;

/**
 * Writes `{ x0, y0, x1, y1 }` (inclusive pixel bounds, clamped to the image)
 * of where `object` may appear into `out`, and returns true; false when no
 * primary ray can hit it (it lies wholly behind the eye).
 */
export function screenBounds(object, camera, out) {
  const sphere = boundingSphere(object);
  setAll(out, camera);
  if (!sphere) return true; // a plane: anywhere
  const { cx, cy, cz } = toCamera(sphere.center, camera);
  const r = sphere.radius;
  if (cz + r <= 0) return false; // every primary ray goes forward
  const sx = slopeRange(cx, cz, r), sy = slopeRange(cy, cz, r);
  if (sx) {
    out.x0 = clamp(Math.floor(camera.pixelX(sx.lo)) - MARGIN, 0, camera.width - 1);
    out.x1 = clamp(Math.ceil(camera.pixelX(sx.hi)) + MARGIN, 0, camera.width - 1);
  }
  if (sy) {
    out.y0 = clamp(Math.floor(camera.pixelY(sy.hi)) - MARGIN, 0, camera.height - 1);
    out.y1 = clamp(Math.ceil(camera.pixelY(sy.lo)) + MARGIN, 0, camera.height - 1);
  }
  return out.x0 <= out.x1 && out.y0 <= out.y1;
}

/**
 * The image-plane slopes s (sideways ÷ forward) of the planes through the eye
 * that pass within r of a centre at (c, cz): a ray hits the sphere only if
 * its plane does, i.e. (c − s·cz)² ≤ r²(1 + s²). Null when not bounded
 * (the eye is level with the sphere: cz ≤ r).
 */
function slopeRange(c, cz, r) {
  const a = cz * cz - r * r;
  if (!(cz > r) || !(a > 0)) return null;
  const root = r * Math.sqrt(c * c + a);
  return { lo: (c * cz - root) / a, hi: (c * cz + root) / a };
}

/** A sphere around the shape: a ball itself, else the sphere around its bounds(); null when unbounded (a plane). */
function boundingSphere(object) {
  const ball = ballOf(object);
  if (ball) return ball;
  const box = typeof object.bounds === 'function' ? object.bounds() : null; // a shape without bounds may be anywhere
  if (!box) return null;
  const { min, max } = box;
  const dx = max.x - min.x, dy = max.y - min.y, dz = max.z - min.z;
  return {
    center: { x: (min.x + max.x) / 2, y: (min.y + max.y) / 2, z: (min.z + max.z) / 2 },
    radius: Math.sqrt(dx * dx + dy * dy + dz * dz) / 2,
  };
}

/** A point in the camera's frame: sideways (right), up, and forward. */
function toCamera(p, camera) {
  const e = camera.position, r = camera.right, u = camera.up, f = camera.forward;
  const x = p.x - e.x, y = p.y - e.y, z = p.z - e.z;
  return { cx: x * r.x + y * r.y + z * r.z, cy: x * u.x + y * u.y + z * u.z, cz: x * f.x + y * f.y + z * f.z };
}

function setAll(out, camera) {
  out.x0 = 0; out.y0 = 0; out.x1 = camera.width - 1; out.y1 = camera.height - 1;
}

/** Tile size (pixels) of the candidate grid. */
export const TILE = 16;

/**
 * For each TILE×TILE tile of the image (of the tile rows covering image rows
 * y0 ≤ y < y1), the shapes that may appear in it, in the scene's order, so
 * that ties resolve exactly as over all shapes. `lists[ty·columns + tx]`.
 * @returns {{ columns: number, lists: object[][] }}
 */
export function tileCandidates(scene, camera, y0 = 0, y1 = camera.height) {
  const columns = Math.ceil(camera.width / TILE);
  const ty0 = Math.floor(y0 / TILE), ty1 = Math.ceil(y1 / TILE);
  const lists = [];
  for (let ty = ty0; ty < ty1; ty++) {
    for (let tx = 0; tx < columns; tx++) lists[ty * columns + tx] = [];
  }
  const rect = {};
  for (const object of scene.objects) {
    if (!screenBounds(object, camera, rect)) continue;
    for (let ty = Math.max(ty0, Math.floor(rect.y0 / TILE)); ty <= Math.min(ty1 - 1, Math.floor(rect.y1 / TILE)); ty++) {
      for (let tx = Math.floor(rect.x0 / TILE); tx <= Math.floor(rect.x1 / TILE); tx++) lists[ty * columns + tx].push(object);
    }
  }
  return { columns, lists };
}
