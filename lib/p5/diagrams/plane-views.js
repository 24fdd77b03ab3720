/**
 * The side and top views: the scene cut along a plane through the eye, with
 * the image plane, the spheres, the lights and the selected ray.
 */
import { isHuge } from '../../tracing/modes.js';
import { nameDiagram } from './aria.js';
import { colorWord } from '../../lesson/describe.js';
import { MUTED, RAY } from './style.js';
import { formatLabel } from '../../text/format.js';
import { labelPlacer, ON_LABEL, ON_THICK, ON_THIN } from './labels.js';
import { panel, closePanel, placeholder, message, messageBox, mapping, clip, unclip, dot, offset, norm2 } from './draw.js';
import {
  markLine, imagePlane, sphereCircle, hugeArc, shadowRayLine, normalArrow, angleArc, eyeGlyph, lightGlyph, lineKey, axesText, edgeLabel, rayEndNote, toEdge,
} from './plane-marks.js';

/**
 * The side view: the scene cut along the y–z plane, seen from the right of
 * the camera (−z, "forward", to the right; y up).
 * @param {object} p a p5 instance
 * @param {object} o
 * @param {import('../../scene/scene.js').Scene} o.scene
 * @param {import('../../math/camera.js').Camera} o.camera
 * @param {object|null} [o.record] inspectPixel's result, or null before a click
 * @param {number} o.x
 * @param {number} o.y
 * @param {number} o.w
 * @param {number} o.h
 * @param {{umin:number, umax:number, vmin:number, vmax:number}} [o.bounds] world units along the view's axes (u = −z, v = y); default: fitted
 * @example
 * p.draw = () => {
 *   p.background(255);
 *   p.drawSideView({ scene: view.scene, camera: view.camera, record: view.selected, x: 0, y: 0, w: 320, h: 240 });
 * };
 */
export function drawSideView(p, o) {
  drawPlaneView(p, o, SIDE);
}

/**
 * The top view: the scene seen from above, in the x–z plane (x to the right,
 * −z, "forward", up the page). Same options as drawSideView, with u = x, v = −z.
 * @example
 * p.drawTopView({ scene: view.scene, camera: view.camera, record: view.selected, x: 320, y: 0, w: 320, h: 240 });
 */
export function drawTopView(p, o) {
  drawPlaneView(p, o, TOP);
}

const SIDE = {
  title: 'Side view (y–z)',
  axes: ['−z forward →', 'y up ↑'],
  u: (q) => -q.z, v: (q) => q.y,
  across: 'up', half: 'halfHeight', planeLabel: 'below', cells: 'height', cellOf: (r) => r.y, cellWord: 'row',
  angle: (r) => ({ name: 'V', value: r.v }),
  ahead: { u: 1, v: 0 },
};
const TOP = {
  title: 'Top view (x–z)',
  axes: ['x right →', '−z forward ↑'],
  u: (q) => q.x, v: (q) => -q.z,
  across: 'right', half: 'halfWidth', planeLabel: 'beside', cells: 'width', cellOf: (r) => r.x, cellWord: 'column',
  angle: (r) => ({ name: 'H', value: r.h }),
  ahead: { u: 0, v: 1 },
};

function drawPlaneView(p, o, view) {
  const { scene, camera, record = null, x, y, w, h } = o;
  const axes = axesText(view.axes);
  const content = panel(p, x, y, w, h, view.title + (record ? `  ·  pixel ${record.x},${record.y}` : ''), axes);
  if (!scene || !camera) {
    placeholder(p, content, 'Pass a scene and a camera to draw this view.');
    return closePanel(p);
  }
  nameDiagram(p, o, planeViewWords(view, scene, camera, record));
  const keyHeight = 26;
  const area = { x: content.x, y: content.y, w: content.w, h: content.h - keyHeight };
  const pr = (q) => ({ u: view.u(q), v: view.v(q) });
  const eye = pr(camera.position);
  const box = o.bounds ? { ...o.bounds } : fitBounds(scene, record, pr, eye, view.ahead);
  const m = mapping(box, area, 0.05);
  const v = { p, view, m, pr, eye, box, area, span: Math.max(box.umax - box.umin, box.vmax - box.vmin), labels: labelPlacer(p, area, { spacing: 8 }) };
  v.ex = m.sx(eye.u); v.ey = m.sy(eye.v);
  clip(p, area);

  // Every mark first, each kept clear of labels, in drawing order: the
  // ground, the camera's frustum, the spheres, the lights, the image plane,
  // the eye, the ray. Each returns its label(s), placed after.
  const grounds = scene.spheres.filter(isHuge).map((s) => hugeArc(p, m, v.labels, pr(s.center), s.radius, eye, s, s === record?.hit?.object));
  const { top, bottom } = frustum(v, scene, camera);
  const spheres = scene.spheres.filter((s) => !isHuge(s) && !s.material.isEmissive)
    .map((s) => sphereCircle(p, m, v.labels, pr(s.center), s.radius, s, s === record?.hit?.object));
  const lights = scene.lights.map((light) => lightMark(v, light, record));
  const plane = imagePlane(p, m, v.labels, top, bottom, camera[view.cells], record ? view.cellOf(record) : null, record?.color, view);
  const eyeName = eyeGlyph(p, v.labels, v.ex, v.ey);
  const ray = record ? rayMarks(v, record) : { note: null, angle: null, normal: null };
  const card = record ? null : placeCard(v.labels, area);

  // The labels, most telling first: each takes the free place nearest its mark.
  const axesLabel = content.noteShown ? null : edgeLabel(area, axes, { color: MUTED, size: 12 });
  for (const l of [ray.note, eyeName, ray.angle, plane, ray.normal, axesLabel, ...spheres, ...lights, ...grounds]) {
    if (l) v.labels.put(l.text, l.places, l.style, l);
  }
  if (card) message(p, card, 'Click a pixel to see its ray');
  unclip(p);
  lineKey(p, { x: content.x, y: content.y + content.h - keyHeight + 4, w: content.w });
  closePanel(p);
}

/** What a side or top view shows, in a few words: its spheres, lights and the selected ray. */
function planeViewWords(view, scene, camera, record) {
  const spheres = scene.spheres.filter((s) => !s.material.isEmissive).map((s) => (isHuge(s) ? 'the ground' : `${s.name || colorWord(s.material.color)}`));
  const shown = `${view.title}: the eye, the image plane of ${camera[view.cells]} ${view.cellWord}s, ${spheres.length ? `the spheres ${spheres.join(', ')}` : 'no spheres'} and ${scene.lights.length} ${scene.lights.length === 1 ? 'light' : 'lights'}.`;
  if (!record) return `${shown} Click a pixel to see its ray.`;
  const { name, value } = view.angle(record);
  const hit = record.hit ? `hits ${record.hit.object.name || 'an object'} at t = ${formatLabel(record.hit.t)}` : 'hits nothing';
  return `${shown} The ray of pixel ${record.x},${record.y}, ${name} = ${formatLabel(value)}°, ${hit}.`;
}

/**
 * The frustum's edges and the straight-ahead axis; returns the image
 * plane's ends. The image plane sits at a display distance: any distance
 * gives the same rays (similar triangles), so it goes between the eye and
 * the nearest sphere.
 */
function frustum(v, scene, camera) {
  const { p, m, labels, pr, eye, span, view } = v;
  const D = imagePlaneDistance(scene, pr, eye, span);
  const a = camera[view.across], half = camera[view.half] * D;
  const centre = offset(camera.position, camera.forward, D);
  const top = pr(offset(centre, a, half)), bottom = pr(offset(centre, a, -half));
  for (const end of [top, bottom]) {
    const dir = norm2(end.u - eye.u, end.v - eye.v);
    markLine(p, m, labels, eye, { u: eye.u + dir.u * 4 * span, v: eye.v + dir.v * 4 * span }, MUTED, 1.5, [6, 5], ON_THIN);
  }
  // straight ahead: the axis the angle is measured from
  markLine(p, m, labels, eye, { u: eye.u + view.ahead.u * span * 0.35, v: eye.v + view.ahead.v * span * 0.35 }, MUTED, 1, [2, 4], ON_THIN);
  return { top, bottom };
}

/**
 * A light drawn where it is, or, when far off the view, as a marker on its
 * edge in its direction from the hit (the shadow rays still point at it).
 */
function lightMark(v, light, record) {
  const { p, m, labels, pr, box, area } = v;
  const at = pr(light.position), name = light.source?.name || 'light';
  const x = m.sx(at.u), y = m.sy(at.v);
  if (x > area.x + 4 && x < area.x + area.w - 4 && y > area.y + 4 && y < area.y + area.h - 4) {
    if (light.object && !isHuge(light.object)) return sphereCircle(p, m, labels, at, light.object.radius, light.object, false);
    return lightGlyph(p, labels, x, y, name);
  }
  const from = record?.hit ? pr(record.hit.point) : { u: (box.umin + box.umax) / 2, v: (box.vmin + box.vmax) / 2 };
  const edge = toEdge(m.sx(from.u), m.sy(from.v), x, y, area, 16);
  return lightGlyph(p, labels, edge.x, edge.y, name, area);
}

/** The ray, its shadow rays, the normal and the angle; returns their labels. */
function rayMarks(v, record) {
  const { p, m, labels, pr, eye, span, area, view } = v;
  const { ray, hit } = record;
  const end = hit ? pr(hit.point) : pr(offset(ray.origin, ray.direction, 4 * span));
  const x1 = m.sx(end.u), y1 = m.sy(end.v);
  let normal = null;
  if (hit) {
    for (const l of hit.lights) shadowRayLine(p, m, labels, end, pr(l.position), l);
    const tip = pr(offset(hit.point, hit.normal, 0.1 * span));
    normal = normalArrow(p, labels, x1, y1, m.sx(tip.u), m.sy(tip.v));
  }
  markLine(p, m, labels, eye, end, RAY, 3.5, hit ? [] : [10, 6], ON_THICK);
  const inView = x1 > area.x + 4 && x1 < area.x + area.w - 4 && y1 > area.y + 4 && y1 < area.y + area.h - 4;
  if (hit) {
    dot(p, x1, y1, 5, RAY);
    labels.keepClearCircle(x1, y1, 6, ON_LABEL, { disc: true });
  }
  const note = !hit ? 'no hit: the background colour' : inView ? null : `hit at t = ${formatLabel(hit.t)}, off the view →`;
  const along = pr(ray.direction);
  return {
    note: note && rayEndNote(area, v.ex, v.ey, x1, y1, note),
    angle: angleArc(p, labels, v.ex, v.ey, view, along, view.angle(record)),
    normal,
  };
}

/** Where the card asking for a click goes: the middle, else above, below, at the bottom or top, off the eye and the plane. */
function placeCard(labels, area) {
  const { w, h } = messageBox(), mx = area.x + area.w / 2, my = area.y + area.h / 2;
  const heights = [my, my - area.h / 4, my + area.h / 4, area.y + area.h - h / 2 - 6, area.y + h / 2 + 6];
  const card = labels.find(w, h, [0, -1, 1].flatMap((k) => heights.map((cy) => [mx + (k * area.w) / 5, cy]))).box;
  labels.take(card);
  return card;
}

/**
 * Bounds (u, v) around what matters: the eye (with room behind it for its
 * labels), the ordinary spheres, boxes and a hit point. Lights count only
 * when near; far ones become markers on the edge. A huge sphere adds just
 * its surface nearest the eye, so the ground line shows.
 */
function fitBounds(scene, record, pr, eye, ahead) {
  const b = { umin: eye.u, umax: eye.u, vmin: eye.v, vmax: eye.v };
  const grow = (q, r = 0) => {
    b.umin = Math.min(b.umin, q.u - r); b.umax = Math.max(b.umax, q.u + r);
    b.vmin = Math.min(b.vmin, q.v - r); b.vmax = Math.max(b.vmax, q.v + r);
  };
  for (const s of scene.spheres) {
    if (s.material.isEmissive) continue;
    if (!isHuge(s)) grow(pr(s.center), s.radius);
    else {
      const c = pr(s.center), d = Math.hypot(eye.u - c.u, eye.v - c.v);
      if (d > s.radius) grow({ u: c.u + ((eye.u - c.u) * s.radius) / d, v: c.v + ((eye.v - c.v) * s.radius) / d });
    }
  }
  for (const o of scene.objects) if (o.min && o.max) { grow(pr(o.min)); grow(pr(o.max)); }
  let size = Math.max(b.umax - b.umin, b.vmax - b.vmin, 2);
  if (record?.hit) {
    const q = pr(record.hit.point);
    // a hit far out on the ground is drawn off the edge, with a note
    if (q.u > b.umin - size && q.u < b.umax + size && q.v > b.vmin - size && q.v < b.vmax + size) grow(q);
  }
  size = Math.max(b.umax - b.umin, b.vmax - b.vmin, 2);
  const near = { umin: b.umin - 0.3 * size, umax: b.umax + 0.3 * size, vmin: b.vmin - 0.3 * size, vmax: b.vmax + 0.3 * size };
  for (const light of scene.lights) {
    const q = pr(light.position), r = light.object?.radius ?? 0;
    if (q.u >= near.umin && q.u <= near.umax && q.v >= near.vmin && q.v <= near.vmax) grow(q, r < 100 ? r : 0);
  }
  // room behind the eye for its label and the angle's
  grow({ u: eye.u - ahead.u * 0.18 * size, v: eye.v - ahead.v * 0.18 * size });
  if (b.umax - b.umin < 2) { b.umin -= 1; b.umax += 1; }
  if (b.vmax - b.vmin < 2) { b.vmin -= 1; b.vmax += 1; }
  return b;
}

/** Where to draw the image plane: 40% of the way to the nearest sphere, within limits. */
function imagePlaneDistance(scene, pr, eye, span) {
  let nearest = Infinity;
  for (const s of scene.spheres) {
    if (isHuge(s) || s.material.isEmissive) continue;
    const c = pr(s.center);
    nearest = Math.min(nearest, Math.hypot(c.u - eye.u, c.v - eye.v) - s.radius);
  }
  const D = Number.isFinite(nearest) && nearest > 0 ? 0.4 * nearest : 0.15 * span;
  return Math.min(0.25 * span, Math.max(0.08 * span, D));
}
