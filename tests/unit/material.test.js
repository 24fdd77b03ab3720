import { describe, it, expect } from 'vitest';
import { Material, Sphere, Plane, Box, PointLight, Scene } from '../../lib/index.js';
import { MATERIAL_FIELDS, MATERIAL_NUMBERS, MATERIAL_AT, MATERIAL_LAYOUT, packMaterial } from '../../lib/shapes/material.js';
import * as pathMaterials from '../../lib/tracing/pathtrace/materials.js';
import { materialToJSON } from '../../lib/shapes/json.js';
import { sceneFromJSON, sceneToCode } from '../../lib/scene/json.js';
import { packScene } from '../../lib/tracing/kernel.js';

describe('Material', () => {
  it('defaults: white, no emission, no reflection, no transparency', () => {
    const m = new Material();
    expect(m.color).toEqual([1, 1, 1]);
    expect(m.emission).toEqual([0, 0, 0]);
    expect(m.reflection).toBe(0);
    expect(m.transparency).toBe(0);
    expect(m.isEmissive).toBe(false);
  });

  it('takes colours as arrays or strings, emission as a number', () => {
    const m = new Material({ color: '#ff0000', emission: 1.2, reflection: 0.5, transparency: 0.25 });
    expect(m.color).toEqual([1, 0, 0]);
    expect(m.emission).toEqual([1.2, 1.2, 1.2]);
    expect(m.reflection).toBe(0.5);
    expect(m.transparency).toBe(0.25);
  });

  it('an emission in any channel makes it emissive (a light)', () => {
    expect(new Material({ emission: [0, 0, 0.1] }).isEmissive).toBe(true);
    expect(new Material({ emission: 'red' }).isEmissive).toBe(true);
    expect(new Material({ emission: 0 }).isEmissive).toBe(false);
  });

  it('Material.from keeps a Material, builds one from options or nothing', () => {
    const m = new Material({ color: [0, 1, 0] });
    expect(Material.from(m)).toBe(m);
    expect(Material.from({ color: [0, 0, 1] }).color).toEqual([0, 0, 1]);
    expect(Material.from(undefined).color).toEqual([1, 1, 1]);
  });

  it('a sphere takes a Material or a plain object', () => {
    const m = new Material({ color: [0, 1, 0] });
    expect(new Sphere([0, 0, 0], 1, m).material).toBe(m);
    expect(new Sphere([0, 0, 0], 1, { reflection: 1 }).material).toBeInstanceOf(Material);
    expect(new Sphere([0, 0, 0], 1, { reflection: 1 }).material.reflection).toBe(1);
  });
});

describe('Material: bad input names the field', () => {
  const cases = [
    [{ reflection: 1.5 }, RangeError, /reflection/],
    [{ reflection: -0.1 }, RangeError, /reflection/],
    [{ reflection: '0.5' }, TypeError, /reflection/],
    [{ transparency: 2 }, RangeError, /transparency/],
    [{ transparency: NaN }, TypeError, /transparency/],
    [{ color: 'not a colour' }, TypeError, /color/],
    [{ color: [1, 0] }, TypeError, /color/],
    [{ color: [1, -1, 0] }, RangeError, /color/],
    [{ emission: [-1, 0, 0] }, RangeError, /emission/],
    [{ emission: 'glow' }, TypeError, /emission/],
    [{ ior: 0.5 }, RangeError, /ior/],
    [{ specular: 3 }, RangeError, /specular/],
    [{ shininess: 0 }, RangeError, /shininess/],
  ];
  for (const [options, type, field] of cases) {
    it(`${JSON.stringify(options)} → ${type.name} ${field}`, () => {
      expect(() => new Material(options)).toThrow(type);
      expect(() => new Material(options)).toThrow(field);
    });
  }

  it('a material that is not an object is a TypeError naming material', () => {
    expect(() => new Material(null)).toThrow(TypeError);
    expect(() => new Material('red')).toThrow(/material/);
    expect(() => new Sphere([0, 0, 0], 1, 'red')).toThrow(/material/);
  });
});

describe('a shape or light named in its constructor', () => {
  it('takes name beside the material options, and keeps the material as it was', () => {
    const ball = new Sphere([0, 0, -20], 4, { color: [1, 0, 0], reflection: 0.5, name: 'pink' });
    expect(ball.name).toBe('pink');
    expect(ball.material).toEqual(new Material({ color: [1, 0, 0], reflection: 0.5 }));
    expect(new Plane([0, 0, 0], [0, 1, 0], { name: 'ground' }).name).toBe('ground');
    expect(new Box([0, 0, 0], [1, 1, 1], { color: 'gray', name: 'pole' }).name).toBe('pole');
    expect(new PointLight([0, 10, 0], { intensity: 0.5, name: 'sun' }).name).toBe('sun');
  });

  it('is empty when not given, also with a Material', () => {
    expect(new Sphere([0, 0, 0], 1).name).toBe('');
    expect(new Sphere([0, 0, 0], 1, new Material({ color: 'red' })).name).toBe('');
    expect(new PointLight([0, 10, 0]).name).toBe('');
  });

  it('must be text, and a misspelt name is named with the suggestion', () => {
    expect(() => new Sphere([0, 0, 0], 1, { name: 7 })).toThrow(/name must be text, got 7/);
    expect(() => new Sphere([0, 0, 0], 1, { nmae: 'ball' })).toThrow('unknown material option "nmae" (did you mean "name"?)');
    expect(() => new PointLight([0, 0, 0], { name: null })).toThrow(/name must be text/);
  });
});

describe('one table of material fields (MATERIAL_FIELDS)', () => {
  const m = new Material({ color: [0.1, 0.2, 0.3], emission: [0.4, 0.5, 0.6], reflection: 0.7, transparency: 0.8, ior: 1.5, specular: 0.9, shininess: 20 });
  const names = MATERIAL_FIELDS.map((field) => field.name);

  it('is what a Material has, in its order, each field checked by its row', () => {
    expect(Object.keys(new Material())).toEqual(names);
    for (const { name, value } of MATERIAL_FIELDS) expect(new Material()[name]).toEqual(value);
    expect(() => new Material({ ior: 5 })).toThrow('ior must be between 1 and 4, got 5');
  });

  it('is what JSON writes and reads, and what the code leaves out as defaults', () => {
    expect(Object.keys(materialToJSON(m))).toEqual(names.filter((name) => name !== 'fuzz')); // fuzz 0 is left out (omitAtDefault): older JSON stays the same
    expect(materialToJSON(new Material({ reflection: 1, fuzz: 0.3 }))).toMatchObject({ reflection: 1, fuzz: 0.3 });
    expect(Object.keys(materialToJSON(new Material({ fuzz: 0.3 })))).toEqual(names);
    expect(() => sceneFromJSON({ objects: [{ type: 'sphere', center: [0, 0, 0], radius: 1, material: { shine: 3 } }] }))
      .toThrow(`objects[0].material has no field "shine" (its fields: ${names.join(', ')})`);
    expect(sceneToCode(new Scene().add(new Sphere([0, 0, -5], 1, { ior: 1.1, shininess: 20 })))).toContain('new Sphere([0, 0, -5], 1, { shininess: 20 })');
  });

  it('is what the packed scene holds, at MATERIAL_AT, MATERIAL_NUMBERS a material', () => {
    const out = new Float64Array(MATERIAL_NUMBERS);
    packMaterial(m, out, 0);
    expect(MATERIAL_NUMBERS).toBe(12);
    expect([...out.slice(MATERIAL_AT.emission, MATERIAL_AT.emission + 3)]).toEqual([0.4, 0.5, 0.6]);
    expect([out[MATERIAL_AT.reflection], out[MATERIAL_AT.transparency], out[MATERIAL_AT.ior], out[MATERIAL_AT.specular], out[MATERIAL_AT.shininess]]).toEqual([0.7, 0.8, 1.5, 0.9, 20]);
    const packed = packScene(new Scene().add(new Sphere([0, 0, -5], 1, m)));
    expect([...packed.materials]).toEqual([...out]);
  });

  it('is the layout the path tracer reads too: its offsets are the table\'s, its numbers the packed scene\'s', () => {
    const fuzzy = new Material({ color: [0.1, 0.2, 0.3], emission: [0.4, 0.5, 0.6], reflection: 0.7, transparency: 0.2, ior: 1.5, fuzz: 0.25 });
    const objects = [new Sphere([0, 0, -5], 1, m), new Sphere([0, 2, -5], 1, fuzzy)];
    expect([...pathMaterials.packMaterials(objects)]).toEqual([...packScene(objects.reduce((scene, o) => scene.add(o), new Scene())).materials]);
    for (const name of ['MATERIAL', 'COLOR', 'EMISSION', 'REFLECTION', 'TRANSPARENCY', 'IOR', 'FUZZ']) expect(pathMaterials[name], name).toBe(MATERIAL_LAYOUT[name]);
    const at = MATERIAL_LAYOUT.MATERIAL;
    expect(pathMaterials.packMaterials(objects)[at + pathMaterials.FUZZ]).toBe(0.25);
  });
});
