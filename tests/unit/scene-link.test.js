// The scene in a link: compressed in the fragment, old ?scene= links still
// read, a warning for links a chat might cut, and no unpacking bomb.
import { describe, it, expect } from 'vitest';
import { deflateRawSync } from 'node:zlib';
import { classScene, Scene, Sphere } from '../../lib/index.js';
import { sceneToJSON } from '../../lib/scene/json.js';
import { encodeScene } from '../../lib/scene/codec.js';
import {
  encodeSceneLink, decodeSceneLink, readSceneLink, sceneLinkURL, sceneTextInLink, linkNotice,
  LINK_WARN_LENGTH, LINK_MAX_LENGTH, MAX_SCENE_BYTES,
} from '../../lib/p5/page/scene-link.js';

const PAGE = 'http://localhost/sketches/05-value-boxes.html';

/** n spheres at made-up places, as a big class might build. */
function manySpheres(n) {
  const scene = new Scene();
  let seed = 1;
  const random = () => ((seed = (seed * 16807) % 2147483647) / 2147483647);
  for (let i = 0; i < n; i++) {
    scene.add(Object.assign(new Sphere([random() * 40 - 20, random() * 20, -20 - random() * 40], 0.5 + random() * 2,
      { color: [random(), random(), random()] }), { name: `ball ${i}` }));
  }
  return sceneToJSON(scene);
}

describe('the scene in a link', () => {
  it('round-trips, compressed, URL-safe', async () => {
    const json = sceneToJSON(classScene());
    json.objects[2].name = 'ünïcode ☀ <b>';
    const text = await encodeSceneLink(json);
    expect(text).toMatch(/^z\.[A-Za-z0-9_-]+$/);
    expect(sceneToJSON(await decodeSceneLink(text))).toEqual(json);
  });

  it('is several times shorter than the old base64url JSON', async () => {
    const json = manySpheres(1000);
    const [old, now] = [encodeScene(json).length, (await encodeSceneLink(json)).length];
    expect(now).toBeLessThan(old / 2);
  });

  it('still reads old ?scene= links, and plain JSON', async () => {
    const json = sceneToJSON(classScene());
    expect(sceneToJSON(await readSceneLink(`${PAGE}?scene=${encodeScene(json)}`))).toEqual(json);
    expect((await decodeSceneLink('{"objects":[{"type":"sphere","center":[0,0,-5],"radius":2}]}')).spheres[0].radius).toBe(2);
  });

  it('reads the fragment first, then the query; null when neither', async () => {
    expect(sceneTextInLink(`${PAGE}?scene=a#scene=b`)).toBe('b');
    expect(sceneTextInLink(`${PAGE}?scene=a`)).toBe('a');
    expect(sceneTextInLink(`${PAGE}?lng=es`)).toBeNull();
    expect(await readSceneLink(PAGE)).toBeNull();
  });

  it('writes the scene into the fragment and drops an old ?scene=', async () => {
    const json = sceneToJSON(classScene());
    const url = new URL(await sceneLinkURL(`${PAGE}?scene=old&lng=es#x`, json));
    expect(url.searchParams.get('scene')).toBeNull();
    expect(url.searchParams.get('lng')).toBe('es');
    expect(url.hash).toMatch(/^#scene=z\./);
    expect(sceneToJSON(await readSceneLink(url.href))).toEqual(json);
  });

  it('says what is wrong with a damaged link', async () => {
    await expect(decodeSceneLink('z.not*base64!')).rejects.toThrow(/not base64url/);
    await expect(decodeSceneLink('z.AAAA')).rejects.toThrow(/cut short or damaged/);
    const text = await encodeSceneLink(sceneToJSON(classScene()));
    await expect(decodeSceneLink(text.slice(0, text.length / 2))).rejects.toThrow(TypeError);
    const bad = `z.${deflateRawSync('{"objects":[{"type":"sphere","center":[0,0,0],"radius":-1}]}').toString('base64url')}`;
    await expect(decodeSceneLink(bad)).rejects.toThrow(/objects\[0\]\.radius/);
  });

  it('refuses a small link that unpacks to more than MAX_SCENE_BYTES', async () => {
    const bomb = deflateRawSync(Buffer.alloc(MAX_SCENE_BYTES + 1024, 32)).toString('base64url');
    expect(bomb.length).toBeLessThan(20_000);
    await expect(decodeSceneLink(`z.${bomb}`)).rejects.toThrow(RangeError);
  });
});

describe('linkNotice', () => {
  it('copies short links quietly, warns about long ones, refuses what no browser opens', () => {
    expect(linkNotice(300)).toEqual({ open: true, message: 'Link copied: paste it into the chat.' });
    expect(linkNotice(LINK_WARN_LENGTH + 1).message).toMatch(/8,001 characters long: a chat or an e-mail may cut it/);
    const tooLong = linkNotice(LINK_MAX_LENGTH + 1);
    expect(tooLong.open).toBe(false);
    expect(tooLong.message).toMatch(/more than a browser opens: copy the scene as code/);
  });
});
