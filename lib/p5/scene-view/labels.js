/**
 * Words over the 3D view: labels at scene points, drawn on a 2D layer above
 * the WEBGL picture (p5's WEBGL text needs a loaded font), and the geometric
 * route of the selected ray for the construction sphere (L, tca, d, thc as
 * lines, each with its value). Placing a label is projecting its point with
 * the orbit camera; a point behind the view has no label.
 */
import { intersectGeometric } from '../../shapes/sphere.js';
import { Vec3 } from '../../math/vec3.js';
import { geometricConstruction, projectToScreen } from '../../lesson/rays3d.js';
import { INK, NORMAL, CONSTRUCT, FONT } from '../diagrams/style.js';

/**
 * The geometric route of `record`'s ray for `sphere`: `{ rays, labels }`,
 * rays `[{ from, to, color, weight }]` and labels `[{ at, text, color, dy }]`
 * part-way along them, so that L and tca (both from the eye) do not sit on
 * each other. Nothing without a sphere or a record.
 */
export function constructionOf(record, sphere) {
  const rays = [], labels = [];
  if (!sphere || !record) return { rays, labels };
  const g = intersectGeometric(record.ray, sphere);
  const parts = geometricConstruction(record.ray, sphere, g);
  const along = ([a, b], k) => new Vec3(a.x + (b.x - a.x) * k, a.y + (b.y - a.y) * k, a.z + (b.z - a.z) * k);
  const add = (seg, color, text, k, dy) => {
    if (!seg) return;
    rays.push({ from: seg[0], to: seg[1], color, weight: 3 });
    labels.push({ at: along(seg, k), text, color, dy });
  };
  add(parts.L, CONSTRUCT, 'L', 0.7, -14);
  add(parts.tca, CONSTRUCT, `tca = ${g.tca.toFixed(2)}`, 0.4, 14);
  add(parts.d, INK, `d = ${Math.sqrt(Math.max(0, g.d2)).toFixed(2)}`, 0.5, 0);
  add(parts.thc, NORMAL, `thc = ${g.thc?.toFixed(2)}`, 0.5, 16);
  return { rays, labels };
}

/**
 * Where each label goes on a width × height canvas seen from `orbit` (lib/lesson/rays3d.js
 * orbitCamera) with vertical field of view `fovy`: `[{ text, color, x, y }]` in
 * CSS px, `y` moved by the label's `dy`; labels behind the view are left out.
 * @param {Array<{ at: {x: number, y: number, z: number}, text: string, color?: string, dy?: number }>} labels
 */
export function placeLabels(labels, orbit, width, height, fovy) {
  const placed = [];
  for (const l of labels) {
    const at = projectToScreen(orbit, l.at, width, height, fovy);
    if (!at) continue;
    placed.push({ text: l.text, color: l.color ?? INK, x: at.x, y: at.y + (l.dy ?? 0) });
  }
  return placed;
}

/** Clears the label layer and writes the placed labels, each on a white halo. */
export function drawLabels(ctx, placed) {
  ctx.clearRect(0, 0, ctx.canvas.width, ctx.canvas.height);
  if (!placed.length) return;
  ctx.font = `bold 14px ${FONT}`;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  for (const l of placed) {
    ctx.lineWidth = 4; ctx.strokeStyle = 'rgba(255, 255, 255, 0.9)';
    ctx.strokeText(l.text, l.x, l.y);
    ctx.fillStyle = l.color;
    ctx.fillText(l.text, l.x, l.y);
  }
}
