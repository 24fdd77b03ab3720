import { describe, it, expect } from 'vitest';
import { checkOptions, editDistance, closestName } from '../../lib/text/check.js';
import { Material } from '../../lib/shapes/material.js';
import { Scene } from '../../lib/scene/scene.js';
import { Camera } from '../../lib/math/camera.js';
import { PointLight } from '../../lib/lights/point-light.js';
import { Sphere } from '../../lib/shapes/sphere.js';
import { Plane } from '../../lib/shapes/plane.js';
import { Box } from '../../lib/shapes/box.js';
import { ProgressiveRenderer } from '../../lib/tracing/frames.js';
import { ParallelRenderer } from '../../lib/tracing/workers/parallel.js';

describe('editDistance', () => {
  it('counts inserts, deletes, replacements and swapped neighbours', () => {
    expect(editDistance('color', 'color')).toBe(0);
    expect(editDistance('colour', 'color')).toBe(1);
    expect(editDistance('widht', 'width')).toBe(1); // two letters swapped: one edit
    expect(editDistance('gird', 'grid')).toBe(1);
    expect(editDistance('backgorund', 'background')).toBe(1);
    expect(editDistance('', 'fov')).toBe(3);
    expect(editDistance('kitten', 'sitting')).toBe(3);
  });
});

describe('checkOptions', () => {
  const KNOWN = ['color', 'emission', 'reflection'];

  it('returns the known options\' own keys, with no prototype, and {} for undefined', () => {
    const options = { color: 'red', reflection: 0.5 };
    const own = checkOptions(options, KNOWN, 'material');
    expect(own).toEqual(options);
    expect(Object.getPrototypeOf(own)).toBeNull();
    expect(Object.getPrototypeOf(checkOptions(undefined, KNOWN, 'material'))).toBeNull();
    expect(checkOptions(undefined, KNOWN, 'material')).toEqual({});
    expect(checkOptions({}, KNOWN, 'material')).toEqual({});
  });

  it('names the unknown key, where it was given and the closest known key', () => {
    expect(() => checkOptions({ colour: [1, 0, 0] }, KNOWN, 'material'))
      .toThrow(new TypeError('unknown material option "colour" (did you mean "color"?)'));
    expect(() => checkOptions({ Color: 'red' }, KNOWN, 'material')).toThrow('(did you mean "color"?)');
  });

  it('lists every known key when none is close', () => {
    expect(() => checkOptions({ zoom: 2 }, ['width', 'height', 'fov'], 'camera'))
      .toThrow('unknown camera option "zoom" (did you mean "fov"? known options: width, height, fov)');
  });

  it('refuses options that are not an object', () => {
    expect(() => checkOptions(null, KNOWN, 'material')).toThrow(TypeError);
    expect(() => checkOptions([1, 0, 0], KNOWN, 'material')).toThrow(/material options must be an object/);
    expect(() => checkOptions('red', KNOWN, 'material')).toThrow(/got "red"/);
  });
});

// Every options object of the library: a misspelt key throws a TypeError with
// the key and the suggestion; the same call with the key spelt right works.
const scene = new Scene(), camera = new Camera({ width: 4, height: 3 });
const CASES = [
  ['Material', (o) => new Material(o), { colour: [1, 0, 0] }, 'unknown material option "colour" (did you mean "color"?)', { color: [1, 0, 0] }],
  ['Material (reflection)', (o) => new Material(o), { reflexion: 0.5 }, 'unknown material option "reflexion" (did you mean "reflection"?)', { reflection: 0.5 }],
  ['Sphere material', (o) => new Sphere([0, 0, -5], 1, o), { colour: 'red' }, 'unknown material option "colour" (did you mean "color"?)', { color: 'red' }],
  ['Plane material', (o) => new Plane([0, 0, 0], [0, 1, 0], o), { emision: 1 }, 'unknown material option "emision" (did you mean "emission"?)', { emission: 1 }],
  ['Box material', (o) => new Box([0, 0, 0], [1, 1, 1], o), { transparancy: 0.5 }, 'unknown material option "transparancy" (did you mean "transparency"?)', { transparency: 0.5 }],
  ['Scene', (o) => new Scene(o), { backgorund: [1, 1, 1] }, 'unknown scene option "backgorund" (did you mean "background"?)', { background: [1, 1, 1] }],
  ['Scene (shadow)', (o) => new Scene(o), { shadow: false }, 'unknown scene option "shadow" (did you mean "shadows"?)', { shadows: false }],
  ['Camera', (o) => new Camera(o), { widht: 32, height: 24 }, 'unknown camera option "widht" (did you mean "width"?)', { width: 32, height: 24 }],
  ['Camera (FOV)', (o) => new Camera(o), { width: 32, height: 24, FOV: 40 }, 'unknown camera option "FOV" (did you mean "fov"?)', { width: 32, height: 24, fov: 40 }],
  ['PointLight', (o) => new PointLight([0, 10, 0], o), { colour: 'red' }, 'unknown point light option "colour" (did you mean "color"?)', { color: 'red' }],
  ['PointLight (intensity)', (o) => new PointLight([0, 10, 0], o), { intensty: 2 }, 'unknown point light option "intensty" (did you mean "intensity"?)', { intensity: 2 }],
  ['ProgressiveRenderer', (o) => new ProgressiveRenderer({ scene, camera, ...o }), { budget: 4 }, 'unknown ProgressiveRenderer option "budget" (did you mean "budgetMs"?)', { budgetMs: 4 }],
  ['ProgressiveRenderer.restart', (o) => new ProgressiveRenderer({ scene, camera }).restart(o), { mod: 'scanline' }, 'unknown restart option "mod" (did you mean "mode"?)', { mode: 'scanline' }],
  ['ParallelRenderer', (o) => new ParallelRenderer(o), { worker: 2 }, 'unknown ParallelRenderer option "worker" (did you mean "workers"?)', { workers: 2 }],
];

describe.each(CASES)('%s options', (name, make, misspelt, message, right) => {
  it('a misspelt key throws a TypeError naming it and the closest known key', () => {
    expect(() => make(misspelt)).toThrow(TypeError);
    expect(() => make(misspelt)).toThrow(message);
  });

  it('the same options spelt right work as before', () => {
    expect(() => make(right)).not.toThrow();
  });
});

describe('valid options are unchanged', () => {
  it('a material keeps every value given', () => {
    const m = new Material({ color: [1, 0, 0], emission: 2, reflection: 0.3, transparency: 0.2, ior: 1.5, specular: 0.4, shininess: 20 });
    expect(m).toMatchObject({ color: [1, 0, 0], emission: [2, 2, 2], reflection: 0.3, transparency: 0.2, ior: 1.5, specular: 0.4, shininess: 20 });
    expect(new Material(m).color).toEqual([1, 0, 0]); // a Material's own fields are its options
  });

  it('a scene and a camera keep every value given', () => {
    expect(new Scene({ background: 'pink', ambient: 0.1, shadows: false, bias: 0, epsilon: 0, maxDepth: 2, specular: false }))
      .toMatchObject({ ambient: 0.1, shadows: false, bias: 0, epsilon: 0, maxDepth: 2, specular: false });
    expect(new Camera({ width: 32, height: 24, fov: 40, position: [1, 2, 3], yaw: 10, pitch: -5 }))
      .toMatchObject({ width: 32, height: 24, fov: 40, position: { x: 1, y: 2, z: 3 }, yaw: 10, pitch: -5 });
  });

  it('a point light takes its colour and intensity as options or one by one, the same light', () => {
    const byOptions = new PointLight([0, 10, 0], { color: [1, 0.5, 0], intensity: 2 });
    const byArguments = new PointLight([0, 10, 0], [1, 0.5, 0], 2);
    expect(byOptions.emission).toEqual([2, 1, 0]);
    expect(byOptions).toEqual(byArguments);
    expect(new PointLight([0, 10, 0], {}).emission).toEqual([1, 1, 1]);
    expect(() => new PointLight([0, 10, 0], { color: 'red' }, 2)).toThrow(/not both/);
  });

  it('ParallelRenderer.render refuses a misspelt onRows', async () => {
    const parallel = new ParallelRenderer({ workers: 1 });
    await expect(parallel.render(scene, camera, { onRow: () => {} }))
      .rejects.toThrow('unknown ParallelRenderer.render option "onRow" (did you mean "onRows"?)');
  });
});

describe('closestName: "did you mean …?" for any name', () => {
  it('finds the name a misspelling meant: a swap, a letter missing or doubled, another case', () => {
    const kit = ['createTracerView', 'createInspector', 'createSceneView', 'createAnswerForm'];
    expect(closestName('createTracerVeiw', kit)).toBe('createTracerView');
    expect(closestName('createInspecter', kit)).toBe('createInspector');
    expect(closestName('createtracerview', kit)).toBe('createTracerView');
    expect(closestName('Spehre', ['Scene', 'Sphere', 'Plane', 'Box'])).toBe('Sphere');
    expect(closestName('pinkk', ['pink', 'hotpink', 'purple'])).toBe('pink');
  });

  it('null when nothing is close enough: a short name may be one edit off, a long one three', () => {
    expect(closestName('box', ['fox'])).toBe('fox');
    expect(closestName('box', ['fix'])).toBeNull();
    expect(closestName('makeSky', ['makeSphere', 'createSky2000'])).toBeNull();
    expect(closestName('pinkish', ['pink', 'hotpink'])).toBeNull();
    expect(closestName('anything', [])).toBeNull();
    expect(closestName('colour', ['color'], 0)).toBeNull(); // the limit can be given
  });

  it('a tie goes to the name that keeps the letters written, then to the one with the same case', () => {
    expect(closestName('gren', ['grey', 'green'])).toBe('green'); // both one edit; green holds g, r, e, n
    expect(closestName('Red', ['RED', 'red'])).toBe('red'); // both 0 edits case aside; with case "red" is 1 edit, "RED" 2
  });
});
