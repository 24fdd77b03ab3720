// The scene form's edits, one object at a time: after any sequence of edits the
// scene is the one sceneFromJSON builds from the JSON, a bad value throws
// sceneFromJSON's own error and keeps the last good scene, and the picture is
// the same bytes.
import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import { Camera, Scene, Sphere, classScene } from '../../lib/index.js';
import { sceneToJSON, sceneFromJSON, objectToJSON, objectFromJSON } from '../../lib/scene/json.js';
import { COLUMNS, withValue } from '../../lib/scene/fields.js';
import { SceneEdits } from '../../lib/scene/edits.js';
import { render } from '../../lib/tracing/render.js';

/** A scene with every type, point lights between shapes and an emissive sphere: orders that matter for the lights. */
const MIXED = {
  background: [0.2, 0.3, 0.4],
  objects: [
    { type: 'sphere', name: 'a', center: [0, 0, -10], radius: 2, material: { color: [1, 0, 0] } },
    { type: 'pointLight', name: 'p', position: [5, 5, 0], intensity: 0.8 },
    { type: 'sphere', name: 'sun', center: [-4, 6, -12], radius: 1, material: { color: [0, 0, 0], emission: 1 } },
    { type: 'plane', point: [0, -2, 0], normal: [0, 1, 0], material: { reflection: 0.3 } },
    { type: 'pointLight', position: [-5, 5, 0], color: [1, 0.5, 0.5] },
    { type: 'box', min: [2, -2, -14], max: [4, 0, -12], material: { color: [0, 1, 0] } },
  ],
};
/** Colours as text, a centre as {x, y, z}, a plane's normal not of length 1: what the first check turns into numbers. */
const WRITTEN = {
  background: 'white',
  objects: [
    { type: 'sphere', name: 'p', center: { x: 1, y: 0, z: -10 }, radius: 2, material: { color: 'pink', emission: [0.1, 0.1, 0.1], reflection: 0.2 } },
    { type: 'plane', point: [0, -2, 0], normal: [0.3, 2, 0.1] },
    { type: 'pointLight', position: [5, 5, 0], color: 'yellow' },
    { type: 'box', min: [2, -2, -14], max: [4, 0, -12], material: { color: '#3366ff' } },
  ],
};
const START = { class: sceneToJSON(classScene()), mixed: MIXED, written: WRITTEN, empty: { objects: [] } };

const number = fc.oneof(
  fc.double({ min: -20, max: 20, noNaN: true }),
  fc.constantFrom(0, -0, 1, 0.5, -1, 2, 1.5, NaN, Infinity, -Infinity, 1e300),
  fc.constantFrom('abc', '', null, [1, 2, 3]),
);
const color = fc.oneof(
  fc.tuple(...Array.from({ length: 3 }, () => fc.double({ min: -0.5, max: 2, noNaN: true }))),
  fc.constantFrom([0, 0, 0], [1, 1, 1], [2, 2, 2], 'pink', '#3366ff', 'nope', [1, 2], [NaN, 0, 0], 7),
);
const xyz = fc.tuple(fc.integer({ min: -10, max: 10 }), fc.integer({ min: -10, max: 10 }), fc.integer({ min: -30, max: 0 }));
const newObject = fc.oneof(
  fc.record({ type: fc.constant('sphere'), name: fc.constantFrom('', 'ball', 'light'), center: xyz, radius: fc.constantFrom(0.5, 1, 3),
    material: fc.record({ color, emission: fc.constantFrom(0, 0, 1, [0.5, 0.5, 0.5]) }) }),
  fc.record({ type: fc.constant('pointLight'), name: fc.constantFrom('', 'lamp'), position: xyz, color: fc.constantFrom([1, 1, 1], [0.5, 1, 0.2]), intensity: fc.constantFrom(1, 0.5, 2) }),
  fc.record({ type: fc.constant('box'), min: fc.constant([-1, -1, -9]), max: fc.constant([1, 1, -7]) }),
  fc.record({ type: fc.constant('plane'), point: fc.constant([0, -3, 0]), normal: fc.constantFrom([0, 1, 0], [0.3, 2, 0.1], [0, 0, 0]) }),
  fc.record({ type: fc.constant('sphere'), center: xyz, radius: fc.constantFrom(-1, 0) }), // a bad one
);
/** An edit; `pick` chooses the object and the column among those there are when it runs. */
const edit = fc.oneof(
  fc.record({ kind: fc.constant('add'), o: newObject }),
  fc.record({ kind: fc.constant('set'), pick: fc.nat(), column: fc.nat(), number, color }),
  fc.record({ kind: fc.constant('set'), pick: fc.nat(), column: fc.nat(), number, color }),
  fc.record({ kind: fc.constant('background'), color }),
  fc.record({ kind: fc.constant('remove'), pick: fc.nat() }),
);

/** The error sceneFromJSON throws for the whole scene `json`, or null. */
function wholeError(json) {
  try {
    sceneFromJSON(json);
    return null;
  } catch (error) {
    return error;
  }
}

/** An object's JSON as sceneToJSON writes it. */
const written = (o) => objectToJSON(objectFromJSON(o, 'o'));

/**
 * Runs one edit on `edits`. The whole scene's check (sceneFromJSON of the
 * JSON with the change) says whether it must be taken, and with what message
 * not. The JSON after it: the one object (or field) changed, as sceneToJSON
 * writes it, the others as they were.
 */
function apply(edits, e) {
  const before = { json: edits.json, scene: edits.scene };
  const { objects, ...fields } = before.json;
  let run, raw, expected;
  if (e.kind === 'add') {
    raw = { ...before.json, objects: [...objects, e.o] };
    expected = () => ({ ...before.json, objects: [...objects, written(e.o)] });
    run = () => edits.add(e.o);
  } else if (e.kind === 'background') {
    raw = withValue(before.json, ['background'], e.color);
    expected = () => ({ ...sceneToJSON(sceneFromJSON({ ...fields, background: e.color })), objects });
    run = () => edits.set(['background'], e.color);
  } else {
    if (objects.length === 0) return;
    const index = e.pick % objects.length;
    if (e.kind === 'remove') {
      raw = { ...before.json, objects: objects.filter((_, i) => i !== index) };
      expected = () => raw;
      run = () => edits.remove(index);
    } else {
      const columns = COLUMNS[objects[index].type];
      const c = columns[e.column % columns.length];
      const path = ['objects', index, ...c.path];
      const value = c.kind === 'color' ? e.color : e.number;
      raw = withValue(before.json, path, value);
      expected = () => ({ ...before.json, objects: objects.map((o, i) => (i === index ? written(raw.objects[index]) : o)) });
      run = () => edits.set(path, value);
    }
  }
  const error = wholeError(raw);
  if (error) {
    expect(run).toThrow(error.constructor);
    expect(run).toThrow(error.message);
    expect(edits.json).toBe(before.json); // the last good scene stays
    expect(edits.scene).toBe(before.scene);
    return;
  }
  run();
  expect(edits.json).toEqual(expected());
}

/** The scene is what sceneFromJSON makes of the JSON, shape for shape and light for light. */
function expectInStep(edits) {
  const rebuilt = sceneFromJSON(edits.json);
  expect(sceneToJSON(edits.scene)).toEqual(sceneToJSON(rebuilt));
  const lights = (scene) => scene.lights.map((l) => objectToJSON(l.source));
  expect(lights(edits.scene)).toEqual(lights(rebuilt));
}

describe('SceneEdits', () => {
  it('after any sequence of edits is the scene sceneFromJSON makes of its JSON; bad values change nothing and say what sceneFromJSON says', () => {
    const camera = new Camera({ width: 16, height: 12, fov: 40 });
    fc.assert(fc.property(fc.constantFrom(...Object.keys(START)), fc.array(edit, { maxLength: 25 }), (start, sequence) => {
      const edits = new SceneEdits(START[start]);
      for (const e of sequence) {
        apply(edits, e);
        expectInStep(edits);
      }
      expect(Buffer.from(render(edits.scene, camera))).toEqual(Buffer.from(render(sceneFromJSON(edits.json), camera)));
    }), { numRuns: 150 });
  });

  it('names the field as sceneFromJSON does', () => {
    const edits = new SceneEdits(START.class);
    expect(() => edits.set(['objects', 1, 'radius'], -1)).toThrow(/^objects\[1\]\.radius must be greater than 0, got -1$/);
    expect(() => edits.set(['objects', 3, 'material', 'reflection'], 1.5)).toThrow(/^objects\[3\]\.material\.reflection /);
    expect(() => edits.set(['background'], 'nope')).toThrow(/^background /);
    expect(() => edits.set(['objects', 99, 'radius'], 1)).toThrow(RangeError);
  });

  it('keeps every other shape as built, and leaves the JSON it gave before as it was', () => {
    const scene = new Scene();
    for (let i = 0; i < 1000; i++) scene.add(new Sphere([i % 40, Math.floor(i / 40), -45], 0.25));
    const edits = new SceneEdits(sceneToJSON(scene));
    const { json, scene: before } = edits;
    edits.set(['objects', 500, 'radius'], 0.3);
    edits.add({ type: 'sphere', center: [0, 3, -12], radius: 1 });
    expect(edits.scene.objects).toHaveLength(1001);
    expect(edits.scene.objects.filter((o, i) => o !== before.objects[i])).toEqual([edits.scene.objects[500], edits.scene.objects[1000]]);
    expect(json.objects).toHaveLength(1000);
    expect(json.objects[500].radius).toBe(0.25);
    expect(edits.json.objects[500].radius).toBe(0.3);
  });
});
