/**
 * The geometry the 3D scene view draws, with no p5 in it: where a pixel sits
 * on the image plane, the plane's corners and pixel grid, the view frustum,
 * and a pixel's whole ray story as straight segments (primary ray, normal,
 * shadow rays, mirror and glass bounces) read from `inspectPixel`'s record, so
 * the 3D picture and the traced picture tell the same story.
 *
 * Points are `Vec3`s in the scene's own coordinates. The camera's image plane
 * sits at distance 1 from the eye (lib/math/camera.js); every ray through a pixel
 * centre also passes through the same pixel of a plane at any other distance,
 * so the view may show it further out, where it is big enough to see.
 */
import { Vec3, dot, cross, normalize, scaleAndAdd, sub, length } from '../math/vec3.js';
import { ballOf } from '../shapes/index.js';
import { nearestHit } from '../tracing/trace.js';
import { show } from '../text/check.js';

/**
 * Spheres bigger than this are drawn as a patch of ground, not a ball. Higher
 * than modes.js's isHuge (radius ≥ 100): in the 3D view a sphere up to this
 * size is still seen whole, as a ball, and frames the view.
 */
export const HUGE_RADIUS = 1000;

/**
 * The point of the image plane at `distance` from the eye under image
 * coordinates (u, v): u from 0 (left edge) to width, v from 0 (top edge) to
 * height; the centre of pixel (x, y) is (x + 0.5, y + 0.5).
 */
export function imagePoint(camera, u, v, distance = 1, out = new Vec3()) {
  const sx = (2 * u / camera.width - 1) * camera.halfWidth;
  const sy = (1 - 2 * v / camera.height) * camera.halfHeight;
  const e = camera.position, r = camera.right, up = camera.up, f = camera.forward;
  out.x = e.x + distance * (f.x + sx * r.x + sy * up.x);
  out.y = e.y + distance * (f.y + sx * r.y + sy * up.y);
  out.z = e.z + distance * (f.z + sx * r.z + sy * up.z);
  return out;
}

/** The centre of pixel (x, y) on the image plane at `distance`: the primary ray passes through it. */
export function pixelCenter(camera, x, y, distance = 1, out = new Vec3()) {
  return imagePoint(camera, x + 0.5, y + 0.5, distance, out);
}

/**
 * The image plane at `distance`: its corners (top-left, top-right,
 * bottom-right, bottom-left), centre, and size in scene units.
 */
export function imagePlane(camera, distance = 1) {
  const W = camera.width, H = camera.height;
  return {
    distance,
    corners: [imagePoint(camera, 0, 0, distance), imagePoint(camera, W, 0, distance), imagePoint(camera, W, H, distance), imagePoint(camera, 0, H, distance)],
    center: imagePoint(camera, W / 2, H / 2, distance),
    width: 2 * camera.halfWidth * distance,
    height: 2 * camera.halfHeight * distance,
  };
}

/**
 * The pixel grid on the image plane at `distance`, at the traced resolution:
 * `columns` (width + 1 lines, left to right) and `rows` (height + 1, top to
 * bottom), each line `[from, to]`.
 */
export function pixelGrid(camera, distance = 1) {
  const W = camera.width, H = camera.height;
  const columns = [], rows = [];
  for (let u = 0; u <= W; u++) columns.push([imagePoint(camera, u, 0, distance), imagePoint(camera, u, H, distance)]);
  for (let v = 0; v <= H; v++) rows.push([imagePoint(camera, 0, v, distance), imagePoint(camera, W, v, distance)]);
  return { columns, rows };
}

/**
 * The view frustum: the eye and the four corner edges out to `far`
 * (a distance along the view direction), as `{ eye, near, far }` corner lists.
 */
export function frustum(camera, far, near = 1) {
  return { eye: camera.position, near: imagePlane(camera, near).corners, far: imagePlane(camera, far).corners };
}

/**
 * Which pixel of the image plane at `distance` a ray (origin, unit
 * direction, e.g. from the 3D view's own camera through the mouse) meets:
 * `{ x, y, point, t }`, or null when it misses the picture.
 */
export function pickImagePlane(camera, distance, origin, direction) {
  const f = camera.forward;
  const denom = dot(direction, f);
  if (Math.abs(denom) < 1e-12) return null; // along the plane
  const center = imagePoint(camera, camera.width / 2, camera.height / 2, distance);
  const t = dot(sub(new Vec3(), center, origin), f) / denom;
  if (!(t > 0)) return null;
  const point = scaleAndAdd(new Vec3(), origin, direction, t);
  const offset = sub(new Vec3(), point, center);
  const sx = dot(offset, camera.right) / distance, sy = dot(offset, camera.up) / distance;
  const u = ((sx / camera.halfWidth + 1) / 2) * camera.width;
  const v = ((1 - sy / camera.halfHeight) / 2) * camera.height;
  if (u < 0 || v < 0 || u >= camera.width || v >= camera.height) return null;
  return { x: Math.floor(u), y: Math.floor(v), point, t };
}

/**
 * The pixel's story as straight segments, from `inspectPixel`'s record, in
 * the order they happen: `{ kind, from, to, depth, ... }` with `kind`
 *   'primary'     eye → hit (`hit: true`), or `missLength` along the ray (`hit: false`);
 *   'normal'      hit point → `normalLength` along the normal;
 *   'shadow'      hit point → light, `lit` (reaches it), `facing` (the light is in front of the surface),
 *                 `blockedAt` (first thing in the way, or null), `light` (its source);
 *   'reflection'  and 'refraction': one bounce to the next hit or `missLength` out, down to scene.maxDepth.
 * Bounces come after the shadow rays of the point they leave; each bounce's own
 * normal and shadow rays follow it.
 */
export function raySegments(scene, record, { missLength = 40, normalLength = 2 } = {}) {
  if (!record || !record.ray) throw new TypeError(`raySegments needs inspectPixel's record, got ${show(record)}`);
  const out = [];
  const ray = record.ray;
  addRay(out, scene, 'primary', 0, ray.origin, ray.direction, record.hit, { missLength, normalLength });
  return out;
}

function addRay(out, scene, kind, depth, origin, direction, hit, opts) {
  if (!hit) {
    out.push({ kind, depth, hit: false, from: origin, to: scaleAndAdd(new Vec3(), origin, direction, opts.missLength) });
    return;
  }
  out.push({ kind, depth, hit: true, from: origin, to: hit.point, object: hit.object, t: hit.t });
  out.push({ kind: 'normal', depth, from: hit.point, to: scaleAndAdd(new Vec3(), hit.point, hit.normal, opts.normalLength) });
  for (const l of hit.lights) {
    out.push({
      kind: 'shadow', depth, from: hit.point, to: l.position, light: l.light,
      facing: l.facing, lit: l.facing && !l.inShadow, transmission: l.transmission, ...(l.sample !== undefined && { sample: l.sample }),
      blockedAt: l.blockedAt,
    });
  }
  if (hit.reflection) addRay(out, scene, 'reflection', depth + 1, hit.point, hit.reflection.direction, hit.reflection.hit, opts);
  if (hit.refraction) addRay(out, scene, 'refraction', depth + 1, hit.point, hit.refraction.direction, hit.refraction.hit, opts);
}

/**
 * Pixel (x, y)'s primary ray alone, as raySegments' first segment (eye → its
 * nearest hit, or `missLength` out), found by trace.js's nearestHit without
 * the pixel's whole record: the 3D view's fan of a row's rays wants only these.
 */
export function primarySegment(scene, camera, x, y, { missLength = 40 } = {}) {
  const { ray } = camera.primaryRay(x, y), hit = { object: null, t: Infinity }, o = ray.origin, d = ray.direction;
  if (!nearestHit(scene.objects, ray, hit, scene.epsilon)) return { kind: 'primary', depth: 0, hit: false, from: o, to: scaleAndAdd(new Vec3(), o, d, missLength) };
  const point = new Vec3(o.x + d.x * hit.t, o.y + d.y * hit.t, o.z + d.z * hit.t); // P = Ro + Rd·t, as trace.js's surfaceAt
  return { kind: 'primary', depth: 0, hit: true, from: o, to: point, object: hit.object, t: hit.t };
}

/**
 * Several rays per pixel (camera.samples > 1): the record's sub-pixel rays as
 * segments `{ kind: 'sample', from, to, hit, dx, dy, color }`, each to what it
 * hit or `missLength` out; [] for one ray per pixel.
 */
export function sampleSegments(record, { missLength = 40 } = {}) {
  if (!record?.samples) return [];
  return record.samples.map((s) => ({
    kind: 'sample', depth: 0, hit: s.t !== null, dx: s.dx, dy: s.dy, color: s.color,
    from: s.ray.origin, to: scaleAndAdd(new Vec3(), s.ray.origin, s.ray.direction, s.t ?? missLength),
  }));
}

/**
 * The geometric route drawn in 3D for one sphere and a ray: `L` (origin →
 * centre), `tca` (origin → the ray's closest approach to the centre), `d`
 * (that point → centre), `thc` (that point → the first hit, when d ≤ r),
 * from `intersectGeometric`'s numbers.
 */
export function geometricConstruction(ray, sphere, geometric) {
  const o = ray.origin, c = sphere.center;
  const closest = scaleAndAdd(new Vec3(), o, ray.direction, geometric.tca);
  const parts = {
    L: [o, c], tca: [o, closest], d: [closest, c],
    thc: geometric.thc === null ? null : [closest, scaleAndAdd(new Vec3(), o, ray.direction, geometric.tca - geometric.thc)],
  };
  return parts;
}

/* ---------------- the 3D view's own camera (an orbit) ---------------- */

/**
 * Centre and radius of what the view should frame: the eye, the image plane
 * and every shape and light except huge spheres (a ground) and planes.
 */
export function sceneBounds(scene, camera, planeDistance) {
  const pts = [camera.position, ...imagePlane(camera, planeDistance).corners];
  for (const o of scene.objects) {
    if (ballOf(o)?.radius > HUGE_RADIUS) continue;
    const box = o.bounds();
    if (box) pts.push(box.min, box.max);
  }
  for (const l of scene.lights) pts.push(l.position);
  const min = new Vec3(Infinity, Infinity, Infinity), max = new Vec3(-Infinity, -Infinity, -Infinity);
  for (const p of pts) {
    min.x = Math.min(min.x, p.x); min.y = Math.min(min.y, p.y); min.z = Math.min(min.z, p.z);
    max.x = Math.max(max.x, p.x); max.y = Math.max(max.y, p.y); max.z = Math.max(max.z, p.z);
  }
  const center = new Vec3((min.x + max.x) / 2, (min.y + max.y) / 2, (min.z + max.z) / 2);
  return { center, radius: length(sub(new Vec3(), max, center)), min, max };
}

/**
 * The orbit camera's eye: `distance` from `target`, turned `yaw` degrees
 * about +y (0 = looking toward −z, as the scene's camera does) and raised
 * `pitch` degrees; with its unit `forward`, `right` and `up`.
 */
export function orbitCamera({ target, yaw, pitch, distance }) {
  const a = (yaw * Math.PI) / 180, b = (pitch * Math.PI) / 180;
  const forward = new Vec3(Math.sin(a) * Math.cos(b), -Math.sin(b), -Math.cos(a) * Math.cos(b));
  const eye = scaleAndAdd(new Vec3(), target, forward, -distance);
  const right = normalize(new Vec3(), cross(new Vec3(), forward, new Vec3(0, 1, 0)));
  const up = cross(new Vec3(), right, forward);
  return { eye, target, forward, right, up };
}

/**
 * The ray from the orbit camera through a point of its canvas (px from the
 * top-left of a w × h canvas), for a perspective of vertical field `fovy`
 * (radians): `{ origin, direction }`.
 */
export function screenRay(orbit, px, py, w, h, fovy) {
  const t = Math.tan(fovy / 2);
  const sx = (2 * px / w - 1) * t * (w / h), sy = (1 - 2 * py / h) * t;
  const d = new Vec3(
    orbit.forward.x + sx * orbit.right.x + sy * orbit.up.x,
    orbit.forward.y + sx * orbit.right.y + sy * orbit.up.y,
    orbit.forward.z + sx * orbit.right.z + sy * orbit.up.z,
  );
  return { origin: orbit.eye, direction: normalize(d, d) };
}

/** Where a scene point lands on the orbit camera's canvas (px), or null behind it. */
export function projectToScreen(orbit, point, w, h, fovy) {
  const rel = sub(new Vec3(), point, orbit.eye);
  const z = dot(rel, orbit.forward);
  if (z <= 1e-6) return null;
  const t = Math.tan(fovy / 2);
  const sx = dot(rel, orbit.right) / (z * t * (w / h)), sy = dot(rel, orbit.up) / (z * t);
  return { x: ((sx + 1) / 2) * w, y: ((1 - sy) / 2) * h };
}
