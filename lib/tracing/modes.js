/**
 * Visual modes: other ways to colour each pixel, shown beside the shaded
 * picture so a class can *see* the numbers of the lesson — the discriminant
 * B² − 4AC, how many roots, the ray's H and V angles, normals and depth t.
 *
 * Every mode is a shader with the signature of `renderPixel`:
 * `(scene, camera, x, y, target) => void`, writing pixel (x, y)'s RGBA bytes
 * at (y·width + x)·4. Shaders allocate nothing: scratch objects live here.
 */
import { Ray } from '../math/ray.js';
import { copy, scaleAndAdd, Vec3 } from '../math/vec3.js';
import { angles, horizontalAngle, verticalAngle } from '../math/camera.js';
import { intersectQuadratic } from '../shapes/sphere.js';
import { ballOf } from '../shapes/index.js';
import { nearestHit } from './trace.js';
import { shapeName } from '../scene/scene.js';
import { renderPixel } from './render.js';
import { toHex, colorToHex } from '../math/color.js';
import { formatRounded, formatPowerOfTen } from '../text/format.js';

/** Every mode, in the order a menu shows them, with one line for students. */
export const MODES = [
  { name: 'shaded', label: 'Shaded', description: 'The picture itself: the colour each ray brings back.' },
  { name: 'discriminant', label: 'Discriminant', description: 'B² − 4AC for the sphere the ray meets: blue = misses, yellow = just touches, red = goes through.' },
  { name: 'roots', label: 'Roots', description: 'How many real solutions t the quadratic has: 0, 1 (tangent) or 2.' },
  { name: 'h', label: 'H angle', description: 'How far left (−) or right (+) each ray points, in degrees.' },
  { name: 'v', label: 'V angle', description: 'How far down (−) or up (+) each ray points, in degrees.' },
  { name: 'normals', label: 'Normals', description: 'Which way the surface faces where the ray hits: x → red, y → green, z → blue.' },
  { name: 'depth', label: 'Depth (t)', description: 'How far the ray travels before it hits: near is bright, far is dark.' },
];

/* ---- colour maps: [t, r, g, b] stops, t in 0–1, channels 0–255 ---- */

/** Discriminant, negative side: from pale blue near 0 to deep navy. */
const MISS_RAMP = [[0, 214, 232, 255], [0.35, 110, 160, 235], [0.7, 40, 80, 190], [1, 12, 22, 90]];
/** Discriminant, positive side: from yellow near 0 through orange to dark red. */
const HIT_RAMP = [[0, 255, 236, 120], [0.35, 255, 160, 50], [0.7, 220, 60, 30], [1, 120, 10, 20]];
/** Tangent: the discriminant is 0 (to the tolerance intersectQuadratic uses). */
const TANGENT_RGB = [255, 255, 200];
/** Angles: purple for negative, white at 0, orange for positive (a diverging map). */
const ANGLE_RAMP = [[0, 84, 39, 136], [0.25, 153, 142, 195], [0.5, 247, 247, 247], [0.75, 241, 163, 64], [1, 179, 88, 6]];
/** Roots: 0, 1, 2. */
const ROOT_RGB = [[44, 62, 110], [255, 214, 0], [230, 60, 50]];
/** Depth: near bright, far dark. */
const DEPTH_RAMP = [[0, 255, 255, 255], [1, 40, 40, 40]];
const NO_HIT_RGB = [0, 0, 0];

/** Discriminant magnitudes are shown on a log scale up to 10^DECADES (more is clamped). */
const DECADES = 6;

/* ---- scratch: one of each, reused for every pixel ---- */
const _ray = new Ray();
const _quadratic = { A: 0, B: 0, C: 0, discriminant: 0, roots: 0, t0: 0, t1: 0, t: 0 };
const _hit = { object: null, t: Infinity };
const _point = new Vec3();
const _normal = new Vec3();
const _rgb = [0, 0, 0];
/** What `sphereFocus` found: the sphere that matters, its discriminant and root count. */
const _focus = { index: -1, discriminant: 0, roots: 0 };

/**
 * The shader of a mode: `(scene, camera, x, y, target) => void`, the same
 * signature as `renderPixel` (which is the 'shaded' mode).
 * @param {string} name one of MODES' names
 */
export function modeShader(name) {
  const shader = SHADERS[name];
  if (!shader) throw new RangeError(`mode must be one of ${MODES.map((m) => `'${m.name}'`).join(', ')}, got '${name}'`);
  return shader;
}

const SHADERS = {
  shaded: renderPixel,

  discriminant(scene, camera, x, y, target) {
    primaryRay(camera, x, y);
    if (sphereFocus(scene.objects, _ray, _focus) < 0) return put(target, camera, x, y, NO_HIT_RGB);
    put(target, camera, x, y, discriminantColor(_focus.discriminant, _focus.roots, _rgb));
  },

  roots(scene, camera, x, y, target) {
    primaryRay(camera, x, y);
    if (sphereFocus(scene.objects, _ray, _focus) < 0) return put(target, camera, x, y, NO_HIT_RGB);
    put(target, camera, x, y, ROOT_RGB[_focus.roots]);
  },

  h(scene, camera, x, y, target) {
    primaryRay(camera, x, y);
    const h = horizontalAngle(_ray.direction);
    put(target, camera, x, y, angleColor(h, angleRange(camera).h, _rgb));
  },

  v(scene, camera, x, y, target) {
    primaryRay(camera, x, y);
    const v = verticalAngle(_ray.direction);
    put(target, camera, x, y, angleColor(v, angleRange(camera).v, _rgb));
  },

  normals(scene, camera, x, y, target) {
    primaryRay(camera, x, y);
    if (!nearestHit(scene.objects, _ray, _hit)) return put(target, camera, x, y, NO_HIT_RGB);
    scaleAndAdd(_point, _ray.origin, _ray.direction, _hit.t);
    _hit.object.normalAt(_point, _normal);
    _rgb[0] = (_normal.x + 1) * 127.5;
    _rgb[1] = (_normal.y + 1) * 127.5;
    _rgb[2] = (_normal.z + 1) * 127.5;
    put(target, camera, x, y, _rgb);
  },

  depth(scene, camera, x, y, target) {
    primaryRay(camera, x, y);
    if (!nearestHit(scene.objects, _ray, _hit)) return put(target, camera, x, y, NO_HIT_RGB);
    const { near, far } = depthRange(scene, camera);
    put(target, camera, x, y, ramp(DEPTH_RAMP, (_hit.t - near) / (far - near), _rgb));
  },
};

/** The camera's ray through pixel (x, y) into the scratch ray (exactly the renderer's). */
function primaryRay(camera, x, y) {
  copy(_ray.origin, camera.position);
  camera.directionAt(x, y, _ray.direction);
}

/**
 * The sphere whose quadratic a pixel shows, in the discriminant and roots
 * modes and in the diagrams alike: the nearest sphere the ray hits (smallest
 * t > 0), even behind a plane or a box that hides it, since the quadratic is a
 * sphere's; when it hits none, the closest miss — the largest (least negative)
 * discriminant. A sphere whose two roots are both behind the eye (t < 0) is
 * skipped then: the line through the eye meets it, the ray does not (a huge
 * ground sphere under the eye would paint the whole sky "two roots"); it is
 * chosen only when every sphere is like that. Other objects are skipped.
 * Writes `out` (`index` in `objects`, `discriminant`, `roots`) and returns
 * the index, -1 when there is no sphere. Allocates nothing.
 * @param {object[]} objects the scene's objects (or just its spheres)
 * @param {import('../math/ray.js').Ray} ray
 * @param {{ index: number, discriminant: number, roots: number }} [out]
 */
export function sphereFocus(objects, ray, out = { index: -1, discriminant: 0, roots: 0 }) {
  let nearest = Infinity, behind = false;
  out.index = -1;
  out.discriminant = -Infinity;
  for (let i = 0; i < objects.length; i++) {
    const sphere = ballOf(objects[i]); // the quadratic is a ball's
    if (!sphere) continue;
    const q = intersectQuadratic(ray, sphere, _quadratic);
    let take;
    if (q.t !== null) {
      take = q.t < nearest;
      if (take) nearest = q.t;
    } else if (nearest === Infinity) {
      const isBehind = q.roots > 0;
      // a miss in front beats any sphere behind; among equals, the larger discriminant
      take = out.index < 0 || (behind && !isBehind) || (behind === isBehind && q.discriminant > out.discriminant);
      if (take) behind = isBehind;
    }
    if (take) {
      out.index = i;
      out.discriminant = q.discriminant;
      out.roots = q.roots;
    }
  }
  return out.index;
}

/**
 * Colour of a discriminant: blue shades below 0, yellow-white at 0 (tangent),
 * yellow → orange → red above 0; the shade is log10(1 + |discriminant|), so
 * each step of the legend is ×10. Writes 0–255 channels into `out`.
 */
export function discriminantColor(discriminant, roots, out = [0, 0, 0]) {
  if (roots === 1) return setRgb(out, TANGENT_RGB);
  const shade = Math.log10(1 + Math.abs(discriminant)) / DECADES;
  return ramp(discriminant < 0 ? MISS_RAMP : HIT_RAMP, shade, out);
}

/** Colour of an angle (degrees) on the diverging map, ±range at the ends. */
export function angleColor(angle, range, out = [0, 0, 0]) {
  return ramp(ANGLE_RAMP, 0.5 + angle / (2 * range), out);
}

/* ---- ranges that depend on the camera or the scene, cached until they change ---- */

const _angles = { camera: null, width: 0, height: 0, fov: 0, yaw: 0, pitch: 0, h: 1, v: 1 };

/**
 * The largest |H| and |V| (degrees) of the camera's rays, rounded up to a
 * multiple of 5: the ends of the angle maps' colour scale. 0 is always in
 * the middle, so a turned camera still shows "straight ahead" as white.
 */
export function angleRange(camera) {
  const c = _angles;
  if (c.camera === camera && c.width === camera.width && c.height === camera.height &&
      c.fov === camera.fov && c.yaw === camera.yaw && c.pitch === camera.pitch) return c;
  let h = 0, v = 0;
  const d = new Vec3(), W = camera.width - 1, H = camera.height - 1;
  // The extremes lie on the image's border: corners and edge midpoints.
  for (const [px, py] of [[0, 0], [W, 0], [0, H], [W, H], [W / 2, 0], [W / 2, H], [0, H / 2], [W, H / 2]]) {
    const a = angles(camera.directionAt(px, py, d));
    h = Math.max(h, Math.abs(a.h));
    v = Math.max(v, Math.abs(a.v));
  }
  Object.assign(c, {
    camera, width: camera.width, height: camera.height, fov: camera.fov, yaw: camera.yaw, pitch: camera.pitch,
    h: Math.max(5, Math.ceil(h / 5) * 5), v: Math.max(5, Math.ceil(v / 5) * 5),
  });
  return c;
}

const _depth = { scene: null, objects: null, count: 0, camera: null, width: 0, height: 0, fov: 0, yaw: 0, pitch: 0, px: 0, py: 0, pz: 0, near: 0, far: 1 };

/**
 * The t range of the depth map, scaled to what this camera sees: from the
 * nearest hit of a coarse 16×12 sample of rays to the farthest hit on an
 * object of ordinary size (a huge ground sphere running to the horizon
 * would otherwise make everything else look equally near).
 */
export function depthRange(scene, camera) {
  const c = _depth, p = camera.position;
  if (c.scene === scene && c.objects === scene.objects && c.count === scene.objects.length &&
      c.camera === camera && c.width === camera.width && c.height === camera.height &&
      c.fov === camera.fov && c.yaw === camera.yaw && c.pitch === camera.pitch &&
      c.px === p.x && c.py === p.y && c.pz === p.z) return c;
  let near = Infinity, far = 0, farAny = 0;
  const ray = new Ray(), hit = { object: null, t: Infinity };
  copy(ray.origin, p);
  for (let j = 0; j < 12; j++) {
    for (let i = 0; i < 16; i++) {
      camera.directionAt(((i + 0.5) / 16) * camera.width - 0.5, ((j + 0.5) / 12) * camera.height - 0.5, ray.direction);
      if (!nearestHit(scene.objects, ray, hit)) continue;
      near = Math.min(near, hit.t);
      farAny = Math.max(farAny, hit.t);
      if (!isHuge(hit.object)) far = Math.max(far, hit.t);
    }
  }
  if (near === Infinity) { near = 0; far = 1; }
  if (far <= near) far = farAny > near ? farAny : near + 1;
  Object.assign(c, {
    scene, objects: scene.objects, count: scene.objects.length, camera,
    width: camera.width, height: camera.height, fov: camera.fov, yaw: camera.yaw, pitch: camera.pitch,
    px: p.x, py: p.y, pz: p.z,
    near: Math.floor(near), far: Math.ceil(far),
  });
  return c;
}

/**
 * True for a sphere so big it stands for a ground or a wall (radius ≥ 100):
 * depth scales and diagrams leave its full size out. (homework.js's HUGE asks
 * "could this be part of a car?" and rays3d.js's HUGE_RADIUS "draw it as a
 * patch of ground?": other questions, other thresholds.)
 */
export function isHuge(object) {
  return (ballOf(object)?.radius ?? 0) >= 100;
}

/* ---- legends ---- */

/**
 * What a legend beside a mode's picture shows:
 * `{ title, kind: 'gradient'|'swatches', stops: [{ value, label, color: '#rrggbb' }], note }`.
 * 'gradient' stops are points of a continuous scale in order; 'swatches'
 * are separate categories.
 */
export function modeLegend(name, scene, camera) {
  modeShader(name); // checks the name
  const mode = MODES.find((m) => m.name === name);
  const legend = LEGENDS[name](scene, camera);
  return { title: mode.label, note: mode.description, ...legend };
}

const LEGENDS = {
  shaded(scene) {
    const stops = scene.objects.map((o, i) => {
      const m = o.material, emits = m.isEmissive;
      return { value: i, label: shapeName(o, scene.objects) + (emits ? ' (light)' : ''), color: colorToHex(emits ? m.emission : m.color) };
    });
    stops.push({ value: null, label: 'background', color: colorToHex(scene.background) });
    return { kind: 'swatches', stops };
  },

  discriminant() {
    const stops = [];
    for (const value of [-1e6, -1e4, -100, -1, 0, 1, 100, 1e4, 1e6]) {
      const label = value === 0 ? '0 tangent' : (value < 0 ? '−' : '+') + formatPowerOfTen(Math.abs(value));
      stops.push({ value, label, color: toHex(discriminantColor(value, value === 0 ? 1 : 2)) });
    }
    return {
      kind: 'gradient', stops,
      note: 'B² − 4AC of the nearest sphere the ray hits, or of its closest miss. Below 0 (blue): no hit. 0 (yellow): the ray just touches. Above 0 (red): two hits. Each step is ×10. Black: no sphere at all.',
    };
  },

  roots() {
    return {
      kind: 'swatches',
      stops: ['0 roots: no hit', '1 root: tangent', '2 roots: in and out'].map((label, value) => ({ value, label, color: toHex(ROOT_RGB[value]) })),
    };
  },

  h(scene, camera) {
    return angleLegend(angleRange(camera).h, 'left', 'right', 'H = atan2(dx, −dz): how far left (−) or right (+) the ray points. White: straight ahead along −z.');
  },

  v(scene, camera) {
    return angleLegend(angleRange(camera).v, 'down', 'up', 'V = asin(dy): how far down (−) or up (+) the ray points. White: level.');
  },

  normals() {
    /** @type {Array<[string, number, number, number]>} */
    const n = [['+x right', 1, 0, 0], ['−x left', -1, 0, 0], ['+y up', 0, 1, 0], ['−y down', 0, -1, 0], ['+z toward the eye', 0, 0, 1], ['−z away', 0, 0, -1]];
    const stops = n.map(([label, x, y, z]) => ({ value: [x, y, z], label, color: toHex([(x + 1) * 127.5, (y + 1) * 127.5, (z + 1) * 127.5]) }));
    stops.push({ value: null, label: 'no hit', color: toHex(NO_HIT_RGB) });
    return { kind: 'swatches', stops, note: 'The normal N where the ray hits, as a colour: (N + 1) / 2 → (red, green, blue).' };
  },

  depth(scene, camera) {
    const { near, far } = depthRange(scene, camera);
    const stops = [0, 0.25, 0.5, 0.75, 1].map((s) => {
      const value = near + s * (far - near);
      return { value, label: `t = ${formatRounded(value)}${s === 1 ? '+' : ''}`, color: toHex(ramp(DEPTH_RAMP, s)) };
    });
    return { kind: 'gradient', stops, note: `t, the distance along the ray to the first hit: bright at t = ${formatRounded(near)}, dark at t = ${formatRounded(far)} and beyond. Black: no hit.` };
  },
};

function angleLegend(range, minus, plus, note) {
  const stops = [-1, -0.5, 0, 0.5, 1].map((s) => ({
    value: s * range,
    label: `${s * range > 0 ? '+' : s * range < 0 ? '−' : ''}${Math.abs(s * range)}°${s === -1 ? ' ' + minus : s === 1 ? ' ' + plus : ''}`,
    color: toHex(angleColor(s * range, range)),
  }));
  return { kind: 'gradient', stops, note };
}

/* ---- small helpers ---- */

/** Linear interpolation along a ramp of [t, r, g, b] stops; t clamped to 0–1. */
function ramp(stops, t, out = [0, 0, 0]) {
  t = t > 1 ? 1 : t > 0 ? t : 0; // NaN → 0
  let i = 1;
  while (i < stops.length - 1 && t > stops[i][0]) i++;
  const a = stops[i - 1], b = stops[i];
  const s = (t - a[0]) / (b[0] - a[0]);
  out[0] = a[1] + (b[1] - a[1]) * s;
  out[1] = a[2] + (b[2] - a[2]) * s;
  out[2] = a[3] + (b[3] - a[3]) * s;
  return out;
}

function setRgb(out, rgb) {
  out[0] = rgb[0]; out[1] = rgb[1]; out[2] = rgb[2];
  return out;
}

function put(target, camera, x, y, rgb) {
  const i = (y * camera.width + x) * 4;
  target[i] = rgb[0];
  target[i + 1] = rgb[1];
  target[i + 2] = rgb[2];
  target[i + 3] = 255;
}
