/**
 * A light the library has never seen, written here with the light protocol
 * (lib/lights/index.js) and listed from this test alone: Scene.add takes it,
 * it renders through the kernel with trace.js's bytes, packs at the named
 * offsets, is inspected as a group of shadow rays, serialises to JSON and code,
 * is checked again on restart and shows in the 3D view, with no change to
 * any file of the library. The recipe of docs/ARCHITECTURE.md, "A new light".
 */
import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, Camera, render, inspectPixel } from '../../lib/index.js';
import { sceneToJSON, sceneFromJSON, sceneToCode } from '../../lib/scene/json.js';
import { renderPixel } from '../../lib/tracing/render.js';
import { packScene } from '../../lib/tracing/kernel.js';
import { checkScene } from '../../lib/scene/check.js';
import { checkWork, MAX_SHADOW_RAYS } from '../../lib/scene/work.js';
import { raySegments, sceneBounds } from '../../lib/lesson/rays3d.js';
import { registerLight } from '../../lib/lights/index.js';
import { LIGHT, POSITION, LIGHT_EMISSION, ATTENUATION, IS_SPOT } from '../../lib/lights/packed.js';
import { lightColor, lightIntensity, lightName, definedOnly } from '../../lib/lights/checks.js';
import { vector } from '../../lib/shapes/json.js';
import { buildMeshes, shapesKey, lightLoops } from '../../lib/p5/scene-view/mesh.js';
import { toVec3, Vec3 } from '../../lib/math/vec3.js';
import { checkOptions } from '../../lib/text/check.js';

/** A strip of light from `a` to `b` (a fluorescent tube), lit from `samples` fixed points along it. */
class StripLight {
  constructor(a, b, options = {}) {
    const { color = [1, 1, 1], intensity = 1, samples = 4, name = '' } = checkOptions(options, ['color', 'intensity', 'samples', 'name'], 'strip light');
    this.a = toVec3(a, 'a');
    this.b = toVec3(b, 'b');
    this.color = lightColor(color);
    this.intensity = lightIntensity(intensity);
    if (!Number.isInteger(samples) || samples < 1) throw new RangeError(`samples must be a whole number ≥ 1, got ${samples}`);
    this.samples = samples;
    this.name = lightName(name);
  }
  static get type() { return 'stripLight'; }
  static get codeName() { return 'StripLight'; }
  static get label() { return 'strip light'; }
  static get grouped() { return true; }
  static get fields() { return ['a', 'b', 'color', 'intensity', 'samples']; }
  static build(o) { return new StripLight(o.a, o.b, definedOnly({ color: o.color, intensity: o.intensity, samples: o.samples })); }
  static codeArguments(o) { return [o.a, o.b, { color: o.color, intensity: o.intensity, samples: o.samples }]; }
  /** Its shadow rays from a hit point, read from its JSON before any check: the limits of a link count them. */
  static workOf(o) { return { shadowRays: Number.isInteger(o.samples) && o.samples > 0 ? o.samples : 4, field: 'samples' }; }
  toJSON() {
    return { type: 'stripLight', name: this.name, a: vector(this.a), b: vector(this.b), color: [...this.color], intensity: this.intensity, samples: this.samples };
  }
  /** One point source per sample, at the middle of each of `samples` equal pieces, each with its share of the light. */
  sources() {
    const { a, b, samples: n } = this, emission = this.color.map((c) => (c * this.intensity) / n);
    return Array.from({ length: n }, (_, i) => {
      const s = (i + 0.5) / n;
      return { position: new Vec3(a.x + (b.x - a.x) * s, a.y + (b.y - a.y) * s, a.z + (b.z - a.z) * s), emission, object: null, source: this, attenuation: 0 };
    });
  }
  outlines() { return [[this.a, this.b]]; }
  viewKey() { return `${vector(this.a)},${vector(this.b)},${this.samples}`; }
}
registerLight(StripLight);

const camera = new Camera({ width: 40, height: 30, position: [0, 4, 6], pitch: -20 });

function stripScene() {
  const strip = new StripLight([-6, 8, -14], [6, 8, -14], { color: [1, 0.9, 0.7], intensity: 1.2, samples: 4, name: 'tube' });
  const scene = new Scene({ background: [0.2, 0.3, 0.5], ambient: 0.05 })
    .add(new Plane([0, -3, 0], [0, 1, 0], { color: [0.8, 0.8, 0.8] }))
    .add(new Sphere([0, 0, -14], 2.5, { color: [1, 0.32, 0.36], reflection: 0.2 }))
    .add(strip);
  return { scene, strip };
}

/** render() through trace.js, pixel by pixel. */
function traced(scene, cam) {
  const out = new Uint8ClampedArray(cam.width * cam.height * 4);
  for (let y = 0; y < cam.height; y++) for (let x = 0; x < cam.width; x++) renderPixel(scene, cam, x, y, out);
  return out;
}

/** The first floor pixel, row by row, whose point some of the strip's points reach and some do not (the penumbra). */
function penumbra(scene) {
  for (let y = 0; y < camera.height; y++) {
    for (let x = 0; x < camera.width; x++) {
      const r = inspectPixel(scene, camera, x, y);
      const g = r.hit?.object === scene.objects[0] ? r.hit.areaLights[0] : null;
      if (g && g.reached > 0 && g.reached < g.samples) return r;
    }
  }
  return null;
}

describe('a light written in a test, listed from the test', () => {
  it('is accepted by Scene.add: one source per sample, each of them the light\'s', () => {
    const { scene, strip } = stripScene();
    expect(scene.lights).toHaveLength(4);
    expect(scene.lights.every((l) => l.source === strip && l.object === null)).toBe(true);
    expect(() => new Scene().add({ sources: () => [] })).toThrow(/scene.add takes a shape/); // not listed: no light
  });

  it('checks its colour and intensity with the words every light uses', () => {
    expect(() => new StripLight([0, 0, 0], [1, 0, 0], { intensity: -1 })).toThrow('intensity must not be negative, got -1');
    expect(() => new StripLight([0, 0, 0], [1, 0, 0], { color: 'pinkk' })).toThrow(/^color must be a colour like/);
  });

  it('renders through the kernel, the same bytes as trace.js; its light is in the picture', () => {
    const { scene } = stripScene();
    expect(packScene(scene)).not.toBeNull();
    const picture = render(scene, camera);
    expect(picture).toEqual(traced(scene, camera));
    const dark = render(new Scene({ background: [0.2, 0.3, 0.5], ambient: 0.05 }).add(scene.objects[0]).add(scene.objects[1]), camera);
    expect(picture).not.toEqual(dark);
  });

  it('packs its sources at the layout\'s named offsets', () => {
    const { scene } = stripScene();
    const k = packScene(scene);
    expect(k.lightCount).toBe(4);
    const first = scene.lights[0];
    expect([...k.lights.slice(POSITION, POSITION + 3)]).toEqual([first.position.x, first.position.y, first.position.z]);
    expect([...k.lights.slice(LIGHT_EMISSION, LIGHT_EMISSION + 3)]).toEqual(first.emission);
    expect(k.lights[3 * LIGHT + ATTENUATION]).toBe(0);
    expect(k.lights[3 * LIGHT + IS_SPOT]).toBe(0);
  });

  it('is inspected as one group of shadow rays under its own label, each ray numbered', () => {
    const { scene, strip } = stripScene();
    const record = penumbra(scene);
    expect(record).not.toBeNull();
    const [group] = record.hit.areaLights;
    expect(group).toMatchObject({ light: strip, label: 'strip light', samples: 4 });
    expect(group.rays.map((l) => l.sample)).toEqual([0, 1, 2, 3]);
    const shadows = raySegments(scene, record).filter((s) => s.kind === 'shadow' && s.light === strip);
    expect(shadows.map((s) => s.sample)).toEqual([0, 1, 2, 3]);
    expect(shadows.filter((s) => s.blockedAt).length).toBe(4 - group.reached);
  });

  it('serialises: JSON and back, the same picture; its code; bad JSON named by path; checked again on restart', () => {
    const { scene } = stripScene();
    const json = sceneToJSON(scene);
    expect(json.objects[2]).toEqual({ type: 'stripLight', name: 'tube', a: [-6, 8, -14], b: [6, 8, -14], color: [1, 0.9, 0.7], intensity: 1.2, samples: 4 });
    const copy = sceneFromJSON(JSON.stringify(json));
    expect(sceneToJSON(copy)).toEqual(json);
    expect(render(copy, camera)).toEqual(render(scene, camera));
    expect(sceneToCode(scene)).toContain("import { Scene, Sphere, Plane, StripLight } from '../lib/index.js';");
    expect(sceneToCode(scene)).toContain('const tube = new StripLight([-6, 8, -14], [6, 8, -14], { color: [1, 0.9, 0.7], intensity: 1.2, samples: 4 });');
    expect(() => sceneFromJSON({ objects: [{ type: 'stripLight', a: [0, 0, 0], b: [1, 0, 0], intensity: -2 }] })).toThrow('objects[0].intensity must not be negative, got -2');
    expect(() => sceneFromJSON({ objects: [{ type: 'stripLight', a: [0, 0, 0], b: [1, 0, 0], size: 2 }] })).toThrow('objects[0] has no field "size"');
    scene.lights[0].source.intensity = -1;
    expect(() => checkScene(scene)).toThrow('lights[0].intensity must not be negative, got -1');
  });

  it('shows in the 3D view: a glow per source, its own outline, a new still part when it moves', () => {
    const { scene, strip } = stripScene();
    const bounds = sceneBounds(scene, camera, 1);
    const state = { scene, camera, bounds, constructionSphere: null };
    const without = { ...state, scene: new Scene().add(scene.objects[0]).add(scene.objects[1]) };
    const GLOW_BALL = 8 * 12 * 6; // vertices of one small glow ball
    expect(buildMeshes(state).mesh.positions.length - buildMeshes(without).mesh.positions.length).toBe(4 * GLOW_BALL * 3);
    expect(lightLoops(scene)).toEqual([[strip.a, strip.b]]);
    const key = shapesKey(state);
    strip.b = new Vec3(8, 8, -14);
    expect(shapesKey(state)).not.toBe(key);
    expect(lightLoops(scene)[0][1].x).toBe(8);
  });

  it('counts the shadow rays its JSON makes, as a link\'s limits do, naming its own field', () => {
    const strips = (n, samples) => Array.from({ length: n }, () => ({ type: 'stripLight', a: [0, 5, 0], b: [1, 5, 0], samples }));
    expect(() => checkWork(strips(MAX_SHADOW_RAYS / 4, 4), {})).not.toThrow();
    expect(() => checkWork(strips(MAX_SHADOW_RAYS / 4 + 1, 4), {})).toThrow(new RegExp(`^objects\\[${MAX_SHADOW_RAYS / 4}\\]\\.samples: the scene's lights cast 1,028 shadow rays`));
    expect(() => checkWork(strips(MAX_SHADOW_RAYS / 8 + 1, 8), {})).toThrow(/^objects\[128\]\.samples:/);
  });
});
