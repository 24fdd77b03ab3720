/**
 * The side and top views: the scene cut along a plane through the eye, with
 * the image plane, the spheres, the lights and the selected ray.
 */
import { isHuge } from '../../modes.js';
import { MUTED, RAY, NORMAL } from './style.js';
import { fmt } from './format.js';
import { panel, closePanel, placeholder, message, mapping, clip, unclip, line, arrow, dot, offset, norm2 } from './draw.js';
import { imagePlane, sphereCircle, hugeArc, shadowRayLine, angleArc, eyeGlyph, lightGlyph, lineKey, axesKey, edgeNote } from './plane-marks.js';

/**
 * The side view: the scene cut along the y–z plane, seen from the right of
 * the camera (−z, "forward", to the right; y up).
 * @param {object} p a p5 instance
 * @param {object} o
 * @param {import('../scene.js').Scene} o.scene
 * @param {import('../camera.js').Camera} o.camera
 * @param {object|null} [o.record] inspectPixel's result, or null before a click
 * @param {number} o.x
 * @param {number} o.y
 * @param {number} o.w
 * @param {number} o.h
 * @param {{umin:number, umax:number, vmin:number, vmax:number}} [o.bounds] world units along the view's axes (u = −z, v = y); default: fitted
 */
export function drawSideView(p, o) {
  drawPlaneView(p, o, SIDE);
}

/**
 * The top view: the scene seen from above, in the x–z plane (x to the right,
 * −z, "forward", up the page). Same options as drawSideView, with u = x, v = −z.
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
  const content = panel(p, x, y, w, h, view.title + (record ? `  ·  pixel ${record.x},${record.y}` : ''));
  if (!scene || !camera) {
    placeholder(p, content, 'Pass a scene and a camera to draw this view.');
    return closePanel(p);
  }
  const pr = (q) => ({ u: view.u(q), v: view.v(q) });
  const eye = pr(camera.position);

  const box = o.bounds ? { ...o.bounds } : fitBounds(scene, record, pr, eye, view.ahead);
  const keyHeight = 26;
  const area = { x: content.x, y: content.y, w: content.w, h: content.h - keyHeight };
  const m = mapping(box, area, 0.05);
  const span = Math.max(box.umax - box.umin, box.vmax - box.vmin);
  const inArea = (q) => m.sx(q.u) > area.x + 4 && m.sx(q.u) < area.x + area.w - 4 && m.sy(q.v) > area.y + 4 && m.sy(q.v) < area.y + area.h - 4;
  clip(p, area);

  // Huge spheres first (the ground), then the frustum and image plane, then spheres.
  for (const s of scene.spheres) if (isHuge(s)) hugeArc(p, m, pr(s.center), s.radius, eye, s, s === record?.hit?.object);

  // The image plane at a display distance: any distance gives the same rays
  // (similar triangles), so put it between the eye and the nearest sphere.
  const D = imagePlaneDistance(scene, pr, eye, span);
  const f = camera.forward, a = camera[view.across], half = camera[view.half] * D;
  const centre = offset(camera.position, f, D);
  const top = pr(offset(centre, a, half)), bottom = pr(offset(centre, a, -half));
  const far = 4 * span;
  for (const end of [top, bottom]) {
    const dir = norm2(end.u - eye.u, end.v - eye.v);
    line(p, m, eye, { u: eye.u + dir.u * far, v: eye.v + dir.v * far }, MUTED, 1.5, [6, 5]);
  }
  // straight ahead: the axis the angle is measured from
  line(p, m, eye, { u: eye.u + view.ahead.u * span * 0.35, v: eye.v + view.ahead.v * span * 0.35 }, MUTED, 1, [2, 4]);

  for (const s of scene.spheres) {
    if (!isHuge(s) && !s.material.isEmissive) sphereCircle(p, m, pr(s.center), s.radius, s, s === record?.hit?.object);
  }
  // Lights: drawn where they are, or, when far off the view, as a marker on
  // its edge in their direction (the shadow rays still point at them).
  const hitAt = record?.hit ? pr(record.hit.point) : null;
  for (const light of scene.lights) {
    const at = pr(light.position), name = light.source?.name || 'light';
    if (inArea(at)) {
      if (light.object && !isHuge(light.object)) sphereCircle(p, m, at, light.object.radius, light.object, false);
      else lightGlyph(p, m.sx(at.u), m.sy(at.v), name);
    } else {
      const from = hitAt ?? { u: (box.umin + box.umax) / 2, v: (box.vmin + box.vmax) / 2 };
      const edge = toEdge(m.sx(from.u), m.sy(from.v), m.sx(at.u), m.sy(at.v), area, 16);
      lightGlyph(p, edge.x, edge.y, `${name} (off view)`, area);
    }
  }

  imagePlane(p, m, top, bottom, camera[view.cells], record ? view.cellOf(record) : null, record?.color, view);
  eyeGlyph(p, m.sx(eye.u), m.sy(eye.v));

  if (record) {
    const ray = record.ray, hit = record.hit;
    const end = hit ? hitAt : pr(offset(ray.origin, ray.direction, far));
    if (hit) {
      for (const l of hit.lights) shadowRayLine(p, m, hitAt, pr(l.position), l);
      arrow(p, m, hitAt, pr(offset(hit.point, hit.normal, 0.1 * span)), NORMAL, 3, 'N');
    }
    line(p, m, eye, end, RAY, 3.5, hit ? [] : [10, 6]);
    if (hit) {
      dot(p, m.sx(end.u), m.sy(end.v), 5, RAY);
      if (!inArea(end)) edgeNote(p, area, `hit at t = ${fmt(hit.t)}, off the view →`);
    } else {
      edgeNote(p, area, 'no hit: the background colour');
    }
    angleArc(p, m, eye, view, pr(offset(ray.origin, ray.direction, 1)), view.angle(record));
  } else {
    message(p, area, 'Click a pixel to see its ray');
  }
  unclip(p);
  axesKey(p, area, view.axes);
  lineKey(p, { x: content.x, y: content.y + content.h - keyHeight + 4, w: content.w });
  closePanel(p);
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

/** The point where the segment from (x0, y0) toward (x1, y1) leaves `area` shrunk by `inset`. */
function toEdge(x0, y0, x1, y1, area, inset) {
  const left = area.x + inset, right = area.x + area.w - inset, top = area.y + inset, bottom = area.y + area.h - inset;
  x0 = Math.min(right, Math.max(left, x0)); y0 = Math.min(bottom, Math.max(top, y0));
  const dx = x1 - x0, dy = y1 - y0;
  let s = 1;
  if (dx > 0) s = Math.min(s, (right - x0) / dx);
  if (dx < 0) s = Math.min(s, (left - x0) / dx);
  if (dy > 0) s = Math.min(s, (bottom - y0) / dy);
  if (dy < 0) s = Math.min(s, (top - y0) / dy);
  return { x: x0 + dx * s, y: y0 + dy * s };
}
