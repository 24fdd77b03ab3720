// Words over the 3D view (lib/p5/scene-view/labels.js): where a label lands on
// the canvas for a point of view, and the geometric route's lines and values.
import { describe, it, expect } from 'vitest';
import { Vec3 } from '../../lib/math/vec3.js';
import { Ray } from '../../lib/math/ray.js';
import { Sphere, intersectGeometric } from '../../lib/shapes/sphere.js';
import { orbitCamera } from '../../lib/lesson/rays3d.js';
import { constructionOf, placeLabels, drawLabels } from '../../lib/p5/scene-view/labels.js';
import { INK, CONSTRUCT, NORMAL } from '../../lib/p5/diagrams/style.js';

const FOVY = Math.PI / 3, W = 480, H = 360;
/** Looking toward −z at the origin from 10 units away. */
const ORBIT = orbitCamera({ target: new Vec3(0, 0, 0), yaw: 0, pitch: 0, distance: 10 });

describe('placeLabels', () => {
  it('puts a label at the point looked at in the middle of the canvas, moved down by its dy', () => {
    const [label] = placeLabels([{ at: new Vec3(0, 0, 0), text: 'C', dy: 14 }], ORBIT, W, H, FOVY);
    expect(label).toEqual({ text: 'C', color: INK, x: W / 2, y: H / 2 + 14 });
  });

  it('puts a point up and to the right above and right of the middle, as far as the field of view says', () => {
    // at the top edge of the view: tan(30°) · 10 units up, 10 units away
    const top = Math.tan(FOVY / 2) * 10;
    const [label] = placeLabels([{ at: new Vec3(2, top, 0), text: 'P', color: '#123456' }], ORBIT, W, H, FOVY);
    expect(label.color).toBe('#123456');
    expect(label.y).toBeCloseTo(0, 9);
    expect(label.x).toBeGreaterThan(W / 2);
    expect(label.x).toBeCloseTo(W / 2 + (2 / (top * W / H)) * (W / 2), 9);
  });

  it('leaves out a label behind the point of view', () => {
    const labels = [{ at: new Vec3(0, 0, 20), text: 'behind' }, { at: new Vec3(0, 0, -5), text: 'ahead' }];
    expect(placeLabels(labels, ORBIT, W, H, FOVY).map((l) => l.text)).toEqual(['ahead']);
  });
});

describe('constructionOf', () => {
  const sphere = new Sphere([1, 0, -20], 4);
  const record = { ray: new Ray([0, 0, 0], [0, 0, -1]) };

  it('draws L, tca, d and thc, each labelled with the value intersectGeometric finds', () => {
    const g = intersectGeometric(record.ray, sphere);
    const { rays, labels } = constructionOf(record, sphere);
    expect(labels.map((l) => l.text)).toEqual(['L', `tca = ${g.tca.toFixed(2)}`, `d = ${Math.sqrt(g.d2).toFixed(2)}`, `thc = ${g.thc.toFixed(2)}`]);
    expect(labels.map((l) => l.text)).toEqual(['L', 'tca = 20.00', 'd = 1.00', 'thc = 3.87']);
    expect(rays.map((r) => r.color)).toEqual([CONSTRUCT, CONSTRUCT, INK, NORMAL]);
    expect(rays[0]).toMatchObject({ from: { x: 0, y: 0, z: 0 }, to: { x: 1, y: 0, z: -20 }, weight: 3 });
    // L's label 0.7 of the way from the eye, tca's 0.4: the two never sit on each other
    expect(labels[0].at.z).toBeCloseTo(-14, 9);
    expect(labels[1].at.z).toBeCloseTo(-8, 9);
  });

  it('has no thc for a ray that passes the sphere by (d > r)', () => {
    const { labels } = constructionOf({ ray: new Ray([0, 0, 0], [0.5, 0, -1]) }, sphere);
    expect(labels.map((l) => l.text.split(' ')[0])).toEqual(['L', 'tca', 'd']);
  });

  it('is empty without a sphere or a selected pixel', () => {
    expect(constructionOf(record, null)).toEqual({ rays: [], labels: [] });
    expect(constructionOf(null, sphere)).toEqual({ rays: [], labels: [] });
  });
});

describe('drawLabels', () => {
  it('clears the layer, then writes each label on a white halo in its colour', () => {
    const calls = [];
    const ctx = new Proxy({ canvas: { width: W, height: H } }, {
      get: (target, key) => (key in target ? target[key] : (...args) => calls.push([key, ...args])),
      set: (target, key, value) => { calls.push([`${String(key)}=`, value]); return true; },
    });
    drawLabels(ctx, [{ text: 'tca', color: CONSTRUCT, x: 10, y: 20 }]);
    expect(calls[0]).toEqual(['clearRect', 0, 0, W, H]);
    const texts = calls.filter(([k]) => k === 'strokeText' || k === 'fillText');
    expect(texts).toEqual([['strokeText', 'tca', 10, 20], ['fillText', 'tca', 10, 20]]);
    expect(calls).toContainEqual(['fillStyle=', CONSTRUCT]);
  });
});
