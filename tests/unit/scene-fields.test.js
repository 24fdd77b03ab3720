// The values a scene form edits: the columns of each type, a box's text, and editing scene JSON.
import { describe, it, expect } from 'vitest';
import { classScene } from '../../lib/index.js';
import { sceneToJSON, sceneFromJSON } from '../../lib/scene/json.js';
import { tableColumns, COLUMNS, withValue, fieldText } from '../../lib/scene/fields.js';

describe('the columns of each kind of object', () => {
  it('give every sphere its centre, radius, colour, reflection, transparency and emission', () => {
    expect(tableColumns('sphere').map((c) => c.label)).toEqual(
      ['centre x', 'centre y', 'centre z', 'radius', 'colour', 'reflection', 'transparency', 'emission']);
    expect(tableColumns('pointLight').map((c) => c.label)).toEqual(['position x', 'position y', 'position z', 'colour', 'intensity']);
    expect(() => tableColumns('teapot')).toThrow(/type must be one of/);
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

describe('fieldText', () => {
  it('shows numbers as they are and colours the way a box reads them back', () => {
    const [sphere] = sceneToJSON(sceneFromJSON({ objects: [{ type: 'sphere', center: [0, -2.5, -5], radius: 1, material: { color: [1, 0, 0], emission: 1.5 } }] })).objects;
    const text = (label) => fieldText(sphere, COLUMNS.sphere.find((c) => c.label === label));
    expect([text('centre y'), text('radius'), text('colour'), text('emission')]).toEqual(['-2.5', '1', '#ff0000', '1.5']);
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
