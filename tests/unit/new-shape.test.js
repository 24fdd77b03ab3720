/**
 * A shape the library has never seen, written here with the shape protocol
 * (lib/shapes/index.js) and listed from this test alone: it renders, is
 * inspected, serialises, is culled and is accepted by Scene.add with no change
 * to any file of the library. The recipe of docs/ARCHITECTURE.md, "A new shape".
 */
import { describe, it, expect } from 'vitest';
import { Scene, Sphere, PointLight, Camera, render, inspectPixel } from '../../lib/index.js';
import { sceneToJSON, sceneFromJSON, sceneToCode } from '../../lib/scene/json.js';
import { renderPixel } from '../../lib/tracing/render.js';
import { packScene } from '../../lib/tracing/kernel.js';
import { screenBounds } from '../../lib/tracing/bounds.js';
import { checkScene } from '../../lib/scene/check.js';
import { registerShape } from '../../lib/shapes/index.js';
import { N } from '../../lib/shapes/packed.js';
import { materialToJSON, vector } from '../../lib/shapes/json.js';
import { xyz } from '../../lib/shapes/form.js';
import { formTypes, tableColumns, fieldText } from '../../lib/scene/fields.js';
import { toVec3, Vec3, set } from '../../lib/math/vec3.js';
import { finiteNumber } from '../../lib/text/check.js';
import { shapeOptions } from '../../lib/shapes/material.js';
import { EPSILON } from '../../lib/math/constants.js';

/** The numbers-only test of a flat disc facing +y, shared by hit and the packed form. */
function discHit(cx, cy, cz, r, ox, oy, oz, dx, dy, dz, tMin) {
  if (dy === 0) return Infinity;
  const t = (cy - oy) / dy;
  if (!(t > tMin)) return Infinity;
  const x = ox + dx * t - cx, z = oz + dz * t - cz;
  return x * x + z * z <= r * r ? t : Infinity;
}

/** A flat round disc facing up (+y): a table top. */
class Disc {
  constructor(center, radius, options) {
    this.center = toVec3(center, 'center');
    finiteNumber(radius, 'radius');
    if (radius <= 0) throw new RangeError(`radius must be greater than 0, got ${radius}`);
    this.radius = radius;
    const shape = shapeOptions(options);
    this.name = shape.name;
    this.material = shape.material;
  }
  hit(ray, tMin = EPSILON) {
    const o = ray.origin, d = ray.direction, c = this.center;
    return discHit(c.x, c.y, c.z, this.radius, o.x, o.y, o.z, d.x, d.y, d.z, tMin);
  }
  normalAt(point, out = new Vec3()) { return set(out, 0, 1, 0); }
  intersect(ray, target = {}) {
    target.denominator = ray.direction.y;
    const t = this.hit(ray);
    target.t = t === Infinity ? null : t;
    return target;
  }
  recordRows(record) { return [['Rd·y', record.denominator], ['t', record.t]]; }
  bounds() {
    const { center: c, radius: r } = this;
    return { min: { x: c.x - r, y: c.y, z: c.z - r }, max: { x: c.x + r, y: c.y, z: c.z + r } };
  }
  toJSON() {
    return { type: 'disc', name: this.name, center: vector(this.center), radius: this.radius, material: materialToJSON(this.material) };
  }
  static get type() { return 'disc'; }
  static get fields() { return ['center', 'radius', 'material']; }
  static build(o, material) { return new Disc(o.center, o.radius, material); }
  static get packed() { return PACKED_DISC; }
  static get form() {
    return { title: 'Discs', what: 'Disc', columns: [...xyz('center', 'centre'), { path: ['radius'], label: 'radius', head: 'radius', kind: 'number', rule: { above: 0 } }] };
  }
}

/** Its packed form (lib/shapes/packed.js): cx cy cz radius. */
const PACKED_DISC = {
  pack: (disc, shapes, at) => shapes.set([disc.center.x, disc.center.y, disc.center.z, disc.radius], at),
  hit: (s, b, ox, oy, oz, dx, dy, dz, tMin) => discHit(s[b], s[b + 1], s[b + 2], s[b + 3], ox, oy, oz, dx, dy, dz, tMin),
  normal: (s, b, surface) => { surface[N] = 0; surface[N + 1] = 1; surface[N + 2] = 0; },
};
registerShape(Disc);

/** The same disc with no packed form: render() has to use trace.js for it. */
class PlainDisc extends Disc {
  static get type() { return 'plainDisc'; }
  static build(o, material) { return new PlainDisc(o.center, o.radius, material); }
  static get packed() { return undefined; }
  toJSON() { return { ...super.toJSON(), type: 'plainDisc' }; }
}
registerShape(PlainDisc);

/** The same disc whose packed form writes seven numbers into its slot of six: a mistake the kernel must name, not draw. */
class LongDisc extends Disc {
  static get type() { return 'longDisc'; }
  static build(o, material) { return new LongDisc(o.center, o.radius, material); }
  static get packed() {
    return { ...PACKED_DISC, pack: (disc, shapes, at) => shapes.set([disc.center.x, disc.center.y, disc.center.z, disc.radius, 0, 0, 1], at) };
  }
  toJSON() { return { ...super.toJSON(), type: 'longDisc' }; }
}
registerShape(LongDisc);

/** A disc whose class is not named as its capitalised type ('top'): the code says the class's own name. */
class TableTop extends Disc {
  static get type() { return 'top'; }
  static build(o, material) { return new TableTop(o.center, o.radius, material); }
  toJSON() { return { ...super.toJSON(), type: 'top' }; }
}
registerShape(TableTop);

const camera = new Camera({ width: 48, height: 36, position: [0, 3, 0], pitch: -15 });

function tableScene(Shape) {
  return new Scene({ background: [0.2, 0.3, 0.5], ambient: 0.1 })
    .add(new Shape([0, -1, -14], 3, { color: [0.9, 0.6, 0.2], name: 'table' }))
    .add(new Sphere([0, 0.5, -14], 1.5, { color: [1, 0.3, 0.4], reflection: 0.2 }))
    .add(new PointLight([-5, 10, 0]));
}

/** render() through trace.js, pixel by pixel. */
function traced(scene, cam) {
  const out = new Uint8ClampedArray(cam.width * cam.height * 4);
  for (let y = 0; y < cam.height; y++) for (let x = 0; x < cam.width; x++) renderPixel(scene, cam, x, y, out);
  return out;
}

describe('a shape written in a test, listed from the test', () => {
  it('is accepted by Scene.add; a thing without the protocol is not', () => {
    const scene = tableScene(Disc);
    expect(scene.objects[0]).toBeInstanceOf(Disc);
    expect(() => new Scene().add({ hit: () => Infinity })).toThrow(/scene.add takes a shape/);
  });

  it('renders: packed by its own packed form, the same bytes as trace.js, and the disc is in the picture', () => {
    const scene = tableScene(Disc);
    expect(packScene(scene)).not.toBeNull();
    const picture = render(scene, camera);
    expect(picture).toEqual(traced(scene, camera));
    const { hit, color } = inspectPixel(scene, camera, 24, 22); // below the ball: the table top
    expect(hit.name).toBe('table');
    expect([...picture.slice((22 * 48 + 24) * 4, (22 * 48 + 24) * 4 + 3)]).toEqual(color);
  });

  it('a packed form that writes past its slot throws when packed, naming the shape', () => {
    const scene = tableScene(LongDisc);
    expect(() => packScene(scene)).toThrow(new RangeError("objects[0] (longDisc 'table'): its packed form wrote 7 numbers, more than the 6 a shape's slot holds (lib/shapes/packed.js: a shape of more numbers keeps them in a side table)"));
    expect(() => render(scene, camera)).toThrow(/objects\[0\] \(longDisc 'table'\)/);
  });

  it('renders with no packed form through trace.js, the same picture', () => {
    const scene = tableScene(PlainDisc);
    expect(packScene(scene)).toBeNull();
    expect(render(scene, camera)).toEqual(render(tableScene(Disc), camera));
  });

  it('is inspected: its own record and lines, its kind in its name', () => {
    const scene = tableScene(Disc);
    scene.objects[0].name = '';
    const { records, hit } = inspectPixel(scene, camera, 24, 22);
    expect(records[0]).toMatchObject({ name: 'disc 1', rows: [['Rd·y', records[0].record.denominator], ['t', hit.t]] });
    expect(records[0].record.denominator).toBeLessThan(0); // looking down at it
  });

  it('serialises: JSON and back, the same scene and picture; its code; its checks', () => {
    const scene = tableScene(Disc);
    const json = sceneToJSON(scene);
    expect(json.objects[0]).toMatchObject({ type: 'disc', name: 'table', center: [0, -1, -14], radius: 3 });
    const copy = sceneFromJSON(JSON.stringify(json));
    expect(copy.objects[0]).toBeInstanceOf(Disc);
    expect(sceneToJSON(copy)).toEqual(json);
    expect(render(copy, camera)).toEqual(render(scene, camera));
    expect(() => sceneFromJSON({ objects: [{ type: 'disc', center: [0, 0, 0], radius: -2 }] })).toThrow('objects[0].radius must be greater than 0, got -2');
    expect(sceneToCode(scene)).toContain('new Disc([0, -1, -14], 3, { color: [0.9, 0.6, 0.2] })');
    expect(sceneToCode(tableScene(TableTop))).toMatch(/^import \{ Scene, Sphere, TableTop, PointLight \} from [^]*new TableTop\(\[0, -1, -14\], 3, /);
    scene.objects[0].radius = 0;
    expect(() => checkScene(scene)).toThrow('objects[0].radius must be greater than 0, got 0');
  });

  it('has a table of its own in the scene form, after the kit\'s', () => {
    expect(formTypes()).toEqual(['sphere', 'pointLight', 'plane', 'box', 'disc', 'plainDisc', 'longDisc', 'top']); // the others inherit Disc's form
    const json = sceneToJSON(tableScene(Disc)).objects[0];
    expect(tableColumns('disc').map((column) => fieldText(json, column))).toEqual(['0', '-1', '-14', '3']);
  });

  it('is culled by its bounds: a disc off to the right covers only part of the picture', () => {
    const disc = new Disc([6, -1, -30], 1);
    const rect = {};
    expect(screenBounds(disc, camera, rect)).toBe(true);
    expect(rect.x0).toBeGreaterThan(camera.width / 2);
    expect(rect.x1 - rect.x0).toBeLessThan(camera.width / 4);
    expect(screenBounds(new Disc([0, 0, 20], 1), camera, rect)).toBe(false); // behind the eye
  });
});
