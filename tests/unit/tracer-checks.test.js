// Every tracer checks the scene it is given when it is called (a sketch may
// change a scene after building it) and names the field; a call whose work
// would freeze a page for about a second is refused, naming the way that does
// not. Through the public API (lib/index.js) only.
import { describe, it, expect } from 'vitest';
import {
  render, renderGPU, pathTrace, pathTraceGPU, inspectPixel, inspectPath, ProgressiveRenderer, ParallelRenderer,
  classScene, Scene, Sphere, PointLight, Camera,
} from '../../lib/index.js';
import { RENDER_RAYS, PATH_SEGMENTS, GPU_SHAPE_TESTS } from '../../lib/tracing/budget.js';

const camera = () => new Camera({ width: 8, height: 6 });

/** Each tracer, called as a sketch calls it. */
const TRACERS = {
  render: (s, c) => render(s, c),
  renderGPU: (s, c) => renderGPU(s, c),
  pathTrace: (s, c) => pathTrace(s, c, { samples: 1 }),
  pathTraceGPU: (s, c) => pathTraceGPU(s, c, { samples: 1 }),
  inspectPixel: (s, c) => inspectPixel(s, c, 4, 3),
  inspectPath: (s, c) => inspectPath(s, c, 4, 3),
  ProgressiveRenderer: (s, c) => new ProgressiveRenderer({ scene: s, camera: c }),
};

/** Damage done to the class scene after it was built: [what, change, kind, the message's start]. */
const DAMAGE = [
  ['a radius set to NaN', (s) => { s.objects[1].radius = NaN; }, TypeError, 'objects[1].radius must be a finite number, got NaN'],
  ['a radius set to Infinity', (s) => { s.objects[2].radius = Infinity; }, TypeError, 'objects[2].radius must be a finite number, got Infinity'],
  ['a centre coordinate set to NaN', (s) => { s.objects[1].center.y = NaN; }, TypeError, 'objects[1].center.y must be a finite number, got NaN'],
  ['a colour channel set to NaN', (s) => { s.objects[1].material.color = [NaN, 0, 0]; }, TypeError, 'objects[1].material.color[0] must be a finite number, got NaN'],
  ['an emission set to Infinity', (s) => { s.objects[1].material.emission = Infinity; }, TypeError, 'objects[1].material.emission[0] must be a finite number, got Infinity'],
  ['a colour that is no colour', (s) => { s.objects[3].material.color = 'blurple'; }, TypeError, 'objects[3].material.color must be a colour like'],
  ['a fuzz of the wrong type', (s) => { s.objects[1].material.fuzz = '0.5'; }, TypeError, 'objects[1].material.fuzz must be a finite number, got "0.5"'],
  ['a reflection over 1', (s) => { s.objects[1].material.reflection = 2; }, RangeError, 'objects[1].material.reflection must be between 0 and 1, got 2'],
  ['a material replaced by a plain object', (s) => { s.objects[1].material = { color: [1, 0, 0] }; }, TypeError, 'objects[1].material must be a Material'],
  ['a shape replaced by text', (s) => { s.objects[0] = 'sphere'; }, TypeError, 'objects[0] must be a shape'],
  ['null pushed into lights', (s) => { s.lights.push(null); }, TypeError, 'lights[3] must be a light source as scene.add(light) makes them'],
  ['a light pushed into lights, not added', (s) => { s.lights.push(new PointLight([0, 10, 0])); }, TypeError, 'lights[3] must be a light source as scene.add(light) makes them'],
  ['a light moved to NaN', (s) => { s.lights[2].source.position.x = NaN; }, TypeError, 'lights[2].position.x must be a finite number, got NaN'],
  ['a light of negative intensity', (s) => { s.lights[2].source.intensity = -1; }, RangeError, 'lights[2].intensity must not be negative, got -1'],
  ['a light source record broken', (s) => { s.lights[2].emission = null; }, TypeError, 'lights[2].emission must be [r, g, b]'],
  ['a background that is no colour', (s) => { s.background = 'skyblue-ish'; }, TypeError, 'scene.background must be a colour like'],
  ['a background of NaN', (s) => { s.background = [0, NaN, 0]; }, TypeError, 'scene.background[1] must be a finite number, got NaN'],
];

/** The class scene (its two lamps, spheres 5 and 6, are lights[0] and lights[1]) with a point light, lights[2]. */
const litScene = () => classScene().add(new PointLight([-10, 20, 0]));

describe('every tracer checks the scene as it is when called, naming the field', () => {
  for (const [name, trace] of Object.entries(TRACERS)) {
    for (const [what, change, Kind, message] of DAMAGE) {
      it(`${name}: ${what}`, () => {
        const scene = litScene();
        change(scene);
        let thrown;
        try { trace(scene, camera()); } catch (error) { thrown = error; }
        expect(thrown).toBeInstanceOf(Kind);
        expect(thrown.message.startsWith(message), thrown.message).toBe(true);
      });
    }
  }

  it('ParallelRenderer.render: the promise is refused, naming the field', async () => {
    const scene = litScene();
    scene.objects[1].radius = NaN;
    await expect(new ParallelRenderer({ workers: 1 }).render(scene, camera())).rejects.toThrow('objects[1].radius must be a finite number, got NaN');
  });

  it('a colour given as text after the scene was built is read as the constructor reads it', () => {
    const scene = litScene(), same = litScene();
    scene.objects[3].material.color = 'red';
    same.objects[3].material.color = [1, 0, 0];
    expect(render(scene, camera())).toEqual(render(same, camera()));
    expect(scene.objects[3].material.color).toEqual([1, 0, 0]);
  });

  it('a sphere centre given as [x, y, z] after the scene was built is traced where it says', () => {
    const scene = litScene(), same = litScene();
    scene.objects[3].center = [2, 1, -18];
    same.objects[3].center = new Sphere([2, 1, -18], 1).center;
    expect(render(scene, camera())).toEqual(render(same, camera()));
  });

  it('a lamp given a brighter emission after it was built lights the scene with it', () => {
    const scene = new Scene().add(new Sphere([0, 0, -20], 4, { color: 'white' })).add(new Sphere([0, 10, -20], 1, { emission: 0.2 }));
    const before = render(scene, camera());
    scene.objects[1].material.emission = [1, 1, 1];
    expect(render(scene, camera())).not.toEqual(before);
  });
});

describe('work budgets', () => {
  it('render: RENDER_RAYS rays pass, one row more is refused, naming the tracer view and the workers', () => {
    const dark = new Scene(); // 399 lights, nothing to light: 400 rays counted a pixel, the background traced
    for (let i = 0; i < 399; i++) dark.add(new PointLight([i, 10, 0]));
    expect(100 * 100 * 400).toBe(RENDER_RAYS);
    expect(render(dark, new Camera({ width: 100, height: 100 })).length).toBe(100 * 100 * 4);
    const over = new Camera({ width: 100, height: 101 });
    expect(() => render(dark, over)).toThrow(RangeError);
    expect(() => render(dark, over)).toThrow(/^render would trace about 4,040,000 rays \(100 × 101 pixels × 1 samples × 400 for the light sources × 1 bounce: no mirror or glass\).*createTracerView.*ParallelRenderer.*blocking: true/);
    expect(render(dark, over, undefined, undefined, { blocking: true }).length).toBe(100 * 101 * 4);
  });

  it('render: lights, camera samples and mirrors count; rows count as asked', () => {
    const scene = classScene({ full: true }); // 2 light sources, mirrors: maxDepth 5
    const cam = new Camera({ width: 400, height: 300, samples: 4 });
    expect(() => render(scene, cam)).toThrow(/400 × 300 pixels × 4 samples × 3 for the light sources × 6 bounces: maxDepth 5/);
    const rows = Math.floor(RENDER_RAYS / (400 * 4 * 3 * 6));
    expect(() => render(scene, cam, undefined, { y0: 0, y1: rows })).not.toThrow();
  });

  it('pathTrace: PATH_SEGMENTS segments pass, one sample more is refused, naming the tracer view with path', () => {
    const empty = new Scene({ background: [0.5, 0.5, 0.5] });
    const cam = new Camera({ width: 100, height: 100 }), samples = PATH_SEGMENTS / (100 * 100 * 5); // maxBounces 4: 5 segments
    expect(Number.isInteger(samples)).toBe(true);
    expect(pathTrace(empty, cam, { samples, maxBounces: 4 })[0]).toBe(128);
    expect(() => pathTrace(empty, cam, { samples: samples + 1, maxBounces: 4 })).toThrow(RangeError);
    expect(() => pathTrace(empty, cam, { samples: samples + 1, maxBounces: 4 })).toThrow(/^pathTrace would trace about 2,050,000 path segments .*createTracerView\(\{ scene, camera, path: \{ samples \} \}\).*blocking: true/);
    expect(pathTrace(empty, cam, { samples: samples + 1, maxBounces: 4, blocking: true })[0]).toBe(128);
  });

  it('pathTrace: without the roulette every bounce counts', () => {
    const cam = new Camera({ width: 100, height: 100 });
    expect(() => pathTrace(new Scene(), cam, { samples: 12, maxBounces: 16, roulette: false })).toThrow(/100 × 100 pixels × 12 samples × 17 for maxBounces 16\)/);
    expect(() => pathTrace(new Scene(), cam, { samples: 12, maxBounces: 16 })).not.toThrow();
  });

  it('renderGPU: GPU_SHAPE_TESTS ray–shape tests reach the GPU, one shape more is refused', () => {
    const scene = new Scene();
    for (let i = 0; i < 2048; i++) scene.add(new Sphere([i % 64, Math.floor(i / 64), -100], 0.4));
    const cam = new Camera({ width: 512, height: 256 });
    expect(512 * 256 * 2048).toBe(GPU_SHAPE_TESTS);
    expect(() => renderGPU(scene, cam)).toThrow(/needs WebGL2/); // under the limit: on to the GPU, which Node has not
    scene.add(new Sphere([0, 0, -50], 1));
    expect(() => renderGPU(scene, cam)).toThrow(RangeError);
    expect(() => renderGPU(scene, cam)).toThrow(/^renderGPU would test .* 2,049 shapes, 268,566,528 tests/);
    expect(() => renderGPU(scene, cam, { blocking: true })).toThrow(/needs WebGL2/);
  });

  it('blocking must be true or false, and the options known', () => {
    expect(() => render(new Scene(), camera(), undefined, undefined, { blocking: 'yes' })).toThrow('blocking must be true or false, got "yes"');
    expect(() => renderGPU(new Scene(), camera(), { blockin: true })).toThrow('unknown renderGPU option "blockin" (did you mean "blocking"?)');
    expect(() => pathTrace(new Scene(), camera(), { samples: 1, blocking: 1 })).toThrow('blocking must be true or false, got 1');
  });
});

describe('unknown options name the key and the closest known one', () => {
  const scene = classScene(), cam = camera();
  it('inspectPath', () => {
    expect(() => inspectPath(scene, cam, 1, 1, { sampel: 2 })).toThrow('unknown inspectPath option "sampel" (did you mean "sample"?)');
    expect(() => inspectPath(scene, cam, 1, 1, { samles: 2 })).toThrow('unknown inspectPath option "samles" (did you mean "samples"?)');
    expect(() => inspectPath(scene, cam, 1, 1, { sample: 0, sed: 2 })).toThrow('unknown inspectPath option "sed" (did you mean "seed"?)');
  });
  it('pathTrace', () => {
    expect(() => pathTrace(scene, cam, { sample: 2 })).toThrow('unknown pathTrace option "sample" (did you mean "samples"?)');
    expect(() => pathTrace(scene, cam, { samples: 2, maxBounce: 2 })).toThrow('unknown pathTrace option "maxBounce" (did you mean "maxBounces"?)');
  });
  it('inspectPath: a sample too large for samples left out is named as sample', () => {
    expect(() => inspectPath(scene, cam, 1, 1, { sample: 70000 })).toThrow(/^sample must be a whole number from 0 to 65535 when samples is left out/);
  });
});

describe('a shape\'s field is named by both of the scene\'s lists of shapes', () => {
  it.each(Object.keys(TRACERS))('%s: objects[2].radius is also scene.shapes[2].radius, the same shape', (name) => {
    const scene = classScene();
    expect(scene.shapes).toBe(scene.objects);
    scene.shapes[2].radius = NaN;
    expect(() => TRACERS[name](scene, camera())).toThrow(/^objects\[2\]\.radius must be a finite number, got NaN \(scene\.shapes\[2\]\.radius\)$/);
  });
});
