// A scene as short URL-safe text: compact JSON, base64url, every field checked on the way back.
import { describe, it, expect } from 'vitest';
import { classScene, render, Camera } from '../../lib/index.js';
import { sceneToJSON, sceneFromJSON } from '../../lib/scene/json.js';
import { compactSceneJSON, encodeScene, decodeScene, toBase64url, fromBase64url, MAX_SCENE_OBJECTS } from '../../lib/scene/codec.js';

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

describe('base64url', () => {
  it("writes what Node's base64url writes, and reads it back, for every byte value", () => {
    const bytes = Uint8Array.from({ length: 300 }, (_, i) => (i * 7) % 256);
    expect(toBase64url(bytes)).toBe(Buffer.from(bytes).toString('base64url'));
    expect(fromBase64url(toBase64url(bytes))).toEqual(bytes);
  });
});

describe('the size limit of a scene from a link or a paste', () => {
  const spheres = (n) => ({ objects: Array.from({ length: n }, (_, i) => ({ type: 'sphere', center: [i % 100, Math.floor(i / 100), -50], radius: 0.1 })) });

  it(`MAX_SCENE_OBJECTS (${MAX_SCENE_OBJECTS.toLocaleString('en')}) objects open; one more is a RangeError naming the limit`, () => {
    expect(decodeScene(encodeScene(spheres(MAX_SCENE_OBJECTS))).objects).toHaveLength(MAX_SCENE_OBJECTS);
    const over = encodeScene(spheres(MAX_SCENE_OBJECTS + 1));
    expect(() => decodeScene(over)).toThrow(RangeError);
    expect(() => decodeScene(over)).toThrow('the scene has 10,001 objects, more than the 10,000 a scene from a link or a paste may have');
    expect(() => decodeScene(JSON.stringify(spheres(MAX_SCENE_OBJECTS + 1)))).toThrow(/more than the 10,000/); // pasted JSON text
  });

  it('sceneFromJSON itself has no limit unless asked', () => {
    expect(sceneFromJSON(spheres(MAX_SCENE_OBJECTS + 1)).objects).toHaveLength(MAX_SCENE_OBJECTS + 1);
    expect(() => sceneFromJSON(spheres(3), { maxObjects: 2 })).toThrow('the scene has 3 objects, more than the 2 a scene from a link or a paste may have');
    expect(() => sceneFromJSON(spheres(1), { maxObject: 2 })).toThrow('unknown sceneFromJSON option "maxObject" (did you mean "maxObjects"?)');
  });
});
