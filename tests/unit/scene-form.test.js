// The scene form's pure parts: its columns, editing scene JSON, and the scene in a link.
import { describe, it, expect } from 'vitest';
import { classScene, render, Camera } from '../../lib/index.js';
import { sceneToJSON, sceneFromJSON } from '../../lib/serialize.js';
import {
  tableColumns, COLUMNS, withValue, compactSceneJSON, encodeScene, decodeScene,
} from '../../lib/p5/scene-form.js';

describe('the columns of each kind of object', () => {
  it('give every sphere its centre, radius, colour, reflection, transparency and emission', () => {
    expect(tableColumns('sphere').map((c) => c.label)).toEqual(
      ['centre x', 'centre y', 'centre z', 'radius', 'colour', 'reflection', 'transparency', 'emission']);
    expect(tableColumns('pointLight').map((c) => c.label)).toEqual(['position x', 'position y', 'position z', 'colour', 'intensity']);
    expect(() => tableColumns('cone')).toThrow(/type must be one of/);
  });

  it('point at fields that exist in the JSON of each type', () => {
    const json = sceneToJSON(sceneFromJSON({
      objects: [
        { type: 'sphere', center: [0, 0, -5], radius: 1 },
        { type: 'pointLight', position: [1, 2, 3] },
        { type: 'plane', point: [0, -1, 0], normal: [0, 1, 0] },
        { type: 'box', min: [0, 0, 0], max: [1, 1, 1] },
      ],
    }));
    for (const o of json.objects) {
      for (const c of COLUMNS[o.type]) {
        const v = c.path.reduce((at, k) => at[k], o);
        expect(v, `${o.type} ${c.label}`).toBeDefined();
      }
    }
  });
});

describe('withValue', () => {
  it('changes a copy, never the original', () => {
    const json = sceneToJSON(classScene());
    const changed = withValue(json, ['objects', 1, 'center', 0], 3);
    expect(changed.objects[1].center).toEqual([3, 0, -20]);
    expect(json.objects[1].center).toEqual([0, 0, -20]);
  });
});

describe('the scene in a link', () => {
  const camera = new Camera({ width: 32, height: 24 });

  it('compact JSON drops defaults and reads back as the same scene, picture for picture', () => {
    const json = sceneToJSON(classScene({ full: true }));
    const compact = compactSceneJSON(json);
    expect(JSON.stringify(compact).length).toBeLessThan(JSON.stringify(json).length);
    expect(compact.objects[1].material).not.toHaveProperty('ior');
    expect(sceneToJSON(sceneFromJSON(compact))).toEqual(json);
    expect(render(sceneFromJSON(compact), camera)).toEqual(render(classScene({ full: true }), camera));
  });

  it('round-trips through URL-safe text', () => {
    const json = sceneToJSON(classScene());
    json.objects[2].name = 'ünïcode ☀';
    const text = encodeScene(json);
    expect(text).toMatch(/^[A-Za-z0-9_-]+$/);
    expect(sceneToJSON(decodeScene(text))).toEqual(json);
  });

  it('also reads plain JSON text', () => {
    const scene = decodeScene('{"objects":[{"type":"sphere","center":[0,0,-5],"radius":2}]}');
    expect(scene.spheres[0].radius).toBe(2);
  });

  it('says what is wrong with a bad link', () => {
    expect(() => decodeScene('')).toThrow(TypeError);
    expect(() => decodeScene('not*base64!')).toThrow(/not base64url/);
    expect(() => decodeScene('abc')).toThrow(TypeError); // not whole base64 / not JSON
    expect(() => decodeScene(Buffer.from('[1,2]').toString('base64url'))).toThrow(/scene must be an object/);
    const badRadius = Buffer.from(JSON.stringify({ objects: [{ type: 'sphere', center: [0, 0, 0], radius: -1 }] })).toString('base64url');
    expect(() => decodeScene(badRadius)).toThrow(/objects\[0\]\.radius/);
  });
});
